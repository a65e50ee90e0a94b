#include "rtamp/util/output_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include "rtamp/util/format.hpp"

namespace rtamp {

namespace {

std::string shown(const std::string& path) { return "'" + escape_text(path) + "'"; }

std::string reason(int e) {
  if (e == ENOSPC) return "no space left on the device";
  if (e == EFBIG) return "the file is too large (a file-size limit or the file system's)";
  if (e == EDQUOT) return "the disk quota is exhausted";
  return std::strerror(e);
}

std::string kind_of(mode_t m) {
  if (S_ISDIR(m)) return "it is a directory";
  if (S_ISBLK(m)) return "it is a block device";
  if (S_ISSOCK(m)) return "it is a socket";
  return "it is not a regular file";
}

// Why an existing, non-regular `m` cannot be written; empty: it can (written directly).
std::string refusal(mode_t m) {
  if (S_ISREG(m) || S_ISFIFO(m) || S_ISCHR(m)) return {};
  return kind_of(m);
}

std::string directory_of(const std::string& path) {
  std::string dir = std::filesystem::path(path).parent_path().string();
  return dir.empty() ? "." : dir;
}

}  // namespace

void check_output(const std::string& path, const std::string& what) {
  auto fail = [&](const std::string& why) {
    throw OutputError(what + ": cannot write " + shown(path) + ": " + why);
  };
  if (path.empty()) fail("empty path");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (const std::string why = refusal(st.st_mode); !why.empty()) fail(why);
    if (::access(path.c_str(), W_OK) != 0) fail(reason(errno));
    if (S_ISREG(st.st_mode)) {  // another writer holds it?
      const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      if (fd < 0) fail(reason(errno));
      const bool locked = ::flock(fd, LOCK_EX | LOCK_NB) != 0;
      ::close(fd);  // releases the lock
      if (locked) fail("it is being written by another process (it is locked)");
    }
    return;
  }
  if (errno != ENOENT) fail(reason(errno));
  const std::string dir = directory_of(path);
  struct stat ds {};
  if (::stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode)) fail("no directory " + shown(dir));
  if (::access(dir.c_str(), W_OK | X_OK) != 0) fail(reason(errno));
}

OutputFile::OutputFile(std::string path, std::string what, Lock lock, Open open)
    : path_(std::move(path)), what_(std::move(what)) {
  if (path_.empty()) fail("empty path");
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (exists) {
    if (const std::string why = refusal(st.st_mode); !why.empty()) fail(why);
  }
  if (exists && S_ISFIFO(st.st_mode)) {
    // Without a reader, open(2) would wait for one: refuse instead.
    fd_ = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) fail(errno == ENXIO ? "a FIFO with no reader" : reason(errno));
    const int flags = ::fcntl(fd_, F_GETFL);
    ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
    return;
  }
  if (exists && S_ISCHR(st.st_mode)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) fail(reason(errno));
    return;
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | O_NOCTTY, 0666);
  if (fd_ < 0) {
    if (errno == ENOENT) fail("no directory " + shown(directory_of(path_)));
    fail(reason(errno));
  }
  struct stat now {};
  const bool statted = ::fstat(fd_, &now) == 0;
  if (!statted || !S_ISREG(now.st_mode)) {  // replaced between stat and open
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    fail(statted ? kind_of(now.st_mode) : reason(e));
  }
  regular_ = true;
  created_ = !exists;
  if (lock == Lock::Exclusive && ::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    fail(e == EWOULDBLOCK ? "it is being written by another process (it is locked)" : reason(e));
  }
  const bool done = open == Open::Truncate ? ::ftruncate(fd_, 0) == 0 : ::lseek(fd_, 0, SEEK_END) >= 0;
  if (!done) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    fail(reason(e));
  }
}

void OutputFile::resize(std::size_t size) {
  if (fd_ < 0) fail("the file is closed");
  if (!regular_) fail("only a regular file can be cut");
  if (::ftruncate(fd_, static_cast<off_t>(size)) != 0 || ::lseek(fd_, static_cast<off_t>(size), SEEK_SET) < 0)
    fail(reason(errno));
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
}

OutputFile::OutputFile(OutputFile&& o) noexcept
    : fd_(std::exchange(o.fd_, -1)),
      regular_(o.regular_),
      created_(o.created_),
      path_(std::move(o.path_)),
      what_(std::move(o.what_)) {}

OutputFile& OutputFile::operator=(OutputFile&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(o.fd_, -1);
    regular_ = o.regular_;
    created_ = o.created_;
    path_ = std::move(o.path_);
    what_ = std::move(o.what_);
  }
  return *this;
}

void OutputFile::fail(const std::string& why) const {
  throw OutputError(what_ + ": cannot write " + shown(path_) + ": " + why);
}

void OutputFile::write(std::string_view bytes) {
  if (fd_ < 0) fail("the file is closed");
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(reason(errno));
    }
    if (n == 0) fail("the device took nothing");
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void OutputFile::close() {
  if (fd_ < 0) return;
  // Every write was checked as it was made (local file systems reserve the
  // room then); close(2) reports what a network file system reports late.
  // No fsync: the promise is that no write is lost silently, not durability across
  // a power cut (a batch closes thousands of logs).
  if (::close(std::exchange(fd_, -1)) != 0 && errno != EINTR) fail(reason(errno));
}

void write_output_file(const std::string& path, const std::string& what, std::string_view text) {
  OutputFile out(path, what);
  out.write(text);
  out.close();
}

void OutputFile::discard() noexcept {
  if (fd_ >= 0) ::close(std::exchange(fd_, -1));
  if (regular_) ::unlink(path_.c_str());
}

}  // namespace rtamp
