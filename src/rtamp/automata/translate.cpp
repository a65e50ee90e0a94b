#include "rtamp/automata/translate.hpp"

#include <exception>
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
#include "rtamp/automata/split.hpp"
#include "rtamp/automata/sum.hpp"
#include "rtamp/automata/suspended_product.hpp"
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
      neg.splitting = Splitting::Never;
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

// The automaton of `nnf` (the NNF of the simplified `input`) in one piece:
// shortcut or VWAA -> TGBA constructions, the pipeline, checked merges, WDBA.
Automaton translate_whole(const Formula& nnf, const std::vector<std::string>& atoms, const TranslateOptions& opt,
                          Negation& negation) {
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
  return a;
}

// The automaton of a split formula (split.hpp): each part translated alone
// (TGBA) and combined, reduced after each step: & is the product of the
// other parts, then the suspended product with the product of the
// suspendable ones; | is the sum of all. Then the pipeline and the checked
// merges as for a whole formula (not the WDBA: translate_whole tries the one
// of the same language). Nothing when a product would need more than 32
// acceptance sets.
std::optional<Automaton> translate_split(const detail::Split& split, const std::vector<std::string>& atoms,
                                         const TranslateOptions& opt, Negation& negation) {
  const bool conjunction = split.op == Op::And;
  // Combines the automata of `parts` into `acc` by `step`.
  auto combine = [&](std::optional<Automaton>& acc, const std::vector<Formula>& parts, auto step) {
    for (const Formula& part : parts) {
      TranslateOptions o = opt;
      o.state_based = false;
      o.one_set = false;
      if (part.is(split.op)) o.splitting = Splitting::Never;  // a group of operands would split the same way again
      Automaton x = translate(part, o);
      remap_atoms(x, atoms);
      if (!acc) {
        acc = std::move(x);
        continue;
      }
      if (conjunction && acc->num_sets + x.num_sets > 32) return false;
      acc = step(*acc, x);
      if (opt.reduce) reduce_all(*acc, false);
    }
    return true;
  };
  std::optional<Automaton> acc, susp;
  if (conjunction) {
    if (!combine(acc, split.parts, product) || !combine(susp, split.suspendable, product)) return std::nullopt;
    if (acc && susp) {
      if (acc->num_sets + susp->num_sets > 32) return std::nullopt;
      acc = suspended_product(*acc, *susp);
    } else if (!acc) {
      acc = std::move(susp);
    }
  } else {
    std::vector<Formula> all = split.parts;
    all.insert(all.end(), split.suspendable.begin(), split.suspendable.end());
    combine(acc, all, sum);
  }
  Automaton reduced_tgba;
  Automaton a = pipeline(std::move(*acc), opt, &reduced_tgba);
  if (opt.reduce && opt.checked_merge) merge_checked_states(a, std::move(reduced_tgba), opt, negation);
  if (a.state_based) a.num_sets = 1;
  return a;
}

// TGBA -> one set on edges, when asked for.
void to_one_set(Automaton& a, const TranslateOptions& opt) {
  if (opt.state_based || !opt.one_set) return;
  a = degeneralize_tba(a);
  if (opt.reduce) {
    reduce_all(a, false);
    a = degeneralize_tba(a);  // the reductions may leave no set (every cycle accepting)
  }
}

// Fewer states, then deterministic rather than not, then fewer edges.
bool smaller(const Automaton& a, const Automaton& b) {
  if (a.num_states() != b.num_states()) return a.num_states() < b.num_states();
  const bool da = is_deterministic(a), db = is_deterministic(b);
  if (da != db) return da;
  return a.num_edges() < b.num_edges();
}

}  // namespace

Automaton translate(const ltl::Formula& input, const TranslateOptions& opt) {
  const Formula f = opt.simplify ? ltl::simplify(input) : input;
  const Formula nnf = detail::to_nnf(f);
  // Atoms: every atom of the input formula, sorted (some may have been
  // simplified away; they stay so that letters mean the same to every caller).
  const std::vector<std::string> atoms = detail::atoms_of(input);
  Negation negation(input, opt);
  const std::optional<detail::Split> split =
      opt.splitting != Splitting::Never ? detail::split_formula(nnf) : std::nullopt;
  // Each way that was tried and stayed within the resource bounds.
  std::optional<Automaton> whole, parts;
  std::exception_ptr failed;
  auto attempt = [&](std::optional<Automaton>& out, auto build) {
    try {
      out = build();
      if (out) to_one_set(*out, opt);
    } catch (const Error&) {
      if (!failed) failed = std::current_exception();
    }
  };
  if (split) attempt(parts, [&] { return translate_split(*split, atoms, opt, negation); });
  if (!split || opt.splitting == Splitting::Smallest || !parts)
    attempt(whole, [&] { return std::optional<Automaton>(translate_whole(nnf, atoms, opt, negation)); });
  // Smallest: the split result only when smaller than the whole formula's.
  if (parts && (!whole || opt.splitting == Splitting::Always || smaller(*parts, *whole))) whole = std::move(parts);
  if (!whole) std::rethrow_exception(failed);
  Automaton& a = *whole;
  a.name = ltl::to_string(input);
  return std::move(a);
}

}  // namespace rtamp::automata
