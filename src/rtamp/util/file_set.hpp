// The files one command reads and writes, checked against each other before
// anything is opened: an output may not be one of the command's inputs, nor
// another of its outputs. Files are compared by what they are, not by how
// they are named: two existing paths are the same file when they have the
// same device and inode (a hard link, a symlink, `./x` and `x`); a path that
// does not exist yet is compared by its resolved path (its directory's
// symlinks resolved), so `--mcap X --log X` is refused before X is created.
// Character devices (`/dev/null`) may be given as several outputs: writing
// there harms nothing.
#pragma once

#include <string>
#include <vector>

namespace rtamp {

class FileSet {
 public:
  // `what` names the file in errors: the option ("--log") or argument ("LOG").
  void input(const std::string& what, const std::string& path);
  // Throws rtamp::OutputError "WHAT: 'PATH' is also OTHER" if `path` is a file
  // given before (an input, or an output that is not a character device).
  void output(const std::string& what, const std::string& path);

 private:
  struct Entry {
    std::string what, path, resolved;
    bool exists = false, device = false;
    unsigned long long dev = 0, ino = 0;
  };
  static Entry entry(const std::string& what, const std::string& path);
  std::vector<Entry> inputs_, outputs_;
};

}  // namespace rtamp
