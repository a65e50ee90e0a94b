// The belief fed by the wrist camera (it moves with the arm and sees only part of the
// table), alone and beside a fixed camera narrowed to one region, in MuJoCo,
// against the truth: with the arm posed over a thing the wrist camera believes what it
// sees where it is and removes nothing (its frames taken where the flange is); with the arm moved over every thing in turn no
// thing is ever believed removed or added, and things only the wrist camera sees are
// kept; a block removed while only the wrist camera could see its spot is kept while the
// wrist looks elsewhere and believed removed once the wrist looks at its spot again.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "rtamp/robot/skills.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/sim/camera_perception.hpp"
#include "rtamp/sim/perception.hpp"
#include "camera_test_helpers.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

using testing::hover;
using testing::narrow_overhead;
using testing::pose_tool;
using testing::truth;
using testing::watch;

constexpr double kAbove = 0.25;  // m from a thing's top up to the tool: the wrist camera about 0.4 m up


// Whether `p` lies in the scene's region `r`, in the table's plane.
bool in_region(const world::Region& r, const Eigen::Vector3d& p) {
  return std::abs(p.x() - r.center[0]) <= r.size[0] / 2 && std::abs(p.y() - r.center[1]) <= r.size[1] / 2;
}

// The last frame's camera (the wrist's) sits over thing i, looking straight down: its
// extrinsics were read where the flange is now.
void expect_wrist_over(const CameraPerception& eyes, Simulation& sim, int i) {
  ASSERT_EQ(eyes.camera_name(), "wrist");
  const Extrinsics& e = eyes.image().extrinsics;
  const Eigen::Vector3d centre = e.to_world(Eigen::Vector3d::Zero()), p = sim.position(i);
  EXPECT_LT(std::hypot(centre.x() - p.x(), centre.y() - p.y()), 0.1);
  EXPECT_GT(centre.z() - p.z(), kAbove);
  EXPECT_GT(e.R.row(2).dot(Eigen::Vector3d(0, 0, -1)), 0.999);  // the optical axis points down
}

std::size_t state_count(const world::Belief& b, world::ThingState s) {
  std::size_t n = 0;
  for (const auto& t : b.things()) n += t.state == s;
  return n;
}

TEST(WristCamera, ArmPosedOverAThingSeesItWhereItIsAndRemovesNothing) {
  int posed = 0;
  for (std::uint64_t seed : {4u, 5u, 8u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const world::Scenario s = testing::camera_scene(seed);
    Simulation sim(s);
    sim.step(50);
    int i = -1;
    for (std::size_t k = 0; k < sim.things().size() && i < 0; ++k)
      if (!sim.thing(static_cast<int>(k)).container && hover(sim, static_cast<int>(k), kAbove)) i = static_cast<int>(k);
    ASSERT_GE(i, 0);
    ++posed;
    CameraPerception eyes(sim, {.cameras = {"wrist"}, .seed = seed});
    ASSERT_EQ(eyes.cameras().size(), 1u);
    watch(sim, eyes, 3);
    expect_wrist_over(eyes, sim, i);
    EXPECT_EQ(eyes.belief().placement(), truth(sim));
    const world::BelievedThing* b = eyes.belief().find(sim.thing(i).name);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->state, world::ThingState::Visible);
    const Eigen::Vector3d p = sim.position(i);
    EXPECT_LT(std::hypot(b->base[0] - p.x(), b->base[1] - p.y()), 0.005);
    EXPECT_EQ(eyes.belief().things().size(), s.objects.size() + s.containers.size());
    std::printf("seed %d: wrist sees %zu things, %zu out of its view\n", static_cast<int>(seed),
                state_count(eyes.belief(), world::ThingState::Visible),
                state_count(eyes.belief(), world::ThingState::OutOfView));
  }
  EXPECT_EQ(posed, 3);
}

TEST(WristCamera, MovingOverEveryThingBesideANarrowFixedCameraNeverRemovesOrAdds) {
  const world::Scenario s = narrow_overhead(testing::camera_scene(5));
  Simulation sim(s);
  sim.step(50);
  const robot::Joints home = sim.arm_q();
  CameraPerception eyes(sim, {.cameras = {"overhead", "wrist"}, .seed = 5});
  watch(sim, eyes, 2);
  const world::Placement before = truth(sim);
  EXPECT_EQ(eyes.belief().placement(), before);
  int hovered = 0, wrist_only = 0;
  for (std::size_t i = 0; i < sim.things().size(); ++i) {
    const Thing& t = sim.thing(static_cast<int>(i));
    if (t.name.empty() || !hover(sim, static_cast<int>(i), kAbove)) continue;
    ++hovered;
    for (int k = 0; k < 3; ++k) {
      watch(sim, eyes, 1);
      EXPECT_EQ(eyes.belief().placement(), before) << "over " << t.name << ", frame " << k;
    }
    expect_wrist_over(eyes, sim, static_cast<int>(i));
    const world::BelievedThing* b = eyes.belief().find(t.name);
    ASSERT_NE(b, nullptr);
    wrist_only += b->state == world::ThingState::Visible && !in_region(s.regions.back(), sim.position(static_cast<int>(i)));
  }
  sim.set_arm_configuration(home);
  watch(sim, eyes, 3);
  EXPECT_EQ(eyes.belief().placement(), before);
  EXPECT_GE(hovered, 3);
  EXPECT_GE(wrist_only, 1);  // seen by the wrist camera alone, and kept since
  EXPECT_GE(state_count(eyes.belief(), world::ThingState::OutOfView), 1u);
}

// A block outside the fixed camera's region within the arm's reach (-1 if none), and the
// tool over another region's centre, within reach, where the wrist camera looks elsewhere.
std::pair<int, std::optional<Eigen::Vector3d>> wrist_only_and_away(Simulation& sim) {
  const world::Scenario& s = sim.scenario();
  const robot::Joints home = sim.arm_q();
  int block = -1;
  std::optional<Eigen::Vector3d> away;
  for (std::size_t k = 0; k < sim.things().size() && block < 0; ++k) {
    const int i = static_cast<int>(k);
    const Thing& t = sim.thing(i);
    if (!t.name.empty() && !t.container && !in_region(s.regions.back(), sim.position(i)) && hover(sim, i, kAbove)) block = i;
  }
  if (block >= 0)
    for (const world::Region& r : s.regions) {
      const Eigen::Vector3d c(r.center[0], r.center[1], r.center[2] + kAbove);
      if (!away && !in_region(r, sim.position(block)) && pose_tool(sim, c)) away = c;
    }
  sim.set_arm_configuration(home);
  return {block, away};
}

TEST(WristCamera, ABlockRemovedWhereOnlyTheWristSeesIsBelievedRemovedOnceItLooksAgain) {
  std::uint64_t seed = 1;
  for (; seed <= 12; ++seed) {
    Simulation probe(narrow_overhead(testing::camera_scene(seed)));
    const auto [block, away] = wrist_only_and_away(probe);
    if (block >= 0 && away) break;
  }
  ASSERT_LE(seed, 12u) << "no scene with a block only the wrist camera can see";
  const world::Scenario s = narrow_overhead(testing::camera_scene(seed));
  Simulation sim(s);
  sim.step(50);
  CameraPerception eyes(sim, {.cameras = {"overhead", "wrist"}, .seed = 6});
  watch(sim, eyes, 2);
  const auto [gone, away] = wrist_only_and_away(sim);
  ASSERT_GE(gone, 0);
  ASSERT_TRUE(away);
  ASSERT_TRUE(hover(sim, gone, kAbove));
  const std::string name = sim.thing(gone).name;
  watch(sim, eyes, 2);
  ASSERT_EQ(eyes.belief().find(name)->state, world::ThingState::Visible);
  const Eigen::Vector3d spot = sim.position(gone);
  // The wrist looks at another region; the block is taken meanwhile.
  ASSERT_TRUE(pose_tool(sim, *away));
  sim.hide(gone);
  watch(sim, eyes, 10);
  ASSERT_NE(eyes.belief().find(name), nullptr) << "removed while no camera saw its spot";
  EXPECT_EQ(eyes.belief().find(name)->state, world::ThingState::OutOfView);
  // The wrist looks at the spot again (the tool over where the block stood).
  ASSERT_TRUE(pose_tool(sim, spot + Eigen::Vector3d(0, 0, 0.02 + kAbove)));
  const double back = sim.time();
  while (eyes.belief().find(name) && sim.time() < back + 2) watch(sim, eyes, 1);
  EXPECT_EQ(eyes.belief().find(name), nullptr);
  EXPECT_LE(sim.time() - back, eyes.belief().options().remove_after + 0.2 + 1e-9);
  EXPECT_EQ(eyes.belief().placement(), truth(sim));
}

}  // namespace
}  // namespace rtamp::sim
