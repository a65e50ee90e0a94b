#include "rtamp/util/error.hpp"

namespace rtamp {

std::string format_location(const SourceLocation& where) {
  std::string out;
  if (!where.file.empty()) out += where.file + ":";
  if (where.line > 0) out += std::to_string(where.line) + ":";
  if (where.column > 0) out += std::to_string(where.column) + ":";
  if (!out.empty()) out += " ";
  return out;
}

std::string caret_line(const std::string& text, int column) {
  std::string out = "  " + text + "\n  ";
  for (int i = 1; i < column; ++i) out += (i - 1 < static_cast<int>(text.size()) && text[i - 1] == '\t') ? '\t' : ' ';
  out += '^';
  return out;
}

Error::Error(std::string what, SourceLocation where, std::string detail)
    : std::runtime_error(format_location(where) + what),
      message_(std::move(what)),
      where_(std::move(where)),
      detail_(std::move(detail)) {}

}  // namespace rtamp
