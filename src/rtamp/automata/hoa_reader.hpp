// HOA v1 input (Hanoi Omega-Automata format) into the automata of paper
// Definition 2, so that automata from Spot (`ltl2tgba`, `ltl2tgba -B`,
// `autfilt`) or Owl can be planned with, compared or tested against.
//
// Supported: one or more automata in a stream (each `HOA: v1 ... --END--`,
// `--ABORT--` discards the one being read); `States:` (optional), several
// `Start:` lines (a fresh initial state is added when there are several; none
// means the empty language); `AP:`; `Alias: @name expr`; `name:`; every
// lower-case header item is ignored; comments `/* */` (nested); quoted
// strings with escapes; labels as arbitrary Boolean formulas over AP indices,
// aliases, `t` and `f` (converted to DNF cubes, one edge per cube); state
// labels; explicit edge labels; implicit labels (2^|AP| unlabelled edges per
// state in ltl2dstar order, for at most 16 APs); state-based and
// transition-based acceptance marks, also mixed.
// Acceptance: `t` (read as a state-based Büchi automaton whose states all
// accept), `f` (no state accepts), and conjunctions of `Inf(i)` — Büchi and
// generalized Büchi. Unused sets are dropped and the others renumbered.
// Not supported (an rtamp::Error names the token): `Fin`, `Inf(!i)`,
// disjunctive acceptance (Rabin, Streett, parity, ...), universal branching
// (`Start: 0&1`, `[0] 1&2`), unknown upper-case header items, more than 64 APs.
// Result: state-based (state_based == true, num_sets == 1) when every mark (of
// a set the acceptance condition uses) is
// on `State:` lines and one set remains, unless `properties:` says trans-acc
// (a one-set automaton written transition-based, even one without marks,
// stays so); otherwise transition-based with each state's marks moved onto
// its outgoing edges.
// Errors: rtamp::Error with file:line:column of the offending token.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata {

// Every automaton of the stream, in order. `file` is used in error locations.
std::vector<Automaton> read_hoa(std::string_view text, const std::string& file = {});

// Exactly one automaton (an error if the stream holds none or several).
Automaton read_hoa_one(std::string_view text, const std::string& file = {});

// Reads a file ("-" is standard input) and parses it with read_hoa.
std::vector<Automaton> read_hoa_file(const std::string& path);

}  // namespace rtamp::automata
