#include "rtamp/plan/motion_cost.hpp"

#include <algorithm>
#include <limits>

#include "rtamp/plan/cost_check.hpp"

namespace rtamp::plan {

MotionQuery MotionCostModel::query(const task::System& ts, const task::State& s, const task::Action& a) {
  MotionQuery q;
  q.thing = ts.thing_uid(a.thing);
  q.container = ts.is_container(a.thing);
  q.hand = ts.hand_point(s);
  q.from = ts.thing_point(s, a.thing);
  // The destination's point is taken in the state before the move; a thing
  // never moves into itself, so the destination does not move with it.
  q.to = ts.location_point(s, a.to);
  return q;
}

double sum_smallest(std::vector<double>& v, std::size_t k) {
  if (k == 0) return 0;
  if (v.size() < k) return std::numeric_limits<double>::infinity();
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k - 1), v.end());
  double s = 0;
  for (std::size_t i = 0; i < k; ++i) s += v[i];
  return s;
}

double kth_smallest(std::vector<double>& v, std::size_t k) {
  if (k == 0) return 0;
  if (v.size() < k) return std::numeric_limits<double>::infinity();
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k - 1), v.end());
  return v[k - 1];
}

double MotionCostModel::transport_bound(const TransportQuery& t) const {
  std::vector<double>& v = *t.scratch;
  v.clear();
  for (std::size_t i = 0; i < t.n; ++i) {
    MotionQuery q;
    q.hand = t.hand;
    q.from = t.from[i];
    q.to = t.to;
    const double b = lower_bound(q, !t.to_known);
    if (!valid_bound(b)) [[unlikely]]
      return b;  // the caller's check reports it
    v.push_back(b);
  }
  return kth_smallest(v, t.m);
}

// With the hand at h, thing x at p_x, destination t: a_x = |h - p_x|,
// c_x = |p_x - t|. The hand's path must, for the first thing delivered, go
// h -> p_x -> t (B1 for the m-th cheapest). If moves carry one thing each,
// the carried stretches are disjoint, so the path is at least
// min a + (sum of the m smallest c) (B2); and between two deliveries at t
// the hand must leave t, reach the next thing (at p_x, or at some other
// location point, at least `nearest` away) and come back:
// min (a + c) + sum of the (m - 1) smallest 2 min(c_x, nearest) (B3).
// Things that share one point p (B4): if k of them must arrive, the hand's
// path, projected on the line from p to t, crosses each point between them k
// times carrying one of them forward and k - 1 times coming back, whatever
// detours they take: (2k - 1) |p - t| (docs/planning.md, "The chain bound's
// groups"); k = m minus the candidates elsewhere.
double EuclidCost::transport_bound(const TransportQuery& t) const {
  std::vector<double>& v = *t.scratch;
  double min_a = std::numeric_limits<double>::infinity(), min_s = min_a;
  v.clear();
  for (std::size_t i = 0; i < t.n; ++i) {
    const double a = distance(t.hand, t.from[i]);
    const double c = t.to_known ? distance(t.from[i], t.to) : 0.0;
    min_a = std::min(min_a, a);
    min_s = std::min(min_s, a + c);
    v.push_back(a + c);
  }
  double best = kth_smallest(v, t.m);  // B1
  if (t.one_at_a_time && t.to_known && t.m >= 1 && t.n >= t.m) {
    v.clear();
    for (std::size_t i = 0; i < t.n; ++i) v.push_back(distance(t.from[i], t.to));
    best = std::max(best, min_a + sum_smallest(v, t.m));  // B2
    v.clear();
    for (std::size_t i = 0; i < t.n; ++i) v.push_back(2 * std::min(distance(t.from[i], t.to), t.nearest));
    best = std::max(best, min_s + sum_smallest(v, t.m - 1));  // B3
    for (std::size_t i = 0; i < t.n; ++i) {  // B4, once per distinct point (its first candidate)
      std::size_t same = 0;
      bool first = true;
      for (std::size_t j = 0; j < t.n && first; ++j) {
        if (t.from[j] != t.from[i]) continue;
        first = j >= i;
        ++same;
      }
      if (!first || same + t.m <= t.n) continue;
      const std::size_t k = same + t.m - t.n;
      best = std::max(best, group_carry_bound(t.from[i], t.to, k));
    }
  }
  return best;
}

// Each move displaces one thing by exactly its cost when moves carry one
// thing each: the sum of the m smallest displacements; otherwise the m-th.
double RegionCost::transport_bound(const TransportQuery& t) const {
  if (!t.to_known) return 0;
  std::vector<double>& v = *t.scratch;
  v.clear();
  for (std::size_t i = 0; i < t.n; ++i) v.push_back(distance(t.from[i], t.to));
  return t.one_at_a_time ? sum_smallest(v, t.m) : kth_smallest(v, t.m);
}

}  // namespace rtamp::plan
