// One camera frame of the default overhead camera (640x480) on the 3-block-tray
// scenario, arm at home (docs/perception.md; the bar for a whole perception frame —
// render, segment, fit, belief — is a tenth of a 10 Hz frame period, median, on one
// core; only the render exists yet):
//   BM_CameraFrame/0/1   RGB + linearised depth + depth noise
//   BM_CameraFrame/0/0   the same without the depth noise
//   BM_CameraFrame/1/1   RGB + depth + noise + the segmentation pass (a second render; tests only)
// Counter fps = frames per second of wall time.
#include <benchmark/benchmark.h>

#include "rtamp/sim/camera_rig.hpp"
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

}  // namespace

BENCHMARK_MAIN();
