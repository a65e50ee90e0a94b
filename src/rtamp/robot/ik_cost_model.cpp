#include "rtamp/robot/ik_cost_model.hpp"

#include <bit>
#include <cmath>
#include <limits>

namespace rtamp::robot {

IkCostModel::IkCostModel(IkCostParams params)
    : params_(std::move(params)),
      arm_(params_.arm),
      block_grasp_(Grasp::block(params_.block_size)),
      tray_grasp_(Grasp::tray(params_.tray_size, params_.tray_rim)) {
  // Margin of the lower bound (docs/robot.md): 4·approach ≥ 3·|rim offset| + |Δ grasp height|.
  const double rim = std::hypot(tray_grasp_.offset.x(), tray_grasp_.offset.y());
  const double dz = std::abs(tray_grasp_.offset.z() - block_grasp_.offset.z());
  bound_valid_ = 4 * params_.skills.approach_height >= 3 * rim + dz;
}

std::size_t IkCostModel::KeyHash::operator()(const Key& k) const {
  std::uint64_t h = k.container ? 0x9e3779b97f4a7c15ull : 0x51afd7ed558ccd8dull;
  for (std::int64_t x : k.v) {
    h ^= static_cast<std::uint64_t>(x) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 31;
  }
  return static_cast<std::size_t>(h);
}

std::size_t IkCostModel::PointKeyHash::operator()(const PointKey& k) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (std::uint64_t x : k.v) {
    h ^= x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 31;
  }
  return static_cast<std::size_t>(h);
}

const Eigen::Vector3d& IkCostModel::hand_tool_point(const Eigen::Vector3d& hand) const {
  PointKey key{};
  for (int i = 0; i < 3; ++i) key.v[i] = std::bit_cast<std::uint64_t>(hand[i]);
  auto it = tool_points_.find(key);
  if (it == tool_points_.end()) it = tool_points_.emplace(key, arm_.tool_point(hand_configuration(hand))).first;
  return it->second;
}

Eigen::Vector3d IkCostModel::snap(const Eigen::Vector3d& x, std::int64_t* out) const {
  Eigen::Vector3d s;
  for (int i = 0; i < 3; ++i) {
    out[i] = static_cast<std::int64_t>(std::llround(x[i] / params_.quantum));
    s[i] = static_cast<double>(out[i]) * params_.quantum;
  }
  return s;
}

Joints IkCostModel::hand_configuration(const Eigen::Vector3d& hand) const {
  if ((hand - params_.home_point).norm() < params_.quantum) return params_.home;
  const Eigen::Vector3d hover = hand + Eigen::Vector3d(0, 0, hover_height());
  const auto q = arm_.ik_nearest(top_down_pose(hover, 0.0), params_.home, params_.skills.weights);
  return q ? *q : params_.home;
}

SkillPlan IkCostModel::move_plan(const Eigen::Vector3d& hand, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                 bool container) const {
  const Grasp& g = container ? tray_grasp_ : block_grasp_;
  return plan_pick_and_place(arm_, hand_configuration(hand), ThingPose{from, 0.0}, ThingPose{to, 0.0}, g,
                             params_.skills, checker_, checker_);
}

double IkCostModel::move_cost(const Eigen::Vector3d& hand, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                              bool container) const {
  Key key{};
  key.container = container;
  const Eigen::Vector3d h = snap(hand, key.v), p = snap(from, key.v + 3), t = snap(to, key.v + 6);
  if (auto it = cache_.find(key); it != cache_.end()) {
    ++hits_;
    return it->second;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const SkillPlan plan = move_plan(h, p, t, container);
  const double cost = plan.ok ? plan.cost : std::numeric_limits<double>::infinity();
  cold_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++cold_;
  cache_.emplace(key, cost);
  return cost;
}

double IkCostModel::lower_bound(const Eigen::Vector3d& hand, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                bool to_anywhere) const {
  if (!bound_valid_) return 0.0;
  // The tool starts at H (the hand configuration's tool point) and must reach the hover
  // point above `from` (up to the grasp offset, paid for by the margin), then above `to`.
  const Eigen::Vector3d& tool = hand_tool_point(hand);
  const Eigen::Vector3d hover_from = from + Eigen::Vector3d(0, 0, hover_height());
  return (tool - hover_from).norm() + (to_anywhere ? 0.0 : (from - to).norm());
}

}  // namespace rtamp::robot
