// LTL parser (paper Section II: the task specification φ is given as text).
//
// Accepts Spot's syntax and the spin/ltl2ba syntax, mixed freely:
//   constants   true false 1 0
//   atoms       [a-z_][a-zA-Z0-9_.]*  (not true/false/xor), or "double quoted"
//               with \" and \\ escapes (any text, e.g. "o1 in r2")
//   unary       ! ~  X  F <>  G []
//   binary      &  &&  /\ ,  |  ||  \/ ,  xor ^ ,  ->  => ,  <->  <=> ,
//               U  R V  W  M
// Upper-case letters are never atoms: X F G U R V W M are operators wherever
// they appear at the start of a token ("GFa" is G F a, as in Spot); other
// upper-case letters are an error. Precedence, loosest first, as in Spot's
// grammar: (-> <->, right assoc.) < | < xor < & < (U R W M, right assoc.)
// < unary operators. & | xor are left associative (& and | are n-ary anyway).
//
// Invariants: the parser is iterative (an operator-precedence parser with an
// explicit stack): no input can overflow the C++ stack. Parenthesis nesting,
// pending operators and the depth of the resulting formula are bounded by
// kMaxParseDepth; deeper input gives rtamp::Error "formula too deeply nested".
// Every syntax error is an rtamp::Error whose location holds the 1-based line
// and column and whose detail is the offending line with a caret under it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rtamp/ltl/formula.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::ltl {

inline constexpr int kMaxParseDepth = 1000;

// Parse `text`; throws rtamp::Error on bad input (line 1, column as above).
Formula parse(std::string_view text);

// Same, for text that starts at `origin` inside some file (e.g. a YAML value):
// reported locations are shifted by origin.line/column and carry origin.file.
Formula parse(std::string_view text, const SourceLocation& origin);

// An atomic proposition as written in a formula's text (for checks that point
// at one atom: task/validate.hpp).
struct AtomOccurrence {
  std::string name;        // unescaped, without the quotes
  bool quoted = false;     // written "in double quotes"
  std::size_t offset = 0;  // byte offset of its first character (the opening quote if quoted)
  std::size_t length = 0;  // bytes it takes in the text, quotes included
  SourceLocation where;    // the location of that first character, as parse() reports locations
};

// The atoms of `text` in order of appearance, found by the same lexer as
// parse(). Meant for text that parse() accepts; on text whose lexing fails it
// throws the same rtamp::Error.
std::vector<AtomOccurrence> atom_occurrences(std::string_view text, const SourceLocation& origin = {});

}  // namespace rtamp::ltl
