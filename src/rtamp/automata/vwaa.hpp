// Very weak alternating automaton of an LTL formula (Gastin & Oddoux, CAV'01,
// Section 2), the first stage of translate.hpp.
//
// States of the VWAA are the subformulas of the NNF formula that are not
// And/Or/true/false (temporal formulas and literals that occur under X).
// The transition function δ(ψ) is a set of Terms (guard cube, conjunctive set
// of target states, postponed eventualities), computed as in the paper:
//   δ(ℓ) = {(ℓ, ∅)}, δ(Xψ) = {(⊤, e) | e ∈ dnf(ψ)}, δ(a∧b) = δ(a) ⊗ δ(b),
//   δ(a∨b) = δ(a) ∪ δ(b), δ(aUb) = δ(b) ∪ (δ(a) ⊗ (⊤, {aUb}, postpone)), ...
// Acceptance: one "key" per distinct promised formula (b for a U b and F b,
// a ∧ b for a M b); a term postpones key k when it keeps an eventuality with
// key k pending. Sharing a key between eventualities with the same promised
// formula is sound and complete (all of them can be fulfilled at the step where
// the promised formula holds) and gives fewer acceptance sets than one per
// Until.
// Invariant: every term list is free of contradictory guards and of terms
// subsumed by another term (same or weaker guard, subset of targets, subset of
// postponed keys).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/ltl/formula.hpp"

namespace rtamp::automata::detail {

// Sets of VWAA states as dense bitsets, hash-consed: equal sets have equal ids.
// Id 0 is the empty set.
class SetPool {
 public:
  explicit SetPool(std::size_t num_bits);
  std::size_t words() const { return words_; }
  std::uint32_t size() const { return static_cast<std::uint32_t>(store_.size() / words_); }
  const std::uint64_t* data(std::uint32_t id) const { return store_.data() + std::size_t{id} * words_; }
  std::uint32_t intern(const std::uint64_t* w);
  std::uint32_t singleton(std::uint32_t bit);
  std::uint32_t unite(std::uint32_t a, std::uint32_t b);
  bool subset(std::uint32_t a, std::uint32_t b) const;  // a ⊆ b
  bool contains(std::uint32_t set, std::uint32_t bit) const {
    return (data(set)[bit / 64] >> (bit % 64)) & 1u;
  }
  template <class Fn>
  void for_each(std::uint32_t set, Fn&& fn) const {
    const std::uint64_t* w = data(set);
    for (std::size_t i = 0; i < words_; ++i)
      for (std::uint64_t b = w[i]; b; b &= b - 1) fn(static_cast<std::uint32_t>(i * 64 + __builtin_ctzll(b)));
  }

 private:
  std::size_t hash(const std::uint64_t* w) const;
  void grow();
  std::size_t words_;
  std::vector<std::uint64_t> store_;
  std::vector<std::uint32_t> slots_;  // open addressing; UINT32_MAX = empty
  std::vector<std::uint64_t> scratch_;
};

struct Term {
  Cube guard;
  std::uint32_t targets = 0;    // SetPool id
  std::uint64_t postponed = 0;  // bit k: eventuality key k kept pending
};
using Terms = std::vector<Term>;

// Removes terms subsumed by another one (keeps the first of equal terms).
void remove_subsumed(Terms& t, const SetPool& pool);
// a ⊗ b: pairwise conjunction, contradictions dropped, subsumed terms removed.
// Throws rtamp::Error ("formula too large to translate") when |a|·|b| exceeds
// kMaxProductTerms (subsumption removal is quadratic in the product).
constexpr std::size_t kMaxProductTerms = 20'000;
Terms product(const Terms& a, const Terms& b, SetPool& pool);

struct Vwaa {
  explicit Vwaa(std::size_t num_states) : sets(num_states) {}
  SetPool sets;
  std::vector<ltl::Formula> states;   // VWAA states (NNF subformulas)
  std::vector<Terms> delta;           // δ per state
  Terms initial_delta;                // δ(φ), computed only when initial_sets.size() > 1
  std::vector<std::uint32_t> initial_sets;  // dnf(φ): the initial conjunctions
  std::vector<std::string> atoms;     // sorted by name; bit i of a Letter = atoms[i]
  std::uint32_t num_keys = 0;         // eventuality keys = acceptance sets
};

// Negation normal form over !, X, F, G, &, |, U, R, W, M (xor, ->, <-> expanded).
ltl::Formula to_nnf(const ltl::Formula& f);
// Atoms of f, sorted by name, duplicate-free.
std::vector<std::string> atoms_of(const ltl::Formula& f);
// f must be in NNF. Throws rtamp::Error beyond kMaxAtoms atoms or 64 keys.
Vwaa build_vwaa(const ltl::Formula& nnf);

}  // namespace rtamp::automata::detail
