// The planner obeys the transition system's move rules beyond capacities:
// footprints (a tray bigger than a region is never planned into it) and
// moves forbidden after a physical failure (Planner::forbid_move). Plans are
// checked against a brute-force optimum over the TS itself (its enabled moves,
// no symmetry), with the oracle's cost formulas and the world layer's labels.
#include <gtest/gtest.h>

#include <map>
#include <queue>

#include "plan_checks.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;

// Minimum lasso cost over the product of `ts` (every enabled move) and the automaton.
std::optional<double> brute_force(const task::System& ts, const automata::Automaton& ba, const std::string& model) {
  const oracle::World w(ts.scenario());
  auto to_oracle = [&](const task::State& s) {
    oracle::St o;
    for (unsigned t = 0; t < ts.num_things(); ++t) o.loc.push_back(static_cast<int>(ts.location(s, t)));
    o.hand = ts.hand(s) == ts.home() ? -1 : static_cast<int>(ts.hand(s));
    return o;
  };
  std::vector<std::pair<task::State, std::uint32_t>> nodes;
  std::map<std::pair<std::array<std::uint64_t, task::kStateWords>, std::uint32_t>, int> index;
  std::vector<std::vector<std::pair<int, double>>> adj;
  auto id = [&](const task::State& s, std::uint32_t q) {
    auto [it, added] = index.emplace(std::make_pair(s.words, q), static_cast<int>(nodes.size()));
    if (added) {
      nodes.emplace_back(s, q);
      adj.emplace_back();
    }
    return it->second;
  };
  id(ts.initial(), ba.initial);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const auto s = nodes[n].first;  // (not a structured binding: the lambdas below capture it)
    const auto q = nodes[n].second;
    const oracle::St os = to_oracle(s);
    const auto l = oracle::label(w, os, ba);
    for (const auto& e : ba.edges[q]) {
      if (!e.guard.matches(l)) continue;
      std::vector<std::pair<int, double>> out{{id(s, e.dst), 0.0}};
      ts.for_each_move(s, [&](const task::Action& a) {
        out.emplace_back(id(ts.successor(s, a), e.dst), oracle::move_cost(w, os, a.thing, a.to, model));
      });
      for (const auto& x : out) adj[n].push_back(x);
    }
  }
  auto dijkstra = [&](int src, bool skip_src) {
    std::vector<double> d(nodes.size(), INFINITY);
    using QI = std::pair<double, int>;
    std::priority_queue<QI, std::vector<QI>, std::greater<QI>> pq;
    if (skip_src) {
      for (auto [m, c] : adj[static_cast<std::size_t>(src)])
        if (c < d[static_cast<std::size_t>(m)]) pq.push({d[static_cast<std::size_t>(m)] = c, m});
    } else {
      pq.push({d[static_cast<std::size_t>(src)] = 0, src});
    }
    while (!pq.empty()) {
      auto [dv, v] = pq.top();
      pq.pop();
      if (dv > d[static_cast<std::size_t>(v)] || (skip_src && v == src)) continue;
      for (auto [m, c] : adj[static_cast<std::size_t>(v)])
        if (dv + c < d[static_cast<std::size_t>(m)]) pq.push({d[static_cast<std::size_t>(m)] = dv + c, m});
    }
    return d;
  };
  const auto d0 = dijkstra(0, false);
  double best = INFINITY;
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (ba.is_accepting_state(nodes[n].second) && d0[n] < best)
      best = std::min(best, d0[n] + dijkstra(static_cast<int>(n), true)[n]);
  if (best == INFINITY) return std::nullopt;
  return best;
}

// The TS the planner plans over, rebuilt independently: current state, forbidden moves, no symmetry.
task::System current_ts(plan::Planner& p) {
  task::System ts(p.scenario(), p.placement(), p.hand());
  ts.forbid_moves(p.forbidden_moves());
  return ts;
}

std::vector<std::string> steps(plan::Planner& p, const plan::Plan& pl) {
  std::vector<std::string> out;
  for (const auto* part : {&pl.prefix, &pl.cycle})
    for (const auto& st : *part) out.push_back(p.describe(st.action));
  return out;
}

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

TEST(MoveRules, ATrayBiggerThanARegionIsNeverPlannedIntoIt) {
  world::Scenario sc = world::load_scenario("3-block-tray");
  plan::Planner roomy(sc);
  const auto r0 = roomy.plan();
  ASSERT_TRUE(r0.found);
  ASSERT_TRUE(contains(steps(roomy, r0.plan), "move(r3, r2)"));  // the tray is worth carrying...

  sc.regions[1].size = {0.28, 0.28, 0};  // ... but a 30 x 16 cm tray does not fit 28 x 28 cm
  plan::Planner tight(sc);
  const auto r = tight.plan();
  ASSERT_TRUE(r.found) << r.message;
  EXPECT_FALSE(contains(steps(tight, r.plan), "move(r3, r2)"));
  EXPECT_GT(r.plan.cost(), r0.plan.cost() + 1e-9);
  const auto best = brute_force(current_ts(tight), tight.automaton(), "euclid");
  ASSERT_TRUE(best);
  EXPECT_NEAR(r.plan.cost(), *best, 1e-9);
  plantest::check_plan(tight, r, "euclid");
}

TEST(MoveRules, AForbiddenMoveIsNotPlannedAndTheNewPlanIsOptimal) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  const auto r0 = p.plan();
  ASSERT_TRUE(r0.found);
  ASSERT_FALSE(r0.plan.prefix.empty());
  const task::Action first = r0.plan.prefix.front().action;
  const std::string thing = p.system().thing_name(first.thing), loc = p.system().location_name(first.to);
  EXPECT_NEAR(r0.plan.cost(), *brute_force(current_ts(p), p.automaton(), "euclid"), 1e-9);

  p.forbid_move(thing, loc);
  p.forbid_move(thing, loc);  // listed once
  ASSERT_EQ(p.forbidden_moves().size(), 1u);
  const auto r1 = p.plan();
  ASSERT_TRUE(r1.found) << r1.message;
  const std::string banned = "move(" + thing + ", " + loc + ")";
  EXPECT_FALSE(contains(steps(p, r1.plan), banned)) << banned;
  EXPECT_TRUE(p.system().forbidden(first.thing, first.to));
  const auto best = brute_force(current_ts(p), p.automaton(), "euclid");
  ASSERT_TRUE(best);
  EXPECT_NEAR(r1.plan.cost(), *best, 1e-9);
  EXPECT_GE(r1.plan.cost(), r0.plan.cost() - 1e-9);

  // Forbid every block's moves into the tray: both plans so far used it.
  for (const char* b : {"o1", "o2", "o3"}) p.forbid_move(b, "r3");
  const auto r2 = p.plan();
  ASSERT_TRUE(r2.found) << r2.message;
  for (const std::string& st : steps(p, r2.plan)) EXPECT_EQ(st.find(", r3)"), std::string::npos) << st;
  EXPECT_NEAR(r2.plan.cost(), *brute_force(current_ts(p), p.automaton(), "euclid"), 1e-9);
  EXPECT_GT(r2.plan.cost(), r1.plan.cost() + 1e-9);
  // And o1's only way left to r2: no plan, as the brute force agrees.
  p.forbid_move("o1", "r2");
  const auto r4 = p.plan();
  EXPECT_FALSE(r4.found);
  EXPECT_FALSE(brute_force(current_ts(p), p.automaton(), "euclid"));

  p.clear_forbidden_moves();
  EXPECT_TRUE(p.forbidden_moves().empty());
  const auto r3 = p.plan();
  ASSERT_TRUE(r3.found);
  EXPECT_NEAR(r3.plan.cost(), r0.plan.cost(), 1e-9);
}

TEST(MoveRules, ForbiddenMovesPersistAcrossRebuildsByName) {
  plan::Planner p(world::load_scenario("3-block-tray"));
  p.forbid_move("o2", "r3");
  p.forbid_move("ghost", "r2");  // unknown: ignored by the TS, kept in the list
  EXPECT_TRUE(p.system().forbidden(1, static_cast<unsigned>(p.system().find_location("r3"))));
  constexpr auto kObserved = plan::Planner::ChangeOrigin::Observed;  // r1 is full: a person overfilled it
  p.apply(world::Change::add_object("o4", "block", "r1"), kObserved);  // rebuilds the TS
  const auto& ts = p.system();
  EXPECT_TRUE(ts.forbidden(static_cast<unsigned>(ts.find_thing("o2")), static_cast<unsigned>(ts.find_location("r3"))));
  EXPECT_EQ(ts.forbidden_moves().size(), 1u);
  p.apply(world::Change::remove_object("o2"), kObserved);  // gone: nothing to forbid
  EXPECT_TRUE(p.system().forbidden_moves().empty());
  EXPECT_EQ(p.forbidden_moves().size(), 2u);
  p.apply(world::Change::add_object("o2", "block", "r1"), kObserved);  // back: forbidden again
  EXPECT_EQ(p.system().forbidden_moves().size(), 1u);
  const auto r = p.plan();
  ASSERT_TRUE(r.found);
  EXPECT_FALSE(contains(steps(p, r.plan), "move(o2, r3)"));
  EXPECT_NEAR(r.plan.cost(), *brute_force(current_ts(p), p.automaton(), "euclid"), 1e-9);
}

}  // namespace
