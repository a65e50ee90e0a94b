// The `ik` motion-cost model: the cost of move(o, l) is the end-effector path
// length of the pick(o) and place(o, l) skill plans (skills.hpp) from the hand's
// current pose — the paper's edge weight "computed by inverse kinematics"
// (Section III-B), cached by what it depends on so that replanning reuses it
// (Section III-C, "experience").
//
// Geometry of a query (all world frame, metres): the hand at point h means the
// tool hovering top-down at h + (0, 0, block grasp height + approach height) —
// exactly where a place at h ends — solved by IK nearest `home`; a hand at the
// home point (or at a point the arm cannot hover over) is the `home`
// configuration. The thing's base sits at point p with yaw 0 (blocks grasped at
// mid-height, containers at the rim, Grasp::block / Grasp::tray); it is placed
// with its base at point t. Unreachable moves cost +infinity.
// Cache: key = (container?, h, p, t) with the points snapped to `quantum`; the
// cost is computed from the snapped points, so a cached value is exactly what a
// cold computation would return. A collision checker, when set, makes costs
// depend on the world it checks: call clear() when that world changes. The
// lower bound's tool point of each hand point is kept too (IK, no collisions:
// it never changes), so a bound costs no IK after the first at that point.
// Not thread-safe (the cache is mutated by const calls).
#pragma once

#include <chrono>
#include <cstdint>
#include <unordered_map>

#include "rtamp/robot/skills.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"

namespace rtamp::robot {

struct IkCostParams {
  Ur5Kinematics::Config arm;  // geometry and base pose (Ur5Kinematics::base_pose(scenario.robot))
  Joints home{0.0, -1.5707963267948966, 1.5707963267948966, -1.5707963267948966, -1.5707963267948966, 0.0};
  Eigen::Vector3d home_point{0, 0, 0.5};  // the planner's home point (base + (0, 0, 0.5))
  SkillOptions skills;
  world::Vec3 block_size{0.04, 0.04, 0.04};
  world::Vec3 tray_size{0.24, 0.16, 0.03};
  double tray_rim = 0.008;
  double quantum = 1e-4;  // m
};

class IkCostModel {
 public:
  explicit IkCostModel(IkCostParams params = {});

  // Cost of picking the thing at `from` (a container if `container`) with the hand at
  // `hand` and placing it at `to`; +infinity if a skill cannot be planned.
  double move_cost(const Eigen::Vector3d& hand, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                   bool container) const;
  // The full plan behind a cost (not cached).
  SkillPlan move_plan(const Eigen::Vector3d& hand, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                      bool container) const;
  // The arm configuration for a hand at point h (see header comment).
  Joints hand_configuration(const Eigen::Vector3d& hand) const;

  // Lower bound on the cost of any move sequence that starts with the hand at `hand`,
  // picks the thing at `from` (or its container) and brings it to `to`:
  //   |H − (from + hover)| + |from − to|   (to_anywhere: first term only),
  // H the tool point of hand_configuration(hand). Every pick/place tool path visits the
  // hover points (up to a container's rim offset) and goes down and up twice (4·approach
  // height), which pays for the rim offset; if the parameters break that margin the bound
  // is 0 (docs/robot.md has the argument).
  double lower_bound(const Eigen::Vector3d& hand, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                     bool to_anywhere) const;
  // Lower bound on the cost of the moves of one thing, each carrying it, from point
  // `from` to point `to`, wherever the hand is: |from − to| (each move's tool path
  // goes from above its start to above its end, with the same margin), or 0 where
  // lower_bound is 0.
  double carry_bound(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
    return bound_valid_ ? (from - to).norm() : 0.0;
  }
  // The point P with |P − p| = |H − (p + hover)| for every p, H the tool point of
  // hand_configuration(hand): the euclid bounds on P and the location points bound
  // the tool's travel between hover points.
  Eigen::Vector3d bound_hand_point(const Eigen::Vector3d& hand) const {
    return hand_tool_point(hand) - Eigen::Vector3d(0, 0, hover_height());
  }
  // Whether the bounds above are the ones documented (false: they are 0).
  bool bounds_valid() const { return bound_valid_; }

  void set_collision_checker(CollisionChecker* checker) {
    checker_ = checker;
    clear();
  }
  void clear() const { cache_.clear(); }

  // Tool height above a location's point when hovering there (block grasp height + approach).
  double hover_height() const { return block_grasp_.offset.z() + params_.skills.approach_height; }

  const IkCostParams& params() const { return params_; }
  const Ur5Kinematics& arm() const { return arm_; }
  std::uint64_t cold_computations() const { return cold_; }
  std::uint64_t cache_hits() const { return hits_; }
  double cold_seconds() const { return cold_seconds_; }  // total time spent in cold computations
  std::size_t cache_size() const { return cache_.size(); }
  std::size_t bound_points() const { return tool_points_.size(); }  // hand points whose tool point is kept

 private:
  struct Key {
    std::int64_t v[9];
    bool container;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  Eigen::Vector3d snap(const Eigen::Vector3d& x, std::int64_t* out) const;
  // The tool point of hand_configuration(hand), kept by the hand point's exact bits.
  const Eigen::Vector3d& hand_tool_point(const Eigen::Vector3d& hand) const;
  struct PointKey {
    std::uint64_t v[3];
    friend bool operator==(const PointKey&, const PointKey&) = default;
  };
  struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const;
  };

  IkCostParams params_;
  Ur5Kinematics arm_;
  Grasp block_grasp_, tray_grasp_;
  CollisionChecker* checker_ = nullptr;
  bool bound_valid_ = true;
  mutable std::unordered_map<Key, double, KeyHash> cache_;
  mutable std::unordered_map<PointKey, Eigen::Vector3d, PointKeyHash> tool_points_;
  mutable std::uint64_t cold_ = 0, hits_ = 0;
  mutable double cold_seconds_ = 0;
};

}  // namespace rtamp::robot
