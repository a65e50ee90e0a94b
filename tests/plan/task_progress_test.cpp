// TaskProgress against brute force on random formulas and random histories:
//  - states(): for every automaton state, whether some run of the automaton
//    on some stuttering of the history reaches it (each earlier letter read
//    1..K+1 times, the current one 0..K times, K = number of states, which
//    is enough for the union to saturate; every combination enumerated and
//    simulated word by word);
//  - satisfied_by_staying(here): for stutter-invariant (X-free) formulas,
//    equals the direct LTL semantics (ltl/lasso.hpp) of history·here^ω, for
//    `here` the current state's label and for a new state's;
//  - can_still_accept(): some continuation lasso (|u| <= 2, |v| <= 2) makes
//    history·u·v^ω a model (X-free formulas, where the tracked stutterings
//    do not matter), and only then.
#include <gtest/gtest.h>

#include <random>

#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp/plan/task_progress.hpp"

namespace {

using namespace rtamp;
using automata::Letter;

const std::vector<std::string> kAtoms = {"a", "b"};

// A letter over kAtoms (bit i = kAtoms[i]) as the automaton's letter and as a name set.
Letter to_ba(const automata::Automaton& ba, unsigned bits) {
  Letter l = 0;
  for (std::size_t i = 0; i < kAtoms.size(); ++i)
    if ((bits >> i) & 1)
      if (int a = ba.find_atom(kAtoms[i]); a >= 0) l |= Letter{1} << a;
  return l;
}
ltl::LassoWord::Letter to_names(unsigned bits) {
  ltl::LassoWord::Letter out;
  for (std::size_t i = 0; i < kAtoms.size(); ++i)
    if ((bits >> i) & 1) out.insert(kAtoms[i]);
  return out;
}

// States reached by some run on the word, from the initial state.
std::vector<bool> simulate(const automata::Automaton& ba, const std::vector<Letter>& word) {
  std::vector<bool> cur(ba.num_states(), false);
  cur[ba.initial] = true;
  for (Letter l : word) {
    std::vector<bool> next(ba.num_states(), false);
    for (std::uint32_t q = 0; q < ba.num_states(); ++q)
      if (cur[q])
        for (const auto& e : ba.edges[q])
          if (e.guard.matches(l)) next[e.dst] = true;
    cur = next;
  }
  return cur;
}

// The brute-force tracked set after the history h (currently at its last state).
std::vector<std::uint32_t> oracle_states(const automata::Automaton& ba, const std::vector<Letter>& h) {
  const unsigned K = ba.num_states();
  std::vector<bool> any(ba.num_states(), false);
  std::vector<unsigned> k(h.size(), 0);
  for (;;) {
    std::vector<Letter> word;
    for (std::size_t i = 0; i < h.size(); ++i)
      for (unsigned r = 0; r < k[i] + (i + 1 < h.size() ? 1 : 0); ++r) word.push_back(h[i]);
    const auto reached = simulate(ba, word);
    for (std::uint32_t q = 0; q < ba.num_states(); ++q)
      if (reached[q]) any[q] = true;
    std::size_t i = 0;
    while (i < k.size() && ++k[i] > K) k[i++] = 0;
    if (i == k.size()) break;
  }
  std::vector<std::uint32_t> out;
  for (std::uint32_t q = 0; q < ba.num_states(); ++q)
    if (any[q]) out.push_back(q);
  return out;
}

ltl::Formula random_formula(std::mt19937_64& rng, bool allow_next) {
  ltl::RandomFormulaOptions opt = ltl::RandomFormulaOptions::without_boolean_sugar();
  opt.atoms = kAtoms;
  opt.size = 2 + ltl::uniform(rng, 0, 9);
  if (!allow_next) opt.set_weight(ltl::Op::Next, 0);
  return ltl::random_formula(rng, opt);
}

TEST(TaskProgress, ResetStartsAtTheInitialStateWithoutClosure) {
  const auto ba = automata::translate(ltl::parse("F a"));
  plan::TaskProgress tp(ba);
  EXPECT_EQ(tp.states(), std::vector<std::uint32_t>{ba.initial});
  EXPECT_FALSE(tp.dead());
  EXPECT_TRUE(tp.can_still_accept());
}

TEST(TaskProgress, StatesMatchBruteForceOverStutterings) {
  std::mt19937_64 rng(5150);
  int checked = 0, nontrivial = 0, dead = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const ltl::Formula f = random_formula(rng, true);
    const automata::Automaton ba = automata::translate(f);
    if (ba.num_states() == 0 || ba.num_states() > 6) continue;
    SCOPED_TRACE("trial " + std::to_string(trial) + " formula " + ltl::to_string(f));
    std::vector<Letter> h;
    plan::TaskProgress tp(ba);
    const std::size_t n = 1 + ltl::uniform(rng, 0, 3);
    for (std::size_t i = 0; i < n; ++i) {
      const Letter l = to_ba(ba, static_cast<unsigned>(ltl::uniform(rng, 0, 3)));
      if (i > 0) tp.leave(h.back());
      h.push_back(l);
      tp.at(l);
      const auto want = oracle_states(ba, h);
      ASSERT_EQ(tp.states(), want) << "after " << h.size() << " letters";
      EXPECT_EQ(tp.dead(), want.empty());
      tp.at(l);  // closing again changes nothing
      EXPECT_EQ(tp.states(), want);
      ++checked;
      if (want.size() > 1) ++nontrivial;
      if (want.empty()) ++dead;
    }
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(nontrivial, 100);
  EXPECT_GT(dead, 5);
}

TEST(TaskProgress, StayingAndAcceptanceMatchLtlSemantics) {
  std::mt19937_64 rng(8086);
  int checked = 0, staying = 0, not_staying = 0, alive = 0, hopeless = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const ltl::Formula f = random_formula(rng, false);
    const automata::Automaton ba = automata::translate(f);
    SCOPED_TRACE("trial " + std::to_string(trial) + " formula " + ltl::to_string(f));
    std::vector<unsigned> h;
    const std::size_t n = 1 + ltl::uniform(rng, 0, 3);
    for (std::size_t i = 0; i < n; ++i) h.push_back(static_cast<unsigned>(ltl::uniform(rng, 0, 3)));
    plan::TaskProgress tp(ba);
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) tp.leave(to_ba(ba, h[i - 1]));
      tp.at(to_ba(ba, h[i]));
    }
    ltl::LassoWord w;
    for (std::size_t i = 0; i + 1 < n; ++i) w.prefix.push_back(to_names(h[i]));
    // Staying at the current state forever.
    w.cycle = {to_names(h.back())};
    const bool stay_here = ltl::holds(f, w);
    EXPECT_EQ(tp.satisfied_by_staying(to_ba(ba, h.back())), stay_here) << ltl::to_string(w);
    // Can the task still be satisfied? Continuations u·v^ω with |u| <= 2, |v| <= 2.
    bool witness = false;
    std::vector<std::vector<unsigned>> words = {{}};
    for (unsigned a = 0; a < 4; ++a) {
      words.push_back({a});
      for (unsigned b = 0; b < 4; ++b) words.push_back({a, b});
    }
    for (const auto& u : words) {
      for (const auto& v : words) {
        if (v.empty()) continue;
        ltl::LassoWord c;
        for (unsigned x : h) c.prefix.push_back(to_names(x));
        for (unsigned x : u) c.prefix.push_back(to_names(x));
        for (unsigned x : v) c.cycle.push_back(to_names(x));
        if (ltl::holds(f, c)) witness = true;
        if (witness) break;
      }
      if (witness) break;
    }
    witness = witness || stay_here;
    EXPECT_EQ(tp.can_still_accept(), witness);
    if (tp.dead()) {
      EXPECT_FALSE(tp.can_still_accept());
    }
    witness ? ++alive : ++hopeless;
    // Leaving for a new state and staying there.
    const unsigned here = static_cast<unsigned>(ltl::uniform(rng, 0, 3));
    plan::TaskProgress next = tp;  // copies track independently
    next.leave(to_ba(ba, h.back()));
    next.at(to_ba(ba, here));
    w.prefix.push_back(to_names(h.back()));
    w.cycle = {to_names(here)};
    const bool stay_there = ltl::holds(f, w);
    EXPECT_EQ(next.satisfied_by_staying(to_ba(ba, here)), stay_there) << ltl::to_string(w);
    stay_there ? ++staying : ++not_staying;
    ++checked;
  }
  EXPECT_GT(checked, 250);
  EXPECT_GT(staying, 50);
  EXPECT_GT(not_staying, 50);
  EXPECT_GT(alive, 50);
  EXPECT_GT(hopeless, 10);
}

}  // namespace
