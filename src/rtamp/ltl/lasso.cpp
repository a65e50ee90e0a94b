#include "rtamp/ltl/lasso.hpp"

#include <stdexcept>
#include <unordered_map>

namespace rtamp::ltl {
namespace {

using Values = std::vector<bool>;

class Evaluator {
 public:
  explicit Evaluator(const LassoWord& w) : w_(w), n_(w.prefix.size() + w.cycle.size()) {
    if (w.cycle.empty()) throw std::invalid_argument("lasso word with an empty cycle");
  }

  const Values& eval(const Formula& f) {
    if (auto it = memo_.find(f); it != memo_.end()) return it->second;
    Values v = compute(f);
    return memo_.emplace(f, std::move(v)).first->second;
  }

 private:
  std::size_t succ(std::size_t i) const { return i + 1 < n_ ? i + 1 : w_.prefix.size(); }
  const LassoWord::Letter& letter(std::size_t i) const {
    return i < w_.prefix.size() ? w_.prefix[i] : w_.cycle[i - w_.prefix.size()];
  }

  // Fixpoint of  v[i] = now[i] || (keep[i] && v[succ(i)])   (least, from false)
  // or           v[i] = now[i] && (keep[i] || v[succ(i)])   (greatest, from true).
  // `now` and `keep` are the two operands of the one-step expansion.
  Values least(const Values& now, const Values& keep) const {
    Values v(n_, false);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = n_; i-- > 0;) {
        const bool x = now[i] || (keep[i] && v[succ(i)]);
        if (x != v[i]) {
          v[i] = x;
          changed = true;
        }
      }
    }
    return v;
  }
  Values greatest(const Values& now, const Values& keep) const {
    Values v(n_, true);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = n_; i-- > 0;) {
        const bool x = now[i] && (keep[i] || v[succ(i)]);
        if (x != v[i]) {
          v[i] = x;
          changed = true;
        }
      }
    }
    return v;
  }

  Values compute(const Formula& f) {
    Values v(n_);
    switch (f.op()) {
      case Op::True: v.assign(n_, true); return v;
      case Op::False: v.assign(n_, false); return v;
      case Op::Atom:
        for (std::size_t i = 0; i < n_; ++i) v[i] = letter(i).count(f.name()) != 0;
        return v;
      case Op::Not: {
        const Values& a = eval(f[0]);
        for (std::size_t i = 0; i < n_; ++i) v[i] = !a[i];
        return v;
      }
      case Op::Next: {
        const Values& a = eval(f[0]);
        for (std::size_t i = 0; i < n_; ++i) v[i] = a[succ(i)];
        return v;
      }
      case Op::And:
      case Op::Or: {
        const bool is_and = f.op() == Op::And;
        v.assign(n_, is_and);
        for (const Formula& c : f.children()) {
          const Values& a = eval(c);
          for (std::size_t i = 0; i < n_; ++i) v[i] = is_and ? (v[i] && a[i]) : (v[i] || a[i]);
        }
        return v;
      }
      case Op::Xor:
      case Op::Implies:
      case Op::Equiv: {
        const Values& a = eval(f[0]);
        const Values& b = eval(f[1]);
        for (std::size_t i = 0; i < n_; ++i) {
          if (f.op() == Op::Xor) v[i] = a[i] != b[i];
          else if (f.op() == Op::Implies) v[i] = !a[i] || b[i];
          else v[i] = a[i] == b[i];
        }
        return v;
      }
      case Op::Finally:  // F a = a | X F a
        return least(eval(f[0]), Values(n_, true));
      case Op::Globally:  // G a = a & X G a
        return greatest(eval(f[0]), Values(n_, false));
      case Op::Until: {  // a U b = b | (a & X(a U b))
        const Values& a = eval(f[0]);
        return least(eval(f[1]), a);
      }
      case Op::Release: {  // a R b = b & (a | X(a R b))
        const Values& a = eval(f[0]);
        return greatest(eval(f[1]), a);
      }
      case Op::WeakUntil: {  // a W b = b | (a & X(a W b)), greatest
        const Values& a = eval(f[0]);
        const Values& b = eval(f[1]);
        Values v2(n_, true);
        for (bool changed = true; changed;) {
          changed = false;
          for (std::size_t i = n_; i-- > 0;) {
            const bool x = b[i] || (a[i] && v2[succ(i)]);
            if (x != v2[i]) {
              v2[i] = x;
              changed = true;
            }
          }
        }
        return v2;
      }
      case Op::StrongRelease: {  // a M b = b & (a | X(a M b)), least
        const Values& a = eval(f[0]);
        const Values& b = eval(f[1]);
        Values v2(n_, false);
        for (bool changed = true; changed;) {
          changed = false;
          for (std::size_t i = n_; i-- > 0;) {
            const bool x = b[i] && (a[i] || v2[succ(i)]);
            if (x != v2[i]) {
              v2[i] = x;
              changed = true;
            }
          }
        }
        return v2;
      }
    }
    throw std::logic_error("unknown LTL operator");
  }

  const LassoWord& w_;
  std::size_t n_;
  std::unordered_map<Formula, Values> memo_;
};

}  // namespace

std::vector<bool> evaluate(const Formula& f, const LassoWord& w) {
  Evaluator e(w);
  return e.eval(f);
}

bool holds(const Formula& f, const LassoWord& w) { return evaluate(f, w)[0]; }

std::string to_string(const LassoWord& w) {
  auto letter = [](const LassoWord::Letter& l) {
    std::string s = "{";
    bool first = true;
    for (const std::string& a : l) {
      if (!first) s += ',';
      first = false;
      s += a;
    }
    return s + "}";
  };
  std::string out;
  for (const auto& l : w.prefix) out += letter(l) + " ";
  out += "(";
  bool first = true;
  for (const auto& l : w.cycle) {
    if (!first) out += ' ';
    first = false;
    out += letter(l);
  }
  return out + ")^w";
}

}  // namespace rtamp::ltl
