// Syntactic classes of the temporal hierarchy (Manna & Pnueli; Černá &
// Pelánek, "Relating hierarchy of temporal properties to model checking",
// MFCS'03), on formulas in negation normal form (other operators: false).
//
//  - safety:     literals, constants, & | X, and G R W over safety operands;
//  - guarantee:  literals, constants, & | X, and F U M over guarantee operands;
//  - obligation: safety, guarantee, and & | X over obligation operands.
// Every syntactic obligation formula defines an obligation language, which a
// weak deterministic Büchi automaton recognises (automata/wdba.hpp relies on
// this).
#pragma once

#include "rtamp/ltl/formula.hpp"

namespace rtamp::ltl {

bool is_syntactic_safety(const Formula& f);     // a bad prefix refutes every non-model
bool is_syntactic_guarantee(const Formula& f);  // a good prefix proves every model
bool is_syntactic_obligation(const Formula& f); // & | X of the two above

}  // namespace rtamp::ltl
