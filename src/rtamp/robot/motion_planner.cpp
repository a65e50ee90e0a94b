#include "rtamp/robot/motion_planner.hpp"

#include <chrono>
#include <memory>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <random>

namespace rtamp::robot {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using RvState = ob::RealVectorStateSpace::StateType;

// Uniform / near / Gaussian sampling with a generator owned by one planning query.
class SeededSampler final : public ob::StateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, std::mt19937_64* rng, JointLimits bounds)
      : ob::StateSampler(space), rng_(rng), bounds_(bounds) {}
  void sampleUniform(ob::State* s) override {
    auto* v = s->as<RvState>();
    for (std::size_t j = 0; j < kDof; ++j)
      v->values[j] = std::uniform_real_distribution<double>(bounds_.lower[j], bounds_.upper[j])(*rng_);
  }
  void sampleUniformNear(ob::State* s, const ob::State* near, double distance) override {
    auto* v = s->as<RvState>();
    const auto* n = near->as<RvState>();
    for (std::size_t j = 0; j < kDof; ++j) {
      const double x = std::uniform_real_distribution<double>(n->values[j] - distance, n->values[j] + distance)(*rng_);
      v->values[j] = std::clamp(x, bounds_.lower[j], bounds_.upper[j]);
    }
  }
  void sampleGaussian(ob::State* s, const ob::State* mean, double std_dev) override {
    auto* v = s->as<RvState>();
    const auto* m = mean->as<RvState>();
    for (std::size_t j = 0; j < kDof; ++j) {
      const double x = std::normal_distribution<double>(m->values[j], std_dev)(*rng_);
      v->values[j] = std::clamp(x, bounds_.lower[j], bounds_.upper[j]);
    }
  }

 private:
  std::mt19937_64* rng_;
  JointLimits bounds_;
};

Joints to_joints(const ob::State* s) {
  const auto* v = s->as<RvState>();
  Joints q;
  for (std::size_t j = 0; j < kDof; ++j) q[j] = v->values[j];
  return q;
}

double l2(const Joints& a, const Joints& b) {
  double s = 0;
  for (std::size_t j = 0; j < kDof; ++j) s += (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(s);
}

Joints lerp(const Joints& a, const Joints& b, double f) {
  Joints q;
  for (std::size_t j = 0; j < kDof; ++j) q[j] = a[j] + f * (b[j] - a[j]);
  return q;
}

// Random shortcuts between two points anywhere on the path (each success shortens it).
void shortcut(std::vector<Joints>& path, CollisionChecker& checker, const PlannerOptions& o, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < o.shortcut_attempts && path.size() > 2; ++attempt) {
    std::vector<double> cum(path.size(), 0.0);
    for (std::size_t i = 1; i < path.size(); ++i) cum[i] = cum[i - 1] + l2(path[i - 1], path[i]);
    const double total = cum.back();
    if (total <= 0) break;
    double s1 = std::uniform_real_distribution<double>(0, total)(rng);
    double s2 = std::uniform_real_distribution<double>(0, total)(rng);
    if (s1 > s2) std::swap(s1, s2);
    auto seg = [&](double s) {
      std::size_t i = static_cast<std::size_t>(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());
      return std::min(std::max<std::size_t>(i, 1), path.size() - 1) - 1;  // segment index i: path[i]→path[i+1]
    };
    const std::size_t i1 = seg(s1), i2 = seg(s2);
    if (i1 == i2) continue;
    auto point = [&](std::size_t i, double s) {
      const double len = cum[i + 1] - cum[i];
      return len > 0 ? lerp(path[i], path[i + 1], (s - cum[i]) / len) : path[i];
    };
    const Joints a = point(i1, s1), b = point(i2, s2);
    if (segment_collides(checker, a, b, o.resolution)) continue;
    std::vector<Joints> out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i1) + 1);
    out.push_back(a);
    out.push_back(b);
    out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(i2) + 1, path.end());
    path.swap(out);
  }
  // Drop points that sit on a straight continuation (zero-length or collinear remnants).
  std::vector<Joints> clean{path.front()};
  for (std::size_t i = 1; i < path.size(); ++i)
    if (max_joint_delta(path[i], clean.back()) > 1e-12) clean.push_back(path[i]);
  if (clean.size() == 1) clean.push_back(path.back());
  path.swap(clean);
}

}  // namespace

JointPathResult plan_joint_path(const Joints& from, const Joints& to, CollisionChecker* checker,
                                const PlannerOptions& options) {
  JointPathResult r;
  if (!checker || !segment_collides(*checker, from, to, options.resolution)) {
    r.ok = true;
    r.path = {from, to};
    return r;
  }
  if (checker->config_collides(from)) {
    r.why = "start configuration collides";
    return r;
  }
  if (checker->config_collides(to)) {
    r.why = "goal configuration collides";
    return r;
  }

  r.planned = true;
  std::mt19937_64 rng(options.seed);
  auto space = std::make_shared<ob::RealVectorStateSpace>(kDof);
  ob::RealVectorBounds bounds(kDof);
  for (std::size_t j = 0; j < kDof; ++j) {
    bounds.setLow(static_cast<unsigned>(j), std::min(options.bounds.lower[j], std::min(from[j], to[j])));
    bounds.setHigh(static_cast<unsigned>(j), std::max(options.bounds.upper[j], std::max(from[j], to[j])));
  }
  space->setBounds(bounds);
  JointLimits sample_bounds;
  for (std::size_t j = 0; j < kDof; ++j) {
    sample_bounds.lower[j] = bounds.low[j];
    sample_bounds.upper[j] = bounds.high[j];
  }
  space->setStateSamplerAllocator([&rng, sample_bounds](const ob::StateSpace* s) -> ob::StateSamplerPtr {
    return std::make_shared<SeededSampler>(s, &rng, sample_bounds);
  });
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker([checker](const ob::State* s) { return !checker->config_collides(to_joints(s)); });
  si->setStateValidityCheckingResolution(options.resolution / space->getMaximumExtent());
  si->setup();

  ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space);
  for (std::size_t j = 0; j < kDof; ++j) {
    start[static_cast<unsigned>(j)] = from[j];
    goal[static_cast<unsigned>(j)] = to[j];
  }
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal);

  og::RRTConnect planner(si);
  planner.setRange(options.range);
  planner.setNearestNeighbors<ompl::NearestNeighborsLinear>();
  planner.setProblemDefinition(pdef);
  planner.setup();

  int iterations = 0;
  const auto t0 = std::chrono::steady_clock::now();
  ob::PlannerTerminationCondition ptc([&] {
    if (++iterations > options.max_iterations) return true;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > options.time_limit;
  });
  const ob::PlannerStatus status = planner.solve(ptc);
  if (status != ob::PlannerStatus::EXACT_SOLUTION) {
    r.why = "no collision-free joint path found (RRTConnect, " + std::to_string(iterations) + " iterations)";
    return r;
  }
  auto* geo = pdef->getSolutionPath()->as<og::PathGeometric>();
  std::vector<Joints> path;
  for (std::size_t i = 0; i < geo->getStateCount(); ++i) path.push_back(to_joints(geo->getState(i)));
  path.front() = from;
  path.back() = to;
  shortcut(path, *checker, options, rng);
  r.ok = true;
  r.path = std::move(path);
  return r;
}

}  // namespace rtamp::robot
