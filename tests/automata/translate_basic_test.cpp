// Hand-written formulas and words: the translator against ltl::holds.
#include <gtest/gtest.h>

#include "oracle.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::automata {
namespace {

using ltl::Formula;

std::vector<ltl::LassoWord> all_small_words(const std::vector<std::string>& atoms) {
  // Every word with prefix length <= 1 and cycle length <= 2 over the atoms.
  std::vector<ltl::LassoWord::Letter> letters;
  for (unsigned m = 0; m < (1u << atoms.size()); ++m) {
    ltl::LassoWord::Letter l;
    for (std::size_t i = 0; i < atoms.size(); ++i)
      if (m >> i & 1u) l.insert(atoms[i]);
    letters.push_back(l);
  }
  std::vector<ltl::LassoWord> out;
  std::vector<std::vector<ltl::LassoWord::Letter>> prefixes{{}};
  for (const auto& l : letters) prefixes.push_back({l});
  for (const auto& p : prefixes) {
    for (const auto& c1 : letters) {
      out.push_back({p, {c1}});
      for (const auto& c2 : letters) out.push_back({p, {c1, c2}});
    }
  }
  return out;
}

void check(const std::string& text) {
  const Formula f = ltl::parse(text);
  const auto words = all_small_words({"a", "b", "c"});
  for (bool sb : {true, false})
    for (bool red : {true, false}) {
      TranslateOptions opt;
      opt.state_based = sb;
      opt.reduce = red;
      const Automaton a = translate(f, opt);
      for (const auto& w : words)
        ASSERT_EQ(lasso_accept(a, test::to_word(a, w)), ltl::holds(f, w))
            << text << " sb=" << sb << " reduce=" << red << " word " << ltl::to_string(w);
    }
}

TEST(TranslateBasic, Shapes) {
  for (const char* s : {"a", "!a", "a & b", "a | b", "true", "false", "G a", "F a", "G F a", "F G a", "X a", "a U b",
                        "a R b", "a W b", "a M b", "G(a -> F b)", "F a & F b", "G F a & G F b", "F G a | G F b",
                        "(a U b) U c", "X X a", "G(a -> X b)", "!(a U b)", "a <-> X b", "a xor F b",
                        "G F a -> G F b", "F(a & X(b U c))", "(G F a & G F b) -> G F c",
                        // weak operators in disguise (vwaa.cpp weak_disjunction) and near misses
                        "(a U b) | G a", "(a M b) | G b", "G !a | F(a & F b)", "G a | F(!a & F b & G F c)",
                        "G a | F(!a & b)", "G !a | F(a & (b W c))", "G a | F !a", "c | (a U b) | G a | G b",
                        "G !b | (a U b)", "G(!c | (a U b) | G a)"})
    check(s);
}

TEST(TranslateBasic, Sizes) {
  auto states = [](const char* s, bool sb) {
    TranslateOptions o;
    o.state_based = sb;
    return translate(ltl::parse(s), o).num_states();
  };
  EXPECT_EQ(states("G F a", false), 1u);
  EXPECT_EQ(states("G F a", true), 2u);
  EXPECT_EQ(states("F G a", true), 2u);
  EXPECT_EQ(states("G a", true), 1u);
  EXPECT_EQ(states("F a", true), 2u);
  EXPECT_EQ(states("a U b", true), 2u);
}

TEST(TranslateBasic, AtomsSortedAndName) {
  const Automaton a = translate(ltl::parse("G(c -> F b) & a"));
  EXPECT_EQ(a.atoms, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_FALSE(a.name.empty());
  EXPECT_TRUE(a.state_based);
  EXPECT_EQ(a.num_sets, 1u);
}

TEST(TranslateBasic, EmptyLanguageIsOneStateWithoutEdges) {
  for (const char* text : {"a & !a", "G a & F !a", "false", "G F a & F G !a", "X(a & !a)"})
    for (bool sb : {true, false}) {
      TranslateOptions o;
      o.state_based = sb;
      const Automaton a = translate(ltl::parse(text), o);
      EXPECT_EQ(a.num_states(), 1u) << text;
      EXPECT_EQ(a.num_edges(), 0u) << text;
    }
}

TEST(TranslateBasic, TrueIsOneAcceptingLoop) {
  const Automaton a = translate(ltl::parse("true"));
  ASSERT_EQ(a.num_states(), 1u);
  ASSERT_EQ(a.num_edges(), 1u);
  EXPECT_TRUE(a.is_accepting_state(0));
  EXPECT_TRUE(a.edges[0][0].guard.is_true());
}

TEST(TranslateBasic, SafetyHasEveryStateAccepting) {
  for (const char* text : {"G(a -> X b)", "a W b", "G(a | X X b)", "a R (b | c)"}) {
    const Automaton ba = translate(ltl::parse(text));
    for (std::uint32_t q = 0; q < ba.num_states(); ++q) EXPECT_TRUE(ba.is_accepting_state(q)) << text;
    TranslateOptions o;
    o.state_based = false;
    EXPECT_EQ(translate(ltl::parse(text), o).num_sets, 0u) << text;
  }
}

TEST(TranslateBasic, LimitsAreErrors) {
  std::vector<Formula> many;
  for (int i = 0; i < 65; ++i) many.push_back(Formula::atom("p" + std::to_string(i)));
  EXPECT_THROW(translate(Formula::And(many)), Error);
  std::vector<Formula> evs;
  for (int i = 0; i < 33; ++i) evs.push_back(Formula::F(Formula::atom("p" + std::to_string(i))));
  EXPECT_THROW(translate(Formula::And(evs)), Error);
  // 14 independent eventualities: 3^14 edges, over the bound.
  std::vector<Formula> fs;
  for (int i = 0; i < 14; ++i) fs.push_back(Formula::F(Formula::atom("p" + std::to_string(i))));
  EXPECT_THROW(translate(Formula::And(fs)), Error);
}

}  // namespace
}  // namespace rtamp::automata
