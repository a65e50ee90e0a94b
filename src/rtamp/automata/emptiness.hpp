// Emptiness check of a Büchi automaton with a witness (used to report
// unsatisfiable specifications, and by tests as a second oracle).
//
// The language is non-empty iff a reachable SCC has an internal edge and its
// internal edges carry every acceptance set. The witness is a lasso u·v^ω:
// a shortest path (BFS) from the initial state to a state s of such an SCC,
// then a cycle through s inside the SCC that takes an edge of each set.
// Each letter is the smallest letter of the edge's guard (its positive atoms).
// Invariant: lasso_accept(a, *find_accepting_lasso(a)) whenever it returns a value.
#pragma once

#include <optional>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/automata/lasso_accept.hpp"

namespace rtamp::automata {

std::optional<LassoWord> find_accepting_lasso(const Automaton& a);
inline bool is_empty(const Automaton& a) { return !find_accepting_lasso(a).has_value(); }

}  // namespace rtamp::automata
