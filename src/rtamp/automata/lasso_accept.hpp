// Does a Büchi automaton accept the ultimately periodic word u·v^ω?
// (Used as the automaton side of the translation's oracle tests, and by the
// planner's plan checks.)
//
// The product of the automaton with the lasso has nodes (q, i), i a position
// of u·v (after the last position of v comes the first of v). The word is
// accepted iff some SCC of the product reachable from (initial, 0) contains
// an edge and the union of its internal edges' marks is every set (for a
// state-based automaton: an accepting state; num_sets == 0: any cycle).
// Letters are over the automaton's atoms (bit i = atoms[i]).
#pragma once

#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

struct LassoWord {
  std::vector<Letter> prefix;  // u
  std::vector<Letter> cycle;   // v, non-empty
};

// Throws rtamp::Error when w.cycle is empty.
bool lasso_accept(const Automaton& a, const LassoWord& w);

}  // namespace rtamp::automata
