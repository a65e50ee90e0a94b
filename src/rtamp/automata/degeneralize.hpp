// TGBA -> state-based Büchi automaton (degeneralisation by a level counter,
// Gastin & Oddoux Section 5 / Babiak et al. 2013 "level tricks").
//
// A BA state is (q, l) with level l in 0..k (k = number of sets); level k is
// the accepting level. Leaving (q, l) by an edge with marks M: start from
// l' = (l == k ? 0 : l) and advance l' while set order[l'] is in M ("skip
// levels"); reaching k gives the accepting copy. Tricks used:
//  - SCC-aware: levels are only kept inside SCCs that need them. States in
//    SCCs without an accepting cycle, in trivial SCCs, or in SCCs where every
//    cycle is accepting (weak) get a single copy (accepting iff weak).
//  - level cache: entering a strong SCC from outside reuses the first level
//    already created for the destination (fewer copies).
//  - sets implied by another inside an SCC get no level;
//  - entry level: entering a strong SCC at the accepting level (same
//    successors as level 0, and it simulates level 0) or at level 0;
//  - the order of the sets and the entry level are chosen among several
//    candidates (all orders for k <= 4, rotations otherwise).
// Precondition: canonicalize_acceptance(a) was applied (a is a TGBA).
// Postcondition: state_based, num_sets == 1, language unchanged.
#pragma once

#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

// The smallest of the candidates below.
Automaton degeneralize(const Automaton& tgba);
// One result per candidate (order of the sets x entry level); callers that
// reduce afterwards can pick the smallest reduced one.
std::vector<Automaton> degeneralize_candidates(const Automaton& tgba);

}  // namespace rtamp::automata
