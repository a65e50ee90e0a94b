// The labeling function L : S -> 2^Π of the paper's Definition 1, compiled
// from the scenario's proposition expressions (world::PropExpr) into a fast
// evaluator over packed states (docs/design.md "Propositions are defined over the
// world").
//
// Each automaton atom is resolved to a proposition of the scenario by name
// (or, if a parser is given, by parsing the atom itself, e.g. "o1 in r2").
// Class quantifiers ("all block in r2", "any", "count") are evaluated over the
// things of the System it is compiled for, so rebuilding the Labeling after
// objects are added or removed re-evaluates "all" over the current set.
// Counting is SWAR: one xor, add and popcount per state word and class.
// Semantics: `X in L` is true iff X's own location is L (a block in a tray
// that stands in r2 is in the tray, not in r2). A name the System does not
// know (a removed object, an unknown location) makes `X in L` false and
// counts nothing. Atoms that resolve to nothing are listed in
// unknown_atoms() and are false.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::task {

class Labeling {
 public:
  using AtomParser = std::function<std::optional<world::PropExpr>(const std::string& atom)>;

  struct Node {
    world::PropExpr::Kind kind = world::PropExpr::Kind::True;
    world::PropExpr::Cmp cmp = world::PropExpr::Cmp::Ge;
    int count = 0;
    int thing = -1;  // In: thing index, -1 unknown
    int loc = -1;    // In/All/Any/Count: location index, -1 unknown
    int cls = -1;    // All/Any/Count: class index, -1: a class with no things
    std::vector<std::uint32_t> children;
  };

  Labeling(const System& ts, const std::vector<std::string>& atoms, AtomParser parser = {});

  automata::Letter label(const State& s) const;
  bool holds(unsigned atom, const State& s) const { return eval(roots_[atom], s); }
  bool eval(std::uint32_t node, const State& s) const;

  // Number of things of class `cls` whose location is `loc`.
  int count(const State& s, int cls, int loc) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  std::uint32_t root(unsigned atom) const { return roots_[atom]; }
  std::size_t num_atoms() const { return roots_.size(); }
  const std::vector<std::string>& unknown_atoms() const { return unknown_; }
  const std::vector<unsigned>& class_things(int cls) const { return class_things_[static_cast<unsigned>(cls)]; }
  const System& system() const { return *ts_; }
  // Things named individually by some atom (`x in L`): they are never interchangeable.
  std::vector<bool> named_things() const;
  // The symmetry groups the labeling allows: objects of one class that no atom
  // names and that have the same moves in the System (System::same_moves():
  // the same footprint rules and forbidden moves), so labels and enabled moves
  // are invariant under permuting a group.
  std::vector<std::vector<unsigned>> symmetry_groups() const;
  // The container groups it allows (System::set_container_symmetry):
  // containers of one class that no atom names, as a thing or as a location,
  // and that System::same_containers() says are alike.
  std::vector<std::vector<unsigned>> container_groups() const;

 private:
  std::uint32_t compile(const world::PropExpr& e);
  int class_index(const std::string& name);

  const System* ts_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> roots_;
  std::vector<std::string> unknown_;
  std::vector<std::string> class_names_;
  std::vector<std::vector<unsigned>> class_things_;
  std::vector<std::array<std::uint64_t, kStateWords>> class_masks_;  // top bit of each member field
  std::uint64_t rep_ = 0, high_ = 0, low_ = 0;                      // SWAR constants
};

}  // namespace rtamp::task
