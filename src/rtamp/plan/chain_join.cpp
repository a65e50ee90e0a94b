// ChainBound's bound through the join of a lasso (declared in
// plan/chain_bound.hpp; argued in docs/planning.md "The join's stretch").
// Invariant: every table entry is at most the D-sum of some automaton walk of
// its kind, so join_bound never exceeds the cost of a lasso.
#include <algorithm>

#include "rtamp/plan/chain_bound.hpp"
#include "rtamp/plan/cost_check.hpp"

namespace rtamp::plan {

double ChainBound::join_between(const std::vector<int>& a, std::uint32_t g1, std::uint32_t gk) const {
  thread_local std::vector<JoinPoints> pts;
  pts.clear();
  const auto& b = forced_[g1];
  const auto& c = forced_[gk];
  for (std::size_t t = 0; t < a.size(); ++t) {
    const int known = (a[t] >= 0) + (b[t] >= 0) + (c[t] >= 0);
    if (known < 2) continue;  // J takes the one known place: free
    if ((a[t] < 0 || b[t] < 0 || a[t] == b[t]) && (c[t] < 0 || b[t] < 0 || c[t] == b[t]) &&
        (a[t] < 0 || c[t] < 0 || a[t] == c[t]))
      continue;  // every known place the same: J there, free
    JoinPoints p;
    if (a[t] >= 0) p.a = ts_->region_center(static_cast<unsigned>(a[t])), p.has_a = true;
    if (b[t] >= 0) p.b = ts_->region_center(static_cast<unsigned>(b[t])), p.has_b = true;
    if (c[t] >= 0) p.c = ts_->region_center(static_cast<unsigned>(c[t])), p.has_c = true;
    pts.push_back(p);
  }
  const double d = model_->join_set_bound(pts.data(), pts.size());
  if (!valid_bound(d)) [[unlikely]]
    throw_bad_bound(*model_, "join_set_bound", d);
  return d;
}

void ChainBound::build_join() {
  const std::uint32_t S = n_states_, F = n_forcing_;
  // Automaton states reached from q by steps that read no forcing guard (q included).
  auto closure = [&](std::uint32_t q) {
    std::vector<std::uint8_t> seen(S, 0);
    std::vector<std::uint32_t> todo{q}, out;
    seen[q] = 1;
    while (!todo.empty()) {
      const std::uint32_t u = todo.back();
      todo.pop_back();
      out.push_back(u);
      for (const Step& st : steps_)
        if (st.src == u && st.forcing < 0 && !seen[st.dst]) seen[st.dst] = 1, todo.push_back(st.dst);
    }
    return out;
  };
  // cyc[(qJ * F + g1) * F + gk]: the least chain g1 .. gk of a closed walk
  // from qJ through an accepting state whose first forcing guard is g1 and
  // last gk; free[qJ]: such a walk reading no forcing guard exists.
  std::vector<double> cyc(std::size_t{S} * F * F, kInf);
  std::vector<std::uint8_t> free(S, 0);
  const std::uint32_t n = S * F * 2;
  auto id = [&](std::uint32_t q, std::uint32_t l, std::uint32_t seen) { return (q * F + l) * 2 + seen; };
  std::vector<double> dist(n);
  std::vector<std::uint8_t> done(n);
  for (std::uint32_t qj = 0; qj < S; ++qj) {
    // (state, accepting seen) reached from qj by non-forcing steps.
    std::vector<std::uint8_t> reach(S * 2, 0);
    std::vector<std::uint32_t> todo;
    auto visit = [&](std::uint32_t u, std::uint32_t sn) {
      if (!reach[u * 2 + sn]) reach[u * 2 + sn] = 1, todo.push_back(u * 2 + sn);
    };
    const std::uint32_t acc0 = starts_accepted(qj) ? 1 : 0;
    for (const Step& st : steps_)  // at least one step
      if (st.src == qj && st.forcing < 0) visit(st.dst, acc0 | (st.accepting ? 1u : 0u));
    std::vector<std::uint8_t> start(S * 2, 0);
    start[qj * 2 + acc0] = 1;
    while (!todo.empty()) {
      const std::uint32_t v = todo.back();
      todo.pop_back();
      for (const Step& st : steps_)
        if (st.src == v / 2 && st.forcing < 0) visit(st.dst, (v % 2) | (st.accepting ? 1u : 0u));
    }
    free[qj] = reach[qj * 2 + 1];
    for (std::uint32_t v = 0; v < S * 2; ++v) start[v] = start[v] | reach[v];
    for (std::uint32_t g1 = 0; g1 < F; ++g1) {
      std::fill(dist.begin(), dist.end(), kInf);
      std::fill(done.begin(), done.end(), 0);
      bool any = false;
      for (const Step& st : steps_)
        for (std::uint32_t sn = 0; sn < 2; ++sn)
          if (st.forcing == static_cast<int>(g1) && start[st.src * 2 + sn])
            dist[id(st.dst, g1, sn | (st.accepting ? 1u : 0u))] = 0, any = true;
      if (!any) continue;
      for (;;) {
        const std::uint32_t u = least_open(dist, done);
        if (u == n) break;
        done[u] = 1;
        const std::uint32_t uq = u / 2 / F, ul = (u / 2) % F, us = u % 2;
        for (const Step& st : steps_) {
          if (st.src != uq) continue;
          const std::uint32_t sn = us | (st.accepting ? 1u : 0u);
          const std::uint32_t l = st.forcing < 0 ? ul : static_cast<std::uint32_t>(st.forcing);
          const double w = st.forcing < 0 ? 0.0 : d_[std::size_t{ul} * F + l];
          const std::uint32_t m = id(st.dst, l, sn);
          dist[m] = std::min(dist[m], dist[u] + w);
        }
      }
      for (std::uint32_t gk = 0; gk < F; ++gk) cyc[(std::size_t{qj} * F + g1) * F + gk] = dist[id(qj, gk, 1)];
    }
  }
  // val[node(q, l)], l a forcing guard: the least rest of the bound once the
  // prefix has read l in state q: on to a join state qJ (the chain), then
  // join_set_bound(l, g1, gk) + cyc (0 for a cycle without forcing guards).
  std::vector<double> val(arcs_.size(), kInf);
  for (std::uint32_t qj = 0; qj < S; ++qj)
    for (std::uint32_t l = 0; l < F; ++l) {
      double& v = val[node(qj, l)];
      if (free[qj]) {
        v = 0;
        continue;
      }
      for (std::uint32_t g1 = 0; g1 < F; ++g1)
        for (std::uint32_t gk = 0; gk < F; ++gk) {
          const double c = cyc[(std::size_t{qj} * F + g1) * F + gk];
          if (c < kInf) v = std::min(v, c + join_between(forced_[l], g1, gk));
        }
    }
  for (bool changed = true; changed;) {  // Bellman-Ford over G's arcs (a few dozen nodes)
    changed = false;
    for (std::uint32_t q = 0; q < S; ++q)
      for (std::uint32_t l = 0; l < F; ++l)
        for (const Arc& a : arcs_[node(q, l)])
          if (val[a.to] + a.weight < val[node(q, l)]) val[node(q, l)] = val[a.to] + a.weight, changed = true;
  }
  join_first_.assign(S, {});
  join_pairs_.assign(S, {});
  join_free_.assign(S, 0);
  for (std::uint32_t q = 0; q < S; ++q) {
    const auto states = closure(q);
    std::vector<double> first(F, kInf), pair(std::size_t{F} * F, kInf);
    for (std::uint32_t u : states) {
      join_free_[q] = join_free_[q] | free[u];
      for (const Step& st : steps_)
        if (st.src == u && st.forcing >= 0) {
          const auto c = static_cast<std::uint32_t>(st.forcing);
          first[c] = std::min(first[c], val[node(st.dst, c)]);
        }
      for (std::size_t k = 0; k < pair.size(); ++k)
        pair[k] = std::min(pair[k], cyc[std::size_t{u} * F * F + k]);
    }
    for (std::uint32_t c = 0; c < F; ++c)
      if (first[c] < kInf) join_first_[q].push_back({c, first[c]});
    for (std::uint32_t g1 = 0; g1 < F; ++g1)
      for (std::uint32_t gk = 0; gk < F; ++gk)
        if (pair[std::size_t{g1} * F + gk] < kInf)
          join_pairs_[q].push_back({g1, gk, pair[std::size_t{g1} * F + gk]});
    std::sort(join_pairs_[q].begin(), join_pairs_[q].end(),
              [](const JoinPair& x, const JoinPair& y) { return x.cycle < y.cycle; });
  }
}

double ChainBound::join_bound(const task::State& s, std::uint32_t q, const std::vector<double>& first,
                              double floor) const {
  if (!enabled_ || join_free_[q]) return floor;
  double best = kInf;
  for (const auto& [c, v] : join_first_[q]) {
    best = std::min(best, first[c] + v);
    if (best <= floor) return floor;
  }
  thread_local std::vector<int> at;
  at.resize(ts_->num_things());
  for (unsigned t = 0; t < ts_->num_things(); ++t) at[t] = static_cast<int>(ts_->location(s, t));
  for (const JoinPair& p : join_pairs_[q]) {
    if (p.cycle >= best) break;
    best = std::min(best, p.cycle + join_between(at, p.g1, p.gk));
    if (best <= floor) return floor;
  }
  return best == kInf ? floor : best;
}

}  // namespace rtamp::plan
