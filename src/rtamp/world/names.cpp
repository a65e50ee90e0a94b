#include "rtamp/world/names.hpp"

#include <algorithm>
#include <cctype>

#include "rtamp/world/geometry.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::world {

namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool is_identifier(std::string_view s) {
  if (s.empty() || s.size() > kMaxNameLength || !ident_start(s[0])) return false;
  return std::all_of(s.begin(), s.end(), ident_char);
}

// A name as shown in a message: quoted, cut after 64 bytes.
std::string shown(std::string_view name) {
  if (name.size() <= kMaxNameLength) return quoted(name);
  return quoted(std::string(name.substr(0, kMaxNameLength)) + "...") + " (" + std::to_string(name.size()) + " bytes)";
}

void add_unique(std::vector<std::string>& v, const std::string& n) {
  if (std::find(v.begin(), v.end(), n) == v.end()) v.push_back(n);
}

bool contains(const std::vector<std::string>& v, std::string_view n) {
  return std::find(v.begin(), v.end(), n) != v.end();
}

// The identifiers of an expression's text with their byte offsets.
struct Word {
  std::size_t offset;
  std::string_view text;
};
std::vector<Word> words_of(std::string_view text) {
  std::vector<Word> out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (ident_start(text[i]) || std::isdigit(static_cast<unsigned char>(text[i]))) {
      std::size_t j = i;
      while (j < text.size() && ident_char(text[j])) ++j;
      if (ident_start(text[i])) out.push_back({i, text.substr(i, j - i)});
      i = j;
    } else {
      ++i;
    }
  }
  return out;
}

enum class Role { Thing, Location, Class };

// Offset of `name` in its role in `text` (the first such word; else the first
// word `name`; else 0).
std::size_t offset_of(std::string_view text, std::string_view name, Role role) {
  const std::vector<Word> w = words_of(text);
  std::size_t any = std::string_view::npos;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w[i].text != name) continue;
    if (any == std::string_view::npos) any = w[i].offset;
    const std::string_view prev = i > 0 ? w[i - 1].text : std::string_view{};
    const std::string_view next = i + 1 < w.size() ? w[i + 1].text : std::string_view{};
    const bool cls = prev == "all" || prev == "any" || prev == "count";
    const Role r = cls ? Role::Class : prev == "in" ? Role::Location : next == "in" ? Role::Thing : Role::Location;
    if (r == role) return w[i].offset;
  }
  return any == std::string_view::npos ? 0 : any;
}

}  // namespace

bool is_reserved_name(std::string_view name) {
  return name == kNoLocation || name == "hand" || name == "home" || is_prop_keyword(name);
}

bool is_valid_name(std::string_view name) { return is_identifier(name) && !is_reserved_name(name); }

bool is_valid_proposition_name(std::string_view name) {
  if (!is_identifier(name) || name == "true" || name == "false") return false;
  return std::islower(static_cast<unsigned char>(name[0])) || name[0] == '_';
}

void check_new_name(std::string_view name, std::string_view kind, const SourceLocation& where,
                    const std::string& detail) {
  const std::string k(kind);
  if (name.empty()) throw Error(k + " has no name", where, detail);
  if (is_valid_name(name)) return;
  if (is_reserved_name(name))
    throw Error(k + " name " + shown(name) + " is a reserved word", where, detail);
  throw Error(k + " name " + shown(name) +
                  " is not an identifier (letters, digits and '_', not starting with a digit, at most 64 characters)",
              where, detail);
}

void check_class_name(std::string_view cls, std::string_view owner, const SourceLocation& where,
                      const std::string& detail) {
  const std::string o(owner);
  if (cls == "object")
    throw Error(o + ": class 'object' is reserved (in propositions it means every object that is not a container)",
                where, detail);
  if (cls.empty()) throw Error(o + ": the class is empty", where, detail);
  if (is_valid_name(cls)) return;
  if (is_reserved_name(cls))
    throw Error(o + ": class " + shown(cls) + " is a reserved word", where, detail);
  throw Error(o + ": class " + shown(cls) + " is not an identifier (letters, digits and '_', at most 64 characters)",
              where, detail);
}

Vocabulary::Vocabulary(const Scenario& s, bool with_script) {
  for (const Region& r : s.regions) add_unique(regions, r.name);
  for (const Container& c : s.containers) {
    add_unique(containers, c.name);
    add_unique(container_classes, c.cls);
  }
  for (const Object& o : s.objects) {
    add_unique(objects, o.name);
    add_unique(object_classes, o.cls);
  }
  if (with_script)
    for (const Intervention& iv : s.interventions) {
      if (iv.kind == Intervention::Kind::Add) {
        add_unique(objects, iv.subject);
        add_unique(object_classes, iv.cls);
      } else if (iv.kind == Intervention::Kind::AddContainer) {
        add_unique(containers, iv.subject);
        add_unique(container_classes, iv.cls);
      }
    }
  for (const Proposition& p : s.propositions) add_unique(propositions, p.name);
}

std::vector<std::string> Vocabulary::things() const {
  std::vector<std::string> out = containers;
  out.insert(out.end(), objects.begin(), objects.end());
  return out;
}

std::vector<std::string> Vocabulary::locations() const {
  std::vector<std::string> out = regions;
  out.insert(out.end(), containers.begin(), containers.end());
  return out;
}

std::vector<std::string> Vocabulary::classes() const {
  std::vector<std::string> out = object_classes;
  for (const std::string& c : container_classes) add_unique(out, c);
  add_unique(out, "object");
  return out;
}

bool Vocabulary::is_region(std::string_view n) const { return contains(regions, n); }
bool Vocabulary::is_container(std::string_view n) const { return contains(containers, n); }
bool Vocabulary::is_object(std::string_view n) const { return contains(objects, n); }
bool Vocabulary::is_class(std::string_view n) const {
  return n == "object" || contains(object_classes, n) || contains(container_classes, n);
}
bool Vocabulary::is_proposition(std::string_view n) const { return contains(propositions, n); }

SourceLocation location_in(std::string_view text, const SourceLocation& start, std::size_t offset,
                           const TextLayout& layout) {
  SourceLocation loc = start;
  if (loc.line <= 0 || loc.column <= 0) return loc;
  offset = std::min(offset, text.size());
  if (auto at = layout.locate(start.file, offset)) return *at;
  const std::size_t nl = text.substr(0, offset).rfind('\n');
  if (nl == std::string_view::npos) {
    loc.column += static_cast<int>(offset);
  } else {
    loc.line += static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
    loc.column = static_cast<int>(offset - nl);
  }
  return loc;
}

void check_expression_names(const PropExpr& e, std::string_view text, const SourceLocation& start,
                            const Vocabulary& v, const std::string& owner, const TextLayout& layout) {
  PropNames names;
  collect_names(e, names);
  auto fail = [&](std::string_view name, Role role, const std::string& what) {
    const std::size_t off = offset_of(text, name, role);
    const std::string detail =
        text.find('\n') == std::string_view::npos ? caret_line(std::string(text), static_cast<int>(off) + 1) : "";
    throw Error(owner + what, location_in(text, start, off, layout), detail);
  };
  // In the order of the text, so that the first wrong word is reported.
  for (const Word& w : words_of(text)) {
    const std::string n(w.text);
    if (names.things.count(n) && !v.is_thing(n)) {
      if (v.is_location(n)) fail(n, Role::Thing, shown(n) + " is a region; 'X in L' needs an object or container X");
      fail(n, Role::Thing, "unknown object " + shown(n) + suggestion(n, v.things()));
    }
    if (names.locations.count(n) && !v.is_location(n)) {
      if (v.is_thing(n)) fail(n, Role::Location, shown(n) + " is an object, not a location");
      fail(n, Role::Location, "unknown location " + shown(n) + suggestion(n, v.locations()));
    }
    if (names.classes.count(n) && !v.is_class(n))
      fail(n, Role::Class, "unknown class " + shown(n) + suggestion(n, v.classes()));
  }
}

}  // namespace rtamp::world
