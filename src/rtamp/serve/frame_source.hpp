// Frames (frame.hpp) of the world a served episode runs in, read between the
// loop's steps on the loop's thread:
//  - SimFrames: the MuJoCo UR5 — the arm's qpos, the tool point, every present
//    body's pose; `at` is each thing's location as the loop last perceived it
//    (perceived() is fed from the loop's observer, so drawing a frame never
//    draws perception noise and the episode stays what it would be unserved);
//  - SymbolicFrames: the symbolic world — no joint angles; the hand point the
//    world interpolates along its moves; things laid out by ThingLayout.
#pragma once

#include <memory>
#include <string>

#include "rtamp/episode/sim_world.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/serve/frame.hpp"
#include "rtamp/serve/thing_layout.hpp"

namespace rtamp::serve {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual Frame frame() = 0;
  // What the loop perceived last (things at "hand" are held).
  virtual void perceived(const world::Placement&) {}
};

class SimFrames final : public FrameSource {
 public:
  explicit SimFrames(const episode::SimWorld& world) : world_(world) {}
  Frame frame() override;
  void perceived(const world::Placement& p) override { seen_ = p; }

 private:
  const episode::SimWorld& world_;
  world::Placement seen_;
};

class SymbolicFrames final : public FrameSource {
 public:
  SymbolicFrames(const exec::SymbolicWorld& world, const world::Scenario& scenario)
      : world_(world), layout_(scenario) {}
  Frame frame() override;

 private:
  const exec::SymbolicWorld& world_;
  ThingLayout layout_;
};

}  // namespace rtamp::serve
