// The per-node arrays of one best-first search over the product graph, and the
// order it expands in. Entries are indexed by node id and reused across queries:
// an entry counts only once its stamp is the current search's generation, so
// starting a search clears nothing and no expanded node allocates (the arrays
// grow geometrically with the graph). Costs are compared as (motion cost,
// number of moves), costs equal within kCostEps.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "rtamp/plan/product_graph.hpp"

namespace rtamp::plan {

inline constexpr double kCostEps = 1e-9;
inline constexpr std::uint32_t kManyMoves = ~std::uint32_t{0};

// (c1, m1) below (c2, m2) in the order (cost, moves).
inline bool lex_less(double c1, std::uint32_t m1, double c2, std::uint32_t m2) {
  return c1 < c2 - kCostEps || (c1 <= c2 + kCostEps && m1 < m2);
}

// A cost in the order (cost, moves).
struct PathCost {
  double c;
  std::uint32_t m;
};
inline constexpr PathCost kNoPathCost{kInf, kManyMoves};

// An open-list entry: f = g + h; ties go to the larger g (deeper), then to fewer moves.
struct SearchItem {
  double f, g;
  NodeId n;
  std::uint32_t m;  // moves on the path (second part of the (cost, moves) order)
};
// Max-heap comparator: "a after b".
inline bool after(const SearchItem& a, const SearchItem& b) {
  if (a.f != b.f) return a.f > b.f;
  if (a.g != b.g) return a.g < b.g;
  return a.m > b.m;
}

class SearchSpace {
 public:
  // A per-node array that grows without initialising its new entries: every
  // field but `stamp` is written before it is read, so a search over a graph
  // that grew pays for copying what it holds, not for clearing what it does not.
  template <class T>
  struct Slots {
    std::unique_ptr<T[]> p;
    std::size_t n = 0;
    T& operator[](std::size_t i) { return p[i]; }
    const T& operator[](std::size_t i) const { return p[i]; }
    std::size_t size() const { return n; }
    void grow(std::size_t cap, bool zero);
  };

  Slots<double> g, h;
  Slots<std::uint32_t> m;  // moves of the path with cost g
  Slots<NodeId> parent;
  Slots<std::uint32_t> pedge, stamp;
  Slots<std::uint8_t> closed;
  std::vector<SearchItem> heap;

  // A new search over ids below n: no entry is seen, the heap is empty.
  void begin(std::size_t n);
  // Room for ids below n (entries kept).
  void ensure(std::size_t n);
  bool seen(NodeId n) const { return stamp[n] == gen_; }
  void mark_seen(NodeId n) { stamp[n] = gen_; }
  // n is reached by a path of cost (cost, moves) whose last edge comes from
  // `from` (it is open again).
  void reach(NodeId n, double cost, std::uint32_t moves, NodeId from, std::uint32_t edge) {
    g[n] = cost;
    m[n] = moves;
    parent[n] = from;
    pedge[n] = edge;
    closed[n] = 0;
  }
  void push(SearchItem it);
  SearchItem pop();
  // True if the item is out of date (its node was reached more cheaply since).
  bool stale(const SearchItem& it) const { return it.g != g[it.n] || it.m != m[it.n]; }
  std::size_t bytes() const;

 private:
  std::uint32_t gen_ = 0;
};

}  // namespace rtamp::plan
