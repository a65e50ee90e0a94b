// Parser: syntax of both dialects, precedence/associativity against explicit
// constructions, error messages with columns, depth limits, big inputs, and
// the formula sets in tests/data.
#include "rtamp/ltl/parser.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "rtamp/ltl/printer.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::ltl {
namespace {

Formula a() { return Formula::atom("a"); }
Formula b() { return Formula::atom("b"); }
Formula c() { return Formula::atom("c"); }

TEST(LtlParser, AtomsAndConstants) {
  EXPECT_EQ(parse("a"), a());
  EXPECT_EQ(parse("  a \n"), a());
  EXPECT_EQ(parse("true"), Formula::tt());
  EXPECT_EQ(parse("1"), Formula::tt());
  EXPECT_EQ(parse("false"), Formula::ff());
  EXPECT_EQ(parse("0"), Formula::ff());
  EXPECT_EQ(parse("_x.y9Z"), Formula::atom("_x.y9Z"));
  EXPECT_EQ(parse("aUb"), Formula::atom("aUb"));  // like Spot: one identifier
  EXPECT_EQ(parse("\"o1 in r2\""), Formula::atom("o1 in r2"));
  EXPECT_EQ(parse("\"a\""), a());
  EXPECT_EQ(parse(R"("q\"uo\\te")"), Formula::atom("q\"uo\\te"));
  EXPECT_EQ(parse("truex"), Formula::atom("truex"));
  EXPECT_EQ(parse("\"true\""), Formula::atom("true"));
}

TEST(LtlParser, Operators) {
  EXPECT_EQ(parse("!a"), Formula::Not(a()));
  EXPECT_EQ(parse("~a"), Formula::Not(a()));
  EXPECT_EQ(parse("X a"), Formula::X(a()));
  EXPECT_EQ(parse("Xa"), Formula::X(a()));
  EXPECT_EQ(parse("F a"), Formula::F(a()));
  EXPECT_EQ(parse("<>a"), Formula::F(a()));
  EXPECT_EQ(parse("G a"), Formula::G(a()));
  EXPECT_EQ(parse("[]a"), Formula::G(a()));
  EXPECT_EQ(parse("GFa"), Formula::G(Formula::F(a())));
  EXPECT_EQ(parse("[]<>a"), Formula::G(Formula::F(a())));
  EXPECT_EQ(parse("a & b"), Formula::And(a(), b()));
  EXPECT_EQ(parse("a && b"), Formula::And(a(), b()));
  EXPECT_EQ(parse("a /\\ b"), Formula::And(a(), b()));
  EXPECT_EQ(parse("a | b"), Formula::Or(a(), b()));
  EXPECT_EQ(parse("a || b"), Formula::Or(a(), b()));
  EXPECT_EQ(parse("a \\/ b"), Formula::Or(a(), b()));
  EXPECT_EQ(parse("a xor b"), Formula::Xor(a(), b()));
  EXPECT_EQ(parse("a ^ b"), Formula::Xor(a(), b()));
  EXPECT_EQ(parse("a -> b"), Formula::Implies(a(), b()));
  EXPECT_EQ(parse("a => b"), Formula::Implies(a(), b()));
  EXPECT_EQ(parse("a <-> b"), Formula::Equiv(a(), b()));
  EXPECT_EQ(parse("a <=> b"), Formula::Equiv(a(), b()));
  EXPECT_EQ(parse("a U b"), Formula::U(a(), b()));
  EXPECT_EQ(parse("a R b"), Formula::R(a(), b()));
  EXPECT_EQ(parse("a V b"), Formula::R(a(), b()));
  EXPECT_EQ(parse("a W b"), Formula::W(a(), b()));
  EXPECT_EQ(parse("a M b"), Formula::M(a(), b()));
  EXPECT_EQ(parse("(a)"), a());
  EXPECT_EQ(parse("((a U (b)))"), Formula::U(a(), b()));
}

TEST(LtlParser, PrecedenceTable) {
  // Each line: text, and the structure Spot's grammar gives it.
  const Formula na = Formula::Not(a());
  EXPECT_EQ(parse("!a & b"), Formula::And(na, b()));
  EXPECT_EQ(parse("!a U b"), Formula::U(na, b()));
  EXPECT_EQ(parse("X a U b"), Formula::U(Formula::X(a()), b()));
  EXPECT_EQ(parse("F a U G b"), Formula::U(Formula::F(a()), Formula::G(b())));
  EXPECT_EQ(parse("a U b & c"), Formula::And(Formula::U(a(), b()), c()));
  EXPECT_EQ(parse("a & b U c"), Formula::And(a(), Formula::U(b(), c())));
  EXPECT_EQ(parse("a & b | c"), Formula::Or(Formula::And(a(), b()), c()));
  EXPECT_EQ(parse("a | b & c"), Formula::Or(a(), Formula::And(b(), c())));
  EXPECT_EQ(parse("a | b xor c"), Formula::Or(a(), Formula::Xor(b(), c())));  // xor binds tighter than |
  EXPECT_EQ(parse("a xor b | c"), Formula::Or(Formula::Xor(a(), b()), c()));
  EXPECT_EQ(parse("a xor b & c"), Formula::Xor(a(), Formula::And(b(), c())));  // & tighter than xor
  EXPECT_EQ(parse("a | b -> c"), Formula::Implies(Formula::Or(a(), b()), c()));
  EXPECT_EQ(parse("a -> b | c"), Formula::Implies(a(), Formula::Or(b(), c())));
  EXPECT_EQ(parse("a <-> b | c"), Formula::Equiv(a(), Formula::Or(b(), c())));
  EXPECT_EQ(parse("G a -> F b"), Formula::Implies(Formula::G(a()), Formula::F(b())));
  EXPECT_EQ(parse("!G a"), Formula::Not(Formula::G(a())));
  EXPECT_EQ(parse("X!a"), Formula::X(na));
}

TEST(LtlParser, Associativity) {
  const Formula d = Formula::atom("d");
  EXPECT_EQ(parse("a U b U c"), Formula::U(a(), Formula::U(b(), c())));
  EXPECT_EQ(parse("a R b R c"), Formula::R(a(), Formula::R(b(), c())));
  EXPECT_EQ(parse("a U b R c"), Formula::U(a(), Formula::R(b(), c())));  // same level, right assoc
  EXPECT_EQ(parse("a W b M c"), Formula::W(a(), Formula::M(b(), c())));
  EXPECT_EQ(parse("a -> b -> c"), Formula::Implies(a(), Formula::Implies(b(), c())));
  EXPECT_EQ(parse("a <-> b -> c"), Formula::Equiv(a(), Formula::Implies(b(), c())));
  EXPECT_EQ(parse("a -> b <-> c"), Formula::Implies(a(), Formula::Equiv(b(), c())));
  EXPECT_EQ(parse("a xor b xor c"), Formula::Xor(Formula::Xor(a(), b()), c()));
  EXPECT_EQ(parse("a & b & c & d"), Formula::And({a(), b(), c(), d}));
  EXPECT_EQ(parse("(a & b) & (c & d)"), Formula::And({a(), b(), c(), d}));
  EXPECT_EQ(parse("a | b | (c | d)"), Formula::Or({a(), b(), c(), d}));
  EXPECT_EQ(parse("a & b & a"), Formula::And(a(), b()));
}

TEST(LtlParser, SpinSyntax) {
  EXPECT_EQ(parse("[](a -> <>b)"), Formula::G(Formula::Implies(a(), Formula::F(b()))));
  EXPECT_EQ(parse("!(a V b) || ~c && X a"),
            Formula::Or(Formula::Not(Formula::R(a(), b())), Formula::And(Formula::Not(c()), Formula::X(a()))));
  EXPECT_EQ(parse("<>[]a"), Formula::F(Formula::G(a())));
  EXPECT_EQ(parse("[] <> a"), Formula::G(Formula::F(a())));
}

// The error for `text` has this column and message substring; the detail is
// the caret line.
void expect_error(const std::string& text, int column, const std::string& message) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for '" << text << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().column, column) << text << ": " << e.what();
    EXPECT_EQ(e.where().line, 1) << text;
    EXPECT_NE(e.message().find(message), std::string::npos) << text << ": " << e.message();
    // The caret sits under the column.
    const std::string& d = e.detail();
    const auto nl = d.find('\n');
    ASSERT_NE(nl, std::string::npos);
    EXPECT_EQ(d.substr(nl + 1).find('^'), static_cast<std::size_t>(column - 1 + 2)) << d;
  }
}

TEST(LtlParser, ErrorsHaveColumns) {
  expect_error("", 1, "empty formula");
  expect_error("   ", 4, "empty formula");
  expect_error("a &", 4, "unexpected end of formula");
  expect_error("a & & b", 5, "expected a formula before '&'");
  expect_error("a b", 3, "expected an operator");
  expect_error("(a | b", 1, "missing ')'");
  expect_error("a | b)", 6, "unmatched ')'");
  expect_error("()", 2, "expected a formula before ')'");
  expect_error("a # b", 3, "unexpected character '#'");
  expect_error("a U Q", 5, "unexpected 'Q'");
  expect_error("G 2", 3, "only numbers are the constants 0 and 1");
  expect_error("a -- b", 3, "unexpected character '-'");
  expect_error("\"abc", 1, "unterminated quoted");
  expect_error("a & \"\"", 5, "empty quoted");
  expect_error("a < b", 3, "unexpected character '<'");
  expect_error("x U", 4, "expected an operand after 'U'");
}

TEST(LtlParser, UpperCaseStartIsOperators) {
  // Upper-case letters start operators: "Foo" is F then the atom "oo", as Spot reads "Fa".
  EXPECT_EQ(parse("Foo"), Formula::F(Formula::atom("oo")));
  EXPECT_EQ(parse("XXa"), Formula::X(Formula::X(a())));
  EXPECT_EQ(parse("aUb U c"), Formula::U(Formula::atom("aUb"), c()));
  expect_error("Quux", 1, "unexpected 'Q'");
}

TEST(LtlParser, OriginShiftsLocation) {
  try {
    parse("a &\n  & b", SourceLocation{"spec.yaml", 7, 10});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "spec.yaml");
    EXPECT_EQ(e.where().line, 8);
    EXPECT_EQ(e.where().column, 3);
    EXPECT_NE(std::string(e.what()).find("spec.yaml:8:3:"), std::string::npos) << e.what();
  }
  try {
    parse("a & )", SourceLocation{"spec.yaml", 7, 10});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line, 7);
    EXPECT_EQ(e.where().column, 14);
  }
}

void expect_too_deep(const std::string& text) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for deep input of size " << text.size();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("formula too deeply nested"), std::string::npos) << e.message();
    EXPECT_LT(e.detail().size(), 400u);  // the caret line is a window, not the whole input
  }
}

TEST(LtlParser, DepthLimit) {
  const int n = 10000;
  expect_too_deep(std::string(n, '(') + "a" + std::string(n, ')'));
  expect_too_deep(std::string(n, '!') + "a");
  std::string xs;
  for (int i = 0; i < n; ++i) xs += "X ";
  expect_too_deep(xs + "a");
  std::string chain = "a";
  for (int i = 0; i < n; ++i) chain += " U a";
  expect_too_deep(chain);
  std::string left = "a";
  for (int i = 0; i < n; ++i) left += " xor a";
  expect_too_deep(left);
  std::string nested = "a";
  for (int i = 0; i < n; ++i) {
    std::string next = "(b & ";
    next += nested;
    next += ')';
    nested = std::move(next);
  }
  expect_too_deep(nested);
  // Just under the limit is fine.
  std::string ok;
  for (int i = 0; i < kMaxParseDepth - 1; ++i) ok += "X";
  EXPECT_EQ(parse(ok + "a").depth(), static_cast<std::size_t>(kMaxParseDepth));
  EXPECT_EQ(parse(std::string(kMaxParseDepth, '(') + "a" + std::string(kMaxParseDepth, ')')), a());
}

TEST(LtlParser, OneMegabyteFormulas) {
  // A wide conjunction of distinct atoms and a long disjunction of repeats.
  std::string wide;
  int count = 0;
  while (wide.size() < (1u << 20)) {
    if (!wide.empty()) wide += " & ";
    wide += 'p';
    wide += std::to_string(count++);
  }
  const Formula f = parse(wide);
  EXPECT_EQ(f.op(), Op::And);
  EXPECT_EQ(f.arity(), static_cast<std::size_t>(count));
  std::string rep;
  while (rep.size() < (1u << 20)) rep += "(a U b) | ";
  rep += "c";
  EXPECT_EQ(parse(rep), Formula::Or(Formula::U(a(), b()), c()));
  // A 1 MB string of garbage after a valid prefix fails with a short message.
  std::string bad = "a & ";
  bad.append(1u << 20, ' ');
  bad += '#';
  try {
    parse(bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().column, static_cast<int>(bad.size()));
    EXPECT_LT(e.detail().size(), 400u);
  }
}

std::vector<std::string> read_formulas(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    out.push_back(line);
  }
  return out;
}

TEST(LtlParser, DwyerPatternsParse) {
  const auto lines = read_formulas(std::string(RTAMP_SOURCE_DIR) + "/tests/data/dac-patterns.ltl");
  ASSERT_EQ(lines.size(), 55u);
  for (const std::string& s : lines) {
    const Formula f = parse(s);
    EXPECT_EQ(parse(to_string(f)), f) << s;
  }
  // Spot-checks of the structure of a few patterns.
  const Formula p = Formula::atom("p"), q = Formula::atom("q"), r = Formula::atom("r");
  EXPECT_EQ(parse(lines[0]), Formula::G(Formula::Not(p)));
  EXPECT_EQ(parse(lines[1]), Formula::Implies(Formula::F(r), Formula::U(Formula::Not(p), r)));
  EXPECT_EQ(parse(lines[5]), Formula::F(p));
  EXPECT_EQ(parse(lines[15]), Formula::G(p));
  // Response "before R": F r -> ((p -> (!r U (s & !r))) U r)
  const Formula s = Formula::atom("s");
  EXPECT_EQ(parse(lines[26]),
            Formula::Implies(Formula::F(r), Formula::U(Formula::Implies(p, Formula::U(Formula::Not(r),
                                                                                 Formula::And(s, Formula::Not(r)))),
                                                       r)));
  (void)q;
}

TEST(LtlParser, RobotPatternsParse) {
  const auto lines = read_formulas(std::string(RTAMP_SOURCE_DIR) + "/tests/data/robot-patterns.ltl");
  ASSERT_GE(lines.size(), 20u);
  for (const std::string& s : lines) {
    const Formula f = parse(s);
    EXPECT_EQ(parse(to_string(f)), f) << s;
  }
}

}  // namespace
}  // namespace rtamp::ltl
