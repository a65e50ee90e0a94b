#include "rtamp/episode/episode.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <random>

#include "rtamp/episode/camera_record.hpp"
#include "rtamp/episode/sim_world.hpp"
#include "rtamp/episode/video_recorder.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/episode/mcap_arm.hpp"
#include "rtamp/episode/mcap_camera.hpp"
#include "rtamp/episode/mcap_ros2.hpp"
#include "rtamp/episode/mcap_ros2_camera.hpp"
#include "rtamp/episode/mcap_ros2_frames.hpp"
#include "rtamp/exec/episode_log.hpp"
#include "rtamp/exec/perception_errors.hpp"
#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/timeline.hpp"
#include "rtamp/exec/tree_dump.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/world/geometry.hpp"

namespace rtamp::episode {

namespace {

// Objects moved to random non-overlapping spots inside their initial location. A layout
// in which some object finds no free spot in 200 draws is drawn again, up to 20 times;
// if none works out, the scenario's own layout stays. (Leaving that one object where the
// scenario put it could make it overlap one already moved there: two blocks 2.5 cm apart
// at the start, which the simulation then pushed apart.)
void randomize_objects(world::Scenario& s, std::mt19937_64& rng) {
  const world::Geometry geometry(s);
  const world::Placement initial = world::initial_placement(s);
  for (int layout = 0; layout < 20; ++layout) {
    std::vector<world::Footprint> placed;
    for (const auto& c : s.containers) placed.push_back({c.position[0], c.position[1], c.size[0], c.size[1]});
    std::vector<world::Object> objects = s.objects;
    bool complete = true;
    for (auto& o : objects) {
      const std::string* loc = initial.location_of(o.name);
      const auto fp = loc ? geometry.footprint_of(*loc) : std::nullopt;
      if (!fp) continue;
      const bool in_region = s.find_region(*loc) != nullptr;
      bool free = false;
      for (int attempt = 0; attempt < 200 && !free; ++attempt) {
        std::uniform_real_distribution<double> ux(fp->min_x() + o.size[0], fp->max_x() - o.size[0]);
        std::uniform_real_distribution<double> uy(fp->min_y() + o.size[1], fp->max_y() - o.size[1]);
        const world::Footprint cand{ux(rng), uy(rng), o.size[0], o.size[1]};
        free = true;
        // In a region, keep clear of containers standing there and of other objects.
        for (const auto& f : placed) free = free && !cand.overlaps(f, in_region ? 0.04 : 0.02);
        if (free) o.position[0] = cand.x, o.position[1] = cand.y;
      }
      if (!free) {
        complete = false;
        break;
      }
      placed.push_back({o.position[0], o.position[1], o.size[0], o.size[1]});
    }
    if (complete) {
      s.objects = std::move(objects);
      return;
    }
  }
}

// Camera perception's frames into an MCAP file of either profile: one writer a
// perceiving camera, each with its own channels and period (none for period inf).
// Registered after the log's observer: a frame's `camera` record, then its image.
template <typename Writer, typename Mcap>
void film(SimWorld& world, Mcap& mcap, double period, std::vector<std::unique_ptr<Writer>>& store) {
  sim::Perception& perception = world.session().perception();
  if (!perception.camera() || !std::isfinite(period)) return;
  std::vector<Writer*> writers;
  for (const world::Camera& c : perception.camera()->cameras()) {
    store.push_back(std::make_unique<Writer>(mcap, c.name, period));
    writers.push_back(store.back().get());
  }
  perception.add_frame_observer([writers, sw = &world](const sim::CameraPerception& frame) {
    const auto& cameras = frame.cameras();
    for (std::size_t k = 0; k < cameras.size(); ++k)
      if (cameras[k].name == frame.camera_name()) writers[k]->frame(sw->session().sim().time(), frame);
  });
}

}  // namespace

EpisodeMetrics run_episode(const world::Scenario& scenario, const EpisodeOptions& opt) {
  return Episode(scenario, opt).run();
}

Episode::~Episode() = default;

Episode::Episode(const world::Scenario& input, const EpisodeOptions& opt, const WorldWrapper& wrap) : scenario_(input) {
  std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + 1);
  world::Scenario& scenario = scenario_;
  if (opt.randomize_initial) randomize_objects(scenario, rng);
  // Every input is checked before any output is opened (a log file is
  // created, a tree directory emptied): the person's numbers, the world's
  // name and settings, the loop's constructor the task, the planner's names
  // and the loop's numbers. Then the outputs, so that a bad path too is
  // refused before anything runs.
  world::PersonOptions po = opt.person;
  if (opt.scripted_operator) po.script.insert(po.script.begin(), scenario.interventions.begin(), scenario.interventions.end());
  po.seed = opt.seed;
  person_ = std::make_unique<world::Person>(scenario, po);

  const WorldInfo info = find_world(opt.world);
  world_ = info.make(scenario, opt.seed, opt.world_settings);
  if (!world_) throw Error("world '" + info.name + "': its factory made no world");
  sim_world_ = dynamic_cast<SimWorld*>(world_.get());
  if (!opt.outputs.video.empty() && !sim_world_)
    throw Error("--video needs the MuJoCo world (world '" + info.name + "' has nothing to film)");
  // The person acts through the world's intervention capability; a world
  // without it runs as it is (people act on it on their own) — unless the
  // person has something to do, which PersonWorld then refuses.
  exec::World* seen = world_.get();
  if (world_->intervenable() || std::isfinite(person_->next_time())) {
    acted_ = std::make_unique<exec::PersonWorld>(*world_, *person_, "the " + info.name + " world");
    seen = acted_.get();
  }
  if (wrap) wrapper_ = wrap(*seen);

  exec::LoopOptions lo = opt.loop;
  robot::register_ik_cost_model();  // the episode layer brings the robot's cost model
  lo.seed = opt.seed;
  lo.world_name = info.name;
  // The operator script's new tasks come first (unless ignored), then the caller's (--new-task).
  if (opt.scripted_operator)
    lo.task_changes.insert(lo.task_changes.begin(), scenario.task_changes.begin(), scenario.task_changes.end());
  // A camera's belief may lag or lose a thing for a moment: the task is judged on a settled percept.
  if (opt.world_settings.perception == "camera") lo.settle = std::max(lo.settle, exec::kCameraSettle);
  loop_ = std::make_unique<exec::ReactiveLoop>(wrapper_ ? *wrapper_ : *seen, scenario, lo);

  const EpisodeOutputs& out = opt.outputs;
  if (!(out.mcap_image_period >= 0))
    throw Error("the MCAP image period must be >= 0 s (0: every frame, inf: none), not " +
                std::to_string(out.mcap_image_period));
  {  // two outputs that are one file: refused before either is opened
    FileSet files;
    if (!out.log.empty()) files.output(out.log_option, out.log);
    if (!out.mcap.empty()) files.output(out.mcap_option, out.mcap);
    if (!out.video.empty() && sim_world_) files.output("--video", out.video);
  }
  if (!out.log.empty()) log_ = std::make_unique<exec::EpisodeLog>(out.log, out.log_option);
  if (!out.mcap.empty() && out.mcap_profile == McapProfile::Ros2) {
    // The same in the ros2 profile; the scene from the world's frames, drawn from now on.
    mcap_ros2_ = std::make_unique<McapRos2>(out.mcap, out.mcap_compression, &scenario_, 1 << 20, out.mcap_option);
    mcap_ros2_frames_ = std::make_unique<McapRos2Frames>(scenario_, *world_, *mcap_ros2_);
    if (!log_) log_ = std::make_unique<exec::EpisodeLog>();
    log_->add_sink([m = mcap_ros2_.get()](const std::string& record) { m->add(record); });
  } else if (!out.mcap.empty()) {
    // The MCAP file gets the log's records as they are written (a log without a file if none).
    mcap_ = std::make_unique<EpisodeMcap>(out.mcap, out.mcap_compression, &scenario_, 1 << 20, out.mcap_option);
    if (!log_) log_ = std::make_unique<exec::EpisodeLog>();
    log_->add_sink([m = mcap_.get()](const std::string& record) { m->add(record); });
  }
  if (!out.trees.empty()) trees_ = std::make_unique<exec::TreeDump>(out.trees);
  if (sim_world_ && !out.video.empty())
    video_ = std::make_unique<VideoRecorder>(sim_world_->session().sim(), out.video);
  if (out.timeline) timeline_ = std::make_unique<exec::Timeline>(out.timeline);
  if (log_) {
    if (SimWorld* sw = sim_world_) {
      log_->add_end_field("mujoco_warnings", [sw] { return static_cast<double>(sw->session().sim().warnings().total()); });
      // Camera perception: a `camera` record per frame (what it detected and believes).
      sw->session().perception().add_frame_observer([log = log_.get(), sw](const sim::CameraPerception& frame) {
        log->record(sw->session().sim().time(), camera_record(frame));
      });
    }
    // Perceived imperfectly, the end record also says where things truly were.
    if (opt.world_settings.perception == "camera")
      if (exec::Intervenable* truth = world_->intervenable())
        log_->set_truth([truth] { return truth->true_placement(); });
    loop_->add_observer(*log_);
  }
  if (mcap_ && sim_world_) {
    mcap_arm_ = std::make_unique<McapArm>(sim_world_->session().sim(), *mcap_);
    loop_->add_observer(*mcap_arm_);  // after the log: a tick's record, then the arm
    film(*sim_world_, *mcap_, out.mcap_image_period, mcap_cameras_);
  }
  if (mcap_ros2_ && sim_world_) film(*sim_world_, *mcap_ros2_, out.mcap_image_period, mcap_ros2_cameras_);
  if (mcap_ros2_frames_) loop_->add_observer(*mcap_ros2_frames_);  // after the log: a tick's record, then the scene
  if (timeline_) loop_->add_observer(*timeline_);
  if (trees_) loop_->add_observer(*trees_);
  if (video_) loop_->add_observer(*video_);
}

EpisodeMetrics Episode::run() {
  EpisodeMetrics m = loop_->run();
  // Every output is closed; the first that failed is thrown (a lost log, MCAP file or video).
  std::exception_ptr failed;
  auto close = [&](auto& output) {
    try {
      if (output) output->close();
    } catch (...) {
      if (!failed) failed = std::current_exception();
    }
  };
  close(log_);
  close(mcap_);
  close(mcap_ros2_);
  close(trees_);
  close(video_);
  if (failed) std::rethrow_exception(failed);
  return m;
}

}  // namespace rtamp::episode
