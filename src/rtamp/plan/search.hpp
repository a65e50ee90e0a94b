// Search strategies over the product graph and the lasso search (paper
// Section III.B: graph search with motion costs; docs/design.md "Plans are lassos").
//
// A lasso plan is a path (the prefix) from one of the start nodes to a node
// J plus a cycle (>= 1 edge) from J back to J that passes an accepting node:
// the prefix may join the cycle anywhere, so the lasso is optimal for the
// task's run and not for where one automaton happens to put its accepting
// state (`G F a & G F b` and `G F b & G F a` cost the same). Its cost is
// prefix + cycle; LassoSearch minimises it exactly over all start nodes:
//   1. Best-first search from the start nodes (multi-source: all at g = 0; the
//      planner passes (s, q) for every tracked automaton state q) in order of
//      f = g + h (h = 0: Dijkstra; h admissible: A*). g(m) is then the distance
//      from the nearest start. Nodes are re-opened when a cheaper path is
//      found, so admissibility suffices for exact g at the end.
//   2. U(J) = the cheapest cycle through J that contains an accepting node
//      (`cycle`: a best-first search over (node, seen an accepting node yet)
//      from J's successors back to (J, yes); for an accepting J simply its
//      cheapest cycle), pruned at best - g(J). Its heuristic is the max of
//      state_distance_bound to J's state, Heuristic::walk_bound to J's
//      automaton state and Heuristic::return_bound to J (through an
//      accepting node while none was passed): all bound every way back to
//      J. The cycle found is kept with its cost (the lasso is rebuilt from
//      it, never searched again). U does not depend
//      on the start, so it is kept in the cycle table of the graph's
//      experience (exact, or "none below b"; plan/experience.hpp) and reused
//      by later queries. When such a search is unbounded (no
//      incumbent yet) and finds nothing, the SCCs reachable from J are
//      classified at once (on_accepting_cycle): nodes whose SCC has no
//      accepting cycle get "none" in the table and no search of their own.
//      An accepting node gets its search when it
//      is popped. A non-accepting node whose automaton state lies on an
//      automaton cycle through an accepting state is a join candidate: it
//      waits in a second heap under the key g + a lower bound on U (the
//      table's, h, and Heuristic::cycle_bound) and is searched only once an
//      incumbent exists and its key is the least open one (the first lasso
//      comes, as before, from an accepting node: any lasso's accepting node
//      has a cycle through itself). Other nodes cannot be on a lasso's cycle.
//   3. Stop when the least key of both heaps is >= best.
// Ties: paths, cycles and lassos are compared as (cost, number of moves)
// lexicographically (costs equal within 1e-9), so among the cheapest lassos
// the one with the fewest moves is returned. h stays a cost bound (its moves
// part is 0, admissible in that order); labels are re-opened when (g, moves)
// improves; an open entry is skipped when (f, moves) is not below the
// incumbent and the search stops when f exceeds the incumbent's cost; the
// arguments below hold in that order.
// Optimality: let L* = P + C be an optimal lasso (over all starts) joining
// its cycle at J*, its prefix P from start node s*. Every node m on P (J*
// included) has f(m) <= g*(m) + V(m) <= L*, where V(m) is the cost of the
// best lasso continuing from m and h(m) <= V(m) (the guard heuristic's parts
// bound the distance to some accepting node, or the whole lasso as max(path
// to acceptance, least cycle through it): plan/heuristic.hpp,
// chain_bound.hpp). So until J* is popped with g = g*(J*) the open list holds
// a node with f <= L*, and the search cannot stop with best > L*; once it is,
// J* (accepting, or a candidate whose key g*(J*) + lb <= g*(J*) + U(J*) = L*)
// gets its cycle search, which finds C (the bound best - g(J*) > C unless
// best is already optimal). Several starts change nothing in this: s* is
// pushed with g = 0 like the others.
// Learned values (experience) are C*_old - g_old(m) for nodes m closed by an
// earlier complete search on the same graph, from any set of starts: g_old(m)
// >= the distance from some old start s, and C*_old <= dist(s, m) + V(m) (the
// old optimum is at most the lasso from s through m), so they are <= V(m),
// whatever the starts of a later query.
// Solved paths (experience, `learn`): the prefix nodes of an optimal lasso
// found by a complete search are marked solved in the experience (their best
// lasso cost is then known exactly, Experience::set_solved; the join node's via
// is kViaCycle and its U is exact in the cycle table). A later search on
// the same graph that reaches a solved node m with cost g(m) has a lasso of
// cost g(m) + V(m) at once (the path to m, then m's recorded lasso); it keeps
// it as the incumbent and never expands solved nodes (nothing through m can
// be cheaper). With several starts the value of a prefix node x is C* minus
// its cost from the start s* the lasso used, again exact (V(x) >= C* -
// g(x) by the learned-bound argument). The stopping rule above then ends the
// search as soon as no open node could beat it, so a replan that starts on or
// next to an earlier plan expands few or no nodes. Optimality is unchanged:
// the incumbent is a real lasso, and the argument above only needs h
// admissible.
// What is not covered: a TS lasso u·v^ω whose automaton run needs several
// turns of v to return to the automaton state it entered v in is, in the
// product, the cycle v^k; it costs k·|v| there, so a cheaper plan of that
// kind is not found (tests/plan/lasso_join_test.cpp checks that every
// cheaper TS lasso it finds is of that kind; rare for patrol tasks).
// Memory: per-search arrays indexed by node id (g, parent, parent edge,
// heuristic, generation stamp), a binary heap with lazy deletion (stale
// entries are skipped), all grown geometrically and reused across queries.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <functional>
#include <vector>

#include "rtamp/plan/experience.hpp"
#include "rtamp/plan/heuristic.hpp"
#include "rtamp/plan/plan.hpp"
#include "rtamp/plan/product_graph.hpp"
#include "rtamp/util/names_table.hpp"

namespace rtamp::plan {

enum class Algorithm { Dijkstra, AStar, AStarExperience };
enum class GraphConstruction { Partial, Full };
const char* to_string(Algorithm a);
const NameTable<GraphConstruction>& graph_constructions();  // partial full
const char* to_string(GraphConstruction g);

// What a long query reports while it runs (SearchLimits::on_progress).
struct SearchProgress {
  const char* phase = "searching";  // or "constructing" (the full graph, before the search)
  std::uint64_t graph_nodes = 0;    // product nodes in the graph so far
  std::uint64_t expanded = 0;       // expansions of this query so far
  double best = kInf;               // cost of the best lasso found so far (kInf: none yet)
  double bound = 0;                 // f of the last node the prefix search took (a lower bound
                                    // on the optimum while no better lasso is known)
  double seconds = 0;               // since the query started
};

// When a query stops without an answer (docs/planning.md "Limits"). The
// memory held is estimated from the planner's own tables, never asked of the
// OS: the product graph, the search arrays and heaps, the experience and the
// motion-cost cache (the figure SearchStats::memory_bytes reports), checked
// every 128 expansions, so a query may end a little above its limit.
struct SearchLimits {
  std::size_t max_nodes = 20'000'000;  // product nodes in the graph
  double time_limit = 60;              // seconds; <= 0, NaN or infinite: none
  std::size_t max_memory_bytes = std::size_t{4} << 30;  // 4 GiB; 0: none
  // Called about every `progress_interval` seconds while a query runs (never
  // if it ends sooner), from the planning thread; it must not use the planner.
  std::function<void(const SearchProgress&)> on_progress;
  double progress_interval = 0.5;
  std::int64_t progress_interval_ns() const { return static_cast<std::int64_t>(progress_interval * 1e9); }
};

// How a lasso search runs.
struct LassoConfig {
  bool cycle_heuristic = true;  // cycle searches use state_distance_bound and Heuristic::walk_bound (else 0)
  bool learn = false;           // use and store learned bounds and solved paths in the experience
};

// When a search stops without finishing (one termination condition, as in
// OMPL): the node and memory limits of `limits`, its progress reports, and
// the query's steady-clock deadline (steady_now_ns; 0: none), which the
// planner derives from limits.time_limit when the query starts.
struct Termination {
  SearchLimits limits;
  std::int64_t deadline_ns = 0;
};

struct LassoResult {
  bool found = false;
  bool hit_node_limit = false, hit_time_limit = false, hit_memory_limit = false;
  bool stopped() const { return hit_node_limit || hit_time_limit || hit_memory_limit; }
  NodeId start = kNoNode;      // the start node the prefix leaves from
  NodeId cycle_start = kNoNode;  // J: where the prefix ends and the cycle begins and ends
  std::vector<std::uint32_t> prefix_edges, cycle_edges;  // edge indices in the graph
  double prefix_cost = 0, cycle_cost = 0;
};

class LassoSearch {
 public:
  // `x`: the experience of `g` (plan/experience.hpp); its cycle table is read
  // and written by every search (a cold query passes a fresh one), learned
  // bounds and solved paths only with config.learn.
  // `starts`: the start nodes (kNoNode entries are skipped); the best lasso
  // from any of them.
  LassoResult run(ProductGraph& g, Experience& x, const std::vector<NodeId>& starts, Heuristic& h,
                  const LassoConfig& config, const Termination& stop, SearchStats& stats);
  LassoResult run(ProductGraph& g, Experience& x, NodeId init, Heuristic& h, const LassoConfig& config,
                  const Termination& stop, SearchStats& stats);
  std::size_t memory_bytes() const { return prefix_.bytes() + cycle_.bytes(); }

 private:
  struct Item {
    double f, g;
    NodeId n;
    std::uint32_t m;  // moves on the path (second part of the (cost, moves) order)
  };
  struct Cost {
    double c;
    std::uint32_t m;
  };
  static constexpr Cost kNoCost{kInf, ~std::uint32_t{0}};
  // A per-node array that grows without initialising its new entries: every
  // field but `stamp` is written before it is read (an entry counts only once
  // its stamp is the search's generation), so a search over a graph that grew
  // pays for copying what it holds, not for clearing what it does not.
  template <class T>
  struct Slots {
    std::unique_ptr<T[]> p;
    std::size_t n = 0;
    T& operator[](std::size_t i) { return p[i]; }
    const T& operator[](std::size_t i) const { return p[i]; }
    std::size_t size() const { return n; }
    void grow(std::size_t cap, bool zero) {
      std::unique_ptr<T[]> q(new T[cap]);
      if (n) std::memcpy(q.get(), p.get(), n * sizeof(T));
      if (zero) std::memset(static_cast<void*>(q.get() + n), 0, (cap - n) * sizeof(T));
      p = std::move(q);
      n = cap;
    }
  };
  struct Space {
    Slots<double> g, h;
    Slots<std::uint32_t> m;  // moves of the path with cost g
    Slots<NodeId> parent;
    Slots<std::uint32_t> pedge, stamp;
    Slots<std::uint8_t> closed;
    std::vector<Item> heap;
    std::uint32_t gen = 0;
    void begin(std::size_t n);
    void ensure(std::size_t n);
    bool seen(NodeId n) const { return stamp[n] == gen; }
    void push(Item it);
    Item pop();
    std::size_t bytes() const;
  };
  // Cheapest cycle through n that contains an accepting node, in the order
  // (cost, moves), below `bound`; kNoCost if none. When found, its path is
  // kept in the experience beside its cost (the lasso is rebuilt from it).
  Cost cycle(ProductGraph& g, NodeId n, Cost bound, SearchStats& stats, LassoResult& r);
  // Whether n lies on any cycle through an accepting node: Tarjan's SCCs over
  // the nodes reachable from n (expanding them); n's SCC must hold an
  // accepting node and an edge. Every node of a finished SCC without one gets
  // "none below (inf, max moves)" in the cycle table (none exists). Called by
  // cycle() after an unbounded search (no incumbent) found nothing, so that a
  // query without a lasso does not run one whole-graph cycle search per
  // accepting node and join candidate. Nodes classified by an earlier call of
  // the same query are not visited again (their SCCs are complete). -1: out of budget.
  int on_accepting_cycle(ProductGraph& g, NodeId n, SearchStats& stats, LassoResult& r);
  void drop_loops(const ProductGraph& g, NodeId from, std::vector<std::uint32_t>& edges);
  // Node, memory and time limits; reports progress. Checks the memory estimate
  // and the clock every 128 calls.
  bool out_of_budget(const ProductGraph& g, const SearchStats& stats, LassoResult& r);

  Experience* x_ = nullptr;  // the experience of the graph being searched (during run())
  const Termination* stop_ = nullptr;  // during run()
  Heuristic* cycle_h_ = nullptr;       // the cycle searches' heuristic (null: none), during run()
  Space prefix_, cycle_;
  std::vector<NodeId> closed_list_;
  std::vector<NodeId> starts_;
  std::vector<Item> cand_;             // join candidates (a heap like Space::heap)
  std::vector<std::uint32_t> cycle_path_;
  // on_accepting_cycle: per-node DFS index and lowlink (valid where scc_stamp_
  // == scc_gen_), SCC state (0 open, 1 on the stack, 2 no accepting cycle, 3
  // on one), the DFS frames (node, next edge) and the SCC stack.
  std::vector<std::uint32_t> scc_index_, scc_low_, scc_stamp_;
  std::vector<std::uint8_t> scc_state_;
  std::vector<std::pair<NodeId, std::uint32_t>> scc_frames_;
  std::vector<NodeId> scc_stack_;
  std::uint32_t scc_gen_ = 0, scc_counter_ = 0;
  std::vector<NodeId> path_nodes_;
  std::uint64_t ticks_ = 0;
  std::int64_t start_ns_ = 0, next_progress_ns_ = 0;
  double progress_best_ = kInf, progress_bound_ = 0;
};

std::int64_t steady_now_ns();

}  // namespace rtamp::plan
