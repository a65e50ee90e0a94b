#include "rtamp/automata/translate.hpp"

#include <optional>
#include <string>
#include <vector>

#include "rtamp/automata/checked_merge.hpp"
#include "rtamp/automata/degeneralize.hpp"
#include "rtamp/automata/degeneralize_tba.hpp"
#include "rtamp/automata/emptiness.hpp"
#include "rtamp/automata/gba.hpp"
#include "rtamp/automata/product.hpp"
#include "rtamp/automata/reduce.hpp"
#include "rtamp/automata/shortcuts.hpp"
#include "rtamp/automata/simulation_reduction.hpp"
#include "rtamp/automata/vwaa.hpp"
#include "rtamp/automata/wdba.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/simplify.hpp"
#include "rtamp/ltl/syntactic_class.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::automata {

namespace {

using ltl::Formula;
using ltl::Op;

void reduce_all(Automaton& a, bool saturate) {
  remove_useless(a);
  canonicalize_acceptance(a, saturate);
  merge_parallel_edges(a);
  for (int round = 0; round < 4; ++round) {
    bool changed = reduce_direct_simulation(a);
    canonicalize_acceptance(a, saturate);
    changed |= reduce_cosimulation(a);
    if (!changed) break;
    canonicalize_acceptance(a, saturate);
    merge_parallel_edges(a);
  }
}

// The automaton of !input (a TGBA over the atoms of input), built on first
// use; nullptr when !input is past the resource bounds.
class Negation {
 public:
  Negation(const Formula& input, const TranslateOptions& opt) : input_(input), opt_(opt) {}
  const Automaton* get() {
    if (!tried_) {
      tried_ = true;
      TranslateOptions neg = opt_;
      neg.wdba = false;
      neg.checked_merge = false;
      neg.state_based = false;
      neg.construction = Construction::GastinOddoux;
      try {
        automaton_ = translate(Formula::Not(input_), neg);
      } catch (const Error&) {
      }
    }
    return automaton_ ? &*automaton_ : nullptr;
  }

 private:
  Formula input_;
  TranslateOptions opt_;
  bool tried_ = false;
  std::optional<Automaton> automaton_;
};

// Checked merges (checked_merge.hpp) then the reductions again if any.
bool merge_and_reduce(Automaton& a, Negation& neg) {
  if (!merge_checked(a, [&neg] { return neg.get(); })) return false;
  reduce_all(a, false);
  return true;
}

// Letters of `a` (over a sorted subset of `atoms`) renumbered over `atoms`.
void remap_atoms(Automaton& a, const std::vector<std::string>& atoms) {
  if (a.atoms == atoms) return;
  std::vector<std::uint32_t> map(a.atoms.size());
  for (std::size_t i = 0, j = 0; i < a.atoms.size(); ++i) {
    while (atoms[j] != a.atoms[i]) ++j;
    map[i] = static_cast<std::uint32_t>(j);
  }
  auto remap = [&](Letter l) {
    Letter r = 0;
    for (std::size_t i = 0; i < map.size(); ++i)
      if ((l >> i) & 1u) r |= Letter{1} << map[i];
    return r;
  };
  for (auto& out : a.edges)
    for (Edge& e : out) e.guard = Cube{remap(e.guard.pos), remap(e.guard.neg)};
  a.atoms = atoms;
}

// TGBA -> final automaton (reductions, degeneralisation) as described in
// docs/translation.md.
// `tgba` receives the reduced TGBA the state-based result was made from.
Automaton pipeline(Automaton a, const TranslateOptions& opt, Automaton* tgba) {
  if (!opt.state_based) {
    if (opt.reduce) {
      // Saturated marks sometimes let simulation merge more, sometimes
      // less (they break the symmetry of G F a & G F b): keep the smaller.
      reduce_all(a, false);
      Automaton sat = a;
      reduce_all(sat, true);
      if (sat.num_states() < a.num_states() ||
          (sat.num_states() == a.num_states() && sat.num_edges() < a.num_edges()))
        a = std::move(sat);
    } else {
      remove_useless(a);
    }
  } else if (!opt.reduce) {
    remove_useless(a);
    canonicalize_acceptance(a);
    a = degeneralize(a);
    remove_useless(a);
  } else {
    // Saturated marks help simulation but put marks on the edges entering a
    // state, which costs accepting copies in degeneralisation: reduce the
    // TGBA without saturation, degeneralise, reduce the BA.
    reduce_all(a, false);
    *tgba = a;
    a = degeneralize(a);
    reduce_all(a, false);
  }
  return a;
}

// Checked merges on the result of the pipeline: on the TGBA (then
// degeneralised again, kept if no larger) and on the result.
void merge_checked_states(Automaton& a, Automaton tgba, const TranslateOptions& opt, Negation& neg) {
  if (opt.state_based && merge_and_reduce(tgba, neg)) {
    Automaton b = degeneralize(tgba);
    reduce_all(b, false);
    if (b.num_states() < a.num_states() ||
        (b.num_states() == a.num_states() && b.num_edges() <= a.num_edges()))
      a = std::move(b);
  }
  merge_and_reduce(a, neg);
}

// Replaces `a` (the automaton of `input`, over its atoms) by its minimal WDBA
// when that is no larger and its language is L(a): L(a) ⊆ L(W) is checked by
// emptiness of a × complement(W); L(W) ⊆ L(input) holds when `obligation`
// (the formula is a syntactic obligation: Dax et al.'s theorem) and is
// checked otherwise by emptiness of W × A_!input.
void try_wdba(Automaton& a, bool obligation, const TranslateOptions& opt, Negation& neg) {
  const std::optional<Automaton> w = minimize_wdba(a, 8 * std::size_t{a.num_states()} + 32);
  if (!w) return;
  Automaton small = *w;
  remove_useless(small);
  // No larger; at equal size it must bring determinism.
  if (small.num_states() > a.num_states() || (small.num_states() == a.num_states() && is_deterministic(a))) return;
  if (!is_empty(product(a, complement_dba(*w)))) return;
  if (!obligation) {
    const Automaton* n = neg.get();
    if (!n || !is_empty(product(small, *n))) return;  // no automaton of !input: keep `a`
  }
  if (!opt.state_based) {
    small.state_based = false;
    canonicalize_acceptance(small);
  }
  a = std::move(small);
}

}  // namespace

Automaton translate(const ltl::Formula& input, const TranslateOptions& opt) {
  const Formula f = opt.simplify ? ltl::simplify(input) : input;
  const Formula nnf = detail::to_nnf(f);
  // Atoms: every atom of the input formula, sorted (some may have been
  // simplified away; they stay so that letters mean the same to every caller).
  const std::vector<std::string> atoms = detail::atoms_of(input);
  Negation negation(input, opt);
  const bool merge = opt.reduce && opt.checked_merge;
  // One construction's TGBA, over `atoms`, through the pipeline and the checked merges.
  auto finish = [&](Automaton t) {
    remap_atoms(t, atoms);
    Automaton reduced_tgba;
    Automaton r = pipeline(std::move(t), opt, &reduced_tgba);
    if (merge) merge_checked_states(r, std::move(reduced_tgba), opt, negation);
    return r;
  };
  Automaton a;
  bool done = false;
  if (opt.shortcuts) done = detail::try_shortcut(nnf, opt.state_based, a);
  if (!done) {
    detail::Vwaa v = detail::build_vwaa(nnf);
    using C = Construction;
    if (opt.construction == C::MergedDestinations) {
      a = finish(*detail::build_tgba_merged(v));
    } else {
      Automaton go = detail::build_tgba(v);
      const std::size_t go_states = go.num_states();
      a = finish(std::move(go));
      if (opt.construction == C::Smallest && v.atoms.size() <= detail::kMaxMergedAtoms) {
        // The merged-destination construction is smaller on some formulas
        // (F r -> (!p U r): 3 states instead of 4), larger on others: keep
        // the smaller result. It is abandoned when it grows well beyond the
        // Gastin–Oddoux automaton (it is a partial subset construction).
        if (auto merged = detail::build_tgba_merged(v, 2 * go_states + 8)) {
          Automaton m = finish(std::move(*merged));
          if (m.num_states() < a.num_states() ||
              (m.num_states() == a.num_states() && m.num_edges() < a.num_edges()))
            a = std::move(m);
        }
      }
    }
  }
  remap_atoms(a, atoms);
  if (a.state_based) a.num_sets = 1;
  if (opt.wdba && !done) try_wdba(a, ltl::is_syntactic_obligation(nnf), opt, negation);
  if (!opt.state_based && opt.one_set) {
    a = degeneralize_tba(a);
    if (opt.reduce) {
      reduce_all(a, false);
      a = degeneralize_tba(a);  // the reductions may leave no set (every cycle accepting)
    }
  }
  a.name = ltl::to_string(input);
  return a;
}

}  // namespace rtamp::automata
