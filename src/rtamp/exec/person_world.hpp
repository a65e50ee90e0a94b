// PersonWorld: a world as the loop sees it with a person acting on it — any
// exec::World with the intervention capability (intervenable.hpp), driven by
// a world::Person (world/person.hpp): a script, random interventions, one
// random change, posted ones. It forwards everything to the inner world and,
// while time passes, stops at each moment the person acts and applies what is
// due through the capability. The loop still only observes; the inner world
// reports the events (take_events()).
//
// Timing: an intervention due at t is applied once the inner world's time
// has reached t (a discrete-event world exactly at t, MuJoCo at the physics
// step nearest t). next_event_time() is the inner world's, or the person's
// next moment if that is earlier — except that a world that cannot tell
// (infinity: continuous, or idle) stays so, and the loop ticks it.
// Invariant: every intervention the person makes is applied exactly once.
#pragma once

#include "rtamp/exec/forwarding_world.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/world/person.hpp"

namespace rtamp::exec {

class PersonWorld final : public ForwardingWorld {
 public:
  // Throws rtamp::Error if `inner` cannot take interventions. Both must
  // outlive this. Interventions due at time() (<= 0) are applied now.
  PersonWorld(World& inner, world::Person& person, const std::string& world_name = "this world");

  void advance(double dt) override;
  double next_event_time() const override;
  Intervenable* intervenable() override { return &hands_; }

  world::Person& person() { return person_; }

 private:
  void apply_due();

  Intervenable& hands_;
  world::Person& person_;
};

}  // namespace rtamp::exec
