// The planner's named choices in one place: search algorithms (paper Section
// III.C: Dijkstra, A* with the guard heuristic, A* with experience) and
// motion-cost models (the edge weight w of Section III.B), each a name, a
// one-line description and a factory. The CLI's option checks and --help, the
// batch grid and the planner itself read these tables, so a name is spelled
// and parsed in exactly one place.
//
// Algorithms are a fixed table (plan::Algorithm). Cost models are a registry
// that starts with the closed-form models euclid, region and unit; other
// layers add theirs by an explicit call (the robot layer's `ik`:
// robot::register_ik_cost_model() in robot/ik_motion_cost.hpp; nothing is
// registered on link or load). Registering a name again replaces its entry.
//
// Invariants: names are unique within their table; parse_algorithm() and
// make_cost_model() accept exactly the listed names and throw rtamp::Error
// with a did-you-mean (or the list of names) otherwise; the registry is safe to
// read and extend from several threads.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/plan/algorithm.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::plan {

struct AlgorithmInfo {
  Algorithm algorithm;
  const char* name;         // as on the command line: "astar-exp"
  const char* description;  // one line, no final period
  // The planner keeps the product graph, learned bounds and the cost cache
  // between plans (else every plan starts cold).
  bool keeps_experience;
  // The search's heuristic for graph `g`, whose experience is `x` (both must
  // outlive it; only astar-exp's heuristic reads x).
  std::unique_ptr<Heuristic> (*make_heuristic)(const ProductGraph& g, Experience& x);
};

// Every algorithm, in the paper's Table I order (astar-exp, astar, dijkstra).
const std::vector<AlgorithmInfo>& algorithms();
const AlgorithmInfo& algorithm_info(Algorithm a);
// "dijkstra" | "astar" | "astar-exp"; throws rtamp::Error ("unknown algorithm
// 'astr' (did you mean 'astar'?)") otherwise.
Algorithm parse_algorithm(std::string_view name);
std::vector<std::string> algorithm_names();

// A model for a scenario (models such as ik read the robot's pose from it).
using CostModelFactory = std::function<std::shared_ptr<MotionCostModel>(const world::Scenario&)>;

struct CostModelInfo {
  std::string name;
  std::string description;  // one line, no final period
  CostModelFactory make;
};

// Adds (or replaces, by name) a model. Throws rtamp::Error for an empty name or factory.
void register_cost_model(CostModelInfo info);
// A snapshot of the registry, in registration order (built-ins first).
std::vector<CostModelInfo> cost_models();
std::vector<std::string> cost_model_names();
bool has_cost_model(std::string_view name);
// The model named `name` for `scenario`; throws rtamp::Error ("unknown
// motion-cost model 'eucild' (did you mean 'euclid'?)") otherwise.
std::shared_ptr<MotionCostModel> make_cost_model(std::string_view name, const world::Scenario& scenario = {});

}  // namespace rtamp::plan
