#include "rtamp/plan/chain_bound.hpp"

#include <algorithm>

#include "rtamp/plan/cost_check.hpp"

namespace rtamp::plan {

namespace {

using Kind = world::PropExpr::Kind;

// The model's carry_bound between regions a and b, checked.
double checked_carry_bound(const MotionCostModel& model, const task::System& ts, unsigned a, unsigned b) {
  const double d = model.carry_bound(ts.region_center(a), ts.region_center(b));
  if (!valid_bound(d)) [[unlikely]]
    throw_bad_bound(model, "carry_bound from " + ts.location_name(a) + " to " + ts.location_name(b), d);
  return d;
}

// Records in `at` the locations that proposition node `node`, wanted `want`,
// forces (see the header); false if it forces a thing to two places (the
// literal set can then never hold). Anything else forces nothing.
bool force(const task::Labeling& lab, std::uint32_t node, bool want, std::vector<int>& at) {
  const auto& nd = lab.nodes()[node];
  auto put = [&](unsigned t, int loc) {
    if (at[t] >= 0 && at[t] != loc) return false;
    at[t] = loc;
    return true;
  };
  if (want) {
    switch (nd.kind) {
      case Kind::In:
        return nd.thing < 0 || nd.loc < 0 || put(static_cast<unsigned>(nd.thing), nd.loc);
      case Kind::All:
        if (nd.cls < 0 || nd.loc < 0) return true;
        for (unsigned t : lab.class_things(nd.cls))
          if (!put(t, nd.loc)) return false;
        return true;
      case Kind::And:
        for (auto c : nd.children)
          if (!force(lab, c, true, at)) return false;
        return true;
      case Kind::Not:
        return force(lab, nd.children[0], false, at);
      default:
        return true;
    }
  }
  switch (nd.kind) {
    case Kind::Or:
      for (auto c : nd.children)
        if (!force(lab, c, false, at)) return false;
      return true;
    case Kind::Not:
      return force(lab, nd.children[0], true, at);
    default:
      return true;
  }
}

constexpr std::uint32_t kMaxNodes = 48;

// D between a state where thing t is in region a[t] and a later one where it
// is in b[t] (-1: either unknown): the model's carry_set_bound for the things
// that change region (every move carries one thing: no containers here).
double between(const MotionCostModel& model, const task::System& ts, const std::vector<int>& a,
               const std::vector<int>& b) {
  thread_local std::vector<world::Vec3> from, to;
  from.clear();
  to.clear();
  for (std::size_t t = 0; t < a.size(); ++t) {
    if (a[t] < 0 || b[t] < 0 || a[t] == b[t]) continue;
    from.push_back(ts.region_center(static_cast<unsigned>(a[t])));
    to.push_back(ts.region_center(static_cast<unsigned>(b[t])));
  }
  const double d = model.carry_set_bound(from.data(), to.data(), from.size());
  if (!valid_bound(d)) [[unlikely]]
    throw_bad_bound(model, "carry_set_bound", d);
  return d;
}

}  // namespace

ChainBound::ChainBound(const task::System& ts, const task::Labeling& lab, const automata::Automaton& ba,
                       const MotionCostModel& model, const std::vector<bool>& useful) {
  n_states_ = ba.num_states();
  kappa_.assign(n_states_, 0);
  if (ts.num_containers() > 0) return;  // a container move carries several things
  ts_ = &ts;
  model_ = &model;
  std::vector<Step>& steps = steps_;
  std::vector<std::vector<int>>& forced = forced_;
  for (std::uint32_t q = 0; q < n_states_; ++q) {
    if (!useful[q]) continue;
    for (const auto& e : ba.edges[q]) {
      if (!useful[e.dst] || e.guard.is_false()) continue;
      std::vector<int> at(ts.num_things(), -1);
      bool holds = true;
      for (unsigned i = 0; i < lab.num_atoms() && holds; ++i) {
        const automata::Letter bit = automata::Letter{1} << i;
        if (e.guard.pos & bit) holds = force(lab, lab.root(i), true, at);
        if (holds && (e.guard.neg & bit)) holds = force(lab, lab.root(i), false, at);
      }
      if (!holds) continue;  // forces a thing to two places: never read
      int idx = -1;
      if (std::any_of(at.begin(), at.end(), [](int l) { return l >= 0; })) {
        // One index per distinct guard (D depends only on the guard).
        idx = static_cast<int>(std::find(cubes_.begin(), cubes_.end(), e.guard) - cubes_.begin());
        if (idx == static_cast<int>(cubes_.size())) {
          cubes_.push_back(e.guard);
          forced.push_back(std::move(at));
        }
      }
      steps.push_back({q, e.dst, idx, ba.accepting_edge(e)});
    }
  }
  n_forcing_ = static_cast<std::uint32_t>(cubes_.size());
  const std::uint32_t n = n_states_ * (n_forcing_ + 1);
  if (n_forcing_ == 0 || n > kMaxNodes) {
    cubes_.clear();
    return;
  }
  d_.assign(std::size_t{n_forcing_} * n_forcing_, 0);
  bool positive = false;
  for (std::uint32_t i = 0; i < n_forcing_; ++i)
    for (std::uint32_t j = 0; j < n_forcing_; ++j) {
      for (unsigned t = 0; t < ts.num_things(); ++t)  // each pair's carry_bound checked, named in the error
        if (forced[i][t] >= 0 && forced[j][t] >= 0 && forced[i][t] != forced[j][t])
          (void)checked_carry_bound(model, ts, static_cast<unsigned>(forced[i][t]), static_cast<unsigned>(forced[j][t]));
      const double sum = between(model, ts, forced[i], forced[j]);
      d_[std::size_t{i} * n_forcing_ + j] = sum;
      positive = positive || sum > 0;
    }
  if (!positive) {
    cubes_.clear();
    return;
  }
  arcs_.assign(n, {});
  for (const auto& st : steps)
    for (std::uint32_t l = 0; l <= n_forcing_; ++l) {
      if (st.forcing < 0) {
        arcs_[node(st.src, l)].push_back({node(st.dst, l), 0.0});
      } else if (l < n_forcing_) {
        const auto c = static_cast<std::uint32_t>(st.forcing);
        arcs_[node(st.src, l)].push_back({node(st.dst, c), d_[std::size_t{l} * n_forcing_ + c]});
      }
    }
  transition_based_ = !ba.state_based;
  accepting_.assign(n_states_, false);
  for (std::uint32_t q = 0; q < n_states_; ++q) accepting_[q] = useful[q] && ba.is_accepting_state(q);
  if (transition_based_)
    for (const auto& st : steps) accepting_[st.dst] = accepting_[st.dst] || st.accepting;
  dist_.resize(n);
  done_.resize(n);
  for (std::uint32_t q = 0; q < n_states_; ++q) {
    double best = kInf;
    if (accepting_[q])
      for (std::uint32_t l = 0; l <= n_forcing_; ++l) {
        if (!transition_based_) {
          dijkstra(node(q, l), true);
          best = std::min(best, dist_[node(q, l)]);
          continue;
        }
        // A walk from (q, l) to some (u, l'), then an accepting step u -> q
        // landing on (q, l) again.
        dijkstra(node(q, l), false);
        for (const auto& st : steps) {
          if (!st.accepting || st.dst != q) continue;
          for (std::uint32_t l1 = 0; l1 <= n_forcing_; ++l1) {
            const double du = dist_[node(st.src, l1)];
            if (du == kInf) continue;
            if (st.forcing < 0 && l1 == l) best = std::min(best, du);
            if (st.forcing == static_cast<int>(l) && l1 < n_forcing_)
              best = std::min(best, du + d_[std::size_t{l1} * n_forcing_ + l]);
          }
        }
      }
    kappa_[q] = best;
  }
  min_kappa_ = kInf;
  for (std::uint32_t q = 0; q < n_states_; ++q)
    if (accepting_[q]) min_kappa_ = std::min(min_kappa_, kappa_[q]);
  if (min_kappa_ == kInf) min_kappa_ = 0;
  // tail of a forcing edge with guard c into state d: from node (d, c) of G
  // on, the least distance to an accepting state plus its kappa (computed once
  // per node).
  // A lasso may join its cycle anywhere, so the cycle need not follow the
  // path to qa: the lasso pays the path to qa (prefix and the cycle's first
  // part) and, separately, a cycle through qa, so it costs at least
  // max(path, kappa(qa)); a tail is the pair (least path, least kappa) over
  // the accepting states reached (a weaker, valid bound than the least max).
  std::vector<Tail> tail(n, Tail{-1.0, -1.0});
  auto tail_of = [&](std::uint32_t d, std::uint32_t c) {
    Tail& t = tail[node(d, c)];
    if (t.path >= 0) return t;
    dijkstra(node(d, c), false);
    t = {kInf, kInf};
    for (std::uint32_t qa = 0; qa < n_states_; ++qa)
      if (accepting_[qa] && kappa_[qa] < kInf)
        for (std::uint32_t l = 0; l <= n_forcing_; ++l)
          if (dist_[node(qa, l)] < kInf) {
            t.path = std::min(t.path, dist_[node(qa, l)]);
            t.kappa = std::min(t.kappa, kappa_[qa]);
          }
    return t;
  };
  // Per state q: the states reachable by non-forcing edges, their kappa, and
  // the forcing edges leaving them (one entry per guard: the least tail).
  zero_tail_.assign(n_states_, kInf);
  entries_.assign(n_states_, {});
  std::vector<std::uint8_t> seen(n_states_);
  std::vector<std::uint32_t> todo;
  std::vector<Tail> best_tail(n_forcing_);
  for (std::uint32_t q = 0; q < n_states_; ++q) {
    std::fill(seen.begin(), seen.end(), 0);
    std::fill(best_tail.begin(), best_tail.end(), Tail{kInf, kInf});
    todo.assign(1, q);
    seen[q] = 1;
    while (!todo.empty()) {
      const std::uint32_t u = todo.back();
      todo.pop_back();
      if (accepting_[u]) zero_tail_[q] = std::min(zero_tail_[q], kappa_[u]);
      for (const auto& st : steps) {
        if (st.src != u) continue;
        if (st.forcing >= 0) {
          const auto c = static_cast<std::uint32_t>(st.forcing);
          const Tail t = tail_of(st.dst, c);
          best_tail[c] = {std::min(best_tail[c].path, t.path), std::min(best_tail[c].kappa, t.kappa)};
        } else if (!seen[st.dst]) {
          seen[st.dst] = 1;
          todo.push_back(st.dst);
        }
      }
    }
    for (std::uint32_t c = 0; c < n_forcing_; ++c)
      if (best_tail[c].path < kInf) entries_[q].push_back({c, best_tail[c]});
  }
  enabled_ = true;
  build_join();
}

std::uint32_t ChainBound::least_open(const std::vector<double>& dist, const std::vector<std::uint8_t>& done,
                                     double below) {
  const auto n = static_cast<std::uint32_t>(dist.size());
  std::uint32_t u = n;
  for (std::uint32_t v = 0; v < n; ++v)
    if (!done[v] && dist[v] < below && (u == n || dist[v] < dist[u])) u = v;
  return u;
}

void ChainBound::dijkstra(std::uint32_t src, bool skip_src) {
  const auto n = static_cast<std::uint32_t>(arcs_.size());
  std::fill(dist_.begin(), dist_.end(), kInf);
  std::fill(done_.begin(), done_.end(), 0);
  auto relax = [&](std::uint32_t u, double du) {
    for (const Arc& a : arcs_[u]) {
      const double d = du + a.weight;
      if (d < dist_[a.to]) dist_[a.to] = d;
    }
  };
  if (skip_src) relax(src, 0);
  else dist_[src] = 0;
  for (;;) {
    const std::uint32_t u = least_open(dist_, done_);
    if (u == n) return;
    done_[u] = 1;
    if (skip_src && u == src) continue;  // back at the source: the cycle is closed
    relax(u, dist_[u]);
  }
}

double ChainBound::from_state(const task::State& s, std::uint32_t c) const {
  thread_local std::vector<int> at;
  at.resize(ts_->num_things());
  for (unsigned t = 0; t < ts_->num_things(); ++t) at[t] = static_cast<int>(ts_->location(s, t));
  return between(*model_, *ts_, at, forced_[c]);
}

double ChainBound::cycle_bound_at(const task::State& s, std::uint32_t q) const {
  return path_bound(s, q, s, q, starts_accepted(q));
}

double ChainBound::path_bound(const task::State& s, std::uint32_t q, const task::State& target,
                              std::uint32_t target_q, bool accepted) const {
  if (!enabled_) return 0;
  const unsigned things = ts_->num_things();
  const std::uint32_t F = n_forcing_;
  // D from s's locations to each forcing guard's, and from each to the target's.
  std::vector<double> to(F, 0), back(F, 0);
  std::vector<int> at(things), end(things);
  for (unsigned t = 0; t < things; ++t) {
    at[t] = static_cast<int>(ts_->location(s, t));
    end[t] = static_cast<int>(ts_->location(target, t));
  }
  for (std::uint32_t c = 0; c < F; ++c) {
    to[c] = between(*model_, *ts_, at, forced_[c]);
    back[c] = between(*model_, *ts_, forced_[c], end);
  }
  // Dijkstra over (automaton state, last forcing guard or F = "s itself", accepting seen).
  const std::uint32_t n = n_states_ * (F + 1) * 2;
  auto id = [&](std::uint32_t qq, std::uint32_t l, std::uint32_t seen) { return (qq * (F + 1) + l) * 2 + seen; };
  std::vector<double> dist(n, kInf);
  std::vector<std::uint8_t> done(n, 0);
  double best = kInf;
  auto relax = [&](std::uint32_t qq, std::uint32_t l, std::uint32_t seen, double du) {
    for (const Step& st : steps_) {
      if (st.src != qq) continue;
      const std::uint32_t seen2 = seen | (st.accepting ? 1u : 0u);
      std::uint32_t l2 = l;
      double w = 0;
      if (st.forcing >= 0) {
        l2 = static_cast<std::uint32_t>(st.forcing);
        w = l == F ? to[l2] : d_[std::size_t{l} * F + l2];
      }
      if (st.dst == target_q && seen2) best = std::min(best, du + w + (l2 == F ? 0.0 : back[l2]));
      const std::uint32_t m = id(st.dst, l2, seen2);
      if (du + w < dist[m]) dist[m] = du + w;
    }
  };
  relax(q, F, accepted || starts_accepted(q) ? 1 : 0, 0);
  for (;;) {
    const std::uint32_t u = least_open(dist, done, best);
    if (u == n) break;
    done[u] = 1;
    relax(u / 2 / (F + 1), (u / 2) % (F + 1), u % 2, dist[u]);
  }
  return best == kInf ? 0.0 : best;  // kInf would mean no such path: leave that to the search
}

double ChainBound::bound(std::uint32_t q, const std::vector<double>& first) const {
  double best = zero_tail_[q];
  for (const auto& [c, t] : entries_[q]) best = std::min(best, std::max(first[c] + t.path, t.kappa));
  return best;
}

}  // namespace rtamp::plan
