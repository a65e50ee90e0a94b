// rtamp::Error — the one exception type for errors a user can cause (bad YAML,
// bad LTL, unknown names, infeasible tasks). It carries *what* went wrong and
// *where* (file, line, column, or a name), so the CLI can print one clear line
// and exit 2. Invariant: what() == format() — the full one-line message.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace rtamp {

struct SourceLocation {
  std::string file;  // empty: not from a file (command line, string)
  int line = 0;      // 1-based; 0: unknown
  int column = 0;    // 1-based; 0: unknown
};

class Error : public std::runtime_error {
 public:
  // `what`: the problem, e.g. "unknown object 'o7'". `where`: location, may be empty.
  explicit Error(std::string what, SourceLocation where = {}, std::string detail = {});

  const std::string& message() const { return message_; }
  const SourceLocation& where() const { return where_; }
  // Extra lines shown under the message (e.g. the input with a caret under the column).
  const std::string& detail() const { return detail_; }

 private:
  std::string message_;
  SourceLocation where_;
  std::string detail_;
};

// "file:line:col: " prefix (parts omitted when unknown), empty when nothing is known.
std::string format_location(const SourceLocation& where);

// The input line with a caret under `column` (1-based), for parser errors.
std::string caret_line(const std::string& text, int column);

// The line of `text` that holds byte `offset`, with a caret under that byte:
// control bytes other than tab are shown as spaces (so the caret stays
// aligned) and a long line is cut to 60 bytes on each side of the caret
// ("..." marks the cuts).
std::string caret_at(std::string_view text, std::size_t offset);

}  // namespace rtamp
