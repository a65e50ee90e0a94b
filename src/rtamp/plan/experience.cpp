#include "rtamp/plan/experience.hpp"

#include <algorithm>

namespace rtamp::plan {

namespace {
// Makes v[n] exist, growing geometrically (new entries = fill).
template <class T>
void reach(std::vector<T>& v, std::uint32_t n, const T& fill) {
  if (n < v.size()) return;
  v.resize(std::max<std::size_t>(std::size_t{n} + 1, v.size() * 2), fill);
}
template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}
}  // namespace

void Experience::forget_graph() {  // memory is released, as the graph's is
  release(learned_);
  release(cycles_);
  release(hcache_);
  release(via_);
  release(solved_moves_);
  release(cycle_at_);
  release(cycle_store_);
}

void Experience::learn(Node n, double v) {
  reach(learned_, n, 0.0);
  learned_[n] = std::max(learned_[n], v);
}

void Experience::set_cycle(Node n, Cycle c) {
  reach(cycles_, n, Cycle{});
  cycles_[n] = c;
}

bool Experience::cycle_path(Node n, std::vector<std::uint32_t>& out) const {
  if (n >= cycle_at_.size() || cycle_at_[n] == 0) return false;
  const std::size_t at = cycle_at_[n] - 1;
  const std::uint32_t len = cycle_store_[at];
  out.insert(out.end(), cycle_store_.begin() + static_cast<std::ptrdiff_t>(at + 1),
             cycle_store_.begin() + static_cast<std::ptrdiff_t>(at + 1 + len));
  return true;
}

void Experience::set_cycle_path(Node n, const std::vector<std::uint32_t>& edges) {
  reach(cycle_at_, n, std::uint32_t{0});
  if (cycle_at_[n] != 0) return;  // recorded once; costs never change
  cycle_at_[n] = static_cast<std::uint32_t>(cycle_store_.size() + 1);
  cycle_store_.push_back(static_cast<std::uint32_t>(edges.size()));
  cycle_store_.insert(cycle_store_.end(), edges.begin(), edges.end());
}

void Experience::set_solved(Node n, double value, std::uint32_t moves, std::uint32_t via) {
  reach(learned_, n, 0.0);
  reach(via_, n, kNoVia);
  reach(solved_moves_, n, std::uint32_t{0});
  learned_[n] = value;
  via_[n] = via;
  solved_moves_[n] = moves;
}

void Experience::record_search(const std::vector<std::pair<Node, double>>& closed, bool found,
                               const std::vector<PrefixStep>& prefix, Node join, double cycle_cost,
                               std::uint32_t cycle_moves) {
  double total = std::numeric_limits<double>::infinity();
  std::uint32_t total_m = cycle_moves;
  if (found) {
    double prefix_cost = 0;  // summed as the lasso's prefix cost is
    for (const PrefixStep& s : prefix) {
      prefix_cost += s.cost;
      total_m += s.move ? 1 : 0;
    }
    total = prefix_cost + cycle_cost;
  }
  for (const auto& [n, g] : closed)
    if (!solved(n)) learn(n, total - g);
  if (!found) return;
  double gx = 0;
  std::uint32_t mx = 0;
  for (const PrefixStep& s : prefix) {
    if (!solved(s.node)) set_solved(s.node, total - gx, total_m - mx, s.edge);
    gx += s.cost;
    mx += s.move ? 1 : 0;
  }
  if (!solved(join)) set_solved(join, cycle_cost, cycle_moves, kViaCycle);
}

void Experience::cache_h(Node n, double v) {
  reach(hcache_, n, kUnknownH);
  hcache_[n] = v;
}

std::size_t Experience::memory_bytes() const {
  return learned_.capacity() * sizeof(double) + cycles_.capacity() * sizeof(Cycle) +
         hcache_.capacity() * sizeof(double) + via_.capacity() * 4 + solved_moves_.capacity() * 4 +
         cycle_at_.capacity() * 4 + cycle_store_.capacity() * 4;
}

}  // namespace rtamp::plan
