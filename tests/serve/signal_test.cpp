// `rtamp serve` through the built binary under SIGINT and SIGTERM:
// a live symbolic episode at speed 1, with a page-like WebSocket client
// connected or none, is interrupted mid-episode; the process exits 130
// (SIGINT) or 143 (SIGTERM) — it does not hang on a connected client — and
// its --log ends with the `end` record of an interrupted episode, as `rtamp
// run` does (tests/cli/run_test.cpp).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "rtamp_source_dir.hpp"
#include "ws_client.hpp"

extern char** environ;

namespace rtamp::serve {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Served {
  pid_t pid = -1;
  unsigned short port = 0;
};

// Starts `rtamp serve` with stdout to `out`; returns once it printed its address.
Served start(const std::vector<std::string>& args, const fs::path& out) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> all = {RTAMP_BIN};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  Served s;
  EXPECT_EQ(posix_spawn(&s.pid, RTAMP_BIN, &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  // Waits for "rtamp serve: http://127.0.0.1:PORT/" (a generous bound: only a
  // server that never starts fails here).
  const auto end = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < end) {
    const std::string text = slurp(out);
    const std::string key = "http://127.0.0.1:";
    if (auto p = text.find(key); p != std::string::npos && text.find('/', p + key.size()) != std::string::npos) {
      s.port = static_cast<unsigned short>(std::stoi(text.substr(p + key.size())));
      return s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return s;
}

// The exit status of `pid`, or nullopt if it has not exited after a minute
// (then it is killed: a hang).
std::optional<int> exit_code(pid_t pid) {
  const auto end = Clock::now() + std::chrono::seconds(60);
  int status = 0;
  while (Clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return std::nullopt;
}

TEST(ServeSignals, InterruptEndsTheEpisodeWithItsEndRecord) {
  const fs::path dir = fs::temp_directory_path() / ("rtamp-serve-signal-" + std::to_string(getpid()));
  fs::create_directories(dir);
  for (const bool client : {false, true})
    for (const auto& [sig, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
      SCOPED_TRACE(std::string(client ? "a client, " : "no client, ") + (sig == SIGINT ? "SIGINT" : "SIGTERM"));
      const fs::path log = dir / "episode.jsonl", out = dir / "stdout.txt";
      fs::remove(log);
      // 3-block takes tens of seconds of world time: at speed 1 the signal
      // arrives mid-episode.
      const Served s = start({"serve", "3-block", "--world", "symbolic", "--port", "0", "--quiet", "--log",
                              log.string(), "--web-root", dir.string()},
                             out);
      ASSERT_GT(s.port, 0) << slurp(out);
      std::optional<test::WsClient> page;
      if (client) {
        page.emplace(s.port);
        // The episode is under way: a log record has reached the page.
        ASSERT_TRUE(page->read_until([](const nlohmann::json& m) { return m.value("type", "") == "log"; }));
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
      }
      ASSERT_EQ(kill(s.pid, sig), 0);
      const std::optional<int> rc = exit_code(s.pid);
      ASSERT_TRUE(rc.has_value()) << "rtamp serve did not exit";
      EXPECT_EQ(*rc, code);
      std::istringstream in(slurp(log));
      std::string line, last;
      while (std::getline(in, line)) last = line;
      ASSERT_FALSE(last.empty());
      const auto end = nlohmann::json::parse(last);
      EXPECT_EQ(end.at("ev"), "end");
      EXPECT_EQ(end.at("end"), "interrupted");
      EXPECT_TRUE(end.at("metrics").at("completion_time").is_null());
    }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtamp::serve
