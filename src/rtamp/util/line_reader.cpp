#include "rtamp/util/line_reader.hpp"

#include "rtamp/util/error.hpp"
#include "rtamp/util/text_file.hpp"

namespace rtamp {

namespace {

std::string bytes_text(std::size_t n) {
  if (n >= (1u << 20) && n % (1u << 20) == 0) return std::to_string(n >> 20) + " MiB";
  if (n >= 1024 && n % 1024 == 0) return std::to_string(n >> 10) + " KiB";
  return std::to_string(n) + " bytes";
}

}  // namespace

LineReader::LineReader(const std::string& path, std::string_view what, std::size_t max_line)
    : in_(open_text_file(path, what)), path_(path), what_(what), max_line_(max_line) {}

bool LineReader::next(std::string& line) {
  line.clear();
  torn_ = false;
  if (!in_) return false;
  std::streambuf* buf = in_.rdbuf();
  bool any = false;
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in_.setstate(std::ios::eofbit);
      if (!any) return false;
      torn_ = true;
      break;
    }
    any = true;
    if (c == '\n') break;
    if (line.size() == max_line_)
      throw Error("a line longer than " + bytes_text(max_line_) + " (the limit of " + what_ + ")",
                  SourceLocation{path_, line_ + 1, 0});
    line += static_cast<char>(c);
  }
  ++line_;
  return true;
}

}  // namespace rtamp
