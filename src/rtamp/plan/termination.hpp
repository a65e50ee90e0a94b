// When a query stops without an answer: its limits (nodes, memory, time), its
// progress reports, and the one termination condition the searches of a query
// share (as in OMPL). The memory held is estimated from the planner's own
// tables, never asked of the OS, and checked with the clock every 128 steps,
// so a query may end a little above its limits (docs/planning.md "Limits").
// A stopped query says which limit stopped it and never "no plan".
#pragma once

#include <cstdint>
#include <functional>

#include "rtamp/plan/product_graph.hpp"

namespace rtamp::plan {

std::int64_t steady_now_ns();

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

// The limits of a query and its steady-clock deadline (steady_now_ns; 0:
// none), which the planner derives from limits.time_limit when the query starts.
struct Termination {
  SearchLimits limits;
  std::int64_t deadline_ns = 0;
};

enum class StopReason { None, NodeLimit, TimeLimit, MemoryLimit };

// The termination condition of one search, checked once per step.
class Budget {
 public:
  // `held_bytes`: the memory the query holds now (graph, experience, searches).
  void start(const Termination& stop, std::function<std::size_t()> held_bytes);
  // True once a limit is hit (then reason() says which); reports progress on the way.
  bool exhausted(const ProductGraph& g, std::uint64_t expanded);
  StopReason reason() const { return reason_; }
  // What the next progress report says of the best lasso and the search's bound.
  void set_progress(double best, double bound) {
    best_ = best;
    bound_ = bound;
  }

 private:
  const Termination* stop_ = nullptr;
  std::function<std::size_t()> held_bytes_;
  StopReason reason_ = StopReason::None;
  std::uint64_t ticks_ = 0;
  std::int64_t start_ns_ = 0, next_progress_ns_ = 0;
  double best_ = kInf, bound_ = 0;
};

}  // namespace rtamp::plan
