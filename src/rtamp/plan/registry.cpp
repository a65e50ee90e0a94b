#include "rtamp/plan/registry.hpp"

#include <algorithm>
#include <utility>

#include "rtamp/util/error.hpp"
#include "rtamp/util/named_registry.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::plan {

namespace {

std::unique_ptr<Heuristic> zero_heuristic(const ProductGraph&, Experience&) { return std::make_unique<ZeroHeuristic>(); }
std::unique_ptr<Heuristic> guard_heuristic(const ProductGraph& g, Experience&) {
  return std::make_unique<GuardHeuristic>(g);
}
std::unique_ptr<Heuristic> experience_heuristic(const ProductGraph& g, Experience& x) {
  return std::make_unique<ExperienceHeuristic>(g, x);
}

const std::vector<AlgorithmInfo> kAlgorithms = {
    {Algorithm::AStarExperience, "astar-exp",
     "A* with experience: keeps the product graph, learned bounds, solved paths and costs between plans", true,
     experience_heuristic},
    {Algorithm::AStar, "astar", "A* with the automaton-guard heuristic, cold on every plan", false, guard_heuristic},
    {Algorithm::Dijkstra, "dijkstra", "Dijkstra (no heuristic), cold on every plan", false, zero_heuristic},
};

NamedRegistry<CostModelInfo>& registry() {
  static NamedRegistry<CostModelInfo> r({
      {"euclid", "hand to the thing, then the thing to its destination, straight lines (metres)",
       [](const world::Scenario&) { return std::make_shared<EuclidCost>(); }},
      {"region", "centre of the thing's location to the destination's centre (metres)",
       [](const world::Scenario&) { return std::make_shared<RegionCost>(); }},
      {"unit", "1 per move", [](const world::Scenario&) { return std::make_shared<UnitCost>(); }},
  });
  return r;
}

}  // namespace

const std::vector<AlgorithmInfo>& algorithms() { return kAlgorithms; }

const AlgorithmInfo& algorithm_info(Algorithm a) {
  for (const auto& e : kAlgorithms)
    if (e.algorithm == a) return e;
  throw Error("unknown algorithm value " + std::to_string(static_cast<int>(a)));
}

std::vector<std::string> algorithm_names() {
  std::vector<std::string> out;
  for (const auto& e : kAlgorithms) out.emplace_back(e.name);
  return out;
}

Algorithm parse_algorithm(std::string_view name) {
  for (const auto& e : kAlgorithms)
    if (name == e.name) return e.algorithm;
  throw Error("unknown algorithm " + world::quoted(name) + world::suggestion(name, algorithm_names()));
}

void register_cost_model(CostModelInfo info) {
  if (info.name.empty() || !info.make) throw Error("a motion-cost model needs a name and a factory");
  registry().add(std::move(info));
}

std::vector<CostModelInfo> cost_models() { return registry().entries(); }

std::vector<std::string> cost_model_names() { return registry().names(); }

bool has_cost_model(std::string_view name) {
  const auto names = cost_model_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::shared_ptr<MotionCostModel> make_cost_model(std::string_view name, const world::Scenario& scenario) {
  const auto model = registry().find(name);
  if (!model)
    throw Error("unknown motion-cost model " + world::quoted(name) + world::suggestion(name, cost_model_names()));
  return model->make(scenario);
}

}  // namespace rtamp::plan
