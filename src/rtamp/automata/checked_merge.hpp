// Merging a state into a state that directly simulates it, kept only when
// checked against the automaton of the negated formula (docs/translation.md,
// "Checked merges").
//
// If r directly simulates q (simulation_reduction.hpp), redirecting every edge
// into q (and the start, if q is initial) to r only adds words: every run of
// the old automaton is matched step by step by a run of the new one from a
// state simulating it, with at least its marks. So L(a) ⊆ L(merged) always,
// and merged accepts exactly L(a) = L(f) iff merged × A_!f is empty, which is
// checked. This catches states equal in language but not in simulation
// (G F a & G F !a: an initial state whose one edge carries no mark).
// Invariant: the language of `a` is unchanged; the automaton only shrinks.
#pragma once

#include <functional>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

// `negation()` gives an automaton of the complement of L(a) over the same
// atoms (or nullptr: nothing is merged); it is called only when a candidate
// pair exists. Tries the pairs (q, r) with r simulating q but not the
// converse, at most `attempts` failed checks (each is a product and an
// emptiness check: the translator allows one); returns true when states were
// merged.
bool merge_checked(Automaton& a, const std::function<const Automaton*()>& negation, int attempts = 1);

}  // namespace rtamp::automata
