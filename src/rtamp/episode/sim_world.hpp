// The MuJoCo UR5 as an exec::World (exec/world.hpp): the reactive loop's
// moves run as the sim layer's pick(o) then place(o, l) skills (the paper's
// skill library, Fig. 2), perception maps body poses to regions, and a
// person's interventions are carried out between physics steps (the
// intervention capability, exec/intervenable.hpp: sim::Operator's physics of
// applying one; exec::PersonWorld drives it). Built on sim::Session.
//
// Failure and preemption never leave the arm in a bad spot:
//  - a move that fails while holding its thing first puts it back — at its
//    source, or, if that is gone or full, the location with room and a free
//    spot closest to the source (regions first on ties; a container only for
//    an object), as the symbolic world does — then reports Failed;
//  - a place whose destination vanished (a tray removed mid-carry), or that the
//    rule book of space (world/space_rules.hpp) refuses when the fingers are to open
//    (a person filled the location during the carry: the arm keeps the thing and
//    backs up), fails the same way — as the symbolic world's place does;
//  - a thing taken out of the gripper, or a pick that failed (a missed grasp), ends
//    the move with Failed and the empty gripper backs off;
//  - halt() stops the arm, puts a held thing back the same way, or backs the
//    empty gripper straight up; busy() is true until that is done.
// With camera perception (sim/perception.hpp) the loop's names are the belief's: a move
// picks at the thing's perceived pose (even where no body is left: the fingers then close
// on nothing, and the belief takes that as evidence), and the simulation's body it acts on
// is the one of that class nearest where the thing is believed, whatever its name (a thing
// a person added has a name of the belief's own, and blocks that look alike may swap
// names). An arm left idle for kParkAfter with its gripper empty goes home, out of the
// fixed camera's view, so that what it covered is seen (a person's change under it would
// otherwise wait for the next move there); a move started meanwhile takes over.
// Invariants: at most one move runs; hand() is where the last place ended ("" once parked).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rtamp/exec/frame.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/sim/session.hpp"

namespace rtamp::episode {

class SimWorld final : public exec::World, public exec::Intervenable, public exec::FrameSource {
 public:
  SimWorld(const world::Scenario& scenario, sim::SessionOptions options);

  double time() const override { return session_.sim().time(); }
  void advance(double dt) override;
  world::Placement observe() override;
  bool confirming() const override { return session_.perception().confirming(); }
  void start(const exec::Move& m) override;
  exec::MoveStatus poll(std::string* why) override;
  void halt() override;
  bool busy() override;
  std::string hand() const override { return hand_; }
  double distance_travelled() const override { return travelled_; }
  std::vector<exec::WorldEvent> take_events() override;
  exec::Intervenable* intervenable() override { return this; }
  exec::FrameSource* frames() override { return this; }

  // --- exec::FrameSource: the arm's qpos, the tool point, every present
  // body's pose; each thing's `at` is where the loop perceived it last (so a
  // frame never draws perception noise and the episode stays what it would be
  // undrawn).
  exec::Frame frame(const world::Placement& perceived) override;

  // --- exec::Intervenable
  // Every present thing where it is (noise-free perception).
  world::Placement true_placement() override { return session_.true_placement(); }
  // Applies one intervention now, between physics steps (sim::Operator::apply);
  // take_events() reports it, and a thing taken from the arm ends the running move.
  exec::WorldEvent apply(const world::Intervention& iv) override;

  sim::Session& session() { return session_; }
  const sim::Session& session() const { return session_; }

  // With camera perception: the seconds an idle, empty arm waits before it parks.
  static constexpr double kParkAfter = 0.3;
  // The arm is on its way home (parking).
  bool parking() const { return parking_; }

 private:
  enum class Phase { Idle, Picking, Placing, Recovering, Done };

  bool holds(const std::string& thing) const;
  // The simulation's body a believed thing's name stands for: the nearest of its class to
  // where it is believed (within 10 cm; else the name itself, as with truth perception).
  std::string body_of(const std::string& believed) const;
  void note(const sim::OperatorEvent& e);
  void fail_or_recover(const std::string& why);
  // Starts placing the held thing at `preferred`, else the location with room closest to
  // source_point_; false if none.
  bool place_somewhere(const std::string& preferred);
  void end(exec::MoveStatus s, const std::string& why);
  void park_if_idle();

  sim::Session session_;
  sim::Percept percept_;
  exec::Move move_;   // in the simulation's names
  std::string to_;    // where the loop asked the move to go, in its names
  Phase phase_ = Phase::Idle;
  exec::MoveStatus status_ = exec::MoveStatus::Idle;
  std::string why_, failure_, hand_, placed_at_;
  static constexpr int kMaxPutBacks = 3;  // places tried to put a failed move's thing back
  int put_backs_ = 0;
  Eigen::Vector3d source_point_ = Eigen::Vector3d::Zero();  // the point of the move's source location
  bool returning_ = false;
  bool taken_ = false;  // a person took the carried thing
  std::string back_thing_;
  double travelled_ = 0;
  double idle_since_ = 0;      // world time the last move ended
  bool parking_ = false;
  bool park_refused_ = false;  // since the last move: not tried again
  std::vector<exec::WorldEvent> events_;
};

}  // namespace rtamp::episode
