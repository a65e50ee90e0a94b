// Negation normal form (paper Section IV: the translator works on NNF).
//
// nnf(f) is equivalent to f, uses only true false atoms !atom & | X F G U R W M
// (negation only directly on atoms; ->, <->, xor eliminated:
//   a -> b = !a | b,  a <-> b = (a & b) | (!a & !b),  a xor b = (a & !b) | (!a & b)),
// and pushes negations inward with the dualities
//   !X a = X !a, !F a = G !a, !G a = F !a, !(a U b) = !a R !b, !(a R b) = !a U !b,
//   !(a W b) = !a M !b, !(a M b) = !a W !b.
// <-> and xor duplicate their operands; the result is a DAG (shared nodes), so
// its memory stays linear, though its printed size may not.
// Invariants: is_nnf(nnf(f)); nnf(nnf(f)) == nnf(f); memoized per call.
#pragma once

#include "rtamp/ltl/formula.hpp"

namespace rtamp::ltl {

Formula nnf(const Formula& f);

// nnf(!f), without building !f first.
Formula negated_nnf(const Formula& f);

// True if f is in the form described above.
bool is_nnf(const Formula& f);

}  // namespace rtamp::ltl
