#include "rtamp/ltl/nnf.hpp"

#include <unordered_map>
#include <unordered_set>

namespace rtamp::ltl {
namespace {

class Nnf {
 public:
  Formula run(const Formula& f, bool neg) {
    auto& memo = memo_[neg ? 1 : 0];
    if (auto it = memo.find(f); it != memo.end()) return it->second;
    Formula r = neg ? negative(f) : positive(f);
    memo.emplace(f, r);
    return r;
  }

 private:
  Formula positive(const Formula& f) {
    switch (f.op()) {
      case Op::True: case Op::False: case Op::Atom: return f;
      case Op::Not: return run(f[0], true);
      case Op::Next: return Formula::X(run(f[0], false));
      case Op::Finally: return Formula::F(run(f[0], false));
      case Op::Globally: return Formula::G(run(f[0], false));
      case Op::And: case Op::Or: {
        std::vector<Formula> cs;
        cs.reserve(f.arity());
        for (const Formula& c : f.children()) cs.push_back(run(c, false));
        return Formula::nary(f.op(), std::move(cs));
      }
      case Op::Xor: return exclusive(f[0], f[1]);
      case Op::Implies: return Formula::Or(run(f[0], true), run(f[1], false));
      case Op::Equiv: return equivalent(f[0], f[1]);
      case Op::Until: case Op::Release: case Op::WeakUntil: case Op::StrongRelease:
        return Formula::binary(f.op(), run(f[0], false), run(f[1], false));
    }
    return f;
  }

  Formula negative(const Formula& f) {
    switch (f.op()) {
      case Op::True: return Formula::ff();
      case Op::False: return Formula::tt();
      case Op::Atom: return Formula::Not(f);
      case Op::Not: return run(f[0], false);
      case Op::Next: return Formula::X(run(f[0], true));
      case Op::Finally: return Formula::G(run(f[0], true));
      case Op::Globally: return Formula::F(run(f[0], true));
      case Op::And: case Op::Or: {
        std::vector<Formula> cs;
        cs.reserve(f.arity());
        for (const Formula& c : f.children()) cs.push_back(run(c, true));
        return Formula::nary(f.op() == Op::And ? Op::Or : Op::And, std::move(cs));
      }
      case Op::Xor: return equivalent(f[0], f[1]);
      case Op::Implies: return Formula::And(run(f[0], false), run(f[1], true));
      case Op::Equiv: return exclusive(f[0], f[1]);
      case Op::Until: return Formula::R(run(f[0], true), run(f[1], true));
      case Op::Release: return Formula::U(run(f[0], true), run(f[1], true));
      case Op::WeakUntil: return Formula::M(run(f[0], true), run(f[1], true));
      case Op::StrongRelease: return Formula::W(run(f[0], true), run(f[1], true));
    }
    return f;
  }

  Formula equivalent(const Formula& a, const Formula& b) {
    return Formula::Or(Formula::And(run(a, false), run(b, false)), Formula::And(run(a, true), run(b, true)));
  }
  Formula exclusive(const Formula& a, const Formula& b) {
    return Formula::Or(Formula::And(run(a, false), run(b, true)), Formula::And(run(a, true), run(b, false)));
  }

  std::unordered_map<Formula, Formula> memo_[2];
};

bool is_nnf_rec(const Formula& f, std::unordered_set<Formula>& seen) {
  if (!seen.insert(f).second) return true;
  switch (f.op()) {
    case Op::Not: return f[0].op() == Op::Atom;
    case Op::Xor: case Op::Implies: case Op::Equiv: return false;
    default:
      for (const Formula& c : f.children())
        if (!is_nnf_rec(c, seen)) return false;
      return true;
  }
}

}  // namespace

Formula nnf(const Formula& f) { return Nnf().run(f, false); }
Formula negated_nnf(const Formula& f) { return Nnf().run(f, true); }

bool is_nnf(const Formula& f) {
  std::unordered_set<Formula> seen;
  return is_nnf_rec(f, seen);
}

}  // namespace rtamp::ltl
