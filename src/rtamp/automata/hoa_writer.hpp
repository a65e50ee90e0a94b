// HOA v1 output (the Hanoi Omega-Automata format that Spot's autfilt and Owl
// read) for the automata of paper Definition 2.
//
// A state-based Büchi automaton is written with `acc-name: Buchi`,
// `Acceptance: 1 Inf(0)` and `properties: state-acc`, accepting states
// carrying `{0}` on their `State:` line. A transition-based automaton is
// written with `generalized-Buchi n` (`Buchi` for n = 1, `all`/`t` for n = 0)
// and marks on edges. Labels are explicit, over AP indices (`[0&!1]`), and
// edges of one state with the same destination and marks are merged into one
// disjunctive label. Invariant: read_hoa(to_hoa(a)) has a's language, atoms,
// states and acceptance kind (tests/automata/hoa_roundtrip_test.cpp).
#pragma once

#include <iosfwd>
#include <string>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

void write_hoa(std::ostream& out, const Automaton& a);
std::string to_hoa(const Automaton& a);

// A C-like double-quoted string with `"` and `\` escaped (HOA's STRING token).
std::string hoa_quote(const std::string& s);

// A cube over AP indices in HOA label syntax: `0&!1`, `t` for the true cube.
std::string hoa_cube(const Cube& c);

}  // namespace rtamp::automata
