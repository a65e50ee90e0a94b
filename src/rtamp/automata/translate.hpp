// LTL -> Büchi automaton translation (paper Section II: the automaton A_φ the
// planner searches in product with the task abstraction).
//
// Pipeline (docs/translation.md): negation normal form -> very weak
// alternating automaton (Gastin–Oddoux, CAV'01) -> transition-based generalized
// Büchi automaton built on the fly with transition subsumption (states =
// conjunctions of VWAA states, or disjunctions of those merged per letter and
// promise set as in Couvreur's construction; the smaller result wins) -> reductions
// (useless states, SCC-based acceptance canonicalisation, direct-simulation
// quotient with little-brother pruning, cosimulation, parallel-edge merging)
// -> optionally SCC-aware degeneralisation to a state-based Büchi automaton,
// reduced again -> checked merges (checked_merge.hpp: a state merged into one
// simulating it when the result × A_!f is empty; on the TGBA, degeneralised
// again, and on the BA) -> the minimal weak deterministic automaton (wdba.hpp) instead
// when it is no larger and its language is checked equal (products with the
// complement of the WDBA and with the automaton of !f are empty).
// Shortcuts build common shapes (Boolean, G p, F p, G F p, F G p) directly.
// Splitting (split.hpp): the parts of a top-level & or | are also translated
// separately and combined (product, suspended product, sum), the result kept
// when smaller.
//
// Invariants of the result: language = models of f; atoms are the atoms of f
// sorted by name; name = the formula text; no unreachable states; every state
// can reach an accepting cycle unless the language is empty (then the result
// is a single state without edges); state_based == opt.state_based; when
// state_based, num_sets == 1; otherwise num_sets = number of acceptance sets
// in use (0 means every infinite run accepts), or exactly 1 with one_set.
#pragma once

#include "rtamp/automata/automaton.hpp"
#include "rtamp/ltl/formula.hpp"

namespace rtamp::automata {

// Which TGBA construction feeds the reductions (docs/translation.md).
enum class Construction {
  Smallest,            // both below (merged only up to 8 atoms), keep the smaller result
  GastinOddoux,        // conjunctions of VWAA states (gba.hpp build_tgba)
  MergedDestinations,  // disjunctions of them per letter and promise set (build_tgba_merged)
};

// Whether the parts of a top-level & or | are translated separately and
// combined (split.hpp; docs/translation.md, "Splitting").
enum class Splitting {
  Smallest,  // both ways, keep the split result only when smaller
  Never,
  Always,    // the split result whenever the formula splits (for tests)
};

struct TranslateOptions {
  bool state_based = true;  // true: state-based Büchi (BA, 1 acceptance set); false: TGBA
  // With state_based == false: one acceptance set on edges (a transition-based
  // Büchi automaton, degeneralize_tba.hpp), the form the planner accepts on.
  bool one_set = false;
  bool simplify = true;     // ltl::simplify before translating
  bool reduce = true;       // post-translation reductions (useless states, simulation, merging)
  bool shortcuts = true;    // direct constructions for Boolean / G p / F p / G F p / F G p
  bool wdba = true;         // minimal WDBA when no larger and checked equivalent
  bool checked_merge = true;  // merge a state into one simulating it when checked against A_!f
  Splitting splitting = Splitting::Smallest;
  Construction construction = Construction::Smallest;
};

// Throws rtamp::Error for formulas with more than kMaxAtoms atoms, more than 32
// distinct eventualities, or whose automaton exceeds the resource bounds of
// gba.hpp / vwaa.hpp ("formula too large to translate").
Automaton translate(const ltl::Formula& f, const TranslateOptions& opt = {});

}  // namespace rtamp::automata
