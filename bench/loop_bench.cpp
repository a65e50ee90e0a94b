// The reactive loop (exec::ReactiveLoop, Algorithm 1) on the symbolic world:
// whole episodes of 3-block-tray with random interventions, one episode per
// iteration (seeds 1, 2, 3, ... so every iteration is a different episode;
// the sequence is the same on every run). items_per_second = episodes per
// second on one core (planning inline, on the benchmark's thread).
//
// Counters: replan_median_us / replan_p90_us — the wall time of the replans
// made inside the episodes (from the tracked automaton states), over every
// episode of the run; success — the fraction of episodes that succeeded;
// replans — per episode.
//
//   BM_SymbolicEpisode/0   random relocate / add / remove (the paper's kinds), 1 per second
//                          during the first 20 s of the episode (it takes about 40 s)
//   BM_SymbolicEpisode/1   all six kinds (also add/remove tray, take from the gripper), likewise
//   BM_SymbolicEpisode/2   no intervention but the scenario's script
//   BM_SymbolicEpisode/3   random relocations only, 1 per second during the first 20 s
//                          (every episode can succeed: nothing is added or removed)
//
// RTAMP_LOOP_EPISODES=N runs every benchmark for exactly N iterations (episodes,
// seeds 1..N): a fixed amount of work, for instruction counts under
// `valgrind --tool=callgrind` that do not depend on the machine's load.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

struct ReplanTimes : exec::EpisodeObserver {
  std::vector<double>* out;
  explicit ReplanTimes(std::vector<double>* o) : out(o) {}
  void on_plan(double, const exec::PlanEvent& e) override {
    if (!e.first) out->push_back(e.result.stats.seconds);
  }
};

void BM_SymbolicEpisode(benchmark::State& state) {
  const world::Scenario scenario = world::load_scenario("3-block-tray");
  using K = world::Intervention::Kind;
  exec::SymbolicWorldOptions wo;
  world::PersonOptions po;
  po.script = scenario.interventions;
  if (state.range(0) < 2) {
    po.rate = 1;
    po.end = 20;
  }
  if (state.range(0) == 0) po.kinds = {K::Relocate, K::Add, K::Remove};
  if (state.range(0) == 3) {
    po.rate = 1;
    po.end = 20;
    po.kinds = {K::Relocate};
  }
  exec::LoopOptions lo;
  lo.planning = exec::PlanningMode::Inline;
  lo.max_time = 300;
  std::vector<double> replans;
  ReplanTimes times(&replans);
  std::uint64_t seed = 0, succeeded = 0, episodes = 0, replan_count = 0;
  for (auto _ : state) {
    wo.seed = po.seed = ++seed;
    exec::SymbolicWorld world(scenario, wo);
    world::Person person(scenario, po);
    exec::PersonWorld acted(world, person);
    exec::ReactiveLoop loop(acted, scenario, lo);
    loop.add_observer(times);
    const exec::EpisodeMetrics& m = loop.run();
    succeeded += m.success ? 1 : 0;
    replan_count += static_cast<std::uint64_t>(m.replans);
    ++episodes;
    benchmark::DoNotOptimize(m.world_time);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(episodes));
  state.counters["success"] = episodes ? double(succeeded) / double(episodes) : 0;
  state.counters["replans"] = episodes ? double(replan_count) / double(episodes) : 0;
  if (!replans.empty()) {
    std::sort(replans.begin(), replans.end());
    state.counters["replan_median_us"] = replans[replans.size() / 2] * 1e6;
    state.counters["replan_p90_us"] = replans[replans.size() * 9 / 10] * 1e6;
  }
}
}  // namespace

int main(int argc, char** argv) {
  auto* b = benchmark::RegisterBenchmark("BM_SymbolicEpisode", BM_SymbolicEpisode);
  b->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMicrosecond);
  if (const char* n = std::getenv("RTAMP_LOOP_EPISODES")) b->Iterations(std::atoll(n));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
