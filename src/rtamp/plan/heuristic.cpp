#include "rtamp/plan/heuristic.hpp"

#include <algorithm>

#include "rtamp/plan/cost_check.hpp"

namespace rtamp::plan {

using Kind = world::PropExpr::Kind;
using Cmp = world::PropExpr::Cmp;

GuardHeuristic::GuardHeuristic(const ProductGraph& g)
    : ts_(&g.system()), lab_(&g.labeling()), ba_(&g.bound_automaton()), model_(&g.model()) {
  const std::uint32_t n = ba_->num_states();
  accepting_.resize(n);
  exits_.resize(n);
  useful_.resize(n);
  for (std::uint32_t q = 0; q < n; ++q) {
    accepting_[q] = ba_->is_accepting_state(q);
    useful_[q] = g.useful(q);
  }
  for (std::uint32_t q = 0; q < n; ++q)
    for (const auto& e : ba_->edges[q])
      if (e.dst != q && useful_[e.dst] && !e.guard.is_false()) exits_[q].push_back(e.guard);
  // Transition-based: no state is accepting, so no exit is "direct"; an
  // accepting edge is also a step into the sink (state n), where walks to
  // acceptance end.
  direct_.assign(n, ba_->state_based);
  for (std::uint32_t q = 0; q < n; ++q)
    for (const auto& e : ba_->edges[q])
      if (e.dst != q && useful_[e.dst] && !e.guard.is_false() && !accepting_[e.dst]) direct_[q] = false;
  steps_.resize(n + 1);
  for (std::uint32_t q = 0; q < n; ++q)
    if (useful_[q])
      for (const auto& e : ba_->edges[q])
        if (useful_[e.dst] && !e.guard.is_false()) {
          steps_[q].push_back({e.dst, e.guard});
          if (!ba_->state_based && ba_->accepting_edge(e)) steps_[q].push_back({n, e.guard});
        }
  literal_.assign(2 * std::size_t{lab_->num_atoms()}, 0);
  literal_stamp_.assign(literal_.size(), 0);
  walk_d_.resize(n + 1);
  walk_done_.resize(n + 1);
  if (ts_->num_containers() == 0) {  // ChainBound needs one thing per move
    chain_ = std::make_unique<ChainBound>(*ts_, *lab_, *ba_, *model_, useful_);
    if (chain_->enabled()) chain_first_.resize(chain_->forcing_cubes().size());
    else chain_.reset();
  }
  scratch_.resize(64);  // per recursion depth; each grows on first use
  points_.resize(64);
  nearest_.assign(ts_->num_regions(), kInf);
  for (unsigned a = 0; a < ts_->num_regions(); ++a)
    for (unsigned b = 0; b < ts_->num_regions(); ++b)
      if (a != b) nearest_[a] = std::min(nearest_[a], distance(ts_->region_center(a), ts_->region_center(b)));
}

double GuardHeuristic::evaluate(const task::State& s, std::uint32_t q) {
  if (!useful_[q]) return kInf;
  begin_call(s);  // literal bounds are shared by the walk and the chain bound
  double h = 0;
  if (!accepting_[q]) {
    if (direct_[q]) {  // every exit of q enters an accepting state: the cheapest exit
      h = kInf;
      for (const auto& cube : exits_[q]) h = std::min(h, cube_bound(s, cube));
    } else {
      h = walk_from(s, q, kAnyAccepting);
    }
  }
  if (chain_ && h < kInf) {
    const auto& cubes = chain_->forcing_cubes();
    for (std::size_t i = 0; i < cubes.size(); ++i)
      chain_first_[i] = std::max(cube_bound(s, cubes[i]), chain_->from_state(s, static_cast<std::uint32_t>(i)));
    h = std::max(h, chain_->bound(q, chain_first_));
    h = chain_->join_bound(s, q, chain_first_, h);
  }
  return h;
}

void GuardHeuristic::begin_call(const task::State& s) {
  if (++call_ == 0) {  // stamps wrapped: forget them all
    std::fill(literal_stamp_.begin(), literal_stamp_.end(), 0);
    call_ = 1;
  }
  hand_ = ts_->hand_point(s);
}

double GuardHeuristic::cube_bound(const task::State& s, const automata::Cube& cube) {
  double lb = 0;
  for (unsigned i = 0; i < lab_->num_atoms(); ++i) {
    const automata::Letter bit = automata::Letter{1} << i;
    for (int want = 0; want < 2; ++want) {
      if (!((want ? cube.pos : cube.neg) & bit)) continue;
      const std::size_t k = 2 * std::size_t{i} + static_cast<std::size_t>(want);
      if (literal_stamp_[k] != call_) {
        literal_stamp_[k] = call_;
        literal_[k] = literal_bound(s, lab_->root(i), want != 0);
      }
      lb = std::max(lb, literal_[k]);
    }
  }
  return lb;
}

double GuardHeuristic::walk(const task::State& s, std::uint32_t q, std::uint32_t target) {
  if (!useful_[q] || (target != kAnyAccepting && !useful_[target])) return kInf;
  begin_call(s);
  return walk_from(s, q, target);
}

double GuardHeuristic::walk_from(const task::State& s, std::uint32_t q, std::uint32_t target) {
  const std::uint32_t n = ba_->num_states() + 1;  // the sink too
  std::fill(walk_d_.begin(), walk_d_.end(), kInf);
  std::fill(walk_done_.begin(), walk_done_.end(), 0);
  // First step out of q (it may return to q), then a minimax Dijkstra.
  for (const auto& [dst, cube] : steps_[q]) walk_d_[dst] = std::min(walk_d_[dst], cube_bound(s, cube));
  for (;;) {
    std::uint32_t u = n;
    for (std::uint32_t v = 0; v < n; ++v)
      if (!walk_done_[v] && walk_d_[v] < kInf && (u == n || walk_d_[v] < walk_d_[u])) u = v;
    if (u == n) return kInf;
    if (u == target || (target == kAnyAccepting && (u == n - 1 || accepting_[u]))) return walk_d_[u];
    walk_done_[u] = 1;
    for (const auto& [dst, cube] : steps_[u]) {
      if (walk_done_[dst]) continue;
      const double d = std::max(walk_d_[u], cube_bound(s, cube));
      if (d < walk_d_[dst]) walk_d_[dst] = d;
    }
  }
}

double GuardHeuristic::bound_in(const task::State& s, unsigned thing, int loc) {
  MotionQuery q;
  q.thing = ts_->thing_uid(thing);
  q.container = ts_->is_container(thing);
  q.hand = hand_;
  q.from = ts_->thing_point(s, thing);
  const bool anywhere = ts_->is_container_location(static_cast<unsigned>(loc));
  if (!anywhere) q.to = ts_->region_center(static_cast<unsigned>(loc));
  const double b = model_->lower_bound(q, anywhere);
  if (!valid_bound(b)) [[unlikely]]
    throw_bad_lower_bound(*model_, *ts_, s, thing, anywhere ? -1 : loc, b);
  return b;
}

double GuardHeuristic::bound_out(const task::State& s, unsigned thing) {
  MotionQuery q;
  q.thing = ts_->thing_uid(thing);
  q.container = ts_->is_container(thing);
  q.hand = hand_;
  q.from = ts_->thing_point(s, thing);
  const double b = model_->lower_bound(q, true);
  if (!valid_bound(b)) [[unlikely]]
    throw_bad_lower_bound(*model_, *ts_, s, thing, -1, b);
  return b;
}

double GuardHeuristic::transport(std::size_t m, int loc, bool into, const task::State& s,
                                 const std::vector<unsigned>& members) {
  const auto& pts = points_[depth_];
  if (m == 0) return 0;
  if (pts.size() < m) return kInf;
  TransportQuery t;
  t.hand = hand_;
  t.from = pts.data();
  t.n = pts.size();
  t.m = m;
  t.to_known = into && !ts_->is_container_location(static_cast<unsigned>(loc));
  if (t.to_known) {
    t.to = ts_->region_center(static_cast<unsigned>(loc));
    t.nearest = nearest_[static_cast<unsigned>(loc)];
  }
  t.one_at_a_time = ts_->num_containers() == 0;
  t.scratch = &scratch_[depth_];
  const double b = model_->transport_bound(t);
  if (!valid_bound(b)) [[unlikely]] {
    // The default transport_bound is made of lower_bound values: name the thing if one of them is bad.
    for (unsigned th : members) {
      if (into && (ts_->location(s, th) == static_cast<std::uint32_t>(loc) ||
                   (ts_->is_container(th) && ts_->is_container_location(static_cast<unsigned>(loc)))))
        continue;
      if (!into && ts_->location(s, th) != static_cast<std::uint32_t>(loc)) continue;
      (void)(into ? bound_in(s, th, loc) : bound_out(s, th));
    }
    throw_bad_bound(*model_,
                    "transport_bound for " + std::to_string(m) + " of " + std::to_string(pts.size()) + " things " +
                        (into ? "into " : "out of ") + ts_->location_name(static_cast<unsigned>(loc)),
                    b);
  }
  return b;
}

double GuardHeuristic::literal_bound(const task::State& s, std::uint32_t id, bool want) {
  const auto& n = lab_->nodes()[id];
  if (lab_->eval(id, s) == want) return 0;
  // From here on the node does not have the wanted value in s.
  switch (n.kind) {
    case Kind::True:
    case Kind::False:
      return kInf;
    case Kind::In: {
      if (n.thing < 0 || n.loc < 0) return kInf;  // never true; (never false is caught above)
      const auto t = static_cast<unsigned>(n.thing);
      // Containers only stand in regions.
      if (want && ts_->is_container(t) && ts_->is_container_location(static_cast<unsigned>(n.loc))) return kInf;
      return want ? bound_in(s, t, n.loc) : bound_out(s, t);
    }
    case Kind::All:
    case Kind::Any:
    case Kind::Count: {
      if (n.cls < 0 || n.loc < 0) return kInf;  // the count is always 0 and does not have the wanted value
      const auto& members = lab_->class_things(n.cls);
      const int total = static_cast<int>(members.size());
      const int c = lab_->count(s, n.cls, n.loc);
      // Target counts c2 in [0, total] for which the atom has the wanted value.
      auto value_at = [&](int c2) -> bool {
        switch (n.kind) {
          case Kind::All: return c2 == total;
          case Kind::Any: return c2 > 0;
          default: break;
        }
        switch (n.cmp) {
          case Cmp::Lt: return c2 < n.count;
          case Cmp::Le: return c2 <= n.count;
          case Cmp::Eq: return c2 == n.count;
          case Cmp::Ne: return c2 != n.count;
          case Cmp::Ge: return c2 >= n.count;
          case Cmp::Gt: return c2 > n.count;
        }
        return false;
      };
      int up = -1, down = -1;
      for (int c2 = c + 1; c2 <= total; ++c2)
        if (value_at(c2) == want) {
          up = c2 - c;
          break;
        }
      for (int c2 = c - 1; c2 >= 0; --c2)
        if (value_at(c2) == want) {
          down = c - c2;
          break;
        }
      if (depth_ >= scratch_.size()) return 0;  // absurdly deep: give up the bound (still admissible)
      auto& pts = points_[depth_];
      double best = kInf;
      const auto loc = static_cast<std::uint32_t>(n.loc);
      const bool loc_is_container = ts_->is_container_location(loc);
      if (up > 0) {
        pts.clear();
        for (unsigned t : members)
          if (ts_->location(s, t) != loc && !(ts_->is_container(t) && loc_is_container)) pts.push_back(ts_->thing_point(s, t));
        best = std::min(best, transport(static_cast<std::size_t>(up), n.loc, true, s, members));
      }
      if (down > 0) {
        pts.clear();
        for (unsigned t : members)
          if (ts_->location(s, t) == loc) pts.push_back(ts_->thing_point(s, t));
        best = std::min(best, transport(static_cast<std::size_t>(down), n.loc, false, s, members));
      }
      return best;
    }
    case Kind::Not:
      return literal_bound(s, n.children[0], !want);
    case Kind::And:
    case Kind::Or: {
      // want true of And / want false of Or: every child must have the value -> max.
      const bool all = (n.kind == Kind::And) == want;
      ++depth_;
      double r = all ? 0.0 : kInf;
      for (auto ch : n.children) {
        const double b = literal_bound(s, ch, want);
        r = all ? std::max(r, b) : std::min(r, b);
      }
      --depth_;
      return r;
    }
  }
  return 0;
}

double state_distance_bound(const task::System& ts, const MotionCostModel& model, const task::State& s,
                            const task::State& target) {
  // The hand is at home only before the first move: no path leads back there.
  if (ts.hand(target) == ts.home() && ts.hand(s) != ts.home()) return kInf;
  double best = 0;
  const world::Vec3 hand = ts.hand_point(s);
  for (unsigned t = 0; t < ts.num_things(); ++t) {
    // Canonical states sort interchangeable objects by location, so a member
    // may reach its target as another member: no per-member bound for them.
    if (ts.group_of(t) >= 0 || ts.container_group_of(t) >= 0) continue;
    const std::uint32_t want = ts.location(target, t);
    if (ts.location(s, t) == want) continue;
    // In interchangeable containers at both ends it may stay where it is
    // (the containers' names permute).
    if (ts.interchangeable_location(ts.location(s, t)) && ts.interchangeable_location(want)) continue;
    MotionQuery q;
    q.thing = ts.thing_uid(t);
    q.container = ts.is_container(t);
    q.hand = hand;
    q.from = ts.thing_point(s, t);
    const bool anywhere = ts.is_container_location(want);
    if (!anywhere) q.to = ts.region_center(want);
    const double b = model.lower_bound(q, anywhere);
    if (!valid_bound(b)) [[unlikely]]
      throw_bad_lower_bound(model, ts, s, t, anywhere ? -1 : static_cast<int>(want), b);
    best = std::max(best, b);
  }
  // Interchangeable objects: where the target has k more members of a group
  // in region r than s, at least k members now elsewhere must be put in r by
  // moves of their own (the model's transport_bound over them).
  thread_local std::vector<world::Vec3> from;
  thread_local std::vector<double> scratch;
  for (unsigned t = 0; t < ts.num_things(); ++t) {
    const int grp = ts.group_of(t);
    if (grp < 0) continue;
    bool first = true;  // one pass per (group, target region), at its first member there
    const std::uint32_t r = ts.location(target, t);
    for (unsigned u = 0; u < t && first; ++u) first = !(ts.group_of(u) == grp && ts.location(target, u) == r);
    if (!first || ts.is_container_location(r)) continue;
    std::size_t want = 0, have = 0;
    from.clear();
    for (unsigned u = 0; u < ts.num_things(); ++u) {
      if (ts.group_of(u) != grp) continue;
      want += ts.location(target, u) == r ? 1 : 0;
      if (ts.location(s, u) == r) ++have;
      else from.push_back(ts.thing_point(s, u));
    }
    if (want <= have) continue;
    TransportQuery q;
    q.hand = hand;
    q.from = from.data();
    q.n = from.size();
    q.m = want - have;
    q.to_known = true;
    q.to = ts.region_center(r);
    q.one_at_a_time = ts.num_containers() == 0;
    q.scratch = &scratch;
    const double b = model.transport_bound(q);
    if (!valid_bound(b)) [[unlikely]]
      throw_bad_lower_bound(model, ts, s, t, static_cast<int>(r), b);
    best = std::max(best, b);
  }
  return best;
}

}  // namespace rtamp::plan
