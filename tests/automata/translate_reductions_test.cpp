// Each reduction of the translation pipeline preserves the language of
// arbitrary (random) automata, checked on random lasso words with the
// brute-force acceptance oracle; plus structural postconditions.
#include <gtest/gtest.h>

#include "random_automaton.hpp"
#include "rtamp/automata/degeneralize.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/reduce.hpp"
#include "rtamp/automata/simulation_reduction.hpp"

namespace rtamp::automata {
namespace {

void expect_same_language(const Automaton& a, const Automaton& b, std::mt19937_64& rng, const char* what, int id) {
  ASSERT_EQ(a.atoms, b.atoms);
  for (int k = 0; k < 100; ++k) {
    const LassoWord w = test::random_word(rng, static_cast<std::uint32_t>(a.atoms.size()));
    ASSERT_EQ(test::brute_accept(a, w), test::brute_accept(b, w)) << what << " automaton " << id << " word " << k;
  }
  // Witnesses transfer both ways.
  if (auto w = find_accepting_lasso(a)) {
    ASSERT_TRUE(test::brute_accept(b, *w)) << what << " " << id;
  }
  if (auto w = find_accepting_lasso(b)) {
    ASSERT_TRUE(test::brute_accept(a, *w)) << what << " " << id;
  }
}

TEST(Reductions, PreserveLanguage) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 3000; ++i) {
    const bool sb = i % 2 == 0;
    const auto states = static_cast<std::uint32_t>(2 + rng() % 6);  // one draw per statement
    const auto marks = static_cast<std::uint32_t>(rng() % 3);
    const Automaton orig = test::random_automaton(rng, states, 2, marks, sb, 0.3);
    Automaton a = orig;
    remove_useless(a);
    expect_same_language(orig, a, rng, "remove_useless", i);
    Automaton b = a;
    canonicalize_acceptance(b);
    expect_same_language(orig, b, rng, "canonicalize_acceptance", i);
    Automaton c = b;
    merge_parallel_edges(c);
    expect_same_language(orig, c, rng, "merge_parallel_edges", i);
    Automaton d = c;
    reduce_direct_simulation(d);
    expect_same_language(orig, d, rng, "simulation", i);
    EXPECT_LE(d.num_states(), c.num_states());
    Automaton cs = c;
    reduce_cosimulation(cs);
    expect_same_language(orig, cs, rng, "cosimulation", i);
    Automaton ns = b;
    canonicalize_acceptance(ns, false);
    expect_same_language(orig, ns, rng, "canonicalize_acceptance without saturation", i);
    if (!sb) {
      for (const Automaton& e : degeneralize_candidates(b)) {
        ASSERT_TRUE(e.state_based);
        ASSERT_EQ(e.num_sets, 1u);
        for (std::uint32_t q = 0; q < e.num_states(); ++q)
          for (const Edge& ed : e.edges[q]) ASSERT_EQ(ed.marks, e.state_accepting[q] ? 1u : 0u);
        expect_same_language(orig, e, rng, "degeneralize", i);
      }
    }
  }
}

TEST(Reductions, RemoveUselessKeepsOnlyUsefulStates) {
  std::mt19937_64 rng(4);
  for (int i = 0; i < 500; ++i) {
    const auto states = static_cast<std::uint32_t>(2 + rng() % 6);  // one draw per statement
    const auto marks = static_cast<std::uint32_t>(1 + rng() % 2);
    Automaton a = test::random_automaton(rng, states, 2, marks, false, 0.3);
    remove_useless(a);
    ASSERT_EQ(a.initial, 0u);
    if (a.num_states() == 1 && a.edges[0].empty()) {
      EXPECT_TRUE(is_empty(a));
      continue;
    }
    // Every state is reachable and non-empty from itself as initial state.
    for (std::uint32_t q = 0; q < a.num_states(); ++q) {
      Automaton b = a;
      b.initial = q;
      EXPECT_FALSE(is_empty(b)) << i << " state " << q;
    }
  }
}

TEST(Reductions, CubeCovered) {
  const Letter A = 1, B = 2, C = 4;
  EXPECT_TRUE(cube_covered(Cube{}, {Cube{A, 0}, Cube{0, A}}));
  EXPECT_FALSE(cube_covered(Cube{}, {Cube{A, 0}, Cube{0, B}}));
  EXPECT_TRUE(cube_covered(Cube{C, 0}, {Cube{A, 0}, Cube{0, A}, Cube{B, 0}}));
  EXPECT_TRUE(cube_covered(Cube{}, {Cube{A, 0}, Cube{0, A | B}, Cube{B, A}}));
  EXPECT_FALSE(cube_covered(Cube{}, {}));
  EXPECT_TRUE(cube_covered(Cube{A, A}, {}));  // a contradictory cube has no letter
}

}  // namespace
}  // namespace rtamp::automata
