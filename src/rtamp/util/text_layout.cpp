#include "rtamp/util/text_layout.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace rtamp {

std::optional<SourceLocation> TextLayout::locate(const std::string& file, std::size_t offset) const {
  if (lines.empty()) return std::nullopt;
  auto it = std::upper_bound(lines.begin(), lines.end(), offset,
                             [](std::size_t o, const Line& l) { return o < l.offset; });
  if (it != lines.begin()) --it;
  const std::size_t into = offset >= it->offset ? offset - it->offset : 0;
  return SourceLocation{file, it->line, it->column + static_cast<int>(into)};
}

TextLayout block_scalar_layout(std::string_view source, std::size_t indicator, int indicator_line,
                               std::string_view value) {
  TextLayout layout;
  if (indicator >= source.size()) return layout;
  // The header: an explicit indentation digit among the indicators (e.g. |2-).
  std::size_t pos = indicator + 1;
  int explicit_indent = 0;
  while (pos < source.size() && (source[pos] == '+' || source[pos] == '-' ||
                                 std::isdigit(static_cast<unsigned char>(source[pos])))) {
    if (std::isdigit(static_cast<unsigned char>(source[pos]))) explicit_indent = source[pos] - '0';
    ++pos;
  }
  // The indicator's own indentation: the parent's, from which an explicit digit counts.
  const std::size_t indicator_line_start = source.rfind('\n', indicator) == std::string_view::npos
                                               ? 0
                                               : source.rfind('\n', indicator) + 1;
  std::size_t parent_indent = 0;
  while (indicator_line_start + parent_indent < indicator && source[indicator_line_start + parent_indent] == ' ')
    ++parent_indent;
  // The content lines, without their indentation.
  struct Content {
    std::string_view text;
    int line;
    int column;
  };
  std::vector<Content> content;
  std::size_t nl = source.find('\n', pos);
  int line = indicator_line;
  std::size_t indent = explicit_indent > 0 ? parent_indent + static_cast<std::size_t>(explicit_indent) : 0;
  while (nl != std::string_view::npos) {
    const std::size_t start = nl + 1;
    ++line;
    nl = source.find('\n', start);
    std::string_view l = source.substr(start, (nl == std::string_view::npos ? source.size() : nl) - start);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    const std::size_t first = l.find_first_not_of(' ');
    if (first == std::string_view::npos) {  // blank: part of the scalar, empty
      content.push_back({std::string_view(), line, static_cast<int>(l.size()) + 1});
      continue;
    }
    if (indent == 0) indent = std::max<std::size_t>(first, 1);
    if (first < indent) break;  // the scalar ended
    content.push_back({l.substr(indent), line, static_cast<int>(indent) + 1});
  }
  // Walk the value along the content lines.
  std::size_t k = 0, c = 0;  // content line, byte in it
  for (std::size_t i = 0; i < value.size() && k < content.size(); ++i) {
    const char v = value[i];
    for (;;) {
      if (k >= content.size()) break;
      const Content& l = content[k];
      if (c == 0 && (layout.lines.empty() || layout.lines.back().line != l.line))
        layout.lines.push_back({i, l.line, l.column});
      if (c < l.text.size()) {
        ++c;  // the same byte (or, defensively, the next one)
        break;
      }
      // At the end of a line: the value's line break (or its folded space), or nothing.
      if (v == '\n' || v == ' ') {
        ++k, c = 0;
        break;
      }
      ++k, c = 0;
    }
  }
  return layout;
}

}  // namespace rtamp
