// PerceptionErrorWorld: any exec::World seen through an imperfect perception —
// the errors a camera and its belief make (sim/camera_perception, world/belief),
// as a model a world without a camera (the symbolic one) can be run with, so
// that property tests cover them. Three errors:
//  - delay: a change the robot did not make itself (a person's) shows in
//    observe() `delay` seconds late, or `late_delay` late with probability
//    `late_probability` (the arm covered the spot);
//  - false removals: a thing that is there vanishes from observe() for
//    `false_removal_duration` seconds, at `false_removal_rate` per thing-second;
//  - a move of a thing, or to a container, whose change is not shown yet
//    reveals it (the arm goes there and the camera sees): it shows at once.
// A change due to show within `delay` is being confirmed (confirming()): the
// camera sees it and its belief is making sure; a late one is hidden till then.
// What the robot's gripper does shows at once (the belief follows the
// gripper): its move's thing going into the hand and out of it, wherever to.
// Invariants: observe() is always a consistent placement (a thing is in a
// region, a shown container, "hand" or "none"); every difference from the
// truth ends within max(delay, late_delay) of its cause, or with the false
// removal's duration; for a seed and a sequence of calls everything is
// reproducible. Forwards moves, interventions and frames to the inner world.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "rtamp/exec/forwarding_world.hpp"
#include "rtamp/util/splitmix.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

struct PerceptionErrors {
  double delay = 0;                   // s a person's change takes to show
  double late_probability = 0;        // chance it takes late_delay instead
  double late_delay = 0;              // s
  double false_removal_rate = 0;      // per thing and second
  double false_removal_duration = 0;  // s a falsely removed thing stays unseen
  std::uint64_t seed = 0;

  // The longest a difference between observe() and the truth lasts.
  double longest() const;
};

// The errors the MuJoCo camera pipeline (overhead camera, world::Belief) was
// measured to make in the Table I batch (docs/benchmarks.md "Camera perception
// in the Table I batch"): a person's change seen 0.36 s late (the median), 21 %
// of them about 2 s late (the arm over the spot); no false removal in 21,800
// thing-seconds.
PerceptionErrors camera_perception_errors(std::uint64_t seed);
// How long the loop lets a camera percept settle before it judges the task
// (LoopOptions::settle): the late changes' median, about the 90th percentile of
// all the latencies measured (2.08 s).
inline constexpr double kCameraSettle = 2.0;

// Throws rtamp::Error "perception errors: NAME ..." unless every time is finite
// and >= 0 and late_probability is in [0, 1].
void check(const PerceptionErrors& e);

class PerceptionErrorWorld final : public ForwardingWorld {
 public:
  // `inner` must outlive this (the second form owns it). Throws rtamp::Error on bad errors.
  PerceptionErrorWorld(World& inner, const world::Scenario& s, PerceptionErrors errors);
  PerceptionErrorWorld(std::unique_ptr<World> inner, const world::Scenario& s, PerceptionErrors errors);

  double next_event_time() const override;
  world::Placement observe() override;
  bool confirming() const override;
  void start(const Move& m) override;

  const PerceptionErrors& errors() const { return errors_; }
  // Whether what observe() last returned differs from the truth it was made from.
  bool differs() const { return differs_; }

 private:
  void update(const world::Placement& truth);
  void show(const std::string& name, const world::Placement& truth);
  void make_consistent(const world::Placement& truth);
  bool robots_own(const std::string& name, const world::Placement& truth) const;
  void schedule_false_removal(double now);

  std::unique_ptr<World> owned_;
  std::set<std::string> regions_;
  PerceptionErrors errors_;
  SplitMix64 rng_;
  world::Placement shown_;                // what is perceived (before false removals)
  std::map<std::string, double> due_;     // a change not shown yet: when it will be
  std::map<std::string, double> hidden_;  // falsely removed: until when
  std::vector<std::string> gone_;         // update()'s scratch: shown things the truth lacks
  double next_false_removal_;
  Move move_;           // the robot's last move
  bool started_ = false;
  bool differs_ = false;
};

}  // namespace rtamp::exec
