// robot layer benchmarks: FK, IK (all solutions / nearest), straight-line
// approach, trajectory parametrisation, a pick skill plan, OMPL planning around an
// obstacle, and one `ik` motion cost cold and cached (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <numbers>
#include <random>
#include <vector>

#include "rtamp/robot/ik_cost_model.hpp"
#include "rtamp/robot/motion_planner.hpp"
#include "rtamp/robot/skills.hpp"
#include "rtamp/robot/trajectory.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"

namespace {

using namespace rtamp::robot;

std::vector<Joints> random_configurations(std::size_t n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-std::numbers::pi, std::numbers::pi);
  std::vector<Joints> qs(n);
  for (auto& q : qs)
    for (double& x : q) x = u(rng);
  return qs;
}

void BM_ForwardKinematicsFlange(benchmark::State& state) {
  Ur5Kinematics arm;
  const auto qs = random_configurations(1024);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(arm.flange_pose(qs[i++ & 1023]));
}
BENCHMARK(BM_ForwardKinematicsFlange);

void BM_ForwardKinematicsAllLinkFrames(benchmark::State& state) {
  Ur5Kinematics arm;
  const auto qs = random_configurations(1024);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(arm.link_frames(qs[i++ & 1023]));
}
BENCHMARK(BM_ForwardKinematicsAllLinkFrames);

void BM_InverseKinematicsAllSolutions(benchmark::State& state) {
  Ur5Kinematics arm;
  const auto qs = random_configurations(1024);
  std::vector<Eigen::Isometry3d> poses;
  for (const auto& q : qs) poses.push_back(arm.tool_pose(q));
  std::size_t i = 0;
  long solutions = 0;
  for (auto _ : state) {
    IkSolutions s;
    solutions += arm.ik_tool(poses[i++ & 1023], s);
    benchmark::DoNotOptimize(s);
  }
  state.counters["solutions/query"] = benchmark::Counter(static_cast<double>(solutions) / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_InverseKinematicsAllSolutions);

void BM_InverseKinematicsNearest(benchmark::State& state) {
  Ur5Kinematics arm;
  const auto qs = random_configurations(1024);
  std::vector<Eigen::Isometry3d> poses;
  for (const auto& q : qs) poses.push_back(arm.tool_pose(q));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(arm.ik_nearest(poses[i & 1023], qs[(i + 1) & 1023]));
    ++i;
  }
}
BENCHMARK(BM_InverseKinematicsNearest);

const Joints kStart{0.3, -1.6, 1.6, -1.57, -1.57, 0.2};

void BM_CartesianLine10cm(benchmark::State& state) {
  Ur5Kinematics arm;
  Eigen::Isometry3d goal = arm.tool_pose(kStart);
  goal.translation().z() -= 0.10;
  for (auto _ : state) benchmark::DoNotOptimize(cartesian_line(arm, kStart, goal, CartesianOptions{}));
}
BENCHMARK(BM_CartesianLine10cm);

void BM_TrajectoryParametrisation(benchmark::State& state) {
  // A 4-waypoint joint path plus a 21-point straight-line polyline (a typical skill).
  Ur5Kinematics arm;
  Eigen::Isometry3d goal = arm.tool_pose(kStart);
  goal.translation().z() -= 0.10;
  const auto line = *cartesian_line(arm, kStart, goal, CartesianOptions{});
  const std::vector<Joints> path{Joints{}, Joints{1, -1, 1, 0, 0, 0}, Joints{0.5, -1.2, 1.4, -1, -1.5, 0}, kStart};
  for (auto _ : state) {
    Trajectory tr(path.front());
    tr.append_joint_path(path, MotionLimits{});
    tr.append_polyline(line, MotionLimits{});
    tr.append_dwell(0.3);
    benchmark::DoNotOptimize(tr.duration());
  }
}
BENCHMARK(BM_TrajectoryParametrisation);

void BM_TrajectorySample(benchmark::State& state) {
  Trajectory tr(Joints{});
  tr.append_joint_path({Joints{}, Joints{1, -1, 1, 0, 0, 0}, Joints{0.5, -1.2, 1.4, -1, -1.5, 0}}, MotionLimits{});
  double t = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tr.sample(t));
    t += 0.001;
    if (t > tr.duration()) t = 0;
  }
}
BENCHMARK(BM_TrajectorySample);

IkCostParams tray_scene() {
  IkCostParams p;  // 3-block-tray: base at the origin, yaw 0, home point (0, 0, 0.5)
  return p;
}

void BM_SkillPickPlan(benchmark::State& state) {
  IkCostModel m(tray_scene());
  const Joints home = m.params().home;
  const Grasp g = Grasp::block({0.04, 0.04, 0.04});
  for (auto _ : state) benchmark::DoNotOptimize(plan_pick(m.arm(), home, ThingPose{{0.40, 0.32, 0}, 0}, g));
}
BENCHMARK(BM_SkillPickPlan);

void BM_IkCostCold(benchmark::State& state) {
  IkCostModel m(tray_scene());
  const Eigen::Vector3d home(0, 0, 0.5), r1(0.40, 0.32, 0), r2(0.40, -0.32, 0);
  for (auto _ : state) {
    m.clear();
    benchmark::DoNotOptimize(m.move_cost(home, r1, r2, state.range(0) != 0));
  }
  state.SetLabel(state.range(0) ? "tray" : "block");
}
BENCHMARK(BM_IkCostCold)->Arg(0)->Arg(1);

void BM_IkCostColdWithCollisionChecks(benchmark::State& state) {
  // A synthetic checker (FK of every link frame against a sphere out of the way): shows
  // how many checks a cold cost makes; the sim's MuJoCo checker costs ~10 us per check.
  IkCostModel m(tray_scene());
  const Ur5Kinematics& arm = m.arm();
  FunctionCollisionChecker checker([&](const Joints& q) {
    const auto f = arm.link_frames(q);
    for (const auto& x : f)
      if ((x.translation() - Eigen::Vector3d(-0.5, 0, 0.3)).norm() < 0.1) return true;
    return false;
  });
  m.set_collision_checker(&checker);
  const Eigen::Vector3d home(0, 0, 0.5), r1(0.40, 0.32, 0), r2(0.40, -0.32, 0);
  const long before = checker.calls();
  for (auto _ : state) {
    m.clear();
    benchmark::DoNotOptimize(m.move_cost(home, r1, r2, false));
  }
  state.counters["checks/cost"] =
      benchmark::Counter(static_cast<double>(checker.calls() - before) / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_IkCostColdWithCollisionChecks);

void BM_IkCostCached(benchmark::State& state) {
  IkCostModel m(tray_scene());
  const Eigen::Vector3d home(0, 0, 0.5), r1(0.40, 0.32, 0), r2(0.40, -0.32, 0);
  m.move_cost(home, r1, r2, false);
  for (auto _ : state) benchmark::DoNotOptimize(m.move_cost(home, r1, r2, false));
}
BENCHMARK(BM_IkCostCached);

void BM_RrtConnectAroundJointBox(benchmark::State& state) {
  FunctionCollisionChecker box([](const Joints& q) { return std::abs(q[0]) < 0.3 && std::abs(q[1]) < 1.0; });
  const Joints a{-1, 0, 0, 0, 0, 0}, b{1, 0, 0, 0, 0, 0};
  for (auto _ : state) benchmark::DoNotOptimize(plan_joint_path(a, b, &box));
}
BENCHMARK(BM_RrtConnectAroundJointBox)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
