// never-claim reader: the claims spin 6.5 and ltl2ba print (captured here
// verbatim), checked by their language on every short lasso against a direct
// predicate; Promela constructs (do/od loops, if/fi fall-through, skip at the
// end, atomic{...assert} matches, false); errors with line and column.
#include <gtest/gtest.h>

#include <functional>

#include "io_lasso_words.hpp"
#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/util/error.hpp"

using namespace rtamp;
using namespace rtamp::automata;
using rtamp::automata::testing::accepts;
using rtamp::automata::testing::all_lassos;

namespace {

using Letter_ = ltl::LassoWord::Letter;
bool in(const Letter_& l, const char* a) { return l.count(a) > 0; }
bool cycle_has(const ltl::LassoWord& w, const std::function<bool(const Letter_&)>& p) {
  for (const auto& l : w.cycle)
    if (p(l)) return true;
  return false;
}
// The word unrolled far enough to decide the simple properties used here.
std::vector<Letter_> unroll(const ltl::LassoWord& w) {
  std::vector<Letter_> s = w.prefix;
  for (int k = 0; k < 3; ++k) s.insert(s.end(), w.cycle.begin(), w.cycle.end());
  return s;
}
bool eventually(const ltl::LassoWord& w, const char* a) {
  for (const auto& l : unroll(w))
    if (in(l, a)) return true;
  return false;
}

void expect_language(const Automaton& a, const std::vector<std::string>& atoms,
                     const std::function<bool(const ltl::LassoWord&)>& p) {
  for (const auto& w : all_lassos(atoms, 2, 2)) ASSERT_EQ(accepts(a, w), p(w)) << "on " << ltl::to_string(w);
}

void expect_error(const std::string& text, int line, int col, const std::string& what) {
  try {
    read_never_claim(text, "claim.pml");
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "claim.pml");
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_EQ(e.where().column, col) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(NeverClaimReader, SpinResponse) {
  // spin -f '[] (p -> <> q)'
  const char* claim =
      "never  {    /* [] (p -> <> q) */\n"
      "T0_init:\n\tdo\n\t:: ((! ((p)) || (q))) -> goto accept_S20\n\t:: (1) -> goto T0_S27\n\tod;\n"
      "accept_S20:\n\tdo\n\t:: ((! ((p)) || (q))) -> goto T0_init\n\t:: (1) -> goto T0_S27\n\tod;\n"
      "accept_S27:\n\tdo\n\t:: ((q)) -> goto T0_init\n\t:: (1) -> goto T0_S27\n\tod;\n"
      "T0_S27:\n\tdo\n\t:: ((q)) -> goto accept_S20\n\t:: (1) -> goto T0_S27\n\t:: ((q)) -> goto accept_S27\n\tod;\n"
      "}\n";
  const Automaton a = read_never_claim(claim);
  EXPECT_TRUE(a.state_based);
  EXPECT_EQ(a.num_states(), 4u);
  EXPECT_EQ(a.initial, 0u);
  EXPECT_FALSE(a.state_accepting[0]);
  EXPECT_TRUE(a.state_accepting[1]);
  EXPECT_TRUE(a.state_accepting[2]);
  EXPECT_FALSE(a.state_accepting[3]);
  expect_language(a, {"p", "q"}, [](const ltl::LassoWord& w) {
    // G(p -> F q) on a lasso: q in the cycle, or no p in the cycle and every
    // p of the prefix followed by some q.
    if (cycle_has(w, [](auto& l) { return in(l, "q"); })) return true;
    if (cycle_has(w, [](auto& l) { return in(l, "p"); })) return false;
    bool pending = false;
    for (const auto& l : w.prefix) {
      if (in(l, "q")) pending = false;
      if (in(l, "p") && !in(l, "q")) pending = true;
    }
    return !pending;
  });
}

TEST(NeverClaimReader, SpinGeneralizedRecurrence) {
  // spin -f '[]<>p && []<>q'
  const char* claim =
      "never  {    /* []<>p && []<>q */\n"
      "T0_init:\n\tdo\n\t:: ((p) && (q)) -> goto accept_S81\n\t:: ((p)) -> goto T1_S81\n\t:: (1) -> goto T0_init\n\tod;\n"
      "accept_S81:\n\tdo\n\t:: (1) -> goto T0_init\n\tod;\n"
      "T1_S81:\n\tdo\n\t:: ((q)) -> goto accept_S81\n\t:: (1) -> goto T1_S81\n\tod;\n"
      "}\n";
  const Automaton a = read_never_claim(claim);
  expect_language(a, {"p", "q"}, [](const ltl::LassoWord& w) {
    return cycle_has(w, [](auto& l) { return in(l, "p"); }) && cycle_has(w, [](auto& l) { return in(l, "q"); });
  });
}

TEST(NeverClaimReader, SpinSeveralLabelsOnOneState) {
  // spin -f '[] p': accept_init and T0_init name the same state.
  const Automaton a = read_never_claim(
      "never  {    /* [] p */\naccept_init:\nT0_init:\n\tdo\n\t:: ((p)) -> goto T0_init\n\tod;\n}\n");
  EXPECT_EQ(a.num_states(), 1u);
  EXPECT_TRUE(a.state_accepting[0]);
  expect_language(a, {"p"}, [](const ltl::LassoWord& w) {
    for (const auto& l : unroll(w))
      if (!in(l, "p")) return false;
    return true;
  });
}

TEST(NeverClaimReader, SpinAssertMatchesAndAcceptAll) {
  // spin -f '<> p'
  const Automaton f = read_never_claim(
      "never  {    /* <> p */\nT0_init:\n\tdo\n\t:: atomic { ((p)) -> assert(!((p))) }\n"
      "\t:: (1) -> goto T0_init\n\tod;\naccept_all:\n\tskip\n}\n");
  EXPECT_EQ(f.num_states(), 2u);
  expect_language(f, {"p"}, [](const ltl::LassoWord& w) { return eventually(w, "p"); });
  // spin -f 'true' and spin -f 'false'
  const Automaton t = read_never_claim(
      "never  {    /* true */\naccept_init:\nT0_init:\n\tdo\n\t:: atomic { (1) -> assert(!(1)) }\n\tod;\n"
      "accept_all:\n\tskip\n}\n");
  expect_language(t, {"p"}, [](const ltl::LassoWord&) { return true; });
  const Automaton n = read_never_claim(
      "never  {    /* false */\naccept_init:\nT0_init:\n\tdo\n\t:: atomic { (false) -> assert(!(false)) }\n\tod;\n"
      "accept_all:\n\tskip\n}\n");
  expect_language(n, {"p"}, [](const ltl::LassoWord&) { return false; });
}

TEST(NeverClaimReader, Ltl2baStyleIfFiAndFalse) {
  // ltl2ba -f 'F p' style, and a claim that is just `false;`.
  const Automaton f = read_never_claim(
      "never { /* F p */\nT0_init:\n\tif\n\t:: (p) -> goto accept_all\n\t:: (1) -> goto T0_init\n\tfi;\n"
      "accept_all:\n\tskip\n}\n");
  expect_language(f, {"p"}, [](const ltl::LassoWord& w) { return eventually(w, "p"); });
  const Automaton e = read_never_claim("never { /* false */\nT0_init:\n\tfalse;\n}\n");
  expect_language(e, {"p"}, [](const ltl::LassoWord&) { return false; });
  const Automaton t = read_never_claim(
      "never { /* true */\naccept_init:\n\tif\n\t:: (1) -> goto accept_init\n\tfi;\n}\n");
  expect_language(t, {"p"}, [](const ltl::LassoWord&) { return true; });
}

TEST(NeverClaimReader, FallThroughAndEndOfClaim) {
  // `if` without goto falls through to the next statement; reaching the end
  // of the claim accepts everything: this claim accepts "p then q then anything".
  const Automaton a = read_never_claim(
      "never {\n  if :: p fi;\n  if :: q && true fi\n}\n");
  expect_language(a, {"p", "q"}, [](const ltl::LassoWord& w) {
    const auto s = unroll(w);
    return in(s[0], "p") && in(s[1], "q");
  });
  // `do` without goto loops in place: a do-loop on !p, then (p) exits.
  const Automaton b = read_never_claim("never {\nT0:\n do :: !p :: p -> goto accept_x od;\naccept_x: skip\n}\n");
  expect_language(b, {"p"}, [](const ltl::LassoWord& w) { return eventually(w, "p"); });
}

TEST(NeverClaimReader, Errors) {
  expect_error("never {\nT0_init:\n\tif\n\t:: (p) -> goto T9\n\tfi;\n}\n", 4, 17, "undefined label 'T9'");
  expect_error("never {\nT0_init:\n\tif\n\t:: (p -> goto T0_init\n\tfi;\n}\n", 4, 8, "expected ')'");
  expect_error("nevr { }", 1, 1, "expected 'never'");
  expect_error("never {\nT0_init:\n\tif\n\t:: (p) -> goto T0_init\n\tfi;\n", 6, 1, "missing '}'");
  expect_error("never {\nT0_init:\n\tif\n\t:: (2) -> goto T0_init\n\tfi;\n}", 4, 6, "integer 2");
  expect_error("never {\nA: skip;\nA: skip\n}", 3, 4, "defined twice");
  expect_error("never { if :: p $ q fi }", 1, 17, "unexpected character '$'");
  expect_error("never { if :: p fi } extra", 1, 22, "after the never claim");
  expect_error("never {\n  if fi\n}", 2, 6, "expected '::' options");
}
