// libFuzzer target for the LTL parser: any input either parses or throws
// rtamp::Error (never crashes, hangs or overflows the stack); a parsed formula
// prints to text that parses back to the identical formula; simplify, nnf and
// the spin printer (with renaming) never crash, and simplify agrees with the
// formula on a fixed lasso word.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>

#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/nnf.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/simplify.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtamp::ltl;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Formula f;
  try {
    f = parse(text);
  } catch (const rtamp::Error&) {
    return 0;
  }
  const std::string printed = to_string(f);
  Formula g;
  try {
    g = parse(printed);
  } catch (const rtamp::Error&) {
    std::abort();  // the printer produced text the parser rejects
  }
  if (g != f) std::abort();  // round trip must give the identical node
  if (f.size() > 4000) return 0;  // DAG-expanding passes on huge inputs are slow, not wrong
  const Formula s = simplify(f);
  if (!is_nnf(s) || !is_nnf(nnf(f))) std::abort();
  std::map<std::string, std::string> renamed;
  try {
    (void)to_spin_string(f, &renamed);
  } catch (const rtamp::Error&) {
    // only "formula too large for spin syntax" is possible with renaming on
  }
  LassoWord w;
  w.prefix = {{"a"}, {}};
  w.cycle = {{"a", "b"}, {"c"}, {}};
  if (holds(f, w) != holds(s, w)) std::abort();
  return 0;
}
