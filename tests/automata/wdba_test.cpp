// The minimal WDBA step (wdba.hpp, used by translate): on random formulas the
// translation with it and without it accept the same random lasso words, and
// agree with the direct semantics; A_f × A_!f is empty; minimize_wdba gives a
// deterministic, complete automaton; on obligation formulas of known minimal
// size it reaches that size; complement_dba complements; on G(a -> F b) (not
// an obligation) the WDBA candidate has a wrong language, which translate's
// check refuses.
#include <gtest/gtest.h>

#include <random>

#include "oracle.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/product.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/automata/wdba.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

namespace rtamp::automata {
namespace {

bool deterministic_and_complete(const Automaton& a, Letter letters) {
  for (std::uint32_t q = 0; q < a.num_states(); ++q)
    for (Letter l = 0; l < letters; ++l) {
      int n = 0;
      for (const Edge& e : a.edges[q]) n += e.guard.matches(l);
      if (n != 1) return false;
    }
  return true;
}

TEST(Wdba, RandomFormulasSameWordsAndEmptyWithNegation) {
  std::mt19937_64 rng(26);
  auto opts = ltl::RandomFormulaOptions::without_boolean_sugar();
  int replaced = 0;  // formulas whose automaton the WDBA replaced
  for (int k = 0; k < 400; ++k) {
    opts.size = 1 + ltl::uniform(rng, 0, 14);
    const ltl::Formula f = ltl::random_formula(rng, opts);
    TranslateOptions old_opt;
    old_opt.wdba = false;
    const Automaton a_new = translate(f);
    const Automaton a_old = translate(f, old_opt);
    replaced += a_new.edges != a_old.edges;
    ASSERT_LE(a_new.num_states(), a_old.num_states()) << ltl::to_string(f);
    for (int i = 0; i < 60; ++i) {
      const ltl::LassoWord w = ltl::random_lasso(rng, a_new.atoms, 4, 4);
      const bool expected = ltl::holds(f, w);
      ASSERT_EQ(lasso_accept(a_new, test::to_word(a_new, w)), expected) << ltl::to_string(f);
      ASSERT_EQ(lasso_accept(a_old, test::to_word(a_old, w)), expected) << ltl::to_string(f);
    }
    TranslateOptions tgba;
    tgba.state_based = false;
    const Automaton neg = translate(ltl::Formula::Not(f), tgba);
    ASSERT_TRUE(is_empty(product(a_new, neg))) << ltl::to_string(f);
  }
  EXPECT_GT(replaced, 0);
}

TEST(Wdba, MinimizeGivesCompleteDeterministicAutomaton) {
  TranslateOptions o;
  o.wdba = false;
  for (const char* text : {"a U b", "F(a & X b)", "G(a -> X b)", "(a U b) | G c", "F a & F b", "G F a"}) {
    const Automaton a = translate(ltl::parse(text), o);
    const auto w = minimize_wdba(a, 1000);
    ASSERT_TRUE(w.has_value()) << text;
    EXPECT_TRUE(deterministic_and_complete(*w, Letter{1} << a.atoms.size())) << text;
  }
}

TEST(Wdba, ReachesMinimalSizesOnObligations) {
  // Minimal deterministic sizes (without the rejecting sink): F a & F b needs
  // 4 states (none seen, a seen, b seen, done); F(a & X b) needs 3.
  EXPECT_EQ(translate(ltl::parse("F a & F b")).num_states(), 4u);
  EXPECT_EQ(translate(ltl::parse("F(a & X b)")).num_states(), 3u);
}

TEST(Wdba, ComplementOfDbaAcceptsTheOtherWords) {
  TranslateOptions o;
  o.wdba = false;
  std::mt19937_64 rng(5);
  for (const char* text : {"a U b", "F(a & X b)", "G(a -> X b)", "(a U b) | G c", "G F a", "F G a"}) {
    const Automaton a = translate(ltl::parse(text), o);
    const auto w = minimize_wdba(a, 1000);
    ASSERT_TRUE(w.has_value());
    const Automaton c = complement_dba(*w);
    for (int i = 0; i < 200; ++i) {
      const ltl::LassoWord lw = ltl::random_lasso(rng, a.atoms, 4, 4);
      EXPECT_NE(lasso_accept(*w, test::to_word(*w, lw)), lasso_accept(c, test::to_word(c, lw))) << text;
    }
  }
}

TEST(Wdba, NotAnObligationIsRefused) {
  const ltl::Formula f = ltl::parse("G(a -> F b)");
  TranslateOptions o;
  o.wdba = false;
  const auto w = minimize_wdba(translate(f, o), 1000);
  ASSERT_TRUE(w.has_value());
  const Automaton a = translate(f);
  std::mt19937_64 rng(3);
  int wrong = 0;
  for (int i = 0; i < 300; ++i) {
    const ltl::LassoWord lw = ltl::random_lasso(rng, a.atoms, 3, 3);
    wrong += lasso_accept(*w, test::to_word(*w, lw)) != ltl::holds(f, lw);
    ASSERT_EQ(lasso_accept(a, test::to_word(a, lw)), ltl::holds(f, lw));
  }
  EXPECT_GT(wrong, 0);
}

}  // namespace
}  // namespace rtamp::automata
