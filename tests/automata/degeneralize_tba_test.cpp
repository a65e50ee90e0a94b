// degeneralize_tba and state_based_form keep the language (brute-force
// acceptance on random lasso words) of random TGBAs with 0..3 sets and of
// random state-based automata; translate's one_set gives a one-set
// transition-based automaton of the formula's models (direct LTL semantics)
// that the HOA writer and reader carry unchanged.
#include <gtest/gtest.h>

#include <random>

#include "io_lasso_words.hpp"
#include "random_automaton.hpp"
#include "rtamp/automata/degeneralize_tba.hpp"
#include "rtamp/automata/hoa_reader.hpp"
#include "rtamp/automata/hoa_writer.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

using namespace rtamp;
using namespace rtamp::automata;

TEST(DegeneralizeTba, RandomAutomataKeepTheirLanguage) {
  std::mt19937_64 rng(31);
  for (int i = 0; i < 400; ++i) {
    const auto states = static_cast<std::uint32_t>(1 + rng() % 5);
    const auto sets = static_cast<std::uint32_t>(rng() % 4);
    const bool sb = i % 4 == 0;
    const Automaton a = test::random_automaton(rng, states, 2, sets, sb, 0.4);
    const Automaton t = degeneralize_tba(a);
    ASSERT_FALSE(t.state_based);
    ASSERT_EQ(t.num_sets, 1u);
    const Automaton b = state_based_form(t);
    ASSERT_TRUE(b.state_based);
    ASSERT_EQ(b.initial, t.initial);
    for (int k = 0; k < 100; ++k) {
      const LassoWord w = test::random_word(rng, 2);
      const bool want = test::brute_accept(a, w);
      ASSERT_EQ(test::brute_accept(t, w), want) << "trial " << i << "\n" << to_hoa(a) << to_hoa(t);
      ASSERT_EQ(test::brute_accept(b, w), want) << "trial " << i << "\n" << to_hoa(t) << to_hoa(b);
    }
  }
}

TEST(DegeneralizeTba, TranslatedFormulasRoundTripThroughHoa) {
  std::mt19937_64 rng(32);
  ltl::RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  TranslateOptions one;
  one.state_based = false;
  one.one_set = true;
  for (int i = 0; i < 200; ++i) {
    opt.size = static_cast<std::size_t>(ltl::uniform(rng, 3, 14));
    const ltl::Formula f = ltl::random_formula(rng, opt);
    const Automaton a = translate(f, one);
    SCOPED_TRACE(ltl::to_string(f) + "\n" + to_hoa(a));
    ASSERT_FALSE(a.state_based);
    ASSERT_EQ(a.num_sets, 1u);
    const std::string text = to_hoa(a);
    const Automaton back = read_hoa_one(text);
    EXPECT_EQ(to_hoa(back), text);
    for (int k = 0; k < 100; ++k) {
      const ltl::LassoWord w = ltl::random_lasso(rng, opt.atoms, 3, 4);
      const bool want = ltl::holds(f, w);
      ASSERT_EQ(automata::testing::accepts(a, w), want) << ltl::to_string(w);
      ASSERT_EQ(automata::testing::accepts(back, w), want) << ltl::to_string(w);
    }
  }
}

// Acceptance waits on an edge instead of a state: the patrols take one state
// fewer than state-based.
TEST(DegeneralizeTba, PatrolsAreSmallerThanStateBased) {
  TranslateOptions one;
  one.state_based = false;
  one.one_set = true;
  for (const char* f : {"G F a & G F b", "G F a & G F b & G F c"}) {
    const ltl::Formula p = ltl::parse(f);
    EXPECT_LT(translate(p, one).num_states(), translate(p).num_states()) << f;
  }
}
