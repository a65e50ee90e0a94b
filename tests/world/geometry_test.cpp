// The geometric abstraction: point location (regions, containers with their
// rim rule and precedence, "none"), initial placement, and the free-spot
// finder checked against brute force (a spot is inside, never overlaps, and
// is found whenever any grid spot is free).
#include "rtamp/world/geometry.hpp"

#include <gtest/gtest.h>

#include <random>

#include "rtamp/world/scenario_io.hpp"

namespace rtamp::world {
namespace {

// A raised region ("high", surface at z = 0.2) exercises the rules' heights;
// validate() refuses one in a scenario file (a region is a patch of the table
// top), so it is raised after parsing.
Scenario scene() {
  Scenario s = parse_scenario(R"yaml(
name: g
regions:
  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.2], capacity: 9}
  - {name: r2, center: [0.4, -0.3, 0], size: [0.3, 0.2], capacity: 9}
  - {name: high, center: [0.8, 0, 0], size: [0.1, 0.1], capacity: 9}
containers:
  - {name: t1, position: [0.5, -0.3, 0], size: [0.2, 0.1, 0.03], capacity: 4}
objects:
  - {name: o1, position: [0.35, 0.3, 0]}
  - {name: o2, position: [0.5, -0.3, 0.01]}
  - {name: o3, position: [0.3, -0.3, 0]}
task: "true"
)yaml",
                              "g.yaml");
  s.regions[2].center[2] = 0.2;  // "high"
  return s;
}

TEST(Footprint, Predicates) {
  const Footprint a{0, 0, 2, 1};
  EXPECT_TRUE(a.contains_point(1, 0.5));  // edges included
  EXPECT_FALSE(a.contains_point(1.01, 0));
  EXPECT_TRUE(a.contains_point(1.01, 0, 0.02));
  EXPECT_TRUE(a.contains(Footprint{0.5, 0, 1, 1}));
  EXPECT_FALSE(a.contains(Footprint{0.6, 0, 1, 1}));
  EXPECT_TRUE(a.overlaps(Footprint{1.5, 0, 2, 2}));
  EXPECT_FALSE(a.overlaps(Footprint{2, 0, 2, 2}));  // touching edges
  EXPECT_TRUE(a.overlaps(Footprint{2, 0, 2, 2}, 0.01));
  EXPECT_FALSE(a.overlaps(Footprint{2.1, 0, 2, 2}, 0.05));
}

TEST(Geometry, Locate) {
  const Scenario s = scene();
  const Geometry g(s);
  EXPECT_EQ(g.locate({0.4, 0.3, 0}), "r1");
  EXPECT_EQ(g.locate({0.55, 0.4, 0}), "r1");  // corner, edges included
  EXPECT_EQ(g.locate({0.56, 0.3, 0}), "none");
  EXPECT_EQ(g.locate({0.4, 0.3, -0.019}), "r1");  // within 2 cm below the surface
  EXPECT_EQ(g.locate({0.4, 0.3, -0.03}), "none");
  EXPECT_EQ(g.locate({0.4, 0.3, 0.5}), "r1");  // any height above
  EXPECT_EQ(g.locate({0.8, 0, 0.2}), "high");
  EXPECT_EQ(g.locate({0.8, 0, 0.1}), "none");  // below the raised region's surface
  EXPECT_EQ(g.locate({0, 0, 0}), "none");
  // The tray (x 0.4-0.6, y -0.35 to -0.25, rim at 0.03) takes precedence over r2.
  EXPECT_EQ(g.locate({0.45, -0.3, 0.01}), "t1");
  EXPECT_EQ(g.locate({0.35, -0.3, 0.01}), "r2");
  // Just outside the footprint: in the tray below its rim, not above it.
  EXPECT_EQ(g.locate({0.605, -0.3, 0.02}), "t1");
  EXPECT_EQ(g.locate({0.605, -0.3, 0.05}), "none");
  EXPECT_EQ(g.locate({0.395, -0.3, 0.05}), "r2");
  EXPECT_EQ(g.locate({0.395, -0.3, 0.02}), "t1");
  EXPECT_EQ(g.locate({0.5, -0.3, 0.3}), "t1");  // high above the tray
  EXPECT_EQ(g.locate_region({0.5, -0.3, 0}), "r2");
}

TEST(Geometry, MovingContainers) {
  Geometry g(scene());
  ASSERT_TRUE(g.move_container("t1", {0.4, 0.3, 0}));
  EXPECT_EQ(g.locate({0.45, 0.3, 0.01}), "t1");
  EXPECT_EQ(g.locate({0.5, -0.3, 0.01}), "r2");
  EXPECT_FALSE(g.move_container("t9", {0, 0, 0}));
  Container t2;
  t2.name = "t2";
  t2.position = {0.47, 0.3, 0};
  t2.size = {0.1, 0.1, 0.03};
  g.add_container(t2);
  EXPECT_EQ(g.locate({0.47, 0.3, 0.01}), "t2");  // nearer centre wins
  EXPECT_EQ(g.locate({0.36, 0.3, 0.01}), "t1");
  EXPECT_TRUE(g.remove_container("t2"));
  EXPECT_FALSE(g.remove_container("t2"));
  EXPECT_EQ(g.locate({0.47, 0.3, 0.01}), "t1");
  EXPECT_EQ(g.surface_z("t1"), std::optional<double>(0.01));
  EXPECT_EQ(g.surface_z("high"), std::optional<double>(0.2));
  EXPECT_FALSE(g.surface_z("nowhere").has_value());
}

TEST(Geometry, InitialPlacement) {
  const Placement p = initial_placement(scene());
  EXPECT_EQ(p.things.size(), 4u);
  EXPECT_EQ(p.things.at("o1").location, "r1");
  EXPECT_EQ(p.things.at("o2").location, "t1");
  EXPECT_EQ(p.things.at("o3").location, "r2");
  EXPECT_EQ(p.things.at("t1").location, "r2");
  EXPECT_TRUE(p.things.at("t1").container);
  EXPECT_EQ(p.things.at("t1").cls, "tray");
  EXPECT_EQ(p.things.at("o1").cls, "block");
  EXPECT_FALSE(p.things.at("o1").container);
}

bool fits(const Footprint& area, const std::vector<Footprint>& occupied, const Footprint& f, double gap) {
  if (!area.contains(f)) return false;
  for (const Footprint& o : occupied)
    if (f.overlaps(o, gap)) return false;
  return true;
}

TEST(FreeSpot, EmptyAreaGivesTheGridPointNearestTheCentre) {
  // 0.3 wide: six columns of pitch 0.05 (no column at the centre); 0.25 deep: five rows (one at the centre).
  const auto spot = free_spot(Footprint{0.4, 0.3, 0.3, 0.25}, 0.05, {}, {0.04, 0.04, 0.04}, 0.01);
  ASSERT_TRUE(spot);
  EXPECT_NEAR(std::abs((*spot)[0] - 0.4), 0.025, 1e-12);
  EXPECT_NEAR((*spot)[1], 0.3, 1e-12);
  EXPECT_EQ((*spot)[2], 0.05);
}

TEST(FreeSpot, FillsAGridThenRefusesWhenFull) {
  // A 0.2 x 0.1 area holds a 4 x 2 grid of 4 cm blocks with 1 cm gaps.
  const Footprint area{0, 0, 0.2, 0.1};
  const Vec3 block{0.04, 0.04, 0.04};
  const double gap = 0.01;
  std::vector<Footprint> occupied;
  for (int i = 0; i < 8; ++i) {
    const auto spot = free_spot(area, 0, occupied, block, gap);
    ASSERT_TRUE(spot) << i;
    const Footprint f = footprint_at(*spot, block);
    ASSERT_TRUE(fits(area, occupied, f, gap)) << i;
    occupied.push_back(f);
  }
  EXPECT_FALSE(free_spot(area, 0, occupied, block, gap));
  EXPECT_FALSE(free_spot(area, 0, {}, {0.3, 0.04, 0.04}));  // too big
  EXPECT_FALSE(free_spot(area, 0, {}, {0, 0.04, 0.04}));    // degenerate
}

// Against brute force: whenever some spot on a fine scan is free, free_spot
// finds one, and whatever it returns is valid.
TEST(FreeSpot, AgreesWithBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  int found = 0, full = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Footprint area{u(rng), u(rng), 0.1 + 0.3 * u(rng), 0.1 + 0.3 * u(rng)};
    const Vec3 size{0.02 + 0.06 * u(rng), 0.02 + 0.06 * u(rng), 0.04};
    std::vector<Footprint> occupied;
    const int n = static_cast<int>(rng() % 12);
    for (int k = 0; k < n; ++k)
      occupied.push_back({area.min_x() + area.sx * u(rng), area.min_y() + area.sy * u(rng), 0.02 + 0.08 * u(rng),
                          0.02 + 0.08 * u(rng)});
    const auto spot = free_spot(area, 0, occupied, size);
    if (spot) {
      ++found;
      EXPECT_TRUE(fits(area, occupied, footprint_at(*spot, size), kPlaceGap)) << trial;
      continue;
    }
    ++full;
    // free_spot's finest grid has a step of a quarter pitch; a free spot that
    // survives a margin of one step in every direction must lie near a grid point.
    const double step = (std::min(size[0], size[1]) + kPlaceGap) / 4;
    const Vec3 grown{size[0] + 2 * step, size[1] + 2 * step, size[2]};
    for (double x = area.min_x(); x <= area.max_x(); x += 0.002)
      for (double y = area.min_y(); y <= area.max_y(); y += 0.002)
        ASSERT_FALSE(fits(area, occupied, footprint_at({x, y, 0}, grown), kPlaceGap))
            << "trial " << trial << ": free at " << x << ", " << y;
  }
  EXPECT_GT(found, 50);
  EXPECT_GT(full, 5);
}

TEST(FreeSpot, InANamedLocation) {
  const Scenario s = scene();
  const Geometry g(s);
  std::vector<Footprint> occupied;
  for (const Object& o : s.objects) occupied.push_back(footprint(o));
  const auto in_tray = g.free_spot("t1", occupied, {0.04, 0.04, 0.04});
  ASSERT_TRUE(in_tray);
  EXPECT_EQ(g.locate(*in_tray), "t1");
  EXPECT_DOUBLE_EQ((*in_tray)[2], 0.01);  // on the tray's floor
  // In r2, the tray's footprint is occupied too.
  occupied.push_back(footprint(s.containers[0]));
  const auto in_r2 = g.free_spot("r2", occupied, {0.04, 0.04, 0.04});
  ASSERT_TRUE(in_r2);
  EXPECT_EQ(g.locate(*in_r2), "r2");
  EXPECT_FALSE(g.free_spot("r9", occupied, {0.04, 0.04, 0.04}));
}

}  // namespace
}  // namespace rtamp::world
