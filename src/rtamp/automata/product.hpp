// Synchronous products and the complement of a deterministic Büchi automaton,
// for language checks (translate.cpp keeps a minimal WDBA only when both
// inclusions hold; docs/translation.md, "WDBA").
//
//  - product(a, b): runs of a and b on the same word; reachable part only.
//    Transition-based generalized: the marks of a's edge in sets
//    0..na-1 and b's in sets na..na+nb-1 (n = 1 for a state-based automaton,
//    num_sets otherwise), so L(product) = L(a) ∩ L(b). Both must have the
//    same atoms.
//  - complement_dba(w): w deterministic, complete and state-based; the result
//    accepts exactly the words whose run of w meets accepting states finitely
//    often (a first copy of w guesses when the run has left them for good and
//    moves to a second copy without accepting states, whose edges are marked).
#pragma once

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

Automaton product(const Automaton& a, const Automaton& b);
Automaton complement_dba(const Automaton& w);

}  // namespace rtamp::automata
