// Shared test helpers: random small scenarios and an independent validity
// check of a plan (legal actions by the oracle's rules, costs recomputed, the
// lasso's label word accepted by the automaton and by the direct LTL
// semantics).
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <set>

#include "oracle.hpp"
#include "rtamp/automata/lasso_accept.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp_source_dir.hpp"

namespace plantest {

using namespace rtamp;

inline std::vector<std::string> robot_patterns() {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/robot-patterns.ltl");
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

inline void collect_atoms(const ltl::Formula& f, std::set<std::string>& out) {
  if (f.is(ltl::Op::Atom)) out.insert(f.name());
  for (const auto& c : f.children()) collect_atoms(c, out);
}

inline world::Region region(const std::string& name, double x, double y, int cap) {
  world::Region r;
  r.name = name;
  r.center = {x, y, 0};
  r.size = {0.3, 0.3, 0};  // a default tray (0.24 x 0.16) and everything else fits: footprints never bind
  r.capacity = cap;
  return r;
}

inline world::Proposition proposition(const std::string& name, const std::string& text) {
  world::Proposition p;
  p.name = name;
  p.text = text;
  p.expr = world::parse_prop_expr(text);
  return p;
}

// A random scenario with 2-4 regions, 1-4 blocks, maybe a tray, and a task
// from the robot pattern set whose atoms are random proposition expressions.
inline world::Scenario random_scenario(std::mt19937& rng, const std::vector<std::string>& formulas) {
  for (;;) {
    world::Scenario sc;
    sc.name = "random";
    const int R = 2 + static_cast<int>(rng() % 3);
    const int N = 1 + static_cast<int>(rng() % 4);
    const int C = rng() % 3 == 0 ? 1 : 0;
    double states = std::pow(R + C, N) * std::pow(R, C) * (R + C + 1);
    if (states > 2000) continue;
    std::uniform_real_distribution<double> U(-0.6, 0.6);
    for (int i = 0; i < R; ++i) {
      const int cap = 1 + static_cast<int>(rng() % (N + C + 1));
      // One draw per statement, y first: the same scenarios from every compiler (the
      // order of a call's arguments is unspecified; this is the order gcc chose).
      const double y = std::round(U(rng) * 20) / 20 + 0.3 * i;
      const double x = 0.4 + std::round(U(rng) * 20) / 20;
      sc.regions.push_back(region("r" + std::to_string(i + 1), x, y, cap));
    }
    for (int i = 0; i < C; ++i) {
      world::Container c;
      c.name = "t1";
      c.capacity = 1 + static_cast<int>(rng() % 3);
      c.position = sc.regions[1].center;
      sc.containers.push_back(c);
    }
    for (int i = 0; i < N; ++i) {
      world::Object o;
      o.name = "o" + std::to_string(i + 1);
      o.position = sc.regions[0].center;
      sc.objects.push_back(o);
    }
    sc.task = formulas[rng() % formulas.size()];
    std::set<std::string> atoms;
    collect_atoms(ltl::parse(sc.task), atoms);
    auto rname = [&]() { return "r" + std::to_string(1 + rng() % static_cast<unsigned>(R)); };
    for (const auto& a : atoms) {
      std::string text;
      switch (rng() % 7) {
        case 0: text = "all block in " + rname(); break;
        case 1: text = "any block in " + rname(); break;
        case 2: {
          const std::string n = std::to_string(1 + rng() % 2);
          text = "count block in " + rname() + " >= " + n;
          break;
        }
        case 3: text = "!(o1 in " + rname() + ")"; break;
        case 4:
          if (C) {
            text = "o1 in t1 | t1 in " + rname();
          } else {
            const std::string second = rname();
            text = "o1 in " + rname() + " & all block in " + second;
          }
          break;
        default: {
          const std::string where = rname();
          text = "o" + std::to_string(1 + rng() % static_cast<unsigned>(N)) + " in " + where;
          break;
        }
      }
      sc.propositions.push_back(proposition(a, text));
    }
    return sc;
  }
}

// Is prefix·cycle a lasso of the product from automaton state q0: some run
// reads the prefix into a state q from which the cycle's letters lead back to
// q, with q accepting (join_anywhere false: the cycle starts and ends at an
// accepting node) or through an accepting state somewhere on the cycle
// (join_anywhere true)? (Weaker than automata::lasso_accept, which also takes
// runs that need several turns of the cycle to close.)
inline bool product_lasso(const automata::Automaton& ba, std::uint32_t q0, const automata::LassoWord& w,
                          bool join_anywhere) {
  const std::uint32_t n = ba.num_states();
  std::vector<bool> cur(n, false);
  cur[q0] = true;
  for (automata::Letter l : w.prefix) {
    std::vector<bool> next(n, false);
    for (std::uint32_t q = 0; q < n; ++q)
      if (cur[q])
        for (const auto& e : ba.edges[q])
          if (e.guard.matches(l)) next[e.dst] = true;
    cur = next;
  }
  for (std::uint32_t q = 0; q < n; ++q) {
    if (!cur[q] || (!join_anywhere && !ba.is_accepting_state(q))) continue;
    std::vector<std::uint8_t> at(n, 0);  // bit 0: reached, no accepting state yet; bit 1: reached after one
    at[q] = 1;
    for (automata::Letter l : w.cycle) {
      std::vector<std::uint8_t> next(n, 0);
      for (std::uint32_t p = 0; p < n; ++p) {
        if (!at[p]) continue;
        const std::uint8_t seen = ba.is_accepting_state(p) ? 2 : at[p];
        for (const auto& e : ba.edges[p])
          if (e.guard.matches(l)) next[e.dst] |= seen;
      }
      at = next;
    }
    if (at[q] & 2) return true;
  }
  return false;
}

// Puts the planner in a random state: every thing somewhere legal, the hand
// anywhere (or at home). Returns the placement and the hand.
inline std::pair<world::Placement, std::string> place_randomly(std::mt19937& rng, plan::Planner& p) {
  const world::Scenario& sc = p.scenario();
  world::Placement pl = p.placement();
  std::vector<std::string> regions, locs;
  for (const auto& r : sc.regions) regions.push_back(r.name);
  locs = regions;
  for (const auto& c : sc.containers) locs.push_back(c.name);
  for (auto& [name, thing] : pl.things) thing.location = thing.container ? regions[rng() % regions.size()] : locs[rng() % locs.size()];
  const std::string hand = rng() % 3 ? locs[rng() % locs.size()] : "";
  p.set_placement(pl, hand);
  return {pl, hand};
}

// h.cycle_bound at node (s, q) of g is at most u, the brute force's cheapest
// accepting cycle through it (+inf: none, nothing checked); counts the checks
// and the positive bounds.
inline void expect_cycle_bound(plan::Heuristic& h, plan::ProductGraph& g, const task::State& s, std::uint32_t q,
                               double u, const std::string& what, int& checked, int& positive) {
  const plan::NodeId node = g.find_or_add(g.system().canonical(s), q);
  if (u == INFINITY || node == plan::kNoNode) return;
  const double cb = h.cycle_bound(g, node);
  EXPECT_LE(cb, u + 1e-9) << what << " q=" << q << " (cycle bound)";
  ++checked;
  positive += cb > 0;
}

// Turns sc's task into a patrol of `goals` (2 or 3) atoms that force every
// block somewhere (the chain bound's case): atom i is "all block in r_j", a
// different region each while there are some.
inline void make_forcing_patrol(world::Scenario& sc, int goals) {
  sc.task = goals == 2 ? "G F a & G F b" : "G F a & G F b & G F c";
  sc.propositions.clear();
  for (std::size_t i = 0; i < 3; ++i)
    sc.propositions.push_back(proposition(std::string(1, static_cast<char>('a' + i)),
                                          "all block in r" + std::to_string(1 + (i + 1) % sc.regions.size())));
}

// Checks r.plan independently; returns the recomputed cost.
inline double check_plan(plan::Planner& planner, const plan::PlanResult& r, const std::string& model) {
  const auto& sc = planner.scenario();
  const auto& ba = planner.automaton();
  oracle::World w(sc);
  w.find_groups(ba.atoms);
  oracle::St s = oracle::start(w, planner.placement(), planner.hand());
  const task::System& ts = planner.system();
  automata::LassoWord word;
  double total = 0;
  oracle::St cycle_start;
  auto run = [&](const std::vector<plan::Step>& steps, std::vector<automata::Letter>& letters) {
    for (const auto& st : steps) {
      const auto l = oracle::label(w, s, ba);
      EXPECT_EQ(l, st.label);
      letters.push_back(l);
      if (!st.action.is_stay()) {
        const int t = w.loc_index(ts.location_name(ts.location(st.from, st.action.thing)));
        (void)t;
        const int thing = static_cast<int>(st.action.thing);
        const int to = w.loc_index(ts.location_name(st.action.to));
        const auto legal = oracle::moves(w, s);
        EXPECT_NE(std::find(legal.begin(), legal.end(), std::make_pair(thing, to)), legal.end())
            << "illegal " << ts.action_name(st.action);
        const double c = oracle::move_cost(w, s, thing, to, model);
        EXPECT_NEAR(c, st.cost, 1e-9);
        total += c;
        s.loc[static_cast<std::size_t>(thing)] = to;
        s.hand = to;
      } else {
        EXPECT_EQ(st.cost, 0.0);
      }
      EXPECT_TRUE(oracle::placement(w, s) == ts.describe(st.to)) << ts.to_string(st.to);
    }
  };
  run(r.plan.prefix, word.prefix);
  cycle_start = s;
  EXPECT_FALSE(r.plan.cycle.empty());
  run(r.plan.cycle, word.cycle);
  EXPECT_TRUE(oracle::canonical(w, s) == oracle::canonical(w, cycle_start))
      << "the cycle does not return to its start (up to interchangeable objects)";
  if (!r.plan.cycle.empty()) {
    EXPECT_EQ(r.plan.cycle.back().ba_to, r.plan.cycle.front().ba_from);
    // The prefix joins the cycle anywhere: the cycle passes an accepting state
    // (transition-based: its steps' edges carry every acceptance set).
    automata::Marks taken = 0;
    for (const plan::Step& st : r.plan.cycle) {
      if (ba.state_based) taken |= ba.is_accepting_state(st.ba_from) ? 1u : 0u;
      else
        for (const auto& e : ba.edges[st.ba_from])
          if (e.dst == st.ba_to && e.guard.matches(st.label)) taken |= ba.cycle_marks(e);
    }
    EXPECT_EQ(taken, ba.cycle_marks_all()) << "the cycle does not take every acceptance set";
    // The plan starts at one of the planner's automaton states, and the
    // automaton started there accepts its word.
    const std::uint32_t q0 = r.plan.prefix.empty() ? r.plan.cycle.front().ba_from : r.plan.prefix.front().ba_from;
    const auto& qs = planner.automaton_states();
    EXPECT_NE(std::find(qs.begin(), qs.end(), q0), qs.end()) << "the plan starts at automaton state " << q0;
    automata::Automaton from_q0 = ba;
    from_q0.initial = q0;
    EXPECT_TRUE(automata::lasso_accept(from_q0, word));
    if (!planner.formula().is_null() && q0 == ba.initial) {
      ltl::LassoWord lw;
      auto names = [&](automata::Letter l) {
        ltl::LassoWord::Letter out;
        for (std::size_t i = 0; i < ba.atoms.size(); ++i)
          if ((l >> i) & 1) out.insert(ba.atoms[i]);
        return out;
      };
      for (auto l : word.prefix) lw.prefix.push_back(names(l));
      for (auto l : word.cycle) lw.cycle.push_back(names(l));
      EXPECT_TRUE(ltl::holds(planner.formula(), lw))
          << "the automaton accepts " << ltl::to_string(lw) << " but the formula " << planner.scenario().task
          << " does not hold on it (an automata::translate bug if lasso_accept passed above)";
    }
  }
  EXPECT_NEAR(total, r.plan.cost(), 1e-6);
  return total;
}

}  // namespace plantest
