// VWAA -> transition-based generalized Büchi automaton (Gastin & Oddoux,
// CAV'01, Section 4), built on the fly from the initial conjunctions.
//
// A TGBA state is a conjunction (set) of VWAA states; its edges are the
// product of the members' δ, with contradictory guards dropped and
// transitions subsumed by another (weaker-or-equal guard, fewer targets, more
// acceptance marks) removed (the paper's simplification). The edge carries
// acceptance set k unless one of the chosen VWAA transitions postponed
// eventuality key k. When φ is a disjunction at the top, a fresh initial state
// with δ(φ) is used so that there is exactly one initial state.
// Invariants: atoms = vwaa.atoms; num_sets = vwaa.num_keys (<= 32, else
// rtamp::Error); no edge with a contradictory guard; all states reachable.
#pragma once

#include <cstdint>
#include <optional>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/automata/vwaa.hpp"

namespace rtamp::automata::detail {

// Resource bound: beyond this many edges build_tgba throws rtamp::Error
// ("formula too large to translate") instead of running out of time/memory.
constexpr std::size_t kMaxTgbaEdges = 1'000'000;

Automaton build_tgba(Vwaa& vwaa);

// Variant with merged destinations (as Couvreur's / Spot's ltl2tgba_fm does
// with its promise variables): a state is a disjunction (antichain) of GO
// conjunctions; for each letter σ and promise assignment π, the edge goes to
// the disjunction of the targets of every term that reads σ and postpones
// only keys in π, with marks = all sets not in π. Sound by König's lemma
// (every conjunction of the destination has a predecessor in the source, so
// an accepting run of disjunctions contains an accepting GO run) and complete
// (a GO run with terms t_i is followed by choosing π_i = postponed(t_i)).
// Letters are enumerated, so this is used up to kMaxMergedAtoms atoms;
// beyond, it falls back to build_tgba. Being a partial subset construction it
// can blow up where build_tgba does not: past max_states states it gives up
// and returns nothing.
constexpr std::size_t kMaxMergedAtoms = 8;
std::optional<Automaton> build_tgba_merged(Vwaa& vwaa, std::size_t max_states = SIZE_MAX);

}  // namespace rtamp::automata::detail
