// LTL printers: Spot syntax (the canonical text form of a Formula everywhere
// in rtamp: CLI output, logs, HOA "name:" headers) and spin/ltl2ba syntax (for
// running spin as an external cross-check of the translator).
//
// Invariants:
//  - parse(to_string(f)) == f for every formula (hash-consed identity), since
//    the printer follows the parser's precedence table and prints And/Or
//    operands in the node's own (id) order. Parentheses are minimal with respect
//    to that table. Constants print as 1 and 0, as Spot does; atoms that are not
//    [a-z_][a-zA-Z0-9_.]* (or that are true/false/xor) print double-quoted with
//    \" and \\ escapes. (The empty atom name prints as "" which the parser
//    rejects: it cannot come from parsed text.)
//  - to_spin_string is fully parenthesised, uses [] <> U V X ! && || -> <->,
//    true/false, and expands the operators spin lacks: a W b = b V (a || b),
//    a M b = b U (a && b), a xor b = !(a <-> b). X prints as X (ltl2ba reads
//    it; Debian's spin 6.5 is built without NXT and rejects it).
#pragma once

#include <map>
#include <string>

#include "rtamp/ltl/formula.hpp"

namespace rtamp::ltl {

std::string to_string(const Formula& f);

// True if `name` can be printed without quotes in Spot syntax.
bool is_plain_atom_name(const std::string& name);

// Spin/ltl2ba text. Spin atoms must be [a-z][a-zA-Z0-9_]* and not a spin
// keyword (true false and the like). An atom that is not: if `renamed` is null,
// throws rtamp::Error("atomic proposition '<name>' is not a valid spin
// identifier"); otherwise it is printed as a fresh name p_<k> (not clashing
// with any atom of f) and (*renamed)[fresh] = original is recorded.
// The W/M expansions duplicate an operand, so nested W/M can blow up: text
// beyond 4 MiB throws rtamp::Error("formula too large for spin syntax ...").
std::string to_spin_string(const Formula& f, std::map<std::string, std::string>* renamed = nullptr);

// True if `name` is usable as-is in spin syntax.
bool is_spin_atom_name(const std::string& name);

}  // namespace rtamp::ltl
