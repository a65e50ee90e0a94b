// Direct constructions for the most common formula shapes, skipping the
// VWAA/GBA pipeline (docs/translation.md, "Shortcuts"). b is a Boolean
// formula, given as its DNF cubes (at most 64, else no shortcut):
//   b      BA/TGBA: init --b--> s --true--> s; every state accepting (TGBA: 0 sets)
//   G b    1 state, loop b; accepting (TGBA: 0 sets)
//   F b    init (loop true, non-accepting) --b--> s (loop true, accepting)
//   G F b  TGBA: 1 state, loop true, loop b in set 0;
//          BA: 2 states, q0 --true--> q0, q0 --b--> q1 (accepting), q1 same edges as q0
//   F G b  init (loop true) --b--> s (loop b, accepting)
// The results are already minimal; they satisfy the invariants of translate().
#pragma once

#include "rtamp/automata/automaton.hpp"
#include "rtamp/ltl/formula.hpp"

namespace rtamp::automata::detail {

// nnf is in negation normal form. Returns false (and leaves out alone) when no
// shortcut applies.
bool try_shortcut(const ltl::Formula& nnf, bool state_based, Automaton& out);

// DNF cubes of a Boolean NNF formula over `atoms` (sorted); false if more than
// max_cubes would be needed. An empty result means the formula is false.
bool boolean_cubes(const ltl::Formula& f, const std::vector<std::string>& atoms, std::vector<Cube>& cubes,
                   std::size_t max_cubes = 64);

}  // namespace rtamp::automata::detail
