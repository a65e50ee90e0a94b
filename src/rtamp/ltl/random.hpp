// Random LTL formulas (in the manner of Spot's randltl) and random lasso words,
// for property tests and benchmarks (paper Section V: random specifications).
//
// random_formula draws a syntax tree of exactly `size` nodes before the
// constructors' trivial identities apply (so the result may be smaller):
// size 1 picks a leaf (atom, true, false), size 2 a unary operator over a leaf,
// size ≥ 3 any operator whose arity fits, splitting the remaining size
// uniformly between the operands of a binary operator. Each choice is
// weighted by `weight[Op]` (0 disables an operator). Same seed, same options:
// same formula (std::mt19937_64 and our own distributions, so the sequence does
// not depend on the standard library).
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "rtamp/ltl/formula.hpp"
#include "rtamp/ltl/lasso.hpp"

namespace rtamp::ltl {

struct RandomFormulaOptions {
  std::vector<std::string> atoms = {"a", "b", "c"};
  std::size_t size = 15;  // like randltl --tree-size
  // Weight of each operator, indexed by static_cast<int>(Op). Defaults as
  // randltl's: atoms 3, every other operator and constant 1.
  std::array<unsigned, 16> weight = {1, 1, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};

  void set_weight(Op op, unsigned w) { weight[static_cast<int>(op)] = w; }
  // Defaults with ->, <-> and xor disabled: only ! & | X F G U R W M and leaves.
  static RandomFormulaOptions without_boolean_sugar();
};

Formula random_formula(std::mt19937_64& rng, const RandomFormulaOptions& options);

// A lasso word over `atoms`: prefix length uniform in [0, max_prefix], cycle
// length uniform in [1, max_cycle], each atom in each letter with probability 1/2.
LassoWord random_lasso(std::mt19937_64& rng, const std::vector<std::string>& atoms, std::size_t max_prefix = 4,
                       std::size_t max_cycle = 4);

// Uniform integer in [lo, hi] (inclusive), independent of the standard library's distributions.
std::uint64_t uniform(std::mt19937_64& rng, std::uint64_t lo, std::uint64_t hi);

}  // namespace rtamp::ltl
