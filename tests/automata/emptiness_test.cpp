// Emptiness check: agrees with a brute-force search on random automata, and
// every witness is accepted (by lasso_accept and the brute-force oracle).
#include "rtamp/automata/emptiness.hpp"

#include <gtest/gtest.h>

#include "random_automaton.hpp"

namespace rtamp::automata {
namespace {

// Non-empty iff some reachable state q has a non-empty cycle through q that
// collects every mark; search over (state, collected marks).
bool brute_nonempty(const Automaton& a) {
  std::set<std::uint32_t> reach{a.initial};
  std::deque<std::uint32_t> todo{a.initial};
  while (!todo.empty()) {
    const std::uint32_t q = todo.front();
    todo.pop_front();
    for (const Edge& e : a.edges[q])
      if (!e.guard.is_false() && reach.insert(e.dst).second) todo.push_back(e.dst);
  }
  const Marks all = a.all_marks();
  for (std::uint32_t v : reach) {
    std::set<std::pair<std::uint32_t, Marks>> seen;
    std::deque<std::pair<std::uint32_t, Marks>> q2;
    auto push = [&](std::uint32_t n, Marks m) {
      if (seen.insert({n, m}).second) q2.push_back({n, m});
    };
    for (const Edge& e : a.edges[v])
      if (!e.guard.is_false()) push(e.dst, e.marks & all);
    while (!q2.empty()) {
      auto [n, m] = q2.front();
      q2.pop_front();
      if (n == v && m == all) return true;
      for (const Edge& e : a.edges[n])
        if (!e.guard.is_false()) push(e.dst, (m | e.marks) & all);
    }
  }
  return false;
}

TEST(Emptiness, EmptyAndNonEmpty) {
  Automaton a;
  a.atom_index("a");
  a.num_sets = 1;
  a.add_state();
  a.add_state();
  a.add_edge(0, 1, Cube{1, 0}, 0);
  a.add_edge(1, 1, Cube{}, 0);
  EXPECT_TRUE(is_empty(a));
  a.add_edge(1, 0, Cube{0, 1}, 1);
  const auto w = find_accepting_lasso(a);
  ASSERT_TRUE(w.has_value());
  EXPECT_TRUE(lasso_accept(a, *w));
  EXPECT_FALSE(w->cycle.empty());
}

TEST(Emptiness, NoStatesOrNoEdges) {
  Automaton a;
  EXPECT_TRUE(is_empty(a));
  a.add_state();
  EXPECT_TRUE(is_empty(a));
}

TEST(Emptiness, MatchesBruteForce) {
  std::mt19937_64 rng(5);
  int nonempty = 0;
  for (int i = 0; i < 4000; ++i) {
    const bool sb = i % 3 == 0;
    const auto states = static_cast<std::uint32_t>(1 + rng() % 7);  // one draw per statement
    const auto marks = static_cast<std::uint32_t>(rng() % 4);
    const Automaton a = test::random_automaton(rng, states, 2, marks, sb, 0.25);
    const auto w = find_accepting_lasso(a);
    ASSERT_EQ(w.has_value(), brute_nonempty(a)) << "automaton " << i;
    if (w) {
      ++nonempty;
      ASSERT_FALSE(w->cycle.empty());
      ASSERT_TRUE(lasso_accept(a, *w)) << "automaton " << i;
      ASSERT_TRUE(test::brute_accept(a, *w)) << "automaton " << i;
    }
  }
  EXPECT_GT(nonempty, 500);  // the generator exercises both outcomes
  EXPECT_LT(nonempty, 3500);
}

}  // namespace
}  // namespace rtamp::automata
