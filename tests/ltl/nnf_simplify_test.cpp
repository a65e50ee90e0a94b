// NNF and the simplifier: every rule on hand cases (expected result), and
// soundness of nnf/simplify/implies on thousands of random formulas against
// the lasso oracle.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>

#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/nnf.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp/ltl/simplify.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::ltl {
namespace {

// The sanitizer builds run these property tests with fewer samples (ASan is
// ~10x slower); the Release build runs them in full.
constexpr int kScale = RTAMP_SANITIZER_BUILD ? 4 : 1;

std::string nnf_of(const std::string& s) { return to_string(nnf(parse(s))); }

TEST(LtlNnf, PushesNegations) {
  EXPECT_EQ(nnf_of("!(a & b)"), to_string(parse("!a | !b")));
  EXPECT_EQ(nnf_of("!X a"), "X!a");
  EXPECT_EQ(nnf_of("!F a"), "G!a");
  EXPECT_EQ(nnf_of("!G a"), "F!a");
  EXPECT_EQ(nnf_of("!(a U b)"), "!a R !b");
  EXPECT_EQ(nnf_of("!(a R b)"), "!a U !b");
  EXPECT_EQ(nnf_of("!(a W b)"), "!a M !b");
  EXPECT_EQ(nnf_of("!(a M b)"), "!a W !b");
  EXPECT_EQ(nnf(parse("a -> b")), parse("!a | b"));
  EXPECT_EQ(nnf(parse("!(a -> b)")), parse("a & !b"));
  EXPECT_EQ(nnf(parse("a <-> b")), parse("(a & b) | (!a & !b)"));
  EXPECT_EQ(nnf(parse("a xor b")), parse("(a & !b) | (!a & b)"));
  EXPECT_EQ(nnf(parse("!(a xor b)")), parse("(a & b) | (!a & !b)"));
  EXPECT_EQ(nnf(parse("G(a -> F b)")), parse("G(!a | F b)"));
  EXPECT_EQ(negated_nnf(parse("G(a -> F b)")), parse("F(a & G !b)"));
  EXPECT_TRUE(is_nnf(nnf(parse("!(a <-> X(b xor !c)) U !G d"))));
  EXPECT_FALSE(is_nnf(parse("!(a U b)")));
  EXPECT_FALSE(is_nnf(parse("a -> b")));
}

// Expected simplifications, one per rule of simplify.hpp.
TEST(LtlSimplify, Rules) {
  auto expect = [](const std::string& in, const std::string& out) {
    EXPECT_EQ(simplify(parse(in)), parse(out)) << in << " gave " << to_string(simplify(parse(in)));
  };
  expect("F F a", "F a");
  expect("G G a", "G a");
  expect("G F G a", "F G a");
  expect("F G F a", "G F a");
  expect("X true", "true");
  expect("X F G a", "F G a");
  expect("X G F a", "G F a");
  expect("F(a | b)", "F a | F b");
  expect("G(a & b)", "G a & G b");
  expect("G F a & G F b", "G F a & G F b");
  expect("G F(a | b)", "G F(a | b)");
  expect("G(F a | F b | X c)", "G(F(a | b) | X c)");
  expect("F G(a & b)", "F G(a & b)");
  expect("F(G a & G b & X c)", "F(G(a & b) & X c)");
  expect("G(F a | F X b)", "G(F a | X F b)");
  expect("G X F a", "G F a");
  expect("G F(a & F b)", "G F a & G F b");
  expect("G(a & X F(b & X F(c & X F d)))", "G a & G F b & G F c & G F d");
  expect("G F(a & X b)", "G F(a & X b)");
  expect("F X a", "X F a");
  expect("G X a", "X G a");
  expect("F(a U b)", "F b");
  expect("G(a R b)", "G b");
  expect("F(a M b)", "F(a & b)");
  expect("G(a W b)", "G(a | b)");
  expect("F(a & G F b)", "F a & G F b");
  expect("G(a | F G b)", "G a | F G b");
  expect("a U F b", "F b");
  expect("a R G b", "G b");
  expect("a U a", "a");
  expect("a R a", "a");
  expect("a W a", "a");
  expect("a M a", "a");
  expect("X a U X b", "X(a U b)");
  expect("X a R X b", "X(a R b)");
  expect("X a W X b", "X(a W b)");
  expect("X a M X b", "X(a M b)");
  expect("a U (b U a)", "b U a");
  expect("(a & b) U a", "a");          // a & b ⇒ a
  expect("a W (a | b)", "a | b");
  expect("(a | b) R a", "a");           // a ⇒ a | b
  expect("a M (a & b)", "a & b");
  expect("true U b", "F b");
  expect("false R b", "G b");
  expect("a W false", "G a");
  expect("a M true", "F a");
  expect("a U true", "true");
  expect("a U false", "false");
  expect("false U b", "b");
  expect("a R true", "true");
  expect("true R b", "b");
  expect("a W true", "true");
  expect("true W b", "true");
  expect("false W b", "b");
  expect("a M false", "false");
  expect("false M b", "false");
  expect("true M b", "b");
  expect("a & (a | b)", "a");
  expect("a | (a & b)", "a");
  expect("(a U b) | b", "a U b");
  expect("(a U b) & b", "b");
  expect("G a & a", "G a");
  expect("G a | F G a", "F G a");
  expect("F a & G F a", "G F a");
  expect("a & !a", "false");
  expect("a | !a", "true");
  expect("X a & X b", "X(a & b)");
  expect("X a | X b | c", "X(a | b) | c");
  expect("(a U b) & (c U b)", "(a & c) U b");
  expect("(a U b) | (a U c)", "a U (b | c)");
  expect("(a W b) & (c W b)", "(a & c) W b");
  expect("(a W b) | (a W c)", "a W (b | c)");
  expect("(a R b) & (a R c)", "a R (b & c)");
  expect("(a R b) | (c R b)", "(a | c) R b");
  expect("(a M b) & (a M c)", "a M (b & c)");
  expect("(a M b) | (c M b)", "(a | c) M b");
  expect("(a U b) & (c U b) & (d U b) & e", "((a & c & d) U b) & e");
  expect("!(a U b)", "!a R !b");
  expect("!G F a", "F G !a");
  expect("G(a -> F b)", "G(!a | F b)");
  // An invariant of the left operand inside an until's goal is a weak until.
  expect("a U (b | G a)", "a W b");
  expect("a W (b | G a)", "a W b");
  expect("a R (b & F a)", "a M b");
  expect("a M (b & F a)", "a M b");
  expect("(a | X c) U (b | G(a | X c))", "(a | X c) W b");
  expect("a U G a", "G a");
}

// The absorption rules above, checked on the lasso oracle with operands that
// are not atoms (the rule holds for any a, b).
TEST(LtlSimplify, AbsorbedInvariantSound) {
  std::mt19937_64 rng(20261205);
  RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  int rewritten = 0;
  for (int k = 0; k < 600 / kScale; ++k) {
    opt.size = 1 + uniform(rng, 0, 6);
    const Formula a = random_formula(rng, opt);
    const Formula b = random_formula(rng, opt);
    const Formula cases[] = {
        Formula::U(a, Formula::Or({b, Formula::G(a)})), Formula::W(a, Formula::Or({b, Formula::G(a)})),
        Formula::R(a, Formula::And({b, Formula::F(a)})), Formula::M(a, Formula::And({b, Formula::F(a)}))};
    for (const Formula& f : cases) {
      const Formula s = simplify(f);
      rewritten += s.size() < f.size();
      for (int t = 0; t < 8; ++t) {
        const LassoWord w = random_lasso(rng, opt.atoms, 3, 4);
        ASSERT_EQ(holds(s, w), holds(f, w))
            << to_string(f) << " -> " << to_string(s) << " on " << to_string(w);
      }
    }
  }
  EXPECT_GT(rewritten, 0);
}

TEST(LtlSimplify, Idempotent) {
  std::mt19937_64 rng(3);
  RandomFormulaOptions opt;
  for (int k = 0; k < 2000; ++k) {
    opt.size = 1 + uniform(rng, 0, 25);
    const Formula f = random_formula(rng, opt);
    const Formula s = simplify(f);
    EXPECT_TRUE(is_nnf(s)) << to_string(f);
    EXPECT_EQ(nnf(s), s);
    // Not a fixpoint in general (rules fire on results of other rules), but
    // never grows on a second pass.
    EXPECT_LE(simplify(s).size(), s.size()) << to_string(f);
  }
}

// The core soundness check: f, nnf(f), simplify(f) agree on random words; and
// implies(x, y) = true only when every sampled word of x satisfies y.
TEST(LtlSimplify, SoundOnRandomFormulasAndWords) {
  std::mt19937_64 rng(20261123);
  RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  std::size_t total_before = 0, total_after = 0;
  int words = 0;
  for (int k = 0; k < 4000 / kScale; ++k) {
    opt.size = 1 + uniform(rng, 0, 24);
    const Formula f = random_formula(rng, opt);
    const Formula n = nnf(f);
    const Formula s = simplify(f);
    total_before += n.size();
    total_after += s.size();
    for (int t = 0; t < 12; ++t) {
      const LassoWord w = random_lasso(rng, opt.atoms, 3, 4);
      const bool expected = holds(f, w);
      ASSERT_EQ(holds(n, w), expected) << "nnf: " << to_string(f) << " -> " << to_string(n) << " on " << to_string(w);
      ASSERT_EQ(holds(s, w), expected) << "simplify: " << to_string(f) << " -> " << to_string(s) << " on "
                                       << to_string(w);
      ++words;
    }
  }
  EXPECT_EQ(words, 48000 / kScale);
  EXPECT_LT(total_after, total_before);  // it does simplify
}

TEST(LtlSimplify, ImpliesIsSound) {
  std::mt19937_64 rng(99);
  RandomFormulaOptions opt = RandomFormulaOptions::without_boolean_sugar();
  opt.atoms = {"a", "b"};
  int claims = 0;
  for (int k = 0; k < 20000 / kScale; ++k) {
    opt.size = 1 + uniform(rng, 0, 8);
    const Formula x = nnf(random_formula(rng, opt));
    opt.size = 1 + uniform(rng, 0, 8);
    const Formula y = nnf(random_formula(rng, opt));
    if (!implies(x, y)) continue;
    ++claims;
    for (int t = 0; t < 20; ++t) {
      const LassoWord w = random_lasso(rng, opt.atoms, 3, 3);
      ASSERT_TRUE(!holds(x, w) || holds(y, w)) << to_string(x) << " => " << to_string(y) << " fails on "
                                                << to_string(w);
    }
  }
  EXPECT_GT(claims, 100 / kScale);
}

// Each hand rule also checked semantically with the atoms replaced by random
// subformulas (eventual, universal and arbitrary), which exercises the
// side conditions.
TEST(LtlSimplify, SoundOnTemporalOperands) {
  std::mt19937_64 rng(5);
  RandomFormulaOptions small;
  small.atoms = {"a", "b", "c"};
  const char* shapes[] = {"F(x | y)", "G(x & y)", "F(x U y)", "G(x R y)", "F(x M y)", "G(x W y)", "x U (y U x)",
                          "x W (y U x)", "x U (y W x)", "x R (y R x)", "x M (y R x)", "(x U y) | y", "x & (x | y)",
                          "X x U X y", "F(x & G F y)", "G(x | F G y)", "x U F y", "x R G y", "X(G F x)",
                          "x W (x | y)", "(x | y) R x", "x M (x & y)", "F x & G F x", "G x | F G x",
                          "(x U y) & (a U y)", "(x U y) | (x U a)", "(x W y) & (a W y)", "(x W y) | (x W a)",
                          "(x R y) & (x R a)", "(x R y) | (a R y)", "(x M y) & (x M a)", "(x M y) | (a M y)"};
  for (const char* shape : shapes) {
    const Formula pattern = parse(shape);
    for (int k = 0; k < 200 / kScale; ++k) {
      small.size = 1 + uniform(rng, 0, 6);
      const Formula x = random_formula(rng, small);
      small.size = 1 + uniform(rng, 0, 6);
      const Formula y = random_formula(rng, small);
      // Substitute x and y.
      std::function<Formula(const Formula&)> subst = [&](const Formula& g) -> Formula {
        if (g.op() == Op::Atom) return g.name() == "x" ? x : g.name() == "y" ? y : g;
        if (g.arity() == 0) return g;
        std::vector<Formula> cs;
        for (const Formula& c : g.children()) cs.push_back(subst(c));
        return g.with_children(std::move(cs));
      };
      const Formula f = subst(pattern);
      const Formula s = simplify(f);
      for (int t = 0; t < 8; ++t) {
        const LassoWord w = random_lasso(rng, small.atoms, 3, 3);
        ASSERT_EQ(holds(s, w), holds(f, w)) << shape << ": " << to_string(f) << " -> " << to_string(s);
      }
    }
  }
}

TEST(LtlSimplify, DwyerPatternsShrinkAndStayEquivalent) {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/dac-patterns.ltl");
  std::string line;
  std::mt19937_64 rng(1);
  int n = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const Formula f = parse(line);
    const Formula s = simplify(f);
    EXPECT_LE(s.size(), nnf(f).size()) << line;
    for (int t = 0; t < 200; ++t) {
      const LassoWord w = random_lasso(rng, {"p", "q", "r", "s", "t", "z"}, 4, 5);
      ASSERT_EQ(holds(s, w), holds(f, w)) << line << " -> " << to_string(s);
    }
    ++n;
  }
  EXPECT_EQ(n, 55);
}

}  // namespace
}  // namespace rtamp::ltl
