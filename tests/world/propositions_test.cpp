// Proposition expressions: parser (structure, precedence, column-accurate
// errors), printer (round trip on random trees) and the reference evaluator
// (hand-checked cases and Boolean identities on random placements).
#include "rtamp/world/propositions.hpp"

#include <gtest/gtest.h>

#include <random>

namespace rtamp::world {
namespace {

using K = PropExpr::Kind;

PropExpr atom_in(const std::string& x, const std::string& l) {
  PropExpr e;
  e.kind = K::In;
  e.subject = x;
  e.location = l;
  return e;
}

PropExpr node(K k, std::vector<PropExpr> children) {
  PropExpr e;
  e.kind = k;
  e.children = std::move(children);
  return e;
}

TEST(PropParse, Atoms) {
  PropExpr e = parse_prop_expr("o1 in r2");
  EXPECT_EQ(e, atom_in("o1", "r2"));

  e = parse_prop_expr("all block in r2");
  EXPECT_EQ(e.kind, K::All);
  EXPECT_EQ(e.subject, "block");
  EXPECT_EQ(e.location, "r2");

  e = parse_prop_expr("  any tray in r3 ");
  EXPECT_EQ(e.kind, K::Any);
  EXPECT_EQ(e.subject, "tray");
  EXPECT_EQ(e.location, "r3");

  e = parse_prop_expr("count block in r2 >= 2");
  EXPECT_EQ(e.kind, K::Count);
  EXPECT_EQ(e.cmp, PropExpr::Cmp::Ge);
  EXPECT_EQ(e.count, 2);
  const std::pair<const char*, PropExpr::Cmp> cmps[] = {{"<", PropExpr::Cmp::Lt},  {"<=", PropExpr::Cmp::Le},
                                                         {"==", PropExpr::Cmp::Eq}, {"!=", PropExpr::Cmp::Ne},
                                                         {">=", PropExpr::Cmp::Ge}, {">", PropExpr::Cmp::Gt}};
  for (const auto& [text, cmp] : cmps) {
    e = parse_prop_expr(std::string("count object in r1 ") + text + "0");
    EXPECT_EQ(e.cmp, cmp) << text;
    EXPECT_EQ(e.count, 0);
  }
  EXPECT_EQ(parse_prop_expr("true").kind, K::True);
  EXPECT_EQ(parse_prop_expr("false").kind, K::False);
}

TEST(PropParse, PrecedenceAndFlattening) {
  // & binds tighter than |, ! tighter than &.
  EXPECT_EQ(parse_prop_expr("a in r1 | b in r2 & c in r3"),
            node(K::Or, {atom_in("a", "r1"), node(K::And, {atom_in("b", "r2"), atom_in("c", "r3")})}));
  EXPECT_EQ(parse_prop_expr("!a in r1 & b in r2"),
            node(K::And, {node(K::Not, {atom_in("a", "r1")}), atom_in("b", "r2")}));
  // Same-kind operands are flattened, parentheses or not; && and || are aliases.
  const PropExpr flat = node(K::And, {atom_in("a", "r1"), atom_in("b", "r2"), atom_in("c", "r3")});
  EXPECT_EQ(parse_prop_expr("a in r1 & b in r2 & c in r3"), flat);
  EXPECT_EQ(parse_prop_expr("(a in r1 && b in r2) & (c in r3)"), flat);
  EXPECT_EQ(parse_prop_expr("a in r1 & (b in r2 & c in r3)"), flat);
  EXPECT_EQ(parse_prop_expr("a in r1 || b in r2"), node(K::Or, {atom_in("a", "r1"), atom_in("b", "r2")}));
  EXPECT_EQ(parse_prop_expr("!!(a in r1)"), node(K::Not, {node(K::Not, {atom_in("a", "r1")})}));
}

TEST(PropPrint, Canonical) {
  EXPECT_EQ(to_string(parse_prop_expr("(a in r1|b in r2)&!(c in r3)")), "(a in r1 | b in r2) & !(c in r3)");
  EXPECT_EQ(to_string(parse_prop_expr("count  block in r2>=2")), "count block in r2 >= 2");
  EXPECT_EQ(to_string(parse_prop_expr("!true | false")), "!true | false");
  // Hand-built nesting of the same kind keeps its structure through the text.
  const PropExpr nested = node(K::And, {atom_in("a", "r1"), node(K::And, {atom_in("b", "r2"), atom_in("c", "r3")})});
  EXPECT_EQ(to_string(nested), "a in r1 & (b in r2 & c in r3)");
}

// Random flattened trees: the parser's normal form.
PropExpr random_expr(std::mt19937& rng, int depth) {
  std::uniform_int_distribution<int> pick(0, depth > 0 ? 8 : 5);
  const char* things[] = {"o1", "o2", "t1"};
  const char* locs[] = {"r1", "r2", "t1"};
  const char* classes[] = {"block", "tray", "object"};
  PropExpr e;
  switch (pick(rng)) {
    case 0:
      e.kind = K::True;
      return e;
    case 1:
      e.kind = K::False;
      return e;
    case 2:
    {
      const std::string& thing = things[rng() % 3];  // one draw per statement (argument order is unspecified)
      return atom_in(thing, locs[rng() % 3]);
    }
    case 3:
    case 4:
    case 5:
      e.kind = std::vector<K>{K::All, K::Any, K::Count}[rng() % 3];
      e.subject = classes[rng() % 3];
      e.location = locs[rng() % 3];
      if (e.kind == K::Count) {
        e.cmp = static_cast<PropExpr::Cmp>(rng() % 6);
        e.count = static_cast<int>(rng() % 5);
      }
      return e;
    case 6:
      return node(K::Not, {random_expr(rng, depth - 1)});
    default: {
      e.kind = rng() % 2 ? K::And : K::Or;
      const int n = 2 + static_cast<int>(rng() % 3);
      while (static_cast<int>(e.children.size()) < n) {
        PropExpr c = random_expr(rng, depth - 1);
        if (c.kind != e.kind) e.children.push_back(std::move(c));
      }
      return e;
    }
  }
}

TEST(PropPrint, RoundTripRandomTrees) {
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const PropExpr e = random_expr(rng, 4);
    const std::string text = to_string(e);
    EXPECT_EQ(parse_prop_expr(text), e) << text;
  }
}

struct BadCase {
  const char* text;
  int column;
  const char* message;
};

TEST(PropParse, ErrorsPointAtTheColumn) {
  const BadCase cases[] = {
      {"", 1, "expected a proposition, found the end"},
      {"o1 in", 6, "expected a location name, found the end"},
      {"o1 r2", 4, "expected 'in' after 'o1'"},
      {"all in r2", 5, "expected a class after 'all', found the keyword 'in'"},
      {"any block r2", 11, "expected 'in' after 'any block'"},
      {"(o1 in r2", 1, "'(' is never closed"},
      {"o1 in r2)", 9, "unmatched ')'"},
      {"o1 in r2 o2 in r1", 10, "expected '&', '|' or the end"},
      {"count block in r2 2", 19, "expected a comparison"},
      {"count block in r2 >= x", 22, "expected a non-negative integer"},
      {"count block in r2 >= -1", 22, "unexpected '-'"},
      {"count block in r2 >= 99999999", 22, "too large"},
      {"count block in r2 = 2", 19, "write '==' to compare"},
      {"o1 in r2 & ", 12, "expected a proposition, found the end"},
      {"o1 in r2 $", 10, "unexpected '$'"},
      {"o1 in true", 7, "found the keyword 'true'"},
      {"in r2", 1, "keyword 'in'"},
      {"o1 in 2r", 8, "unexpected 'r' in a number"},
      {"()", 2, "expected a proposition, found ')'"},
  };
  for (const BadCase& c : cases) {
    try {
      parse_prop_expr(c.text);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const Error& e) {
      EXPECT_NE(e.message().find(c.message), std::string::npos) << c.text << " -> " << e.message();
      // The caret line marks the column (detail = "  text\n  <spaces>^").
      const std::string& d = e.detail();
      const auto nl = d.find('\n');
      ASSERT_NE(nl, std::string::npos) << c.text;
      EXPECT_EQ(static_cast<int>(d.size() - nl - 3), c.column) << c.text << "\n" << d;
    }
  }
}

TEST(PropParse, ErrorLocationIsOffsetIntoTheFile) {
  try {
    parse_prop_expr("o1 in r2 | o2 in", SourceLocation{"s.yaml", 12, 14});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "s.yaml");
    EXPECT_EQ(e.where().line, 12);
    EXPECT_EQ(e.where().column, 14 + 16);
    EXPECT_EQ(std::string(e.what()).rfind("s.yaml:12:30: ", 0), 0u) << e.what();
  }
}

TEST(PropParse, DeepNestingIsAnErrorNotACrash) {
  std::string deep(5000, '(');
  EXPECT_THROW(parse_prop_expr(deep + "true" + std::string(5000, ')')), Error);
  EXPECT_THROW(parse_prop_expr(std::string(100000, '!') + "true"), Error);
  // 150 levels are fine.
  EXPECT_EQ(parse_prop_expr(std::string(150, '(') + "true" + std::string(150, ')')).kind, K::True);
}

Placement sample_placement() {
  Placement p;
  p.set("o1", "r1", "block");
  p.set("o2", "r2", "block");
  p.set("o3", "t1", "block");  // on the tray
  p.set("b1", "r2", "ball");
  p.set("t1", "r2", "tray", true);
  return p;
}

TEST(PropEval, DirectSemantics) {
  const Placement p = sample_placement();
  auto ev = [&](const char* text) { return evaluate(parse_prop_expr(text), p); };
  EXPECT_TRUE(ev("o1 in r1"));
  EXPECT_FALSE(ev("o1 in r2"));
  EXPECT_FALSE(ev("o3 in r2"));  // on the tray standing in r2: in the tray, not in r2
  EXPECT_TRUE(ev("o3 in t1"));
  EXPECT_TRUE(ev("t1 in r2"));
  EXPECT_FALSE(ev("o9 in r1"));  // absent things are nowhere
  EXPECT_FALSE(ev("all block in r2"));
  EXPECT_TRUE(ev("all ball in r2"));
  EXPECT_TRUE(ev("all cube in r2"));  // no thing of the class: vacuously true
  EXPECT_FALSE(ev("any cube in r2"));
  EXPECT_TRUE(ev("any block in t1"));
  EXPECT_TRUE(ev("count block in r2 == 1"));
  EXPECT_TRUE(ev("count object in r2 == 2"));  // o2 and b1, not the tray
  EXPECT_TRUE(ev("count tray in r2 == 1"));
  EXPECT_FALSE(ev("all object in r2"));
  EXPECT_TRUE(ev("count block in r1 >= 1 & count block in r1 <= 1 & count block in r1 < 2 & count block in r1 > 0"));
  EXPECT_TRUE(ev("count block in r1 != 0"));
  EXPECT_TRUE(ev("!(o1 in r2) & (o2 in r1 | o2 in r2)"));
  EXPECT_TRUE(ev("true"));
  EXPECT_FALSE(ev("false"));

  Placement moved = p;
  moved.set("o1", "r2", "block");
  moved.set("o3", "r2", "block");
  EXPECT_TRUE(evaluate(parse_prop_expr("all block in r2"), moved));
}

TEST(PropEval, BooleanIdentitiesOnRandomPlacements) {
  std::mt19937 rng(11);
  const char* locs[] = {"r1", "r2", "t1"};
  for (int i = 0; i < 300; ++i) {
    Placement p;
    const int n = static_cast<int>(rng() % 4);
    for (int k = 1; k <= n; ++k) p.set("o" + std::to_string(k), locs[rng() % 3], "block");
    if (rng() % 2) p.set("t1", rng() % 2 ? "r1" : "r2", "tray", true);
    const PropExpr a = random_expr(rng, 2), b = random_expr(rng, 2);
    const bool va = evaluate(a, p), vb = evaluate(b, p);
    EXPECT_EQ(evaluate(node(K::Not, {node(K::And, {a, b})}), p), !va || !vb);
    EXPECT_EQ(evaluate(node(K::Or, {a, b}), p), va || vb);
    // count ... >= 1 is any; count ... == total is all.
    for (const char* cls : {"block", "tray", "object"})
      for (const char* loc : locs) {
        int total = 0, here = 0;
        for (const auto& [name, t] : p.things) {
          const bool match = std::string(cls) == "object" ? !t.container : t.cls == cls;
          total += match;
          here += match && t.location == loc;
        }
        const std::string suffix = std::string(cls) + " in " + loc;
        EXPECT_EQ(evaluate(parse_prop_expr("any " + suffix), p), here >= 1);
        EXPECT_EQ(evaluate(parse_prop_expr("all " + suffix), p), here == total);
        EXPECT_EQ(evaluate(parse_prop_expr("count " + suffix + " == " + std::to_string(here)), p), true);
        EXPECT_EQ(evaluate(parse_prop_expr("count " + suffix + " > " + std::to_string(here)), p), false);
      }
  }
}

TEST(PropNamesTest, CollectsByRole) {
  PropNames names;
  collect_names(parse_prop_expr("o1 in r1 & (all block in t1 | count tray in r2 > 0)"), names);
  EXPECT_EQ(names.things, (std::set<std::string>{"o1"}));
  EXPECT_EQ(names.classes, (std::set<std::string>{"block", "tray"}));
  EXPECT_EQ(names.locations, (std::set<std::string>{"r1", "r2", "t1"}));
}

}  // namespace
}  // namespace rtamp::world
