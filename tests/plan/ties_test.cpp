// Ties in cost go to fewer moves: every search minimises (cost, number of
// moves) lexicographically. Checked against the brute force in the same
// order (oracle::min_lasso_lex) on random scenarios, all algorithms, both
// graph constructions, the three models and experience replans, and on the
// built-in 3-block-tray scenario; and no plan holds a pair of consecutive
// moves of one thing that puts it back where it was (e.g. with `region`, a
// zero-cost move(o1, t1), move(o1, r1) while t1 stands in r1) unless removing
// the pair breaks the plan (illegal, not accepted, cycle not closed, or dearer).
#include <gtest/gtest.h>

#include "plan_checks.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using namespace plantest;

int moves_of(const plan::Plan& p) {
  int n = 0;
  for (const auto* part : {&p.prefix, &p.cycle})
    for (const auto& st : *part) n += st.action.is_stay() ? 0 : 1;
  return n;
}

struct Act {
  int thing = -1, to = -1;  // oracle indices; thing -1: stay
};

// Replays prefix and cycle by the oracle's rules; the total cost, or nullopt
// if the actions are illegal, the cycle does not return to its start or the
// word is no lasso of the product from q0 (plan_checks.hpp, product_lasso).
std::optional<double> replay(plan::Planner& planner, const std::vector<Act>& prefix, std::vector<Act> cycle,
                             const std::string& model, std::uint32_t q0) {
  const auto& ba = planner.automaton();
  oracle::World w(planner.scenario());
  w.find_groups(ba.atoms);
  oracle::St s = oracle::start(w, planner.placement(), planner.hand());
  if (cycle.empty()) cycle.push_back({});
  automata::LassoWord word;
  double total = 0;
  auto run = [&](const std::vector<Act>& acts, std::vector<automata::Letter>& letters) {
    for (const Act& a : acts) {
      letters.push_back(oracle::label(w, s, ba));
      if (a.thing < 0) continue;
      const auto legal = oracle::moves(w, s);
      if (std::find(legal.begin(), legal.end(), std::make_pair(a.thing, a.to)) == legal.end()) return false;
      total += oracle::move_cost(w, s, a.thing, a.to, model);
      s.loc[static_cast<std::size_t>(a.thing)] = a.to;
      s.hand = a.to;
    }
    return true;
  };
  if (!run(prefix, word.prefix)) return std::nullopt;
  const oracle::St start = s;
  if (!run(cycle, word.cycle)) return std::nullopt;
  if (!(oracle::canonical(w, s) == oracle::canonical(w, start))) return std::nullopt;
  if (!product_lasso(ba, q0, word, true)) return std::nullopt;
  return total;
}

// "" if the plan has no removable back-and-forth pair, else a description.
std::string removable_back_and_forth(plan::Planner& planner, const plan::PlanResult& r, const std::string& model) {
  const task::System& ts = planner.system();
  oracle::World w(planner.scenario());
  oracle::St s = oracle::start(w, planner.placement(), planner.hand());
  std::vector<Act> parts[2];
  std::vector<int> from_loc[2];  // the thing's location before each move
  const std::vector<plan::Step>* steps[2] = {&r.plan.prefix, &r.plan.cycle};
  for (int k = 0; k < 2; ++k)
    for (const auto& st : *steps[k]) {
      Act a;
      if (!st.action.is_stay()) {
        a.thing = static_cast<int>(st.action.thing);
        a.to = w.loc_index(ts.location_name(st.action.to));
      }
      from_loc[k].push_back(a.thing < 0 ? -1 : s.loc[static_cast<std::size_t>(a.thing)]);
      if (a.thing >= 0) {
        s.loc[static_cast<std::size_t>(a.thing)] = a.to;
        s.hand = a.to;
      }
      parts[k].push_back(a);
    }
  const std::uint32_t q0 = r.plan.prefix.empty() ? r.plan.cycle.front().ba_from : r.plan.prefix.front().ba_from;
  for (int k = 0; k < 2; ++k) {
    auto& acts = parts[k];
    for (std::size_t i = 0; i < acts.size(); ++i) {
      if (acts[i].thing < 0) continue;
      std::size_t j = i + 1;
      while (j < acts.size() && acts[j].thing < 0) ++j;  // the next move
      if (j == acts.size() || acts[j].thing != acts[i].thing || acts[j].to != from_loc[k][i]) continue;
      std::vector<Act> cut = acts;
      cut.erase(cut.begin() + static_cast<std::ptrdiff_t>(j));
      cut.erase(cut.begin() + static_cast<std::ptrdiff_t>(i));
      const auto c = k == 0 ? replay(planner, cut, parts[1], model, q0) : replay(planner, parts[0], cut, model, q0);
      if (c && *c <= r.plan.cost() + 1e-9)
        return std::string(k == 0 ? "prefix" : "cycle") + " steps " + std::to_string(i) + "," + std::to_string(j) +
               ": " + ts.action_name(steps[k]->at(i).action) + ", " + ts.action_name(steps[k]->at(j).action);
    }
  }
  return "";
}

void check_ties(plan::Planner& p, const plan::PlanResult& r, const std::string& model) {
  const auto want = oracle::min_lasso_lex(p.scenario(), p.placement(), p.hand(), p.automaton(), model);
  ASSERT_EQ(r.found, want.has_value()) << r.message;
  if (!r.found) return;
  EXPECT_NEAR(r.plan.cost(), want->first, 1e-6);
  EXPECT_EQ(moves_of(r.plan), want->second) << "cost " << r.plan.cost();
  EXPECT_EQ(removable_back_and_forth(p, r, model), "");
  check_plan(p, r, model);
}

const plan::Algorithm kAlgos[] = {plan::Algorithm::Dijkstra, plan::Algorithm::AStar,
                                  plan::Algorithm::AStarExperience};
const char* kModels[] = {"euclid", "region", "unit"};

TEST(Ties, TrayScenarioPlansHaveTheFewestMovesAmongCheapest) {
  for (const char* model : kModels)
    for (auto algo : kAlgos) {
      SCOPED_TRACE(std::string(model) + " " + plan::to_string(algo));
      plan::PlannerOptions opt;
      opt.algorithm = algo;
      opt.cost = model;
      plan::Planner p(world::load_scenario("3-block-tray"), opt);
      check_ties(p, p.plan(), model);
      // From other states too: the tray carrying a block, blocks spread.
      p.apply(world::Change::relocate("o1", "r3"), plan::Planner::ChangeOrigin::Observed);  // into the tray
      check_ties(p, p.plan(), model);
      p.apply(world::Change::relocate("o2", "r2"), plan::Planner::ChangeOrigin::Observed);
      check_ties(p, p.plan(), model);
    }
}

TEST(Ties, RandomScenariosAllStrategies) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(31337);
  int found = 0, trays = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    const std::string model = kModels[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    if (!sc.containers.empty()) ++trays;
    for (auto algo : kAlgos)
      for (auto graph : {plan::GraphConstruction::Partial, plan::GraphConstruction::Full}) {
        SCOPED_TRACE(std::string(plan::to_string(algo)) + "/" + plan::to_string(graph));
        plan::PlannerOptions opt;
        opt.algorithm = algo;
        opt.graph = graph;
        opt.cost = model;
        plan::Planner p(sc, opt);
        const plan::PlanResult r = p.plan();
        check_ties(p, r, model);
        found += r.found;
      }
  }
  EXPECT_GT(found, 600);
  EXPECT_GT(trays, 50);
}

TEST(Ties, ExperienceReplans) {
  const auto formulas = robot_patterns();
  std::mt19937 rng(2718);
  int checked = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const world::Scenario sc = random_scenario(rng, formulas);
    const std::string model = kModels[trial % 3];
    SCOPED_TRACE("trial " + std::to_string(trial) + " task " + sc.task + " model " + model);
    plan::PlannerOptions opt;
    opt.cost = model;
    plan::Planner p(sc, opt);
    plan::PlanResult r = p.plan();
    for (int k = 0; k < 8; ++k) {
      if (rng() % 2 == 0 && r.found && !r.plan.prefix.empty()) {
        p.execute(r.plan.prefix.front().action);
      } else {
        const auto& cur = p.scenario();
        std::vector<std::string> locs;
        for (const auto& reg : cur.regions) locs.push_back(reg.name);
        for (const auto& c : cur.containers) locs.push_back(c.name);
        const std::string thing = cur.objects[rng() % cur.objects.size()].name;  // one draw per statement
        p.apply(world::Change::relocate(thing, locs[rng() % locs.size()]), plan::Planner::ChangeOrigin::Observed);
      }
      SCOPED_TRACE("query " + std::to_string(k));
      r = p.plan();
      check_ties(p, r, model);
      ++checked;
    }
  }
  EXPECT_GT(checked, 900);
}

}  // namespace
