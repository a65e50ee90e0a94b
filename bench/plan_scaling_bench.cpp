// How the cost of a cold plan grows with the number of objects and of
// regions, for four kinds of task (docs/design.md "Benchmarks"; the figure and
// table are in docs/benchmarks.md, "Scaling").
//
//   BM_PlanScaling/<task>/<M>/<n>/<C>  a cold A* plan (partial construction,
//                                   `euclid`, interchangeable objects merged)
//                                   on `rtamp gen --regions M --objects n
//                                   --containers C --layout line` with the task below
//
// Tasks (every block starts in r1; regions lie on a line 0.5 m apart):
//   0 reach     F G all_in_r2                       move everything once
//   1 sequence  F (all_in_r3 & F G all_in_r2)       gather in r3, then settle in r2
//   2 split     F G (half_in_r2 & half_in_r3)       ceil(n/2) blocks to r2, floor(n/2) to r3
//   3 patrol    G F all_in_r2 & G F all_in_r3       a cycle that moves everything twice
// Grids: n = 1..48 at M = 5 and M = 3..64 at n = 4, no trays (C = 0), and
// n = 1..8 at M = 5 with C = 1, 2, 3 trays (rtamp gen puts them in r2 onwards).
// Counters: regions, objects, trays, task, generated, expanded, memory_bytes,
// bytes_per_node, cost, limit. A plan that stops at a limit (20 s, 40 M
// nodes) is never reported as a time: its run is an error "limit: ...", its
// label "<task> limit" and its counter limit is 1 (0 for every finished plan).
//
//   BM_PlanAcceptance/<task>/<n>/<tb>  the same cold A* plan (task 1 sequence or
//                                   3 patrol, M = 5, no trays) searching the
//                                   state-based automaton (tb = 0) or the
//                                   transition-based one (tb = 1, acceptance on
//                                   the product's edges); counters expanded,
//                                   cycle_searches, graph_nodes,
//                                   automaton_states, cost (docs/benchmarks.md
//                                   "Acceptance on transitions").
//   BM_PlanGeneralized/<n>/<trays>/<gen>/<algo>  the patrol (M = 5, n objects,
//                                   trays) searched transition-based with its
//                                   one-set automaton (gen = 0) or its 2-set
//                                   generalized one (gen = 1), by A* (algo = 0)
//                                   or Dijkstra (1); counters as above
//                                   (docs/benchmarks.md "Generalized acceptance
//                                   in the product").
// Machine-readable output for the plot (scripts/plot-scaling):
//   build/bench/plan_scaling_bench --benchmark_out_format=csv
//       --benchmark_out=docs/results/plan-scaling.csv
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "rtamp/plan/planner.hpp"
#include "rtamp/world/generator.hpp"

namespace {

using namespace rtamp;

const char* kTaskNames[] = {"reach", "sequence", "split", "patrol"};

world::Scenario scaling_scenario(int task, int regions, int objects, int trays) {
  world::GeneratorOptions g;
  g.regions = regions;
  g.objects = objects;
  g.containers = trays;
  g.layout = world::GeneratorOptions::Layout::Line;
  switch (task) {
    case 0: break;  // F G all_in_r2 (the generator's default)
    case 1:
      g.task = "F (all_in_r3 & F G all_in_r2)";
      g.propositions = {{"all_in_r3", "all block in r3"}};
      break;
    case 2:
      g.task = "F G (half_in_r2 & half_in_r3)";
      g.propositions = {{"half_in_r2", "count block in r2 >= " + std::to_string((objects + 1) / 2)},
                        {"half_in_r3", "count block in r3 >= " + std::to_string(objects / 2)}};
      break;
    default:
      g.task = "G F all_in_r2 & G F all_in_r3";
      g.propositions = {{"all_in_r3", "all block in r3"}};
  }
  return world::generate_scenario(g);
}

void BM_PlanScaling(benchmark::State& state) {
  const int task = static_cast<int>(state.range(0));
  const int regions = static_cast<int>(state.range(1));
  const int objects = static_cast<int>(state.range(2));
  const int trays = static_cast<int>(state.range(3));
  const world::Scenario scenario = scaling_scenario(task, regions, objects, trays);
  plan::PlannerOptions o;
  o.algorithm = plan::Algorithm::AStar;
  o.cost = "euclid";
  o.limits.time_limit = 20;
  o.limits.max_nodes = 40'000'000;
  o.limits.max_memory_bytes = 0;  // the node and time limits bound these runs
  plan::PlanResult r;
  bool limit = false;
  for (auto _ : state) {
    plan::Planner p(scenario, o);  // translation and TS set-up are not timed
    (void)p.system();
    r = p.plan();
    limit = r.stats.hit_node_limit || r.stats.hit_time_limit || r.stats.hit_memory_limit;
    if (limit || !r.found) break;  // no time is recorded for a plan that did not finish
    state.SetIterationTime(r.stats.seconds);
  }
  state.counters["task"] = task;
  state.counters["regions"] = regions;
  state.counters["objects"] = objects;
  state.counters["trays"] = trays;
  state.counters["generated"] = double(r.stats.generated);
  state.counters["expanded"] = double(r.stats.expanded);
  state.counters["memory_bytes"] = double(r.stats.memory_bytes);
  state.counters["bytes_per_node"] = r.stats.bytes_per_node();
  state.counters["cost"] = r.found && !limit ? r.plan.cost() : -1;
  state.counters["limit"] = limit ? 1 : 0;
  if (limit) {
    state.SetLabel(std::string(kTaskNames[task]) + " limit");
    state.SkipWithError(("limit: " + (r.message.empty() ? std::string("stopped at a limit") : r.message)).c_str());
    return;
  }
  if (!r.found) {
    state.SkipWithError(("no plan: " + r.message).c_str());
    return;
  }
  state.SetLabel(kTaskNames[task]);
}

void scaling_grid(benchmark::internal::Benchmark* b) {
  for (int task = 0; task < 4; ++task) {
    for (int n : {1, 2, 4, 6, 8, 12, 16, 20, 24, 32, 40, 48}) b->Args({task, 5, n, 0});
    for (int m : {3, 8, 12, 16, 24, 32, 48, 64}) b->Args({task, m, 4, 0});  // M = 5 is in the row above
    for (int c = 1; c <= 3; ++c)  // trays: objects up to where the product outgrows the limits
      for (int n : {1, 2, 4, 6, 8}) b->Args({task, 5, n, c});
  }
}
BENCHMARK(BM_PlanScaling)->Apply(scaling_grid)->UseManualTime()->Unit(benchmark::kMillisecond);

// Cold plans of `scenario` with `o` (translation and TS set-up not timed);
// the counters of the last, or the error of a limit or of no plan.
void plan_and_count(benchmark::State& state, const world::Scenario& scenario, const plan::PlannerOptions& o,
                    const std::string& label) {
  plan::PlanResult r;
  std::uint32_t states = 0;
  for (auto _ : state) {
    plan::Planner p(scenario, o);
    (void)p.system();
    states = p.automaton().num_states();
    r = p.plan();
    if (!r.found || r.stats.hit_node_limit || r.stats.hit_time_limit) break;
    state.SetIterationTime(r.stats.seconds);
  }
  if (r.stats.hit_node_limit || r.stats.hit_time_limit) {
    state.SkipWithError(("limit: " + (r.message.empty() ? std::string("stopped at a limit") : r.message)).c_str());
    return;
  }
  if (!r.found) {
    state.SkipWithError(("no plan: " + r.message).c_str());
    return;
  }
  state.counters["expanded"] = double(r.stats.expanded);
  state.counters["cycle_searches"] = double(r.stats.cycle_searches);
  state.counters["graph_nodes"] = double(r.stats.graph_nodes);
  state.counters["automaton_states"] = states;
  state.counters["cost"] = r.plan.cost();
  state.SetLabel(label);
}

void BM_PlanAcceptance(benchmark::State& state) {
  const int task = static_cast<int>(state.range(0));
  const int objects = static_cast<int>(state.range(1));
  const bool tb = state.range(2) != 0;
  plan::PlannerOptions o;
  o.algorithm = plan::Algorithm::AStar;
  o.cost = "euclid";
  o.transition_based = tb;
  plan_and_count(state, scaling_scenario(task, 5, objects, 0), o,
                 std::string(kTaskNames[task]) + (tb ? " transition" : " state"));
}
BENCHMARK(BM_PlanAcceptance)
    ->ArgsProduct({{1, 3}, {4, 8, 16}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_PlanGeneralized(benchmark::State& state) {
  const int objects = static_cast<int>(state.range(0));
  const int trays = static_cast<int>(state.range(1));
  const bool gen = state.range(2) != 0;
  const bool dijkstra = state.range(3) != 0;
  plan::PlannerOptions o;
  o.algorithm = dijkstra ? plan::Algorithm::Dijkstra : plan::Algorithm::AStar;
  o.cost = "euclid";
  o.transition_based = true;
  o.generalized = gen ? plan::PlannerOptions::Generalized::Always : plan::PlannerOptions::Generalized::Never;
  o.limits.time_limit = 20;
  o.limits.max_nodes = 40'000'000;
  o.limits.max_memory_bytes = 0;
  plan_and_count(state, scaling_scenario(3, 5, objects, trays), o,
                 std::string(gen ? "generalized" : "one set") + (dijkstra ? " dijkstra" : " astar"));
}
void generalized_grid(benchmark::internal::Benchmark* b) {
  for (const auto& [n, trays] : {std::pair{4, 0}, {6, 0}, {4, 2}})
    for (int gen : {0, 1})
      for (int dijkstra : {0, 1}) b->Args({n, trays, gen, dijkstra});
}
BENCHMARK(BM_PlanGeneralized)
    ->Apply(generalized_grid)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
