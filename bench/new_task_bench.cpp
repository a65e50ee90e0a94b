// A new task while the robot works: the planner's replan after a task change
// (Planner::set_task on a planner that has planned the scenario's task: the
// TS and the motion-cost cache kept) against a cold first plan of the same
// new task (a new Planner: what starting a new episode costs), in one run.
// Args: scene (0: 3-block-tray, 1: `rtamp gen -m 5 -n 8`, its regions on an arc in reach), cost model
// (0: euclid, 1: ik). Counters: expansions, the model's cost evaluations.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <memory>

#include "rtamp/plan/planner.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

world::Scenario scene(std::int64_t which) {
  if (which == 0) {
    world::Scenario s = world::load_scenario("3-block-tray");
    s.task = "F G all_in_r2";
    return s;
  }
  world::GeneratorOptions g;
  g.regions = 5;
  g.objects = 8;
  g.seed = 1;
  world::Scenario s = world::generate_scenario(g);
  // Generated regions lie on a 2 m line, beyond the UR5's reach at both ends:
  // set them on an arc of radius 0.55 m in front of the base (the blocks move with r1).
  const world::Vec3 old = s.regions[0].center;
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const double a = (-60.0 + 30.0 * static_cast<double>(i)) * 3.14159265358979 / 180.0;
    s.regions[i].center = {0.55 * std::cos(a), 0.55 * std::sin(a), 0};
  }
  for (auto& o : s.objects)
    for (int k = 0; k < 2; ++k) o.position[static_cast<std::size_t>(k)] += s.regions[0].center[static_cast<std::size_t>(k)] - old[static_cast<std::size_t>(k)];
  s.task = "F G \"all block in r2\"";
  return s;
}

// The new task: 3-block-tray: the blocks into r2 with the tray left in r1; gen: into r3.
world::TaskChange new_task(std::int64_t which) {
  world::TaskChange c;
  c.task = which == 0 ? "F G (\"all block in r2\" & \"r3 in r1\")" : "F G \"all block in r3\"";
  c.by = "bench";
  return c;
}

// The cost model by name, counting its evaluations.
class Counting final : public plan::MotionCostModel {
 public:
  explicit Counting(std::shared_ptr<plan::MotionCostModel> inner) : inner_(std::move(inner)) {}
  std::string name() const override { return inner_->name(); }
  double cost(const plan::MotionQuery& q) const override {
    calls.fetch_add(1, std::memory_order_relaxed);
    return inner_->cost(q);
  }
  double lower_bound(const plan::MotionQuery& q, bool anywhere) const override {
    return inner_->lower_bound(q, anywhere);
  }
  unsigned depends() const override { return inner_->depends(); }
  bool expensive() const override { return inner_->expensive(); }
  double transport_bound(const plan::TransportQuery& t) const override { return inner_->transport_bound(t); }
  double carry_bound(const world::Vec3& a, const world::Vec3& b) const override { return inner_->carry_bound(a, b); }
  double carry_set_bound(const world::Vec3* f, const world::Vec3* t, std::size_t n) const override {
    return inner_->carry_set_bound(f, t, n);
  }
  double join_set_bound(const plan::JoinPoints* p, std::size_t n) const override { return inner_->join_set_bound(p, n); }
  mutable std::atomic<long> calls{0};

 private:
  std::shared_ptr<plan::MotionCostModel> inner_;
};

plan::PlannerOptions options(const world::Scenario& s, std::int64_t cost, std::shared_ptr<Counting>& counted) {
  robot::register_ik_cost_model();
  plan::PlannerOptions o;
  counted = std::make_shared<Counting>(plan::make_cost_model(cost == 0 ? "euclid" : "ik", s));
  o.model = counted;
  return o;
}

void BM_ReplanAfterTaskChange(benchmark::State& state) {
  const world::Scenario s = scene(state.range(0));
  const world::TaskChange c = new_task(state.range(0));
  double expanded = 0, calls = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::shared_ptr<Counting> model;
    auto planner = std::make_unique<plan::Planner>(s, options(s, state.range(1), model));
    if (!planner->plan().found) {
      state.ResumeTiming();
      state.SkipWithError("the first task has no plan");
      break;
    }
    const long before = model->calls.load();
    state.ResumeTiming();
    planner->set_task(c);
    const plan::PlanResult r = planner->plan();
    if (!r.found) {
      state.SkipWithError("the new task has no plan");
      break;
    }
    state.PauseTiming();
    expanded += static_cast<double>(r.stats.expanded);
    calls += static_cast<double>(model->calls.load() - before);
    planner.reset();
    state.ResumeTiming();
  }
  state.counters["expanded"] = benchmark::Counter(expanded, benchmark::Counter::kAvgIterations);
  state.counters["cost_calls"] = benchmark::Counter(calls, benchmark::Counter::kAvgIterations);
}

void BM_ColdPlanOfTheNewTask(benchmark::State& state) {
  world::Scenario s = scene(state.range(0));
  s.task = new_task(state.range(0)).task;
  double expanded = 0, calls = 0;
  for (auto _ : state) {
    std::shared_ptr<Counting> model;
    plan::Planner planner(s, options(s, state.range(1), model));
    const plan::PlanResult r = planner.plan();
    if (!r.found) {
      state.SkipWithError("the new task has no plan");
      break;
    }
    expanded += static_cast<double>(r.stats.expanded);
    calls += static_cast<double>(model->calls.load());
  }
  state.counters["expanded"] = benchmark::Counter(expanded, benchmark::Counter::kAvgIterations);
  state.counters["cost_calls"] = benchmark::Counter(calls, benchmark::Counter::kAvgIterations);
}

void args(benchmark::internal::Benchmark* b) {
  for (std::int64_t scene = 0; scene < 2; ++scene)
    for (std::int64_t cost = 0; cost < 2; ++cost) b->Args({scene, cost});
  b->ArgNames({"scene", "ik"})->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_ReplanAfterTaskChange)->Apply(args);
BENCHMARK(BM_ColdPlanOfTheNewTask)->Apply(args);

}  // namespace

BENCHMARK_MAIN();
