// The scenario generator: deterministic per seed, always valid, objects on a
// non-overlapping grid in r1, the documented layouts, and clear errors.
#include "rtamp/world/generator.hpp"

#include <gtest/gtest.h>

#include "rtamp/world/geometry.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::world {
namespace {

GeneratorOptions opts(int m, int n, GeneratorOptions::Layout layout, std::uint64_t seed = 1, int c = 0) {
  GeneratorOptions o;
  o.regions = m;
  o.objects = n;
  o.layout = layout;
  o.seed = seed;
  o.containers = c;
  return o;
}

std::string numbered(char prefix, std::size_t i) {
  std::string out(1, prefix);
  out += std::to_string(i);
  return out;
}

constexpr auto kLine = GeneratorOptions::Layout::Line;
constexpr auto kRandom = GeneratorOptions::Layout::Random;

TEST(Generator, DeterministicPerSeed) {
  for (std::uint64_t seed : {1u, 2u, 99u}) {
    const std::string a = to_yaml(generate_scenario(opts(5, 6, kRandom, seed)));
    const std::string b = to_yaml(generate_scenario(opts(5, 6, kRandom, seed)));
    EXPECT_EQ(a, b);
  }
  EXPECT_NE(to_yaml(generate_scenario(opts(5, 6, kRandom, 1))), to_yaml(generate_scenario(opts(5, 6, kRandom, 2))));
  // The line layout ignores the seed.
  EXPECT_EQ(to_yaml(generate_scenario(opts(5, 6, kLine, 1))), to_yaml(generate_scenario(opts(5, 6, kLine, 2))));
}

// Pinned output: benchmark scenes must not change silently between versions
// or machines (the sampler is mt19937_64 with our own uniform mapping).
TEST(Generator, PinnedRandomLayout) {
  const Scenario s = generate_scenario(opts(5, 4, kRandom, 1));
  ASSERT_EQ(s.regions.size(), 5u);
  EXPECT_EQ(s.name, "gen-random-m5-n4-s1");
  std::string centres;
  for (const Region& r : s.regions) centres += std::to_string(r.center[0]) + "," + std::to_string(r.center[1]) + ";";
  EXPECT_EQ(centres, "0.334000,-0.364000;0.651000,-0.479000;0.551000,0.411000;0.289000,0.056000;0.990000,-0.278000;");
}

TEST(Generator, BenchmarkSizesAreValid) {
  for (std::uint64_t seed = 1; seed <= 100; ++seed)
    for (int n : {2, 6, 10}) {
      const Scenario s = generate_scenario(opts(5, n, kRandom, seed, static_cast<int>(seed % 3)));
      ASSERT_NO_THROW(validate(s));
      const Placement p = initial_placement(s);
      for (const Object& o : s.objects) ASSERT_EQ(p.things.at(o.name).location, "r1") << seed;
      // Random centres lie in the 1 m square, regions at least 2 cm apart.
      for (std::size_t i = 0; i < s.regions.size(); ++i) {
        EXPECT_GE(s.regions[i].center[0], 0.2);
        EXPECT_LE(s.regions[i].center[0], 1.2);
        EXPECT_GE(s.regions[i].center[1], -0.5);
        EXPECT_LE(s.regions[i].center[1], 0.5);
        for (std::size_t j = 0; j < i; ++j)
          EXPECT_FALSE(footprint(s.regions[i]).overlaps(footprint(s.regions[j]), 0.0199)) << seed;
      }
    }
}

TEST(Generator, ObjectsOnANonOverlappingGridInR1) {
  for (int n : {1, 2, 3, 7, 10, 25, 64, 256}) {
    const Scenario s = generate_scenario(opts(2, n, kLine));
    ASSERT_EQ(s.objects.size(), static_cast<std::size_t>(n));
    const Footprint r1 = footprint(s.regions[0]);
    EXPECT_GE(s.regions[0].capacity, n);
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
      EXPECT_EQ(s.objects[i].name, numbered('o', i + 1));
      EXPECT_EQ(s.objects[i].cls, "block");
      EXPECT_TRUE(r1.contains(footprint(s.objects[i]))) << n << " " << i;
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_FALSE(footprint(s.objects[i]).overlaps(footprint(s.objects[j]), 0.0199)) << n << " " << i << " " << j;
    }
  }
}

TEST(Generator, LineLayout) {
  const Scenario s = generate_scenario(opts(5, 3, kLine));
  ASSERT_EQ(s.regions.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(s.regions[i].name, numbered('r', i + 1));
    EXPECT_DOUBLE_EQ(s.regions[i].center[0], 0.5);
    if (i > 0) {
      EXPECT_NEAR(s.regions[i].center[1] - s.regions[i - 1].center[1], 0.5, 1e-9);
    }
  }
  EXPECT_NEAR(s.regions[0].center[1] + s.regions[4].center[1], 0, 1e-9);  // centred on y = 0
  // Regions too wide for 0.5 m spacing spread out.
  const Scenario wide = generate_scenario(opts(3, 100, kLine));
  EXPECT_NO_THROW(validate(wide));
  EXPECT_GT(wide.regions[1].center[1] - wide.regions[0].center[1], 0.5);
}

TEST(Generator, TaskPropositionsAndContainers) {
  const Scenario s = generate_scenario(opts(4, 3, kLine, 1, 2));
  EXPECT_EQ(s.task, "F G all_in_r2");
  ASSERT_EQ(s.propositions.size(), 1u);
  EXPECT_EQ(s.propositions[0].name, "all_in_r2");
  EXPECT_EQ(to_string(s.propositions[0].expr), "all block in r2");
  ASSERT_EQ(s.containers.size(), 2u);
  const Placement p = initial_placement(s);
  EXPECT_EQ(p.things.at("t1").location, "r4");
  EXPECT_EQ(p.things.at("t2").location, "r3");
  for (const Region& r : s.regions) EXPECT_EQ(r.capacity, 5);

  GeneratorOptions o = opts(3, 2, kRandom, 4);
  o.task = "F (p & F q)";
  o.propositions = {{"p", "o1 in r3"}, {"q", "count block in r2 >= 2"}};
  const Scenario t = generate_scenario(o);
  EXPECT_EQ(t.task, "F (p & F q)");
  ASSERT_EQ(t.propositions.size(), 3u);
  EXPECT_EQ(t.propositions[1].name, "p");
  EXPECT_EQ(t.propositions[2].expr.kind, PropExpr::Kind::Count);

  GeneratorOptions one = opts(1, 2, kLine);
  one.task = "G true";
  EXPECT_NO_THROW(generate_scenario(one));
}

TEST(Generator, Errors) {
  auto fails = [](const GeneratorOptions& o, const char* what) {
    try {
      generate_scenario(o);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const Error& e) {
      EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
    }
  };
  fails(opts(0, 3, kLine), "--regions must be between 1 and 64");
  fails(opts(65, 3, kLine), "--regions must be between 1 and 64");
  fails(opts(2, 0, kLine), "--objects must be between 1 and 256");
  fails(opts(2, 3, kLine, 1, 2), "--containers must be between 0 and regions - 1 = 1");
  fails(opts(1, 3, kLine), "needs a region r2");
  fails(opts(30, 256, kRandom), "cannot place 30 regions");
  GeneratorOptions o = opts(2, 2, kLine);
  o.propositions = {{"p", "o1 in"}};
  fails(o, "expected a location name");
  o.propositions = {{"p", "o9 in r1"}};
  fails(o, "unknown object 'o9'");
  o.propositions = {{"all_in_r2", "o1 in r1"}};
  fails(o, "duplicate proposition 'all_in_r2'");
  EXPECT_THROW(parse_layout("grid"), Error);
  EXPECT_EQ(parse_layout("random"), kRandom);
}

}  // namespace
}  // namespace rtamp::world
