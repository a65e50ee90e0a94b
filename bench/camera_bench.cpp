// One camera frame of the default overhead camera (640x480) on the 3-block-tray
// scenario, arm at home (docs/perception.md; the bar for a whole perception frame —
// render, segment, fit, belief — is a tenth of a 10 Hz frame period, median, on one core):
//   BM_CameraFrame/0/1   RGB + linearised depth + depth noise
//   BM_CameraFrame/0/0   the same without the depth noise
//   BM_CameraFrame/1/1   RGB + depth + noise + the segmentation pass (a second render; tests only)
//   BM_DepthNoise        the depth noise alone, on one frame's clean depth
//   BM_SegmentAndFit     colour segmentation, top faces and box fits of one rendered frame
//   BM_PerceptionFrame/C a whole frame: render with noise, detect, visibility, belief update,
//                        of C = 0 the overhead camera, 1 the wrist camera (424x240, arm at
//                        home), 2 both (one frame of each)
//   BM_PerceptionFrameArmOver  a whole overhead frame with the arm in view as in an episode:
//                        the tool 5 and 20 cm over each thing in turn, a pose a frame
// Counter fps = frames per second of wall time; things = boxes fitted a frame.
#include <benchmark/benchmark.h>

#include "rtamp/robot/skills.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/sim/camera_detector.hpp"
#include "rtamp/sim/camera_perception.hpp"
#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/depth_noise.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

void BM_CameraFrame(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  sim::Simulation sim(s);
  sim::CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  sim::CameraImage image;
  sim::CameraPasses passes;
  passes.segmentation = state.range(0) != 0;
  passes.noise = state.range(1) != 0;
  for (auto _ : state) rig.render(k, image, passes);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CameraFrame)->Args({0, 1})->Args({0, 0})->Args({1, 1})->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DepthNoise(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  sim::Simulation sim(s);
  sim::CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  sim::CameraImage image;
  rig.render(k, image, {.noise = false, .segmentation = false});
  std::vector<float> noisy;
  std::mt19937_64 rng(1);
  for (auto _ : state) sim::apply_depth_noise(image.depth, noisy, image.width, image.height, rig.cameras()[k].noise, rng);
}
BENCHMARK(BM_DepthNoise)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SegmentAndFit(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  sim::Simulation sim(s);
  sim.step(50);
  sim::CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  sim::CameraImage image;
  rig.render(k, image, {.noise = true, .segmentation = false});
  sim::CameraDetector detector(s, rig.cameras()[k].noise);
  std::vector<world::Detection> seen;
  for (auto _ : state) detector.detect(image, seen);
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["things"] = static_cast<double>(seen.size());
}
BENCHMARK(BM_SegmentAndFit)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PerceptionFrame(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  sim::Simulation sim(s);
  sim.step(50);
  sim::CameraPerceptionOptions o;
  const std::vector<std::vector<std::string>> sets{{"overhead"}, {"wrist"}, {"overhead", "wrist"}};
  o.cameras = sets.at(static_cast<std::size_t>(state.range(0)));
  sim::CameraPerception eyes(sim, o);
  for (auto _ : state) eyes.frame();
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["things"] = static_cast<double>(eyes.belief().things().size());
}
BENCHMARK(BM_PerceptionFrame)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PerceptionFrameArmOver(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  sim::Simulation sim(s);
  sim.step(50);
  // The arm's configurations: the tool over each thing, gripper down (the first free IK
  // solution).
  robot::Ur5Kinematics::Config cfg;
  cfg.base = robot::Ur5Kinematics::base_pose(s.robot);
  cfg.tool_offset = sim.options().mjcf.arm.tool_offset;
  const robot::Ur5Kinematics arm(cfg);
  std::vector<robot::Joints> poses;
  for (int i = 0; i < static_cast<int>(sim.things().size()); ++i)
    for (double above : {0.05, 0.2}) {
      Eigen::Vector3d tool = sim.position(i);
      const sim::Thing& t = sim.thing(i);
      tool.z() += (t.container ? t.size[2] : t.size[2] / 2) + above;
      robot::IkSolutions q;
      const robot::Joints now = sim.arm_q();
      arm.ik_tool(robot::top_down_pose(tool, 0), q, &now);
      for (const robot::Joints& c : q)
        if (!sim.config_collides(c)) {
          poses.push_back(c);
          break;
        }
    }
  if (poses.empty()) {
    state.SkipWithError("no free configuration over any thing");
    return;
  }
  sim::CameraPerception eyes(sim, {});
  std::size_t k = 0;
  for (auto _ : state) {
    sim.set_arm_configuration(poses[k++ % poses.size()]);
    eyes.frame();
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["poses"] = static_cast<double>(poses.size());
}
BENCHMARK(BM_PerceptionFrameArmOver)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
