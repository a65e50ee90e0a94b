// An output file, written the one way every rtamp command writes one
// (`run --log/--mcap`, `serve --log/--mcap`, `batch -o/--log-dir`, `log
// to-mcap`, ...):
//  - a regular file (or a new one) is opened without truncating it, locked
//    with an exclusive flock(2) that is held until it is closed — a second
//    writer of the same file is refused ("... is being written by another
//    process") and nothing of the file is changed — and only then truncated;
//  - a FIFO or a character device (`/dev/null`, a pipe) is written directly:
//    never truncated, locked, replaced or removed; a FIFO without a reader is
//    refused instead of waiting for one; anything else that is not a regular
//    file (a directory, a socket, a block device) is refused;
//  - every write and the close are checked: a lost output (a full disk, a
//    file-size limit, an I/O error) is an OutputError naming the file and the
//    reason, never silence.
// Errors read "WHAT: cannot write 'PATH': WHY" (WHAT: the option, e.g. "--log").
// The process should ignore SIGXFSZ (the CLI does), so that a file-size
// limit is a write error and not a signal.
#pragma once

#include <string>
#include <string_view>

#include "rtamp/util/error.hpp"

namespace rtamp {

// An output that could not be written (or was lost while writing it).
class OutputError : public Error {
 public:
  using Error::Error;
};

class OutputFile {
 public:
  enum class Lock { Exclusive, None };
  // Truncate: the file starts empty (once it is locked). Keep: a regular file
  // keeps what it holds (to be read, then resize()d), and writes go at its end.
  enum class Open { Truncate, Keep };

  OutputFile() = default;
  // Opens (creates, locks, truncates) `path`; throws OutputError if it cannot.
  OutputFile(std::string path, std::string what, Lock lock = Lock::Exclusive, Open open = Open::Truncate);
  ~OutputFile();  // closes quietly (close() explicitly to see errors)
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // All of `bytes`, or OutputError.
  void write(std::string_view bytes);
  // A regular file cut (or extended) to `size` bytes, the next write there.
  void resize(std::size_t size);
  // Closes; OutputError if the close reports a loss (every write was checked already). Idempotent.
  void close();
  // Closes quietly and removes the file if it is a regular file (a failed conversion
  // leaves no half-written file); a FIFO or a device is never removed.
  void discard() noexcept;

  bool is_open() const { return fd_ >= 0; }
  bool regular() const { return regular_; }
  bool created() const { return created_; }  // the file did not exist before
  const std::string& path() const { return path_; }
  const std::string& what() const { return what_; }

 private:
  [[noreturn]] void fail(const std::string& why) const;

  int fd_ = -1;
  bool regular_ = false, created_ = false;
  std::string path_, what_;
};

// The whole of `text` as the file `path` (OutputFile: locked, checked, closed).
void write_output_file(const std::string& path, const std::string& what, std::string_view text);

// Whether `path` can be opened as OutputFile opens it, without creating or
// changing anything (the lock is tried and released on an existing regular
// file; a new file's directory must be writable). Throws OutputError.
void check_output(const std::string& path, const std::string& what);

}  // namespace rtamp
