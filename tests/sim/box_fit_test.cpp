// Poses from pixels against the truth: in generated static scenes (2-5 regions, 1-8
// blocks, 0-2 trays with blocks on them; arm at home; seeds 1-12, or 1-N with
// RTAMP_CAMERA_SCENES=N) the default overhead camera's image with its depth noise goes
// through the detector (sim::CameraDetector: colour segments, top faces, touching blocks
// cut apart, a tray's rims joined, a box of the class's size fitted). Every thing gets
// one complete fit; its base lies within 5 mm of the truth (median within 2 mm), and
// the placement read from the fitted poses with the world's geometry equals the truth's.
// Also: the fit itself on exact synthetic boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "rtamp/sim/box_fit.hpp"
#include "rtamp/sim/camera_detector.hpp"
#include "rtamp/sim/camera_rig.hpp"
#include "rtamp/sim/perception.hpp"
#include "rtamp/world/geometry.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

Eigen::Vector3d truth_base(const Simulation& sim, int i) {
  const Thing& t = sim.things()[static_cast<std::size_t>(i)];
  Eigen::Vector3d c = sim.position(i);
  if (!t.container) c.z() -= t.size[2] / 2;
  return c;
}

TEST(BoxFit, StaticScenesArePerceivedAsTheyAre) {
  std::vector<double> errors;
  int scenes = 0;
  for (std::uint64_t seed = 1; seed <= testing::camera_scene_count(); ++seed) {
    const world::Scenario s = testing::camera_scene(seed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    Simulation sim(s);
    sim.step(50);
    CameraRig rig(sim, world::cameras_of(s), seed);
    const std::size_t cam = rig.index("overhead", {});
    CameraImage im;
    rig.render(cam, im, {.noise = true, .segmentation = false});
    CameraDetector detector(s, rig.cameras()[cam].noise);
    std::vector<world::Detection> seen;
    detector.detect(im, seen);
    // Each detection is scored against the thing of its class nearest its base (the scoring's
    // association; identity is the belief's job).
    std::vector<int> fitted_by(sim.things().size(), 0);
    std::vector<Eigen::Vector3d> fitted(sim.things().size());
    for (const world::Detection& d : seen) {
      const Eigen::Vector3d base(d.base[0], d.base[1], d.base[2]);
      int best = -1;
      double best_d = INFINITY;
      for (std::size_t k = 0; k < sim.things().size(); ++k) {
        const Thing& t = sim.things()[k];
        if (!t.present || t.name.empty() || t.cls != d.cls) continue;
        const double dist = (base - truth_base(sim, static_cast<int>(k))).head<2>().norm();
        if (dist < best_d) best_d = dist, best = static_cast<int>(k);
      }
    ASSERT_GE(best, 0) << "a detection of class " << d.cls << " and no such thing";
      EXPECT_TRUE(d.complete) << sim.things()[static_cast<std::size_t>(best)].name;
      ++fitted_by[static_cast<std::size_t>(best)];
      fitted[static_cast<std::size_t>(best)] = base;
    }
    // Every thing fitted once; poses near the truth; the placement equal to the truth's.
    world::Geometry geometry(s);
    for (std::size_t k = 0; k < sim.things().size(); ++k) {
      const Thing& t = sim.things()[k];
      if (!t.present || t.name.empty()) continue;
      ASSERT_EQ(fitted_by[k], 1) << t.name;
      const double e = (fitted[k] - truth_base(sim, static_cast<int>(k))).norm();
      errors.push_back(e);
      EXPECT_LE(e, 0.005) << t.name;
      if (t.container) geometry.move_container(t.name, {fitted[k].x(), fitted[k].y(), fitted[k].z()});
    }
    Perception truth(sim);
    const Percept p = truth.observe();
    for (const Observation& o : p.things) {
      const int k = sim.find(o.name);
      const Eigen::Vector3d& b = fitted[static_cast<std::size_t>(k)];
      const std::string at = o.container ? geometry.locate_region({b.x(), b.y(), b.z()}) : geometry.locate({b.x(), b.y(), b.z()});
      EXPECT_EQ(at, o.location) << o.name;
    }
    ++scenes;
  }
  std::sort(errors.begin(), errors.end());
  ASSERT_FALSE(errors.empty());
  const double median = errors[errors.size() / 2];
  EXPECT_LE(median, 0.002);
  std::printf("box fit over %d scenes, %zu things: base error median %.2f mm, p99 %.2f mm, worst %.2f mm\n", scenes,
              errors.size(), median * 1000, errors[errors.size() * 99 / 100] * 1000, errors.back() * 1000);
}

TEST(BoxFit, ExactBoxesAreFoundAndPartOfOneIsNotComplete) {
  // The top face of a 4 x 6 x 3 cm box at (0.3, -0.2), turned 0.4 rad, on the table, as a
  // grid of points 1 mm apart, plus side points below the top band.
  const world::Vec3 size{0.04, 0.06, 0.03};
  const double yaw = 0.4, c = std::cos(yaw), s = std::sin(yaw);
  std::vector<Eigen::Vector3d> pts;
  for (double u = -0.02; u <= 0.02 + 1e-9; u += 0.001)
    for (double v = -0.03; v <= 0.03 + 1e-9; v += 0.001) pts.emplace_back(0.3 + c * u - s * v, -0.2 + s * u + c * v, 0.03);
  for (double h = 0; h < 0.02; h += 0.002) pts.emplace_back(0.3 + c * 0.02, -0.2 + s * 0.02, h);
  const Eigen::Vector3d eye(0.3, -0.2, 1.0);  // straight above
  BoxFit f = fit_box(pts, size, false, eye);
  EXPECT_TRUE(f.complete);
  EXPECT_NEAR(f.base.x(), 0.3, 1e-4);
  EXPECT_NEAR(f.base.y(), -0.2, 1e-4);
  EXPECT_NEAR(f.base.z(), 0.0, 1e-6);
  EXPECT_NEAR(std::remainder(f.yaw - yaw, std::numbers::pi), 0, 1e-3);
  // Half of the top hidden: the sides no longer match, the fit says so.
  std::vector<Eigen::Vector3d> half;
  for (const auto& p : pts)
    if ((p - Eigen::Vector3d(0.3, -0.2, 0)).dot(Eigen::Vector3d(-s, c, 0)) > 0) half.push_back(p);
  f = fit_box(half, size, false, eye);
  EXPECT_FALSE(f.complete);
  EXPECT_FALSE(fit_box({}, size, false, eye).complete);
}

}  // namespace
}  // namespace rtamp::sim
