// The scenario: everything rtamp knows about a workspace before it runs
// (docs/design.md "Files users touch"; paper Section II: regions R, objects O, the
// LTL task φ, and Section V's scripted interventions).
//
// Plain value types, loaded from YAML by scenario_io.hpp and written back by it.
// Geometry is in metres in the world frame (z up, table top at z = 0).
// Invariants (checked by validate()): names are unique across regions,
// containers and objects; sizes are positive; capacities >= 1; every name a
// proposition or intervention uses exists (objects named by `add` interventions
// count from the time they are added).
// validate.hpp lists every check in full; docs/scenario.md documents the YAML.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/util/error.hpp"
#include "rtamp/util/names_table.hpp"
#include "rtamp/util/text_layout.hpp"
#include "rtamp/world/camera.hpp"

namespace rtamp::world {

using Vec3 = std::array<double, 3>;

// A fixed region of the table: an axis-aligned box footprint [center ± size/2] in x, y.
struct Region {
  std::string name;
  Vec3 center{0, 0, 0};
  Vec3 size{0.2, 0.2, 0};  // x, y extents used; z ignored
  int capacity = 8;        // how many movable things fit
  SourceLocation where;    // where it was defined (for messages)
};

// A movable region (a tray): both an object that can be moved and a location
// that holds objects. Moving it carries its contents. Containers do not nest.
struct Container {
  std::string name;
  std::string cls = "tray";
  Vec3 position{0, 0, 0};  // centre of its footprint on the table
  Vec3 size{0.24, 0.16, 0.03};
  int capacity = 4;
  SourceLocation where;
};

// A movable object (a block).
struct Object {
  std::string name;
  std::string cls = "block";
  Vec3 position{0, 0, 0};  // centre of its base on the table (or in a container)
  Vec3 size{0.04, 0.04, 0.04};
  SourceLocation where;
};

// `colours:` — the colour things of a class are drawn in, and, with camera perception,
// recognised by (sim/colour_segmentation.hpp). Classes not listed take a default: the
// colour their name names, else a hue of their own (sim/class_colours.hpp).
struct ClassColour {
  std::string cls;
  Vec3 rgb{0, 0, 0};     // each channel in [0, 1]
  SourceLocation where;  // of the class's key
};

struct Robot {
  std::string model = "ur5";
  Vec3 base{0, 0, 0};
  double yaw = 0;  // rotation about z, radians
};

// Proposition expressions, defined over the world (docs/design.md "Propositions are
// defined over the world"). Grammar (propositions.hpp parses it):
//   expr   := term ('|' term)*          term := factor ('&' factor)*
//   factor := '!' factor | '(' expr ')' | atom
//   atom   := NAME 'in' LOC                  (object or container NAME is in location LOC)
//           | 'all' CLASS 'in' LOC           (every thing of CLASS; true if there is none)
//           | 'any' CLASS 'in' LOC           (at least one thing of CLASS)
//           | 'count' CLASS 'in' LOC CMP INT (CMP one of < <= == != >= >)
//           | 'true' | 'false'
// CLASS is an object or container class ("block", "tray"), or "object" for every
// movable object that is not a container. LOC is a region or container name.
struct PropExpr {
  enum class Kind { True, False, In, All, Any, Count, Not, And, Or };
  enum class Cmp { Lt, Le, Eq, Ne, Ge, Gt };
  Kind kind = Kind::True;
  std::string subject;   // In: object/container name; All/Any/Count: class
  std::string location;  // In/All/Any/Count: region or container name
  Cmp cmp = Cmp::Ge;     // Count
  int count = 0;         // Count
  std::vector<PropExpr> children;  // Not: 1; And/Or: >= 2

  bool operator==(const PropExpr&) const = default;  // structural equality
};

struct Proposition {
  std::string name;  // the atom used in the LTL task, e.g. "all_in_r2"
  std::string text;  // the expression as written, e.g. "all block in r2"
  PropExpr expr;
  SourceLocation where;  // of the text's first byte
  TextLayout layout;     // of a block scalar's text (| or >) in its file; empty otherwise
};

// A change of the world (paper Section III.A: the world changes between
// plans; Section V: a person intervenes). The one vocabulary for every change:
// the planner applies it (plan::Planner::apply; `rtamp plan --change`), a
// world carries it out (the scripted and random interventions of
// exec::SymbolicWorld and sim::Operator), and the reactive loop reports it.
// Its text form, rules and effect on a scenario are in world/change.hpp.
// Not every world can carry out every kind: the planner's symbolic state has
// no held thing (TakeFromGripper is a change of a running robot), and a
// simulated workspace gets no new region (AddRegion is a planning change);
// those refuse it with a message.
struct Change {
  enum class Kind {
    Relocate,         // move `subject` to `location` (a region or container); `position` optional
    Add,              // add object `subject` of class `cls` at `location` (or `position`)
    Remove,           // remove object `subject`
    AddContainer,     // add container `subject` (class `cls`, e.g. tray) at `location` / `position`
    RemoveContainer,  // remove container `subject` (its contents fall to where it stood)
    TakeFromGripper,  // take whatever the gripper holds; put it at `location` if given, else remove it
    AddRegion,        // add region `region` (its name is `subject`)
  };
  Kind kind = Kind::Relocate;
  std::string subject;           // the object, container or region ("" for TakeFromGripper)
  std::string cls;               // Add, AddContainer ("" = block / tray)
  std::string location;          // a region or container name (AddContainer: a region)
  std::optional<Vec3> position;  // an exact spot (worlds that place things; the planner uses `location`)
  int capacity = 4;              // AddContainer
  Region region;                 // AddRegion

  static Change relocate(std::string thing, std::string location);
  static Change add_object(std::string object, std::string cls, std::string location);
  static Change remove_object(std::string object);
  static Change add_container(std::string container, std::string cls, std::string region, int capacity = 4);
  static Change remove_container(std::string container);
  static Change add_region(Region region);
  static Change take_from_gripper(std::string location = {});
  // parse_change(text) (world/change.hpp). Throws rtamp::Error.
  static Change parse(const std::string& text);
  // "move OBJ LOC", "add OBJ CLASS LOC", "remove OBJ", "add-container NAME
  // CLASS REGION [CAPACITY]", "remove-container NAME", "add-region NAME X Y
  // [CAPACITY [SX SY]]" (size SX x SY m, default 0.2 x 0.2; world/change.hpp parses it; TakeFromGripper, which has no
  // text form, prints as "take-from-gripper [LOC]").
  std::string to_string() const;
};

// The kind's name in logs and the Python API: relocate, add, remove,
// add-container, remove-container, take-from-gripper, add-region.
const char* to_string(Change::Kind k);
// The kinds a person's intervention can be (every kind but add-region), by name.
const NameTable<Change::Kind>& intervention_kinds();
// The kinds of an episode's one random change (`--change`; the paper's Table I
// changes, in its order): relocate remove add.
const NameTable<Change::Kind>& random_change_kinds();

// A scripted change of the world at a time (the paper's "human
// intervention"): the scenario's `interventions:`, a world's random ones.
struct Intervention : Change {
  double time = 0;       // seconds of simulated time from the start of the episode
  SourceLocation where;  // where it was defined (for messages)
};

// A new task for a running episode (the paper's "new temporal logic
// specifications"): the scenario's `operator:` entries `{time, action:
// new_task, task, propositions}`, `rtamp run|serve|batch --new-task T@LTL`,
// the page, ReactiveLoop::set_task. The new task replaces the one in force
// from `time` on (docs/exec.md "A new task"); its propositions join the
// scenario's (a name the scenario already defines must keep its expression).
// Checked like the scenario's own task (task/validate.hpp).
struct TaskChange {
  double time = 0;                        // seconds of world time from the start of the episode
  std::string task;                       // LTL over proposition names or quoted expressions
  SourceLocation task_where;              // of the task's first byte (or an option's text)
  TextLayout task_layout;                 // of a block scalar task in its file; empty otherwise
  std::vector<Proposition> propositions;  // new propositions for this task
  std::string by = "script";              // who gave it: script, command line, page, api, ros2, ...
  SourceLocation where;                   // where it was defined (for messages)
};

struct Scenario {
  std::string name;
  std::string description;
  std::vector<Region> regions;
  std::vector<Container> containers;
  std::vector<Object> objects;
  Robot robot;
  std::vector<Proposition> propositions;
  std::string task;  // LTL formula over proposition names, e.g. "F G all_in_r2"
  SourceLocation task_where;  // of the task's first byte
  TextLayout task_layout;     // of a block scalar task (| or >) in its file; empty otherwise
  std::vector<Intervention> interventions;  // sorted by time
  std::vector<TaskChange> task_changes;     // the operator script's new tasks, sorted by time
  std::vector<Camera> cameras;              // as listed (world/camera.hpp: cameras_of() adds defaults)
  std::vector<ClassColour> colours;         // as listed
  std::string source;                       // file it was loaded from ("" if generated)

  const Region* find_region(const std::string& n) const;
  const Container* find_container(const std::string& n) const;
  const Object* find_object(const std::string& n) const;
  const Proposition* find_proposition(const std::string& n) const;
  const ClassColour* find_colour(const std::string& cls) const;
};

}  // namespace rtamp::world
