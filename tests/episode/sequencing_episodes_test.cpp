// MuJoCo episodes of tasks with history (sequencing: "first the red block into
// r3, then everything into r2") with one scripted intervention of every kind
// in the middle of a move. For each task a first, undisturbed episode's log
// gives the moves' windows ("action" start / finished, and the "perceived"
// records: the thing in the hand from the grasp to the release); then one
// episode per (intervention kind, phase) puts the intervention in the middle
// of the approach (before the grasp), the carry (half-way between grasp and
// release) or the place (just before the release) of one of those moves:
// relocate (the moved thing), add (a block at the move's destination), remove
// (the moved thing, or another), add-container (a tray in r2), remove-container
// (the tray), take-from-gripper to a location and away. Interventions that
// would make the task unsatisfiable (o1 taken away before its visit, the tray
// removed before the red block was on it) are aimed at another move.
//
// Every episode must succeed, its log be complete, and the run that happened
// (the log's `run` records) as a lasso with its last state repeated must
// satisfy the task under the direct LTL semantics (ltl/lasso.hpp), labels by
// the world layer's reference evaluator. Slow: about 60 MuJoCo episodes.
// RTAMP_SEQUENCING_ONLY=<task>/<kind>/<phase> (e.g. tray-red/remove-container/place)
// runs the matching episodes alone, with their timeline. RTAMP_SEQUENCING_PERCEPTION=camera
// runs them all with camera perception and keeps every log (scripts/perception-latency
// then says whether each intervention was perceived, and counts phantoms).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {
namespace {

using Kind = world::Intervention::Kind;
using nlohmann::json;

world::Proposition prop(const std::string& name, const std::string& text) {
  world::Proposition p;
  p.name = name;
  p.text = text;
  p.expr = world::parse_prop_expr(text);
  return p;
}

// A task with history: `thing` must have visited `visit` before the rest.
struct Task {
  std::string name;
  world::Scenario scenario;
  std::string thing = "o1", visit;
};

// 3-block's blocks on 3-block-tray's regions, plus a region r3 in front of the
// base between r1 and r2 (x 0.52-0.72, y -0.10-0.10: at most 0.73 m from the
// base axis); o1 is red.
world::Scenario blocks_r3() {
  world::Scenario s = world::load_scenario("3-block");
  const world::Scenario tray = world::load_scenario("3-block-tray");
  s.name = "3-block-r3";
  s.regions = tray.regions;
  world::Region r3 = tray.regions[0];
  r3.name = "r3";
  r3.center = {0.62, 0.0, 0};
  r3.size = {0.20, 0.20};
  r3.capacity = 4;
  s.regions.push_back(r3);
  s.objects[0].cls = "red";
  s.interventions.clear();
  s.propositions = {prop("red_in_r3", "any red in r3"), prop("o1_in_r2", "o1 in r2"),
                    prop("all_in_r1", "all object in r1"), prop("all_in_r2", "all object in r2")};
  return s;
}

// 3-block-tray (the tray is r3), o1 red.
world::Scenario tray_red() {
  world::Scenario s = world::load_scenario("3-block-tray");
  s.objects[0].cls = "red";
  s.interventions.clear();
  s.propositions = {prop("red_in_r3", "any red in r3"), prop("all_in_r2", "all object in r2")};
  return s;
}

std::vector<Task> tasks() {
  std::vector<Task> out;
  Task a{"blocks-red", blocks_r3(), "o1", "r3"};
  a.scenario.task = "F (red_in_r3 & F G all_in_r2)";
  out.push_back(a);
  Task b{"blocks-o1", blocks_r3(), "o1", "r2"};
  b.scenario.task = "F (o1_in_r2 & F G all_in_r1)";
  out.push_back(b);
  Task c{"tray-red", tray_red(), "o1", "r3"};
  c.scenario.task = "F (red_in_r3 & F G all_in_r2)";
  out.push_back(c);
  return out;
}

// A directory of this process's own (two runs of the test at once do not share logs).
std::filesystem::path scratch_dir() {
  const auto d = std::filesystem::temp_directory_path() / ("rtamp_seq_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

std::vector<json> read_log(const std::string& path) {
  std::vector<json> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) out.push_back(json::parse(line));
  return out;
}

// One move of the undisturbed run and its phase boundaries (world seconds).
struct Window {
  std::string thing, from, to;
  double start = 0, grasp = 0, release = 0, end = 0;
};

std::vector<Window> move_windows(const std::vector<json>& log) {
  std::vector<Window> out;
  std::map<std::string, std::string> state;  // the run's current state
  std::optional<Window> cur;
  bool held = false;
  for (const json& r : log) {
    const std::string ev = r.at("ev");
    const double t = r.at("t");
    if (ev == "run") {
      state.clear();
      for (const auto& [k, v] : r.at("state").items()) state[k] = v.get<std::string>();
    } else if (ev == "action" && r.at("what") == "start") {
      // "move(o1, r2)"
      const std::string a = r.at("action");
      const auto open = a.find('('), comma = a.find(", "), close = a.find(')');
      Window w;
      w.thing = a.substr(open + 1, comma - open - 1);
      w.to = a.substr(comma + 2, close - comma - 2);
      w.from = state.count(w.thing) ? state[w.thing] : "";
      w.start = t;
      cur = w;
      held = false;
    } else if (ev == "perceived" && cur) {
      const auto& p = r.at("placement");
      const bool in_hand = p.contains(cur->thing) && p.at(cur->thing) == exec::kInHand;
      if (in_hand && !held && cur->grasp == 0) cur->grasp = t;
      if (!in_hand && held && cur->release == 0) cur->release = t;
      held = in_hand;
    } else if (ev == "action" && r.at("what") == "finished" && cur) {
      cur->end = t;
      if (cur->grasp > 0 && cur->release > 0) out.push_back(*cur);
      cur.reset();
    }
  }
  return out;
}

// When `thing` first stood in `loc` in the logged run (infinity: never).
double first_visit(const std::vector<json>& log, const std::string& thing, const std::string& loc) {
  for (const json& r : log)
    if (r.at("ev") == "run" && r.at("state").contains(thing) && r.at("state").at(thing) == loc) return r.at("t");
  return std::numeric_limits<double>::infinity();
}

const char* kind_name(Kind k, bool with_location) {
  switch (k) {
    case Kind::Relocate: return "relocate";
    case Kind::Add: return "add";
    case Kind::Remove: return "remove";
    case Kind::AddContainer: return "add-container";
    case Kind::RemoveContainer: return "remove-container";
    case Kind::TakeFromGripper: return with_location ? "take-to" : "take-away";
    case Kind::AddRegion: return "add-region";
  }
  return "?";
}

enum class Phase { Approach, Carry, Place };
const char* phase_name(Phase p) { return p == Phase::Approach ? "approach" : p == Phase::Carry ? "carry" : "place"; }

double time_in(const Window& w, Phase p) {
  switch (p) {
    case Phase::Approach: return w.start + 0.5 * (w.grasp - w.start);
    case Phase::Carry: return w.grasp + 0.5 * (w.release - w.grasp);
    case Phase::Place: return w.grasp + 0.92 * (w.release - w.grasp);
  }
  return w.start;
}

// A location other than the move's source and destination (and than the thing itself).
std::string other_location(const world::Scenario& s, const Window& w) {
  std::vector<std::string> locs;
  for (const auto& r : s.regions) locs.push_back(r.name);
  for (const auto& c : s.containers) locs.push_back(c.name);
  for (const auto& l : locs)
    if (l != w.from && l != w.to && l != w.thing && !(s.find_container(w.thing) && s.find_container(l))) return l;
  return w.from;
}

// The intervention of `kind` in `phase` of one of the moves, aimed so that the
// task stays satisfiable; nullopt if no move suits it.
std::optional<world::Intervention> aim(const Task& task, const std::vector<Window>& moves, double visited, Kind kind,
                                       bool with_location, Phase phase, int salt, std::string* about) {
  const world::Scenario& s = task.scenario;
  // Moves in turn from one that depends on the salt; a tray to remove is
  // preferred while it is the destination.
  const std::size_t n = moves.size();
  std::vector<const Window*> order;
  for (std::size_t k = 0; k < n; ++k) order.push_back(&moves[(static_cast<std::size_t>(salt) + k) % n]);
  if (kind == Kind::RemoveContainer && !s.containers.empty()) {
    const std::string& tray = s.containers[0].name;
    std::stable_partition(order.begin(), order.end(), [&](const Window* w) { return w->to == tray; });
  }
  for (const Window* wp : order) {
    const Window& w = *wp;
    // A loaded tray removed or taken from the gripper in the air has a test of
    // its own (LoadedTrayTakenInTheAir below); aimed at other moves here.
    const bool tray_in_air = s.find_container(w.thing) && phase != Phase::Approach;
    if (tray_in_air && (kind == Kind::RemoveContainer || kind == Kind::TakeFromGripper)) continue;
    world::Intervention iv;
    iv.kind = kind;
    iv.time = time_in(w, phase);
    // A thing is needed until the task's visit has happened.
    auto needed = [&](const std::string& thing) {
      return (thing == task.thing && iv.time <= visited) || (thing == task.visit && iv.time <= visited);
    };
    const bool moving_container = s.find_container(w.thing) != nullptr;
    switch (kind) {
      case Kind::Relocate:
        iv.subject = w.thing;
        iv.location = other_location(s, w);
        break;
      case Kind::Add:
        iv.subject = "o4";
        iv.cls = "block";
        iv.location = w.to;
        break;
      case Kind::Remove:
        if (moving_container) continue;
        iv.subject = w.thing;
        if (needed(w.thing))
          for (const auto& o : s.objects)
            if (o.name != w.thing && !needed(o.name)) {
              iv.subject = o.name;
              break;
            }
        if (needed(iv.subject)) continue;
        break;
      case Kind::AddContainer:
        iv.subject = "t2";
        iv.cls = "tray";
        iv.location = "r2";
        break;
      case Kind::RemoveContainer:
        if (s.containers.empty() || needed(s.containers[0].name)) continue;
        iv.subject = s.containers[0].name;
        break;
      case Kind::TakeFromGripper:
        if (with_location) iv.location = other_location(s, w);
        else if (phase != Phase::Approach && needed(w.thing)) continue;
        break;
      case Kind::AddRegion:
        continue;  // not a person's change
    }
    std::ostringstream d;
    d << task.name << " " << kind_name(kind, with_location) << " " << (iv.subject.empty() ? "" : iv.subject + " ")
      << (iv.location.empty() ? "" : "to " + iv.location + " ") << "at " << iv.time << " s, " << phase_name(phase)
      << " of move(" << w.thing << ", " << w.from << " -> " << w.to << ") [" << w.start << ", grasp " << w.grasp
      << ", release " << w.release << ", " << w.end << "]";
    *about = d.str();
    return iv;
  }
  return std::nullopt;
}

// Class and container flag of every name the run may mention.
std::map<std::string, world::Placement::Thing> kinds_of(const world::Scenario& s, const world::Intervention* iv) {
  std::map<std::string, world::Placement::Thing> out;
  for (const auto& o : s.objects) out[o.name] = {"", o.cls, false};
  for (const auto& c : s.containers) out[c.name] = {"", c.cls, true};
  if (iv && (iv->kind == Kind::Add || iv->kind == Kind::AddContainer))
    out[iv->subject] = {"", iv->cls, iv->kind == Kind::AddContainer};
  return out;
}

ltl::LassoWord::Letter letter(const world::Scenario& s, const world::Placement& p) {
  ltl::LassoWord::Letter l;
  for (const auto& prop : s.propositions)
    if (world::evaluate(prop.expr, p)) l.insert(prop.name);
  return l;
}

// The logged run as a lasso, its last state repeated.
ltl::LassoWord run_word(const world::Scenario& s, const std::vector<json>& log, const world::Intervention* iv,
                        std::string* text) {
  const auto kinds = kinds_of(s, iv);
  std::vector<world::Placement> run;
  std::ostringstream d;
  for (const json& r : log) {
    if (r.at("ev") != "run") continue;
    world::Placement p;
    d << "  t=" << r.at("t").get<double>() << ":";
    for (const auto& [name, loc] : r.at("state").items()) {
      // A name the scenario does not know is the added thing's (a camera's belief names it).
      const bool added = iv && (iv->kind == Kind::Add || iv->kind == Kind::AddContainer);
      auto k = kinds.count(name) ? kinds.at(name)
               : added           ? world::Placement::Thing{"", iv->cls, iv->kind == Kind::AddContainer}
                                 : world::Placement::Thing{"", "block", false};
      p.set(name, loc.get<std::string>(), k.cls, k.container);
      d << ' ' << name << '@' << loc.get<std::string>();
    }
    d << '\n';
    run.push_back(p);
  }
  *text = d.str();
  ltl::LassoWord w;
  for (std::size_t i = 0; i + 1 < run.size(); ++i) w.prefix.push_back(letter(s, run[i]));
  if (!run.empty()) w.cycle.push_back(letter(s, run.back()));
  return w;
}

struct Outcome {
  EpisodeMetrics metrics;
  std::vector<json> log;
};

// The perception the episodes run with: RTAMP_SEQUENCING_PERCEPTION, else the truth.
std::string perception() {
  const char* p = std::getenv("RTAMP_SEQUENCING_PERCEPTION");
  return p ? p : "truth";
}

Outcome run_one(const world::Scenario& s, std::uint64_t seed, const std::string& log_path, bool verbose) {
  EpisodeOptions o;
  o.world = "mujoco";
  o.world_settings.perception = perception();
  o.seed = seed;
  o.loop.max_time = 300;
  o.outputs.log = log_path;
  if (verbose) o.outputs.timeline = [](const std::string& line) { std::cout << line << '\n'; };
  Outcome out;
  out.metrics = run_episode(s, o);
  out.log = read_log(log_path);
  return out;
}

// How many things lie in each region of an end record's placement (a thing in a
// container counts in the container's region): names aside.
std::map<std::string, int> per_region(const nlohmann::json& placement) {
  std::map<std::string, int> n;
  for (const auto& [name, at] : placement.items()) {
    const std::string loc = at.get<std::string>();
    ++n[placement.contains(loc) ? placement.at(loc).get<std::string>() : loc];
  }
  return n;
}

// The checks every episode must pass.
void check(const world::Scenario& s, const Outcome& e, const world::Intervention* iv, const std::string& about,
           const std::string& log_path) {
  SCOPED_TRACE(about + " (log " + log_path + ")");
  const EpisodeMetrics& m = e.metrics;
  EXPECT_TRUE(m.success) << to_string(m.end) << ": " << m.reason;
  ASSERT_GE(e.log.size(), 2u);
  EXPECT_EQ(e.log.front().at("ev"), "episode");
  EXPECT_EQ(e.log.back().at("ev"), "end");
  EXPECT_EQ(e.log.back().at("success"), m.success);
  EXPECT_EQ(m.interventions, iv ? 1 : 0);
  EXPECT_EQ(m.interventions, m.interventions_applied + m.interventions_refused);
  std::string text;
  const ltl::LassoWord w = run_word(s, e.log, iv, &text);
  ASSERT_FALSE(w.cycle.empty()) << "no run records";
  if (m.success) {
    EXPECT_TRUE(ltl::holds(ltl::parse(s.task), w))
        << "succeeded, but the run with its last state repeated violates '" << s.task << "':\n"
        << text << ltl::to_string(w);
    // Perceived through a camera, a success must be one in the world too: as many things
    // in each region where they truly are as perceived (the belief names a person's
    // addition its own way, and look-alike blocks may swap names).
    const nlohmann::json& end = e.log.back();
    if (end.contains("truth")) {
      EXPECT_EQ(per_region(end.at("truth")), per_region(end.at("placement"))) << "the truth at the end: " << end.at("truth");
    }
  }
}

TEST(SequencingEpisodes, MidMoveInterventionsOfEveryKind) {
  const char* only = std::getenv("RTAMP_SEQUENCING_ONLY");
  const auto dir = scratch_dir();
  struct Kinded {
    Kind kind;
    bool with_location;
  };
  const std::vector<Kinded> kinds{{Kind::Relocate, false},        {Kind::Add, false},
                                  {Kind::Remove, false},          {Kind::AddContainer, false},
                                  {Kind::RemoveContainer, false}, {Kind::TakeFromGripper, true},
                                  {Kind::TakeFromGripper, false}};
  int episodes = 0, applied = 0;
  std::uint64_t seed = 0;
  for (const Task& task : tasks()) {
    // One seed per task: the disturbed episodes repeat the undisturbed one up to the intervention.
    ++seed;
    SCOPED_TRACE(task.name + ": " + task.scenario.task);
    const std::string base_log = (dir / ("rtamp_seq_" + task.name + "_undisturbed.jsonl")).string();
    const Outcome base = run_one(task.scenario, seed, base_log, false);
    check(task.scenario, base, nullptr, task.name + " undisturbed", base_log);
    const std::vector<Window> moves = move_windows(base.log);
    ASSERT_GE(moves.size(), 2u) << "the undisturbed run has too few moves";
    const double visited = first_visit(base.log, task.thing, task.visit);
    ASSERT_LT(visited, std::numeric_limits<double>::infinity());
    int salt = 0;
    for (const Kinded& k : kinds) {
      for (Phase phase : {Phase::Approach, Phase::Carry, Phase::Place}) {
        ++salt;
        const std::string key =
            task.name + "/" + kind_name(k.kind, k.with_location) + "/" + phase_name(phase);
        if (only && key.find(only) == std::string::npos) continue;
        std::string about;
        const auto iv = aim(task, moves, visited, k.kind, k.with_location, phase, salt, &about);
        if (!iv) continue;  // e.g. no container to remove
        world::Scenario s = task.scenario;
        s.interventions = {*iv};
        std::string name = key;
        std::replace(name.begin(), name.end(), '/', '_');
        const std::string log = (dir / ("rtamp_seq_" + name + ".jsonl")).string();
        if (only) std::cout << about << '\n';
        const Outcome e = run_one(s, seed, log, only != nullptr);
        check(s, e, &*iv, about + ", seed " + std::to_string(seed), log);
        std::cout << about << ": " << to_string(e.metrics.end) << " at " << e.metrics.world_time << " s, intervention "
                  << (e.metrics.interventions_applied ? "applied" : "refused") << ", " << e.metrics.replans
                  << " replans, " << e.metrics.actions_failed << " failed moves\n";
        ++episodes;
        applied += e.metrics.interventions_applied;
        if (!::testing::Test::HasFailure() && !only && perception() == "truth") std::filesystem::remove(log);
      }
    }
    if (!::testing::Test::HasFailure() && perception() == "truth") std::filesystem::remove(base_log);
  }
  if (perception() != "truth") std::cout << "logs kept in " << dir.string() << '\n';
  std::cout << episodes << " disturbed episodes, " << applied << " interventions applied\n";
  if (!only) {
    EXPECT_GE(episodes, 50);
  }
}

// The loaded tray of 3-block-tray (plain task) removed, or taken from the
// gripper to r1, half-way through its carry r1 -> r2. The operator sets a
// removed tray's blocks down in the region under it or the nearest one with
// room (sim/operator.hpp), and a tray taken to r1 arrives with its blocks; the
// loop sees where they are and replans. (These used to end `lost`: the blocks
// fell between r1 and r2, outside every location.) `rtamp run` reproduces
// them with this operator on 3-block-tray:
//   operator: [{time: 22.16, action: remove_container, container: r3}]
//   operator: [{time: 22.16, action: take_from_gripper, to: r1}]
TEST(SequencingEpisodes, LoadedTrayTakenInTheAir) {
  world::Scenario base = world::load_scenario("3-block-tray");
  base.interventions.clear();
  const std::string log_path = (scratch_dir() / "rtamp_seq_tray_in_air.jsonl").string();
  const Outcome plain = run_one(base, 1, log_path, false);
  const auto moves = move_windows(plain.log);
  const auto tray = std::find_if(moves.begin(), moves.end(), [](const Window& w) { return w.thing == "r3"; });
  ASSERT_NE(tray, moves.end());
  for (bool remove : {true, false}) {
    world::Intervention iv;
    iv.kind = remove ? Kind::RemoveContainer : Kind::TakeFromGripper;
    iv.subject = remove ? "r3" : "";
    iv.location = remove ? "" : "r1";
    iv.time = time_in(*tray, Phase::Carry);
    world::Scenario s = base;
    s.interventions = {iv};
    const Outcome e = run_one(s, 1, log_path, false);
    check(s, e, &iv, std::string(remove ? "remove-container" : "take-to r1") + " at " + std::to_string(iv.time), log_path);
  }
}

}  // namespace
}  // namespace rtamp::episode
