// A camera frame allocates nothing once the rig and the image have their sizes: after a
// first frame, rendering the loop's passes (RGB and noisy depth) again and again makes no
// C++ allocation (this executable counts every call of the global operator new; EGL,
// Mesa and MuJoCo are C and allocate through malloc, which is not counted).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "rtamp/sim/camera_rig.hpp"
#include "test_scenarios.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// The sanitizers replace the allocator themselves (and check that what one form of new
// allocated the same form deletes): the count is a release build's.
#if !RTAMP_SANITIZER_BUILD
void* operator new(std::size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n == 0 ? 1 : n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
#endif

namespace rtamp::sim {
namespace {

TEST(CameraRigAllocation, AFrameAfterTheFirstAllocatesNothing) {
  if (RTAMP_SANITIZER_BUILD) GTEST_SKIP() << "allocations are counted in a release build";
  const world::Scenario s = testing::three_block(true);
  Simulation sim(s);
  sim.step(50);
  CameraRig rig(sim, world::cameras_of(s));
  const std::size_t k = rig.index("overhead", {});
  CameraImage image;
  const CameraPasses loop{.noise = true, .segmentation = false};
  rig.render(k, image, loop);
  const long before = allocations.load();
  for (int frame = 0; frame < 5; ++frame) {
    sim.step(10);
    rig.render(k, image, loop);
  }
  EXPECT_EQ(allocations.load() - before, 0);
  EXPECT_EQ(image.depth.size(), static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
}

}  // namespace
}  // namespace rtamp::sim
