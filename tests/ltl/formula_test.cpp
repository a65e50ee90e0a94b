// Formula core: hash-consing, constructor identities, n-ary canonical order,
// syntactic classes (checked semantically with the lasso oracle), and the
// unique table releasing nodes.
#include "rtamp/ltl/formula.hpp"

#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

namespace rtamp::ltl {
namespace {

TEST(LtlFormula, HashConsing) {
  const Formula a1 = Formula::atom("a"), a2 = Formula::atom("a");
  EXPECT_EQ(a1, a2);
  EXPECT_EQ(a1.id(), a2.id());
  EXPECT_EQ(Formula::U(a1, Formula::atom("b")), Formula::U(a2, Formula::atom("b")));
  EXPECT_NE(Formula::U(a1, Formula::atom("b")), Formula::U(Formula::atom("b"), a1));
  EXPECT_EQ(std::hash<Formula>{}(a1), std::hash<Formula>{}(a2));
}

TEST(LtlFormula, ConstructorIdentities) {
  const Formula a = Formula::atom("a"), b = Formula::atom("b");
  EXPECT_EQ(Formula::Not(Formula::Not(a)), a);
  EXPECT_EQ(Formula::Not(Formula::tt()), Formula::ff());
  EXPECT_EQ(Formula::X(Formula::tt()), Formula::tt());
  EXPECT_EQ(Formula::F(Formula::F(a)), Formula::F(a));
  EXPECT_EQ(Formula::G(Formula::G(a)), Formula::G(a));
  EXPECT_EQ(Formula::And(a, Formula::tt()), a);
  EXPECT_EQ(Formula::And(a, Formula::ff()), Formula::ff());
  EXPECT_EQ(Formula::Or(a, Formula::tt()), Formula::tt());
  EXPECT_EQ(Formula::And(a, b), Formula::And(b, a));
  EXPECT_EQ(Formula::And({a, Formula::And(b, a)}), Formula::And(a, b));
  EXPECT_EQ(Formula::And(std::vector<Formula>{}), Formula::tt());
  EXPECT_EQ(Formula::Or(std::vector<Formula>{}), Formula::ff());
  const Formula c = Formula::And({b, a, Formula::atom("c")});
  for (std::size_t i = 1; i < c.arity(); ++i) EXPECT_LT(c[i - 1].id(), c[i].id());
  EXPECT_EQ(c.with_children({a, b}), Formula::And(a, b));
}

TEST(LtlFormula, SizeDepthBoolean) {
  const Formula f = parse("G(a -> F b)");
  EXPECT_EQ(f.size(), 5u);
  EXPECT_EQ(f.depth(), 4u);
  EXPECT_FALSE(f.is_boolean());
  EXPECT_TRUE(parse("a & !b | c").is_boolean());
}

// is_eventual: f ≡ F f; is_universal: f ≡ G f. Check on random words.
TEST(LtlFormula, SyntacticClassesAreSemanticallyRight) {
  std::mt19937_64 rng(17);
  RandomFormulaOptions opt;
  int eventual = 0, universal = 0;
  for (int k = 0; k < 5000; ++k) {
    opt.size = 2 + uniform(rng, 0, 14);
    const Formula f = random_formula(rng, opt);
    if (!f.is_eventual() && !f.is_universal()) continue;
    eventual += f.is_eventual();
    universal += f.is_universal();
    for (int t = 0; t < 10; ++t) {
      const LassoWord w = random_lasso(rng, opt.atoms);
      const bool v = holds(f, w);
      if (f.is_eventual()) {
        ASSERT_EQ(v, holds(Formula::F(f), w)) << to_string(f);
      }
      if (f.is_universal()) {
        ASSERT_EQ(v, holds(Formula::G(f), w)) << to_string(f);
      }
    }
  }
  EXPECT_GT(eventual, 100);
  EXPECT_GT(universal, 100);
}

TEST(LtlFormula, UniqueTableReleasesNodes) {
  const std::size_t before = live_formula_nodes();
  {
    const Formula f = parse("G(zz_unique_1 -> F zz_unique_2) U X zz_unique_3");
    EXPECT_GT(live_formula_nodes(), before);
  }
  EXPECT_EQ(live_formula_nodes(), before);
}

TEST(LtlFormula, ConcurrentConstructionGivesSameNodes) {
  std::vector<std::uint64_t> ids(4);
  std::vector<std::thread> threads;
  const Formula keep = parse("a U (b & X c)");
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([t, &ids] {
      Formula f;
      for (int i = 0; i < 2000; ++i) f = parse("a U (b & X c)");
      ids[t] = f.id();
    });
  }
  for (auto& th : threads) th.join();
  for (std::uint64_t id : ids) EXPECT_EQ(id, keep.id());
}

}  // namespace
}  // namespace rtamp::ltl
