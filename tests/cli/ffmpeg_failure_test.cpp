// An ffmpeg that fails while `rtamp run --video` or `rtamp sim --video` runs
// ("external encoders fail with a clean error, never a signal"). A
// fake `ffmpeg` first on PATH either exits at once, reads a few frames and
// exits non-zero, or reads every frame and exits non-zero at the end. For
// each, and for both commands: rtamp exits (no signal, not SIGPIPE's 141)
// with code 2 and one line `rtamp: error: ...` naming ffmpeg and the video,
// and `run`'s episode log is complete: valid JSON Lines ending with the `end`
// record (`error` when the encoder failed during the episode).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "run_cli.hpp"

namespace rtamp::cli::testing {
namespace {

struct Fake {
  const char* name;
  const char* script;  // the fake ffmpeg's body
  bool during;         // fails while frames are still written
};

const Fake kFakes[] = {
    {"exits-at-once", "exit 1", true},
    {"reads-three-frames", "head -c 2764800 >/dev/null\nexit 1", true},  // 3 frames of 640x480 RGB
    {"fails-at-the-end", "cat >/dev/null\nexit 1", false},
};

// A directory holding only an executable `ffmpeg` running `f.script`; the
// assignment that puts it first on PATH (a child killed by a signal would
// show as the shell's 128 + signal, e.g. 141, not 2).
std::string path_with(const Fake& f) {
  const auto dir = scratch() / (std::string("bin-") + f.name);
  std::filesystem::create_directories(dir);
  const std::string exe =
      write_file(std::string("bin-") + f.name + "/ffmpeg", std::string("#!/bin/sh\n") + f.script + "\n");
  ::chmod(exe.c_str(), 0755);
  return "PATH='" + dir.string() + "':\"$PATH\" ";
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

void expect_clean_error(const Result& r, const std::string& video, const std::string& what) {
  EXPECT_EQ(r.rc, 2) << what << "\n" << r.err;
  const std::vector<std::string> err = lines(r.err);
  ASSERT_FALSE(err.empty()) << what;
  EXPECT_EQ(err.size(), 1u) << what << "\n" << r.err;
  EXPECT_EQ(err[0].rfind("rtamp: error: ", 0), 0u) << what << "\n" << r.err;
  EXPECT_NE(err[0].find("ffmpeg"), std::string::npos) << err[0];
  EXPECT_NE(err[0].find(video), std::string::npos) << err[0];
}

TEST(FfmpegFailure, RunEndsCleanlyWithACompleteLog) {
  for (const Fake& f : kFakes) {
    const auto dir = scratch();
    const std::string log = (dir / (std::string("run-") + f.name + ".jsonl")).string();
    const std::string video = (dir / (std::string("run-") + f.name + ".mp4")).string();
    const Result r = run_env(path_with(f), "run 3-block --quiet --no-operator --max-time 4 --log '" + log +
                                               "' --video '" + video + "'");
    expect_clean_error(r, video, f.name);
    const std::vector<std::string> records = lines(slurp(log));
    ASSERT_FALSE(records.empty()) << f.name;
    for (const std::string& l : records) EXPECT_TRUE(nlohmann::json::accept(l)) << f.name << ": " << l;
    const auto end = nlohmann::json::parse(records.back());
    EXPECT_EQ(end.at("ev"), "end") << f.name;
    if (f.during) {
      EXPECT_EQ(end.at("end"), "error") << f.name << ": " << end.dump();
      EXPECT_NE(end.at("reason").get<std::string>().find("ffmpeg"), std::string::npos) << end.dump();
    } else {
      EXPECT_NE(end.at("end"), "error") << f.name << ": " << end.dump();
    }
  }
}

TEST(FfmpegFailure, SimEndsCleanly) {
  for (const Fake& f : kFakes) {
    const std::string video = (scratch() / (std::string("sim-") + f.name + ".mp4")).string();
    const Result r = run_env(path_with(f), "sim 3-block --do 'move o1 r2' --video '" + video + "'");
    expect_clean_error(r, video, f.name);
  }
}

}  // namespace
}  // namespace rtamp::cli::testing
