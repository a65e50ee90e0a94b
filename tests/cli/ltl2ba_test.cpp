// `rtamp ltl2ba`: runs the built binary and checks what it prints with the
// library's readers (HOA, never claim) against the direct LTL semantics on
// random lassos; -F files (comments, blank lines, stdin, bad lines reported
// with file:line:column while the others are still translated, exit 2);
// --format stats/dot; --gba; --tba (read back: one set on edges, the
// language, the same text when written again); --help; bad options.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "../automata/io_lasso_words.hpp"
#include "rtamp/automata/hoa_reader.hpp"
#include "rtamp/automata/hoa_writer.hpp"
#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"
#include "run_cli.hpp"

using namespace rtamp;
using rtamp::automata::testing::accepts;
using rtamp::cli::testing::run;
using rtamp::cli::testing::write_file;

namespace {

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void expect_models(const automata::Automaton& a, const std::string& formula, std::uint64_t seed) {
  const ltl::Formula f = ltl::parse(formula);
  std::mt19937_64 rng(seed);
  std::vector<std::string> atoms = a.atoms;
  if (atoms.empty()) atoms = {"a"};
  for (int i = 0; i < 300; ++i) {
    const ltl::LassoWord w = ltl::random_lasso(rng, atoms, 3, 4);
    ASSERT_EQ(accepts(a, w), ltl::holds(f, w)) << formula << " on " << ltl::to_string(w);
  }
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string l;
  while (std::getline(in, l)) out.push_back(l);
  return out;
}

}  // namespace

TEST(CliLtl2ba, DefaultIsStateBasedHoaWithTheRightLanguage) {
  for (const std::string f : {"G(p -> F q)", "[]<>a && <>[]!b", "a U (b R c)", "F G \"o1 in r2\""}) {
    const auto r = run("ltl2ba " + quote(f));
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_NE(r.out.find("acc-name: Buchi\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("state-acc"), std::string::npos) << r.out;
    const automata::Automaton a = automata::read_hoa_one(r.out);
    EXPECT_TRUE(a.state_based);
    EXPECT_EQ(a.name, ltl::to_string(ltl::parse(f)));
    expect_models(a, f, 1);
  }
}

TEST(CliLtl2ba, GbaIsTransitionBased) {
  const auto r = run("ltl2ba --gba 'G F a & G F b & G F c'");
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("trans-acc"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("acc-name: generalized-Buchi 3\nAcceptance: 3 Inf(0)&Inf(1)&Inf(2)\n"), std::string::npos)
      << r.out;
  const automata::Automaton a = automata::read_hoa_one(r.out);
  EXPECT_FALSE(a.state_based);
  EXPECT_EQ(a.num_sets, 3u);
  expect_models(a, "G F a & G F b & G F c", 2);
}

TEST(CliLtl2ba, TbaIsTransitionBasedWithOneSetAndRoundTrips) {
  const std::vector<std::string> formulas = {"G F a & G F b", "G F a & G F b & G F c", "F (a & F G b)",
                                             "G (a -> F b)", "F G a | G F b", "a U (b R c)"};
  std::string all;
  for (const auto& f : formulas) all += " " + quote(f);
  const auto r = run("ltl2ba --tba" + all);
  ASSERT_EQ(r.rc, 0) << r.err;
  std::size_t at = 0;
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    const std::size_t end = r.out.find("--END--\n", at) + 8;
    const std::string text = r.out.substr(at, end - at);
    at = end;
    SCOPED_TRACE(formulas[i] + "\n" + text);
    EXPECT_NE(text.find("acc-name: Buchi\nAcceptance: 1 Inf(0)\n"), std::string::npos);
    EXPECT_NE(text.find("trans-acc"), std::string::npos);
    EXPECT_NE(text.find(" {0}\n"), std::string::npos) << "marks on edges";
    const automata::Automaton a = automata::read_hoa_one(text);
    EXPECT_FALSE(a.state_based);
    EXPECT_EQ(a.num_sets, 1u);
    EXPECT_EQ(automata::to_hoa(a), text) << "writing what was read gives the same text";
    expect_models(a, formulas[i], 10 + i);
  }
  // Smaller than the state-based automaton where acceptance waits on edges.
  const automata::Automaton tba = automata::read_hoa_one(run("ltl2ba --tba 'G F a & G F b'").out);
  const automata::Automaton ba = automata::read_hoa_one(run("ltl2ba 'G F a & G F b'").out);
  EXPECT_LT(tba.num_states(), ba.num_states());
}

TEST(CliLtl2ba, TbaRefusesWhatItCannotCombineWith) {
  const auto g = run("ltl2ba --tba --gba 'F a'");
  EXPECT_EQ(g.rc, 2);
  EXPECT_EQ(g.err, "rtamp: error: --gba and --tba exclude each other: choose one acceptance form\n");
  EXPECT_TRUE(g.out.empty()) << g.out;
  const auto n = run("ltl2ba --tba --format never 'F a'");
  EXPECT_EQ(n.rc, 2);
  EXPECT_EQ(n.err, "rtamp: error: --format never needs a state-based Büchi automaton: drop --tba\n");
}

TEST(CliLtl2ba, NoSimplifyNoReduceKeepTheLanguage) {
  const std::string f = "G(a -> X(b U c)) & F G !a";
  const auto r = run("ltl2ba --no-simplify --no-reduce " + quote(f));
  ASSERT_EQ(r.rc, 0) << r.err;
  expect_models(automata::read_hoa_one(r.out), f, 3);
}

TEST(CliLtl2ba, FileInputInOrderWithCommentsAndBlankLines) {
  const std::vector<std::string> formulas = {"F a", "G(a -> F b)", "a U b", "[]<>a", "G !a & F a"};
  std::string text = "# a comment\n\n";
  for (const auto& f : formulas) text += f + "\n   # indented comment\n\n";
  const std::string path = write_file("formulas.ltl", text);
  const auto r = run("ltl2ba -F " + quote(path));
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto all = automata::read_hoa(r.out);
  ASSERT_EQ(all.size(), formulas.size());
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    EXPECT_EQ(all[i].name, ltl::to_string(ltl::parse(formulas[i])));
    expect_models(all[i], formulas[i], 10 + i);
  }
  // The same from standard input, with a formula argument first.
  const auto s = run("ltl2ba 'G b' -F -", &text);
  ASSERT_EQ(s.rc, 0) << s.err;
  const auto all2 = automata::read_hoa(s.out);
  ASSERT_EQ(all2.size(), formulas.size() + 1);
  EXPECT_EQ(all2[0].name, "Gb");
  EXPECT_EQ(all2[1].name, all[0].name);
}

TEST(CliLtl2ba, BadLinesAreReportedAndTheOthersTranslated) {
  const std::string path = write_file("bad.ltl", "F a\nG(a -> \n# fine\nb U U c\nG b\n");
  const auto r = run("ltl2ba --format stats -F " + quote(path));
  EXPECT_EQ(r.rc, 2);
  const auto out = lines(r.out);
  ASSERT_EQ(out.size(), 3u) << r.out;  // header + F a + G b
  EXPECT_NE(out[1].find("\tFa"), std::string::npos);
  EXPECT_NE(out[2].find("\tGb"), std::string::npos);
  EXPECT_NE(r.err.find("rtamp: error: " + path + ":2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rtamp: error: " + path + ":4:5:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(path + ":1:"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(path + ":5:"), std::string::npos) << r.err;
}

TEST(CliLtl2ba, BadFormulaArgumentIsOneClearErrorWithColumn) {
  const auto r = run("ltl2ba 'G(a -> F)'");
  EXPECT_EQ(r.rc, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.rfind("rtamp: error: <formula>:1:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find('^'), std::string::npos) << "a caret under the column: " << r.err;
}

TEST(CliLtl2ba, StatsLinesAndUnsatisfiable) {
  const auto r = run("ltl2ba --format stats 'G F a' 'G a & F !a'");
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto out = lines(r.out);
  ASSERT_EQ(out.size(), 3u) << r.out;
  EXPECT_EQ(out[0], "states\tedges\tsets\ttime_us\tstatus\tformula");
  EXPECT_NE(out[1].find("\tsatisfiable\tGFa"), std::string::npos) << out[1];
  EXPECT_EQ(out[2].rfind("1\t0\t1\t", 0), 0u) << "the empty automaton: " << out[2];
  EXPECT_NE(out[2].find("\tunsatisfiable\t"), std::string::npos) << out[2];
}

TEST(CliLtl2ba, NeverClaimAndDot) {
  const auto r = run("ltl2ba --format never 'G(p -> F q)'");
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(r.out.rfind("never {", 0), 0u) << r.out;
  expect_models(automata::read_never_claim(r.out), "G(p -> F q)", 4);
  const auto g = run("ltl2ba --format never --gba 'F a'");
  EXPECT_EQ(g.rc, 2);
  EXPECT_NE(g.err.find("drop --gba"), std::string::npos) << g.err;
  const auto q = run("ltl2ba --format never 'F \"o1 in r2\"'");
  EXPECT_EQ(q.rc, 2);
  EXPECT_NE(q.err.find("not a Promela identifier"), std::string::npos) << q.err;
  const auto d = run("ltl2ba --format dot 'a U b'");
  ASSERT_EQ(d.rc, 0) << d.err;
  EXPECT_EQ(d.out.rfind("digraph \"a U b\" {", 0), 0u) << d.out;
  EXPECT_NE(d.out.find("doublecircle"), std::string::npos) << d.out;
}

TEST(CliLtl2ba, HelpAndUsageErrors) {
  const auto h = run("ltl2ba --help");
  EXPECT_EQ(h.rc, 0);
  for (const char* s : {"FORMULA SYNTAX", "Precedence", "<>", "--format", "stats", "never", "-F"})
    EXPECT_NE(h.out.find(s), std::string::npos) << s;
  EXPECT_EQ(run("ltl2ba --format xml 'F a'").rc, 2);
  EXPECT_EQ(run("ltl2ba").rc, 2);
  const auto m = run("ltl2ba -F /nonexistent/formulas.ltl");
  EXPECT_EQ(m.rc, 2);
  EXPECT_NE(m.err.find("/nonexistent/formulas.ltl: cannot read the formula file (-F): no such file"), std::string::npos) << m.err;
}
