// Plans and planning results: value types that cross into the bt / exec
// layers (docs/design.md "Types that cross layers").
//
// A Plan is a lasso over the product automaton (docs/design.md "Plans are
// lassos"): `prefix` leads from a start product node (the current state and
// one of the planner's automaton states) to a node J, `cycle` (non-empty)
// leads from J back to J and passes an accepting node (J itself need not be
// accepting: the prefix may join the cycle anywhere). cost() = prefix_cost +
// cycle_cost, the quantity the searches minimise. Each step records the TS
// state before and after, the BA states, the action, its motion cost and the
// label L(from) that the BA read on that step.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/task/state.hpp"

namespace rtamp::plan {

struct Step {
  task::Action action;
  task::State from, to;
  std::uint32_t ba_from = 0, ba_to = 0;
  double cost = 0;
  automata::Letter label = 0;  // L(from), over the automaton's atoms
};

struct Plan {
  std::vector<Step> prefix;
  std::vector<Step> cycle;
  double prefix_cost = 0;
  double cycle_cost = 0;
  double cost() const { return prefix_cost + cycle_cost; }
};

enum class NoPlanReason {
  None,              // a plan was found
  Unsatisfiable,     // the formula has no model at all (its automaton accepts nothing)
  NoAcceptingCycle,  // no lasso of the product is accepting from this state
  Capacity,          // there would be one if locations had no capacity limits
  UnknownName,       // the task uses an atom that is no proposition of the scenario
  NodeLimit,         // the search hit its node limit first
  TimeLimit,         // the search hit its time limit first
  MemoryLimit,       // the search hit its memory limit first
};
const char* to_string(NoPlanReason r);

struct SearchStats {
  std::uint64_t generated = 0;        // product nodes created during this query
  std::uint64_t expanded = 0;         // node expansions by the prefix and cycle searches
  std::uint64_t successor_generations = 0;  // expansions that had to compute successors
  std::uint64_t cycle_searches = 0;   // cycle searches run (cache misses of the cycle table)
  std::uint64_t graph_nodes = 0;      // nodes in the product graph after the query
  std::uint64_t graph_edges = 0;
  std::uint64_t impossible_moves = 0;  // moves the cost model priced +inf (dropped), over the graph's life
  bool cache_used = false;            // the motion-cost cache was consulted (astar-exp, expensive models)
  std::uint64_t cache_hits = 0;       // motion-cost cache
  std::uint64_t cache_misses = 0;
  std::uint64_t reused_nodes = 0;     // nodes already in the graph when the query started
  std::uint64_t reused_path_edges = 0;  // plan edges taken from an earlier optimal plan (astar-exp)
  std::size_t memory_bytes = 0;       // product graph + search arrays + cache, after the query
  double construction_seconds = 0;    // full construction before the search (graph "full")
  double seconds = 0;                 // wall time of the whole query (the capacity diagnosis included)
  std::uint64_t diagnosis_nodes = 0;  // capacity diagnosis: capacity-free product nodes explored
  double diagnosis_seconds = 0;       // capacity diagnosis: its wall time (0 if it did not run)
  bool hit_node_limit = false;
  bool hit_time_limit = false;
  bool hit_memory_limit = false;
  double bytes_per_node() const { return graph_nodes ? double(memory_bytes) / double(graph_nodes) : 0; }
};

struct PlanResult {
  bool found = false;
  Plan plan;
  NoPlanReason reason = NoPlanReason::None;
  std::string message;  // human-readable reason when !found
  SearchStats stats;
};

}  // namespace rtamp::plan
