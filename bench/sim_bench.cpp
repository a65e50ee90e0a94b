// Simulation speed on the 3-block-tray scenario (issue "The robot and its world": the
// bar is >= 50x real time including control and perception; bare MuJoCo ~60x).
//   BM_SimBareStep         mj_step1/mj_step2 with gravity compensation, arm holding still
//   BM_SimControlledStep   controller tracking a pick trajectory + the above
//   BM_SimEpisode          whole episode: plan + execute pick/place of all blocks onto the
//                          tray, carry it to r2; perception every 10 ms (a 100 Hz BT tick)
// Counter rtf = simulated seconds per CPU second.
#include <benchmark/benchmark.h>

#include "rtamp/sim/session.hpp"
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

BENCHMARK_MAIN();
