// The person who intervenes (paper Section III: someone moves, adds or
// removes things while the robot works; Section V's operator) — one for every
// world: a script of interventions at given times, random interventions (a
// Poisson process of `rate` per second of world time in [start, end), each of
// a kind drawn from `kinds`), one random change of a given kind at a random
// time in a window, and an inbox that other threads post to. The person only
// decides what to do and when; a world that can take interventions applies
// them (exec/person_world.hpp drives any such world; the worlds keep only the
// physics or rules of applying one).
//
// Random draws use one portable generator (util/splitmix.hpp), so a seed means
// the same interventions on every world, platform and standard library, and
// targets are drawn when an intervention is due, against the world's true
// placement then, by one rule: the subject uniformly among the present things
// of the kind; the target uniformly among the locations other than the
// subject's own — regions in declaration order, then (for an object) present
// containers that are not held, by name — that the rule book of space
// (space_rules.hpp) lets take it, else among all of them; new things get fresh names
// x1, x2, ... and a class of the scenario's (the first container class for
// containers); take-from-gripper puts the thing down or removes it, a coin toss.
//
// Invariants: due() returns interventions in time order (script entries in
// the order given for equal times; a posted one is due at once), each once.
#pragma once

#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "rtamp/util/splitmix.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::world {

// One random change (`rtamp run|batch --change KIND`, the paper's Table I): a
// kind, at a time uniform in [begin, end); a relocated subject is an object
// (the paper moves blocks), otherwise the rule above.
struct RandomChange {
  Intervention::Kind kind = Intervention::Kind::Relocate;
  double begin = 2, end = 20;
};

struct PersonOptions {
  std::vector<Intervention> script;  // applied at each entry's time
  double rate = 0;                   // random interventions per second of world time
  double start = 0;                  // no random intervention before this time
  double end = std::numeric_limits<double>::infinity();  // nor from this time on
  std::vector<Intervention::Kind> kinds{Intervention::Kind::Relocate,        Intervention::Kind::Add,
                                        Intervention::Kind::Remove,          Intervention::Kind::AddContainer,
                                        Intervention::Kind::RemoveContainer, Intervention::Kind::TakeFromGripper};
  std::optional<RandomChange> change;
  std::uint64_t seed = 1;
};

// The kinds a random person draws from by default (every kind a world carries out).
const std::vector<Intervention::Kind>& random_intervention_kinds();

class Person {
 public:
  // Throws rtamp::Error if an option is out of range (rate not finite or < 0,
  // a window with end < start, a script time or change window not finite or < 0,
  // add-region among the kinds).
  Person(const Scenario& scenario, PersonOptions options = {});

  // When the next intervention is due (infinity if none; a posted one: -infinity).
  double next_time() const;
  // The next intervention due at `now` (its time <= now), with `time` set and
  // its random parts drawn against `truth` (what is where now: a held thing in
  // "hand"); nullopt when none is due.
  std::optional<Intervention> due(double now, const Placement& truth);
  // Posts an intervention to be applied at once (thread-safe).
  void post(Intervention iv);

  const PersonOptions& options() const { return options_; }

 private:
  Intervention draw(Intervention::Kind kind, double now, const Placement& truth, bool objects_only = false);
  std::string target(const std::string& thing, const Body& body, const Placement& truth);
  std::string fresh_name(const Placement& truth);
  void schedule_random(double from);

  PersonOptions options_;
  Scenario scenario_;  // regions, sizes and capacities for the rule book
  std::vector<std::string> object_classes_;
  std::set<std::string> names_ever_;
  std::size_t next_script_ = 0;
  double next_random_ = std::numeric_limits<double>::infinity();
  double change_at_ = std::numeric_limits<double>::infinity();
  int added_ = 0;
  SplitMix64 rng_;
  mutable std::mutex inbox_mutex_;
  std::vector<Intervention> inbox_;
};

}  // namespace rtamp::world
