#include "rtamp/ltl/simplify.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "rtamp/ltl/nnf.hpp"

namespace rtamp::ltl {
namespace {

constexpr int kImplicationBudget = 64;  // structural steps per implies() query
constexpr std::size_t kMaxSubsumptionWidth = 24;  // And/Or wider than this: no pairwise checks

bool suspendable(const Formula& f) { return f.is_eventual() && f.is_universal(); }

// Syntactic implication f ⇒ g; `budget` bounds the work.
bool imp(const Formula& f, const Formula& g, int& budget) {
  if (f == g) return true;
  if (g.is(Op::True) || f.is(Op::False)) return true;
  if (--budget < 0) return false;
  // Complete decompositions first.
  if (f.is(Op::Or)) {
    for (const Formula& c : f.children())
      if (!imp(c, g, budget)) return false;
    return true;
  }
  if (g.is(Op::And)) {
    for (const Formula& c : g.children())
      if (!imp(f, c, budget)) return false;
    return true;
  }
  if (f.is(Op::And)) {
    for (const Formula& c : f.children())
      if (imp(c, g, budget)) return true;
  }
  if (g.is(Op::Or)) {
    for (const Formula& c : g.children())
      if (imp(f, c, budget)) return true;
  }
  switch (g.op()) {
    case Op::Finally:  // f ⇒ g0 ⇒ F g0;  F f0 ⇒ F g0 if f0 ⇒ g0
      if (imp(f, g[0], budget)) return true;
      if (f.is(Op::Finally) && imp(f[0], g[0], budget)) return true;
      break;
    case Op::Until:  // f ⇒ b ⇒ a U b;  (a' U b') ⇒ (a U b) if a' ⇒ a and b' ⇒ b
      if (imp(f, g[1], budget)) return true;
      if (f.is(Op::Until) && imp(f[0], g[0], budget) && imp(f[1], g[1], budget)) return true;
      break;
    case Op::WeakUntil:  // f ⇒ b ⇒ a W b; U or W componentwise; G h ⇒ a W b if h ⇒ a
      if (imp(f, g[1], budget)) return true;
      if ((f.is(Op::Until) || f.is(Op::WeakUntil)) && imp(f[0], g[0], budget) && imp(f[1], g[1], budget))
        return true;
      if (f.is(Op::Globally) && imp(f[0], g[0], budget)) return true;
      break;
    case Op::Release:  // f ⇒ a & b ⇒ a R b; R or M componentwise; G h ⇒ a R b if h ⇒ b
      if (imp(f, g[0], budget) && imp(f, g[1], budget)) return true;
      if ((f.is(Op::Release) || f.is(Op::StrongRelease)) && imp(f[0], g[0], budget) && imp(f[1], g[1], budget))
        return true;
      if (f.is(Op::Globally) && imp(f[0], g[1], budget)) return true;
      break;
    case Op::StrongRelease:  // f ⇒ a & b ⇒ a M b; M componentwise
      if (imp(f, g[0], budget) && imp(f, g[1], budget)) return true;
      if (f.is(Op::StrongRelease) && imp(f[0], g[0], budget) && imp(f[1], g[1], budget)) return true;
      break;
    case Op::Globally:  // G f0 ⇒ G g0 if f0 ⇒ g0; u ⇒ G g0 if u ⇒ g0 (u ≡ G u)
      if (f.is(Op::Globally) && imp(f[0], g[0], budget)) return true;
      if (f.is_universal() && imp(f, g[0], budget)) return true;
      break;
    case Op::Next:  // X f0 ⇒ X g0 if f0 ⇒ g0; u ⇒ X g0 if u ⇒ g0 (u ⇒ X u)
      if (f.is(Op::Next) && imp(f[0], g[0], budget)) return true;
      if (f.is_universal() && imp(f, g[0], budget)) return true;
      break;
    default:
      break;
  }
  switch (f.op()) {
    case Op::Globally:  // G h ⇒ h
      return imp(f[0], g, budget);
    case Op::Until:  // a U b: b now, or a now
    case Op::WeakUntil:
      return imp(f[0], g, budget) && imp(f[1], g, budget);
    case Op::Release:  // a R b and a M b imply b now
    case Op::StrongRelease:
      return imp(f[1], g, budget);
    case Op::Finally:  // F h ⇒ e if h ⇒ e, e an eventuality
    case Op::Next:     // X h ⇒ e if h ⇒ e, e an eventuality
      return g.is_eventual() && imp(f[0], g, budget);
    default:
      return false;
  }
}

bool implies_budget(const Formula& f, const Formula& g) {
  int budget = kImplicationBudget;
  return imp(f, g, budget);
}

class Simplifier {
 public:
  Formula run(const Formula& f) {
    if (auto it = memo_.find(f); it != memo_.end()) return it->second;
    Formula r = rewrite(f);
    memo_.emplace(f, r);
    return r;
  }

 private:
  Formula rewrite(const Formula& f) {
    switch (f.op()) {
      case Op::True: case Op::False: case Op::Atom: case Op::Not:
        return f;  // NNF: Not is on an atom
      case Op::Next: return mkX(run(f[0]));
      case Op::Finally: return mkF(run(f[0]));
      case Op::Globally: return mkG(run(f[0]));
      case Op::And: case Op::Or: {
        std::vector<Formula> cs;
        cs.reserve(f.arity());
        for (const Formula& c : f.children()) cs.push_back(run(c));
        return f.is(Op::And) ? mkAnd(std::move(cs)) : mkOr(std::move(cs));
      }
      case Op::Until: return mkU(run(f[0]), run(f[1]));
      case Op::Release: return mkR(run(f[0]), run(f[1]));
      case Op::WeakUntil: return mkW(run(f[0]), run(f[1]));
      case Op::StrongRelease: return mkM(run(f[0]), run(f[1]));
      default:
        return f;  // ->, <->, xor do not occur after nnf()
    }
  }

  // Under G, F x | F y | r = F(x | y) | r; under F, G x & G y & r =
  // G(x & y) & r (F distributes over |, G over &), for Boolean x, y: one
  // eventuality (one invariant) over a Boolean formula, which the G F p and
  // F G p shortcuts translate directly. nullopt unless `a` (an Or for F, an
  // And for G) has two such children.
  std::optional<Formula> merge_children(const Formula& a, Op op) {
    std::vector<Formula> inner, rest;
    for (const Formula& c : a.children()) {
      if (c.is(op) && c[0].is_boolean())
        inner.push_back(c[0]);
      else
        rest.push_back(c);
    }
    if (inner.size() < 2) return std::nullopt;
    if (op == Op::Finally) {
      rest.push_back(Formula::F(mkOr(std::move(inner))));
      return mkOr(std::move(rest));
    }
    rest.push_back(Formula::G(mkAnd(std::move(inner))));
    return mkAnd(std::move(rest));
  }

  static Formula mkX(const Formula& a) {
    if (suspendable(a)) return a;  // includes constants
    return Formula::X(a);
  }

  Formula mkF(const Formula& a) {
    if (a.is_eventual()) return a;
    switch (a.op()) {
      case Op::Or: {
        std::vector<Formula> cs;
        cs.reserve(a.arity());
        for (const Formula& c : a.children()) cs.push_back(mkF(c));
        return mkOr(std::move(cs));
      }
      case Op::Next: return mkX(mkF(a[0]));
      case Op::Until: return mkF(a[1]);
      case Op::StrongRelease: return mkF(mkAnd({a[0], a[1]}));
      case Op::And: {
        if (auto merged = merge_children(a, Op::Globally)) return mkF(*merged);
        std::vector<Formula> rest, susp;
        for (const Formula& c : a.children()) (suspendable(c) ? susp : rest).push_back(c);
        if (!susp.empty() && !rest.empty()) {
          susp.push_back(mkF(mkAnd(std::move(rest))));
          return mkAnd(std::move(susp));
        }
        break;
      }
      default:
        break;
    }
    return Formula::F(a);
  }

  Formula mkG(const Formula& a) {
    if (a.is_universal()) return a;
    switch (a.op()) {
      case Op::And: {
        std::vector<Formula> cs;
        cs.reserve(a.arity());
        for (const Formula& c : a.children()) cs.push_back(mkG(c));
        return mkAnd(std::move(cs));
      }
      case Op::Next:  // G X e = G e for an eventuality e
        return a.is_eventual() ? mkG(a[0]) : mkX(mkG(a[0]));
      case Op::Finally: {  // G F(r & e) = G F r & G e for eventualities e
        if (!a[0].is(Op::And)) break;
        std::vector<Formula> ev, rest;
        for (const Formula& c : a[0].children()) (c.is_eventual() ? ev : rest).push_back(c);
        if (ev.empty() || rest.empty()) break;
        return mkAnd({mkG(mkF(mkAnd(std::move(rest)))), mkG(mkAnd(std::move(ev)))});
      }
      case Op::Release: return mkG(a[1]);
      case Op::WeakUntil: return mkG(mkOr({a[0], a[1]}));
      case Op::Or: {
        if (auto merged = merge_children(a, Op::Finally)) return mkG(*merged);
        std::vector<Formula> rest, susp;
        for (const Formula& c : a.children()) (suspendable(c) ? susp : rest).push_back(c);
        if (!susp.empty() && !rest.empty()) {
          susp.push_back(mkG(mkOr(std::move(rest))));
          return mkOr(std::move(susp));
        }
        break;
      }
      default:
        break;
    }
    return Formula::G(a);
  }

  // `f` without the operand `x` of its top-level `op` (And/Or): nullopt when
  // x is not an operand; the neutral element when f == x.
  std::optional<Formula> without(const Formula& f, Op op, const Formula& x) {
    if (f == x) return op == Op::Or ? Formula::ff() : Formula::tt();
    if (!f.is(op)) return std::nullopt;
    const auto& kids = f.children();
    if (std::find(kids.begin(), kids.end(), x) == kids.end()) return std::nullopt;
    std::vector<Formula> rest;
    for (const Formula& c : kids)
      if (c != x) rest.push_back(c);
    return op == Op::Or ? mkOr(std::move(rest)) : mkAnd(std::move(rest));
  }

  Formula mkU(const Formula& a, const Formula& b) {
    if (b.is_constant() || a.is(Op::False) || a == b) return b;
    if (a.is(Op::True)) return mkF(b);
    if (b.is_eventual()) return b;
    if (a.is(Op::Next) && b.is(Op::Next)) return mkX(mkU(a[0], b[0]));
    if (implies_budget(a, b)) return b;
    if (auto rest = without(b, Op::Or, mkG(a))) return mkW(a, *rest);  // a U (b | G a) = a W b
    return Formula::U(a, b);
  }

  Formula mkR(const Formula& a, const Formula& b) {
    if (b.is_constant() || a.is(Op::True) || a == b) return b;
    if (a.is(Op::False)) return mkG(b);
    if (b.is_universal()) return b;
    if (a.is(Op::Next) && b.is(Op::Next)) return mkX(mkR(a[0], b[0]));
    if (implies_budget(b, a)) return b;
    if (auto rest = without(b, Op::And, mkF(a))) return mkM(a, *rest);  // a R (b & F a) = a M b
    return Formula::R(a, b);
  }

  Formula mkW(const Formula& a, const Formula& b) {
    if (b.is(Op::True) || a.is(Op::True)) return Formula::tt();
    if (b.is(Op::False)) return mkG(a);
    if (a.is(Op::False) || a == b) return b;
    if (a.is(Op::Next) && b.is(Op::Next)) return mkX(mkW(a[0], b[0]));
    if (implies_budget(a, b)) return b;
    if (auto rest = without(b, Op::Or, mkG(a))) return mkW(a, *rest);  // a W (b | G a) = a W b
    return Formula::W(a, b);
  }

  Formula mkM(const Formula& a, const Formula& b) {
    if (b.is(Op::False) || a.is(Op::False)) return Formula::ff();
    if (b.is(Op::True)) return mkF(a);
    if (a.is(Op::True) || a == b) return b;
    if (a.is(Op::Next) && b.is(Op::Next)) return mkX(mkM(a[0], b[0]));
    if (implies_budget(b, a)) return b;
    if (auto rest = without(b, Op::And, mkF(a))) return mkM(a, *rest);  // a M (b & F a) = a M b
    return Formula::M(a, b);
  }

  // Shared by mkAnd and mkOr: `conj` selects And.
  Formula mkBool(bool conj, std::vector<Formula> cs) {
    const Op op = conj ? Op::And : Op::Or;
    Formula f = Formula::nary(op, std::move(cs));
    if (!f.is(op)) return f;
    const std::vector<Formula>& kids = f.children();
    // a & !a = false, a | !a = true (atoms; children are sorted by id, small).
    for (const Formula& c : kids) {
      if (c.is(Op::Not) && std::find(kids.begin(), kids.end(), c[0]) != kids.end())
        return conj ? Formula::ff() : Formula::tt();
    }
    // Merge the X operands: X a & X b = X(a & b).
    std::size_t nx = 0;
    for (const Formula& c : kids) nx += c.is(Op::Next);
    if (nx >= 2) {
      std::vector<Formula> rest, inner;
      for (const Formula& c : kids) (c.is(Op::Next) ? inner : rest).push_back(c.is(Op::Next) ? c[0] : c);
      rest.push_back(mkX(mkBool(conj, std::move(inner))));
      return mkBool(conj, std::move(rest));
    }
    // Merge U/W/R/M operands that share an operand:
    //   (a U b) & (c U b) = (a & c) U b    (a U b) | (a U c) = a U (b | c)   (same for W)
    //   (a R b) & (a R c) = a R (b & c)    (a R b) | (c R b) = (a | c) R b   (same for M)
    if (Formula merged = merge_shared(conj, kids); merged) return merged;
    // Subsumption: in a conjunction drop x if another kept y ⇒ x; in a
    // disjunction drop x if x ⇒ another kept y.
    if (kids.size() > kMaxSubsumptionWidth) return f;
    std::vector<bool> dropped(kids.size(), false);
    bool any = false;
    for (std::size_t i = 0; i < kids.size(); ++i) {
      for (std::size_t j = 0; j < kids.size(); ++j) {
        if (i == j || dropped[j]) continue;
        if (conj ? implies_budget(kids[j], kids[i]) : implies_budget(kids[i], kids[j])) {
          dropped[i] = true;
          any = true;
          break;
        }
      }
    }
    if (!any) return f;
    std::vector<Formula> kept;
    for (std::size_t i = 0; i < kids.size(); ++i)
      if (!dropped[i]) kept.push_back(kids[i]);
    return Formula::nary(op, std::move(kept));
  }
  // One merge step (see mkBool), or the null formula if nothing merges.
  Formula merge_shared(bool conj, const std::vector<Formula>& kids) {
    for (Op t : {Op::Until, Op::WeakUntil, Op::Release, Op::StrongRelease}) {
      const bool until_like = t == Op::Until || t == Op::WeakUntil;
      const std::size_t shared = (until_like == conj) ? 1 : 0;  // index of the common operand
      for (std::size_t i = 0; i < kids.size(); ++i) {
        if (!kids[i].is(t)) continue;
        std::vector<Formula> inner{kids[i][1 - shared]};
        std::vector<Formula> rest;
        for (std::size_t j = 0; j < kids.size(); ++j) {
          if (j == i) continue;
          if (j > i && kids[j].is(t) && kids[j][shared] == kids[i][shared]) {
            inner.push_back(kids[j][1 - shared]);
          } else {
            rest.push_back(kids[j]);
          }
        }
        if (inner.size() < 2) continue;
        const Formula combined = mkBool(conj, std::move(inner));
        const Formula& common = kids[i][shared];
        const Formula& lhs = shared == 0 ? common : combined;
        const Formula& rhs = shared == 0 ? combined : common;
        switch (t) {
          case Op::Until: rest.push_back(mkU(lhs, rhs)); break;
          case Op::WeakUntil: rest.push_back(mkW(lhs, rhs)); break;
          case Op::Release: rest.push_back(mkR(lhs, rhs)); break;
          default: rest.push_back(mkM(lhs, rhs)); break;
        }
        return mkBool(conj, std::move(rest));
      }
    }
    return Formula();
  }

  Formula mkAnd(std::vector<Formula> cs) { return mkBool(true, std::move(cs)); }
  Formula mkOr(std::vector<Formula> cs) { return mkBool(false, std::move(cs)); }

  std::unordered_map<Formula, Formula> memo_;
};

}  // namespace

bool implies(const Formula& f, const Formula& g) { return implies_budget(f, g); }

Formula simplify(const Formula& f) { return Simplifier().run(nnf(f)); }

}  // namespace rtamp::ltl
