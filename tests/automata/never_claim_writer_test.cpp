// never-claim writer: exact text on a small BA, refusal of TGBAs and of atoms
// that are not Promela identifiers, and (when spin is installed) spin itself
// accepting the claim inside a small Promela model.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "rtamp/automata/never_claim_writer.hpp"
#include "rtamp/util/error.hpp"

using namespace rtamp;
using namespace rtamp::automata;

namespace {

Cube lit(unsigned i, bool positive) {
  Cube c;
  (positive ? c.pos : c.neg) = Letter{1} << i;
  return c;
}

Automaton response() {  // G(p -> F q), initial state 1 to test reordering
  Automaton a;
  a.name = "G(p -> F q) */";
  a.atoms = {"p", "q"};
  a.state_based = true;
  a.add_state(false);
  a.add_state(true);
  a.initial = 1;
  a.add_edge(1, 1, lit(0, false));
  a.add_edge(1, 1, lit(1, true));
  a.add_edge(1, 0, lit(0, true) & lit(1, false));
  a.add_edge(0, 1, lit(1, true));
  a.add_edge(0, 0, lit(1, false));
  a.add_state(false);  // state 2: no edges
  return a;
}

bool have_spin() { return std::system("command -v spin >/dev/null 2>&1") == 0; }

}  // namespace

TEST(NeverClaimWriter, ExactText) {
  EXPECT_EQ(to_never_claim(response()),
            "never { /* G(p -> F q) * / */\n"
            "accept_init:\n"
            "\tif\n"
            "\t:: ((!p) || (q)) -> goto accept_init\n"
            "\t:: (p && !q) -> goto T0_S0\n"
            "\tfi;\n"
            "T0_S0:\n"
            "\tif\n"
            "\t:: (q) -> goto accept_init\n"
            "\t:: (!q) -> goto T0_S0\n"
            "\tfi;\n"
            "T0_S2:\n"
            "\tfalse;\n"
            "}\n");
}

TEST(NeverClaimWriter, RefusesTgbaAndNonIdentifierAtoms) {
  Automaton t = response();
  t.state_based = false;
  EXPECT_THROW(to_never_claim(t), Error);
  Automaton q = response();
  q.atoms[0] = "o1 in r2";
  try {
    to_never_claim(q);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'o1 in r2' is not a Promela identifier"), std::string::npos);
  }
  q.atoms[0] = "true";
  EXPECT_THROW(to_never_claim(q), Error);
}

TEST(NeverClaimWriter, SpinParsesTheClaim) {
  if (!have_spin()) GTEST_SKIP() << "spin is not installed";
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rtamp_never_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream pml(dir / "m.pml");
    pml << "bool p, q;\nactive proctype env() {\n  do\n  :: p = !p\n  :: q = !q\n  od\n}\n" << to_never_claim(response());
  }
  // spin -a generates the verifier (pan.c) only if the model parses.
  const std::string cmd = "cd '" + dir.string() + "' && spin -a m.pml >out.txt 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream out(dir / "out.txt");
  const std::string log((std::istreambuf_iterator<char>(out)), std::istreambuf_iterator<char>());
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(fs::exists(dir / "pan.c")) << log;
  fs::remove_all(dir);
}
