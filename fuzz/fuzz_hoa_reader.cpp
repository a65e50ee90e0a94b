// libFuzzer target for the automata readers (hoa_reader, never_claim_reader):
// any input must either parse or raise rtamp::Error — no crash, hang, leak or
// other exception. For every automaton that parses, writing it as HOA and
// reading it back must succeed, and a second round trip must give the same
// text (the writer/reader pair is idempotent after one round).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "rtamp/automata/hoa_reader.hpp"
#include "rtamp/automata/hoa_writer.hpp"
#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  using namespace rtamp::automata;
  try {
    for (const Automaton& a : read_hoa(text, "fuzz.hoa")) {
      const std::string t1 = to_hoa(a);
      const std::string t2 = to_hoa(read_hoa_one(t1));
      const std::string t3 = to_hoa(read_hoa_one(t2));
      if (t2 != t3) std::abort();
    }
  } catch (const rtamp::Error&) {
  }
  try {
    const Automaton a = read_never_claim(text, "fuzz.pml");
    (void)read_hoa_one(to_hoa(a));
  } catch (const rtamp::Error&) {
  }
  return 0;
}
