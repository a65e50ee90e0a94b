#include "rtamp/automata/vwaa.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "rtamp/util/error.hpp"

namespace rtamp::automata::detail {

using ltl::Formula;
using ltl::Op;

// ---------------------------------------------------------------- SetPool

SetPool::SetPool(std::size_t num_bits) : words_(std::max<std::size_t>(1, (num_bits + 63) / 64)) {
  slots_.assign(64, UINT32_MAX);
  scratch_.assign(words_, 0);
  intern(scratch_.data());  // id 0 = empty set
}

std::size_t SetPool::hash(const std::uint64_t* w) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (std::size_t i = 0; i < words_; ++i) {
    h ^= w[i] + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xff51afd7ed558ccdull;
  }
  return static_cast<std::size_t>(h ^ (h >> 33));
}

void SetPool::grow() {
  std::vector<std::uint32_t> old(slots_.size() * 2, UINT32_MAX);
  old.swap(slots_);
  const std::size_t mask = slots_.size() - 1;
  for (std::uint32_t id = 0; id < size(); ++id) {
    std::size_t i = hash(data(id)) & mask;
    while (slots_[i] != UINT32_MAX) i = (i + 1) & mask;
    slots_[i] = id;
  }
}

std::uint32_t SetPool::intern(const std::uint64_t* w) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = hash(w) & mask;
  while (slots_[i] != UINT32_MAX) {
    if (std::equal(w, w + words_, data(slots_[i]))) return slots_[i];
    i = (i + 1) & mask;
  }
  const std::uint32_t id = size();
  // Copy before insert: w may point into store_.
  std::vector<std::uint64_t> copy(w, w + words_);
  store_.insert(store_.end(), copy.begin(), copy.end());
  slots_[i] = id;
  if (std::size_t{size()} * 2 > slots_.size()) grow();
  return id;
}

std::uint32_t SetPool::singleton(std::uint32_t bit) {
  std::fill(scratch_.begin(), scratch_.end(), 0);
  scratch_[bit / 64] |= std::uint64_t{1} << (bit % 64);
  return intern(scratch_.data());
}

std::uint32_t SetPool::unite(std::uint32_t a, std::uint32_t b) {
  if (a == b || b == 0) return a;
  if (a == 0) return b;
  const std::uint64_t* x = data(a);
  const std::uint64_t* y = data(b);
  for (std::size_t i = 0; i < words_; ++i) scratch_[i] = x[i] | y[i];
  return intern(scratch_.data());
}

bool SetPool::subset(std::uint32_t a, std::uint32_t b) const {
  if (a == b || a == 0) return true;
  const std::uint64_t* x = data(a);
  const std::uint64_t* y = data(b);
  for (std::size_t i = 0; i < words_; ++i)
    if (x[i] & ~y[i]) return false;
  return true;
}

// ---------------------------------------------------------------- terms

namespace {
// t1 makes t2 redundant.
bool subsumes(const Term& t1, const Term& t2, const SetPool& pool) {
  return t2.guard.implies(t1.guard) && (t1.postponed & ~t2.postponed) == 0 && pool.subset(t1.targets, t2.targets);
}
}  // namespace

void remove_subsumed(Terms& t, const SetPool& pool) {
  const std::size_t n = t.size();
  if (n < 2) return;
  std::vector<char> dead(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (dead[i]) continue;
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || dead[j]) continue;
      if (subsumes(t[j], t[i], pool)) {
        // Equal terms: keep the first.
        if (subsumes(t[i], t[j], pool) && i < j) continue;
        dead[i] = 1;
        break;
      }
    }
  }
  std::size_t w = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!dead[i]) t[w++] = t[i];
  t.resize(w);
}

Terms product(const Terms& a, const Terms& b, SetPool& pool) {
  if (a.size() * b.size() > kMaxProductTerms)
    throw Error("formula too large to translate: a transition product exceeds " + std::to_string(kMaxProductTerms) +
                    " terms",
                {}, {});
  Terms out;
  out.reserve(a.size() * b.size());
  for (const Term& x : a)
    for (const Term& y : b) {
      Cube g = x.guard & y.guard;
      if (g.is_false()) continue;
      out.push_back(Term{g, pool.unite(x.targets, y.targets), x.postponed | y.postponed});
    }
  remove_subsumed(out, pool);
  return out;
}

// ---------------------------------------------------------------- NNF

namespace {

Formula nnf(const Formula& f, bool neg) {
  switch (f.op()) {
    case Op::True: return neg ? Formula::ff() : f;
    case Op::False: return neg ? Formula::tt() : f;
    case Op::Atom: return neg ? Formula::Not(f) : f;
    case Op::Not: return nnf(f[0], !neg);
    case Op::Next: return Formula::X(nnf(f[0], neg));
    case Op::Finally: return neg ? Formula::G(nnf(f[0], true)) : Formula::F(nnf(f[0], false));
    case Op::Globally: return neg ? Formula::F(nnf(f[0], true)) : Formula::G(nnf(f[0], false));
    case Op::And:
    case Op::Or: {
      std::vector<Formula> c;
      c.reserve(f.arity());
      for (const Formula& g : f.children()) c.push_back(nnf(g, neg));
      return (f.is(Op::And) != neg) ? Formula::And(std::move(c)) : Formula::Or(std::move(c));
    }
    case Op::Xor:
    case Op::Equiv: {
      const bool equiv = f.is(Op::Equiv) != neg;  // a<->b, or !(a xor b)
      const Formula a = nnf(f[0], false), na = nnf(f[0], true);
      const Formula b = nnf(f[1], false), nb = nnf(f[1], true);
      return equiv ? Formula::Or(Formula::And(a, b), Formula::And(na, nb))
                   : Formula::Or(Formula::And(a, nb), Formula::And(na, b));
    }
    case Op::Implies:
      return neg ? Formula::And(nnf(f[0], false), nnf(f[1], true)) : Formula::Or(nnf(f[0], true), nnf(f[1], false));
    case Op::Until:
      return neg ? Formula::R(nnf(f[0], true), nnf(f[1], true)) : Formula::U(nnf(f[0], false), nnf(f[1], false));
    case Op::Release:
      return neg ? Formula::U(nnf(f[0], true), nnf(f[1], true)) : Formula::R(nnf(f[0], false), nnf(f[1], false));
    case Op::WeakUntil:
      return neg ? Formula::M(nnf(f[0], true), nnf(f[1], true)) : Formula::W(nnf(f[0], false), nnf(f[1], false));
    case Op::StrongRelease:
      return neg ? Formula::W(nnf(f[0], true), nnf(f[1], true)) : Formula::M(nnf(f[0], false), nnf(f[1], false));
  }
  return f;
}

void collect_atoms(const Formula& f, std::unordered_set<Formula>& seen, std::vector<std::string>& out) {
  if (!seen.insert(f).second) return;
  if (f.is(Op::Atom)) out.push_back(f.name());
  for (const Formula& c : f.children()) collect_atoms(c, seen, out);
}

// Light rewriting of the NNF that keeps the VWAA small (all valid identities;
// see also weak_disjunction above):
// a U b with b eventual is b, a R b with b universal is b, true U b = F b,
// false R b = G b, F(a | b) stays (δ handles it), X true = true.
// Disjunctions that are weak operators in disguise (valid identities):
//   (a U b) | G a = a W b,   (a M b) | G b = a R b,
//   G a | F(!a & e) = a W (!a & e)   when e is a pure eventuality (e = F e):
//   if !a & e holds at some j, then at the first i <= j where !a holds, e
//   holds too (e at j implies e at every earlier position).
// Returns the rewritten disjunction, or the null formula if nothing applies.
Formula weak_disjunction(const Formula& r) {
  std::vector<Formula> c = r.children();
  bool changed = false;
  auto find = [&](const Formula& g) {
    for (std::size_t j = 0; j < c.size(); ++j)
      if (c[j] == g) return static_cast<std::ptrdiff_t>(j);
    return std::ptrdiff_t{-1};
  };
  for (std::size_t i = 0; i < c.size(); ++i) {
    Formula repl;
    std::ptrdiff_t j = -1;
    if (c[i].is(Op::Until)) {
      j = find(Formula::G(c[i][0]));
      if (j >= 0) repl = Formula::W(c[i][0], c[i][1]);
    } else if (c[i].is(Op::StrongRelease)) {
      j = find(Formula::G(c[i][1]));
      if (j >= 0) repl = Formula::R(c[i][0], c[i][1]);
    } else if (c[i].is(Op::Globally)) {
      const Formula& a = c[i][0];
      const Formula na = nnf(a, true);
      for (std::size_t k = 0; k < c.size() && j < 0; ++k) {
        if (!c[k].is(Op::Finally)) continue;
        const Formula& y = c[k][0];
        if (y == na || (y.is(Op::And) && std::find(y.children().begin(), y.children().end(), na) != y.children().end())) {
          std::vector<Formula> rest;
          if (y.is(Op::And))
            for (const Formula& z : y.children())
              if (z != na) rest.push_back(z);
          const Formula e = Formula::And(rest);
          if (e.is_eventual()) {
            j = static_cast<std::ptrdiff_t>(k);
            repl = Formula::W(a, y);
          }
        }
      }
    }
    if (j >= 0) {
      c[i] = repl;
      c.erase(c.begin() + j);
      changed = true;
      i = static_cast<std::size_t>(-1);  // restart: indices moved
    }
  }
  return changed ? Formula::Or(std::move(c)) : Formula();
}

Formula tidy(const Formula& f) {
  if (f.arity() == 0) return f;
  std::vector<Formula> c;
  c.reserve(f.arity());
  for (const Formula& g : f.children()) c.push_back(tidy(g));
  Formula r = f.with_children(std::move(c));
  switch (r.op()) {
    case Op::Until:
      if (r[1].is_eventual()) return r[1];
      if (r[0].is(Op::True)) return Formula::F(r[1]);
      if (r[0].is(Op::False)) return r[1];
      break;
    case Op::Release:
      if (r[1].is_universal()) return r[1];
      if (r[0].is(Op::False)) return Formula::G(r[1]);
      if (r[0].is(Op::True)) return r[1];
      break;
    case Op::WeakUntil:
      if (r[0].is(Op::True)) return Formula::tt();
      if (r[0].is(Op::False)) return r[1];
      break;
    case Op::StrongRelease:
      if (r[0].is(Op::False)) return Formula::ff();
      if (r[0].is(Op::True)) return r[1];
      break;
    case Op::Finally:
      if (r[0].is_eventual() && !r[0].is_constant()) return r[0];
      break;
    case Op::Globally:
      if (r[0].is_universal() && !r[0].is_constant()) return r[0];
      break;
    case Op::Or:
      if (Formula w = weak_disjunction(r); !w.is_null()) return tidy(w);
      break;
    default:
      break;
  }
  return r;
}

bool is_state_formula(const Formula& f) {
  switch (f.op()) {
    case Op::And: case Op::Or: case Op::True: case Op::False: return false;
    default: return true;
  }
}

class Builder {
 public:
  Builder(Vwaa& v, const std::vector<std::string>& atoms) : v_(v) {
    for (std::size_t i = 0; i < atoms.size(); ++i) atom_bit_[atoms[i]] = i;
  }

  std::uint32_t state(const Formula& f) {
    if (auto it = state_id_.find(f); it != state_id_.end()) return it->second;
    const auto id = static_cast<std::uint32_t>(v_.states.size());
    state_id_.emplace(f, id);
    v_.states.push_back(f);
    v_.delta.emplace_back();
    v_.delta[id] = compute_state_delta(f, id);
    return id;
  }

  // dnf(f): the conjunctions of states equivalent to f.
  std::vector<std::uint32_t> dnf(const Formula& f) {
    switch (f.op()) {
      case Op::True: return {0};
      case Op::False: return {};
      case Op::Or: {
        std::vector<std::uint32_t> out;
        for (const Formula& g : f.children())
          for (std::uint32_t s : dnf(g)) out.push_back(s);
        return minimise(out);
      }
      case Op::And: {
        std::vector<std::uint32_t> acc{0};
        for (const Formula& g : f.children()) {
          std::vector<std::uint32_t> next;
          for (std::uint32_t s : dnf(g))
            for (std::uint32_t a : acc) next.push_back(v_.sets.unite(a, s));
          acc = minimise(next);
        }
        return acc;
      }
      default:
        return {v_.sets.singleton(state(f))};
    }
  }

  // δ of any NNF formula (states are looked up, And/Or combined).
  Terms delta(const Formula& f) {
    switch (f.op()) {
      case Op::True: return {Term{}};
      case Op::False: return {};
      case Op::And: {
        Terms acc{Term{}};
        for (const Formula& g : f.children()) {
          acc = product(acc, delta(g), v_.sets);
          if (acc.empty()) break;
        }
        return acc;
      }
      case Op::Or: {
        Terms out;
        for (const Formula& g : f.children()) {
          Terms d = delta(g);
          out.insert(out.end(), d.begin(), d.end());
        }
        remove_subsumed(out, v_.sets);
        return out;
      }
      default:
        return v_.delta[state(f)];
    }
  }

  std::uint64_t key(const Formula& promised) {
    auto [it, fresh] = key_id_.emplace(promised, static_cast<std::uint32_t>(key_id_.size()));
    if (fresh && it->second >= 64)
      throw Error("formula has too many distinct eventualities for the translation (at most 64)", {}, {});
    return std::uint64_t{1} << it->second;
  }

  std::uint32_t num_keys() const { return static_cast<std::uint32_t>(key_id_.size()); }

 private:
  std::vector<std::uint32_t> minimise(std::vector<std::uint32_t> sets) {
    std::sort(sets.begin(), sets.end());
    sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
    std::vector<std::uint32_t> out;
    for (std::uint32_t s : sets) {
      bool redundant = false;
      for (std::uint32_t o : sets)
        if (o != s && v_.sets.subset(o, s)) { redundant = true; break; }
      if (!redundant) out.push_back(s);
    }
    return out;
  }

  Cube literal(const Formula& f) {
    const bool neg = f.is(Op::Not);
    const std::string& name = neg ? f[0].name() : f.name();
    const Letter bit = Letter{1} << atom_bit_.at(name);
    return neg ? Cube{0, bit} : Cube{bit, 0};
  }

  Terms compute_state_delta(const Formula& f, std::uint32_t self) {
    const std::uint32_t me = v_.sets.singleton(self);
    switch (f.op()) {
      case Op::Atom:
      case Op::Not:
        return {Term{literal(f), 0, 0}};
      case Op::Or: {
        Terms out;
        for (const Formula& g : f.children()) {
          Terms d = delta(g);
          out.insert(out.end(), d.begin(), d.end());
        }
        remove_subsumed(out, v_.sets);
        return out;
      }
      case Op::Next: {
        Terms out;
        for (std::uint32_t s : dnf(f[0])) out.push_back(Term{Cube{}, s, 0});
        return out;
      }
      case Op::Finally: {
        const std::uint64_t k = key(f[0]);
        Terms out = delta(f[0]);
        out.push_back(Term{Cube{}, me, k});
        remove_subsumed(out, v_.sets);
        return out;
      }
      case Op::Globally:
        return product(delta(f[0]), {Term{Cube{}, me, 0}}, v_.sets);
      case Op::Until: {
        const std::uint64_t k = key(f[1]);
        Terms out = delta(f[1]);
        Terms stay = product(delta(f[0]), {Term{Cube{}, me, k}}, v_.sets);
        out.insert(out.end(), stay.begin(), stay.end());
        remove_subsumed(out, v_.sets);
        return out;
      }
      case Op::WeakUntil: {
        Terms out = delta(f[1]);
        Terms stay = product(delta(f[0]), {Term{Cube{}, me, 0}}, v_.sets);
        out.insert(out.end(), stay.begin(), stay.end());
        remove_subsumed(out, v_.sets);
        return out;
      }
      case Op::Release: {
        Terms db = delta(f[1]);
        Terms out = product(delta(f[0]), db, v_.sets);
        Terms stay = product(db, {Term{Cube{}, me, 0}}, v_.sets);
        out.insert(out.end(), stay.begin(), stay.end());
        remove_subsumed(out, v_.sets);
        return out;
      }
      case Op::StrongRelease: {
        const std::uint64_t k = key(Formula::And(f[0], f[1]));
        Terms db = delta(f[1]);
        Terms out = product(delta(f[0]), db, v_.sets);
        Terms stay = product(db, {Term{Cube{}, me, k}}, v_.sets);
        out.insert(out.end(), stay.begin(), stay.end());
        remove_subsumed(out, v_.sets);
        return out;
      }
      default:
        throw Error("internal error: formula not in negation normal form", {}, {});
    }
  }

  Vwaa& v_;
  std::unordered_map<std::string, std::size_t> atom_bit_;
  std::unordered_map<Formula, std::uint32_t> state_id_;
  std::unordered_map<Formula, std::uint32_t> key_id_;
};

std::size_t count_state_formulas(const Formula& f, std::unordered_set<Formula>& seen) {
  if (!seen.insert(f).second) return 0;
  std::size_t n = is_state_formula(f) ? 1 : 0;
  for (const Formula& c : f.children()) n += count_state_formulas(c, seen);
  return n;
}

}  // namespace

Formula to_nnf(const Formula& f) { return tidy(nnf(f, false)); }

std::vector<std::string> atoms_of(const Formula& f) {
  std::unordered_set<Formula> seen;
  std::vector<std::string> out;
  collect_atoms(f, seen, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Vwaa build_vwaa(const Formula& f) {
  std::unordered_set<Formula> seen;
  // Literals count twice at most (p and !p share nothing), which the bound covers.
  Vwaa v(count_state_formulas(f, seen) + 1);
  v.atoms = atoms_of(f);
  if (v.atoms.size() > kMaxAtoms)
    throw Error("too many atomic propositions (at most " + std::to_string(kMaxAtoms) + ")", {}, {});
  Builder b(v, v.atoms);
  v.initial_sets = b.dnf(f);
  v.num_keys = b.num_keys();
  // δ(φ) is only needed for a fresh initial state (φ a disjunction at the top).
  if (v.initial_sets.size() > 1) v.initial_delta = b.delta(f);
  return v;
}

}  // namespace rtamp::automata::detail
