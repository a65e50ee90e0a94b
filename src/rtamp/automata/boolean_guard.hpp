// Boolean guards as readers meet them (HOA labels such as `0 & !(1 | @a)`,
// never-claim guards such as `((p) && !(q))`), and their conversion to the
// DNF of cubes that Automaton edges carry (automaton.hpp: one edge per cube).
//
// Support code for the automata readers (hoa_reader, never_claim_reader); not
// part of the paper. Invariants: to_dnf() returns non-contradictory cubes with
// no cube implying another one (subsumed cubes are dropped); an empty result
// means `false`, a single true cube means `true`.
#pragma once

#include <cstddef>
#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

struct BoolExpr {
  enum class Kind : unsigned char { False, True, Var, Not, And, Or };
  Kind kind = Kind::True;
  unsigned var = 0;               // atom index, for Var
  std::vector<BoolExpr> kids;     // Not: one; And/Or: two or more

  static BoolExpr constant(bool b) { return {b ? Kind::True : Kind::False, 0, {}}; }
  static BoolExpr variable(unsigned v) { return {Kind::Var, v, {}}; }
  static BoolExpr negate(BoolExpr e) { return {Kind::Not, 0, {std::move(e)}}; }
  static BoolExpr both(BoolExpr a, BoolExpr b) { return {Kind::And, 0, {std::move(a), std::move(b)}}; }
  static BoolExpr either(BoolExpr a, BoolExpr b) { return {Kind::Or, 0, {std::move(a), std::move(b)}}; }
};

// Thrown (as a plain flag) when a conjunction's DNF would exceed `max_cubes`
// cubes (disjunctions grow only linearly with the text and are not limited);
// the readers turn it into an rtamp::Error that names the guard's location.
struct GuardTooLarge {};

// Disjunctive normal form of `e`; throws GuardTooLarge past `max_cubes`.
std::vector<Cube> to_dnf(const BoolExpr& e, std::size_t max_cubes = 1024);

// Removes contradictory cubes and cubes implied by another cube (keeps order
// of first occurrence among the survivors).
void simplify_cubes(std::vector<Cube>& cubes);

}  // namespace rtamp::automata
