// Splitting (split.hpp, sum.hpp, suspended_product.hpp, translate's
// Splitting modes): the classification of a top-level & / | into parts; the
// sum and the suspended product against the brute-force acceptance oracle on
// random automata; and random formulas with a top-level & or | (operands of
// every kind, suspendable ones included) translated with the split result
// forced and kept when smaller, for every output form, against the direct
// semantics on random lassos, with A_f × A_!f empty and witnesses models of f.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "random_automaton.hpp"
#include "random_oracle.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/product.hpp"
#include "rtamp/automata/split.hpp"
#include "rtamp/automata/sum.hpp"
#include "rtamp/automata/suspended_product.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/automata/vwaa.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

namespace rtamp::automata {
namespace {

using ltl::Formula;
using ltl::parse;

std::optional<detail::Split> split_of(const char* text) { return detail::split_formula(detail::to_nnf(parse(text))); }

Formula nnf(const char* text) { return detail::to_nnf(parse(text)); }

TEST(SplitFormula, SortsOperandsIntoObligationsSuspendableAndRest) {
  // F b: obligation; G F a: suspendable; G(a -> F b): neither.
  auto s = split_of("G F a & F b & G(a -> F b)");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->op, ltl::Op::And);
  EXPECT_EQ(s->parts, (std::vector<Formula>{nnf("F b"), nnf("G(a -> F b)")}));
  EXPECT_EQ(s->suspendable, std::vector<Formula>{nnf("G F a")});
  // With a rest, a safety operand (G c) joins the rest, not the obligations.
  s = split_of("F b & G c & G F a & G(a -> F b)");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->parts, (std::vector<Formula>{nnf("F b"), nnf("G c & G(a -> F b)")}));
  // Without a rest it stays with the obligations.
  s = split_of("X b & F c & F G a");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->parts, std::vector<Formula>{nnf("X b & F c")});
  EXPECT_EQ(s->suspendable, std::vector<Formula>{nnf("F G a")});
  s = split_of("G F a | F G b | (a U b)");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->op, ltl::Op::Or);
  EXPECT_EQ(s->parts, std::vector<Formula>{nnf("a U b")});
  EXPECT_EQ(s->suspendable.size(), 2u);
}

TEST(SplitFormula, LeavesObligationsAndSinglePartsWhole) {
  EXPECT_FALSE(split_of("F a & G b"));                     // an obligation: the WDBA's job
  EXPECT_FALSE(split_of("G(a -> F b) & G(c -> F d)"));     // one part: the rest
  EXPECT_FALSE(split_of("G F a"));                         // no & or | at the top
  EXPECT_FALSE(split_of("(a U G b) & (c U G d) & G e"));   // rest and safety: one part
}

TEST(Sum, AcceptsTheUnion) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 400; ++i) {
    const auto na = static_cast<std::uint32_t>(rng() % 4), nb = static_cast<std::uint32_t>(rng() % 4);
    const auto sa = static_cast<std::uint32_t>(1 + rng() % 4), sb = static_cast<std::uint32_t>(1 + rng() % 4);
    const Automaton a = test::random_automaton(rng, sa, 2, na, i % 3 == 0, 0.4);
    const Automaton b = test::random_automaton(rng, sb, 2, nb, i % 5 == 0, 0.4);
    const Automaton s = sum(a, b);
    for (int k = 0; k < 60; ++k) {
      const LassoWord w = test::random_word(rng, 2);
      ASSERT_EQ(test::brute_accept(s, w), test::brute_accept(a, w) || test::brute_accept(b, w)) << i << " " << k;
    }
  }
}

// A random suspendable formula over a and b (G F r, F G r, and & | of those).
Formula random_suspendable(std::mt19937_64& rng) {
  ltl::RandomFormulaOptions o;
  o.atoms = {"a", "b"};
  auto one = [&] {
    o.size = 1 + ltl::uniform(rng, 0, 4);
    const Formula r = ltl::random_formula(rng, o);
    return rng() % 2 ? Formula::G(Formula::F(r)) : Formula::F(Formula::G(r));
  };
  switch (rng() % 3) {
    case 0: return one();
    case 1: return Formula::And(one(), one());
    default: return Formula::Or(one(), one());
  }
}

TEST(SuspendedProduct, AcceptsTheIntersection) {
  std::mt19937_64 rng(12);
  int tested = 0, fewer = 0;
  while (tested < 300) {
    const Formula f = random_suspendable(rng);
    ASSERT_TRUE(f.is_eventual() && f.is_universal()) << ltl::to_string(f);
    TranslateOptions o;
    o.state_based = tested % 4 == 0;
    const Automaton s = translate(f, o);
    if (s.atoms != std::vector<std::string>{"a", "b"}) continue;  // simplified to fewer atoms
    const auto sets = static_cast<std::uint32_t>(rng() % 3), states = static_cast<std::uint32_t>(1 + rng() % 5);
    const Automaton a = test::random_automaton(rng, states, 2, sets, tested % 3 == 0, 0.35);
    const Automaton p = suspended_product(a, s);
    const Automaton full = product(a, s);
    fewer += p.num_states() < full.num_states();
    for (int k = 0; k < 60; ++k) {
      const LassoWord w = test::random_word(rng, 2);
      ASSERT_EQ(test::brute_accept(p, w), test::brute_accept(a, w) && test::brute_accept(s, w))
          << ltl::to_string(f) << " automaton " << tested << " word " << k;
    }
    ++tested;
  }
  EXPECT_GT(fewer, 0);
}

// Random formula with a top-level & or | of 2 to 4 operands: random formulas,
// G F r and F G r.
Formula random_split_formula(std::mt19937_64& rng, const std::vector<std::string>& atoms) {
  ltl::RandomFormulaOptions o;
  o.atoms = atoms;
  std::vector<Formula> operands;
  const auto n = 2 + rng() % 3;
  for (std::uint64_t i = 0; i < n; ++i) {
    const auto kind = rng() % 4;
    o.size = kind < 2 ? 1 + ltl::uniform(rng, 0, 7) : 1 + ltl::uniform(rng, 0, 3);
    const Formula r = ltl::random_formula(rng, o);
    operands.push_back(kind < 2 ? r : kind == 2 ? Formula::G(Formula::F(r)) : Formula::F(Formula::G(r)));
  }
  return rng() % 3 ? Formula::And(operands) : Formula::Or(operands);
}

TEST(TranslateSplit, RandomConjunctionsAndDisjunctionsAgreeWithTheSemantics) {
  std::mt19937_64 rng(13);
  const std::vector<std::string> atoms = {"a", "b", "c"};
  int split = 0, kept = 0;
  for (int i = 0; i < 800; ++i) {
    const Formula f = random_split_formula(rng, atoms);
    const std::string text = ltl::to_string(f);
    std::vector<ltl::LassoWord> words;
    std::vector<bool> truth;
    for (int k = 0; k < 40; ++k) {
      words.push_back(ltl::random_lasso(rng, atoms, 4, 4));
      truth.push_back(ltl::holds(f, words.back()));
    }
    TranslateOptions neg_opt;
    neg_opt.state_based = false;
    neg_opt.splitting = Splitting::Never;
    const Automaton neg = translate(Formula::Not(f), neg_opt);
    split += detail::split_formula(detail::to_nnf(f)).has_value();
    for (int variant = 0; variant < 12; ++variant) {
      TranslateOptions opt;
      opt.state_based = variant % 3 == 0;
      opt.one_set = variant % 3 == 2;
      opt.splitting = (variant / 3) % 2 ? Splitting::Always : Splitting::Smallest;
      opt.reduce = variant < 6;
      opt.simplify = i % 4 != 0;
      const Automaton a = translate(f, opt);
      const std::string what = text + " variant " + std::to_string(variant);
      ASSERT_EQ(a.state_based, opt.state_based) << what;
      ASSERT_EQ(a.initial, 0u) << what;
      if (opt.one_set) {
        ASSERT_EQ(a.num_sets, 1u) << what;
      }
      for (int k = 0; k < 40; ++k)
        ASSERT_EQ(lasso_accept(a, test::to_word(a, words[k])), truth[k]) << what << " word " << ltl::to_string(words[k]);
      ASSERT_TRUE(is_empty(product(a, neg))) << what;
      if (const auto w = find_accepting_lasso(a)) {
        ASSERT_TRUE(ltl::holds(f, test::to_named(a, *w))) << what;
      } else {
        ASSERT_TRUE(std::none_of(truth.begin(), truth.end(), [](bool t) { return t; })) << what;
      }
    }
    // Kept only when smaller: never larger than without splitting.
    TranslateOptions never;
    never.splitting = Splitting::Never;
    const Automaton whole = translate(f, never);
    const Automaton best = translate(f);
    ASSERT_LE(best.num_states(), whole.num_states()) << text;
    kept += best.num_states() < whole.num_states() || best.num_edges() < whole.num_edges();
  }
  EXPECT_GT(split, 200);
  EXPECT_GT(kept, 0);
}

}  // namespace
}  // namespace rtamp::automata
