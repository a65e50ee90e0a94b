// Search strategies over the product graph and the lasso search (paper Section III.B).
// LassoSearch returns a minimum-cost lasso over all start nodes: a prefix to a node J
// and a cycle (>= 1 edge) back to J through an accepting node, joined anywhere; cost
// prefix + cycle, ties broken by fewer moves. Invariants: every heuristic is admissible
// (a cost bound, moves part 0); learned bounds and solved paths from the experience are
// at most the true remaining cost, so they never cost optimality; a stopped search
// reports which termination condition hit and never "no plan". Per-search arrays are
// indexed by node id and reused across queries (no allocation per expanded node).
// The algorithm, its proof of optimality, the experience argument and the one kind of
// lasso not covered (a cycle the automaton needs several turns of): docs/planning.md,
// "Lasso search and why it is optimal".

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
