// Reading a whole input file as text, with the errors a user can cause said
// plainly: "PATH: cannot read WHAT: no such file | it is a directory |
// Permission denied | ...". Every reader of a user's file (scenario, BT XML,
// HOA, CSV, formula lists) goes through it, so a directory given as a file is
// named as one instead of surfacing as a parser's "empty input".
// Invariant: returns only after the whole file was read; throws rtamp::Error
// (located at the path) otherwise. `max_bytes`: larger files are refused.
#pragma once

#include <cstddef>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

namespace rtamp {

std::string read_text_file(const std::string& path, std::string_view what,
                           std::size_t max_bytes = std::numeric_limits<std::size_t>::max());

// Whether anything (file, directory, ...) exists at `path`.
bool path_exists(const std::string& path);

// The same checks for a file read as a stream (line by line): an open stream,
// or rtamp::Error saying why not.
std::ifstream open_text_file(const std::string& path, std::string_view what);

}  // namespace rtamp
