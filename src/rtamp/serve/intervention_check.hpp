// The check a page's intervention passes before it reaches the world: the
// one rule set of scripted operator actions (world/intervention_rules.hpp,
// which world/validate.cpp applies to a scenario's script) applied to the
// world as it is now, so that a page and a scenario file refuse the same
// mistake with the same words. The world then applies the
// intervention or refuses it with its own reason (no room, nothing held),
// exactly as for a scripted one. Unlike a scenario's script, a page cannot
// bring a new class: an add names one of the classes the page offers (the
// scenario's, its script's, block and tray, and any seen since) or none.
//
// State kept here: every thing name and class ever seen, with its kind (names
// keep their kind for the whole episode), and the fresh names for adds that
// name no subject.
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
