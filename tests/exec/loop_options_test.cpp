// The reactive loop refuses options out of range before anything runs (issue
// 13: numeric options have documented ranges in the C++ and Python APIs too):
// a NaN or non-positive max_time, a zero, negative or non-finite tick, a
// negative or non-finite outside_grace, fewer than one failure before giving
// up, a negative cycle count. Each is an rtamp::Error naming the option and
// the value; the world has not moved (its time is still 0). The defaults and
// an infinite max_time are accepted.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::exec {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(LoopOptions, OutOfRangeIsRefusedBeforeAnythingRuns) {
  const world::Scenario s = world::load_scenario("3-block");
  struct Bad {
    const char* option;
    std::function<void(LoopOptions&)> set;
    const char* shown;
  };
  const std::vector<Bad> bad = {
      {"max_time", [](LoopOptions& o) { o.max_time = kNaN; }, "nan"},
      {"max_time", [](LoopOptions& o) { o.max_time = 0; }, "0"},
      {"max_time", [](LoopOptions& o) { o.max_time = -5; }, "-5"},
      {"tick_period", [](LoopOptions& o) { o.tick_period = 0; }, "0"},
      {"tick_period", [](LoopOptions& o) { o.tick_period = kNaN; }, "nan"},
      {"tick_period", [](LoopOptions& o) { o.tick_period = kInf; }, "inf"},
      {"outside_grace", [](LoopOptions& o) { o.outside_grace = -1; }, "-1"},
      {"outside_grace", [](LoopOptions& o) { o.outside_grace = kNaN; }, "nan"},
      {"max_failures_per_move", [](LoopOptions& o) { o.max_failures_per_move = 0; }, "0"},
      {"cycles", [](LoopOptions& o) { o.cycles = -1; }, "-1"},
  };
  for (const Bad& b : bad) {
    SymbolicWorld w(s);
    LoopOptions o;
    o.planning = PlanningMode::Inline;
    b.set(o);
    try {
      ReactiveLoop loop(w, s, o);
      ADD_FAILURE() << b.option << " = " << b.shown << " accepted";
    } catch (const Error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(std::string("loop option ") + b.option + ":"), std::string::npos) << m;
      EXPECT_NE(m.find(std::string("found ") + b.shown), std::string::npos) << m;
    }
    EXPECT_EQ(w.time(), 0.0);
  }
}

TEST(LoopOptions, DefaultsAndNoTimeLimitRun) {
  const world::Scenario s = world::load_scenario("3-block");
  SymbolicWorld w(s);
  LoopOptions o;
  o.planning = PlanningMode::Inline;
  o.max_time = kInf;  // no limit: the task ends the episode
  ReactiveLoop loop(w, s, o);
  EXPECT_TRUE(loop.run().success);
}

}  // namespace
}  // namespace rtamp::exec
