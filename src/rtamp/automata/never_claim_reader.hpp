// spin never claims (what `spin -f` and ltl2ba print) read into a state-based
// Büchi automaton (paper Definition 2), so that spin can serve as an
// independent oracle for our translator (tests/automata/spin_oracle_test.cpp)
// and never claims from other tools can be planned with.
//
// Accepted subset of Promela:
//   never { /* comment */
//   label: [label: ...] statement [;]
//   ...
//   }
// where a statement is
//   if :: option ... fi      do :: option ... od      skip      false      (0)
// and an option is
//   guard -> goto label      guard  (no goto: `do` loops, `if` falls through
//                                    to the next statement)
//   atomic { guard -> assert(!(guard)) }   (spin's "the claim is matched"
//                                           idiom: reading `guard` accepts
//                                           every continuation)
// Guards: `1`/`true`, `0`/`false`, identifiers (atoms), `!`, `&&`, `||`,
// parentheses. A state is accepting iff one of its labels starts with
// "accept". The first statement's state is initial. Reaching the end of the
// claim (after `skip` or a fall-through) accepts every continuation, as in
// spin; `accept_all: skip` thus becomes an accepting state with a true
// self-loop. Errors: rtamp::Error with line and column.
#pragma once

#include <string>
#include <string_view>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

Automaton read_never_claim(std::string_view text, const std::string& file = {});

}  // namespace rtamp::automata
