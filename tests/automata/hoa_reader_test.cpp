// HOA reader: what Spot's ltl2tgba / ltl2tgba -B / autfilt print and the
// examples of the HOA v1 specification (aliases, implicit labels, state
// labels, several initial states, mixed state/transition acceptance), checked
// by their language on every short lasso against a direct predicate; and the
// errors (unsupported acceptance, universal branching, syntax) with their
// line and column.
#include <gtest/gtest.h>

#include <functional>

#include "io_lasso_words.hpp"
#include "rtamp/automata/hoa_reader.hpp"
#include "rtamp/util/error.hpp"

using namespace rtamp;
using namespace rtamp::automata;
using rtamp::automata::testing::accepts;
using rtamp::automata::testing::all_lassos;

namespace {

using Pred = std::function<bool(const ltl::LassoWord&)>;

bool in(const ltl::LassoWord::Letter& l, const char* a) { return l.count(a) > 0; }
bool cycle_has(const ltl::LassoWord& w, const std::function<bool(const ltl::LassoWord::Letter&)>& p) {
  for (const auto& l : w.cycle)
    if (p(l)) return true;
  return false;
}

void expect_language(const Automaton& a, const std::vector<std::string>& atoms, const Pred& p) {
  for (const auto& w : all_lassos(atoms, 2, 2))
    ASSERT_EQ(accepts(a, w), p(w)) << "on " << ltl::to_string(w);
}

// The language of G F a & G F b.
bool gfa_and_gfb(const ltl::LassoWord& w) {
  return cycle_has(w, [](auto& l) { return in(l, "a"); }) && cycle_has(w, [](auto& l) { return in(l, "b"); });
}

// Expects read_hoa(text) to throw an Error at line:col whose message contains `what`.
void expect_error(const std::string& text, int line, int col, const std::string& what) {
  try {
    read_hoa(text, "in.hoa");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "in.hoa");
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_EQ(e.where().column, col) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

const char* kSpotBuchiGFa =
    "HOA: v1\n"
    "name: \"G F a\"\n"
    "States: 2\n"
    "Start: 0\n"
    "AP: 1 \"a\"\n"
    "acc-name: Buchi\n"
    "Acceptance: 1 Inf(0)\n"
    "properties: trans-labels explicit-labels state-acc complete\n"
    "properties: deterministic stutter-invariant\n"
    "--BODY--\n"
    "State: 0\n"
    "[!0] 0\n"
    "[0] 1\n"
    "State: 1 {0}\n"
    "[!0] 0\n"
    "[0] 1\n"
    "--END--\n";

const char* kSpotTgba =
    "HOA: v1\n"
    "name: \"GFa & GFb\"\n"
    "States: 1\n"
    "Start: 0\n"
    "AP: 2 \"a\" \"b\"\n"
    "acc-name: generalized-Buchi 2\n"
    "Acceptance: 2 Inf(0)&Inf(1)\n"
    "properties: trans-labels explicit-labels trans-acc complete\n"
    "properties: deterministic stutter-invariant\n"
    "--BODY--\n"
    "State: 0\n"
    "[!0&!1] 0\n"
    "[0&!1] 0 {0}\n"
    "[!0&1] 0 {1}\n"
    "[0&1] 0 {0 1}\n"
    "--END--\n";

}  // namespace

TEST(HoaReader, SpotStateBasedBuchi) {
  const Automaton a = read_hoa_one(kSpotBuchiGFa);
  EXPECT_EQ(a.name, "G F a");
  EXPECT_TRUE(a.state_based);
  EXPECT_EQ(a.num_sets, 1u);
  EXPECT_EQ(a.num_states(), 2u);
  EXPECT_EQ(a.atoms, std::vector<std::string>{"a"});
  EXPECT_FALSE(a.state_accepting[0]);
  EXPECT_TRUE(a.state_accepting[1]);
  expect_language(a, {"a"}, [](const ltl::LassoWord& w) { return cycle_has(w, [](auto& l) { return in(l, "a"); }); });
}

TEST(HoaReader, SpotTransitionBasedGeneralizedBuchi) {
  const Automaton a = read_hoa_one(kSpotTgba);
  EXPECT_FALSE(a.state_based);
  EXPECT_EQ(a.num_sets, 2u);
  EXPECT_EQ(a.num_edges(), 4u);
  expect_language(a, {"a", "b"}, gfa_and_gfb);
}

// One set on edges (the form of rtamp ltl2ba --tba): transition-based with
// one set; trans-acc keeps even an automaton without marks transition-based.
TEST(HoaReader, TransitionBasedBuchi) {
  const char* tba =
      "HOA: v1\nStates: 2\nStart: 0\nAP: 2 \"a\" \"b\"\nacc-name: Buchi\nAcceptance: 1 Inf(0)\n"
      "properties: trans-labels explicit-labels trans-acc\n--BODY--\n"
      "State: 0\n[!0] 0\n[0&1] 0 {0}\n[0&!1] 1\nState: 1\n[1] 0 {0}\n[!1] 1\n--END--\n";
  const Automaton a = read_hoa_one(tba);
  EXPECT_FALSE(a.state_based);
  EXPECT_EQ(a.num_sets, 1u);
  EXPECT_EQ(a.num_states(), 2u);
  expect_language(a, {"a", "b"}, gfa_and_gfb);
  const Automaton none = read_hoa_one(
      "HOA: v1\nStates: 1\nStart: 0\nAP: 1 \"a\"\nAcceptance: 1 Inf(0)\nproperties: trans-acc\n--BODY--\n"
      "State: 0\n[t] 0\n--END--\n");
  EXPECT_FALSE(none.state_based);
  EXPECT_EQ(none.num_sets, 1u);
  expect_language(none, {"a"}, [](const ltl::LassoWord&) { return false; });
}

TEST(HoaReader, SeveralAutomataInOneStreamAndAbort) {
  const std::string text = std::string(kSpotBuchiGFa) + "HOA: v1 States: 3 --ABORT--\n" + kSpotTgba +
                           "/* trailing comment */\n";
  const auto all = read_hoa(text);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].name, "G F a");
  EXPECT_EQ(all[1].name, "GFa & GFb");
  EXPECT_THROW(read_hoa_one(text), Error);
}

TEST(HoaReader, AliasesArbitraryLabelsCommentsAndEscapes) {
  // a U (b & c), written with aliases, a disjunctive label, nested comments
  // and an escaped atom name.
  const char* text =
      "HOA: v1 /* nested /* comment */ here */\n"
      "name: \"a U \\\"bc\\\"\"\n"
      "States: 2 Start: 0 AP: 3 \"a\" \"b\" \"c\"\n"
      "Alias: @a 0\n"
      "Alias: @bc 1 & 2\n"
      "acc-name: Buchi Acceptance: 1 Inf(0)\n"
      "tool: \"handwritten\" \"1.0\"\n"
      "--BODY--\n"
      "State: 0 \"start\"\n"
      "[@a & !@bc] 0\n"
      "[!(!@bc) | f] 1\n"
      "State: 1 {0}\n"
      "[t] 1\n"
      "--END--\n";
  const Automaton a = read_hoa_one(text);
  EXPECT_EQ(a.name, "a U \"bc\"");
  EXPECT_EQ(a.num_edges(), 4u);  // [@a & !@bc] is a&!b | a&!c: two cubes
  expect_language(a, {"a", "b", "c"}, [](const ltl::LassoWord& w) {
    std::vector<ltl::LassoWord::Letter> seq = w.prefix;
    for (int k = 0; k < 3; ++k) seq.insert(seq.end(), w.cycle.begin(), w.cycle.end());
    for (const auto& l : seq) {
      if (in(l, "b") && in(l, "c")) return true;
      if (!in(l, "a")) return false;
    }
    return false;  // cycle all a & !(b&c)
  });
}

TEST(HoaReader, ImplicitLabelsAndTransitionAcceptance) {
  // The specification's "TGBA with implicit labels" example.
  const char* text =
      "HOA: v1\nname: \"GFa & GFb\"\nStates: 1\nStart: 0\nacc-name: generalized-Buchi 2\n"
      "Acceptance: 2 (Inf(0) & Inf(1))\nAP: 2 \"a\" \"b\"\n--BODY--\n"
      "State: 0\n 0 /* !a & !b */\n 0 {0} /* a & !b */\n 0 {1}\n 0 {0 1}\n--END--\n";
  const Automaton a = read_hoa_one(text);
  EXPECT_EQ(a.num_sets, 2u);
  expect_language(a, {"a", "b"}, gfa_and_gfb);
}

TEST(HoaReader, StateLabelsAndSeveralInitialStates) {
  // The specification's Wring-style state-labelled BA for G F a.
  const char* text =
      "HOA: v1\nname: \"GFa\"\nStates: 2\nStart: 0\nStart: 1\nacc-name: Buchi\nAcceptance: 1 Inf(0)\n"
      "AP: 1 \"a\"\n--BODY--\nState: [0] 0 {0}\n  0 1\nState: [!0] 1\n  0 1\n--END--\n";
  const Automaton a = read_hoa_one(text);
  EXPECT_TRUE(a.state_based);
  EXPECT_EQ(a.num_states(), 3u);  // a fresh initial state joins the two
  expect_language(a, {"a"}, [](const ltl::LassoWord& w) { return cycle_has(w, [](auto& l) { return in(l, "a"); }); });
}

TEST(HoaReader, MixedStateAndTransitionAcceptance) {
  // The specification's GFa | G(b <-> Xa), without States: (deduced).
  const char* text =
      "HOA: v1\nname: \"GFa | G(b <-> Xa)\"\nStart: 0\nacc-name: Buchi\nAcceptance: 1 Inf(0)\n"
      "AP: 2 \"a\" \"b\"\nproperties: explicit-labels trans-labels\n--BODY--\n"
      "State: 0\n [t] 1\n [1] 2\n [!1] 3\n"
      "State: 1 \"GFa\"\n [0] 1 {0}\n [!0] 1\n"
      "State: 2 \"a & G(b <-> Xa)\" {0}\n [0&1] 2\n [0&!1] 3\n"
      "State: 3 \"!a & G(b <-> Xa)\" {0}\n [!0&1] 2\n [!0&!1] 3\n--END--\n";
  const Automaton a = read_hoa_one(text);
  EXPECT_FALSE(a.state_based);  // edge marks: transition-based
  EXPECT_EQ(a.num_states(), 4u);
  expect_language(a, {"a", "b"}, [](const ltl::LassoWord& w) {
    if (cycle_has(w, [](auto& l) { return in(l, "a"); })) return true;
    // G(b <-> X a) on u v^ω: check positions 0 .. |u|+2|v|.
    std::vector<ltl::LassoWord::Letter> seq = w.prefix;
    for (int k = 0; k < 3; ++k) seq.insert(seq.end(), w.cycle.begin(), w.cycle.end());
    for (std::size_t i = 0; i + 1 < seq.size(); ++i)
      if (in(seq[i], "b") != in(seq[i + 1], "a")) return false;
    return true;
  });
}

TEST(HoaReader, TrivialAcceptanceAndUnusedSets) {
  // t: every run accepts (read as a BA whose states all accept).
  const Automaton t = read_hoa_one(
      "HOA: v1 States: 1 Start: 0 AP: 1 \"a\" acc-name: all Acceptance: 0 t --BODY-- State: 0 [0] 0 --END--");
  EXPECT_TRUE(t.state_based);
  expect_language(t, {"a"}, [](const ltl::LassoWord& w) {
    for (auto& l : w.prefix)
      if (!in(l, "a")) return false;
    return !cycle_has(w, [](auto& l) { return !in(l, "a"); });
  });
  // f: nothing accepts.
  const Automaton f = read_hoa_one(
      "HOA: v1 States: 1 Start: 0 AP: 0 Acceptance: 1 Inf(0)&f --BODY-- State: 0 {0} [t] 0 --END--");
  expect_language(f, {"a"}, [](const ltl::LassoWord&) { return false; });
  // Set 0 declared but unused; set 1 is the Büchi set.
  const Automaton u = read_hoa_one(
      "HOA: v1 States: 1 Start: 0 AP: 1 \"a\" Acceptance: 2 Inf(1) --BODY-- State: 0 [0] 0 {0 1} [!0] 0 {0} --END--");
  EXPECT_EQ(u.num_sets, 1u);
  expect_language(u, {"a"}, [](const ltl::LassoWord& w) { return cycle_has(w, [](auto& l) { return in(l, "a"); }); });
  // No Start: the empty language.
  const Automaton e = read_hoa_one("HOA: v1 States: 1 AP: 0 Acceptance: 0 t --BODY-- State: 0 [t] 0 --END--");
  expect_language(e, {"a"}, [](const ltl::LassoWord&) { return false; });
  // States: 0.
  const Automaton z = read_hoa_one("HOA: v1 States: 0 Acceptance: 0 t --BODY-- --END--");
  EXPECT_EQ(z.num_states(), 1u);
  EXPECT_TRUE(z.edges[0].empty());
}

TEST(HoaReader, UnsupportedFeaturesAreClearErrors) {
  expect_error("HOA: v1\nStates: 1\nAcceptance: 1 Fin(0)\n--BODY--\n--END--\n", 3, 15, "Fin acceptance");
  expect_error("HOA: v1\nAcceptance: 2 Inf(0) | Inf(1)\n--BODY--\n--END--\n", 2, 22, "disjunctive");
  expect_error("HOA: v1\nAcceptance: 1 Inf(!0)\n--BODY--\n--END--\n", 2, 19, "Inf(!i)");
  expect_error("HOA: v1\nStart: 0&1\nAcceptance: 0 t\n--BODY--\n--END--\n", 2, 9, "universal branching");
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 1 \"a\"\n--BODY--\nState: 0\n[0] 0&0\n--END--\n", 6, 6,
               "universal branching");
  expect_error("HOA: v2\nAcceptance: 0 t\n--BODY--\n--END--\n", 1, 6, "version");
  expect_error("HOA: v1\nFoo: 1\nAcceptance: 0 t\n--BODY--\n--END--\n", 2, 1, "unsupported header item 'Foo:'");
}

TEST(HoaReader, SyntaxErrorsNameLineAndColumn) {
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 1 \"a\"\n--BODY--\nState: 0\n[0 & 1] 0\n--END--\n", 6, 6,
               "atomic proposition 1 out of range");
  expect_error("HOA: v1\nAcceptance: 0 t\n--BODY--\nState: 0\n[@x] 0\n--END--\n", 5, 2, "undefined alias '@x'");
  expect_error("HOA: v1\nStates: 1\nAcceptance: 0 t\n--BODY--\nState: 0\n[t] 1\n--END--\n", 6, 5,
               "state 1 out of range");
  expect_error("HOA: v1\nAcceptance: 0 t\n--BODY--\nState: 0\nState: 0\n--END--\n", 5, 8, "defined twice");
  expect_error("HOA: v1\nAcceptance: 0 t\nname: \"abc\n", 3, 7, "unterminated string");
  expect_error("HOA: v1\nAcceptance: 0 t /* open\n", 2, 17, "unterminated comment");
  expect_error("HOA: v1\nAP: 1 \"a\"\n--BODY--\n--END--\n", 1, 1, "missing 'Acceptance:'");
  expect_error("HOA: v1\nAcceptance: 1 Inf(0)\nAP: 1 \"a\"\n--BODY--\nState: 0 {1}\n--END--\n", 5, 11,
               "acceptance set 1 out of range");
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 2 \"a\"\n--BODY--\n--END--\n", 4, 1, "expected string");
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 2 \"a\" \"a\"\n--BODY--\n--END--\n", 3, 11, "declared twice");
  // Names leave rtamp as Python str and JSON: a string that is not UTF-8 is refused where it is.
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 1 \"a\xff\"\n--BODY--\n--END--\n", 3, 7, "not UTF-8 (byte 2");
  expect_error("HOA: v1\nname: \"\xc0\xaf\"\nAcceptance: 0 t\n--BODY--\n--END--\n", 2, 7, "not UTF-8 (byte 1");
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 1 \"a\"\n--BODY--\nState: 0\n0 0 0\n--END--\n", 5, 8,
               "implicit labels need exactly 2^1 = 2");
  expect_error("HOA: v1\nAcceptance: 0 t\nAP: 1 \"a\"\n--BODY--\nState: 0\n[0] 0 0\n--END--\n", 6, 7,
               "mixes labelled and unlabelled");
  expect_error("HOA: v1\nAcceptance: 0 t\n--BODY--\nState: 0\n[t] 0\n", 6, 1, "expected 'State:' or --END--");
  expect_error("HOA: v1\nAcceptance: 0 t\n--BODY--\nState: 0 # 0\n--END--\n", 4, 10, "unexpected character '#'");
  expect_error("HOA: v1\nAcceptance: 0 t\nStates: 99999999999\n", 3, 9, "integer too large");
}

TEST(HoaReader, DeepNestingIsAnErrorNotACrash) {
  std::string text = "HOA: v1 Acceptance: 0 t AP: 1 \"a\" --BODY-- State: 0 [";
  for (int i = 0; i < 5000; ++i) text += '(';
  text += "0";
  for (int i = 0; i < 5000; ++i) text += ')';
  text += "] 0 --END--";
  EXPECT_THROW(read_hoa(text), Error);
}

TEST(HoaReader, AliasBlowUpIsAnErrorAndLongDisjunctionsAreFine) {
  // Each alias doubles the previous one: expanding @a40 would need 2^40 nodes.
  std::string text = "HOA: v1 Acceptance: 0 t AP: 1 \"a\"\nAlias: @a0 0\n";
  for (int i = 1; i <= 40; ++i)
    text += "Alias: @a" + std::to_string(i) + " @a" + std::to_string(i - 1) + " & @a" + std::to_string(i - 1) + "\n";
  EXPECT_THROW(read_hoa(text + "--BODY-- --END--"), Error);
  // A disjunction of 4096 distinct cubes over 12 APs: every letter, read in one label.
  std::string big = "HOA: v1 States: 1 Start: 0 Acceptance: 0 t AP: 12";
  for (int i = 0; i < 12; ++i) big += " \"p" + std::to_string(i) + "\"";
  big += " --BODY-- State: 0 [";
  for (int v = 0; v < 4096; ++v) {
    if (v) big += " | ";
    for (int i = 0; i < 12; ++i) big += std::string(i ? "&" : "") + ((v >> i & 1) ? "" : "!") + std::to_string(i);
  }
  big += "] 0 --END--";
  const Automaton a = read_hoa_one(big);
  EXPECT_EQ(a.num_edges(), 4096u);
}
