// Collision-free joint-space motion between two configurations: the straight
// joint segment when it is free, otherwise a detour planned with OMPL's
// RRTConnect (docs/design.md robot layer; issue "plan around with OMPL") followed by
// shortcut simplification.
//
// Determinism: the same inputs and seed give the same path. OMPL's own random
// generators are seeded from a process-wide sequence, so the planner here
// samples with its own seeded generator (a custom StateSampler), uses linear
// nearest-neighbour search, stops after a number of iterations (a wall-clock
// limit is only a safety net), and simplifies with its own seeded shortcutting.
// Invariants of a successful result: path.front() == from, path.back() == to,
// every segment is collision-free at `resolution` (when a checker is given).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/robot/collision_checker.hpp"
#include "rtamp/robot/joints.hpp"

namespace rtamp::robot {

struct PlannerOptions {
  double resolution = 0.02;     // rad: largest joint step between collision checks
  int max_iterations = 20000;   // RRTConnect iterations before giving up
  double time_limit = 5.0;      // s wall clock, safety net only
  double range = 1.0;           // rad: RRTConnect's extension step
  int shortcut_attempts = 200;  // random shortcuts tried after planning
  std::uint64_t seed = 1;
  JointLimits bounds;           // sampling bounds (default: the UR5's ±2π)
};

struct JointPathResult {
  bool ok = false;
  std::vector<Joints> path;  // from, ..., to
  bool planned = false;      // true if the direct segment collided and OMPL was used
  std::string why;           // failure reason
};

// The direct segment if no checker is given or it is free; otherwise RRTConnect.
JointPathResult plan_joint_path(const Joints& from, const Joints& to, CollisionChecker* checker,
                                const PlannerOptions& options = {});

}  // namespace rtamp::robot
