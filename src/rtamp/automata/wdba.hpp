// Minimal weak deterministic Büchi automaton (WDBA) of a Büchi automaton
// (Dax, Eisinger & Klaedtke, "Mechanizing the powerset construction for
// restricted classes of ω-automata", ATVA'07; docs/translation.md, "WDBA").
//
// minimize_wdba(a): subset construction of `a` over the letters of the atoms
// its guards use; an SCC of the subset automaton is accepting iff `a` accepts
// one lasso u·v^ω whose run stays in that SCC (a cycle v through one of its
// states); states of accepting SCCs are accepting, a state on no cycle takes
// the status its successors share (else either status, the one that merges
// more); then Moore's partition
// refinement minimises the result as a DFA (states with equal finite-word
// residuals have equal Büchi languages, since the runs meet accepting states
// at the same positions). The result is state-based, deterministic and
// complete (the empty subset, if reached, is a rejecting sink).
// Its language equals L(a) when L(a) is an obligation language; otherwise it
// may differ, so callers must check (translate.cpp does, with the products
// of product.hpp). Returns nullopt past the budget: more than `max_states`
// subsets, more than 2^12 letters, more than 2^22 successor-table words, or
// more than 2^22 (subset, letter) cells.
#pragma once

#include <cstddef>
#include <optional>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

std::optional<Automaton> minimize_wdba(const Automaton& a, std::size_t max_states);

}  // namespace rtamp::automata
