// The rules one operator intervention (paper Section III: the person changes
// the world while the robot works) must satisfy against the world at the
// moment it happens — the one implementation behind a scenario's scripted
// operator actions (validate.cpp walks its script through it) and a page's
// interventions in `rtamp serve` (serve/intervention_check.hpp, against the
// world as it is now), so that both refuse the same mistakes with the same
// words.
//
// Rules: relocate names a present thing and a target; add / add_container a
// new valid name (world/names.hpp: not reserved, not a region, not a present
// thing, not a proposition, not a name that is or was a thing of the other
// kind) and a valid class that is not the class of the other kind; remove a
// present object; remove_container a present container; a class only for add
// and add_container; take_from_gripper names no subject; add_region is
// refused (a change for the planner, not a person's); a target is a region
// or a present container (a container only into a region, nothing into
// itself) or a position; a position lies on the table top (table.hpp) and,
// given with a region, inside it.
//
// Errors are rtamp::Error, located by `locate(field)` (fields as the scenario
// file spells them: "object", "container", "to", "position", "class"), with a
// did-you-mean (suggest.hpp) where one fits. The syntax decides only the
// words that name the input's fields and kinds ("to: LOCATION" or
// "'location'", add_container or add-container).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

// The world an intervention is checked against.
struct InterventionWorld {
  std::map<std::string, std::string> objects, containers;  // present now: name -> class
  std::map<std::string, bool> ever;                         // every thing name, ever -> a container?
  std::map<std::string, bool> classes;                      // every class -> of containers?
};

enum class InterventionSyntax { Scenario, Request };  // a scenario's `operator:` list, a page's request

// "relocate", "add_container" (Scenario) / "add-container" (Request), ...
const char* intervention_kind_name(Intervention::Kind k, InterventionSyntax syntax);

// Throws unless `iv` may happen in `w` of scenario `s` (its regions and
// propositions). `owner` starts every message (e.g. "operator action 'add' at
// t=2: "). `locate` may be empty (then errors carry no location).
void check_intervention(const Intervention& iv, const Scenario& s, const InterventionWorld& w,
                        InterventionSyntax syntax, const std::string& owner,
                        const std::function<SourceLocation(std::string_view field)>& locate = {});

// Applies a checked intervention's names to `w` (what it adds or removes).
void note_intervention(const Intervention& iv, InterventionWorld& w);

}  // namespace rtamp::world
