// Fuzz target for `sim --do` parsing and checking (sim/session.hpp
// parse_actions, sim/action_check.hpp): on any input, parsing the action list
// and checking its names against the 3-block-tray scene either succeeds or
// throws rtamp::Error located in the list ("--do", line 1, a column inside
// it) — never crashes, hangs or throws anything else. Nothing is simulated.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "rtamp/sim/action_check.hpp"
#include "rtamp/sim/session.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtamp;
  static const world::Scenario scene = world::load_scenario("3-block-tray");
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const std::vector<sim::SimAction> actions = sim::parse_actions(text);
    sim::check_actions(actions, scene, text, true);
    for (const sim::SimAction& a : actions)
      if (a.column < 1 || static_cast<std::size_t>(a.column) > text.size()) std::abort();
  } catch (const Error& e) {
    const SourceLocation& w = e.where();
    if (w.file != "--do" || w.line != 1 || w.column < 1 || static_cast<std::size_t>(w.column) > text.size() + 1) {
      std::fprintf(stderr, "fuzz_sim_do: error outside the list: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
