// A change of the world (world::Change, scenario.hpp) as text and as a
// checked value (paper Section III.A: the world changes between plans): the
// parser behind `rtamp plan --change` and rtamp.Change.parse, the rules a
// change must satisfy against the world it is applied to, and its effect on a
// scenario, its placement and the hand (what plan::Planner::apply does; an added
// thing takes the size of the first thing of its class, as in the symbolic world).
//
// The rules are the scenario file's (world/names.hpp, world/validate.hpp): a
// new name is a valid identifier, not reserved and not used by a region,
// container, object or proposition; a class is valid, not "object", and names
// either objects or containers, never both; a new region lies within ±1000 m,
// has a positive size and overlaps no region; capacities are integers >= 1;
// numbers are finite; the things and locations a change names exist at that
// point (earlier changes count), a container goes only into a region and
// nothing into itself.
//
// Errors are rtamp::Error. With a location (`where`: where the change's text
// starts, e.g. {"--change #2", 1, 1}) they point at the offending word and
// carry the text with a caret; without one they start "bad change 'TEXT': ".
// TakeFromGripper (a change of a running robot: the symbolic state has no held
// thing) has no text form and is refused by check_change.
// parse_changes() also checks the rules of space (check_change_room): a change
// that would put a thing where the rule book (world/space_rules.hpp: fit,
// capacity, room) refuses it is an error naming the thing and the location.
// plan::Planner::apply does not (the loop applies what it observed, a fact).
// Invariant: parse_changes() accepts a list exactly when applying the changes
// one by one to a plan::Planner for `scenario` throws nothing and every state
// they make keeps the rule book where they put things.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rtamp/util/error.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

// The syntax of one change (the grammar in Change::to_string); numbers must be finite,
// coordinates within ±1000 m, capacities integers from 1 to 2^31 - 1.
Change parse_change(std::string_view text, const SourceLocation& where = {});

// Throws unless `c` may be applied to the world of scenario `s` (its current
// regions, containers, objects and classes). `text` (the change as written,
// optional) lets errors point at the offending word.
void check_change(const Change& c, const Scenario& s, const SourceLocation& where = {},
                  std::string_view text = {});

// Throws unless `c`, checked, keeps the rule book (world/space_rules.hpp) where it
// puts things in the world of `s` with placement `p` (before the change): a moved or
// added thing fits its location and the location has room (capacity and area); a
// removed container's contents, falling into its region, all have room there.
void check_change_room(const Change& c, const Scenario& s, const Placement& p, const SourceLocation& where = {},
                       std::string_view text = {});

// Applies a checked change to a scenario, its placement and the hand's
// location (what Planner::apply does to its world).
void apply_change(const Change& c, Scenario& s, Placement& p, std::string& hand);

// Parses and checks `texts` in order, each against the world the earlier ones
// made, starting from `scenario`'s initial state. Errors are located at
// "OPTION #K" (K counts from 1), line 1, the column of the offending word.
std::vector<Change> parse_changes(const Scenario& scenario, const std::vector<std::string>& texts,
                                  const std::string& option = "--change");

}  // namespace rtamp::world
