// The joint angles the page shows for the UR5 (main thread; the drawing worker only
// draws them, render/robot.js). With streamed joint angles (MuJoCo) they are the
// frame's; in the symbolic world (q = null) the arm reaches the streamed tool point
// pointing down (kinematics.js reachTool, warm-started from the last solution, ~0.25 ms),
// or rests at home when that point is out of such reach (the symbolic world's parked
// hand). Kept on the main thread so that window.rtamp.tool is the drawn tool point of
// the latest frame at once, not after a round trip to the worker.
// Invariant: toolPoint is linkFrames(robot, q)[7]'s origin for the q last returned.
import { linkFrames, origin, reachTool } from './kinematics.js';

export class ArmPose {
  constructor(robot) {
    this.robot = robot;
    this.reached = false;
    this.set(robot.home);
  }

  set(q) {
    this.q = q;
    this.toolPoint = origin(linkFrames(this.robot, q)[7]);
    return q;
  }

  // The angles to show for a frame ({q} or {tool}).
  update(frame) {
    if (Array.isArray(frame.q)) return this.set(frame.q);
    if (!Array.isArray(frame.tool)) return this.set(this.robot.home);
    // A tool point the arm cannot reach pointing down (the server parks the symbolic hand
    // above the base) leaves the arm at home.
    const q = reachTool(this.robot, frame.tool, this.reached ? this.q : this.robot.home);
    const p = origin(linkFrames(this.robot, q)[7]);
    this.reached = Math.hypot(p[0] - frame.tool[0], p[1] - frame.tool[1], p[2] - frame.tool[2]) < 0.005;
    return this.set(this.reached ? q : this.robot.home);
  }
}
