// The arm of a MuJoCo episode in its MCAP file: an EpisodeObserver that, after
// each tick of the loop, gives the simulated UR5's joint angles to the
// episode's EpisodeMcap (its /joint_states and /tf channels). The log has no
// `frame` records in `rtamp run` and `rtamp batch`, so this is where those
// files get the arm; the MCAP file then has more than the log's conversion.
#pragma once

#include <string>

#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/exec/episode_observer.hpp"
#include "rtamp/sim/simulation.hpp"

namespace rtamp::episode {

class McapArm final : public exec::EpisodeObserver {
 public:
  // Both must outlive this. Draws the arm where it starts.
  McapArm(const sim::Simulation& sim, EpisodeMcap& mcap) : sim_(sim), mcap_(mcap) { draw(sim_.time()); }
  void on_tick(double t, bt::Status, const std::string&) override { draw(t); }

 private:
  void draw(double t) {
    const robot::Joints q = sim_.arm_q();
    mcap_.arm(t, {q[0], q[1], q[2], q[3], q[4], q[5]});
  }

  const sim::Simulation& sim_;
  EpisodeMcap& mcap_;
};

}  // namespace rtamp::episode
