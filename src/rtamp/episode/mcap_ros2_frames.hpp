// The scene of a live episode in its ros2-profile MCAP file (mcap_ros2.hpp): an
// EpisodeObserver that, where the arm starts and after each tick of the loop,
// takes the world's own frame (exec::FrameSource: MuJoCo's poses and joint
// angles, the symbolic world's placement) — or, for a world that cannot draw
// itself, the perceived placement laid out (exec/laid_out_frames.hpp) — and
// gives it to McapRos2::frame (/joint_states, /tf, /markers). Things are labelled
// with the world's true placement where it has one (exec::Intervenable), else
// with what the loop perceived: the file shows what happened, every present
// thing at the world's pose at the loop's rate, the held thing in the gripper,
// not the log's coarser records. Drawing reads the world only (FrameSource's rule).
#pragma once

#include <memory>
#include <string>

#include "rtamp/episode/mcap_ros2.hpp"
#include "rtamp/exec/episode_observer.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/exec/laid_out_frames.hpp"
#include "rtamp/exec/world.hpp"

namespace rtamp::episode {

class McapRos2Frames final : public exec::EpisodeObserver {
 public:
  // All must outlive this. Draws the scene as it is now.
  McapRos2Frames(const world::Scenario& scenario, exec::World& world, McapRos2& mcap)
      : mcap_(mcap) {
    truth_ = world.intervenable();
    source_ = world.frames();
    if (!source_) {
      laid_out_ = std::make_unique<exec::LaidOutFrames>(scenario, world);
      source_ = laid_out_.get();
    }
    draw(world.time());
  }
  void on_perceived(double, const world::Placement& seen, const world::Placement&) override { perceived_ = seen; }
  void on_tick(double t, bt::Status, const std::string&) override { draw(t); }

 private:
  void draw(double t) {
    exec::Frame f = source_->frame(truth_ ? truth_->true_placement() : perceived_);
    f.t = t;
    mcap_.frame(f);
  }

  McapRos2& mcap_;
  exec::FrameSource* source_ = nullptr;
  exec::Intervenable* truth_ = nullptr;
  std::unique_ptr<exec::FrameSource> laid_out_;
  world::Placement perceived_;
};

}  // namespace rtamp::episode
