// Direct LTL semantics on ultimately periodic words u·v^ω (paper Section II:
// the semantics of φ; plans are lassos). This is the independent oracle for
// the translator, NNF and simplifier tests: it uses no automata.
//
// A letter is the set of atom names true at that step. Position i of the lasso
// has successor i+1, except the last position whose successor is |u| (the
// start of the cycle). Every suffix of u·v^ω equals the suffix at one of these
// |u|+|v| positions, so each subformula has one truth value per position,
// computed bottom-up: Boolean operators pointwise, X by the successor, and
//   U, F, M  as least fixpoints     (iterate from all-false),
//   R, G, W  as greatest fixpoints  (iterate from all-true)
// of their one-step expansions, e.g. a U b = b | (a & X(a U b)).
// Invariant: the cycle is non-empty (holds() throws std::invalid_argument
// otherwise).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "rtamp/ltl/formula.hpp"

namespace rtamp::ltl {

struct LassoWord {
  using Letter = std::set<std::string>;
  std::vector<Letter> prefix;  // u (may be empty)
  std::vector<Letter> cycle;   // v (non-empty)
};

// Does u·v^ω satisfy f (at position 0)?
bool holds(const Formula& f, const LassoWord& w);

// Truth value of f at each of the |u|+|v| positions.
std::vector<bool> evaluate(const Formula& f, const LassoWord& w);

// "{a,b} {} ; ({a})^ω" style text, for test failure messages.
std::string to_string(const LassoWord& w);

}  // namespace rtamp::ltl
