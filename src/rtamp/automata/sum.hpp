// The sum (union) of two Büchi automata over the same atoms:
// L(sum(a, b)) = L(a) ∪ L(b) (the disjunction of a split formula,
// split.hpp; the conjunction is product.hpp's product).
//
// The result is transition-based generalized with k = max(ka, kb) sets (ka: a's
// sets, 1 for a state-based automaton): an automaton with fewer sets gives the
// missing ones to every edge carrying its last set (every edge if it has none),
// which keeps its accepting runs. A fresh initial state copies the out-edges
// of both initial states; the two automata follow, disjoint.
#pragma once

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

Automaton sum(const Automaton& a, const Automaton& b);

}  // namespace rtamp::automata
