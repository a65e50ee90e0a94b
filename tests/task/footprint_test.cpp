// Footprints in the transition system: the fits table agrees with
// world::free_spot() on random sizes, the room bound never refuses a
// placement that free_spot-style placement achieves, it refuses the common
// impossible ones (a tray bigger than a region, a full region), symmetry
// groups only hold objects with the same moves, and forbidden moves.
#include <array>
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "rtamp/task/labeling.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::task {
namespace {

world::Region region(const std::string& name, double x, double y, double sx, double sy, int cap = 64) {
  world::Region r;
  r.name = name;
  r.center = {x, y, 0};
  r.size = {sx, sy, 0};
  r.capacity = cap;
  return r;
}

world::Object object(const std::string& name, const world::Vec3& at, double sx, double sy) {
  world::Object o;
  o.name = name;
  o.position = at;
  o.size = {sx, sy, 0.04};
  return o;
}

world::Container tray(const std::string& name, const world::Vec3& at, double sx, double sy, int cap = 64) {
  world::Container c;
  c.name = name;
  c.position = at;
  c.size = {sx, sy, 0.03};
  c.capacity = cap;
  return c;
}

// Everything in r0 (a big store far from the others).
world::Placement in_store(const world::Scenario& s) {
  world::Placement p;
  for (const auto& o : s.objects) p.set(o.name, "r0", o.cls);
  for (const auto& c : s.containers) p.set(c.name, "r0", c.cls, true);
  return p;
}

TEST(Footprint, FitsTableAgreesWithFreeSpotOnRandomSizes) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> side(0.02, 0.5);
  const world::FitRules rules;
  int fit = 0, no_fit = 0;
  for (int trial = 0; trial < 300; ++trial) {
    world::Scenario s;
    s.name = "fit";
    s.regions.push_back(region("r0", 0, 0, 10, 10));
    // Sizes drawn into a braced list: one order of draws whatever the compiler.
    auto sizes = [&] { return std::array<double, 2>{side(rng), side(rng)}; };
    const auto r1 = sizes(), t1 = sizes(), t2 = sizes();
    s.regions.push_back(region("r1", 20, 0, r1[0], r1[1]));
    s.containers.push_back(tray("t1", {0, 0, 0}, t1[0], t1[1]));
    s.containers.push_back(tray("t2", {2, 2, 0}, t2[0], t2[1]));
    for (int i = 0; i < 4; ++i) {
      const auto o = sizes();
      s.objects.push_back(object("o" + std::to_string(i), {-2, -2 + 0.6 * i, 0}, o[0], o[1]));
    }
    const System ts(s, in_store(s));
    for (unsigned t = 0; t < ts.num_things(); ++t) {
      const world::Vec3 size = t < ts.num_objects() ? s.objects[t].size : s.containers[t - ts.num_objects()].size;
      for (unsigned l = 1; l < ts.num_locations(); ++l) {
        std::optional<world::Vec3> spot;
        if (l < ts.num_regions()) {
          spot = world::free_spot(world::footprint(s.regions[l]), 0, {}, size, rules.gap);
        } else {
          const world::Container& c = s.containers[l - ts.num_regions()];
          // Its floor inside the rims (sim::free_spot treats the rims as obstacles).
          const world::Extent u = world::usable_extent(c, rules);
          spot = world::free_spot({c.position[0], c.position[1], u.x, u.y}, 0, {}, size, rules.gap);
        }
        EXPECT_EQ(ts.fits(t, l), spot.has_value()) << trial << " " << ts.thing_name(t) << " in " << ts.location_name(l);
        (ts.fits(t, l) ? fit : no_fit)++;
        // An empty location: the move is enabled iff the thing fits (and is allowed there).
        const bool legal = !ts.is_container(t) || l < ts.num_regions();
        EXPECT_EQ(ts.enabled(ts.initial(), Action::move(static_cast<std::uint16_t>(t), static_cast<std::uint16_t>(l))),
                  legal && spot.has_value());
      }
    }
  }
  EXPECT_GT(fit, 500);  // both outcomes are exercised
  EXPECT_GT(no_fit, 500);
}

// Things of one size placed one by one into a region by world::free_spot (its
// regular grid of pitch size + gap, an independent search) with the arm's
// clearance: the room rule (grid shares) admits a thing exactly when free_spot
// finds it a spot. Mixed sizes have no exact per-thing rule (world/fit.hpp).
TEST(Footprint, RoomAdmitsWhatPlacementOfOneSizeAchieves) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> area(0.1, 0.6), small(0.02, 0.12);
  const world::FitRules rules;
  int placed = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    world::Scenario s;
    s.name = "room";
    s.regions.push_back(region("r0", 0, 0, 20, 20));
    // Sizes drawn into a braced list: one order of draws whatever the compiler.
    auto sizes = [&](auto& d) { return std::array<double, 2>{d(rng), d(rng)}; };
    const auto r1_size = sizes(area);
    const world::Region r1 = region("r1", 30, 0, r1_size[0], r1_size[1]);
    s.regions.push_back(r1);
    const auto o = sizes(small);
    for (int i = 0; i < 30; ++i) s.objects.push_back(object("o" + std::to_string(i), {-5 + 0.3 * i, -8, 0}, o[0], o[1]));
    const System ts(s, in_store(s));
    std::vector<world::Footprint> occupied;
    State st = ts.initial();
    for (unsigned t = 0; t < ts.num_things(); ++t) {
      const world::Vec3& size = s.objects[t].size;
      const auto spot = world::free_spot(world::footprint(r1), 0, occupied, size, rules.gap);
      const Action a = Action::move(static_cast<std::uint16_t>(t), 1);
      ASSERT_EQ(ts.enabled(st, a), spot.has_value())
          << trial << ": " << ts.thing_name(t) << " (" << o[0] << " x " << o[1] << ") into " << r1_size[0] << " x "
          << r1_size[1] << " after " << placed;
      if (!spot) {
        ++refused;
        break;
      }
      ++placed;
      st = ts.successor(st, a);
      EXPECT_TRUE(ts.valid(st));
      occupied.push_back(world::footprint_at(*spot, size));
    }
  }
  EXPECT_GT(placed, 1000);
  EXPECT_GT(refused, 250);  // most regions fill up before 30
}

// A tray holds blocks on a grid centred in it (the arm sets things down nearest its
// centre): the 3-block-tray scenario's 30 x 16 cm tray takes three 4 cm blocks in a
// row and no fourth whatever its capacity; a 36 x 36 cm region two 30 x 16 cm trays
// side by side (1.5 cm apart), not a third.
TEST(Footprint, RoomInATrayAndForTrays) {
  world::Scenario s;
  s.name = "tray";
  s.regions.push_back(region("r0", 0, 0, 4, 4));
  s.regions.push_back(region("r1", 5, 0, 0.36, 0.36));
  for (int k = 0; k < 4; ++k) s.containers.push_back(tray("t" + std::to_string(k), {-1.0 + k, 1, 0}, 0.30, 0.16, 9));
  for (int i = 0; i < 4; ++i) s.objects.push_back(object("o" + std::to_string(i), {-1 + 0.1 * i, -1, 0}, 0.04, 0.04));
  const System ts(s, in_store(s));
  const unsigned t0 = ts.location_of_container(ts.num_objects());
  State st = ts.initial();
  for (unsigned t = 0; t < 4; ++t) {
    const Action a = Action::move(static_cast<std::uint16_t>(t), static_cast<std::uint16_t>(t0));
    EXPECT_EQ(ts.enabled(st, a), t < 3) << t;
    if (t < 3) st = ts.successor(st, a);
  }
  for (unsigned k = 0; k < 4; ++k) {
    const unsigned t = ts.num_objects() + k;
    const Action a = Action::move(static_cast<std::uint16_t>(t), 1);
    EXPECT_EQ(ts.enabled(st, a), k < 2) << k;
    if (k < 2) st = ts.successor(st, a);
  }
}

TEST(Footprint, CommonImpossibleCasesAreRefused) {
  world::Scenario s;
  s.name = "common";
  s.regions.push_back(region("r0", 0, 0, 2, 2));
  s.regions.push_back(region("small", 3, 0, 0.2, 0.2));
  s.containers.push_back(tray("tray", {0.5, 0.5, 0}, 0.24, 0.16, 4));
  for (int i = 0; i < 12; ++i) s.objects.push_back(object("o" + std::to_string(i), {-0.8 + 0.12 * i, -0.5, 0}, 0.04, 0.04));
  const System ts(s, in_store(s));
  const unsigned tray_t = ts.num_objects(), small = 1;
  // A tray bigger than a region never goes there.
  EXPECT_FALSE(ts.fits(tray_t, small));
  EXPECT_FALSE(ts.enabled(ts.initial(), Action::move(static_cast<std::uint16_t>(tray_t), small)));
  ts.for_each_move(ts.initial(), [&](const Action& a) { EXPECT_FALSE(a.thing == tray_t && a.to == small); });
  // 4 cm blocks 3.5 cm apart in 20 x 20 cm: free_spot places 9, the bound allows 9.
  State st = ts.initial();
  std::vector<world::Footprint> occ;
  int spots = 0;
  for (unsigned t = 0; t < 12; ++t) {
    const auto spot = world::free_spot(world::footprint(s.regions[1]), 0, occ, {0.04, 0.04, 0.04}, 0.035);
    const Action a = Action::move(static_cast<std::uint16_t>(t), small);
    EXPECT_EQ(ts.enabled(st, a), spot.has_value()) << t;
    if (!spot) continue;
    ++spots;
    occ.push_back(world::footprint_at(*spot, {0.04, 0.04, 0}));
    st = ts.successor(st, a);
  }
  EXPECT_EQ(spots, 9);
  // The tray's floor inside its rims is 22.4 x 14.4 cm: a 15 x 15 cm block does not fit.
  world::Scenario s2 = s;
  s2.objects[0].size = {0.15, 0.15, 0.04};
  const System ts2(s2, in_store(s2));
  EXPECT_FALSE(ts2.fits(0, ts2.location_of_container(tray_t)));
  EXPECT_TRUE(ts2.fits(1, ts2.location_of_container(tray_t)));
}

// Trays side by side keep only container_gap (1.5 cm) from each other: a grid
// of 16 trays of 10 cm in 50 cm is placeable, and the bound allows all 16.
TEST(Footprint, RoomAllowsAGridOfTrays) {
  world::Scenario s;
  s.name = "trays";
  s.regions.push_back(region("r0", 0, 0, 4, 4));
  s.regions.push_back(region("r1", 5, 0, 0.5, 0.5));
  for (int i = 0; i < 16; ++i) s.containers.push_back(tray("t" + std::to_string(i), {-1.8 + 0.2 * i, 0, 0}, 0.1, 0.1));
  const System ts(s, in_store(s));
  State st = ts.initial();
  std::vector<world::Footprint> occ;
  for (unsigned t = ts.num_objects(); t < ts.num_things(); ++t) {
    const auto spot = world::free_spot(world::footprint(s.regions[1]), 0, occ, {0.1, 0.1, 0.03}, 0.015);
    ASSERT_TRUE(spot) << t;
    const Action a = Action::move(static_cast<std::uint16_t>(t), 1);
    ASSERT_TRUE(ts.enabled(st, a)) << ts.thing_name(t);
    occ.push_back(world::footprint_at(*spot, {0.1, 0.1, 0}));
    st = ts.successor(st, a);
  }
}

// `rtamp gen` scenes: every region can hold all blocks, so "all block in r2"
// stays achievable whatever the size (and a tray fits every region).
TEST(Footprint, GeneratedScenesHaveRoomForEverything) {
  for (int n : {1, 4, 9, 10, 16, 25, 60})
    for (int c : {0, 1, 3}) {
      world::GeneratorOptions o;
      o.regions = 4;
      o.objects = n;
      o.containers = c;
      const world::Scenario s = world::generate_scenario(o);
      ASSERT_NO_THROW(world::validate(s));
      const System ts(s);
      EXPECT_TRUE(ts.valid(ts.initial())) << n << " " << c;
      for (unsigned t = ts.num_objects(); t < ts.num_things(); ++t) EXPECT_TRUE(ts.fits(t, 0));
      // Every block into r2, one at a time (all start in r1), when no tray stands there
      // (trays stand in r4, r3, r2 in this order).
      if (c >= 3) continue;
      State st = ts.initial();
      for (unsigned t = 0; t < ts.num_objects(); ++t) {
        const Action a = Action::move(static_cast<std::uint16_t>(t), 1);
        ASSERT_TRUE(ts.enabled(st, a)) << n << " " << c << " " << ts.to_string(st) << " + " << ts.action_name(a);
        st = ts.successor(st, a);
      }
      EXPECT_TRUE(ts.valid(st));
    }
}

TEST(Footprint, IgnoreGeometryAndCapacity) {
  world::Scenario s;
  s.name = "relaxed";
  s.regions.push_back(region("r0", 0, 0, 2, 2));
  s.regions.push_back(region("small", 3, 0, 0.1, 0.1));
  s.containers.push_back(tray("tray", {0.5, 0.5, 0}, 0.24, 0.16, 4));
  System::Options geo_off;
  geo_off.ignore_geometry = true;
  const System strict(s, in_store(s)), relaxed(s, in_store(s), "", geo_off);
  EXPECT_FALSE(strict.enabled(strict.initial(), Action::move(0, 1)));
  EXPECT_TRUE(relaxed.enabled(relaxed.initial(), Action::move(0, 1)));
  // ignore_capacity ignores room but not whether a thing fits at all.
  System::Options cap_off;
  cap_off.ignore_capacity = true;
  const System no_cap(s, in_store(s), "", cap_off);
  EXPECT_FALSE(no_cap.enabled(no_cap.initial(), Action::move(0, 1)));
}

// A store r0, a 30 cm region r1 and a 24 x 16 cm tray in r0 (objects added by the test).
world::Scenario store_r1_and_tray() {
  world::Scenario s;
  s.name = "store";
  s.regions.push_back(region("r0", 0, 0, 1, 1));
  s.regions.push_back(region("r1", 2, 0, 0.3, 0.3));
  s.containers.push_back(tray("tray", {0.2, 0.2, 0}, 0.24, 0.16, 4));
  return s;
}

TEST(Footprint, SymmetryNeedsTheSameFootprintRules) {
  world::Scenario s = store_r1_and_tray();
  s.objects.push_back(object("a", {-0.3, -0.3, 0}, 0.04, 0.04));
  s.objects.push_back(object("b", {-0.2, -0.3, 0}, 0.04, 0.04));
  s.objects.push_back(object("big", {-0.1, -0.3, 0}, 0.2, 0.2));  // same class, does not fit the tray
  s.objects.push_back(object("c", {0.0, -0.3, 0}, 0.04, 0.04));
  System ts(s, in_store(s));
  const Labeling lab(ts, {});
  const auto groups = lab.symmetry_groups();
  std::set<std::vector<unsigned>> got(groups.begin(), groups.end());
  EXPECT_EQ(got, (std::set<std::vector<unsigned>>{{0, 1, 3}, {2}}));
  EXPECT_THROW(ts.set_symmetry({{0, 2}}), Error);
  ts.set_symmetry(groups);
  EXPECT_EQ(ts.group_of(1), ts.group_of(0));
  // A forbidden move takes its thing out of its group.
  ts.forbid_move(1, 1);
  EXPECT_LT(ts.group_of(1), 0);
  EXPECT_GE(ts.group_of(0), 0);
  EXPECT_EQ(ts.group_of(0), ts.group_of(3));
  EXPECT_FALSE(ts.same_moves(0, 1));
  const Labeling lab2(ts, {});
  const auto groups2 = lab2.symmetry_groups();
  std::set<std::vector<unsigned>> got2(groups2.begin(), groups2.end());
  EXPECT_EQ(got2, (std::set<std::vector<unsigned>>{{0, 3}, {1}, {2}}));
}

TEST(Footprint, ForbiddenMoves) {
  world::Scenario s = store_r1_and_tray();
  s.objects.push_back(object("a", {-0.3, -0.3, 0}, 0.04, 0.04));
  s.objects.push_back(object("b", {-0.2, -0.3, 0}, 0.04, 0.04));
  System ts(s, in_store(s));
  auto moves = [&] {
    std::set<std::string> names;
    ts.for_each_move(ts.initial(), [&](const Action& a) { names.insert(ts.action_name(a)); });
    return names;
  };
  const std::set<std::string> all{"move(a, r1)", "move(a, tray)", "move(b, r1)", "move(b, tray)", "move(tray, r1)"};
  EXPECT_EQ(moves(), all);
  ts.forbid_moves({{"a", "tray"}, {"gone", "r1"}, {"b", "nowhere"}, {"tray", "r1"}});
  ts.forbid_move(99, 0);  // out of range: ignored
  ts.forbid_move(0, 2);   // again: listed once
  EXPECT_EQ(moves(), (std::set<std::string>{"move(a, r1)", "move(b, r1)", "move(b, tray)"}));
  EXPECT_FALSE(ts.enabled(ts.initial(), Action::move(0, 2)));
  EXPECT_FALSE(ts.enabled(ts.initial(), Action::move(2, 1)));
  EXPECT_TRUE(ts.enabled(ts.initial(), Action::move(1, 2)));
  EXPECT_TRUE(ts.forbidden(0, 2));
  EXPECT_FALSE(ts.forbidden(1, 2));
  EXPECT_EQ(ts.forbidden_moves(), (std::vector<std::pair<unsigned, unsigned>>{{0, 2}, {2, 1}}));
}

}  // namespace
}  // namespace rtamp::task
