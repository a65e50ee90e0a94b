// Simulation speed on the 3-block-tray scenario (issue "The robot and its world": the
// bar is >= 50x real time including control and perception; bare MuJoCo ~60x).
//   BM_SimBareStep         mj_step1/mj_step2 with gravity compensation, arm holding still
//   BM_SimControlledStep   controller tracking a pick trajectory + the above
//   BM_SimEpisode          whole episode: plan + execute pick/place of all blocks onto the
//                          tray, carry it to r2; perception every 10 ms (a 100 Hz BT tick)
//   BM_IkCostColdMujocoChecks / BM_IkCostCachedMujocoChecks   one `ik` edge cost with
//                          MuJoCo collision checks, cold (cache cleared) and cached
// Counter rtf = simulated seconds per CPU second.
#include <benchmark/benchmark.h>

#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/sim/session.hpp"
#include "rtamp/sim/skill_runner.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

void BM_SimBareStep(benchmark::State& state) {
  sim::Simulation s(world::load_scenario("3-block-tray"));
  for (auto _ : state) s.step();
  state.counters["rtf"] = benchmark::Counter(static_cast<double>(state.iterations()) * s.timestep(),
                                             benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimBareStep);

void BM_SimControlledStep(benchmark::State& state) {
  sim::Session session(world::load_scenario("3-block-tray"));
  sim::Percept percept;
  long n = 0;
  for (auto _ : state) {
    if (session.controller().status() != sim::Status::Running) {
      state.PauseTiming();
      if (session.sim().held() >= 0) session.skills().start_place(session.sim().held() == session.sim().find("o1") ? "r2" : "r1");
      else session.skills().start_pick("o1");
      state.ResumeTiming();
    }
    session.controller().step();
    if (++n % 5 == 0) session.perception().observe(percept);
  }
  state.counters["rtf"] = benchmark::Counter(static_cast<double>(state.iterations()) * session.sim().timestep(),
                                             benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimControlledStep);

void BM_SimEpisode(benchmark::State& state) {
  const auto sc = world::load_scenario("3-block-tray");
  const auto actions = sim::parse_actions("move o1 r3; move o2 r3; move o3 r3; move r3 r2");
  double sim_time = 0;
  int failures = 0;
  for (auto _ : state) {
    sim::Session session(sc);
    sim::Percept percept;
    double next = 0;
    for (const auto& a : actions) {
      // execute() runs the controller; observe at 100 Hz of simulated time around it.
      sim::ActionResult r = session.execute(a);
      failures += r.status != sim::Status::Success;
      while (next <= session.sim().time()) {
        session.perception().observe(percept);
        next += 0.01;
      }
    }
    sim_time += session.sim().time();
  }
  state.counters["rtf"] = benchmark::Counter(sim_time, benchmark::Counter::kIsRate);
  state.counters["failures"] = failures;
}
BENCHMARK(BM_SimEpisode)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

// One cold `ik` edge cost with MuJoCo's collision checks (issue "The robot and its
// world": "one cold ik edge cost (IK + collision check) and a cached one, timed"):
// move(block, r1 -> r2) with the hand at home, the checker on the simulation's
// scratch data of the 3-block-tray scene (the tray and the blocks in place).
// The 3-block-tray scene with an `ik` cost model that checks collisions with MuJoCo.
struct IkCostScene {
  world::Scenario scenario = world::load_scenario("3-block-tray");
  sim::Simulation sim{scenario};
  sim::SimCollisionChecker checker{sim};
  robot::IkCostModel model{robot::IkMotionCost::params_for(scenario)};
  const Eigen::Vector3d home{0, 0, 0.5}, r1{0.40, 0.32, 0}, r2{0.40, -0.32, 0};
  IkCostScene() { model.set_collision_checker(&checker); }
  double block_r1_to_r2() { return model.move_cost(home, r1, r2, false); }
};

void BM_IkCostColdMujocoChecks(benchmark::State& state) {
  IkCostScene scene;
  const long before = scene.checker.calls();
  for (auto _ : state) {
    scene.model.clear();
    benchmark::DoNotOptimize(scene.block_r1_to_r2());
  }
  state.counters["checks/cost"] = benchmark::Counter(static_cast<double>(scene.checker.calls() - before) /
                                                     static_cast<double>(state.iterations()));
}
BENCHMARK(BM_IkCostColdMujocoChecks)->Unit(benchmark::kMicrosecond);

void BM_IkCostCachedMujocoChecks(benchmark::State& state) {
  IkCostScene scene;
  scene.block_r1_to_r2();
  for (auto _ : state) benchmark::DoNotOptimize(scene.block_r1_to_r2());
}
BENCHMARK(BM_IkCostCachedMujocoChecks);

BENCHMARK_MAIN();
