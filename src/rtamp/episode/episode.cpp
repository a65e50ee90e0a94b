#include "rtamp/episode/episode.hpp"

#include <algorithm>
#include <memory>
#include <random>

#include "rtamp/episode/sim_world.hpp"
#include "rtamp/episode/video_recorder.hpp"
#include "rtamp/exec/episode_log.hpp"
#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/exec/timeline.hpp"
#include "rtamp/exec/tree_dump.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/world/geometry.hpp"

namespace rtamp::episode {

namespace {

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

}  // namespace

const NameTable<WorldKind>& worlds() {
  static const NameTable<WorldKind> t = {
      {"mujoco", WorldKind::MuJoCo, "the simulated UR5 in MuJoCo"},
      {"symbolic", WorldKind::Symbolic, "a discrete-event world with no physics (milliseconds an episode)"},
  };
  return t;
}

const char* to_string(WorldKind w) { return name_of(worlds(), w); }

EpisodeMetrics run_episode(const world::Scenario& scenario, const EpisodeOptions& opt) {
  return Episode(scenario, opt).run();
}

Episode::~Episode() = default;

Episode::Episode(const world::Scenario& input, const EpisodeOptions& opt, const WorldWrapper& wrap) : scenario_(input) {
  std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + 1);
  world::Scenario& scenario = scenario_;
  if (opt.randomize_initial) randomize_objects(scenario, rng);
  // The person: the scenario's script, random interventions, one random change.
  world::PersonOptions po;
  if (opt.scripted_operator) po.script = scenario.interventions;
  po.rate = opt.random_rate;
  if (opt.random_change) po.change = world::RandomChange{*opt.random_change, opt.change_window_begin, opt.change_window_end};
  po.seed = opt.seed;
  person_ = std::make_unique<world::Person>(scenario, po);

  // Every input is checked before any output is opened (a log file is
  // created, a tree directory emptied): the world checks its options, the
  // loop's constructor the task, the planner's names and the loop's numbers.
  // Then the outputs, so that a bad path too is refused before anything runs.
  if (!opt.video_path.empty() && opt.world != WorldKind::MuJoCo)
    throw Error("--video needs the MuJoCo world (the symbolic world has nothing to film)");

  if (opt.world == WorldKind::MuJoCo) {
    sim::SessionOptions so;
    so.seed = opt.seed;
    auto w = std::make_unique<SimWorld>(scenario, so);
    sim_world_ = w.get();
    world_ = std::move(w);
  } else {
    exec::SymbolicWorldOptions so;
    so.seed = opt.seed;
    so.failure_probability = opt.failure_probability;
    auto w = std::make_unique<exec::SymbolicWorld>(scenario, so);
    symbolic_world_ = w.get();
    world_ = std::move(w);
  }
  acted_ = std::make_unique<exec::PersonWorld>(*world_, *person_, std::string("the ") + to_string(opt.world) + " world");
  if (wrap) wrapper_ = wrap(*acted_);

  exec::LoopOptions lo;
  lo.planner.algorithm = opt.algorithm;
  robot::register_ik_cost_model();  // the episode layer brings the robot's cost model
  lo.planner.cost = opt.cost;
  lo.conditions = opt.conditions;
  lo.reconfiguration = opt.reconfiguration;
  lo.planning = opt.planning;
  lo.max_time = opt.max_time;
  lo.tick_period = opt.tick_period;
  lo.max_failures_per_move = opt.max_failures_per_move;
  lo.outside_grace = opt.outside_grace;
  lo.cycles = opt.cycles;
  lo.seed = opt.seed;
  lo.world_name = to_string(opt.world);
  lo.interrupt = opt.interrupt;
  loop_ = std::make_unique<exec::ReactiveLoop>(wrapper_ ? *wrapper_ : *acted_, scenario, lo);

  if (!opt.log_path.empty()) log_ = std::make_unique<exec::EpisodeLog>(opt.log_path);
  if (!opt.tree_dir.empty()) trees_ = std::make_unique<exec::TreeDump>(opt.tree_dir);
  if (sim_world_ && !opt.video_path.empty())
    video_ = std::make_unique<VideoRecorder>(sim_world_->session().sim(), opt.video_path);
  if (opt.timeline) timeline_ = std::make_unique<exec::Timeline>(opt.timeline);
  if (log_) {
    if (SimWorld* sw = sim_world_)
      log_->add_end_field("mujoco_warnings", [sw] { return static_cast<double>(sw->session().sim().warnings().total()); });
    loop_->add_observer(*log_);
  }
  if (timeline_) loop_->add_observer(*timeline_);
  if (trees_) loop_->add_observer(*trees_);
  if (video_) loop_->add_observer(*video_);
}

EpisodeMetrics Episode::run() {
  EpisodeMetrics m = loop_->run();
  if (video_) video_->close();
  return m;
}

}  // namespace rtamp::episode
