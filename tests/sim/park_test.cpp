// The MuJoCo world with a camera parks an idle, empty arm at home, out of the fixed
// camera's view: after a move ends and no other starts, the arm goes home within a few
// seconds, hand() becomes home (""), and every thing is seen again (none left covered by
// the arm); a move started meanwhile takes over from where the arm is and succeeds. With
// the truth perceived the arm stays where its last move left it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "rtamp/episode/sim_world.hpp"
#include "camera_test_helpers.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

exec::MoveStatus finish(episode::SimWorld& w, double limit = 30) {
  exec::MoveStatus st = w.poll(nullptr);
  const double until = w.time() + limit;
  while ((st == exec::MoveStatus::Running || w.busy()) && w.time() < until) {
    w.advance(0.01);
    st = w.poll(nullptr);
  }
  return st;
}

double from_home(episode::SimWorld& w) {
  const robot::Joints q = w.session().sim().arm_q(), home = w.session().skills().home();
  double far = 0;
  for (int j = 0; j < 6; ++j) far = std::max(far, std::abs(q[j] - home[j]));
  return far;
}

// A world perceiving through `source` after move(o1, r2) succeeded (null if it did not).
std::unique_ptr<episode::SimWorld> after_a_move(PerceptionSource source) {
  SessionOptions o;
  o.perception.source = source;
  auto w = std::make_unique<episode::SimWorld>(testing::three_block(), o);
  w->advance(0.5);
  w->start({"move(o1, r2)", "o1", "r1", "r2"});
  if (finish(*w) != exec::MoveStatus::Succeeded) return nullptr;
  return w;
}

TEST(Park, AnIdleArmGoesHomeWithACameraAndEveryThingIsSeenAgain) {
  auto world = after_a_move(PerceptionSource::Camera);
  ASSERT_TRUE(world);
  episode::SimWorld& w = *world;
  EXPECT_EQ(w.hand(), "r2");
  EXPECT_GT(from_home(w), 0.3);
  const double ended = w.time();
  bool parked = false;
  while (w.time() < ended + 8 && !(parked = !w.parking() && from_home(w) < 0.02)) w.advance(0.05);
  ASSERT_TRUE(parked) << "still " << from_home(w) << " rad from home";
  EXPECT_GT(w.time(), ended + episode::SimWorld::kParkAfter);
  EXPECT_EQ(w.hand(), "");
  w.advance(0.5);  // the camera's next frames
  for (const auto& t : w.session().perception().camera()->belief().things())
    EXPECT_EQ(t.state, world::ThingState::Visible) << t.name;
  EXPECT_EQ(w.observe(), testing::truth(w.session().sim()));
}

TEST(Park, AMoveStartedWhileTheArmParksTakesOver) {
  auto world = after_a_move(PerceptionSource::Camera);
  ASSERT_TRUE(world);
  episode::SimWorld& w = *world;
  w.advance(0.6);
  ASSERT_TRUE(w.parking());
  w.start({"move(o2, r2)", "o2", "r1", "r2"});
  EXPECT_FALSE(w.parking());
  EXPECT_EQ(finish(w), exec::MoveStatus::Succeeded);
  EXPECT_EQ(*testing::truth(w.session().sim()).location_of("o2"), "r2");
  EXPECT_EQ(w.hand(), "r2");
}

TEST(Park, WithTheTruthPerceivedTheArmStaysWhereItWas) {
  auto world = after_a_move(PerceptionSource::Truth);
  ASSERT_TRUE(world);
  episode::SimWorld& w = *world;
  const robot::Joints q = w.session().sim().arm_q();
  w.advance(3);
  EXPECT_FALSE(w.parking());
  const robot::Joints after = w.session().sim().arm_q();
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(after[j], q[j], 0.01) << "joint " << j;
  EXPECT_EQ(w.hand(), "r2");
}

}  // namespace
}  // namespace rtamp::sim
