// Random generator: determinism per seed, size bound, weights respected,
// lasso shapes.
#include "rtamp/ltl/random.hpp"

#include <gtest/gtest.h>

#include <set>

#include "rtamp/ltl/printer.hpp"

namespace rtamp::ltl {
namespace {

bool uses(const Formula& f, Op op) {
  if (f.op() == op) return true;
  for (const Formula& c : f.children())
    if (uses(c, op)) return true;
  return false;
}

TEST(LtlRandom, DeterministicPerSeed) {
  RandomFormulaOptions opt;
  std::mt19937_64 r1(5), r2(5), r3(6);
  std::set<std::string> distinct;
  for (int i = 0; i < 100; ++i) {
    const Formula a = random_formula(r1, opt), b = random_formula(r2, opt);
    EXPECT_EQ(a, b);
    distinct.insert(to_string(random_formula(r3, opt)));
  }
  EXPECT_GT(distinct.size(), 80u);
}

TEST(LtlRandom, SizeIsAnUpperBound) {
  std::mt19937_64 rng(1);
  RandomFormulaOptions opt;
  std::size_t sum = 0;
  for (int i = 0; i < 1000; ++i) {
    opt.size = 1 + i % 40;
    const Formula f = random_formula(rng, opt);
    EXPECT_LE(f.size(), opt.size);
    sum += f.size();
  }
  EXPECT_GT(sum, 1000u * 10);  // the identities only trim a little
}

TEST(LtlRandom, WeightsDisableOperators) {
  std::mt19937_64 rng(2);
  RandomFormulaOptions opt = RandomFormulaOptions::without_boolean_sugar();
  opt.set_weight(Op::Until, 0);
  opt.set_weight(Op::True, 0);
  opt.set_weight(Op::False, 0);
  bool saw_release = false;
  for (int i = 0; i < 500; ++i) {
    opt.size = 20;
    const Formula f = random_formula(rng, opt);
    EXPECT_FALSE(uses(f, Op::Until) || uses(f, Op::Xor) || uses(f, Op::Implies) || uses(f, Op::Equiv))
        << to_string(f);
    saw_release = saw_release || uses(f, Op::Release);
  }
  EXPECT_TRUE(saw_release);
  // Only leaves: atoms.
  RandomFormulaOptions leaves;
  for (unsigned& w : leaves.weight) w = 0;
  leaves.set_weight(Op::Atom, 1);
  leaves.size = 10;
  EXPECT_EQ(random_formula(rng, leaves).op(), Op::Atom);
}

TEST(LtlRandom, LassoShapes) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 200; ++i) {
    const LassoWord w = random_lasso(rng, {"a", "b"}, 3, 5);
    EXPECT_LE(w.prefix.size(), 3u);
    EXPECT_GE(w.cycle.size(), 1u);
    EXPECT_LE(w.cycle.size(), 5u);
    for (const auto& l : w.cycle)
      for (const auto& a : l) EXPECT_TRUE(a == "a" || a == "b");
  }
  EXPECT_EQ(uniform(rng, 4, 4), 4u);
}

}  // namespace
}  // namespace rtamp::ltl
