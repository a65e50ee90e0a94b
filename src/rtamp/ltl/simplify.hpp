// LTL simplification before translation (paper Section IV: smaller formulas
// give smaller Büchi automata, which the planner's product search explores).
//
// simplify(f) = rewrite(nnf(f)): the result is equivalent to f and in negation
// normal form (see nnf.hpp), so the translator's simplify() then nnf() pipeline
// is a no-op in its second step. The rewriting is bottom-up, memoized per node
// within one call, and applies the rules below (Spot's "basic" rewritings,
// Etessami–Holzmann and Somenzi–Bloem rules). Notation: e is a pure
// eventuality (e ≡ F e), u is purely universal (u ≡ G u), s is both
// (s ≡ X s), and  x ⇒ y  is the syntactic implication check `implies`.
//
//   X s = s                       F e = e                  G u = u
//   F(a | b) = F a | F b          G(a & b) = G a & G b
//   G(F p | F q | r) = G(F(p | q) | r)   F(G p & G q & r) = F(G(p & q) & r)
//        (p, q Boolean: undoes the line above under G / F, so that
//        G F(p | q) and F G(p & q) keep one eventuality / one invariant)
//   F X a = X F a                 G X a = X G a
//   G X e = G e                   G F(a & e) = G F a & G e
//   F(a U b) = F b                G(a R b) = G b
//   F(a M b) = F(a & b)           G(a W b) = G(a | b)
//   F(a & s) = F a & s            G(a | s) = G a | s
//   a U e = e                     a R u = u
//   a U a = a  (also R W M)       X a U X b = X(a U b)  (also R W M)
//   a U b = b,  a W b = b         if a ⇒ b
//   a R b = b,  a M b = b         if b ⇒ a
//   true U b = F b   false R b = G b   a W false = G a   a M true = F a
//   and the constant cases of U R W M.
//   x & y = x  if x ⇒ y           x | y = y  if x ⇒ y     (subsumption:
//        a & (a | b) = a,  (a U b) | b = a U b,  a U (b U a) = b U a, ...)
//   (a U b) & (c U b) = (a & c) U b    (a U b) | (a U c) = a U (b | c)   (also W)
//   (a R b) & (a R c) = a R (b & c)    (a R b) | (c R b) = (a | c) R b   (also M)
//   a & !a = false,  a | !a = true   (atoms)
//   X a & X b = X(a & b)          X a | X b = X(a | b)
//   (G F a & G F b is kept: G distributes over &, never the reverse.)
//
// `implies(f, g)` is sound but incomplete (Somenzi–Bloem style structural
// rules with a step budget); it never claims an implication that does not hold.
// Every rule is checked against the lasso-word semantics (lasso.hpp) in
// tests/ltl/nnf_simplify_test.cpp.
#pragma once

#include "rtamp/ltl/formula.hpp"

namespace rtamp::ltl {

Formula simplify(const Formula& f);

// Sound syntactic implication: true only if every word satisfying f satisfies g.
// f and g should be in NNF (other operators are treated as opaque).
bool implies(const Formula& f, const Formula& g);

}  // namespace rtamp::ltl
