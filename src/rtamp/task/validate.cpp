#include "rtamp/task/validate.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "rtamp/ltl/parser.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
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

void validate_task(const world::Scenario& s) {
  TaskChecker(s).run();
  if (!s.task_changes.empty()) validate_task_changes(s, s.task_changes);
}

world::Scenario with_task(const world::Scenario& s, const world::TaskChange& c) {
  const std::string owner = "new task at t = " + format_number(c.time) + " s";
  auto located = [&](const Error& e) {
    std::string what = e.message();
    return Error(what.rfind(owner, 0) == 0 ? what : owner + ": " + what, e.where(), e.detail());
  };
  if (!std::isfinite(c.time) || c.time < 0)
    throw Error("new task at t = " + format_number(c.time) + ": the time must be a finite number of seconds >= 0",
                c.where);
  world::Scenario next = s;
  next.task = c.task;
  next.task_where = c.task_where;
  next.task_layout = c.task_layout;
  next.task_changes.clear();
  // Only what the change brings is checked (the scenario was checked before it).
  const world::Vocabulary known(s);
  std::set<std::string> seen;
  for (const world::Proposition& p : c.propositions) {
    if (!world::is_valid_proposition_name(p.name))
      throw Error(owner + ": proposition name " + world::quoted(p.name) +
                      " is not a valid atom (lower-case letter or '_' first, then letters, digits, '_'; not true/false)",
                  p.where);
    if (!seen.insert(p.name).second) throw Error(owner + ": duplicate proposition " + world::quoted(p.name), p.where);
    if (known.is_thing(p.name) || known.is_region(p.name))
      throw Error(owner + ": proposition " + world::quoted(p.name) + " has the name of a thing or region", p.where);
    if (const world::Proposition* old = s.find_proposition(p.name)) {
      if (old->expr == p.expr) continue;
      throw Error(owner + ": proposition " + world::quoted(p.name) + " is already defined as \"" + old->text +
                      "\" (a new task may add propositions, not change them; give this one another name)",
                  p.where);
    }
    try {
      world::check_expression_names(p.expr, p.text, p.where, known,
                                    "proposition " + world::quoted(p.name) + ": ", p.layout);
    } catch (const Error& e) {
      throw located(e);
    }
    next.propositions.push_back(p);
  }
  if (std::all_of(c.task.begin(), c.task.end(), [](char ch) { return std::isspace(static_cast<unsigned char>(ch)); }))
    throw Error(owner + ": the task is empty (write an LTL formula over the propositions, e.g. \"F G all_in_r2\")",
                c.task_where.line > 0 ? c.task_where : c.where);
  try {
    TaskChecker(next).run();
  } catch (const Error& e) {
    throw located(e);
  }
  return next;
}

void validate_task_changes(const world::Scenario& s, const std::vector<world::TaskChange>& changes) {
  world::Scenario at = s;
  for (const world::TaskChange& c : changes) at = with_task(at, c);
}

void validate(const world::Scenario& s) {
  world::validate(s);
  validate_task(s);
}

}  // namespace rtamp::task
