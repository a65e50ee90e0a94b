// Checked merges (checked_merge.hpp): redirecting a state into one that
// simulates it only adds words (random automata, brute-force acceptance, with
// a negation that accepts nothing so that every candidate is merged); a
// negation that accepts everything blocks every merge; on formulas, the
// merge reaches the sizes of the hand-minimal automata and keeps the language
// (hand cases, and random formulas against the lasso oracle and A_!f).
#include "rtamp/automata/checked_merge.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "oracle.hpp"
#include "random_automaton.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/product.hpp"
#include "rtamp/automata/reduce.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

namespace rtamp::automata {
namespace {

Automaton nothing(const std::vector<std::string>& atoms) {
  Automaton n;
  n.atoms = atoms;
  n.add_state();
  return n;
}

Automaton everything(const std::vector<std::string>& atoms) {
  Automaton u;
  u.atoms = atoms;
  u.num_sets = 0;
  u.add_state();
  u.add_edge(0, 0, Cube{});
  return u;
}

TEST(CheckedMerge, RedirectingOnlyAddsWords) {
  std::mt19937_64 rng(26);
  int merged = 0;
  for (int i = 0; i < 2000; ++i) {
    const bool sb = i % 2 == 0;
    const auto states = static_cast<std::uint32_t>(2 + rng() % 6);
    const auto marks = static_cast<std::uint32_t>(rng() % 3);
    Automaton a = test::random_automaton(rng, states, 2, marks, sb, 0.3);
    remove_useless(a);
    canonicalize_acceptance(a, false);
    const Automaton orig = a;
    const Automaton none = nothing(a.atoms);
    Automaton grown = a;
    if (merge_checked(grown, [&] { return &none; }, 100)) {
      ++merged;
      EXPECT_LT(grown.num_states(), orig.num_states());
    }
    for (int k = 0; k < 100; ++k) {
      const LassoWord w = test::random_word(rng, static_cast<std::uint32_t>(a.atoms.size()));
      if (test::brute_accept(orig, w)) {
        ASSERT_TRUE(test::brute_accept(grown, w)) << "automaton " << i << " word " << k;
      }
    }
    const Automaton all = everything(a.atoms);
    Automaton kept = a;
    if (orig.num_states() > 1 && !orig.edges[orig.initial].empty()) {
      EXPECT_FALSE(merge_checked(kept, [&] { return &all; })) << i;
    }
  }
  EXPECT_GT(merged, 100);
}

TEST(CheckedMerge, HandMinimalSizes) {
  struct Case {
    const char* formula;
    std::uint32_t states;  // state-based Büchi
  };
  const Case cases[] = {
      {"G F a & G F !a", 3},                              // was 4: an initial state with one unmarked edge
      {"F G a | G F b", 4},                               // was 5
      {"G F a -> G F b", 4},                              // was 5
      {"G(a -> F b) & ((X a U b) | !X(a U (a & b)))", 2},  // the second conjunct is valid
  };
  std::mt19937_64 rng(5);
  for (const Case& c : cases) {
    const ltl::Formula f = ltl::parse(c.formula);
    const Automaton a = translate(f);
    EXPECT_EQ(a.num_states(), c.states) << c.formula;
    TranslateOptions off;
    off.checked_merge = false;
    off.splitting = Splitting::Never;  // splitting reaches two of these sizes on its own
    EXPECT_GT(translate(f, off).num_states(), c.states) << c.formula;
    for (int k = 0; k < 300; ++k) {
      const ltl::LassoWord w = ltl::random_lasso(rng, a.atoms, 4, 4);
      ASSERT_EQ(lasso_accept(a, test::to_word(a, w)), ltl::holds(f, w)) << c.formula << " " << ltl::to_string(w);
    }
  }
}

// `a` accepts 40 random lassos iff they satisfy f.
bool agrees_on_lassos(const Automaton& a, const ltl::Formula& f, std::mt19937_64& rng) {
  for (int i = 0; i < 40; ++i) {
    const ltl::LassoWord w = ltl::random_lasso(rng, a.atoms, 4, 4);
    if (lasso_accept(a, test::to_word(a, w)) != ltl::holds(f, w)) return false;
  }
  return true;
}

// Random formulas, with and without the merges: both accept the same random
// lassos as ltl::holds, the merged one × A_!f (translated independently, as a
// TGBA) is empty, and the merges make the automata smaller in total.
TEST(CheckedMerge, RandomFormulasKeepTheLanguage) {
  std::mt19937_64 rng(1205);
  auto opts = ltl::RandomFormulaOptions::without_boolean_sugar();
  std::size_t with = 0, without = 0;
  int smaller = 0;
  for (int k = 0; k < 600; ++k) {
    opts.size = 1 + ltl::uniform(rng, 0, 14);
    const ltl::Formula f = ltl::random_formula(rng, opts);
    TranslateOptions off;
    off.checked_merge = false;
    for (bool state_based : {true, false}) {
      TranslateOptions on;
      on.state_based = off.state_based = state_based;
      const Automaton a = translate(f, on);
      const Automaton b = translate(f, off);
      with += a.num_states();
      without += b.num_states();
      smaller += a.num_states() < b.num_states();
      ASSERT_TRUE(agrees_on_lassos(a, f, rng)) << ltl::to_string(f);
      ASSERT_TRUE(agrees_on_lassos(b, f, rng)) << ltl::to_string(f);
      TranslateOptions neg;
      neg.state_based = false;
      neg.checked_merge = false;
      ASSERT_TRUE(is_empty(product(a, translate(ltl::Formula::Not(f), neg)))) << ltl::to_string(f);
    }
  }
  EXPECT_LT(with, without);
  EXPECT_GT(smaller, 0);
  std::printf("states with checked merges %zu, without %zu; smaller on %d of 1200\n", with, without, smaller);
}

}  // namespace
}  // namespace rtamp::automata
