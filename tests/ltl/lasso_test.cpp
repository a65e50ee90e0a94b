// The lasso oracle: hand-picked words for every operator, the fixpoint
// subtleties (U vs W, R vs M on cycles), and agreement with a second, naive
// semantics that unrolls the word to a long finite horizon.
#include "rtamp/ltl/lasso.hpp"

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"

namespace rtamp::ltl {
namespace {

// "a b- ; c" : prefix {a},{b} ... letters are runs of one-letter atoms, "-" is
// the empty letter, ';' separates prefix from cycle.
LassoWord word(const std::string& text) {
  LassoWord w;
  std::istringstream in(text);
  std::string tok;
  bool in_cycle = false;
  while (in >> tok) {
    if (tok == ";") {
      in_cycle = true;
      continue;
    }
    LassoWord::Letter l;
    for (char ch : tok)
      if (ch != '-') l.insert(std::string(1, ch));
    (in_cycle ? w.cycle : w.prefix).push_back(l);
  }
  return w;
}

bool sat(const std::string& f, const std::string& w) { return holds(parse(f), word(w)); }

TEST(LtlLasso, Constants) {
  EXPECT_TRUE(sat("true", "; -"));
  EXPECT_FALSE(sat("false", "; -"));
}

TEST(LtlLasso, AtomsAndBoolean) {
  EXPECT_TRUE(sat("a", "a ; -"));
  EXPECT_FALSE(sat("a", "- ; a"));
  EXPECT_TRUE(sat("!a", "- ; a"));
  EXPECT_TRUE(sat("a & b", "; ab"));
  EXPECT_FALSE(sat("a & b", "; a"));
  EXPECT_TRUE(sat("a | b", "; b"));
  EXPECT_FALSE(sat("a | b", "; c"));
  EXPECT_TRUE(sat("a xor b", "; a"));
  EXPECT_FALSE(sat("a xor b", "; ab"));
  EXPECT_TRUE(sat("a -> b", "; -"));
  EXPECT_FALSE(sat("a -> b", "; a"));
  EXPECT_TRUE(sat("a <-> b", "; -"));
  EXPECT_TRUE(sat("a <-> b", "; ab"));
  EXPECT_FALSE(sat("a <-> b", "; b"));
}

TEST(LtlLasso, Next) {
  EXPECT_TRUE(sat("X a", "- ; a"));
  EXPECT_FALSE(sat("X a", "a ; -"));
  EXPECT_TRUE(sat("X X a", "- - ; a"));
  // X from the last position wraps to the start of the cycle.
  EXPECT_TRUE(sat("X X X a", "- ; a -"));   // positions 0,1,2,3=1(a)
  EXPECT_FALSE(sat("X X X X a", "- ; a -"));  // position 4 = 2 (-)
  EXPECT_TRUE(sat("X a", "; a"));
}

TEST(LtlLasso, FinallyGlobally) {
  EXPECT_TRUE(sat("F a", "- - ; - a"));
  EXPECT_FALSE(sat("F a", "- - ; -"));
  EXPECT_TRUE(sat("F a", "a ; -"));
  EXPECT_TRUE(sat("G a", "a ; a"));
  EXPECT_FALSE(sat("G a", "a ; a -"));
  EXPECT_TRUE(sat("G F a", "- ; - a"));
  EXPECT_FALSE(sat("G F a", "a ; -"));
  EXPECT_TRUE(sat("F G a", "- - ; a"));
  EXPECT_FALSE(sat("F G a", "a ; a -"));
  EXPECT_TRUE(sat("F G !a", "a ; -"));
}

TEST(LtlLasso, Until) {
  EXPECT_TRUE(sat("a U b", "; b"));
  EXPECT_TRUE(sat("a U b", "a a ; b"));
  EXPECT_FALSE(sat("a U b", "a - ; b"));
  EXPECT_FALSE(sat("a U b", "; a"));  // b never: strong until fails (least fixpoint)
  EXPECT_TRUE(sat("a U b", "a ; a b"));
  EXPECT_FALSE(sat("a U b", "a ; - b"));
}

TEST(LtlLasso, WeakUntil) {
  EXPECT_TRUE(sat("a W b", "; a"));  // the difference with U: G a suffices
  EXPECT_TRUE(sat("a W b", "a ; b"));
  EXPECT_FALSE(sat("a W b", "a ; -"));
  EXPECT_TRUE(sat("a W b", "; b"));
  EXPECT_FALSE(sat("a W b", "a ; - a"));
}

TEST(LtlLasso, Release) {
  EXPECT_TRUE(sat("a R b", "; b"));  // G b suffices (greatest fixpoint)
  EXPECT_TRUE(sat("a R b", "b ; ab -"));
  EXPECT_FALSE(sat("a R b", "b ; a"));  // b fails before a & b
  EXPECT_FALSE(sat("a R b", "a ; b"));  // b must hold now
  EXPECT_TRUE(sat("false R b", "; b"));
  EXPECT_FALSE(sat("false R b", "b ; b -"));
}

TEST(LtlLasso, StrongRelease) {
  EXPECT_FALSE(sat("a M b", "; b"));  // needs a & b eventually (least fixpoint)
  EXPECT_TRUE(sat("a M b", "b ; ab"));
  EXPECT_FALSE(sat("a M b", "b - ; ab"));
  EXPECT_TRUE(sat("a M b", "; ab"));
  EXPECT_FALSE(sat("a M b", "a ; ab"));
}

TEST(LtlLasso, PositionsAndNesting) {
  const LassoWord w = word("a - ; b a");
  const auto v = evaluate(parse("a"), w);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v, (std::vector<bool>{true, false, false, true}));
  EXPECT_EQ(evaluate(parse("X a"), w), (std::vector<bool>{false, false, true, false}));
  EXPECT_EQ(evaluate(parse("G F b"), w), (std::vector<bool>{true, true, true, true}));
  EXPECT_EQ(evaluate(parse("!b U a"), w), (std::vector<bool>{true, false, false, true}));
  EXPECT_TRUE(sat("G(a -> F b)", "a ; - b"));
  EXPECT_FALSE(sat("G(a -> F b)", "b ; a"));
  EXPECT_TRUE(sat("F(a & X(b U c))", "- a ; b c"));
  EXPECT_FALSE(sat("F(a & X(b U c))", "- a ; b"));
}

TEST(LtlLasso, EmptyCycleRejected) {
  LassoWord w;
  w.prefix.push_back({});
  EXPECT_THROW(holds(Formula::tt(), w), std::invalid_argument);
}

// A second semantics, as naive as possible: unroll u v^ω to a horizon long
// enough that every U/F/R/G witness of a lasso appears, and evaluate the
// standard recursive definition at absolute positions with memoization. For a
// lasso of n positions and a formula of temporal depth d, a horizon of
// |u| + (d+2) * n * |v| positions is plenty; beyond the horizon we take the
// value from the equivalent position one cycle earlier.
class Unrolled {
 public:
  Unrolled(const LassoWord& w, std::size_t horizon) : w_(w), horizon_(horizon) {}
  bool at(const Formula& f, std::size_t i) {
    i = norm(i);
    auto key = std::make_pair(f.id(), i);
    if (auto it = memo_.find(key); it != memo_.end()) return it->second;
    bool r = compute(f, i);
    memo_[key] = r;
    return r;
  }

 private:
  std::size_t norm(std::size_t i) const {
    const std::size_t p = w_.prefix.size(), c = w_.cycle.size();
    while (i >= horizon_) i -= c;
    (void)p;
    return i;
  }
  const LassoWord::Letter& letter(std::size_t i) const {
    const std::size_t p = w_.prefix.size();
    return i < p ? w_.prefix[i] : w_.cycle[(i - p) % w_.cycle.size()];
  }
  bool compute(const Formula& f, std::size_t i) {
    switch (f.op()) {
      case Op::True: return true;
      case Op::False: return false;
      case Op::Atom: return letter(i).count(f.name()) != 0;
      case Op::Not: return !at(f[0], i);
      case Op::And:
        for (const Formula& c : f.children())
          if (!at(c, i)) return false;
        return true;
      case Op::Or:
        for (const Formula& c : f.children())
          if (at(c, i)) return true;
        return false;
      case Op::Xor: return at(f[0], i) != at(f[1], i);
      case Op::Implies: return !at(f[0], i) || at(f[1], i);
      case Op::Equiv: return at(f[0], i) == at(f[1], i);
      case Op::Next: return at(f[0], i + 1);
      default: break;
    }
    // Scan positions j = i, i+1, ..., i + span: after one full pass over the
    // cycle past the prefix, every suffix has been seen.
    const std::size_t span = w_.prefix.size() + w_.cycle.size() + 1;
    for (std::size_t j = i; j < i + span; ++j) {
      switch (f.op()) {
        case Op::Finally: if (at(f[0], j)) return true; break;
        case Op::Globally: if (!at(f[0], j)) return false; break;
        case Op::Until:
          if (at(f[1], j)) return true;
          if (!at(f[0], j)) return false;
          break;
        case Op::WeakUntil:
          if (at(f[1], j)) return true;
          if (!at(f[0], j)) return false;
          break;
        case Op::Release:
          if (!at(f[1], j)) return false;
          if (at(f[0], j)) return true;
          break;
        case Op::StrongRelease:
          if (!at(f[1], j)) return false;
          if (at(f[0], j)) return true;
          break;
        default: break;
      }
    }
    // No decision within a full period: the pattern repeats forever.
    switch (f.op()) {
      case Op::Finally: case Op::Until: case Op::StrongRelease: return false;
      default: return true;  // G, W, R
    }
  }

  const LassoWord& w_;
  std::size_t horizon_;
  std::map<std::pair<std::uint64_t, std::size_t>, bool> memo_;
};

TEST(LtlLasso, AgreesWithUnrolledSemanticsOnRandomFormulas) {
  std::mt19937_64 rng(20261123);
  RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  int checked = 0;
  for (int k = 0; k < 1500; ++k) {
    opt.size = 1 + uniform(rng, 0, 14);
    const Formula f = random_formula(rng, opt);
    for (int t = 0; t < 6; ++t) {
      const LassoWord w = random_lasso(rng, opt.atoms, 3, 4);
      // Positions >= |u| + 2|v| map back by one cycle; indices stay bounded.
      Unrolled u(w, w.prefix.size() + 2 * w.cycle.size());
      ASSERT_EQ(holds(f, w), u.at(f, 0)) << to_string(f) << " on " << to_string(w);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 9000);
}

}  // namespace
}  // namespace rtamp::ltl
