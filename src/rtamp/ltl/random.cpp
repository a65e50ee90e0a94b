#include "rtamp/ltl/random.hpp"

namespace rtamp::ltl {
namespace {

constexpr Op kLeaves[] = {Op::Atom, Op::True, Op::False};
constexpr Op kUnary[] = {Op::Not, Op::Next, Op::Finally, Op::Globally};
constexpr Op kBinary[] = {Op::And, Op::Or, Op::Xor, Op::Implies, Op::Equiv,
                          Op::Until, Op::Release, Op::WeakUntil, Op::StrongRelease};

template <std::size_t N>
unsigned total(const RandomFormulaOptions& o, const Op (&ops)[N]) {
  unsigned t = 0;
  for (Op op : ops) t += o.weight[static_cast<int>(op)];
  return t;
}

// Picks among the groups enabled (by non-zero total weight).
Op pick(std::mt19937_64& rng, const RandomFormulaOptions& o, bool leaves, bool unary, bool binary) {
  unsigned sum = 0;
  if (leaves) sum += total(o, kLeaves);
  if (unary) sum += total(o, kUnary);
  if (binary) sum += total(o, kBinary);
  std::uint64_t r = uniform(rng, 0, sum - 1);
  auto scan = [&](auto& ops, Op& out) {
    for (Op op : ops) {
      const unsigned w = o.weight[static_cast<int>(op)];
      if (r < w) {
        out = op;
        return true;
      }
      r -= w;
    }
    return false;
  };
  Op out = Op::Atom;
  if (leaves && scan(kLeaves, out)) return out;
  if (unary && scan(kUnary, out)) return out;
  if (binary && scan(kBinary, out)) return out;
  return Op::Atom;
}

Formula gen(std::mt19937_64& rng, const RandomFormulaOptions& o, std::size_t size) {
  const bool has_leaf = total(o, kLeaves) > 0;
  const bool has_unary = total(o, kUnary) > 0;
  const bool has_binary = total(o, kBinary) > 0;
  const bool leaf_only = size <= 1 || (!has_unary && (size == 2 || !has_binary));
  Op op;
  if (leaf_only) {
    op = has_leaf ? pick(rng, o, true, false, false) : Op::Atom;
  } else if (size == 2 || !has_binary) {
    op = pick(rng, o, false, true, false);
  } else {
    op = pick(rng, o, false, has_unary, true);
  }
  switch (op) {
    case Op::True: return Formula::tt();
    case Op::False: return Formula::ff();
    case Op::Atom:
      if (o.atoms.empty()) return Formula::tt();
      return Formula::atom(o.atoms[uniform(rng, 0, o.atoms.size() - 1)]);
    case Op::Not: case Op::Next: case Op::Finally: case Op::Globally:
      return Formula::unary(op, gen(rng, o, size - 1));
    default: {
      const std::size_t left = uniform(rng, 1, size - 2);
      Formula a = gen(rng, o, left);
      Formula b = gen(rng, o, size - 1 - left);
      if (op == Op::And || op == Op::Or) return Formula::nary(op, {a, b});
      return Formula::binary(op, a, b);
    }
  }
}

}  // namespace

RandomFormulaOptions RandomFormulaOptions::without_boolean_sugar() {
  RandomFormulaOptions o;
  o.set_weight(Op::Implies, 0);
  o.set_weight(Op::Equiv, 0);
  o.set_weight(Op::Xor, 0);
  return o;
}

std::uint64_t uniform(std::mt19937_64& rng, std::uint64_t lo, std::uint64_t hi) {
  if (hi <= lo) return lo;
  const std::uint64_t span = hi - lo + 1;
  if (span == 0) return rng();  // the full 64-bit range
  // Rejection sampling for an unbiased draw.
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
  std::uint64_t x;
  do {
    x = rng();
  } while (x >= limit);
  return lo + x % span;
}

Formula random_formula(std::mt19937_64& rng, const RandomFormulaOptions& options) {
  return gen(rng, options, options.size == 0 ? 1 : options.size);
}

LassoWord random_lasso(std::mt19937_64& rng, const std::vector<std::string>& atoms, std::size_t max_prefix,
                       std::size_t max_cycle) {
  LassoWord w;
  auto letter = [&] {
    LassoWord::Letter l;
    for (const std::string& a : atoms)
      if (rng() & 1) l.insert(a);
    return l;
  };
  const std::size_t np = uniform(rng, 0, max_prefix);
  const std::size_t nc = uniform(rng, 1, max_cycle < 1 ? 1 : max_cycle);
  for (std::size_t i = 0; i < np; ++i) w.prefix.push_back(letter());
  for (std::size_t i = 0; i < nc; ++i) w.cycle.push_back(letter());
  return w;
}

}  // namespace rtamp::ltl
