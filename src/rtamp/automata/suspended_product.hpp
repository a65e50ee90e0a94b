// The product of an automaton with the automaton of a suspendable formula
// (Spot's product_susp; docs/translation.md, "Splitting").
//
// A formula s is suspendable when u·w ⊨ s iff w ⊨ s for every finite u
// (syntactically: both eventual and universal, e.g. G F a, F G a). So the
// automaton of s may start late: suspended_product(a, s) runs s only while a
// is in an accepting SCC, starting s's initial state on every entry into one
// from outside, and runs a alone elsewhere. L(result) = L(a) ∩ L(s), with
// fewer states than product(a, s) where a has transient or rejecting parts.
// Marks as in product.hpp: a's sets first, then s's. Same atoms required.
#pragma once

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

Automaton suspended_product(const Automaton& a, const Automaton& s);

}  // namespace rtamp::automata
