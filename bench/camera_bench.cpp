// One camera frame of the default overhead camera (640x480) on the 3-block-tray
// scenario, arm at home (docs/perception.md; the bar for a whole perception frame —
// render, segment, fit, belief — is a tenth of a 10 Hz frame period, median, on one
// core; the belief does not exist yet):
//   BM_CameraFrame/0/1   RGB + linearised depth + depth noise
//   BM_CameraFrame/0/0   the same without the depth noise
//   BM_CameraFrame/1/1   RGB + depth + noise + the segmentation pass (a second render; tests only)
//   BM_SegmentAndFit     colour segmentation, top faces and box fits of one rendered frame
// Counter fps = frames per second of wall time; things = boxes fitted a frame.
#include <benchmark/benchmark.h>

#include "rtamp/sim/blob_points.hpp"
#include "rtamp/sim/box_fit.hpp"
#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/colour_segmentation.hpp"
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

void BM_SegmentAndFit(benchmark::State& state) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  sim::Simulation sim(s);
  sim.step(50);
  sim::CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  sim::CameraImage image;
  rig.render(k, image, {.noise = true, .segmentation = false});
  const sim::ColourSegmenter segmenter(sim::scene_colours(s));
  sim::ColourSegmentation seg;
  const Eigen::Vector3d eye = image.extrinsics.to_world(Eigen::Vector3d::Zero());
  std::size_t fitted = 0;
  for (auto _ : state) {
    segmenter.segment(image.rgb.data(), image.width, image.height, seg);
    fitted = 0;
    for (const sim::ColourBlob& blob : seg.blobs) {
      const bool tray = segmenter.colours()[blob.colour].label == "tray";
      sim::BlobPointsOptions options;
      options.split = !tray;
      options.noise = rig.cameras()[k].noise;
      if (tray) options.top = world::Container{}.size[2];
      const world::Vec3 size = tray ? world::Container{}.size : world::Object{}.size;
      sim::BoxFitOptions fit;
      for (const auto& points : sim::blob_points(blob, image.depth, image.width, image.intrinsics, image.extrinsics, options)) {
        if (tray) fit.spacing = (points.front() - eye).norm() / image.intrinsics.fx;
        benchmark::DoNotOptimize(sim::fit_box(points, size, tray, eye, fit));
        ++fitted;
      }
    }
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["things"] = static_cast<double>(fitted);
}
BENCHMARK(BM_SegmentAndFit)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
