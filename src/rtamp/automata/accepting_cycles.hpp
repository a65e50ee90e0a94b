// Where accepting cycles lie in a Büchi automaton, state-based or with one set
// on edges, over the edges whose guards are not false (the product search asks
// once per automaton, plan/product_graph.hpp). A cycle is accepting when it
// takes an accepting edge (Automaton::accepting_edge: for a state-based
// automaton an edge entering an accepting state, so this is "through an
// accepting state"):
//  - useful_states: from q an accepting edge u -> v on a cycle is reachable
//    (q == u included); only these enter the product;
//  - states_on_accepting_cycles: q lies on a cycle that takes an accepting
//    edge u -> v (q reaches u and v reaches q, either possibly by no edge):
//    only there can a lasso's cycle pass, since its automaton projection is
//    such a cycle. Every such state is useful.
#pragma once

#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

std::vector<bool> useful_states(const Automaton& ba);
std::vector<bool> states_on_accepting_cycles(const Automaton& ba);

}  // namespace rtamp::automata
