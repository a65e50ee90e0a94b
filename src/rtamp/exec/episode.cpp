#include "rtamp/exec/episode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <random>

#include "rtamp/exec/sim_action_runner.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/sim/controller.hpp"
#include "rtamp/sim/operator.hpp"
#include "rtamp/sim/perception.hpp"
#include "rtamp/sim/renderer.hpp"
#include "rtamp/sim/skill_runner.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/geometry.hpp"

namespace rtamp::exec {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

const char* kind_name(world::Intervention::Kind k) {
  switch (k) {
    case world::Intervention::Kind::Relocate: return "relocate";
    case world::Intervention::Kind::Add: return "add";
    case world::Intervention::Kind::Remove: return "remove";
    case world::Intervention::Kind::AddContainer: return "add-container";
    case world::Intervention::Kind::RemoveContainer: return "remove-container";
    case world::Intervention::Kind::TakeFromGripper: return "take-from-gripper";
  }
  return "?";
}

nlohmann::json placement_json(const world::Placement& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, thing] : p.things) j[name] = thing.location;
  return j;
}

// The simulated time as a bt::Clock (Timeout decorators and actions see sim time).
class SimClock final : public bt::Clock {
 public:
  explicit SimClock(const sim::Simulation& s) : sim_(s) {}
  bt::Duration now() const override {
    return std::chrono::duration_cast<bt::Duration>(std::chrono::duration<double>(sim_.time()));
  }

 private:
  const sim::Simulation& sim_;
};

// Objects moved to random non-overlapping spots inside their initial location.
void randomize_objects(world::Scenario& s, std::mt19937_64& rng) {
  const world::Geometry geometry(s);
  const world::Placement initial = world::initial_placement(s);
  std::vector<world::Footprint> placed;
  for (const auto& c : s.containers) placed.push_back({c.position[0], c.position[1], c.size[0], c.size[1]});
  for (auto& o : s.objects) {
    const std::string* loc = initial.location_of(o.name);
    const auto fp = loc ? geometry.footprint_of(*loc) : std::nullopt;
    if (!fp) continue;
    const bool in_region = s.find_region(*loc) != nullptr;
    for (int attempt = 0; attempt < 200; ++attempt) {
      std::uniform_real_distribution<double> ux(fp->min_x() + o.size[0], fp->max_x() - o.size[0]);
      std::uniform_real_distribution<double> uy(fp->min_y() + o.size[1], fp->max_y() - o.size[1]);
      world::Footprint cand{ux(rng), uy(rng), o.size[0], o.size[1]};
      bool clash = false;
      for (const auto& f : placed) {
        // In a region, keep clear of containers standing there and of other objects.
        if (cand.overlaps(f, in_region ? 0.04 : 0.02)) clash = true;
      }
      if (clash) continue;
      o.position[0] = cand.x;
      o.position[1] = cand.y;
      break;
    }
    placed.push_back({o.position[0], o.position[1], o.size[0], o.size[1]});
  }
}

// Moves (not stays) in a plan's prefix and cycle.
std::size_t moves_in(const plan::Plan& p) {
  auto moves = [](const std::vector<plan::Step>& steps) {
    return std::count_if(steps.begin(), steps.end(), [](const plan::Step& s) { return !s.action.is_stay(); });
  };
  return static_cast<std::size_t>(moves(p.prefix) + moves(p.cycle));
}

world::Intervention random_intervention(const world::Scenario& s, world::Intervention::Kind kind,
                                        const EpisodeOptions& o, std::mt19937_64& rng) {
  world::Intervention iv;
  iv.kind = kind;
  iv.time = std::uniform_real_distribution<double>(o.change_window_begin, o.change_window_end)(rng);
  std::vector<std::string> blocks;
  for (const auto& obj : s.objects) blocks.push_back(obj.name);
  if (kind == world::Intervention::Kind::Add) {
    iv.subject = "o_added";
    iv.cls = "block";
    iv.location = s.regions.empty() ? std::string{} : s.regions[rng() % s.regions.size()].name;
  } else if (!blocks.empty()) {
    iv.subject = blocks[rng() % blocks.size()];
    if (kind == world::Intervention::Kind::Relocate && !s.regions.empty())
      iv.location = s.regions[rng() % s.regions.size()].name;
  }
  return iv;
}

}  // namespace

nlohmann::json to_json(const EpisodeMetrics& m) {
  return {{"success", m.success},
          {"reason", m.reason},
          {"first_plan_seconds", m.first_plan_seconds},
          {"replan_seconds", m.replan_seconds},
          {"replans", m.replans},
          {"tree_changes", m.tree_changes},
          {"completion_time", m.completion_time},
          {"motion_cost", m.motion_cost},
          {"interventions", m.interventions},
          {"actions_succeeded", m.actions_succeeded},
          {"actions_failed", m.actions_failed},
          {"wall_seconds", m.wall_seconds},
          {"real_time_factor", m.real_time_factor},
          {"seed", m.seed}};
}

EpisodeMetrics run_episode(const world::Scenario& input, const EpisodeOptions& opt) {
  const auto wall0 = Clock::now();
  EpisodeMetrics m;
  m.seed = opt.seed;
  std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + 1);

  // ---- the log: opened first, so that every outcome is recorded ------------
  std::ofstream log;
  if (!opt.log_path.empty()) {
    log.open(opt.log_path);
    if (!log) throw Error("cannot write the episode log '" + opt.log_path + "'");
  }
  double now = 0;
  auto emit = [&](nlohmann::json j) {
    if (!log.is_open()) return;
    j["t"] = std::round(now * 1e4) / 1e4;
    log << j.dump() << '\n';
  };
  auto say = [&](const std::string& line) {
    if (!opt.timeline) return;
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "[%7.2f s] ", now);
    opt.timeline(stamp + line);
  };

  world::Scenario scenario = input;
  if (opt.randomize_initial) randomize_objects(scenario, rng);
  sim::OperatorOptions op_options;
  op_options.seed = opt.seed;
  if (opt.scripted_operator) op_options.script = scenario.interventions;
  if (opt.random_change) op_options.script.push_back(random_intervention(scenario, *opt.random_change, opt, rng));
  std::sort(op_options.script.begin(), op_options.script.end(),
            [](const auto& a, const auto& b) { return a.time < b.time; });

  emit({{"ev", "episode"},
        {"scenario", scenario.name},
        {"task", scenario.task},
        {"algorithm", plan::to_string(opt.algorithm)},
        {"conditions", to_string(opt.conditions)},
        {"reconfiguration", opt.reconfiguration == Reconfiguration::Online ? "online" : "offline"},
        {"seed", opt.seed}});

  try {
    sim::Simulation sim(scenario);
    sim::Controller controller(sim);
    sim::SkillRunner skills(sim, controller);
    sim::PerceptionOptions perception_options;
    perception_options.seed = opt.seed;
    sim::Perception perception(sim, perception_options);
    sim::Operator op(sim, op_options);
    SimActionRunner runner(sim, skills, controller);
    runner.on_event = [&](const char* what, const std::string& action, const std::string& why) {
      emit({{"ev", "action"}, {"what", what}, {"action", action}, {"reason", why}});
      say(std::string(what) + " " + action + (why.empty() ? "" : " (" + why + ")"));
    };

    std::unique_ptr<sim::Renderer> renderer;
    std::unique_ptr<sim::VideoWriter> video;
    std::vector<std::uint8_t> frame;
    if (!opt.video_path.empty()) {
      renderer = std::make_unique<sim::Renderer>(sim);
      video = std::make_unique<sim::VideoWriter>(opt.video_path, renderer->width(), renderer->height(), 30);
    }
    double next_frame = 0;

    plan::PlannerOptions planner_options;
    planner_options.algorithm = opt.algorithm;
    planner_options.cost = opt.cost;
    if (opt.cost == "ik")
      planner_options.model = std::make_shared<robot::IkMotionCost>(robot::IkMotionCost::params_for(scenario));
    plan::Planner planner(scenario, planner_options);
    PlanTree tree(opt.conditions, opt.reconfiguration, runner, std::make_shared<SimClock>(sim));

    int tree_files = 0;
    auto write_tree = [&] {
      if (opt.tree_dir.empty()) return;
      std::filesystem::create_directories(opt.tree_dir);
      char name[64];
      std::snprintf(name, sizeof name, "/tree_%03d.xml", tree_files++);
      std::ofstream(opt.tree_dir + name) << bt::to_btcpp_xml(tree.tree());
    };
    auto show_tree = [&] {  // the subtrees' roots, one line each (the whole tree only at the start)
      if (!opt.timeline) return;
      std::string lines;
      for (const bt::Node* c : tree.tree().root()->children())
        lines += "\n    " + std::string(bt::to_string(c->status())) + "  " + c->name();
      say("tree now:" + (lines.empty() ? std::string(" (empty)") : lines));
    };
    bool recurring = false;  // the installed plan's cycle has moves: the task never finishes
    auto install = [&](const plan::PlanResult& r, bool first) {
      recurring = std::any_of(r.plan.cycle.begin(), r.plan.cycle.end(),
                              [](const plan::Step& st) { return !st.action.is_stay(); });
      const auto tuples = planner.action_tuples(r.plan);
      const ReconfigurationReport rep = tree.set_plan(tuples);
      nlohmann::json actions = nlohmann::json::array();
      std::string listed;
      for (const auto& t : tuples) {
        actions.push_back(t.action);
        listed += (listed.empty() ? "" : ", ") + t.action;
      }
      say("plan: " + (listed.empty() ? std::string("nothing to move") : listed));
      emit({{"ev", "plan"}, {"first", first}, {"cost", r.plan.cost()}, {"actions", actions},
            {"seconds", r.stats.seconds}, {"expanded", r.stats.expanded}, {"generated", r.stats.generated},
            {"cache_used", r.stats.cache_used}, {"cache_hits", r.stats.cache_hits},
            {"cache_misses", r.stats.cache_misses}});
      emit({{"ev", "tree"}, {"applied", rep.applied}, {"inserted", rep.inserted}, {"removed", rep.removed},
            {"updated", rep.updated}, {"changes", tree.changes()}});
      if (rep.applied) {
        say("tree: +" + std::to_string(rep.inserted) + " -" + std::to_string(rep.removed) + " subtrees, " +
            std::to_string(rep.updated) + " updated (" + std::to_string(tree.changes()) + " changes so far)");
        if (!first && rep.inserted + rep.removed > 0) show_tree();
        write_tree();
      } else {
        say("tree change deferred: a running move must finish first");
      }
    };

    // ---- first plan (the arm waits; its time is charged to simulated time) ----
    sim::Percept percept = perception.observe();
    world::Placement believed = percept.placement();
    planner.set_placement(believed);
    // On a worker thread like every replan: the C library sets up a thread's
    // memory arena on its first allocation (mmap and page faults, seen with
    // strace) and later worker threads reuse it, so that cost lands here and
    // not in the first replan (which took ~65 µs instead of ~30 µs).
    plan::PlanResult first = std::async(std::launch::async, [&planner] { return planner.plan(); }).get();
    m.first_plan_seconds = first.stats.seconds;
    if (!first.found) {
      m.reason = std::string("no plan: ") + first.message;
      emit({{"ev", "end"}, {"success", false}, {"reason", m.reason}});
      say(m.reason);
      m.wall_seconds = seconds_since(wall0);
      return m;
    }
    say("first plan in " + std::to_string(first.stats.seconds * 1e3) + " ms: " +
        std::to_string(moves_in(first.plan)) + " moves, cost " + std::to_string(first.plan.cost()));
    for (double until = sim.time() + first.stats.seconds; sim.time() < until;) sim.step();
    tree.placement() = believed;
    install(first, true);
    if (opt.timeline) say("tree:\n" + bt::to_text(tree.tree()));

    // ---- the reactive loop (Algorithm 1) -----------------------------------------
    struct Pending {
      std::future<plan::PlanResult> future;
      std::optional<plan::PlanResult> result;  // set once the worker is done
      double requested_at = 0;                  // simulated time of the request
      Clock::time_point wall_start;
    };
    std::optional<Pending> pending;
    auto planner_view = [&](world::Placement p) {
      // A thing in the hand will be where the running move puts it (the move is not cut).
      std::string hand = runner.hand();
      if (!runner.current().empty()) {
        if (auto it = p.things.find(runner.thing()); it != p.things.end()) it->second.location = runner.destination();
        hand = runner.destination();
      }
      // A thing in the hand of a halted move goes back to its source.
      const std::string& held_to = runner.returning() ? runner.source() : runner.destination();
      for (auto& [name, thing] : p.things)
        if (thing.location == sim::kInHand) thing.location = held_to.empty() ? "none" : held_to;
      // The hand's last location may be a container that is gone: then "home".
      const auto* held_by = p.things.count(hand) ? &p.things.at(hand) : nullptr;
      if (!scenario.find_region(hand) && !(held_by && held_by->container)) hand.clear();
      planner.set_placement(std::move(p), hand);
    };
    auto request_plan = [&](const std::string& why) {
      if (pending) return;
      planner_view(believed);
      say("replanning: " + why);
      emit({{"ev", "replan"}, {"why", why}});
      pending = Pending{std::async(std::launch::async, [&planner] { return planner.plan(); }), std::nullopt, sim.time(),
                        Clock::now()};
    };

    std::map<std::string, double> outside_since;  // things perceived outside every location, since when
    int failures_seen = 0, successes_seen = 0, consecutive_failures = 0;
    Eigen::Vector3d last_tool = sim.tool_pose().translation();
    const int steps_per_tick = std::max(1, static_cast<int>(std::lround(opt.tick_period / sim.timestep())));
    bool done = false;
    while (!done && sim.time() < opt.max_time) {
      for (int k = 0; k < steps_per_tick; ++k) {
        controller.update();
        sim.step();
        const Eigen::Vector3d tool = sim.tool_pose().translation();
        m.motion_cost += (tool - last_tool).norm();  // the tool path actually travelled
        last_tool = tool;
        if (video && sim.time() >= next_frame) {
          renderer->render(frame);
          video->add(frame);
          next_frame += 1.0 / 30;
        }
      }
      now = sim.time();

      // Operator interventions due by now.
      bool things_changed = false, relocated = false;
      for (const sim::OperatorEvent& e : op.update()) {
        ++m.interventions;
        emit({{"ev", "intervention"}, {"kind", kind_name(e.what.kind)}, {"subject", e.what.subject},
              {"location", e.what.location}, {"applied", e.applied}, {"detail", e.detail}});
        say("operator: " + std::string(kind_name(e.what.kind)) + " " + e.what.subject +
            (e.what.location.empty() ? "" : " -> " + e.what.location) + (e.applied ? "" : " (refused: " + e.detail + ")"));
        if (!e.applied) continue;
        if (e.what.kind == world::Intervention::Kind::Relocate) relocated = true;
        else things_changed = true;
      }

      // Perceive. A thing seen outside every location (tumbling, or knocked off
      // the table) keeps its last believed location for a while; the episode
      // ends if it stays out.
      perception.observe(percept);
      world::Placement seen = percept.placement();
      if (seen != believed) emit({{"ev", "perceived"}, {"placement", placement_json(seen)}});
      std::string lost;
      for (auto& [name, thing] : seen.things) {
        if (thing.location != "none") {
          outside_since.erase(name);
          continue;
        }
        const auto since = outside_since.emplace(name, now).first->second;
        if (const std::string* was = believed.location_of(name); was && *was != "none") thing.location = *was;
        if (now - since > opt.outside_grace) lost = name;
      }
      // Timeline: what perception saw change that the robot's own move does not explain.
      if (opt.timeline && seen != believed) {
        for (const auto& [name, thing] : seen.things) {
          const std::string* was = believed.location_of(name);
          if (!was || *was == thing.location || name == runner.thing() || thing.location == sim::kInHand ||
              *was == sim::kInHand)
            continue;
          say("perceived " + name + " in " + thing.location + " (was in " + *was + ")");
        }
      }
      believed = seen;
      tree.placement() = believed;
      if (!lost.empty()) {
        m.reason = "'" + lost + "' is outside every region and container (since t = " +
                   std::to_string(outside_since.at(lost)) + " s): nothing can plan with it";
        emit({{"ev", "lost"}, {"thing", lost}, {"reason", m.reason}});
        say(m.reason);
        break;
      }

      if (things_changed) {
        // Algorithm 1 lines 9-10: objects or containers added/removed: update the TS.
        if (pending) {  // the worker owns the planner: wait for it, its plan is stale
          if (!pending->result) pending->future.get();
          pending.reset();
        }
        for (const auto& [name, thing] : believed.things) {
          if (planner.placement().things.count(name)) continue;
          if (thing.container) planner.apply(plan::Change::add_container(name, thing.cls, thing.location));
          else planner.apply(plan::Change::add_object(name, thing.cls, thing.location));
          say("perceived new " + thing.cls + " " + name + " in " + thing.location);
        }
        std::vector<std::string> gone;
        for (const auto& [name, thing] : planner.placement().things)
          if (!believed.things.count(name)) gone.push_back(name);
        for (const auto& name : gone) {
          const bool container = planner.placement().things.at(name).container;
          planner.apply(container ? plan::Change::remove_container(name) : plan::Change::remove_object(name));
          say("perceived " + name + " is gone");
        }
        request_plan("things were added or removed");
      } else if (relocated) {
        // Algorithm 1 lines 5-8: a relocation some subtree can handle needs no planning.
        if (const std::string by = tree.handler(believed); !by.empty()) {
          say("the tree can go on (" + (by == "every step is done" ? by : "can run " + by) + "): no replanning");
          emit({{"ev", "handled_by_tree"}, {"by", by}});
        } else {
          request_plan("relocation no subtree can handle");
        }
      }

      // Tick the tree.
      if (auto r = tree.retry_pending(); r && r->applied) {
        emit({{"ev", "tree"}, {"applied", true}, {"inserted", r->inserted}, {"removed", r->removed},
              {"updated", r->updated}, {"changes", tree.changes()}, {"deferred", true}});
        say("deferred tree change applied: +" + std::to_string(r->inserted) + " -" + std::to_string(r->removed) +
            " subtrees, " + std::to_string(r->updated) + " updated");
        show_tree();
        write_tree();
      }
      // While the arm puts back what a halted move held, the tree waits.
      const bt::Status status = runner.returning() ? bt::Status::Running : tree.tick();
      if (runner.failed > failures_seen) {
        consecutive_failures += runner.failed - failures_seen;
        failures_seen = runner.failed;
        if (consecutive_failures >= opt.max_consecutive_failures) {
          m.reason = "gave up after " + std::to_string(consecutive_failures) + " failed moves in a row (last: " +
                     runner.last_failure + ")";
          emit({{"ev", "gave_up"}, {"reason", m.reason}});
          break;
        }
      }
      if (runner.succeeded > successes_seen) {  // a move that works ends a run of failures
        successes_seen = runner.succeeded;
        consecutive_failures = 0;
      }
      emit({{"ev", "tick"}, {"status", std::string(bt::to_string(status))}, {"running", tree.running_action()}});

      // A plan computed on the worker is used once its planning time has passed in
      // sim time. The simulation runs faster than real time, so while the worker
      // is busy it may not run further ahead of the request than the wall time
      // the worker has had: it waits for the worker for the difference.
      if (pending && !pending->result) {
        const double ahead = (sim.time() - pending->requested_at) - seconds_since(pending->wall_start);
        const auto wait = std::chrono::duration<double>(std::max(0.0, ahead));
        if (pending->future.wait_for(wait) == std::future_status::ready) pending->result = pending->future.get();
      }
      if (pending && pending->result && sim.time() >= pending->requested_at + pending->result->stats.seconds) {
        plan::PlanResult r = std::move(*pending->result);
        pending.reset();
        ++m.replans;
        m.replan_seconds += r.stats.seconds;
        if (!r.found) {
          m.reason = std::string("no plan: ") + r.message;
          emit({{"ev", "no_plan"}, {"reason", m.reason}});
          say(m.reason);
          break;
        }
        say("replanned in " + std::to_string(r.stats.seconds * 1e6) + " us: " + std::to_string(moves_in(r.plan)) +
            " moves, cost " + std::to_string(r.plan.cost()) +
            (r.stats.cache_used ? " (cache hits " + std::to_string(r.stats.cache_hits) + ", misses " +
                                      std::to_string(r.stats.cache_misses) + ")"
                                : std::string()));
        install(r, false);
        continue;  // the status ticked above belongs to the old tree
      }
      if (pending || tree.has_pending()) continue;

      if (status == bt::Status::Failure) {
        request_plan("no subtree can run in the perceived state");
      } else if (status == bt::Status::Success && runner.current().empty()) {
        // Every step is done: finished if a plan from here needs no move.
        planner_view(believed);
        plan::PlanResult check = planner.plan();
        if (check.found && moves_in(check.plan) == 0) {
          done = true;
          m.success = true;
          m.reason = "task done";
          m.completion_time = sim.time();
        } else if (!check.found) {
          m.reason = std::string("no plan: ") + check.message;
          emit({{"ev", "no_plan"}, {"reason", m.reason}});
          say(m.reason);
          break;
        } else {
          ++m.replans;
          m.replan_seconds += check.stats.seconds;
          say("steps done but the task is not: new plan with " + std::to_string(moves_in(check.plan)) + " moves");
          install(check, false);
        }
      }
    }
    if (pending && !pending->result) pending->future.wait();
    tree.tree().halt();  // stop a move still running (logged before the end record)
    if (!done && m.reason.empty()) {
      m.reason = "time limit (" + std::to_string(opt.max_time) + " s of simulated time)";
      if (recurring) m.reason += " while repeating the plan's cycle: a recurring task never finishes";
    }
    m.tree_changes = tree.changes();
    m.actions_succeeded = runner.succeeded;
    m.actions_failed = runner.failed;
    if (video) video->close();
    m.wall_seconds = seconds_since(wall0);
    m.real_time_factor = m.wall_seconds > 0 ? sim.time() / m.wall_seconds : 0;
    const auto w = sim.warnings();
    emit({{"ev", "end"}, {"success", m.success}, {"reason", m.reason}, {"metrics", to_json(m)},
          {"placement", placement_json(believed)}, {"mujoco_warnings", w.total()}});
    say(m.success ? "task done" : "episode ended: " + m.reason);
  } catch (const std::exception& e) {
    m.success = false;
    m.reason = std::string("error: ") + e.what();
    emit({{"ev", "end"}, {"success", false}, {"reason", m.reason}});
    say(m.reason);
    m.wall_seconds = seconds_since(wall0);
  }
  return m;
}

}  // namespace rtamp::exec
