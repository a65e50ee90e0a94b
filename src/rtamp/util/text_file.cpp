#include "rtamp/util/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "rtamp/util/error.hpp"

namespace rtamp {

namespace {

[[noreturn]] void refuse(const std::string& path, std::string_view what, const std::string& why) {
  throw Error("cannot read " + std::string(what) + ": " + why, SourceLocation{path});
}

}  // namespace

bool path_exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

std::ifstream open_text_file(const std::string& path, std::string_view what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) refuse(path, what, "it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int e = errno;
    refuse(path, what, e == ENOENT ? "no such file" : e != 0 ? std::string(std::strerror(e)) : "cannot open it");
  }
  return in;
}

std::string read_text_file(const std::string& path, std::string_view what, std::size_t max_bytes) {
  std::ifstream in = open_text_file(path, what);
  std::string text;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      refuse(path, what, "the file is too large (at most " + std::to_string(max_bytes) + " bytes)");
  }
  if (in.bad()) refuse(path, what, "a read error");
  return text;
}

}  // namespace rtamp
