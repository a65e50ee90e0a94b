// spin never-claim output (`rtamp ltl2ba --format never`), the format spin and
// ltl2ba print, for state-based Büchi automata (paper Definition 2).
//
// Layout: the initial state first (`accept_init` / `T0_init`), the others as
// `accept_S<i>` (accepting) or `T0_S<i>`; each state is an `if :: guard ->
// goto L ... fi;` (a state without edges is `false;`); guards are `(1)` or
// `(p && !q)`, several cubes to one destination joined with `||`. The claim is
// spin-compatible: tests read it back with never_claim_reader and, when spin is
// installed, have spin parse it. Requires a state-based automaton whose atoms
// are Promela identifiers; otherwise throws rtamp::Error naming the problem.
#pragma once

#include <iosfwd>
#include <string>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

void write_never_claim(std::ostream& out, const Automaton& a);
std::string to_never_claim(const Automaton& a);

}  // namespace rtamp::automata
