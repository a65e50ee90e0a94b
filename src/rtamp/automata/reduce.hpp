// Language-preserving clean-ups of Büchi automata (TGBA or state-based BA),
// used after translation (docs/translation.md, "Reductions").
//
//  - scc_decompose: Tarjan's SCCs (iterative), numbered in reverse topological
//    order (an edge never goes from SCC i to SCC j > i).
//  - remove_useless: drops states unreachable from the initial state or unable
//    to reach an accepting SCC (one whose internal edges carry every set);
//    renumbers states in BFS order from the initial state. An empty language
//    gives a single state without edges.
//  - canonicalize_acceptance: (1) marks are irrelevant on edges between SCCs
//    and on edges of SCCs without an accepting cycle (cleared); (2) saturation:
//    an edge inside an accepting SCC that lies on no cycle avoiding set i gets
//    set i (every closed walk through it visits i anyway) — in particular
//    every edge of a weak accepting SCC carries every set; for a state-based
//    automaton, a state on no cycle of non-accepting states becomes
//    accepting; (3) TGBA only: a set carried by every edge that carries some
//    other set is dropped, and if every cycle is accepting, num_sets becomes
//    0. This makes equivalent states look alike for simulation and gives
//    degeneralisation fewer levels.
//  - merge_parallel_edges: per (source, destination, marks), drops guards
//    implied by another and merges c∧v | c∧!v into c, to a fixpoint; sorts
//    edges for a deterministic layout.
//  - cube_covered: is every letter of g matched by one of the cubes hs.
#pragma once

#include <cstdint>
#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

struct SccInfo {
  std::vector<std::uint32_t> scc_of;  // per state
  std::uint32_t count = 0;
  std::vector<Marks> internal_marks;  // per SCC: union of marks of internal edges
  std::vector<bool> has_cycle;        // per SCC: at least one internal edge
  bool accepting(std::uint32_t scc, Marks all) const {
    return has_cycle[scc] && (internal_marks[scc] & all) == all;
  }
};

SccInfo scc_decompose(const Automaton& a);
void remove_useless(Automaton& a);
void canonicalize_acceptance(Automaton& a, bool saturate = true);
void merge_parallel_edges(Automaton& a);
bool cube_covered(const Cube& g, const std::vector<Cube>& hs);

}  // namespace rtamp::automata
