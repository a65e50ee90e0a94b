// Test support: run the rtamp binary through the shell and capture its exit
// code, standard output and standard error.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "rtamp_source_dir.hpp"

namespace rtamp::cli::testing {

struct Result {
  int rc = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A scratch directory for this test process.
inline std::filesystem::path scratch() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("rtamp_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// Runs `ENV RTAMP_BIN <args>` (args is shell text, quote it yourself; env:
// shell variable assignments for the command, e.g. "PATH=/x:\"$PATH\" "),
// optionally with `stdin_text` on standard input.
inline Result run_env(const std::string& env, const std::string& args, const std::string* stdin_text = nullptr) {
  const auto dir = scratch();
  std::string cmd = env + "'" + RTAMP_BIN + "' " + args + " >'" + (dir / "out").string() + "' 2>'" +
                    (dir / "err").string() + "'";
  if (stdin_text) {
    std::ofstream(dir / "in", std::ios::binary) << *stdin_text;
    cmd += " <'" + (dir / "in").string() + "'";
  } else {
    cmd += " </dev/null";
  }
  Result r;
  const int status = std::system(cmd.c_str());
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  return r;
}

inline Result run(const std::string& args, const std::string* stdin_text = nullptr) {
  return run_env("", args, stdin_text);
}

inline std::string write_file(const std::string& name, const std::string& text) {
  const auto p = scratch() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

}  // namespace rtamp::cli::testing
