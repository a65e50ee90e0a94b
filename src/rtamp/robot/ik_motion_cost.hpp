// The `ik` model behind the planner's MotionCostModel interface
// (plan/motion_cost.hpp): move(o, l) costs the tool path length of the pick(o)
// and place(o, l) skill plans from the hand's pose (ik_cost_model.hpp; paper
// Section III-B). Header-only so that rtamp_robot does not have to link the
// planning layer; a program using it links rtamp_plan and rtamp_robot.
//
// It depends on the moved thing only through "is it a container" (blocks and
// trays are grasped differently), but MotionQuery carries that flag beside the
// thing's id, so depends() must include kDependsThing for the planner's
// experience cache to be exact; the model's own cache (keyed on the flag and the
// points) computes each geometry once regardless.
// Invariants: cost(q) >= lower_bound(q, false) >= 0; cost is +infinity when the
// skills cannot be planned (the planner gives such a move no edge:
// plan/cost_check.hpp).
#pragma once

#include <memory>
#include <string>

#include "rtamp/plan/motion_cost.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/robot/ik_cost_model.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::robot {

class IkMotionCost final : public plan::MotionCostModel {
 public:
  explicit IkMotionCost(IkCostParams params = {}) : model_(std::move(params)) {}

  // Parameters for a scenario: the robot's base pose, the planner's home point,
  // the first block's and the first container's sizes (defaults if there are none).
  static IkCostParams params_for(const world::Scenario& s) {
    IkCostParams p;
    p.arm.base = Ur5Kinematics::base_pose(s.robot);
    p.home_point = Eigen::Vector3d(s.robot.base[0], s.robot.base[1], s.robot.base[2] + task::kHomeHeight);
    if (!s.objects.empty()) p.block_size = s.objects.front().size;
    if (!s.containers.empty()) p.tray_size = s.containers.front().size;
    return p;
  }

  using plan::MotionCostModel::cost;  // cost(ts, s, a) as well
  std::string name() const override { return "ik"; }
  double cost(const plan::MotionQuery& q) const override {
    return model_.move_cost(v(q.hand), v(q.from), v(q.to), q.container);
  }
  double lower_bound(const plan::MotionQuery& q, bool to_anywhere) const override {
    return model_.lower_bound(v(q.hand), v(q.from), v(q.to), to_anywhere);
  }
  double carry_bound(const world::Vec3& from, const world::Vec3& to) const override {
    return model_.carry_bound(v(from), v(to));
  }
  // Without containers every move carries one block, whose tool path runs through
  // the hover points above its start and end (hover height above the points) and
  // goes down and up `approach` at both: the euclid transport bound on the hover
  // points, from the hand's tool point, plus 4·approach per delivered block
  // (docs/robot.md). With containers, the default (from lower_bound).
  double transport_bound(const plan::TransportQuery& t) const override {
    if (!t.one_at_a_time || !model_.bounds_valid()) return plan::MotionCostModel::transport_bound(t);
    plan::TransportQuery u = t;
    const Eigen::Vector3d h = model_.bound_hand_point(v(t.hand));
    u.hand = {h.x(), h.y(), h.z()};
    return plan::EuclidCost().transport_bound(u) +
           4.0 * model_.params().skills.approach_height * static_cast<double>(t.m);
  }
  unsigned depends() const override {
    return plan::kDependsThing | plan::kDependsHand | plan::kDependsFrom | plan::kDependsTo;
  }
  bool expensive() const override { return true; }

  IkCostModel& model() { return model_; }
  const IkCostModel& model() const { return model_; }

 private:
  static Eigen::Vector3d v(const world::Vec3& x) { return Eigen::Vector3d(x[0], x[1], x[2]); }
  IkCostModel model_;
};

// Adds "ik" to the planner's cost-model registry (plan/registry.hpp), built for
// each scenario with params_for(). Idempotent; programs that want the name
// call it once (the rtamp CLI at start, run_episode before planning).
inline void register_ik_cost_model() {
  plan::register_cost_model({"ik",
                             "tool path length of the UR5's pick and place skills, from inverse kinematics "
                             "(no collision checks)",
                             [](const world::Scenario& s) -> std::shared_ptr<plan::MotionCostModel> {
                               return std::make_shared<IkMotionCost>(IkMotionCost::params_for(s));
                             }});
}

}  // namespace rtamp::robot
