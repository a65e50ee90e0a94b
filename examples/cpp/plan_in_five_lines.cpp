// Plan a task in five lines: load a built-in scenario (the paper's "3-block +
// tray", task F G all_in_r2), plan its LTL task at minimum motion cost, print
// the plan — the lasso's prefix and the cycle repeated forever (docs/library.md).
// Build against the installed package: find_package(rtamp) and rtamp::rtamp, or
// `c++ -std=c++20 plan_in_five_lines.cpp $(pkg-config --cflags --libs rtamp)`.
#include <iostream>

#include "rtamp/plan/planner.hpp"
#include "rtamp/world/scenario_io.hpp"

int main() {
  rtamp::plan::Planner planner(rtamp::world::load_scenario("3-block-tray"));
  rtamp::plan::PlanResult r = planner.plan();
  if (!r.found) return std::cerr << "no plan: " << r.message << "\n", 1;
  for (const auto& step : r.plan.prefix) std::cout << planner.describe(step.action) << "\n";
  for (const auto& step : r.plan.cycle) std::cout << "(cycle) " << planner.describe(step.action) << "\n";
  std::cout << "cost " << r.plan.cost() << "\n";
}
