// Outputs that run out of room or are not regular files (util/output_file.hpp):
// a write that hits the file-size limit (RLIMIT_FSIZE, set in the child only:
// `ulimit -f`) is exit 2 naming the file and why — never exit 0, never
// SIGXFSZ — for run --log / --mcap, serve --log, batch -o / --log-dir and log
// to-mcap (whose half-written OUT is removed); a FIFO with a reader gets the
// whole log and stays a FIFO; as root, private character devices made with
// mknod in a temporary directory (a null and a full one, never the system's
// own /dev entries) are written directly and stay devices: the null one takes
// everything (exit 0), the full one is exit 2 "no space left on the device",
// and a zero one, read as a log, is refused after the 8 MiB line limit.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "run_cli.hpp"

namespace rtamp::cli::testing {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;  // exit code, -1 if killed
  int signal = 0;
  std::string err;
};

// Runs the binary in `dir` with an argument vector; `fsize`: RLIMIT_FSIZE in bytes (0: none).
Outcome run_in(const fs::path& dir, const std::vector<std::string>& args, rlim_t fsize = 0) {
  const std::string err = (dir / "loss.err").string(), out = (dir / "loss.out").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open("/dev/null", O_RDONLY);
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || o < 0 || e < 0) ::_exit(127);
    ::dup2(in, 0);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    if (fsize) {
      const rlimit lim{fsize, fsize};
      ::setrlimit(RLIMIT_FSIZE, &lim);
    }
    ::alarm(120);
    std::vector<char*> argv{const_cast<char*>(RTAMP_BIN)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(RTAMP_BIN, argv.data());
    ::_exit(127);
  }
  Outcome r;
  int status = 0;
  if (pid < 0 || ::waitpid(pid, &status, 0) != pid) return r;
  if (WIFEXITED(status)) r.code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.err = slurp(err);
  return r;
}

class OutputLoss : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void expect_lost(const Outcome& r, const std::string& option, const std::string& file,
                   const std::string& why) {
    EXPECT_EQ(r.signal, 0) << r.err;
    EXPECT_EQ(r.code, 2) << r.err;
    const std::string line = "rtamp: error: " + option + ": cannot write '" + file + "': " + why;
    EXPECT_NE(r.err.find(line), std::string::npos) << "expected '" << line << "' in: " << r.err;
  }
  fs::path dir_;
};

const std::vector<std::string> kRun = {"run",     "3-block-tray", "--world", "symbolic",
                                       "--quiet", "--rate",       "0.2"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& more) {
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

TEST_F(OutputLoss, AFileSizeLimitIsExit2NamingTheFileNeverSuccess) {
  const std::string too_large = "the file is too large";
  // Unlimited, the log is larger than 2 KiB: the limit is hit mid-episode.
  ASSERT_EQ(run_in(dir_, with(kRun, {"--log", "whole.jsonl"})).code, 0);
  ASSERT_GT(fs::file_size(dir_ / "whole.jsonl"), 4096u);
  Outcome r = run_in(dir_, with(kRun, {"--log", "ep.jsonl"}), 2048);
  expect_lost(r, "--log", "ep.jsonl", too_large);
  // What was written is kept, whole lines of the same episode up to the limit.
  const std::string kept = slurp(dir_ / "ep.jsonl"), whole = slurp(dir_ / "whole.jsonl");
  EXPECT_EQ(kept.substr(0, kept.find('\n')), whole.substr(0, whole.find('\n')));
  expect_lost(run_in(dir_, with(kRun, {"--mcap", "ep.mcap"}), 2048), "--mcap", "ep.mcap", too_large);
  expect_lost(run_in(dir_,
                     {"serve", "3-block-tray", "--world", "symbolic", "--port", "0", "--speed", "0",
                      "--exit-at-end", "--quiet", "--log", "sv.jsonl"},
                     2048),
              "--log", "sv.jsonl", too_large);
  expect_lost(
      run_in(dir_, {"batch", "3-block", "--world", "symbolic", "--trials", "30", "-q", "-o", "b.csv"}, 1024),
      "--output", "b.csv", too_large);
  r = run_in(
      dir_,
      {"batch", "3-block", "--world", "symbolic", "--trials", "3", "-q", "-o", "c.csv", "--log-dir", "logs"},
      4096);  // which episode's log reaches the limit first depends on the workers
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("rtamp: error: --log-dir: cannot write 'logs/"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".jsonl': the file is too large"), std::string::npos) << r.err;
  // log to-mcap: the half-written OUT does not stay.
  expect_lost(run_in(dir_, {"log", "to-mcap", "whole.jsonl", "out.mcap", "--compression", "none"}, 1024),
              "OUT", "out.mcap", too_large);
  EXPECT_FALSE(fs::exists(dir_ / "out.mcap"));
  // The same commands without the limit succeed (the limit, not the command, failed).
  EXPECT_EQ(run_in(dir_, {"log", "to-mcap", "whole.jsonl", "out.mcap", "--compression", "none"}).code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "out.mcap"));
}

TEST_F(OutputLoss, AFifoWithAReaderGetsTheWholeLogAndStaysAFifo) {
  const fs::path fifo = dir_ / "log.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  // The reader is there before the writer comes (rtamp refuses a FIFO without one), and
  // reads until the writer has gone.
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  std::string got;
  std::atomic<bool> done{false};
  std::thread reader([&] {
    char buf[4096];
    for (;;) {
      const bool last = done.load();
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n > 0) {
        got.append(buf, static_cast<std::size_t>(n));
        continue;
      }
      if (last) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  const Outcome r = run_in(dir_, with(kRun, {"--log", fifo.string()}));
  done = true;
  reader.join();
  ::close(fd);
  EXPECT_EQ(r.code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  ASSERT_FALSE(got.empty());
  EXPECT_EQ(got.rfind("{\"algorithm\"", 0), 0u) << got.substr(0, 80);
  const std::size_t last = got.rfind('\n', got.size() - 2);
  EXPECT_NE(got.find("\"ev\":\"end\"", last), std::string::npos);
}

// Private character devices (as root only): written directly, never replaced.
TEST_F(OutputLoss, PrivateDevicesAreWrittenDirectlyAndStayDevices) {
  if (::geteuid() != 0) GTEST_SKIP() << "mknod needs root";
  const fs::path null = dir_ / "null", full = dir_ / "full";
  if (::mknod(null.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0 ||
      ::mknod(full.c_str(), S_IFCHR | 0666, ::makedev(1, 7)) != 0)
    GTEST_SKIP() << "mknod is not allowed here";
  auto still_device = [](const fs::path& p, unsigned minor) {
    struct stat st {};
    ASSERT_EQ(::lstat(p.c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode)) << p << " is no longer a character device";
    EXPECT_EQ(::minor(st.st_rdev), minor);
  };
  // The null device takes everything: success, and still the device (as several outputs too).
  Outcome r = run_in(dir_, with(kRun, {"--log", null.string(), "--mcap", null.string()}));
  EXPECT_EQ(r.code, 0) << r.err;
  r = run_in(dir_, {"batch", "3-block", "--world", "symbolic", "--trials", "2", "-q", "-o", null.string()});
  EXPECT_EQ(r.code, 0) << r.err;
  still_device(null, 3);
  // The full device: every write fails — exit 2 with the reason, the node kept.
  expect_lost(
      run_in(dir_, {"batch", "3-block", "--world", "symbolic", "--trials", "2", "-q", "-o", full.string()}),
      "--output", full.string(), "no space left on the device");
  expect_lost(run_in(dir_, with(kRun, {"--log", full.string()})), "--log", full.string(),
              "no space left on the device");
  ASSERT_EQ(run_in(dir_, with(kRun, {"--log", "ep.jsonl"})).code, 0);
  expect_lost(run_in(dir_, {"log", "to-mcap", "ep.jsonl", full.string()}), "OUT", full.string(),
              "no space left on the device");
  still_device(full, 7);
  // An endless input (a private zero device): refused after the line limit, not read for ever
  // (serve --replay reads only regular files).
  const fs::path zero = dir_ / "zero";
  ASSERT_EQ(::mknod(zero.c_str(), S_IFCHR | 0666, ::makedev(1, 5)), 0);
  r = run_in(dir_, {"log", "to-mcap", zero.string(), "z.mcap"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(zero.string() + ":1: a line longer than 8 MiB"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "z.mcap"));
  r = run_in(dir_, {"serve", "3-block", "--world", "symbolic", "--port", "0", "--replay", zero.string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--replay: cannot read '" + zero.string() + "': it is not a regular file"),
            std::string::npos)
      << r.err;
  still_device(zero, 5);
  // --resume needs a regular file to resume from.
  r = run_in(dir_, {"batch", "3-block", "--world", "symbolic", "--trials", "2", "-q", "--resume", "-o",
                    null.string()});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--resume: '" + null.string() + "' is not a regular file"), std::string::npos)
      << r.err;
  still_device(null, 3);
}

}  // namespace
}  // namespace rtamp::cli::testing
