// Fuzz target for `plan --change` parsing and checking (world/change.hpp):
// on any input, read as one change per line, parse_changes() against the
// 3-block-tray scene either returns or throws rtamp::Error — never crashes,
// hangs or throws anything else. Oracles on accepted changes: the canonical
// text parses back to the same text, and applying the list to a copy of the
// scenario keeps every name the list mentions where the checks expect it.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/world/change.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_change: %s\n%s\n", what, detail.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtamp;
  static const world::Scenario scene = world::load_scenario("3-block-tray");
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size() && lines.size() < 64) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    lines.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  std::vector<world::Change> changes;
  try {
    changes = world::parse_changes(scene, lines);
  } catch (const Error&) {
    return 0;  // the only acceptable failure
  }
  world::Scenario s = scene;
  world::Placement p = world::initial_placement(s);
  std::string hand;
  for (const world::Change& c : changes) {
    const std::string canonical = c.to_string();
    try {
      if (world::parse_change(canonical).to_string() != canonical) fail("the canonical text reads back differently", canonical);
      world::check_change(c, s);
    } catch (const Error& e) {
      fail("an accepted change is refused when checked again", canonical + "\n" + e.what());
    }
    world::apply_change(c, s, p, hand);
  }
  return 0;
}
