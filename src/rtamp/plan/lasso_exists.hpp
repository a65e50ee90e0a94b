// Whether the product TS x BA has an accepting lasso at all, costs aside: the
// capacity diagnosis (Planner: "no plan within the capacities, but one if
// they are ignored") asks it of the capacity-free TS.
//
// It explores the product reachable from (initial state, q) for the given
// automaton states q (edges as in ProductGraph: stay and every enabled move,
// to every BA successor whose guard holds in the source's label) and finds
// its strongly connected components (Tarjan, iterative); a lasso exists iff a
// reachable SCC has an edge (size > 1, or a self loop) and holds an accepting
// node (state-based) or, transition-based, edges inside it that carry every
// acceptance set between them (found by going over its members' edges again
// when it closes). It stops at the first such SCC. No costs are asked of any model, and
// the hand is dropped from the state: labels and enabled moves never read it
// (it only prices moves), so the abstraction has a lasso iff the TS does (a
// cycle of placements, taken twice, returns the hand to where it was).
// States are canonical when the System has symmetry groups (the quotient has
// the same lassos). Linear in the explored product; a node limit or deadline
// stops it with `stopped` (the answer is then unknown).
#pragma once

#include <cstdint>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/task/labeling.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::plan {

struct LassoExistence {
  bool exists = false;
  bool stopped = false;          // a limit ended the exploration: `exists` is unknown (false)
  std::uint64_t nodes = 0;       // product nodes (placement, automaton state) reached
  std::uint64_t expansions = 0;  // nodes whose successors were generated
};

// From (ts.initial(), q) for each q in `starts`. `max_nodes` 0: no limit;
// `deadline_ns` 0: none (plan/termination.hpp's steady_now_ns()).
LassoExistence find_accepting_lasso(const task::System& ts, const task::Labeling& lab, const automata::Automaton& ba,
                                    const std::vector<std::uint32_t>& starts, std::size_t max_nodes,
                                    std::int64_t deadline_ns);

}  // namespace rtamp::plan
