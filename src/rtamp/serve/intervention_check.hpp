// The check a page's intervention passes before it reaches the world: the
// rules world/validate.cpp applies to a scenario's scripted operator actions
// (through the same name rules and did-you-mean, world/names.hpp and
// world/suggest.hpp), applied to the world as it is now instead of as the
// script has made it so far. The world then applies the intervention or
// refuses it with its own reason (no room, nothing held), exactly as for a
// scripted one.
//
// Rules: relocate names a present thing and a target; add / add-container a
// new valid name (not a region, present thing, proposition, nor a name that
// was ever a thing of the other kind) and a class that is valid and not the
// class of the other kind; remove a present object; remove-container a present
// container; a class only for add and add-container; a target is a region or
// a present container (a container only into a region) or a position; a
// position given with a region lies inside it.
#pragma once

#include <map>
#include <string>

#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

class InterventionCheck {
 public:
  explicit InterventionCheck(const world::Scenario& scenario);

  // "" if `iv` may be applied to a world whose present things are `now`, else why not
  // ("intervention 'relocate': unknown object or container 'o9' (did you mean 'o1'?)").
  std::string check(const world::Intervention& iv, const world::Placement& now) const;
  // Records the things of `now` (call after each observation: names keep their kind).
  void note(const world::Placement& now);
  // A fresh name for an added thing: "o<N>" (objects) or "t<N>" (containers),
  // the smallest N >= 1 not used by anything ever seen, a region or a proposition.
  std::string fresh_name(bool container) const;

 private:
  bool used(const std::string& name) const;

  world::Scenario scenario_;
  std::map<std::string, bool> ever_;      // every thing name seen -> container?
  std::map<std::string, bool> classes_;   // every class seen -> of containers?
};

const char* kind_name(world::Intervention::Kind k);

}  // namespace rtamp::serve
