// MJCF generation: the MuJoCo world of a scenario, built as XML text at run time
// (docs/design.md "Simulation"; the paper's Gazebo scene of Section V, rebuilt for MuJoCo).
//
// What the model holds, in this order (the order is part of the contract with
// simulation.hpp: the arm's 6 hinge joints are joints 0..5 = dofs 0..5, the two
// finger slides are joints 6, 7, then one free joint per movable body):
//  - a table (top face at z = 0), visual-only region rectangles with outlines;
//  - the UR5 of the model file models/ur5.xml (sim/ur5_model.hpp; its <custom>,
//    <default>, <worldbody> and <actuator> sections, spliced in), on a body "ur5:mount"
//    at the scenario's base pose. Its site "flange" equals A_1 ... A_6 of the DH
//    parameters robot::Ur5Kinematics uses (both come from that file), and site "tcp" is
//    the flange moved tool_offset along its z (robot::Ur5Kinematics' tool frame);
//  - a parallel two-finger gripper inside the body "ur5:flange" (body "gripper" =
//    flange frame; fingers slide along tool y; a finger's joint value is the distance of
//    its inner face from the tool axis);
//  - one body with a free joint per scenario object (box) and container (base plate
//    plus four rims), then reserved spare blocks and trays parked out of view with
//    contacts disabled (the operator's "add" uses them);
//  - one inactive weld equality (gripper, body) per movable body, named "grasp:<body>";
//  - a fixed camera "overview" that frames table, regions, arm and objects;
//  - one MuJoCo camera "camera:<name>" per camera of world::cameras_of(scenario): a
//    fixed one in the world body, a wrist one inside the flange body; the offscreen
//    buffer holds the largest of their images.
// Invariants: body names are "obj:<name>", "ctr:<name>", "spare_block:<k>",
// "spare_tray:<k>"; every movable body has exactly one free joint and one weld.
#pragma once

#include <array>
#include <string>

#include "rtamp/robot/joints.hpp"
#include "rtamp/world/fit.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::sim {

// What the scene adds to the UR5 model file (whose DH parameters are fixed there).
struct ArmGeometry {
  double tool_offset = 0.15;  // flange -> fingertip centre along flange z
};

struct MjcfOptions {
  ArmGeometry arm;
  // Initial arm configuration: tool pointing down above the table, clear of it.
  robot::Joints home{0.0, -1.5707963267948966, 1.5707963267948966, -1.5707963267948966, -1.5707963267948966, 0.0};
  int spare_blocks = 4;  // hidden bodies the operator can add as blocks
  int spare_trays = 1;   // hidden bodies the operator can add as trays
  world::Vec3 spare_block_size{0.04, 0.04, 0.04};
  world::Vec3 spare_tray_size{0.24, 0.16, 0.03};
  double timestep = 0.002;
  double block_mass = 0.1;  // kg
  double tray_mass = 0.4;   // kg
  double friction = 1.0;    // sliding friction of blocks, trays, fingers
  double finger_max = 0.04;  // fully open: inner faces 2 * finger_max apart
};

// Geometric constants of the generated trays and gripper that other parts need.
inline constexpr double kTrayPlate = 0.01;  // thickness of a tray's base plate (= world::kContainerFloor)
inline constexpr double kTrayRim = world::kContainerRim;  // thickness of its rims (the rule book's)
inline constexpr double kFingerPad = 0.01;   // finger thickness along tool y
inline constexpr double kFingerTipBelowTcp = 0.004;  // fingers reach this far past the tool point

// The MuJoCo camera of a scenario camera: "camera:<name>".
std::string mujoco_camera_name(const std::string& camera);

// Where a parked (hidden) spare body sits: far below the table, out of view.
world::Vec3 parking_position(int index);

// z of a scenario object's body origin (box centre), lifting it onto a tray's floor when
// its footprint centre lies inside a container of the scenario.
double object_base_z(const world::Scenario& s, const world::Object& o);

// The model as MJCF text. Throws rtamp::Error on names MJCF cannot hold.
std::string build_mjcf(const world::Scenario& scenario, const MjcfOptions& options = {});

}  // namespace rtamp::sim
