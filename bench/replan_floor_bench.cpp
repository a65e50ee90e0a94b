// The floor of a replan after a change to the *set of things* (an object
// added or removed) on 3-block-tray with the `euclid` model: what even a
// perfect heuristic cannot avoid. The planning bar asks A* with experience to be 10x
// faster than cold A* on replans; this benchmark measures how fast any A*-type
// replan can be when the change makes a new transition system, so that no
// node of the old product graph is ever reached again.
//
//   BM_FloorRebuild/<change>       a fresh Planner for the changed world and the
//                                  observed state: transition system, labeling,
//                                  symmetry groups (what every replan after such
//                                  a change must build; the cold replan does it too)
//   BM_FloorOracleSearch/<change>  LassoSearch on a fresh product graph of that
//                                  system with the *exact* best-lasso cost V*(n)
//                                  as the heuristic (h = h*: A* then expands only
//                                  nodes of optimal plans); V* comes from a full
//                                  construction and backward Dijkstra, untimed
//   BM_FloorColdAStar/<change>     the cold replan it is compared with: a fresh
//                                  Planner + plan() with A* and the guard heuristic
//
// <change>: 0 add o4 (in r1, r2 or the tray r3, in turn), 1 remove o1/o2/o3.
// floor = rebuild + oracle search; the best possible speed-up of any replan
// that searches = cold / floor. Counters: expansions per replan, plan cost
// (the oracle search must find the cold plan's cost; checked in set-up).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "rtamp/plan/planner.hpp"
#include "rtamp/plan/lasso_search.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using Clock = std::chrono::steady_clock;
using plan::kInf;
using plan::kNoNode;
using plan::NodeId;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

plan::PlannerOptions astar_euclid() {
  plan::PlannerOptions o;
  o.algorithm = plan::Algorithm::AStar;
  o.cost = "euclid";
  return o;
}

// A changed world: the scenario after the change, the observed placement and
// the hand, as a planner holds them after apply().
struct ChangedWorld {
  world::Scenario scenario;
  automata::Automaton automaton;
  world::Placement placement;
  std::string hand;
};

std::vector<ChangedWorld> changed_worlds(int kind) {
  std::vector<ChangedWorld> out;
  std::vector<world::Change> changes;
  if (kind == 0)
    for (const char* l : {"r1", "r2", "r3"}) changes.push_back(world::Change::add_object("o4", "block", l));
  else
    for (const char* o : {"o1", "o2", "o3"}) changes.push_back(world::Change::remove_object(o));
  for (const auto& c : changes) {
    plan::Planner p(world::load_scenario("3-block-tray"), astar_euclid());
    (void)p.plan();
    p.apply(c, plan::Planner::ChangeOrigin::Observed);  // what a person did, as the loop sees it
    out.push_back({p.scenario(), p.automaton(), p.placement(), p.hand()});
  }
  return out;
}

// h = V*: the exact cost of the best lasso from each node, looked up in a
// fully constructed product graph of the same system (same state encoding).
class OracleHeuristic final : public plan::Heuristic {
 public:
  OracleHeuristic(const plan::ProductGraph& full, std::vector<double> v) : full_(&full), v_(std::move(v)) {}
  std::string name() const override { return "oracle"; }
  double estimate(const plan::ProductGraph& g, NodeId n) override {
    const NodeId m = full_->find(g.state(n), g.ba_state(n));
    return m == kNoNode ? kInf : v_[m];
  }

 private:
  const plan::ProductGraph* full_;
  std::vector<double> v_;
};

// V*(n) = min over accepting a of dist(n, a) + cycle(a), cycle(a) the cheapest
// cycle (>= 1 edge) through a: Dijkstra from every accepting node for its
// cycle, then one backward multi-source Dijkstra.
std::vector<double> exact_lasso_values(plan::ProductGraph& g) {
  const std::size_t n = g.size();
  std::vector<std::vector<std::pair<NodeId, double>>> rev(n), fwd(n);
  for (NodeId u = 0; u < n; ++u) {
    g.expand(u);
    for (auto e = g.edge_begin(u); e < g.edge_end(u); ++e) {
      const auto& ed = g.edge(e);
      fwd[u].push_back({ed.dst, ed.cost});
      rev[ed.dst].push_back({u, ed.cost});
    }
  }
  using Item = std::pair<double, NodeId>;
  auto dijkstra = [&](const auto& adj, std::vector<double>& d) {
    std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
    for (NodeId u = 0; u < n; ++u)
      if (d[u] < kInf) pq.push({d[u], u});
    while (!pq.empty()) {
      auto [du, u] = pq.top();
      pq.pop();
      if (du > d[u]) continue;
      for (auto [v, c] : adj[u])
        if (du + c < d[v]) pq.push({d[v] = du + c, v});
    }
  };
  std::vector<double> v(n, kInf);
  for (NodeId a = 0; a < n; ++a) {
    if (!g.accepting(a)) continue;
    std::vector<double> d(n, kInf);
    for (auto [s, c] : fwd[a]) d[s] = std::min(d[s], c);
    dijkstra(fwd, d);
    v[a] = d[a];  // the cheapest path a -> ... -> a with at least one edge
  }
  dijkstra(rev, v);
  return v;
}

struct FloorCase {
  ChangedWorld world;
  std::unique_ptr<plan::Planner> oracle_planner;  // owns the TS and labeling the oracle graph uses
  std::unique_ptr<plan::ProductGraph> full;
  std::vector<double> v;
  double cold_cost = 0;
};

std::vector<FloorCase>& floor_cases(int kind) {
  static std::vector<FloorCase> cases[2];
  if (!cases[kind].empty()) return cases[kind];
  for (auto& w : changed_worlds(kind)) {
    FloorCase c;
    c.world = w;
    plan::Planner cold(w.scenario, w.automaton, astar_euclid());
    cold.set_placement(w.placement, w.hand);
    const auto r = cold.plan();
    if (!r.found) throw std::runtime_error("floor bench: the changed world has no plan");
    c.cold_cost = r.plan.cost();
    c.oracle_planner = std::make_unique<plan::Planner>(w.scenario, w.automaton, astar_euclid());
    c.oracle_planner->set_placement(w.placement, w.hand);
    const auto& ts = c.oracle_planner->system();
    c.full = std::make_unique<plan::ProductGraph>(ts, c.oracle_planner->labeling(), c.oracle_planner->automaton(),
                                                  c.oracle_planner->model(), nullptr);
    const NodeId init = c.full->find_or_add(ts.canonical(c.oracle_planner->state()), w.automaton.initial);
    c.full->expand_all(init, 50'000'000, 0);
    c.v = exact_lasso_values(*c.full);
    if (std::abs(c.v[init] - c.cold_cost) > 1e-9)
      throw std::runtime_error("floor bench: V*(init) differs from the cold plan's cost");
    cases[kind].push_back(std::move(c));
  }
  return cases[kind];
}

const char* kind_name(int kind) { return kind == 0 ? "add" : "remove"; }

void BM_FloorRebuild(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  auto& cases = floor_cases(kind);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& w = cases[i++ % cases.size()].world;
    const auto t0 = Clock::now();
    plan::Planner p(w.scenario, w.automaton, astar_euclid());
    p.set_placement(w.placement, w.hand);
    benchmark::DoNotOptimize(p.state());
    state.SetIterationTime(since(t0));
  }
  state.SetLabel(kind_name(kind));
}
BENCHMARK(BM_FloorRebuild)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMicrosecond);

void BM_FloorOracleSearch(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  auto& cases = floor_cases(kind);
  std::size_t i = 0;
  double expanded = 0, runs = 0;
  for (auto _ : state) {
    auto& c = cases[i++ % cases.size()];
    plan::Planner& p = *c.oracle_planner;
    OracleHeuristic h(*c.full, c.v);
    const auto t0 = Clock::now();
    plan::ProductGraph g(p.system(), p.labeling(), p.automaton(), p.model(), nullptr);
    plan::LassoSearch ls;
    plan::Experience x;
    plan::SearchStats stats;
    const NodeId init = g.find_or_add(p.system().canonical(p.state()), p.automaton().initial);
    const auto r = ls.run(g, x, init, h, plan::LassoConfig{}, plan::Termination{}, stats);
    state.SetIterationTime(since(t0));
    if (!r.found || std::abs(r.prefix_cost + r.cycle_cost - c.cold_cost) > 1e-9)
      state.SkipWithError("the oracle search did not find the optimal cost");
    expanded += double(stats.expanded);
    runs += 1;
  }
  state.counters["expanded"] = expanded / runs;
  state.SetLabel(kind_name(kind));
}
BENCHMARK(BM_FloorOracleSearch)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMicrosecond);

void BM_FloorColdAStar(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  auto& cases = floor_cases(kind);
  std::size_t i = 0;
  double expanded = 0, runs = 0;
  for (auto _ : state) {
    const auto& w = cases[i++ % cases.size()].world;
    const auto t0 = Clock::now();
    plan::Planner p(w.scenario, w.automaton, astar_euclid());
    p.set_placement(w.placement, w.hand);
    const auto r = p.plan();
    state.SetIterationTime(since(t0));
    expanded += double(r.stats.expanded);
    runs += 1;
  }
  state.counters["expanded"] = expanded / runs;
  state.SetLabel(kind_name(kind));
}
BENCHMARK(BM_FloorColdAStar)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
