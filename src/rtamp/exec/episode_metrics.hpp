// What one episode of the reactive loop measured (the quantities of the
// paper's Table I and Fig. 4, plus what a user needs to tell how it ended).
// A plain value type: logs, the CLI and the experiments layer format it.
// Invariants: completion_time is set iff success; interventions ==
// interventions_applied + interventions_refused.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtamp::exec {

// Why an episode ended.
enum class EndReason {
  None,           // still running
  TaskDone,       // every step done and staying here satisfies the task
  Cycles,         // a recurring task completed the requested number of cycles
  Unsatisfiable,  // the history observed so far leaves no way to satisfy the task
  NoPlan,         // the planner found no plan from the observed state
  GaveUp,         // too many failed moves in a row
  Lost,           // a thing stayed outside every region and container
  TimeLimit,      // max_time of world time passed
  Interrupted,    // stop() was called (SIGINT / SIGTERM in the CLI)
  Error,          // an exception (a bug or a world that broke its contract)
};
const char* to_string(EndReason r);

// One task that was in force during the episode: the scenario's, then each
// new one (docs/exec.md "A new task").
struct TaskOutcome {
  double time = 0;                   // world seconds at which it took effect
  std::string task;                  // the formula
  std::string by;                    // who gave it: scenario, script, command line, page, api, ...
  std::size_t automaton_states = 0;  // of its automaton
  int cycles = 0;                    // cycles completed while it was in force
  std::string outcome;               // "superseded" (a newer task replaced it), else the episode's end
};

struct EpisodeMetrics {
  bool success = false;
  EndReason end = EndReason::None;
  std::string reason;                     // readable: why it ended
  double first_plan_seconds = 0;          // wall time of the first plan
  double replan_seconds = 0;              // total wall time of replans
  int replans = 0;
  std::size_t tree_changes = 0;           // subtrees inserted + removed, over the episode
  std::optional<double> completion_time;  // world seconds until the task was done (success only)
  double motion_cost = 0;                 // tool path travelled (m), when the world measures it
  int interventions = 0;                  // reported by the world, applied or refused
  int interventions_applied = 0, interventions_refused = 0;
  int actions_succeeded = 0, actions_failed = 0;
  int cycles = 0;                         // completed cycles of the recurring task in force
  std::vector<TaskOutcome> tasks;         // every task in force, in order (the scenario's first)
  std::size_t run_length = 0;             // states of the observed run
  double world_time = 0;                  // world seconds at the end
  double wall_seconds = 0;
  double real_time_factor = 0;            // world time / wall time
  std::uint64_t seed = 0;
};

}  // namespace rtamp::exec
