// The C++ side of python/bench/bench_plan.py (docs/benchmarks.md, "Python
// module"): N times, load 3-block-tray and make the first plan with a fresh
// plan::Planner (astar-exp, euclid) — exactly the calls the Python script makes
// through the module, so the two processes' times compare the binding's cost.
// Usage: rtamp_py_plan_peer N  (prints the last plan's cost).
#include <cstdio>
#include <cstdlib>

#include "rtamp/plan/planner.hpp"
#include "rtamp/world/scenario_io.hpp"

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000;
  double cost = 0;
  for (int i = 0; i < n; ++i) {
    rtamp::plan::Planner p(rtamp::world::load_scenario("3-block-tray"));
    cost = p.plan().plan.cost();
  }
  std::printf("%d plans, cost %.6f\n", n, cost);
  return 0;
}
