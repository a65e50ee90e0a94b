// Skills executed in the simulation: the bridge between the robot layer's skill plans
// (robot/skills.hpp: pick(o), place(o, spot) as trajectories + gripper events) and the
// controller. It reads where things are from the simulation, chooses a free spot in the
// target location (scene.hpp), plans with a MuJoCo collision checker on a scratch
// mjData, and starts the controller — the paper's "skill library" of Fig. 2 running on
// the simulated UR5. A tray is moved like a block (grasped on a long rim); its contents
// ride along physically.
//
// Non-blocking use (a BT action node): start_pick / start_place, then Controller::step()
// until it is not RUNNING. Blocking use (CLI, tests): move(o, l) = pick + place.
// Invariants: a failed plan leaves the controller in FAILURE with the planner's reason
// (e.g. "unreachable"); a place is only started while the object is held.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/robot/skills.hpp"
#include "rtamp/sim/controller.hpp"
#include "rtamp/sim/scene.hpp"

namespace rtamp::sim {

// robot::CollisionChecker on the simulation's scratch data.
class SimCollisionChecker final : public robot::CollisionChecker {
 public:
  SimCollisionChecker(const Simulation& sim, std::vector<int> ignore = {}) : sim_(sim), ignore_(std::move(ignore)) {}
  bool config_collides(const robot::Joints& q) override {
    ++calls_;
    return sim_.config_collides(q, ignore_);
  }
  long calls() const { return calls_; }

 private:
  const Simulation& sim_;
  std::vector<int> ignore_;
  long calls_ = 0;
};

struct ActionResult {
  std::string action;  // "move o1 r2"
  Status status = Status::Idle;
  std::string reason;  // failure reason
  double cost = 0;     // motion cost: tool path length of the executed plans (m)
  double start = 0;    // sim time at start
  double duration = 0; // sim time it took
};

// Where the robot perceives a thing (camera perception): its base and yaw, and the box
// it believes the thing has.
struct SeenThing {
  robot::ThingPose pose;
  world::Vec3 size{};
  bool container = false;
};

struct SkillRunnerOptions {
  robot::SkillOptions skill;
  double place_gap = world::kPlaceGap;  // clearance between placed things (room for the fingers)
  double drop_height = 0.003; // place a thing this far above its support
  bool collision_checking = true;
  // Places obey the rule book (world/space_rules.hpp); false only to measure what the
  // arm can place regardless (tests/sim/packing_test.cpp).
  bool space_rules = true;
};

class SkillRunner {
 public:
  SkillRunner(Simulation& sim, Controller& controller, SkillRunnerOptions options = {});

  const robot::Ur5Kinematics& arm() const { return arm_; }
  // The grasp used for a thing (blocks: around the middle; trays: a long rim).
  robot::Grasp grasp_for(int thing) const;
  static robot::Grasp grasp_for(const world::Vec3& size, bool container);

  // Plan and start a pick of `object` where it is, or where the robot `seen` it (its
  // perceived base and yaw: a pose that is off makes the grasp miss, as on a real robot).
  // With `seen`, the object need not be in the scene at all (a thing removed where the
  // camera could not see): the arm goes there and its fingers close on nothing.
  // False (controller in FAILURE) if planning failed.
  bool start_pick(const std::string& object, const std::optional<SeenThing>& seen = {});
  // Plan and start placing the held object into `location` (region or container). False
  // (controller in FAILURE) if the rule book refuses it there ("cannot place o3: r2 has no
  // room (capacity 2)", sim::space_refusal), there is no free spot or no plan. The rule
  // book is asked again when the fingers are to open: refused then (a person filled the
  // location meanwhile), the thing stays in hand, the arm backs up and the controller
  // ends FAILURE with the same words.
  bool start_place(const std::string& location);
  // Back the empty gripper straight up by `height` (after a halted skill), unless the
  // tool is already that high above the table. False (controller in FAILURE) if the
  // gripper holds something or the line is not feasible; true if no motion is needed
  // (then the controller is left as it was) or the motion started.
  bool start_retreat(double height = 0.10);
  // Take the empty arm home (the model's "home" keyframe), out of a fixed camera's view:
  // straight up to `height` above the table, then in joint space. False (controller in
  // FAILURE) if the gripper holds something or a part of the path collides; true if the
  // arm is home already (controller left as it was) or the motion started.
  bool start_park(double height = 0.25);
  // The arm's home configuration.
  robot::Joints home() const;
  // The spot a place into `location` would use for thing `i` (centre of its base).
  std::optional<world::Vec3> place_spot(int thing, const std::string& location) const;
  // The grasp the held thing is actually in (its pose relative to the tool, as welded),
  // not the nominal one: a thing pushed while the fingers closed (after a missed grasp,
  // say) sits off the tool axis, and a place must put the THING on its spot.
  robot::Grasp held_grasp(int thing) const;

  // Blocking pick + place; `on_step` runs after every physics step (operator, video).
  ActionResult move(const std::string& object, const std::string& location,
                    const std::function<void()>& on_step = {});
  // Runs the controller to completion, calling on_step after each physics step.
  Status run_controller(const std::function<void()>& on_step, double max_time = 120);

 private:
  Simulation& sim_;
  Controller& controller_;
  SkillRunnerOptions options_;
  robot::Ur5Kinematics arm_;
  std::vector<int> carried_;   // contents of a picked tray
};

}  // namespace rtamp::sim
