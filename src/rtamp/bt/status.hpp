// rtamp::bt::Status — the four return values of a behavior-tree node (paper
// Section III.D: SUCCESS, RUNNING, FAILURE, INVALID), with py_trees /
// BehaviorTree.CPP meaning. INVALID is "not ticked in the current run, or
// halted"; tick() never returns it (the engine rejects it).
#pragma once

#include <cstdint>
#include <string_view>

namespace rtamp::bt {

enum class Status : std::uint8_t { Invalid = 0, Running = 1, Success = 2, Failure = 3 };

// "INVALID", "RUNNING", "SUCCESS", "FAILURE".
constexpr std::string_view to_string(Status s) {
  switch (s) {
    case Status::Invalid:
      return "INVALID";
    case Status::Running:
      return "RUNNING";
    case Status::Success:
      return "SUCCESS";
    case Status::Failure:
      return "FAILURE";
  }
  return "?";
}

// The marker of the terminal rendering: "[-]" invalid, "[*]" running, "[o]" success, "[x]" failure.
constexpr std::string_view status_marker(Status s) {
  switch (s) {
    case Status::Invalid:
      return "[-]";
    case Status::Running:
      return "[*]";
    case Status::Success:
      return "[o]";
    case Status::Failure:
      return "[x]";
  }
  return "[?]";
}

constexpr bool is_done(Status s) { return s == Status::Success || s == Status::Failure; }

}  // namespace rtamp::bt
