// One row of a batch's results: the trial that was run (scenario, algorithm,
// BT variant, change kind, trial number, seed) and the episode's metrics
// (exec::EpisodeMetrics, the quantities of the paper's Table I and Fig. 4).
//
// Invariants: a batch or a merged set of slices holds at most one record per
// key() (scenario, algorithm, bt, change, trial); canonical_less() orders
// records by scenario, then change, algorithm and BT variant in the paper's
// order (trials.hpp ranks), then trial number — the order of the CSV files
// rtamp writes.
#pragma once

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

namespace rtamp::batch {

struct EpisodeRecord {
  std::string scenario;
  std::string algorithm;  // astar-exp | astar | dijkstra
  std::string bt;         // online-action | online-state | offline
  std::string change;     // relocate | remove | add | none
  int trial = 1;
  std::uint64_t seed = 0;
  bool success = false;
  std::string reason;
  double first_plan_s = 0;   // wall time of the first plan
  double replan_s = 0;       // total wall time of replans
  int replans = 0;
  std::uint64_t tree_changes = 0;
  double completion_s = 0;   // simulated time until the task was done
  double motion_cost = 0;    // m of tool path
  int interventions = 0;
  double wall_s = 0;         // wall time of the whole episode
  double rtf = 0;            // real-time factor (simulated / wall)

  std::tuple<const std::string&, const std::string&, const std::string&, const std::string&, int> key() const {
    return {scenario, algorithm, bt, change, trial};
  }
  bool operator==(const EpisodeRecord&) const = default;
};

// "scenario 3-block-tray, astar-exp, online-action, relocate, trial 7" — for messages.
std::string describe_key(const EpisodeRecord& r);

bool canonical_less(const EpisodeRecord& a, const EpisodeRecord& b);
void sort_canonical(std::vector<EpisodeRecord>& records);

}  // namespace rtamp::batch
