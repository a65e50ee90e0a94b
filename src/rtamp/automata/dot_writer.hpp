// Graphviz DOT output of the automata of paper Definition 2, for people
// (`rtamp ltl2ba --format dot | dot -Tsvg`).
//
// States are circles numbered as in the automaton; accepting states of a
// state-based Büchi automaton are double circles; the initial state has an
// arrow from an invisible point. Edge labels are guards over atom names
// (`a & !b`, `true`; several cubes to one destination joined with ` | `), and
// for transition-based automata the acceptance marks follow in braces
// (`a & !b {0,1}`). The automaton's name is the graph's title. Every string is
// escaped for DOT, so atoms such as "o1 in r2" are safe.
#pragma once

#include <iosfwd>
#include <string>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

void write_dot(std::ostream& out, const Automaton& a);
std::string to_dot(const Automaton& a);

// A guard cube over atom names: "a & !b", "true".
std::string cube_to_string(const Cube& c, const std::vector<std::string>& atoms);

}  // namespace rtamp::automata
