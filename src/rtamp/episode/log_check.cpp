#include "rtamp/episode/log_check.hpp"

#include <cmath>

#include "rtamp/util/line_reader.hpp"
#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/scenario_io.hpp"

#include "rtamp/util/error.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::episode {

using nlohmann::json;

namespace {

// The deepest nesting of arrays and objects in `line` (brackets inside strings do not count).
int depth_of(std::string_view line) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : line) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

const json* field(const json& j, const char* name) {
  auto it = j.find(name);
  return it == j.end() ? nullptr : &*it;
}

[[noreturn]] void bad(const std::string& ev, const char* name, const std::string& why) {
  throw Error("`" + ev + "` record: \"" + name + "\" " + why);
}

bool is_finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

// A field that must be there, of a type.
const json& need(const json& j, const std::string& ev, const char* name, bool (json::*is)() const noexcept,
                 const char* type) {
  const json* v = field(j, name);
  if (!v) bad(ev, name, "is missing");
  if (!((*v).*is)()) bad(ev, name, std::string("must be ") + type);
  return *v;
}

// A field that may be absent; if there, of a type.
const json* may(const json& j, const std::string& ev, const char* name, bool (json::*is)() const noexcept,
                const char* type) {
  const json* v = field(j, name);
  if (v && !((*v).*is)()) bad(ev, name, std::string("must be ") + type);
  return v;
}

void numbers(const json& a, const std::string& ev, const char* name, std::size_t n) {
  if (!a.is_array() || a.size() != n) bad(ev, name, "must be " + std::to_string(n) + " numbers");
  for (const json& x : a)
    if (!is_finite_number(x)) bad(ev, name, "must be " + std::to_string(n) + " numbers");
}

// A status string: one of I R S F a node.
void node_statuses(const json& s, const std::string& ev, const char* name) {
  if (s.get<std::string>().find_first_not_of("IRSF") != std::string::npos)
    bad(ev, name, "must be node statuses (one of I, R, S, F a node)");
}

const std::set<std::string> kKinds = {"episode", "run",    "plan",   "tree",  "replan", "things",  "intervention",
                                      "perceived", "handled_by_tree", "action", "cycle", "tick", "frame", "camera", "end",
                                      "task", "redirect", "statuses"};
const std::set<std::string> kBeliefStates = {"visible", "occluded", "held", "out-of-view", "missing"};
const std::set<std::string> kInterventions = {"relocate",         "add", "remove", "add-container",
                                              "remove-container", "take-from-gripper"};
const std::set<std::string> kActionWhat = {"start", "finished", "failed", "halted"};

}  // namespace

json parse_log_line(std::string_view line) {
  if (line.size() > kMaxLineBytes)
    throw Error("a line of " + std::to_string(line.size()) + " bytes (the limit is 8 MiB)");
  if (depth_of(line) > kMaxDepth)
    throw Error("nested deeper than " + std::to_string(kMaxDepth) + " levels (the limit of a record)");
  try {
    return json::parse(line);
  } catch (const json::exception&) {
    throw Error("not a JSON object (is this an episode log?)");
  }
}

LogCheck::LogCheck(const world::Scenario* scenario) {
  if (scenario) use(*scenario);
}

void LogCheck::use(const world::Scenario& scenario) {
  scenario_ = &scenario;
  for (const auto& o : scenario.objects) things_.insert(o.name);
  for (const auto& c : scenario.containers) things_.insert(c.name);
}

void LogCheck::thing(const json& name, const char* what) const {
  if (!name.is_string()) throw Error(std::string(what) + ": a thing's name must be a string");
  const std::string n = name.get<std::string>();
  if (scenario_ && !things_.count(n))
    throw Error(std::string(what) + ": no thing " + world::quoted(n) + " exists here" +
                world::suggestion(n, {things_.begin(), things_.end()}));
}

void LogCheck::location(const json& name, const char* what) const {
  if (!name.is_string()) throw Error(std::string(what) + ": a location must be a string");
  const std::string n = name.get<std::string>();
  if (!scenario_ || n == "hand" || n == "none" || things_.count(n) || scenario_->find_region(n)) return;
  throw Error(std::string(what) + ": no location " + world::quoted(n) + " exists here");
}

// {"thing": "location"}; `introduces`: perception reports what exists (a thing may be new).
void LogCheck::placement(const json& j, const char* what, bool introduces) {
  if (!j.is_object()) throw Error(std::string(what) + " must be an object (thing -> location)");
  if (introduces)
    for (const auto& [name, loc] : j.items()) things_.insert(name);
  for (const auto& [name, loc] : j.items()) {
    thing(json(name), what);
    location(loc, what);
  }
}

void LogCheck::record(const json& j) {
  if (!j.is_object()) throw Error("not an episode log record (a JSON object)");
  const json* evp = field(j, "ev");
  if (!evp || !evp->is_string()) throw Error("not an episode log record (no string \"ev\")");
  const std::string ev = evp->get<std::string>();
  if (!kKinds.count(ev))
    throw Error("unknown record kind " + world::quoted(ev) +
                world::suggestion(ev, {kKinds.begin(), kKinds.end()}));
  const json* t = field(j, "t");
  if (!t || !is_finite_number(*t) || t->get<double>() < 0 || t->get<double>() > kMaxTime)
    bad(ev, "t", "must be a time in world seconds, a number in [0, 1e8]");
  const double time = t->get<double>();
  if (ended_) throw Error("a `" + ev + "` record after the `end` record (the end is the last line)");
  if (records_ > 0 && time < t_ - 1e-9)
    throw Error("records out of time order (t=" + std::to_string(time) + " after t=" + std::to_string(t_) + ")");
  if ((records_ == 0) != (ev == "episode"))
    throw Error(records_ == 0 ? "the first record is `" + ev + "`, not `episode`"
                              : std::string("a second `episode` record (a log holds one episode)"));
  ++records_;
  t_ = time;
  using J = json;
  if (ev == "episode") {
    if (const json* v = field(j, "version")) {
      if (!v->is_number_unsigned() || v->get<std::uint64_t>() < 1) bad(ev, "version", "must be a version (1, 2, ...)");
      if (v->get<std::uint64_t>() > static_cast<std::uint64_t>(kLogVersion))
        throw Error("a log of format version " + std::to_string(v->get<std::uint64_t>()) + "; this rtamp reads version " +
                    std::to_string(kLogVersion) + " (a newer rtamp wrote it)");
    }
    const json* name = may(j, ev, "scenario", &J::is_string, "a string");
    if (!scenario_ && name && world::builtin_scenario_text(name->get<std::string>())) {
      builtin_ = world::load_scenario(name->get<std::string>());
      use(*builtin_);
    }
    may(j, ev, "world", &J::is_string, "a string");
    may(j, ev, "conditions", &J::is_string, "a string");
    may(j, ev, "automaton_states", &J::is_number_unsigned, "a count");
    if (const json* a = may(j, ev, "automaton", &J::is_object, "an object")) {
      need(*a, ev, "states", &J::is_array, "an array");
      need(*a, ev, "edges", &J::is_array, "an array");
    }
  } else if (ev == "run") {
    placement(need(j, ev, "state", &J::is_object, "an object"), "`run` record: \"state\"", false);
    if (const json* a = may(j, ev, "automaton_states", &J::is_array, "an array"))
      for (const json& s : *a)
        if (!s.is_number_unsigned()) bad(ev, "automaton_states", "must be automaton states (numbers >= 0)");
  } else if (ev == "plan") {
    const json& actions = need(j, ev, "actions", &J::is_array, "an array");
    const json& costs = need(j, ev, "costs", &J::is_array, "an array");
    const json& cycle = need(j, ev, "in_cycle", &J::is_array, "an array");
    if (costs.size() != actions.size() || cycle.size() != actions.size())
      bad(ev, "costs", "and \"in_cycle\" must have one entry per action");
    for (const json& a : actions) {
      const std::string s = a.is_string() ? a.get<std::string>() : "";
      const std::size_t comma = s.find(", ");
      if (s.rfind("move(", 0) != 0 || comma == std::string::npos || s.back() != ')')
        bad(ev, "actions", "must be moves \"move(THING, LOCATION)\"");
      thing(json(s.substr(5, comma - 5)), "`plan` record: \"actions\"");
      location(json(s.substr(comma + 2, s.size() - comma - 3)), "`plan` record: \"actions\"");
    }
    for (const json& c : costs)
      if (!is_finite_number(c)) bad(ev, "costs", "must be numbers");
    for (const json& c : cycle)
      if (!c.is_boolean()) bad(ev, "in_cycle", "must be true or false");
    if (const json* s = may(j, ev, "start", &J::is_object, "an object")) placement(*s, "`plan` record: \"start\"", false);
    if (const json* h = may(j, ev, "hand", &J::is_string, "a string"); h && *h != "home")
      location(*h, "`plan` record: \"hand\"");
  } else if (ev == "tree") {
    need(j, ev, "applied", &J::is_boolean, "true or false");
  } else if (ev == "things") {
    for (const char* f : {"added", "removed"})
      if (const json* a = may(j, ev, f, &J::is_array, "an array"))
        for (const json& n : *a) {
          if (!n.is_string()) bad(ev, f, "must be names");
          things_.insert(n.get<std::string>());
        }
  } else if (ev == "intervention") {
    const json& kind = need(j, ev, "kind", &J::is_string, "a string");
    if (!kInterventions.count(kind.get<std::string>())) bad(ev, "kind", "is not a kind of intervention");
    const bool applied = need(j, ev, "applied", &J::is_boolean, "true or false").get<bool>();
    const json* subject = may(j, ev, "subject", &J::is_string, "a string");
    may(j, ev, "location", &J::is_string, "a string");
    may(j, ev, "detail", &J::is_string, "a string");
    may(j, ev, "class", &J::is_string, "a string");
    if (applied && subject && (kind == "add" || kind == "add-container")) things_.insert(subject->get<std::string>());
  } else if (ev == "perceived") {
    placement(need(j, ev, "placement", &J::is_object, "an object"), "`perceived` record: \"placement\"", true);
  } else if (ev == "handled_by_tree") {
    need(j, ev, "by", &J::is_string, "a string");
  } else if (ev == "action") {
    const json& what = need(j, ev, "what", &J::is_string, "a string");
    if (!kActionWhat.count(what.get<std::string>())) bad(ev, "what", "must be start, finished, failed or halted");
    need(j, ev, "action", &J::is_string, "a string");
  } else if (ev == "cycle") {
    need(j, ev, "completed", &J::is_number_unsigned, "a count");
  } else if (ev == "tick") {
    need(j, ev, "status", &J::is_string, "a string");
  } else if (ev == "statuses") {
    node_statuses(need(j, ev, "s", &J::is_string, "a string"), ev, "s");
  } else if (ev == "frame") {
    const json* q = field(j, "q");
    if (q && !q->is_null()) numbers(*q, ev, "q", 6);
    numbers(need(j, ev, "tool", &J::is_array, "an array"), ev, "tool", 3);
    if (const json* h = field(j, "held"); h && !h->is_null()) thing(*h, "`frame` record: \"held\"");
    for (const json& th : need(j, ev, "things", &J::is_array, "an array")) {
      if (!th.is_object()) bad(ev, "things", "must be objects");
      thing(th.contains("name") ? th["name"] : json(), "`frame` record: \"things\"");
      numbers(need(th, ev, "pos", &J::is_array, "an array"), ev, "pos", 3);
      if (const json* quat = field(th, "quat")) numbers(*quat, ev, "quat", 4);
      if (const json* size = field(th, "size")) numbers(*size, ev, "size", 3);
      if (const json* at = field(th, "at")) location(*at, "`frame` record: \"at\"");
    }
  } else if (ev == "camera") {
    // Belief names (a thing first seen is "<class>_seen<n>") need not be the scenario's.
    need(j, ev, "camera", &J::is_string, "a string");
    for (const json& d : need(j, ev, "detections", &J::is_array, "an array")) {
      if (!d.is_object()) bad(ev, "detections", "must be objects");
      need(d, ev, "class", &J::is_string, "a string");
      numbers(need(d, ev, "at", &J::is_array, "an array"), ev, "at", 3);
    }
    for (const json& th : need(j, ev, "things", &J::is_array, "an array")) {
      if (!th.is_object()) bad(ev, "things", "must be objects");
      need(th, ev, "name", &J::is_string, "a string");
      const json& state = need(th, ev, "state", &J::is_string, "a string");
      if (!kBeliefStates.count(state.get<std::string>())) bad(ev, "state", "is not a belief state");
      numbers(need(th, ev, "at", &J::is_array, "an array"), ev, "at", 3);
    }
  } else if (ev == "task") {
    need(j, ev, "task", &J::is_string, "a string");
    need(j, ev, "by", &J::is_string, "a string");
    may(j, ev, "propositions", &J::is_object, "an object");
    if (need(j, ev, "applied", &J::is_boolean, "true or false").get<bool>()) {
      need(j, ev, "automaton_states", &J::is_number_unsigned, "a count");
      const json& a = need(j, ev, "automaton", &J::is_object, "an object");
      need(a, ev, "states", &J::is_array, "an array");
      need(a, ev, "edges", &J::is_array, "an array");
    } else {
      need(j, ev, "refused", &J::is_string, "a string");
    }
  } else if (ev == "redirect") {
    need(j, ev, "action", &J::is_string, "a string");
    need(j, ev, "rule", &J::is_string, "a string");
  } else if (ev == "end") {
    need(j, ev, "success", &J::is_boolean, "true or false");
    placement(need(j, ev, "placement", &J::is_object, "an object"), "`end` record: \"placement\"", false);
    if (const json* s = may(j, ev, "statuses", &J::is_string, "a string")) node_statuses(*s, ev, "statuses");
    ended_ = true;
  }
}

void LogCheck::finish() const {
  if (records_ == 0) throw Error("the log is empty");
  if (!ended_) throw Error("no `end` record (the log of a finished episode ends with one)");
}

void read_episode_log(const std::string& path, const world::Scenario* scenario,
                      const std::function<void(const json& record, const std::string& text, int line)>& each) {
  LineReader in(path, "the episode log", kMaxLineBytes);
  LogCheck check(scenario);
  std::string line;
  while (in.next(line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    json j;
    try {
      j = parse_log_line(line);
      check.record(j);
    } catch (const Error& e) {
      throw Error(e.message(), SourceLocation{path, in.line_number(), 0});
    }
    if (each) each(j, line, in.line_number());
  }
  try {
    check.finish();
  } catch (const Error& e) {
    throw Error(e.message(), SourceLocation{path});
  }
}

}  // namespace rtamp::episode
