// Where accepting cycles lie in a Büchi automaton — state-based, or
// generalized with any number of sets on edges — over the edges whose guards
// are not false (the product search asks once per automaton,
// plan/product_graph.hpp). A cycle is accepting when the union of its edges'
// Automaton::cycle_marks is cycle_marks_all() (state-based: it passes an
// accepting state; one set: it takes an accepting edge):
//  - states_on_accepting_cycles: q lies on such a cycle, i.e. the edges
//    inside q's strongly connected component carry every set between them
//    (a cycle through the component can take each of them): only there can a
//    lasso's cycle pass, since its automaton projection is such a cycle;
//  - useful_states: q reaches (by zero or more edges) a state on an
//    accepting cycle; only these enter the product. Every state on an
//    accepting cycle is useful.
#pragma once

#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

std::vector<bool> useful_states(const Automaton& ba);
std::vector<bool> states_on_accepting_cycles(const Automaton& ba);

}  // namespace rtamp::automata
