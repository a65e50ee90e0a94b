// lasso_accept against hand-made automata and a brute-force oracle.
#include "rtamp/automata/lasso_accept.hpp"

#include <gtest/gtest.h>

#include "random_automaton.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::automata {
namespace {

// G F a as a one-state TGBA: a-loop in set 0, true-loop outside.
Automaton gfa_tgba() {
  Automaton a;
  a.atom_index("a");
  a.num_sets = 1;
  a.add_state();
  a.add_edge(0, 0, Cube{1, 0}, 1);
  a.add_edge(0, 0, Cube{}, 0);
  return a;
}

TEST(LassoAccept, GFa) {
  const Automaton a = gfa_tgba();
  EXPECT_TRUE(lasso_accept(a, {{0, 0}, {0, 1}}));
  EXPECT_TRUE(lasso_accept(a, {{}, {1}}));
  EXPECT_FALSE(lasso_accept(a, {{1, 1, 1}, {0}}));
  EXPECT_FALSE(lasso_accept(a, {{}, {0, 0}}));
}

TEST(LassoAccept, StateBasedFGa) {
  Automaton a;
  a.atom_index("a");
  a.state_based = true;
  a.add_state(false);
  a.add_state(true);
  a.add_edge(0, 0, Cube{});
  a.add_edge(0, 1, Cube{1, 0});
  a.add_edge(1, 1, Cube{1, 0});
  EXPECT_TRUE(lasso_accept(a, {{0, 0}, {1}}));
  EXPECT_FALSE(lasso_accept(a, {{1}, {1, 0}}));
  EXPECT_EQ(a.edges[1][0].marks, 1u);
}

TEST(LassoAccept, ZeroSetsAcceptsEveryInfiniteRun) {
  Automaton a;
  a.atom_index("a");
  a.num_sets = 0;
  a.add_state();
  a.add_edge(0, 0, Cube{0, 1});
  EXPECT_TRUE(lasso_accept(a, {{}, {0}}));
  EXPECT_FALSE(lasso_accept(a, {{0, 0}, {0, 1}}));
}

TEST(LassoAccept, GeneralizedNeedsEverySet) {
  // Two sets: a-edges carry set 0, b-edges set 1.
  Automaton a;
  a.atom_index("a");
  a.atom_index("b");
  a.num_sets = 2;
  a.add_state();
  a.add_edge(0, 0, Cube{1, 0}, 1);
  a.add_edge(0, 0, Cube{2, 0}, 2);
  a.add_edge(0, 0, Cube{}, 0);
  EXPECT_TRUE(lasso_accept(a, {{}, {1, 2}}));
  EXPECT_TRUE(lasso_accept(a, {{}, {3}}));
  EXPECT_FALSE(lasso_accept(a, {{}, {1, 0}}));
  EXPECT_FALSE(lasso_accept(a, {{3, 3}, {2}}));
}

TEST(LassoAccept, EmptyCycleIsAnError) {
  EXPECT_THROW(lasso_accept(gfa_tgba(), {{1}, {}}), Error);
}

TEST(LassoAccept, MatchesBruteForce) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 3000; ++i) {
    const bool sb = i % 3 == 0;
    const auto states = static_cast<std::uint32_t>(1 + rng() % 6);  // one draw per statement
    const auto marks = static_cast<std::uint32_t>(rng() % 4);
    const Automaton a = test::random_automaton(rng, states, 2, marks, sb, 0.35);
    for (int k = 0; k < 10; ++k) {
      const LassoWord w = test::random_word(rng, 2);
      ASSERT_EQ(lasso_accept(a, w), test::brute_accept(a, w)) << "automaton " << i << " word " << k;
    }
  }
}

}  // namespace
}  // namespace rtamp::automata
