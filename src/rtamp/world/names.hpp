// The name rules of a scenario and the vocabulary it defines — the one set of
// checks behind every input that names things: the scenario file
// (validate.hpp), the atoms of the LTL task (task/validate.hpp), `plan
// --change` (world/change.hpp), `sim --do` (sim/action_check.hpp) and the
// Python module. Every check throws rtamp::Error at the offending word, with a
// did-you-mean (suggest.hpp) where one fits, so that all entry points refuse
// the same inputs with the same words.
//
// Rules: a name (region, container, object, class) is an identifier
// [A-Za-z_][A-Za-z0-9_]* of at most 64 characters that is not a keyword of the
// proposition grammar (in all any count true false) and not a word the worlds
// use for a place ("none": outside every location, "hand": held, "home": the
// arm's rest); a class is
// a name other than "object" (which means "every object that is not a
// container" in expressions); a proposition name is an identifier starting
// with a lower-case letter or '_', other than true/false.
//
// Vocabulary: every name a scenario defines, by role — the regions, the
// containers and objects present at the start or added by an operator action
// of its script, their classes, its propositions. Invariant: each list is
// in the order of definition (the start, then the script) without duplicates.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

inline constexpr std::size_t kMaxNameLength = 64;

bool is_reserved_name(std::string_view name);           // none hand home, and the grammar's keywords
bool is_valid_name(std::string_view name);              // regions, containers, objects, classes
bool is_valid_proposition_name(std::string_view name);  // atoms of the LTL task

// Throws unless `name` may name a new region, container or object; `kind` is
// "region", "container", "object" (the message starts with it). `detail` is
// passed on (e.g. a caret line).
void check_new_name(std::string_view name, std::string_view kind, const SourceLocation& where,
                    const std::string& detail = {});
// Throws unless `cls` may be the class of an object or container; `owner`
// starts the message (e.g. "container 't2'").
void check_class_name(std::string_view cls, std::string_view owner, const SourceLocation& where,
                      const std::string& detail = {});

struct Vocabulary {
  std::vector<std::string> regions, containers, objects;  // at the start, or added by the script
  std::vector<std::string> object_classes, container_classes;
  std::vector<std::string> propositions;

  Vocabulary() = default;
  // `with_script`: count the names the scenario's operator actions add.
  explicit Vocabulary(const Scenario& s, bool with_script = true);

  std::vector<std::string> things() const;     // containers and objects
  std::vector<std::string> locations() const;  // regions and containers
  std::vector<std::string> classes() const;    // every class, and "object"
  bool is_region(std::string_view n) const;
  bool is_container(std::string_view n) const;
  bool is_object(std::string_view n) const;
  bool is_thing(std::string_view n) const { return is_container(n) || is_object(n); }
  bool is_location(std::string_view n) const { return is_region(n) || is_container(n); }
  bool is_class(std::string_view n) const;
  bool is_proposition(std::string_view n) const;
};

// The location of byte `offset` of `text`, which starts at `start` (a
// location with line and column, or empty: then the result is empty too).
// With a `layout` (the text is a YAML block scalar: util/text_layout.hpp),
// the layout's file line and column.
SourceLocation location_in(std::string_view text, const SourceLocation& start, std::size_t offset,
                           const TextLayout& layout = {});

// Checks that every name expression `e` (parsed from `text`, which starts at
// `start`) uses exists in `v`: things for `X in L`, locations for every L,
// classes for all/any/count. Errors are "<owner>unknown class 'blocks' (did
// you mean 'block'?)" and the like, located at the name's word in `text`, with
// `text` and a caret under it as detail when `text` is one line.
void check_expression_names(const PropExpr& e, std::string_view text, const SourceLocation& start,
                            const Vocabulary& v, const std::string& owner, const TextLayout& layout = {});

}  // namespace rtamp::world
