// Reading a text file line by line with a bound on every line: a line longer
// than `max_line` bytes is refused as soon as its first max_line + 1 bytes
// are read (`/dev/zero` or a file without newlines ends in an error, not in
// memory exhaustion), and the reader never holds more than one line. Lines
// end at '\n' (a '\r' before it is kept: callers treat it as a blank). The
// last line may lack its '\n'; torn() says whether it did.
// Errors are rtamp::Error located at the file (and the line, for a long one).
#pragma once

#include <cstddef>
#include <fstream>
#include <string>
#include <string_view>

namespace rtamp {

class LineReader {
 public:
  // Opens `path` (open_text_file: a directory or a missing file is said so);
  // `what` names the file in errors ("the episode log").
  LineReader(const std::string& path, std::string_view what, std::size_t max_line);

  // The next line (without '\n') into `line`; false at the end of the file.
  bool next(std::string& line);
  int line_number() const { return line_; }  // of the line last returned (1-based)
  bool torn() const { return torn_; }        // the last line returned had no '\n'

 private:
  std::ifstream in_;
  std::string path_, what_;
  std::size_t max_line_;
  int line_ = 0;
  bool torn_ = false;
};

}  // namespace rtamp
