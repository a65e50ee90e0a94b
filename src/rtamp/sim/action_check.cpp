#include "rtamp/sim/action_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::sim {

namespace {

// Byte offset (in the action's own text) of word `k`.
std::size_t word_offset(const std::string& text, std::size_t k) {
  std::size_t i = 0, n = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size()) break;
    if (n++ == k) return i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  }
  return text.size();
}

std::string shown(std::string_view w) {
  if (w.size() <= 64) return world::quoted(w);
  return world::quoted(std::string(w.substr(0, 64)) + "...");
}

}  // namespace

void check_actions(const std::vector<SimAction>& actions, const world::Scenario& scenario, std::string_view text,
                   bool with_script) {
  check_actions(actions, world::Vocabulary(scenario, with_script), text);
}

void check_actions(const std::vector<SimAction>& actions, const world::Vocabulary& v, std::string_view text,
                   const std::string& source) {
  for (const SimAction& a : actions) {
    auto fail = [&](std::size_t k, const std::string& what) {
      const std::size_t at = static_cast<std::size_t>(std::max(a.column, 1) - 1) + word_offset(a.text, k);
      throw Error(what, SourceLocation{source, 1, static_cast<int>(at) + 1}, caret_at(text, at));
    };
    auto thing = [&](const std::string& n, std::size_t k) {
      if (v.is_thing(n)) return;
      if (v.is_region(n)) fail(k, shown(n) + " is a region; only objects and containers are picked up");
      fail(k, "unknown object or container " + shown(n) + world::suggestion(n, v.things()));
    };
    auto location = [&](const std::string& n, std::size_t k) {
      if (v.is_location(n)) return;
      if (v.is_object(n)) fail(k, shown(n) + " is an object, not a location");
      fail(k, "unknown location " + shown(n) + world::suggestion(n, v.locations()));
    };
    switch (a.kind) {
      case SimAction::Kind::Move:
        thing(a.thing, 1);
        location(a.location, 2);
        if (a.thing == a.location) fail(2, shown(a.thing) + " cannot be placed in itself");
        if (v.is_container(a.thing) && !v.is_region(a.location))
          fail(2, "container " + shown(a.thing) + " can only be placed in a region, not in container " +
                      shown(a.location) + " (containers do not nest)");
        break;
      case SimAction::Kind::Pick:
        thing(a.thing, 1);
        break;
      case SimAction::Kind::Place:
        location(a.location, 1);
        break;
      case SimAction::Kind::Wait:  // parse_actions' rule, for lists built in code
        if (!std::isfinite(a.seconds) || a.seconds < 0 || a.seconds > 3600)
          fail(1, "'" + format_number(a.seconds) + "' is not a duration in seconds (0 to 3600)");
        break;
    }
  }
}

}  // namespace rtamp::sim
