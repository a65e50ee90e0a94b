// Fuzz target for the scenario loader (world/scenario_io.hpp): on any input,
// parse_scenario() either returns a valid scenario or throws rtamp::Error —
// never crashes, hangs or throws anything else. Oracles on accepted inputs:
// the YAML round trip parse(to_yaml(s)) is equivalent to s, validate() passes,
// and the geometry and proposition evaluator run on the initial state. The
// input is also tried as a proposition expression (parse/print round trip).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "rtamp/util/error.hpp"
#include "rtamp/world/compare.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_scenario_yaml: %s\n%s\n", what, detail.c_str());
  std::abort();
}

void check_expression(std::string_view text) {
  using namespace rtamp::world;
  PropExpr e;
  try {
    e = parse_prop_expr(text);
  } catch (const rtamp::Error&) {
    return;
  }
  const std::string printed = to_string(e);
  try {
    if (!(parse_prop_expr(printed) == e)) fail("expression round trip changed the expression", printed);
  } catch (const rtamp::Error& err) {
    fail("printed expression does not parse", printed + "\n" + err.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtamp::world;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (size <= 4096) check_expression(text);

  Scenario s;
  try {
    s = parse_scenario(text, "fuzz.yaml");
  } catch (const rtamp::Error&) {
    return 0;  // the only acceptable failure
  }
  try {
    validate(s);
  } catch (const rtamp::Error& e) {
    fail("parse_scenario accepted a scenario that validate() rejects", e.what());
  }
  const std::string yaml = to_yaml(s);
  Scenario back;
  try {
    back = parse_scenario(yaml, "round-trip.yaml");
  } catch (const rtamp::Error& e) {
    fail("to_yaml output does not parse", yaml + "\n" + e.what());
  }
  if (const std::string diff = first_difference(s, back); !diff.empty()) fail("round trip changed the scenario", diff);
  const Placement p = initial_placement(s);
  for (const Proposition& prop : s.propositions) (void)evaluate(prop.expr, p);
  return 0;
}
