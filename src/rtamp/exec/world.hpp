// The world the reactive loop (reactive_loop.hpp, the paper's Algorithm 1)
// perceives and acts in: the one interface a user implements to run rtamp on
// their own robot and perception. rtamp ships two: the MuJoCo UR5
// (episode/sim_world.hpp) and a symbolic world with no physics
// (symbolic_world.hpp).
//
// The loop only ever
//  - asks what time it is and lets time pass (advance),
//  - observes where every present thing is (observe, confirming),
//  - starts one move at a time, polls it, and may halt it (start / poll / halt / busy).
// People act on the world on their own: the loop learns of their interventions
// by observing; take_events() only reports them for the log. A world a
// simulated person can act on says so (intervenable(), intervenable.hpp); a
// PersonWorld (person_world.hpp) then drives it — the loop still only observes.
// A world that can draw itself for pictures says so too (frames(), frame.hpp).
//
// Contract (what the loop relies on):
//  - observe() lists every present thing with its class; a thing the gripper
//    holds has location kInHand ("hand"), a thing outside every region and
//    container has location "none".
//  - start(m) begins move(m.thing, m.to) from wherever m.thing is; poll()
//    reports Running until it ends in Succeeded or Failed (with a reason). At
//    most one move runs; start() is only called when poll() is not Running
//    and busy() is false.
//  - halt() stops the running move. The world then makes the arm safe on its
//    own: a held thing goes back to the move's source, or — if that is gone or
//    has no room — to another valid location; an empty gripper backs off.
//    busy() is true until that is done; poll() reports Failed ("halted").
//  - A thing taken out of the gripper by a person ends the running move with
//    Failed.
//  - While no move runs, a world may move its empty arm on its own (the MuJoCo
//    world with a camera parks it out of the camera's view); start() then takes
//    over from where the arm is, and hand() says where the arm is.
//  - next_event_time() lets a discrete-event world say when something will
//    next happen; continuous worlds return infinity and are ticked at the
//    loop's tick period. The loop is live: it ticks the tree before it lets
//    time pass, and while the arm is free it never advances a world more than
//    one tick period, so a discrete-event world jumps only over moments in
//    which the robot could not act anyway (a move's phase, a halt's recovery).
//  - The loop checks the world's answers: time() finite and never going
//    back, observe() naming only regions, present containers, "hand" and
//    "none"; otherwise the episode ends with an error naming the method.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "rtamp/util/names_table.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

class Intervenable;
class FrameSource;

// One pick-and-place move as the loop asks for it: pick `thing` (where the
// plan believes it is: `from`) and place it at location `to`.
struct Move {
  std::string action;  // "move(o1, r2)"
  std::string thing, from, to;
};

enum class MoveStatus { Idle, Running, Succeeded, Failed };
const NameTable<MoveStatus>& move_statuses();  // idle running succeeded failed
const char* to_string(MoveStatus s);

// An intervention of a person, as the world applied (or refused) it.
struct WorldEvent {
  double time = 0;
  world::Intervention what;
  bool applied = false;
  std::string detail;  // where it went, or why it was refused
};

class World {
 public:
  virtual ~World() = default;

  // Seconds since the episode began (simulated time, or wall time on a real robot).
  virtual double time() const = 0;
  // Lets `dt` seconds pass (physics steps, discrete events, or waiting).
  virtual void advance(double dt) = 0;
  // When the world will next change on its own (a move's phase ends, a
  // scheduled intervention); infinity if it cannot tell (continuous worlds).
  virtual double next_event_time() const { return std::numeric_limits<double>::infinity(); }

  // Where every present thing is (see the contract above).
  virtual world::Placement observe() = 0;
  // Whether the world's perception has seen a change it does not report in observe()
  // yet, because it is still confirming it (a camera's belief making sure a new thing is
  // one, or that a thing is gone). The loop judges the task on a settled percept, and a
  // percept is not settled while this holds. It must not hold for long (a few seconds).
  virtual bool confirming() const { return false; }

  virtual void start(const Move& m) = 0;
  // Status of the last started move; on Failed `why` (if not null) gets the reason.
  virtual MoveStatus poll(std::string* why) = 0;
  virtual void halt() = 0;
  // The arm is still making itself safe after a halt.
  virtual bool busy() = 0;
  // Where the hand is: the location the last place ended at ("" before the
  // first move: home). The planner's motion costs start from here.
  virtual std::string hand() const = 0;

  // Length of the path the tool has travelled so far (m), if the world measures it.
  virtual double distance_travelled() const { return 0; }
  // Interventions applied or refused since the last call (for logs).
  virtual std::vector<WorldEvent> take_events() { return {}; }
  // The optional capability to take a person's interventions
  // (intervenable.hpp); null if people act on this world on their own.
  virtual Intervenable* intervenable() { return nullptr; }
  // The optional capability to draw the scene (frame.hpp); null: pictures
  // lay things out in the locations the loop perceives.
  virtual FrameSource* frames() { return nullptr; }
};

}  // namespace rtamp::exec
