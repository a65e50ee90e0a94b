// Direct-simulation reduction of Büchi automata (TGBA or state-based BA), in
// the spirit of Spot's `simulation` (Babiak et al., "Direct simulation
// reduction", and Somenzi & Bloem, CAV'00).
//
// r directly simulates q (q <= r) iff for every edge (q, g, m, q') and every
// letter a in g there is an edge (r, h, n, r') with a in h, m ⊆ n and q' <= r'.
// The relation is the greatest fixpoint, computed by iterated refinement of
// all pairs (guards compared symbolically with cube_covered, so any number of
// atoms works). Then:
//  - quotient: states that simulate each other are merged (language kept,
//    since mutually similar states have the same language);
//  - little-brother pruning: an edge (q, g, m, d) is dropped when g is covered
//    by edges (q, h, n, d') with m ⊆ n, d <= d' and (n, d') != (m, d): the
//    relation stays a simulation of the pruned automaton, so no run is lost.
// For a state-based automaton the marks of an edge are its source's
// acceptance, so the same definition is the classic one (acc(q) => acc(r)).
// Precondition: no useless states (every state has an outgoing edge) — call
// remove_useless first. Automata above kMaxSimulationStates states, or whose
// states × edges exceed kMaxSimulationWork, are left alone (the relation
// computation is quadratic in states; this keeps huge automata translatable).
#pragma once

#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

constexpr std::uint32_t kMaxSimulationStates = 2048;
constexpr std::uint64_t kMaxSimulationWork = 4'000'000;

// The relation itself: out[q][r] iff r directly simulates q (q <= r).
std::vector<std::vector<bool>> direct_simulation(const Automaton& a);

// One round of quotient + pruning; returns true when the automaton changed.
bool reduce_direct_simulation(Automaton& a);

// Cosimulation (backward direct simulation): r co-simulates q iff q is not the
// initial state or r is, for a state-based automaton acc(q) => acc(r), and for
// every edge (p, g, m, q) and letter a in g there is an edge (p', h, n, r)
// with a in h, m ⊆ n and p' co-simulating p.
// States that co-simulate each other are merged (every finite run reaching
// one can be matched by a run reaching the other with at least its marks, so
// merging adds no accepted word). Returns true when states were merged.
bool reduce_cosimulation(Automaton& a);

}  // namespace rtamp::automata
