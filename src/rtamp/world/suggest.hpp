// Helpers for error messages about names: "did you mean 'capacity'?" for a
// likely typo, else the list of names that would have been accepted.
// Used by the scenario loader and validator (errors a user can cause must say
// what is wrong and how to fix it).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rtamp::world {

// 'word' in single quotes. (Built by appending: GCC 12 falsely warns
// -Wrestrict on "'" + std::string(...) + "'".)
std::string quoted(std::string_view word);

// Levenshtein distance (bytes), capped: returns cap + 1 once it exceeds `cap`.
int edit_distance(std::string_view a, std::string_view b, int cap = 3);

// " (did you mean 'x'?)" when one candidate is within edit distance 2 (or 1 for
// short words), else " (expected one of: a, b, c)" listing up to 12 candidates,
// else "" when there are none.
std::string suggestion(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace rtamp::world
