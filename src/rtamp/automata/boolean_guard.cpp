#include "rtamp/automata/boolean_guard.hpp"

namespace rtamp::automata {

namespace {

using Cubes = std::vector<Cube>;

Cubes dnf(const BoolExpr& e, bool negated, std::size_t max_cubes) {
  using K = BoolExpr::Kind;
  switch (e.kind) {
    case K::True:
      return negated ? Cubes{} : Cubes{Cube{}};
    case K::False:
      return negated ? Cubes{Cube{}} : Cubes{};
    case K::Var: {
      Cube c;
      (negated ? c.neg : c.pos) = Letter{1} << e.var;
      return {c};
    }
    case K::Not:
      return dnf(e.kids.at(0), !negated, max_cubes);
    case K::And:
    case K::Or: {
      const bool conj = (e.kind == K::And) != negated;  // De Morgan
      Cubes acc = conj ? Cubes{Cube{}} : Cubes{};
      for (const BoolExpr& k : e.kids) {
        Cubes sub = dnf(k, negated, max_cubes);
        if (conj) {
          Cubes prod;
          for (const Cube& a : acc)
            for (const Cube& b : sub) {
              Cube c = a & b;
              if (c.is_false()) continue;
              prod.push_back(c);
              if (prod.size() > 4 * max_cubes) throw GuardTooLarge{};
            }
          acc = std::move(prod);
          simplify_cubes(acc);
          if (acc.size() > max_cubes) throw GuardTooLarge{};
          if (acc.empty()) break;  // false
        } else {
          // A disjunction only grows linearly with its text: simplify once.
          acc.insert(acc.end(), sub.begin(), sub.end());
        }
      }
      if (!conj) simplify_cubes(acc);
      return acc;
    }
  }
  return {};
}

}  // namespace

void simplify_cubes(std::vector<Cube>& cubes) {
  std::vector<Cube> out;
  out.reserve(cubes.size());
  for (std::size_t i = 0; i < cubes.size(); ++i) {
    const Cube& c = cubes[i];
    if (c.is_false()) continue;
    bool redundant = false;
    for (std::size_t j = 0; j < cubes.size() && !redundant; ++j) {
      if (j == i || cubes[j].is_false() || !c.implies(cubes[j])) continue;
      // c implies cubes[j]: drop c unless they are equal and c comes first.
      redundant = !(cubes[j] == c) || j < i;
    }
    if (!redundant) out.push_back(c);
  }
  cubes = std::move(out);
}

std::vector<Cube> to_dnf(const BoolExpr& e, std::size_t max_cubes) { return dnf(e, false, max_cubes); }

}  // namespace rtamp::automata
