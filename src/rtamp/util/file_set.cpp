#include "rtamp/util/file_set.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "rtamp/util/format.hpp"
#include "rtamp/util/output_file.hpp"

namespace rtamp {

FileSet::Entry FileSet::entry(const std::string& what, const std::string& path) {
  Entry e{what, path, {}, false, false, 0, 0};
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    e.exists = true;
    e.device = S_ISCHR(st.st_mode);
    e.dev = st.st_dev;
    e.ino = st.st_ino;
  }
  std::error_code ec;
  const auto resolved = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  e.resolved = ec ? path : resolved.lexically_normal().string();
  return e;
}

void FileSet::input(const std::string& what, const std::string& path) {
  inputs_.push_back(entry(what, path));
}

void FileSet::output(const std::string& what, const std::string& path) {
  const Entry e = entry(what, path);
  auto same = [&](const Entry& o) {
    if (e.exists && o.exists) return e.dev == o.dev && e.ino == o.ino;
    return !e.exists && !o.exists && e.resolved == o.resolved;
  };
  auto refuse = [&](const Entry& o, const char* as) {
    throw OutputError(what + ": cannot write '" + escape_text(path) + "': it is " + as + o.what + " ('" +
                      escape_text(o.path) + "')");
  };
  for (const Entry& o : inputs_)
    if (same(o)) refuse(o, "also the input ");
  if (!e.device)
    for (const Entry& o : outputs_)
      if (same(o)) refuse(o, "also the output ");
  outputs_.push_back(e);
}

}  // namespace rtamp
