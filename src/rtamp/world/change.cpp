#include "rtamp/world/change.hpp"

#include "rtamp/world/space_rules.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "rtamp/world/geometry.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/space_rules.hpp"
#include "rtamp/world/suggest.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::world {

namespace {

using world::quoted;

struct Word {
  std::string_view text;
  std::size_t offset;
};

std::vector<Word> split(std::string_view text) {
  std::vector<Word> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    std::size_t j = i;
    while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
    if (j > i) out.push_back({text.substr(i, j - i), i});
    i = j;
  }
  return out;
}

// A word as shown in a message: quoted, cut after 64 bytes.
std::string shown(std::string_view w) {
  if (w.size() <= 64) return quoted(w);
  return quoted(std::string(w.substr(0, 64)) + "...");
}

// Where errors about one change go: at a word of its text when the change has
// a location, else into the message ("bad change 'TEXT': ...").
class Reporter {
 public:
  Reporter(std::string_view text, const SourceLocation& where) : text_(text), where_(where), words_(split(text)) {}

  [[noreturn]] void fail_at(std::size_t offset, const std::string& what) const {
    if (where_.line > 0) throw Error(what, world::location_in(text_, where_, offset), caret_at(text_, offset));
    std::string t(text_.size() > 80 ? std::string(text_.substr(0, 80)) + "..." : std::string(text_));
    for (char& c : t)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    throw Error("bad change " + quoted(t) + ": " + what, where_);
  }
  // At word `k` (0 = the kind); past the end when there is no such word.
  [[noreturn]] void fail(std::size_t k, const std::string& what) const {
    fail_at(k < words_.size() ? words_[k].offset : text_.size(), what);
  }
  SourceLocation at(std::size_t k) const {
    if (where_.line <= 0) return where_;
    return world::location_in(text_, where_, k < words_.size() ? words_[k].offset : text_.size());
  }
  const std::vector<Word>& words() const { return words_; }

 private:
  std::string_view text_;
  SourceLocation where_;
  std::vector<Word> words_;
};

struct Kind {
  const char* word;
  std::size_t args_min, args_max;
  const char* counts;  // the argument counts it takes, in words
  const char* usage;
};
const Kind kKinds[] = {
    {"move", 2, 2, "2", "move OBJ LOC"},
    {"add", 3, 3, "3", "add OBJ CLASS LOC"},
    {"remove", 1, 1, "1", "remove OBJ"},
    {"add-container", 3, 4, "3 or 4", "add-container NAME CLASS REGION [CAPACITY]"},
    {"remove-container", 1, 1, "1", "remove-container NAME"},
    {"add-region", 3, 6, "3, 4 or 6", "add-region NAME X Y [CAPACITY [SX SY]]"},
};

// The shortest text that reads back as the same double.
std::string number(double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, ptr) : "nan";
}

// A whole word read as a double (a leading '+' allowed); "inf" and "nan" read
// as numbers, out of range.
enum class Read { Ok, NotANumber, OutOfRange };
Read read_number(std::string_view w, double& v) {
  const char* first = w.data();
  const char* last = w.data() + w.size();
  if (first != last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && ptr == last && !std::isfinite(v)))
    return Read::OutOfRange;
  return ec != std::errc() || ptr != last || first == last ? Read::NotANumber : Read::Ok;
}

double coordinate(const Reporter& r, std::size_t k, const char* axis) {
  const std::string_view w = r.words()[k].text;
  double v = 0;
  const Read read = read_number(w, v);
  if (read == Read::OutOfRange)
    r.fail(k, std::string(axis) + " " + shown(w) + " is out of range (coordinates are finite, within ±1000 m)");
  if (read == Read::NotANumber) r.fail(k, std::string(axis) + " must be a number (metres), found " + shown(w));
  if (std::abs(v) > world::kMaxCoordinate)
    r.fail(k, std::string(axis) + " " + shown(w) + " is out of range (coordinates are within ±1000 m)");
  return v;
}

// A region's side: a positive number of metres, at most world::kMaxSize.
double side(const Reporter& r, std::size_t k, const char* axis) {
  const std::string_view w = r.words()[k].text;
  double v = 0;
  const Read read = read_number(w, v);
  if (read == Read::NotANumber) r.fail(k, std::string(axis) + " must be a number (metres), found " + shown(w));
  if (read == Read::OutOfRange || !(v > 0) || !(v <= world::kMaxSize))
    r.fail(k, std::string(axis) + " " + shown(w) + " is out of range (a region's sides are positive, at most 100 m)");
  return v;
}

int capacity(const Reporter& r, std::size_t k) {
  const std::string_view w = r.words()[k].text;
  const char* first = w.data();
  const char* last = w.data() + w.size();
  if (first != last && *first == '+') ++first;
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec == std::errc() && ptr == last && first != last) {
    if (v < 1) r.fail(k, "capacity must be at least 1 (got " + std::string(w) + ")");
    if (v > std::numeric_limits<int>::max())
      r.fail(k, "capacity " + shown(w) + " is out of range (at most " +
                    std::to_string(std::numeric_limits<int>::max()) + ")");
    return static_cast<int>(v);
  }
  if (ec == std::errc::result_out_of_range)
    r.fail(k, "capacity " + shown(w) + " is out of range (at most " + std::to_string(std::numeric_limits<int>::max()) +
                  ")");
  r.fail(k, "capacity must be an integer, found " + shown(w));
}

std::string a_kind(const world::Vocabulary& v, std::string_view n) {
  if (v.is_region(n)) return "a region";
  if (v.is_container(n)) return "a container";
  if (v.is_object(n)) return "an object";
  return "a proposition";
}

}  // namespace

// ---- Change ----------------------------------------------------------------

Change Change::relocate(std::string thing, std::string location) {
  Change c;
  c.kind = Kind::Relocate;
  c.subject = std::move(thing);
  c.location = std::move(location);
  return c;
}
Change Change::add_object(std::string object, std::string cls, std::string location) {
  Change c;
  c.kind = Kind::Add;
  c.subject = std::move(object);
  c.cls = std::move(cls);
  c.location = std::move(location);
  return c;
}
Change Change::remove_object(std::string object) {
  Change c;
  c.kind = Kind::Remove;
  c.subject = std::move(object);
  return c;
}
Change Change::add_container(std::string container, std::string cls, std::string region, int capacity) {
  Change c;
  c.kind = Kind::AddContainer;
  c.subject = std::move(container);
  c.cls = std::move(cls);
  c.location = std::move(region);
  c.capacity = capacity;
  return c;
}
Change Change::remove_container(std::string container) {
  Change c;
  c.kind = Kind::RemoveContainer;
  c.subject = std::move(container);
  return c;
}
Change Change::add_region(Region region) {
  Change c;
  c.kind = Kind::AddRegion;
  c.subject = region.name;
  c.region = std::move(region);
  return c;
}
Change Change::take_from_gripper(std::string location) {
  Change c;
  c.kind = Kind::TakeFromGripper;
  c.location = std::move(location);
  return c;
}

Change Change::parse(const std::string& text) { return parse_change(text); }

std::string Change::to_string() const {
  switch (kind) {
    case Kind::Relocate: return "move " + subject + " " + location;
    case Kind::Add: return "add " + subject + " " + cls + " " + location;
    case Kind::Remove: return "remove " + subject;
    case Kind::AddContainer:
      return "add-container " + subject + " " + cls + " " + location + " " + std::to_string(capacity);
    case Kind::RemoveContainer: return "remove-container " + subject;
    case Kind::TakeFromGripper: return location.empty() ? "take-from-gripper" : "take-from-gripper " + location;
    case Kind::AddRegion: {
      std::string s = "add-region " + subject + " " + number(region.center[0]) + " " + number(region.center[1]) + " " +
                      std::to_string(region.capacity);
      if (region.size[0] != Region{}.size[0] || region.size[1] != Region{}.size[1])
        s += " " + number(region.size[0]) + " " + number(region.size[1]);
      return s;
    }
  }
  return "?";
}

const char* to_string(Change::Kind k) {
  switch (k) {
    case Change::Kind::Relocate: return "relocate";
    case Change::Kind::Add: return "add";
    case Change::Kind::Remove: return "remove";
    case Change::Kind::AddContainer: return "add-container";
    case Change::Kind::RemoveContainer: return "remove-container";
    case Change::Kind::TakeFromGripper: return "take-from-gripper";
    case Change::Kind::AddRegion: return "add-region";
  }
  return "?";
}

const NameTable<Change::Kind>& intervention_kinds() {
  using K = Change::Kind;
  static const NameTable<K> t = {
      {"relocate", K::Relocate, "move a thing (a container with its contents) to a location or position"},
      {"add", K::Add, "a new object appears"},
      {"remove", K::Remove, "an object disappears"},
      {"add-container", K::AddContainer, "a new container appears in a region"},
      {"remove-container", K::RemoveContainer, "a container disappears; its contents fall where it stood"},
      {"take-from-gripper", K::TakeFromGripper, "take the held thing and put it somewhere, or away"},
  };
  return t;
}

const NameTable<Change::Kind>& random_change_kinds() {
  using K = Change::Kind;
  static const NameTable<K> t = {
      {"relocate", K::Relocate, "a random present object to another location"},
      {"remove", K::Remove, "a random present object disappears"},
      {"add", K::Add, "a new object in a random location"},
  };
  return t;
}

// ---- Text, rules, effect -----------------------------------------------------

Change parse_change(std::string_view text, const SourceLocation& where) {
  const Reporter r(text, where);
  const auto& w = r.words();
  if (w.empty())
    r.fail_at(0, "the change is empty (expected move, add, remove, add-container, remove-container or add-region)");
  const Kind* kind = nullptr;
  std::vector<std::string> names;
  for (const Kind& k : kKinds) {
    names.emplace_back(k.word);
    if (w[0].text == k.word) kind = &k;
  }
  if (!kind) r.fail(0, "unknown change " + shown(w[0].text) + world::suggestion(w[0].text, names));
  const std::size_t args = w.size() - 1;
  const bool odd_region = w[0].text == "add-region" && args == 5;  // a size needs both sides
  if (args < kind->args_min || args > kind->args_max || odd_region) {
    r.fail(args > kind->args_max ? kind->args_max + 1 : w.size(),
           quoted(kind->word) + " takes " + kind->counts + " argument" + (kind->args_max == 1 ? "" : "s") + ": " +
               kind->usage + " (found " + std::to_string(args) + ")");
  }
  auto s = [&](std::size_t k) { return std::string(w[k].text); };
  const std::string_view k = w[0].text;
  if (k == "move") return Change::relocate(s(1), s(2));
  if (k == "add") return Change::add_object(s(1), s(2), s(3));
  if (k == "remove") return Change::remove_object(s(1));
  if (k == "add-container") return Change::add_container(s(1), s(2), s(3), args == 4 ? capacity(r, 4) : 4);
  if (k == "remove-container") return Change::remove_container(s(1));
  world::Region region;
  region.name = s(1);
  region.center = {coordinate(r, 2, "x"), coordinate(r, 3, "y"), 0};
  if (args >= 4) region.capacity = capacity(r, 4);
  if (args == 6) region.size = {side(r, 5, "size x"), side(r, 6, "size y"), 0};
  return Change::add_region(region);
}

void check_change(const Change& c, const world::Scenario& s, const SourceLocation& where, std::string_view text) {
  // Without the text, word positions are those of the canonical text.
  const std::string written = text.empty() ? c.to_string() : std::string(text);
  const Reporter r(written, where);
  const world::Vocabulary v(s, false);

  auto new_name = [&](const std::string& name, const char* kind) {
    if (!world::is_valid_name(name)) {
      try {
        world::check_new_name(name, kind, {});
      } catch (const Error& e) {
        r.fail(1, e.message());
      }
    }
    if (v.is_region(name) || v.is_thing(name) || v.is_proposition(name))
      r.fail(1, "name " + shown(name) + " is already used by " + a_kind(v, name));
  };
  auto class_of = [&](const std::string& cls, const std::string& owner, bool container) {
    if (cls.empty()) return;
    try {
      world::check_class_name(cls, owner, {});
    } catch (const Error& e) {
      r.fail(2, e.message());
    }
    const auto& other = container ? v.object_classes : v.container_classes;
    if (std::find(other.begin(), other.end(), cls) != other.end())
      r.fail(2, owner + ": class " + shown(cls) + " is the class of " + (container ? "objects" : "containers") +
                    " (a class names either objects or containers)");
  };
  auto location = [&](const std::string& loc, std::size_t k) {
    if (v.is_location(loc)) return;
    if (v.is_object(loc)) r.fail(k, shown(loc) + " is an object, not a location");
    r.fail(k, "unknown location " + shown(loc) + world::suggestion(loc, v.locations()));
  };

  switch (c.kind) {
    case Change::Kind::Relocate:
      if (!v.is_thing(c.subject)) {
        if (v.is_region(c.subject)) r.fail(1, shown(c.subject) + " is a region; only objects and containers move");
        r.fail(1, "unknown object or container " + shown(c.subject) + world::suggestion(c.subject, v.things()));
      }
      location(c.location, 2);
      if (c.subject == c.location) r.fail(2, shown(c.subject) + " cannot be placed in itself");
      if (v.is_container(c.subject) && !v.is_region(c.location))
        r.fail(2, "container " + shown(c.subject) + " can only be placed in a region, not in container " +
                      shown(c.location) + " (containers do not nest)");
      return;
    case Change::Kind::Add:
      new_name(c.subject, "object");
      class_of(c.cls, "object " + shown(c.subject), false);
      location(c.location, 3);
      return;
    case Change::Kind::Remove:
      if (!v.is_object(c.subject)) {
        if (v.is_container(c.subject)) r.fail(1, shown(c.subject) + " is a container: use remove-container");
        r.fail(1, "unknown object " + shown(c.subject) + world::suggestion(c.subject, v.objects));
      }
      return;
    case Change::Kind::AddContainer:
      new_name(c.subject, "container");
      class_of(c.cls, "container " + shown(c.subject), true);
      if (!v.is_region(c.location)) {
        if (v.is_container(c.location))
          r.fail(3, shown(c.location) + " is a container; a container stands in a region (containers do not nest)");
        r.fail(3, "unknown region " + shown(c.location) + " (containers stand in regions)" +
                      world::suggestion(c.location, v.regions));
      }
      if (c.capacity < 1) r.fail(4, "capacity must be at least 1 (got " + std::to_string(c.capacity) + ")");
      return;
    case Change::Kind::RemoveContainer:
      if (!v.is_container(c.subject)) {
        if (v.is_object(c.subject)) r.fail(1, shown(c.subject) + " is an object: use remove");
        r.fail(1, "unknown container " + shown(c.subject) + world::suggestion(c.subject, v.containers));
      }
      return;
    case Change::Kind::TakeFromGripper:
      r.fail(0, "take-from-gripper is a change of a running robot (the planner's state holds nothing in the gripper)");
    case Change::Kind::AddRegion: {
      const world::Region& g = c.region;
      if (g.name != c.subject) r.fail(1, "the region's name " + shown(g.name) + " is not the change's " + shown(c.subject));
      new_name(g.name, "region");
      for (int i = 0; i < 2; ++i)
        if (!std::isfinite(g.center[i]) || std::abs(g.center[i]) > world::kMaxCoordinate)
          r.fail(2 + i, "the centre is out of range (coordinates are finite, within ±1000 m)");
      for (int i = 0; i < 2; ++i)
        if (!(g.size[i] > 0) || !(g.size[i] <= world::kMaxSize))
          r.fail(r.words().size() > static_cast<std::size_t>(5 + i) ? static_cast<std::size_t>(5 + i) : 1,
                 "region " + shown(g.name) + ": its size must be positive (and at most 100 m) in x and y");
      if (g.capacity < 1) r.fail(4, "capacity must be at least 1 (got " + std::to_string(g.capacity) + ")");
      for (const world::Region& other : s.regions)
        if (world::footprint(g).overlaps(world::footprint(other)))
          r.fail(2, "region " + shown(g.name) + " overlaps region " + shown(other.name) + " (regions must be disjoint)");
      return;
    }
  }
}

void check_change_room(const Change& c, const world::Scenario& s, const world::Placement& p,
                       const SourceLocation& where, std::string_view text) {
  const std::string written = text.empty() ? c.to_string() : std::string(text);
  const Reporter r(written, where);
  // Puts `thing` (of `body`) into `loc`, the location named by word k; world `s`, `q`.
  auto put = [&](const std::string& thing, const world::Body& body, const std::string& loc, std::size_t k,
                 const world::Scenario& in, const world::Placement& q) {
    const std::string why = world::refusal(thing, body, loc, world::location_now(in, q, loc, thing), {});
    if (!why.empty()) r.fail(k, "cannot put " + shown(thing) + " in " + shown(loc) + ": " + why);
  };
  switch (c.kind) {
    case Change::Kind::Relocate:
      put(c.subject, world::body_of(s, c.subject), c.location, 2, s, p);
      return;
    case Change::Kind::Add:
      put(c.subject, world::new_body(s, c.cls.empty() ? "block" : c.cls, false), c.location, 3, s, p);
      return;
    case Change::Kind::AddContainer:
      put(c.subject, world::new_body(s, c.cls.empty() ? "tray" : c.cls, true), c.location, 3, s, p);
      return;
    case Change::Kind::RemoveContainer: {
      // Its contents fall into the region it stood in, one by one.
      const std::string* region = p.location_of(c.subject);
      if (!region) return;
      world::Scenario after = s;
      world::Placement q = p;
      std::string hand;
      apply_change(Change::remove_container(c.subject), after, q, hand);
      for (auto& [name, t] : q.things)
        if (t.location == *region && p.things.at(name).location == c.subject) t.location = "";
      for (const auto& [name, t] : p.things) {
        if (t.location != c.subject) continue;
        put(name, world::body_of(after, name), *region, 1, after, q);
        q.things[name].location = *region;
      }
      return;
    }
    case Change::Kind::Remove:
    case Change::Kind::AddRegion:
    case Change::Kind::TakeFromGripper:
      return;
  }
}

void apply_change(const Change& c, world::Scenario& s, world::Placement& p, std::string& hand) {
  auto point_of = [&](const std::string& loc) -> world::Vec3 {
    if (const auto* r = s.find_region(loc)) return r->center;
    if (const auto* k = s.find_container(loc)) {
      const std::string* reg = p.location_of(k->name);
      if (reg)
        if (const auto* r = s.find_region(*reg)) return r->center;
      return k->position;
    }
    return {0, 0, 0};
  };
  auto erase_named = [](auto& v, const std::string& name) {
    v.erase(std::remove_if(v.begin(), v.end(), [&](const auto& x) { return x.name == name; }), v.end());
  };
  switch (c.kind) {
    case Change::Kind::Relocate:
      p.things[c.subject].location = c.location;
      return;
    case Change::Kind::Add: {
      world::Object o;
      o.name = c.subject;
      o.cls = c.cls.empty() ? "block" : c.cls;
      o.size = world::new_body(s, o.cls, false).size;  // as the symbolic world adds one
      o.position = point_of(c.location);
      s.objects.push_back(o);
      p.set(o.name, c.location, o.cls, false);
      return;
    }
    case Change::Kind::Remove:
      erase_named(s.objects, c.subject);
      p.things.erase(c.subject);
      return;
    case Change::Kind::AddContainer: {
      world::Container k;
      k.name = c.subject;
      k.cls = c.cls.empty() ? "tray" : c.cls;
      k.size = world::new_body(s, k.cls, true).size;
      if (const auto* r = s.find_region(c.location)) k.position = r->center;
      k.capacity = c.capacity;
      s.containers.push_back(k);
      p.set(k.name, c.location, k.cls, true);
      return;
    }
    case Change::Kind::RemoveContainer: {
      const std::string region = p.things[c.subject].location;
      for (auto& [name, thing] : p.things)
        if (thing.location == c.subject) thing.location = region;  // contents fall where it stood
      if (hand == c.subject) hand = region;
      erase_named(s.containers, c.subject);
      p.things.erase(c.subject);
      return;
    }
    case Change::Kind::AddRegion:
      s.regions.push_back(c.region);
      return;
    case Change::Kind::TakeFromGripper:
      return;  // refused by check_change
  }
}

std::vector<Change> parse_changes(const world::Scenario& scenario, const std::vector<std::string>& texts,
                                  const std::string& option) {
  world::Scenario s = scenario;
  world::Placement p = world::initial_placement(s);
  std::string hand;
  std::vector<Change> out;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const SourceLocation where{option + " #" + std::to_string(i + 1), 1, 1};
    Change c = parse_change(texts[i], where);
    check_change(c, s, where, texts[i]);
    check_change_room(c, s, p, where, texts[i]);
    apply_change(c, s, p, hand);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace rtamp::world
