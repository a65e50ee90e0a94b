#include "rtamp/plan/motion_cost.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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
// detours they take: (2k - 1) |p - t| (docs/planning.md, "The hand's way
// back"); k = m minus the candidates elsewhere.
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
      best = std::max(best, static_cast<double>(2 * k - 1) * distance(t.from[i], t.to));
    }
  }
  return best;
}

double MotionCostModel::carry_set_bound(const world::Vec3* from, const world::Vec3* to, std::size_t n) const {
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += carry_bound(from[i], to[i]);
  return sum;
}

double EuclidCost::carry_set_bound(const world::Vec3* from, const world::Vec3* to, std::size_t n) const {
  double best = MotionCostModel::carry_set_bound(from, to, n);
  // Axes: the distinct directions of the moves (at most 8; any axis is valid).
  std::vector<world::Vec3> axes;
  for (std::size_t i = 0; i < n && axes.size() < 8; ++i) {
    const double d = distance(from[i], to[i]);
    if (d <= 0) continue;
    const world::Vec3 u{(to[i][0] - from[i][0]) / d, (to[i][1] - from[i][1]) / d, (to[i][2] - from[i][2]) / d};
    bool known = false;
    for (const auto& a : axes) known = known || std::abs(std::abs(a[0] * u[0] + a[1] * u[1] + a[2] * u[2]) - 1) < 1e-12;
    if (!known) axes.push_back(u);
  }
  struct Event {
    double x;
    int df, db;  // change of the forward and backward counts at x
  };
  std::vector<Event> ev;
  for (const auto& u : axes) {
    ev.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const double a = from[i][0] * u[0] + from[i][1] * u[1] + from[i][2] * u[2];
      const double b = to[i][0] * u[0] + to[i][1] * u[1] + to[i][2] * u[2];
      if (a < b) ev.push_back({a, 1, 0}), ev.push_back({b, -1, 0});
      else if (b < a) ev.push_back({b, 0, 1}), ev.push_back({a, 0, -1});
    }
    std::sort(ev.begin(), ev.end(), [](const Event& p, const Event& q) { return p.x < q.x; });
    double total = 0;
    int f = 0, bk = 0;
    for (std::size_t j = 0; j < ev.size(); ++j) {
      if (j > 0 && (f > 0 || bk > 0))
        total += (ev[j].x - ev[j - 1].x) * std::max(f + bk, 2 * std::max(f, bk) - 1);
      f += ev[j].df;
      bk += ev[j].db;
    }
    best = std::max(best, total);
  }
  return best;
}

double MotionCostModel::join_set_bound(const JoinPoints* p, std::size_t n) const {
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!p[i].has_b) continue;
    double d = 0;
    if (p[i].has_a && p[i].a != p[i].b) d = carry_bound(p[i].a, p[i].b);
    if (p[i].has_c && p[i].c != p[i].b) d = std::max(d, carry_bound(p[i].c, p[i].b));
    sum += d;
  }
  return sum;
}

namespace {

// Crossings of a point x that the hand makes at least in one stretch where
// f things must pass x forward and b backward (docs/planning.md).
int crossings(int f, int b) { return f + b == 0 ? 0 : std::max(f + b, 2 * std::max(f, b) - 1); }

double project(const world::Vec3& p, const world::Vec3& u) { return p[0] * u[0] + p[1] * u[1] + p[2] * u[2]; }

using Counts = std::array<int, 4>;  // forward and backward passes of x: stretch 1, stretch 2

// Things alike that may put J on either side: their counts on each side.
struct Flexible {
  int side[2][4];
  int count;
};

// The least crossings of x of both stretches over the sides the flexible
// things' J may take: every split of each group is tried while there are
// few (a group's members are interchangeable), then each count's smaller
// side (a relaxation: crossings grow with every count).
double least_crossings(const Counts& base, const std::vector<Flexible>& groups) {
  long combos = 1;
  std::size_t exact = 0;
  while (exact < groups.size() && combos * (groups[exact].count + 1) <= 4096)
    combos *= groups[exact++].count + 1;
  Counts floor = base;
  for (std::size_t g = exact; g < groups.size(); ++g)
    for (int k = 0; k < 4; ++k)
      floor[k] += groups[g].count * std::min(groups[g].side[0][k], groups[g].side[1][k]);
  int best = std::numeric_limits<int>::max();
  auto rec = [&](auto&& self, std::size_t g, const Counts& acc) -> void {
    if (g == exact) {
      best = std::min(best, crossings(acc[0], acc[1]) + crossings(acc[2], acc[3]));
      return;
    }
    for (int left = 0; left <= groups[g].count; ++left) {
      Counts next = acc;
      for (int k = 0; k < 4; ++k)
        next[k] += left * groups[g].side[0][k] + (groups[g].count - left) * groups[g].side[1][k];
      self(self, g + 1, next);
    }
  };
  rec(rec, 0, floor);
  return best;
}

}  // namespace

double EuclidCost::join_set_bound(const JoinPoints* p, std::size_t n) const {
  double best = MotionCostModel::join_set_bound(p, n);
  std::vector<world::Vec3> axes;
  auto add_axis = [&](const world::Vec3& from, const world::Vec3& to) {
    const double d = distance(from, to);
    if (d <= 0 || axes.size() >= 8) return;
    const world::Vec3 u{(to[0] - from[0]) / d, (to[1] - from[1]) / d, (to[2] - from[2]) / d};
    for (const auto& a : axes)
      if (std::abs(std::abs(project(a, u)) - 1) < 1e-12) return;
    axes.push_back(u);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (p[i].has_a && p[i].has_b) add_axis(p[i].a, p[i].b);
    if (p[i].has_c && p[i].has_b) add_axis(p[i].c, p[i].b);
    if (p[i].has_a && p[i].has_c) add_axis(p[i].a, p[i].c);
  }
  std::vector<double> xs;
  struct Proj {
    double a, b, c;
  };
  std::vector<Proj> pr(n);
  std::vector<Flexible> flexible;
  for (const auto& u : axes) {
    xs.clear();
    for (std::size_t i = 0; i < n; ++i) {
      pr[i] = {project(p[i].a, u), project(p[i].b, u), project(p[i].c, u)};
      if (p[i].has_a) xs.push_back(pr[i].a);
      if (p[i].has_b) xs.push_back(pr[i].b);
      if (p[i].has_c) xs.push_back(pr[i].c);
    }
    std::sort(xs.begin(), xs.end());
    double total = 0;
    for (std::size_t j = 1; j < xs.size(); ++j) {
      if (xs[j] <= xs[j - 1]) continue;
      const double x = 0.5 * (xs[j] + xs[j - 1]);
      Counts base{};
      flexible.clear();
      for (std::size_t i = 0; i < n; ++i) {
        // Counts (f1, b1, f2, b2) for J_i left (side 0) or right (side 1) of
        // x; an unknown point takes J_i's side (it costs nothing there).
        Flexible v{};
        v.count = 1;
        for (int side = 0; side < 2; ++side) {
          const int a = p[i].has_a ? (pr[i].a > x) : side;
          const int b = p[i].has_b ? (pr[i].b > x) : side;
          const int c = p[i].has_c ? (pr[i].c > x) : side;
          if (a != side) ++v.side[side][side > a ? 0 : 1];
          if (b != side) ++v.side[side][b > side ? 0 : 1];
          if (c != side) ++v.side[side][side > c ? 2 : 3];
        }
        bool left_le = true, right_le = true;
        for (int k = 0; k < 4; ++k) {
          left_le = left_le && v.side[0][k] <= v.side[1][k];
          right_le = right_le && v.side[1][k] <= v.side[0][k];
        }
        if (left_le || right_le) {  // a side no worse in every count
          for (int k = 0; k < 4; ++k) base[k] += v.side[left_le ? 0 : 1][k];
          continue;
        }
        auto same = [&](const Flexible& g) {
          return std::equal(&g.side[0][0], &g.side[0][0] + 8, &v.side[0][0]);
        };
        auto it = std::find_if(flexible.begin(), flexible.end(), same);
        if (it == flexible.end())
          flexible.push_back(v);
        else
          ++it->count;
      }
      total += (xs[j] - xs[j - 1]) * least_crossings(base, flexible);
    }
    best = std::max(best, total);
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
