// The claim translate relies on to skip the negation check: for a syntactic
// obligation formula (ltl/syntactic_class.hpp) the minimal WDBA of its
// automaton (automata/wdba.hpp) accepts exactly its models. Checked on random
// obligation formulas against the direct semantics on random lassos; plus the
// classes on hand-picked formulas.
#include <gtest/gtest.h>

#include <random>

#include "oracle.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/automata/wdba.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/nnf.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp/ltl/syntactic_class.hpp"

namespace rtamp::automata {
namespace {

using ltl::is_syntactic_guarantee;
using ltl::is_syntactic_obligation;
using ltl::is_syntactic_safety;
using ltl::parse;

TEST(SyntacticClass, HandPicked) {
  EXPECT_TRUE(is_syntactic_safety(parse("G(a | X b) & (a W b) & (a R X c)")));
  EXPECT_FALSE(is_syntactic_safety(parse("G F a")));
  EXPECT_FALSE(is_syntactic_safety(parse("a U b")));
  EXPECT_TRUE(is_syntactic_guarantee(parse("F(a & X b) | (a U b) | (a M b)")));
  EXPECT_FALSE(is_syntactic_guarantee(parse("F G a")));
  EXPECT_TRUE(is_syntactic_obligation(parse("G a | F b")));
  EXPECT_TRUE(is_syntactic_obligation(parse("X(G a & (b U c))")));
  EXPECT_FALSE(is_syntactic_obligation(parse("G(a | F b)")));
  EXPECT_FALSE(is_syntactic_obligation(parse("F G a")));
  EXPECT_FALSE(is_syntactic_obligation(parse("a U G b")));
}

TEST(SyntacticClass, ObligationWdbaIsExact) {
  std::mt19937_64 rng(11);
  auto opts = ltl::RandomFormulaOptions::without_boolean_sugar();
  TranslateOptions plain;
  plain.wdba = false;
  int checked = 0;
  for (int k = 0; k < 3000 && checked < 300; ++k) {
    opts.size = 2 + ltl::uniform(rng, 0, 13);
    const ltl::Formula f = ltl::random_formula(rng, opts);
    if (!is_syntactic_obligation(ltl::nnf(f))) continue;
    ++checked;
    const auto w = minimize_wdba(translate(f, plain), 100000);
    if (!w) continue;
    for (int i = 0; i < 60; ++i) {
      const ltl::LassoWord lw = ltl::random_lasso(rng, w->atoms, 4, 4);
      ASSERT_EQ(lasso_accept(*w, test::to_word(*w, lw)), ltl::holds(f, lw)) << ltl::to_string(f);
    }
  }
  EXPECT_GE(checked, 300);
}

}  // namespace
}  // namespace rtamp::automata
