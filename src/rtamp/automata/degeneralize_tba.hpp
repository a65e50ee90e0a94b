// TGBA -> transition-based Büchi automaton (one acceptance set on edges), the
// form the planner's product accepts on (plan/product_graph.hpp).
//
// A state is (q, l) with a level l in 0..k-1 (k = num_sets, k >= 2). Inside an
// SCC, an edge with marks M leaving (q, l) advances l' from l while set
// order[l'] is in M; reaching k makes the edge accepting and l' = 0. Edges
// between SCCs carry no marks (canonicalize_acceptance) and enter level 0, so
// levels only multiply the strong accepting SCCs (weak accepting SCCs carry
// every set on every internal edge: all their edges accept at level 0). The
// result is the smallest over the rotations of the order of the sets.
// First canonicalize_acceptance (no marks between SCCs); then one set: as it
// is; no set (every cycle accepts): every edge inside an SCC accepting. A state-based input is turned into its transition-based
// form first (an edge accepts when it leaves an accepting state).
// Postcondition: !state_based, num_sets == 1, language unchanged; states
// reachable from the initial one.
#pragma once

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

Automaton degeneralize_tba(const Automaton& a);

// The state-based form of a one-set transition-based automaton: states
// 0..n-1 are a's states, non-accepting, with their ids kept; each state that
// an accepting edge enters gets an accepting copy (ids n, n+1, ...), which
// every accepting edge enters instead. Same language; a state-based input is
// returned as it is.
Automaton state_based_form(const Automaton& a);

}  // namespace rtamp::automata
