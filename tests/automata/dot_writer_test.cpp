// DOT writer: accepting states are double circles, guards use atom names,
// marks follow TGBA edge labels, strings are escaped.
#include <gtest/gtest.h>

#include "rtamp/automata/dot_writer.hpp"

using namespace rtamp::automata;

namespace {

Cube lit(unsigned i, bool positive) {
  Cube c;
  (positive ? c.pos : c.neg) = Letter{1} << i;
  return c;
}

}  // namespace

TEST(DotWriter, BuchiAcceptingStatesAreDoubleCircles) {
  Automaton a;
  a.name = "F \"goal\"";
  a.atoms = {"goal", "o1 in r2"};
  a.state_based = true;
  a.add_state(false);
  a.add_state(true);
  a.initial = 0;
  a.add_edge(0, 1, lit(0, true) & lit(1, false));
  a.add_edge(0, 0, lit(0, false));
  a.add_edge(1, 1, Cube{});
  const std::string d = to_dot(a);
  EXPECT_EQ(d.rfind("digraph \"F \\\"goal\\\"\" {", 0), 0u) << d;
  EXPECT_NE(d.find("  1 [label=\"1\", shape=doublecircle];"), std::string::npos) << d;
  EXPECT_NE(d.find("  0 [label=\"0\"];"), std::string::npos) << d;
  EXPECT_NE(d.find("I -> 0;"), std::string::npos) << d;
  EXPECT_NE(d.find("0 -> 1 [label=\"goal & !o1 in r2\"];"), std::string::npos) << d;
  EXPECT_NE(d.find("0 -> 0 [label=\"!goal\"];"), std::string::npos) << d;
  EXPECT_NE(d.find("1 -> 1 [label=\"true\"];"), std::string::npos) << d;
  EXPECT_EQ(d.substr(d.size() - 2), "}\n");
}

TEST(DotWriter, TgbaMarksOnEdgesAndDisjunctions) {
  Automaton a;
  a.atoms = {"a", "b"};
  a.state_based = false;
  a.num_sets = 2;
  a.add_state();
  a.add_edge(0, 0, lit(0, true), 1);
  a.add_edge(0, 0, lit(1, true) & lit(0, false), 1);
  a.add_edge(0, 0, Cube{}, 0);
  a.add_edge(0, 0, lit(0, true) & lit(1, true), 3);
  const std::string d = to_dot(a);
  EXPECT_NE(d.find("0 -> 0 [label=\"a | (!a & b) {0}\"];"), std::string::npos) << d;
  EXPECT_NE(d.find("0 -> 0 [label=\"true\"];"), std::string::npos) << d;
  EXPECT_NE(d.find("0 -> 0 [label=\"a & b {0,1}\"];"), std::string::npos) << d;
  EXPECT_EQ(d.find("doublecircle"), std::string::npos) << d;
}

TEST(DotWriter, CubeToString) {
  EXPECT_EQ(cube_to_string(Cube{}, {"a"}), "true");
  EXPECT_EQ(cube_to_string(lit(1, false) & lit(0, true), {"a", "b"}), "a & !b");
}
