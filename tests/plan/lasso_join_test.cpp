// Lassos optimal for the task, not for one automaton: on small random
// patrol scenarios (conjunctions of G F of propositions, with and without an
// F G or F part) the planner's cost equals a brute-force search over the
// transition system itself — every TS lasso u·v^ω (moves only, or a cycle
// that stays), cost-pruned, checked by the direct LTL semantics
// (ltl/lasso.hpp) — and both spellings of a conjunction (halves swapped)
// cost the same.
#include <gtest/gtest.h>

#include "plan_checks.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

struct TsOracle {
  const world::Scenario* sc;
  const ltl::Formula* f;
  const automata::Automaton* ba;
  std::string model;
  oracle::World w;
  std::vector<oracle::St> states;
  std::vector<ltl::LassoWord::Letter> labels;
  double best = INFINITY;
  std::uint64_t lassos = 0;
  int max_moves;

  TsOracle(const world::Scenario& s, const ltl::Formula& formula, const automata::Automaton& a, std::string m,
           int max_moves_)
      : sc(&s), f(&formula), ba(&a), model(std::move(m)), w(s), max_moves(max_moves_) {
    w.find_groups(a.atoms);
  }
  ltl::LassoWord::Letter names(const oracle::St& s) const {
    const automata::Letter l = oracle::label(w, s, *ba);
    ltl::LassoWord::Letter out;
    for (std::size_t i = 0; i < ba->atoms.size(); ++i)
      if ((l >> i) & 1) out.insert(ba->atoms[i]);
    return out;
  }
  std::vector<automata::Letter> letters;  // the path's labels as automaton letters
  automata::LassoWord best_word;          // the best lasso's label word
  bool accepts(std::size_t j, bool stay) {
    ++lassos;
    ltl::LassoWord lw;
    lw.prefix.assign(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(j));
    if (stay) lw.cycle = {labels.back()};
    else lw.cycle.assign(labels.begin() + static_cast<std::ptrdiff_t>(j), labels.end() - 1);
    if (!ltl::holds(*f, lw)) return false;
    best_word.prefix.assign(letters.begin(), letters.begin() + static_cast<std::ptrdiff_t>(j));
    if (stay) best_word.cycle = {letters.back()};
    else best_word.cycle.assign(letters.begin() + static_cast<std::ptrdiff_t>(j), letters.end() - 1);
    return true;
  }
  // states/labels hold the path so far (labels[i] = L(states[i])).
  void dfs(double cost) {
    const std::size_t k = states.size() - 1;
    if (cost < best - 1e-9 && accepts(k, true)) best = cost;  // u = path, v = stay at its end
    const oracle::St end = oracle::canonical(w, states.back());
    for (std::size_t j = 0; j < k && cost < best - 1e-9; ++j)
      if (oracle::canonical(w, states[j]) == end && accepts(j, false)) best = cost;
    if (static_cast<int>(k) >= max_moves) return;
    for (auto [t, to] : oracle::moves(w, states.back())) {
      const double c = cost + oracle::move_cost(w, states.back(), t, to, model);
      if (c >= best - 1e-9) continue;
      oracle::St s2 = states.back();
      s2.loc[static_cast<std::size_t>(t)] = to;
      s2.hand = to;
      states.push_back(s2);
      labels.push_back(names(s2));
      letters.push_back(oracle::label(w, s2, *ba));
      dfs(c);
      states.pop_back();
      labels.pop_back();
      letters.pop_back();
    }
  }
  // The cheapest lasso costing below `upper` (INFINITY if none).
  double run(const world::Placement& p, const std::string& hand, double upper) {
    best = upper;
    states = {oracle::start(w, p, hand)};
    labels = {names(states[0])};
    letters = {oracle::label(w, states[0], *ba)};
    best_word = {};
    dfs(0);
    return best;
  }
};

// A random patrol scenario: 2-3 regions, 1-2 blocks, no container.
world::Scenario patrol_scenario(std::mt19937& rng, const std::string& task) {
  static const std::vector<std::string> kFormulas = {"G F a"};
  world::Scenario sc = random_scenario(rng, kFormulas);
  while (!sc.containers.empty() || sc.regions.size() > 3 || sc.objects.size() > 2)
    sc = random_scenario(rng, kFormulas);
  sc.task = task;
  std::set<std::string> atoms;
  collect_atoms(ltl::parse(task), atoms);
  sc.propositions.clear();
  const auto R = static_cast<unsigned>(sc.regions.size());
  const auto N = static_cast<unsigned>(sc.objects.size());
  auto rname = [&]() { return "r" + std::to_string(1 + rng() % R); };
  for (const auto& a : atoms) {
    std::string text;
    switch (rng() % 4) {
      case 0: text = "all block in " + rname(); break;
      case 1: text = "any block in " + rname(); break;
      case 2: text = "!(o1 in " + rname() + ")"; break;
      default: text = "o" + std::to_string(1 + rng() % N) + " in " + rname(); break;
    }
    sc.propositions.push_back(proposition(a, text));
  }
  return sc;
}

struct Spelled {
  std::string one, swapped;
};
const Spelled kTasks[] = {
    {"G F a & G F b", "G F b & G F a"},
    {"G F a & G F b & G F c", "G F c & G F b & G F a"},
    {"G F a & G F b & F c", "F c & G F b & G F a"},
    {"G F a & F G b", "F G b & G F a"},
    {"G F a & G F b & F G c", "F G c & G F b & G F a"},
};

TEST(LassoJoin, PatrolCostsEqualTheBestTsLasso) {
  std::mt19937 rng(606);
  const char* models[] = {"euclid", "unit"};
  int found = 0, improved = 0, equal = 0, several_turns = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const Spelled& task = kTasks[trial % 5];
    const std::string model = models[(trial / 5) % 2];
    const world::Scenario sc = patrol_scenario(rng, task.one);
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    world::Scenario swapped = sc;
    swapped.task = task.swapped;
    double cost = -1;
    for (auto algo : {plan::Algorithm::Dijkstra, plan::Algorithm::AStar, plan::Algorithm::AStarExperience}) {
      SCOPED_TRACE(plan::to_string(algo));
      plan::PlannerOptions opt;
      opt.algorithm = algo;
      opt.cost = model;
      plan::Planner p(sc, opt), q(swapped, opt);
      const plan::PlanResult r = p.plan(), rq = q.plan();
      ASSERT_EQ(r.found, rq.found);
      if (r.found) {
        EXPECT_NEAR(rq.plan.cost(), r.plan.cost(), 1e-6) << "the two spellings differ";
        check_plan(p, r, model);
        check_plan(q, rq, model);
      }
      if (algo != plan::Algorithm::Dijkstra) {
        if (r.found) {
          EXPECT_NEAR(r.plan.cost(), cost, 1e-6);
        }
        continue;
      }
      // Once per scenario: the TS brute force (every cheaper TS lasso).
      TsOracle ts(p.scenario(), p.formula(), p.automaton(), model, 8);
      const double want = ts.run(p.placement(), p.hand(), r.found ? r.plan.cost() + 1e-6 : INFINITY);
      if (!r.found) {
        EXPECT_EQ(want, INFINITY) << "the TS has a lasso the planner did not find";
        continue;
      }
      cost = r.plan.cost();
      ++found;
      const auto old = oracle::min_lasso(p.scenario(), p.placement(), p.hand(), p.automaton(), model, true, {}, false);
      if (old && *old > cost + 1e-6) ++improved;
      EXPECT_LE(want, cost + 1e-6);
      if (want >= cost - 1e-6) {
        ++equal;
      } else {
        // A cheaper TS lasso u·v^ω exists only when the automaton needs more
        // than one turn of v to come back to the state it entered v in: then
        // it is no lasso of the product (the planner's cycle would be v
        // repeated, at several times the cost).
        EXPECT_FALSE(product_lasso(p.automaton(), p.automaton().initial, ts.best_word, true))
            << "the planner missed a cheaper product lasso: TS " << want << " planner " << cost;
        ++several_turns;
      }
    }
  }
  std::printf("%d scenarios with a plan, %d cheaper than the old lasso shape, %d equal to the TS optimum, %d need "
              "several turns of the TS cycle\n",
              found, improved, equal, several_turns);
  EXPECT_GT(found, 50);
  EXPECT_GT(improved, 5);  // the old lasso shape (cycle through the prefix's accepting node) cost more there
  EXPECT_GT(equal, found - 5) << several_turns << " scenarios need several turns of the TS cycle";
}

}  // namespace
