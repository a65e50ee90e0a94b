// Where the bytes of a text taken from a file lie in that file (so that
// every error points at file:line:col). A YAML block scalar (| or >) drops
// the indentation of each of its lines and > folds line breaks into spaces,
// so a byte's column in the text is not its column in the file; a quoted
// scalar's continuation lines are re-indented too. The layout records, for
// each line of the file that the text comes from, the offset in the text of
// the line's first byte and the file line and column of that byte.
//
// Invariant: `lines` is in increasing order of offset (and of file line);
// every byte from one entry's offset up to the next entry's lies on the
// entry's file line, one column per byte. An empty layout means "unknown":
// callers then assume the text lies in the file as written from its start.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "rtamp/util/error.hpp"

namespace rtamp {

struct TextLayout {
  struct Line {
    std::size_t offset = 0;  // first byte of the file line in the text
    int line = 0;            // 1-based file line
    int column = 0;          // 1-based file column of that byte
  };
  std::vector<Line> lines;

  bool empty() const { return lines.empty(); }
  // The file line and column of byte `offset` of the text (file from `file`);
  // nullopt when the layout is empty.
  std::optional<SourceLocation> locate(const std::string& file, std::size_t offset) const;
};

// The layout of a YAML block scalar whose indicator (| or >) is at byte
// `indicator` of `source` (the whole file, 1-based line `indicator_line` of
// the indicator) and whose value is `value`. Walks the scalar's content lines
// (after the indicator's line, without their indentation) along the value:
// a byte of a line matches the same byte of the value; a line break is the
// value's '\n' or (folded) ' ', or nothing when > drops it before a blank line.
TextLayout block_scalar_layout(std::string_view source, std::size_t indicator, int indicator_line,
                               std::string_view value);

}  // namespace rtamp
