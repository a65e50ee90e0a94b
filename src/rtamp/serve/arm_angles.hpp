// Joint angles for the frames of a world that streams none (the symbolic world,
// a world laid out from perception): the UR5's closed-form inverse kinematics
// (robot::Ur5Kinematics, the robot layer's) for the frame's tool point with the
// gripper pointing down: of the solutions whose elbow and wrists are above the
// tool point (none through the table or a tray), the one nearest the previous
// frame's angles (the first: home, the MuJoCo model's). A tool point the arm
// cannot reach so (the symbolic world's parked hand) gives home.
// The page draws these angles as it draws MuJoCo's (forward kinematics), and a
// served log's `frame` records carry them, so a replay shows the same arm.
// Invariants: a filled q puts the tool at the frame's tool point (forward
// kinematics, < 1e-6 m) with link frames 2-4 above it, or is home; a frame that
// has angles is left alone.
#pragma once

#include "rtamp/exec/frame.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

class ArmAngles {
 public:
  explicit ArmAngles(const world::Robot& robot);

  // Fills f.q when the frame has none (the call order is the frames' order).
  void fill(exec::Frame& f);

  const robot::Joints& home() const { return home_; }
  const robot::Ur5Kinematics& kinematics() const { return kin_; }

 private:
  robot::Ur5Kinematics kin_;
  robot::Joints home_;
  robot::Joints last_;
};

}  // namespace rtamp::serve
