// ForwardingWorld: an exec::World that passes every call to an inner world —
// the base of worlds that change one aspect of another (a person acting on it,
// PersonWorld; an imperfect perception of it, PerceptionErrorWorld) and
// override only that. The inner world must outlive it.
#pragma once

#include "rtamp/exec/world.hpp"

namespace rtamp::exec {

class ForwardingWorld : public World {
 public:
  explicit ForwardingWorld(World& inner) : inner_(inner) {}

  double time() const override { return inner_.time(); }
  void advance(double dt) override { inner_.advance(dt); }
  double next_event_time() const override { return inner_.next_event_time(); }
  world::Placement observe() override { return inner_.observe(); }
  bool confirming() const override { return inner_.confirming(); }
  void start(const Move& m) override { inner_.start(m); }
  MoveStatus poll(std::string* why) override { return inner_.poll(why); }
  void halt() override { inner_.halt(); }
  bool busy() override { return inner_.busy(); }
  std::string hand() const override { return inner_.hand(); }
  double distance_travelled() const override { return inner_.distance_travelled(); }
  std::vector<WorldEvent> take_events() override { return inner_.take_events(); }
  Intervenable* intervenable() override { return inner_.intervenable(); }
  FrameSource* frames() override { return inner_.frames(); }

  World& inner() { return inner_; }

 protected:
  World& inner_;
};

}  // namespace rtamp::exec
