// A move of a thing the camera still believes present after a person took it where no
// camera could see (out of view here; under the arm in the batch): the arm goes to the
// believed pose and its fingers close on nothing there — the move fails as a missed grasp,
// not at once — the empty gripper backs off, the belief no longer holds the thing (the
// grasp was the look the camera could not take), and the next pick grasps.
// With the truth perceived, such a move still fails at once: nothing is believed there.
// Two blocks swapped out of sight: a move takes the block where its thing is believed.
#include <gtest/gtest.h>

#include "camera_test_helpers.hpp"
#include "rtamp/episode/sim_world.hpp"
#include "test_scenarios.hpp"

namespace rtamp::sim {
namespace {

// Runs the world until the move ends and the arm is free; the move's status and reason.
std::pair<exec::MoveStatus, std::string> finish(episode::SimWorld& w, double limit = 30) {
  std::string why;
  exec::MoveStatus st = w.poll(&why);
  const double until = w.time() + limit;
  while ((st == exec::MoveStatus::Running || w.busy()) && w.time() < until) {
    w.advance(0.01);
    st = w.poll(&why);
  }
  return {st, why};
}

// The overhead camera narrowed to r2: the blocks in r1 lie outside its view, so what the
// robot believes of them it cannot check by looking — as of a block under the arm.
class OutOfSight : public ::testing::Test {
 protected:
  OutOfSight() : w(testing::narrow_overhead(testing::three_block(), 1), camera()), sim(w.session().sim()),
                 eyes(*w.session().perception().camera()) {
    w.advance(0.5);
  }
  static SessionOptions camera() {
    SessionOptions o;
    o.perception.source = PerceptionSource::Camera;
    return o;
  }
  episode::SimWorld w;
  Simulation& sim;
  const CameraPerception& eyes;
};

TEST_F(OutOfSight, AMoveOfAThingTakenOutOfSightClosesOnNothingWhereItWasBelieved) {
  ASSERT_EQ(w.observe(), testing::truth(sim));
  ASSERT_EQ(eyes.belief().find("o2")->state, world::ThingState::OutOfView);
  const world::BelievedThing believed = *eyes.belief().find("o2");
  sim.hide(sim.find("o2"));  // taken where no camera sees
  w.advance(1.0);
  ASSERT_TRUE(w.observe().things.count("o2"));

  const double t0 = w.time();
  w.start({"move(o2, r2)", "o2", "r1", "r2"});
  const auto [status, why] = finish(w);
  EXPECT_EQ(status, exec::MoveStatus::Failed);
  EXPECT_NE(why.find("missed"), std::string::npos) << why;
  // The fingers closed where o2 was believed, after the arm had got there.
  const Simulation::FailedGrasp& grasp = sim.last_failed_grasp();
  EXPECT_TRUE(grasp.empty);
  EXPECT_GT(grasp.time, t0 + 0.5);
  EXPECT_LT(std::hypot(grasp.tool.x() - believed.base[0], grasp.tool.y() - believed.base[1]), 0.005);
  // Backed off, and the belief has let o2 go: what is perceived is the truth again.
  EXPECT_GT(sim.tool_pose().translation().z(), grasp.tool.z() + 0.05);
  EXPECT_EQ(eyes.belief().find("o2"), nullptr);
  EXPECT_EQ(w.observe(), testing::truth(sim));
  // The next pick starts with open fingers and grasps o1 (the missed grasp left them closed).
  w.start({"move(o1, r2)", "o1", "r1", "r2"});
  EXPECT_EQ(finish(w).first, exec::MoveStatus::Succeeded);
}

// Blocks of one colour look alike: two swapped where no camera sees keep their believed
// names, so a move of o1 goes where o1 is believed and takes the block that lies there
// (the simulation's o2), not the body named o1.
TEST_F(OutOfSight, AMoveTakesTheBlockWhereItsThingIsBelievedWhateverItsName) {
  const int o1 = sim.find("o1"), o2 = sim.find("o2");
  const Eigen::Isometry3d p1 = sim.pose(o1), p2 = sim.pose(o2);
  sim.set_pose(o1, p2);  // swapped out of view
  sim.set_pose(o2, p1);
  w.advance(1.0);
  ASSERT_EQ(eyes.belief().find("o1")->state, world::ThingState::OutOfView);
  w.start({"move(o1, r2)", "o1", "r1", "r2"});
  ASSERT_EQ(finish(w).first, exec::MoveStatus::Succeeded);
  EXPECT_EQ(*testing::truth(sim).location_of("o2"), "r2");
  EXPECT_EQ(*testing::truth(sim).location_of("o1"), "r1");
  EXPECT_EQ(*w.observe().location_of("o1"), "r2");  // the belief's name for it
}

TEST(MissedGrasp, WithTheTruthPerceivedAMoveOfAThingNotThereFailsAtOnce) {
  episode::SimWorld w(testing::three_block(), SessionOptions{});
  Simulation& sim = w.session().sim();
  w.advance(0.1);
  sim.hide(sim.find("o2"));
  w.start({"move(o2, r2)", "o2", "r1", "r2"});
  std::string why;
  EXPECT_EQ(w.poll(&why), exec::MoveStatus::Failed);
  EXPECT_EQ(why, "'o2' is not in the scene");
  EXPECT_LT(sim.last_failed_grasp().time, 0);
}

}  // namespace
}  // namespace rtamp::sim
