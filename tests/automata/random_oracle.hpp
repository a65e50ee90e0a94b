// Randomized oracle check of the translator shared by translate_random_test
// and translate_random_slow_test: for random formulas and random lasso words,
// lasso_accept(translate(f), w) == ltl::holds(f, w), for the state-based BA
// and the TGBA, with and without reductions (and with/without simplification
// and shortcuts on odd formulas, each construction and each splitting mode on
// a share of them). The emptiness witness of every non-empty
// automaton must satisfy f, and an empty automaton must reject every word.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "oracle.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

namespace rtamp::automata {
namespace test {

inline ltl::LassoWord to_named(const Automaton& a, const LassoWord& w) {
  auto conv = [&](Letter l) {
    ltl::LassoWord::Letter s;
    for (std::size_t i = 0; i < a.atoms.size(); ++i)
      if (l >> i & 1u) s.insert(a.atoms[i]);
    return s;
  };
  ltl::LassoWord out;
  for (Letter l : w.prefix) out.prefix.push_back(conv(l));
  for (Letter l : w.cycle) out.cycle.push_back(conv(l));
  return out;
}

inline void run_random_oracle(std::uint64_t seed, int formulas, int words, std::size_t max_size = 15) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < formulas; ++i) {
    ltl::RandomFormulaOptions o;
    o.atoms = (i % 2) ? std::vector<std::string>{"a", "b", "c"} : std::vector<std::string>{"a", "b", "c", "d"};
    o.size = 1 + ltl::uniform(rng, 0, max_size - 1);
    const ltl::Formula f = ltl::random_formula(rng, o);
    const std::string text = ltl::to_string(f);
    std::vector<ltl::LassoWord> ws;
    std::vector<bool> truth;
    for (int k = 0; k < words; ++k) {
      ws.push_back(ltl::random_lasso(rng, o.atoms, 4, 4));
      truth.push_back(ltl::holds(f, ws.back()));
    }
    for (int variant = 0; variant < 4; ++variant) {
      TranslateOptions opt;
      opt.state_based = variant & 1;
      opt.reduce = variant & 2;
      opt.simplify = (i % 3) != 0;
      opt.shortcuts = (i % 5) != 0;
      opt.construction = static_cast<Construction>((i / 2) % 3);
      opt.splitting = static_cast<Splitting>((i / 6) % 3);
      Automaton a;
      try {
        a = translate(f, opt);
      } catch (const std::exception& e) {
        // Forcing the merged-destination construction (a partial subset
        // construction) may legitimately hit the size bound; the default
        // construction abandons it instead.
        if (opt.construction == Construction::MergedDestinations &&
            std::string(e.what()).find("too large") != std::string::npos)
          continue;
        FAIL() << "formula " << text << " state_based=" << opt.state_based << " reduce=" << opt.reduce
               << " construction=" << static_cast<int>(opt.construction) << ": " << e.what();
      }
      ASSERT_EQ(a.state_based, opt.state_based);
      // Output invariants (docs/translation.md).
      ASSERT_EQ(a.initial, 0u) << text;
      ASSERT_TRUE(std::is_sorted(a.atoms.begin(), a.atoms.end())) << text;
      if (opt.state_based) {
        ASSERT_EQ(a.num_sets, 1u) << text;
      }
      for (std::uint32_t q = 0; q < a.num_states(); ++q)
        for (const Edge& e : a.edges[q]) {
          ASSERT_LT(e.dst, a.num_states()) << text;
          ASSERT_FALSE(e.guard.is_false()) << text;
          ASSERT_EQ(e.marks & ~a.all_marks(), 0u) << text;
          if (opt.state_based) {
            ASSERT_EQ(e.marks, a.state_accepting[q] ? 1u : 0u) << text;
          }
        }
      for (int k = 0; k < words; ++k)
        ASSERT_EQ(lasso_accept(a, test::to_word(a, ws[k])), truth[k])
            << "formula " << text << " word " << ltl::to_string(ws[k]) << " state_based=" << opt.state_based
            << " reduce=" << opt.reduce << " states=" << a.num_states();
      const auto witness = find_accepting_lasso(a);
      if (witness) {
        ASSERT_TRUE(lasso_accept(a, *witness)) << text;
        ASSERT_TRUE(ltl::holds(f, to_named(a, *witness))) << text << " witness " << ltl::to_string(to_named(a, *witness));
      } else {
        for (int k = 0; k < words; ++k) ASSERT_FALSE(truth[k]) << text << " empty automaton, satisfiable formula";
      }
    }
  }
}

}  // namespace test
}  // namespace rtamp::automata
