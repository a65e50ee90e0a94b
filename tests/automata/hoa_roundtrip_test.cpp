// Round trips: automaton -> HOA text -> automaton (and -> never claim ->
// automaton for state-based ones) keeps the language, checked with
// lasso_accept on random lasso words, for random hand-made automata (BA and
// TGBA with 0..3 sets) and for translated random LTL formulas.
#include <gtest/gtest.h>

#include <random>

#include "io_lasso_words.hpp"
#include "rtamp/automata/hoa_reader.hpp"
#include "rtamp/automata/hoa_writer.hpp"
#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/automata/never_claim_writer.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

using namespace rtamp;
using namespace rtamp::automata;
using rtamp::automata::testing::accepts;

namespace {

Automaton random_automaton(std::mt19937_64& rng, bool state_based) {
  auto pick = [&](std::uint64_t lo, std::uint64_t hi) { return ltl::uniform(rng, lo, hi); };
  Automaton a;
  const auto natoms = pick(1, 3);
  for (std::uint64_t i = 0; i < natoms; ++i) a.atoms.push_back(std::string(1, static_cast<char>('a' + i)));
  a.state_based = state_based;
  a.num_sets = state_based ? 1 : static_cast<std::uint32_t>(pick(0, 3));
  const auto n = static_cast<std::uint32_t>(pick(1, 6));
  for (std::uint32_t q = 0; q < n; ++q) a.add_state(state_based && pick(0, 2) == 0);
  for (std::uint32_t q = 0; q < n; ++q) {
    const auto ne = pick(0, 4);
    for (std::uint64_t k = 0; k < ne; ++k) {
      Cube c;
      for (std::uint64_t i = 0; i < natoms; ++i) {
        const auto r = pick(0, 2);
        if (r == 1) c.pos |= Letter{1} << i;
        if (r == 2) c.neg |= Letter{1} << i;
      }
      const auto to = static_cast<std::uint32_t>(pick(0, n - 1));  // one draw per statement
      a.add_edge(q, to, c, static_cast<Marks>(pick(0, a.all_marks())));
    }
  }
  a.initial = static_cast<std::uint32_t>(pick(0, n - 1));
  return a;
}

void expect_same_language(const Automaton& x, const Automaton& y, std::mt19937_64& rng, const std::string& what) {
  std::vector<std::string> atoms = x.atoms;
  for (const auto& p : y.atoms)
    if (std::find(atoms.begin(), atoms.end(), p) == atoms.end()) atoms.push_back(p);
  for (int i = 0; i < 200; ++i) {
    const ltl::LassoWord w = ltl::random_lasso(rng, atoms, 3, 4);
    ASSERT_EQ(accepts(x, w), accepts(y, w)) << what << " on " << ltl::to_string(w);
  }
}

}  // namespace

TEST(HoaRoundTrip, RandomStateBasedAutomata) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 300; ++i) {
    const Automaton a = random_automaton(rng, true);
    const std::string text = to_hoa(a);
    const Automaton b = read_hoa_one(text);
    EXPECT_TRUE(b.state_based);
    EXPECT_EQ(b.num_states(), a.num_states()) << text;
    EXPECT_EQ(b.initial, a.initial);
    EXPECT_EQ(b.atoms, a.atoms);
    for (std::uint32_t q = 0; q < a.num_states(); ++q) EXPECT_EQ(b.state_accepting[q], a.state_accepting[q]);
    expect_same_language(a, b, rng, text);
    EXPECT_EQ(to_hoa(b), text) << "writing the re-read automaton gives the same text";
  }
}

TEST(HoaRoundTrip, RandomTransitionBasedAutomata) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 300; ++i) {
    const Automaton a = random_automaton(rng, false);
    const std::string text = to_hoa(a);
    const Automaton b = read_hoa_one(text);
    EXPECT_EQ(b.num_states(), a.num_states()) << text;
    if (a.num_sets == 0) {
      EXPECT_TRUE(b.state_based) << "acceptance t is read as a BA whose states all accept";
    } else {  // one set without marks too: the writer says trans-acc
      EXPECT_FALSE(b.state_based);
      EXPECT_EQ(b.num_sets, a.num_sets);
    }
    expect_same_language(a, b, rng, text);
  }
}

TEST(HoaRoundTrip, TranslatedRandomFormulasBaAndTgba) {
  std::mt19937_64 rng(3);
  ltl::RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  for (int i = 0; i < 150; ++i) {
    opt.size = static_cast<std::size_t>(ltl::uniform(rng, 3, 14));
    const ltl::Formula f = ltl::random_formula(rng, opt);
    for (bool sb : {true, false}) {
      TranslateOptions to;
      to.state_based = sb;
      const Automaton a = translate(f, to);
      const Automaton b = read_hoa_one(to_hoa(a));
      EXPECT_EQ(b.name, ltl::to_string(f));
      expect_same_language(a, b, rng, ltl::to_string(f) + (sb ? " (BA)" : " (TGBA)"));
    }
  }
}

TEST(NeverClaimRoundTrip, TranslatedRandomFormulas) {
  std::mt19937_64 rng(4);
  ltl::RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  for (int i = 0; i < 150; ++i) {
    opt.size = static_cast<std::size_t>(ltl::uniform(rng, 3, 14));
    const ltl::Formula f = ltl::random_formula(rng, opt);
    const Automaton a = translate(f);
    const std::string claim = to_never_claim(a);
    const Automaton b = read_never_claim(claim);
    EXPECT_EQ(b.num_states(), a.num_states()) << claim;
    expect_same_language(a, b, rng, claim);
  }
}

TEST(NeverClaimRoundTrip, RandomStateBasedAutomata) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 300; ++i) {
    const Automaton a = random_automaton(rng, true);
    const std::string claim = to_never_claim(a);
    expect_same_language(a, read_never_claim(claim), rng, claim);
  }
}
