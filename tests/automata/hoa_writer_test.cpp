// HOA writer: exact output on small hand-built automata (state-based Büchi,
// transition-based generalized Büchi, acceptance t), quoting, edge merging.
#include <gtest/gtest.h>

#include "rtamp/automata/hoa_writer.hpp"

using namespace rtamp::automata;

namespace {

Cube lit(unsigned i, bool positive) {
  Cube c;
  (positive ? c.pos : c.neg) = Letter{1} << i;
  return c;
}

}  // namespace

TEST(HoaWriter, StateBasedBuchi) {
  // G F a as a 2-state BA.
  Automaton a;
  a.name = "G F a";
  a.atoms = {"a"};
  a.state_based = true;
  a.num_sets = 1;
  a.add_state(false);
  a.add_state(true);
  a.add_edge(0, 0, lit(0, false));
  a.add_edge(0, 1, lit(0, true));
  a.add_edge(1, 0, lit(0, false));
  a.add_edge(1, 1, lit(0, true));
  EXPECT_EQ(to_hoa(a),
            "HOA: v1\n"
            "name: \"G F a\"\n"
            "States: 2\n"
            "Start: 0\n"
            "AP: 1 \"a\"\n"
            "acc-name: Buchi\n"
            "Acceptance: 1 Inf(0)\n"
            "properties: trans-labels explicit-labels state-acc\n"
            "--BODY--\n"
            "State: 0\n"
            "[!0] 0\n"
            "[0] 1\n"
            "State: 1 {0}\n"
            "[!0] 0\n"
            "[0] 1\n"
            "--END--\n");
}

TEST(HoaWriter, TransitionBasedGeneralizedBuchiMergesParallelEdges) {
  Automaton a;
  a.atoms = {"a", "b"};
  a.state_based = false;
  a.num_sets = 2;
  a.add_state();
  a.add_edge(0, 0, lit(0, true) & lit(1, false), 1);
  a.add_edge(0, 0, lit(0, false) & lit(1, true), 2);
  a.add_edge(0, 0, lit(0, true) & lit(1, true), 3);
  a.add_edge(0, 0, lit(0, false) & lit(1, false), 0);
  a.add_edge(0, 0, lit(0, true) & lit(1, true), 3);  // duplicate: merged into one label
  const std::string h = to_hoa(a);
  EXPECT_NE(h.find("acc-name: generalized-Buchi 2\nAcceptance: 2 Inf(0)&Inf(1)\n"), std::string::npos) << h;
  EXPECT_NE(h.find("properties: trans-labels explicit-labels trans-acc\n"), std::string::npos) << h;
  EXPECT_NE(h.find("[0&!1] 0 {0}\n"), std::string::npos) << h;
  EXPECT_NE(h.find("[!0&1] 0 {1}\n"), std::string::npos) << h;
  EXPECT_NE(h.find("[0&1] 0 {0 1}\n"), std::string::npos) << h;
  EXPECT_NE(h.find("[!0&!1] 0\n"), std::string::npos) << h;
  EXPECT_EQ(h.find("\nname:"), std::string::npos) << "no name header when the name is empty";
}

TEST(HoaWriter, AllAcceptingAndTrueGuard) {
  Automaton a;
  a.atoms = {"x"};
  a.state_based = false;
  a.num_sets = 0;
  a.add_state();
  a.add_edge(0, 0, Cube{});
  a.add_edge(0, 0, lit(0, true));  // subsumed by true: the group prints as [t]
  const std::string h = to_hoa(a);
  EXPECT_NE(h.find("acc-name: all\nAcceptance: 0 t\n"), std::string::npos) << h;
  EXPECT_NE(h.find("State: 0\n[t] 0\n--END--"), std::string::npos) << h;
}

TEST(HoaWriter, QuotesNamesAndAtoms) {
  EXPECT_EQ(hoa_quote("a\"b\\c"), "\"a\\\"b\\\\c\"");
  Automaton a;
  a.name = "F \"o1 in r2\"";
  a.atoms = {"o1 in r2"};
  a.state_based = true;
  a.add_state(true);
  const std::string h = to_hoa(a);
  EXPECT_NE(h.find("name: \"F \\\"o1 in r2\\\"\"\n"), std::string::npos) << h;
  EXPECT_NE(h.find("AP: 1 \"o1 in r2\"\n"), std::string::npos) << h;
}

TEST(HoaWriter, CubeSyntax) {
  EXPECT_EQ(hoa_cube(Cube{}), "t");
  EXPECT_EQ(hoa_cube(lit(3, true) & lit(0, false) & lit(63, true)), "!0&3&63");
}
