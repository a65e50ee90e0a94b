// Where accepting cycles lie in a state-based Büchi automaton, over the edges
// whose guards are not false (the product search asks once per automaton,
// plan/product_graph.hpp):
//  - useful_states: from q some accepting state on a cycle (>= 1 edge) is
//    reachable (q itself included); only these enter the product;
//  - states_on_accepting_cycles: q lies on a cycle through an accepting state
//    (q reaches such a state qa and qa reaches q, each by >= 1 edge): only
//    there can a lasso's cycle pass, since its automaton projection is such a
//    cycle. Every such state is useful.
#pragma once

#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

std::vector<bool> useful_states(const Automaton& ba);
std::vector<bool> states_on_accepting_cycles(const Automaton& ba);

}  // namespace rtamp::automata
