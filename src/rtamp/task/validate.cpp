#include "rtamp/task/validate.hpp"

#include <algorithm>

#include "rtamp/ltl/parser.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/suggest.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::task {

namespace {

// Byte offset in the task text of character `k` of a quoted atom's (unescaped) name.
std::size_t raw_offset(std::string_view text, const ltl::AtomOccurrence& a, std::size_t k) {
  std::size_t r = a.offset + 1;
  for (std::size_t i = 0; i < k && r < a.offset + a.length; ++i) r += text[r] == '\\' ? 2 : 1;
  return r;
}

std::string shown_atom(const std::string& name) {
  std::string s = name.size() > 60 ? name.substr(0, 60) + "..." : name;
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return "\"" + s + "\"";
}

class TaskChecker {
 public:
  explicit TaskChecker(const world::Scenario& s)
      : s_(s), origin_(s.task_where.line > 0 ? s.task_where : SourceLocation{"<task>", 1, 1}), v_(s) {}

  void run() const {
    // Syntax errors, located: the parser's line and column in the text, then
    // where that byte lies in the file (a block scalar's indentation counts).
    try {
      (void)ltl::parse(s_.task, SourceLocation{});
    } catch (const Error& err) {
      fail(offset_of(err.where()), err.message());
    }
    for (const ltl::AtomOccurrence& a : ltl::atom_occurrences(s_.task, origin_)) check(a);
  }

 private:
  [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
    throw Error(what, world::location_in(s_.task, origin_, offset, s_.task_layout), caret_at(s_.task, offset));
  }

  // The byte of the task at a 1-based line and column of its text.
  std::size_t offset_of(const SourceLocation& at) const {
    std::size_t start = 0;
    for (int l = 1; l < at.line; ++l) {
      const std::size_t nl = s_.task.find('\n', start);
      if (nl == std::string::npos) break;
      start = nl + 1;
    }
    return std::min(s_.task.size(), start + static_cast<std::size_t>(std::max(at.column, 1) - 1));
  }

  void check(const ltl::AtomOccurrence& a) const {
    if (v_.is_proposition(a.name)) return;
    if (!a.quoted) {
      std::string hint;
      if (v_.is_thing(a.name) || v_.is_location(a.name))
        hint = " (" + world::quoted(a.name) + " is " +
               (v_.is_region(a.name) ? "a region" : v_.is_object(a.name) ? "an object" : "a container") +
               "; to say where things are, write an expression in double quotes, e.g. \"o1 in r2\")";
      else if (v_.propositions.empty())
        hint = " (the scenario defines none; write an expression in double quotes, e.g. \"o1 in r2\")";
      else
        hint = world::suggestion(a.name, v_.propositions);
      fail(a.offset, "the task uses " + world::quoted(a.name) + ", which is not a proposition of the scenario" + hint);
    }
    const std::string owner = "task atom " + shown_atom(a.name) + ": ";
    world::PropExpr e;
    try {
      e = world::parse_prop_expr(a.name, SourceLocation{"", 1, 1});
    } catch (const Error& err) {
      std::string what = err.message();
      const std::string prefix = "in proposition expression: ";
      if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
      fail(raw_offset(s_.task, a, static_cast<std::size_t>(std::max(err.where().column, 1) - 1)), owner + what);
    }
    try {
      world::check_expression_names(e, a.name, SourceLocation{"", 1, 1}, v_, owner);
    } catch (const Error& err) {
      fail(raw_offset(s_.task, a, static_cast<std::size_t>(std::max(err.where().column, 1) - 1)), err.message());
    }
  }

  const world::Scenario& s_;
  SourceLocation origin_;
  world::Vocabulary v_;
};

}  // namespace

void validate_task(const world::Scenario& s) { TaskChecker(s).run(); }

void validate(const world::Scenario& s) {
  world::validate(s);
  validate_task(s);
}

}  // namespace rtamp::task
