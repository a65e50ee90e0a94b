// `rtamp batch --resume` and signals, through the built binary: a batch is
// killed (SIGKILL) once it has written some rows, a torn last line is added
// as a kill mid-write would leave it, the batch is resumed and interrupted
// (SIGINT: exit 130, every log of the log directory ends with its `end`
// record and every MCAP file with its footer, the CSV holds whole rows only),
// then resumed to its end. The merged
// CSV must have the rows of an uninterrupted run of the same seeds: equal in
// every column that does not measure wall time. Also: --resume refuses a CSV
// of another batch and changes nothing (the bad-input table has more).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../cli/run_cli.hpp"
#include "rtamp/batch/csv.hpp"

namespace {

namespace fs = std::filesystem;
namespace ct = rtamp::cli::testing;
using rtamp::batch::EpisodeRecord;

const std::vector<std::string> kBatch = {"batch",  "3-block-tray", "--world",  "symbolic", "--trials", "2000",
                                         "--algo", "astar-exp",    "--change", "relocate", "-q"};

pid_t spawn(const fs::path& dir, std::vector<std::string> args) {
  args.insert(args.begin(), kBatch.begin(), kBatch.end());
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string out = (dir / "batch.out").string(), err = (dir / "batch.err").string();
    if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(err.c_str(), "w", stderr) ||
        ::chdir(dir.c_str()))
      ::_exit(127);
    ::alarm(300);
    std::vector<char*> argv{const_cast<char*>(RTAMP_BIN)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(RTAMP_BIN, argv.data());
    ::_exit(127);
  }
  return pid;
}

int lines_of(const fs::path& p) {
  const std::string s = ct::slurp(p);
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

// Waits until `csv` has at least `rows` lines (or the process ended); then sends `sig`.
int interrupt_after(pid_t pid, const fs::path& csv, int rows, int sig) {
  int status = 0;
  while (lines_of(csv) < rows) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(pid, sig);
  ::waitpid(pid, &status, 0);
  return status;
}

// The columns that do not measure wall time (first_plan_s, replan_s, wall_s and rtf do).
std::string deterministic(const EpisodeRecord& r) {
  return r.scenario + "," + r.algorithm + "," + r.bt + "," + r.change + "," + std::to_string(r.trial) + "," +
         std::to_string(r.seed) + "," + std::to_string(r.success) + "," + r.reason + "," +
         std::to_string(r.replans) + "," + std::to_string(r.tree_changes) + "," +
         std::to_string(r.completion_s) + "," + std::to_string(r.motion_cost) + "," +
         std::to_string(r.interventions);
}

TEST(CliBatchResume, KilledThenInterruptedThenResumedEqualsAnUninterruptedRun) {
  const fs::path dir = ct::scratch() / "resume";
  fs::remove_all(dir);
  fs::create_directories(dir);
  int status = 0;
  ::waitpid(spawn(dir, {"-o", "whole.csv"}), &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ct::slurp(dir / "batch.err");
  const auto whole = rtamp::batch::read_csv_file((dir / "whole.csv").string());
  ASSERT_EQ(whole.size(), 2000u);

  // 1. SIGKILL: the rows written so far stay; a torn line as a kill mid-write leaves it.
  status = interrupt_after(spawn(dir, {"-o", "part.csv"}), dir / "part.csv", 60, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the batch ended before it was killed";
  const int after_kill = lines_of(dir / "part.csv");
  ASSERT_LT(after_kill, 2001);
  std::ofstream(dir / "part.csv", std::ios::app) << "3-block-tray,astar-exp,online-act";

  // 2. --resume, then SIGINT: exit 130, whole rows only, every log ended.
  status = interrupt_after(spawn(dir, {"-o", "part.csv", "--resume", "--log-dir", "logs", "--mcap"}), dir / "part.csv",
                           after_kill + 60, SIGINT);
  const std::string err = ct::slurp(dir / "batch.err");
  ASSERT_TRUE(WIFEXITED(status)) << err;
  ASSERT_EQ(WEXITSTATUS(status), 130) << err;
  EXPECT_NE(err.find("interrupted by SIGINT"), std::string::npos) << err;
  const auto interrupted =
      rtamp::batch::read_csv_file((dir / "part.csv").string());  // whole rows, or it throws
  EXPECT_GT(interrupted.size(), static_cast<std::size_t>(after_kill));
  EXPECT_LT(interrupted.size(), 2000u);
  EXPECT_TRUE(std::is_sorted(interrupted.begin(), interrupted.end(), rtamp::batch::canonical_less));
  int logs = 0;
  const std::string magic("\x89MCAP0\r\n", 8);
  for (const auto& e : fs::directory_iterator(dir / "logs")) {
    if (e.path().extension() == ".mcap") {  // closed: its summary and footer written, the magic last
      const std::string mcap = ct::slurp(e.path());
      ASSERT_GT(mcap.size(), 2 * magic.size()) << e.path();
      EXPECT_EQ(mcap.substr(mcap.size() - magic.size()), magic) << e.path() << " has no end";
      continue;
    }
    const std::string log = ct::slurp(e.path());
    ASSERT_FALSE(log.empty()) << e.path();
    const std::size_t last = log.rfind('\n', log.size() - 2);
    EXPECT_NE(log.find("\"ev\":\"end\"", last == std::string::npos ? 0 : last), std::string::npos)
        << e.path() << " has no end record";
    ++logs;
  }
  EXPECT_GE(logs, 60);

  // 3. --resume to the end: the rows of the uninterrupted run.
  ::waitpid(spawn(dir, {"-o", "part.csv", "--resume"}), &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ct::slurp(dir / "batch.err");
  const auto merged = rtamp::batch::read_csv_file((dir / "part.csv").string());
  ASSERT_EQ(merged.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i)
    ASSERT_EQ(deterministic(merged[i]), deterministic(whole[i])) << i;

  // 4. Resuming a finished batch runs nothing and keeps every row.
  const std::string before = ct::slurp(dir / "part.csv");
  ::waitpid(spawn(dir, {"-o", "part.csv", "--resume"}), &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(ct::slurp(dir / "part.csv"), before);
}

TEST(CliBatchResume, SigtermIsExit143WithTheSummaryOfWhatRan) {
  const fs::path dir = ct::scratch() / "term";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const int status = interrupt_after(spawn(dir, {"-o", "t.csv", "--json"}), dir / "t.csv", 40, SIGTERM);
  ASSERT_TRUE(WIFEXITED(status)) << ct::slurp(dir / "batch.err");
  EXPECT_EQ(WEXITSTATUS(status), 143);
  const auto rows = rtamp::batch::read_csv_file((dir / "t.csv").string());
  const std::string out = ct::slurp(dir / "batch.out");  // the JSON summary of the rows that ran
  EXPECT_NE(out.find("\"episodes\": " + std::to_string(rows.size())), std::string::npos)
      << out.substr(0, 200);
}

}  // namespace
