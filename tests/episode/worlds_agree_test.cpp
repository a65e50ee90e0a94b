// The worlds agree: the same scenario and the same person's script — drawn at
// random per seed, then fixed — run in the symbolic world and in MuJoCo end
// the same way, with every object in the same place. (Timings differ: the
// worlds model the arm's motion differently, so an intervention may fall in
// another phase of a move; the outcome and where things end up must not —
// unless one world takes an intervention the other refuses because its arm
// was elsewhere at that moment; such seeds are counted, not compared.)
// The rule book of space is kept in both: a person filling the arm's target
// mid-carry stops that move in both worlds, and under random persons who fill
// locations no perceived state, no state a plan starts from and no final state
// breaks a capacity.
// Slow: a few dozen MuJoCo episodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/forwarding_world.hpp"
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

// "" if no location of `s` holds more things directly than its capacity in `p`, else
// which (an added container: capacity 4, the symbolic world's default).
std::string over_capacity(const world::Scenario& s, const world::Placement& p) {
  std::map<std::string, int> count;
  for (const auto& [name, t] : p.things) ++count[t.location];
  std::string out;
  for (const auto& [loc, n] : count) {
    int cap = -1;
    if (const world::Region* r = s.find_region(loc)) cap = r->capacity;
    else if (const world::Container* c = s.find_container(loc)) cap = c->capacity;
    else if (p.things.count(loc)) cap = 4;
    if (cap >= 0 && n > cap) out += loc + " holds " + std::to_string(n) + " (capacity " + std::to_string(cap) + ") ";
  }
  return out;
}

// Every state the loop perceived and every state a plan started from keeps the
// capacities; the running moves halted because their place could not finish.
class RuleWatch final : public exec::EpisodeObserver {
 public:
  explicit RuleWatch(const world::Scenario& s) : s_(s) {}
  void on_perceived(double t, const world::Placement& seen, const world::Placement&) override {
    if (const std::string w = over_capacity(s_, seen); !w.empty()) broken += "perceived at " + std::to_string(t) + ": " + w;
  }
  void on_plan(double t, const exec::PlanEvent& ev) override {
    if (const std::string w = over_capacity(s_, ev.start); !w.empty()) broken += "planned from at " + std::to_string(t) + ": " + w;
  }
  void on_redirect(double, const std::string&, const std::string& rule) override {
    if (rule.find("cannot place") != std::string::npos) ++redirected;
  }
  std::string broken;
  int redirected = 0;

 private:
  const world::Scenario& s_;
};

// The person of the mid-carry case: adds a block `name` into `location` once `thing`
// has been in the gripper for `after` s of world time (at the same point of the carry
// in every world, whatever its timing).
class FillWhileCarried final : public exec::ForwardingWorld {
 public:
  FillWhileCarried(exec::World& inner, std::string thing, std::string name, std::string location, double after)
      : ForwardingWorld(inner), thing_(std::move(thing)), name_(std::move(name)), location_(std::move(location)),
        after_(after) {}
  double next_event_time() const override {
    const double inner = inner_.next_event_time();
    return held_since_ && !done_ ? std::min(inner, *held_since_ + after_) : inner;
  }
  void advance(double dt) override {
    const double target = time() + std::max(0.0, dt);
    if (held_since_ && !done_ && *held_since_ + after_ < target) {
      inner_.advance(*held_since_ + after_ - time());
      fill();
      inner_.advance(target - time());
    } else {
      inner_.advance(dt);
    }
    if (!held_since_) {
      const world::Placement p = inner_.intervenable()->true_placement();
      if (const std::string* at = p.location_of(thing_); at && *at == exec::kInHand) held_since_ = time();
    }
    if (held_since_ && !done_ && time() >= *held_since_ + after_ - 1e-9) fill();
  }
  bool filled() const { return applied_; }

 private:
  void fill() {
    world::Intervention iv;
    iv.kind = world::Intervention::Kind::Add;
    iv.subject = name_;
    iv.cls = "block";
    iv.location = location_;
    iv.time = time();
    applied_ = inner_.intervenable()->apply(iv).applied;
    done_ = true;
  }
  std::string thing_, name_, location_;
  double after_;
  std::optional<double> held_since_;
  bool done_ = false, applied_ = false;
};

struct End {
  exec::EndReason end;
  int applied;               // interventions the world applied
  world::Placement objects;  // where every object (not container) is
  std::string reason;
  std::string broken;        // RuleWatch: capacities broken
  int redirected = 0;        // RuleWatch: moves halted because their place could not finish
};

End run_in(const std::string& world, const world::Scenario& s, std::uint64_t seed,
           std::vector<world::TaskChange> new_tasks = {}, const world::PersonOptions& person = {},
           const Episode::WorldWrapper& wrap = {}) {
  EpisodeOptions o;
  o.loop.task_changes = std::move(new_tasks);
  o.world = world;
  o.seed = seed;
  o.person = person;
  o.loop.planning = exec::PlanningMode::Inline;
  o.loop.max_time = 400;
  Episode e(s, o, wrap);
  RuleWatch watch(e.scenario());
  e.loop().add_observer(watch);
  const EpisodeMetrics m = e.run();
  End out{m.end, m.interventions_applied, {}, m.reason, watch.broken, watch.redirected};
  const world::Placement last = e.world().intervenable()->true_placement();
  for (const auto& [name, t] : last.things)
    if (!t.container) out.objects.things[name] = t;
  out.broken += over_capacity(e.scenario(), last);
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

namespace rtamp::episode {
namespace {

// r2 (capacity 2) holds o2; task: o1 in r2. The arm carries o1 there and a person adds
// o3 into r2 during the carry: the move cannot finish — both worlds halt it, put o1
// back, take o2 or o3 out and then put o1 in, the same way; no state perceived or
// planned from ever has three things in r2.
world::Scenario fill_target_scenario() {
  world::Scenario s = world::load_scenario("3-block");
  s.regions[1].capacity = 2;
  s.objects.erase(s.objects.begin() + 2);                   // o1 in r1, o2 ...
  s.objects[1].position = {0.40, -0.32, 0};                 // ... in r2
  s.propositions.clear();
  s.task = "F G \"o1 in r2\"";
  return s;
}

TEST(WorldsAgree, APersonFillingTheTargetMidCarryStopsTheMoveInBothWorlds) {
  const world::Scenario s = fill_target_scenario();
  for (const double after : {0.3, 1.0}) {  // early in the carry, and later
    SCOPED_TRACE("o3 added " + std::to_string(after) + " s after o1 was grasped");
    auto wrap = [after](exec::World& inner) -> std::unique_ptr<exec::World> {
      return std::make_unique<FillWhileCarried>(inner, "o1", "o3", "r2", after);
    };
    const End sym = run_in("symbolic", s, 1, {}, {}, wrap);
    const End mj = run_in("mujoco", s, 1, {}, {}, wrap);
    for (const End* e : {&sym, &mj}) {
      EXPECT_EQ(e->end, exec::EndReason::TaskDone) << e->reason;
      EXPECT_EQ(e->broken, "");
      EXPECT_EQ(e->redirected, 1);  // halted once, its thing put back
      ASSERT_TRUE(e->objects.things.count("o3"));
      EXPECT_EQ(e->objects.things.at("o1").location, "r2");
    }
    EXPECT_EQ(text(sym.objects), text(mj.objects)) << "symbolic | MuJoCo";
  }
}

// Random persons who add things (and move them) into locations of capacity 2: whatever
// they fill while the arm carries, both worlds end alike with the same placements, and
// no perceived state, no state a plan starts from and no final state breaks a capacity.
TEST(WorldsAgree, RandomPersonsFillingLocationsEndTheSameWayInBothWorlds) {
  world::Scenario s = world::load_scenario("3-block");
  s.regions[1].capacity = 3;
  s.propositions.clear();
  s.task = "F G (\"o1 in r2\" & \"o2 in r2\")";
  int compared = 0, redirected = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    world::PersonOptions person;
    person.rate = 0.25;
    person.start = 1;
    person.end = 14;
    person.kinds = {Kind::Add, Kind::Add, Kind::Relocate};
    SCOPED_TRACE("seed " + std::to_string(seed));
    const End sym = run_in("symbolic", s, seed, {}, person);
    const End mj = run_in("mujoco", s, seed, {}, person);
    EXPECT_EQ(sym.broken, "");
    EXPECT_EQ(mj.broken, "");
    redirected += sym.redirected + mj.redirected;
    if (sym.applied != mj.applied) continue;  // different worlds (see above)
    EXPECT_EQ(exec::to_string(sym.end), exec::to_string(mj.end)) << sym.reason << " | " << mj.reason;
    if (sym.end == exec::EndReason::TaskDone && mj.end == exec::EndReason::TaskDone) {
      EXPECT_EQ(text(sym.objects), text(mj.objects)) << "symbolic | MuJoCo";
      ++compared;
    }
  }
  std::cout << compared << " of 12 seeds compared; " << redirected << " moves stopped because their place could not finish\n";
  EXPECT_GE(compared, 6);
}

}  // namespace
}  // namespace rtamp::episode
