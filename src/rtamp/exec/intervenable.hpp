// The optional capability of a world that a person can act on: the true
// placement (what is where right now, as a person sees it — not what the
// robot perceives) and applying one intervention. The symbolic world and the
// MuJoCo world have it, a Python world may; a real robot's world need not
// (there, real people act). World::intervenable() returns it, or null.
//
// Contract: apply() carries the intervention out now, whole or not at all,
// never throws for a refusal, and returns the event (applied, or refused
// with the reason in `detail`); the world also reports it from take_events().
// The names it gets have been drawn or checked by the caller
// (world/person.hpp, world/intervention_rules.hpp).
#pragma once

#include "rtamp/exec/world.hpp"

namespace rtamp::exec {

class Intervenable {
 public:
  virtual ~Intervenable() = default;
  // Every present thing where it truly is (a held thing in "hand", a thing
  // outside every location in "none").
  virtual world::Placement true_placement() = 0;
  // Applies `iv` now (its time is ignored; the event carries the world's time).
  virtual WorldEvent apply(const world::Intervention& iv) = 0;
};

}  // namespace rtamp::exec
