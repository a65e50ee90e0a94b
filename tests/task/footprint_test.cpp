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

// Sequential free_spot placement with the simulation's clearances (objects
// keep `gap` from objects, min(gap, container_gap) from a tray): every thing
// that gets a spot was allowed by the room bound.
TEST(Footprint, RoomNeverRefusesWhatPlacementAchieves) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> area(0.15, 0.6), small(0.02, 0.09), big(0.1, 0.3);
  const world::FitRules rules;
  int placed = 0, refused = 0;
  for (int trial = 0; trial < 200; ++trial) {
    world::Scenario s;
    s.name = "room";
    s.regions.push_back(region("r0", 0, 0, 20, 20));
    // Sizes drawn into a braced list: one order of draws whatever the compiler.
    auto sizes = [&](auto& d) { return std::array<double, 2>{d(rng), d(rng)}; };
    const auto r1_size = sizes(area);
    const world::Region r1 = region("r1", 30, 0, r1_size[0], r1_size[1]);
    s.regions.push_back(r1);
    const bool into_tray = trial % 3 == 0;
    if (into_tray) {
      const auto t0 = sizes(area);
      s.containers.push_back(tray("t0", {5, 5, 0}, t0[0], t0[1]));
    }
    for (int i = 0; i < 40; ++i) {
      if (!into_tray && i % 7 == 3) {
        const auto t = sizes(big);
        s.containers.push_back(tray("t" + std::to_string(i), {-5 + 0.5 * i, 8, 0}, t[0], t[1]));
      } else {
        const double a = small(rng);
        s.objects.push_back(object("o" + std::to_string(i), {-5 + 0.2 * i, -8, 0}, a, rng() % 2 ? a : small(rng)));
      }
    }
    const System ts(s, in_store(s));
    const unsigned target = into_tray ? ts.num_regions() : 1;
    world::Footprint area_fp = world::footprint(r1);
    std::vector<world::Footprint> occupied;
    if (into_tray) {
      const world::Container& c = s.containers[0];
      const world::Extent u = world::usable_extent(c, rules);
      area_fp = {c.position[0], c.position[1], u.x, u.y};
    }
    State st = ts.initial();
    for (unsigned t = 0; t < ts.num_things(); ++t) {
      if (into_tray && ts.is_container(t)) continue;
      const bool con = ts.is_container(t);
      const world::Vec3& size = con ? s.containers[t - ts.num_objects()].size : s.objects[t].size;
      const auto spot = world::free_spot(area_fp, 0, occupied, size, 0);
      const Action a = Action::move(static_cast<std::uint16_t>(t), static_cast<std::uint16_t>(target));
      if (!spot) {
        refused += !ts.enabled(st, a);
        continue;
      }
      ASSERT_TRUE(ts.enabled(st, a)) << trial << ": " << ts.thing_name(t) << " has a spot in " << ts.location_name(target)
                                     << " but the room bound refuses it (" << ts.to_string(st) << ")";
      ++placed;
      st = ts.successor(st, a);
      EXPECT_TRUE(ts.valid(st));
      const double g = con ? std::min(rules.gap, rules.container_gap) : rules.gap;  // others keep this from it
      occupied.push_back(world::footprint_at(*spot, {size[0] + 2 * g, size[1] + 2 * g, 0}));
    }
  }
  EXPECT_GT(placed, 1000);
  EXPECT_GT(refused, 100);  // the bound does refuse things in full locations
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

// `rtamp gen` scenes: every region can hold all blocks and a tray at once, so
// "all block in r2" stays achievable whatever the size.
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
      // Move a tray, then every block, into r1 one at a time.
      State st = ts.initial();
      for (unsigned k = 0; k < ts.num_things(); ++k) {
        const unsigned t = (k + ts.num_objects()) % ts.num_things();  // containers first
        if (ts.location(st, t) == 0 || (ts.is_container(t) && t > ts.num_objects())) continue;
        const Action a = Action::move(static_cast<std::uint16_t>(t), 0);
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
