// Splitting a formula at its top-level conjunction or disjunction, in the
// manner of Spot's `ltl-split` (docs/translation.md, "Splitting").
//
// The operands of the top-level & (or |) of an NNF formula that is not a
// syntactic obligation are sorted into three kinds: syntactic obligations
// (which the minimal WDBA translates well), suspendable formulas (both
// syntactically eventual and universal, e.g. G F a, F G a: their truth does not
// depend on any finite prefix) and the rest. Obligations form one part (their
// & or | is again an obligation), the rest form one part, and each
// suspendable operand is a part of its own; when there is a rest, the
// syntactic safety obligations join it (they add no acceptance sets and
// constrain its translation, as in Spot). The formula is equivalent to the &
// (|) of all its parts, so its automaton is the product (sum) of theirs; for
// & the suspendable parts may start late (suspended_product.hpp).
// Invariant of a result: at least two parts in all, each smaller than the
// input (a strict subset of its operands).
#pragma once

#include <optional>
#include <vector>

#include "rtamp/ltl/formula.hpp"

namespace rtamp::automata::detail {

struct Split {
  ltl::Op op = ltl::Op::And;              // And: product of the parts; Or: their sum
  std::vector<ltl::Formula> parts;        // the obligations' part, then the rest's
  std::vector<ltl::Formula> suspendable;  // one per suspendable operand
};

// nnf in negation normal form; nothing when it is not an & or | worth
// splitting (a syntactic obligation, or fewer than two parts).
std::optional<Split> split_formula(const ltl::Formula& nnf);

}  // namespace rtamp::automata::detail
