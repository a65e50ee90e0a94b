// The worlds agree: the same scenario and the same person's script — drawn at
// random per seed, then fixed — run in the symbolic world and in MuJoCo end
// the same way, with every object in the same place. (Timings differ: the
// worlds model the arm's motion differently, so an intervention may fall in
// another phase of a move; the outcome and where things end up must not —
// unless one world takes an intervention the other refuses because its arm
// was elsewhere at that moment; such seeds are counted, not compared.)
// Slow: a few dozen MuJoCo episodes.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/util/splitmix.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {
namespace {

using Kind = world::Intervention::Kind;

// A script of one or two interventions on the scenario's objects, in the first
// 12 s (every episode of these scenarios runs longer in both worlds).
std::vector<world::Intervention> random_script(const world::Scenario& s, std::uint64_t seed) {
  SplitMix64 rng(seed * 7919 + 3);
  std::vector<world::Intervention> out;
  const int n = 1 + static_cast<int>(rng.below(2));
  int added = 0;
  for (int i = 0; i < n; ++i) {
    world::Intervention iv;
    iv.time = 1 + rng.unit() * 11;  // while both worlds' episodes still run (the symbolic arm is faster)
    const std::string object = s.objects[rng.below(s.objects.size())].name;
    switch (rng.below(3)) {
      case 0:
        iv.kind = Kind::Relocate;
        iv.subject = object;
        iv.location = rng.below(2) ? "r1" : "r2";
        break;
      case 1:
        iv.kind = Kind::Add;
        iv.subject = "x" + std::to_string(++added);
        iv.cls = "block";
        iv.location = "r1";
        break;
      default:
        iv.kind = Kind::Remove;
        iv.subject = object;
        break;
    }
    out.push_back(iv);
  }
  return out;
}

struct End {
  exec::EndReason end;
  int applied;               // interventions the world applied
  world::Placement objects;  // where every object (not container) is
  std::string reason;
};

End run_in(const std::string& world, const world::Scenario& s, std::uint64_t seed,
           std::vector<world::TaskChange> new_tasks = {}) {
  EpisodeOptions o;
  o.loop.task_changes = std::move(new_tasks);
  o.world = world;
  o.seed = seed;
  o.loop.planning = exec::PlanningMode::Inline;
  o.loop.max_time = 400;
  Episode e(s, o);
  const EpisodeMetrics m = e.run();
  End out{m.end, m.interventions_applied, {}, m.reason};
  for (const auto& [name, t] : e.world().intervenable()->true_placement().things)
    if (!t.container) out.objects.things[name] = t;
  return out;
}

std::string text(const world::Placement& p) {
  std::string out;
  for (const auto& [name, t] : p.things) out += name + "@" + t.location + " ";
  return out;
}

TEST(WorldsAgree, TheSameScriptEndsTheSameWayInBothWorlds) {
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    world::Scenario s = world::load_scenario(seed % 2 ? "3-block" : "3-block-tray");
    s.interventions = random_script(s, seed);
    std::string script;
    for (const auto& iv : s.interventions) script += iv.to_string() + " @" + std::to_string(iv.time) + "; ";
    SCOPED_TRACE(s.name + ", seed " + std::to_string(seed) + ": " + script);
    const End sym = run_in("symbolic", s, seed);
    const End mj = run_in("mujoco", s, seed);
    // An intervention one world could take and the other not (a location full
    // in one and not yet in the other, the arms being at different points of
    // their moves) makes different worlds: those are not compared.
    if (sym.applied != mj.applied) continue;
    EXPECT_EQ(exec::to_string(sym.end), exec::to_string(mj.end)) << sym.reason << " | " << mj.reason;
    if (sym.end == exec::EndReason::TaskDone && mj.end == exec::EndReason::TaskDone) {
      EXPECT_EQ(text(sym.objects), text(mj.objects)) << "symbolic | MuJoCo";
      ++compared;
    }
  }
  EXPECT_GE(compared, 18);
  std::cout << compared << " of 24 seeds compared\n";
}

// A new task at a moment of the first moves (a running move kept, redirected,
// or the task already done): both worlds end alike, with the same placements.
TEST(WorldsAgree, TheSameNewTaskEndsTheSameWayInBothWorlds) {
  const std::vector<std::string> tasks = {
      "F G (\"o1 in r2\" & \"o2 in r1\")", "G \"o1 in r1\" & F G \"o2 in r2\"", "F G \"all block in r1\"",
      "F (\"o3 in r2\" & F G \"all block in r1\")"};
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const world::Scenario s = world::load_scenario(seed % 3 ? "3-block" : "3-block-tray");
    world::TaskChange c;
    c.time = 1.0 + static_cast<double>(seed % 5) * 1.5;
    c.task = tasks[seed % tasks.size()];
    c.by = "test";
    SCOPED_TRACE("seed " + std::to_string(seed) + ": '" + c.task + "' at " + std::to_string(c.time));
    const End sym = run_in("symbolic", s, seed, {c});
    const End mj = run_in("mujoco", s, seed, {c});
    EXPECT_EQ(exec::to_string(sym.end), exec::to_string(mj.end)) << sym.reason << " | " << mj.reason;
    // Done (the placements agree too), or unsatisfiable in both (o1 left r1 before "G o1 in r1").
    EXPECT_TRUE(sym.end == exec::EndReason::TaskDone || sym.end == exec::EndReason::Unsatisfiable) << sym.reason;
    if (sym.end == exec::EndReason::TaskDone && mj.end == exec::EndReason::TaskDone) {
      EXPECT_EQ(text(sym.objects), text(mj.objects)) << "symbolic | MuJoCo";
      ++compared;
    }
  }
  EXPECT_GE(compared, 18);
}

}  // namespace
}  // namespace rtamp::episode
