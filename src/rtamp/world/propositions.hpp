// Proposition expressions over the world: parser, printer and the reference
// evaluator (docs/design.md "Propositions are defined over the world"; the atomic
// propositions Π and labelling L(s) of the paper's Section II).
//
// Grammar (documented with PropExpr in scenario.hpp; `&&`, `||` are accepted
// as aliases of `&`, `|`):
//   expr   := term ('|' term)*          term := factor ('&' factor)*
//   factor := '!' factor | '(' expr ')' | atom
//   atom   := NAME 'in' LOC | 'all' CLASS 'in' LOC | 'any' CLASS 'in' LOC
//           | 'count' CLASS 'in' LOC CMP INT | 'true' | 'false'
// NAME, CLASS, LOC are identifiers [A-Za-z_][A-Za-z0-9_]*; the words in, all,
// any, count, true, false cannot be names.
//
// Semantics (evaluate): `x in L` holds when thing x is *directly* in L (a
// block on a tray that stands in r2 is in the tray, not in r2 — the paper's
// state o_i r_3). `all C in L` is true when there is no thing of class C.
// Class "object" matches every thing that is not a container.
//
// Invariants of a parsed PropExpr: And/Or have >= 2 children and no child of
// the same kind (they are flattened); Not has exactly one child; Count has
// 0 <= count <= 1000000. parse_prop_expr(to_string(e)) is structurally equal
// to e for every parsed e.
#pragma once

#include <set>
#include <string>
#include <string_view>

#include "rtamp/util/error.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

// Parses `text`. `where` is the location of the text's first character (may be
// empty); errors are rtamp::Error at where.line, where.column + offset, with the
// text and a caret under the offending column as detail.
// `layout`: where the text's bytes lie in its file when it is a YAML block scalar.
PropExpr parse_prop_expr(std::string_view text, const SourceLocation& where = {}, const TextLayout& layout = {});

// Canonical text with the fewest parentheses, e.g. "all block in r2 & !(o1 in r3 | false)".
std::string to_string(const PropExpr& e);
const char* to_string(PropExpr::Cmp cmp);

// The reference evaluator: direct semantics over a Placement (see above).
bool evaluate(const PropExpr& e, const Placement& placement);

// Every name an expression mentions, by role (for validation and for the task
// layer's dependency tracking).
struct PropNames {
  std::set<std::string> things;     // subjects of `x in L`
  std::set<std::string> classes;    // classes of all/any/count
  std::set<std::string> locations;  // every L
};
void collect_names(const PropExpr& e, PropNames& out);

// True if `word` is reserved by the expression grammar (in, all, any, count, true, false).
bool is_prop_keyword(std::string_view word);

}  // namespace rtamp::world
