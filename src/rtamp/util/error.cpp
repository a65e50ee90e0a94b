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

std::string caret_at(std::string_view text, std::size_t offset) {
  constexpr std::size_t kWindow = 60;
  const std::size_t at = offset < text.size() ? offset : text.size();
  const std::size_t nl = at == 0 ? std::string_view::npos : text.rfind('\n', at - 1);
  const std::size_t begin = nl == std::string_view::npos ? 0 : nl + 1;
  std::size_t end = text.find('\n', begin);
  if (end == std::string_view::npos) end = text.size();
  if (end > begin && text[end - 1] == '\r') --end;
  std::size_t from = begin, to = end;
  std::string shown;
  if (at > begin + kWindow) {
    from = at - kWindow;
    shown = "...";
  }
  const std::size_t column = shown.size() + (at - from) + 1;
  const bool cut = to > at + kWindow;
  if (cut) to = at + kWindow;
  if (to > from) shown.append(text.substr(from, to - from));
  if (cut) shown += "...";
  for (char& c : shown)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) c = ' ';  // caret_line aligns tabs
  return caret_line(shown, static_cast<int>(column));
}

Error::Error(std::string what, SourceLocation where, std::string detail)
    : std::runtime_error(format_location(where) + what),
      message_(std::move(what)),
      where_(std::move(where)),
      detail_(std::move(detail)) {}

}  // namespace rtamp
