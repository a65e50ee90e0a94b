// The rule book of space (world/space_rules.hpp): the order and words of its
// refusals, the state of a location in a scenario's world, and a planner change
// that would break a capacity or a room being an error naming the thing and the
// location (check_change_room through parse_changes).
#include <gtest/gtest.h>

#include "rtamp/world/change.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::world {
namespace {

const Body kBlock{{0.04, 0.04, 0.04}, false};
const Body kTray{{0.30, 0.16, 0.03}, true};

LocationNow region(double side, int capacity, int count = 0, std::int64_t used = 0) {
  LocationNow at;
  at.kind = LocationNow::Kind::Region;
  at.usable = {side, side};
  at.capacity = capacity;
  at.count = count;
  at.used = used;
  return at;
}

TEST(SpaceRules, RefusalsInTheirOrderAndWords) {
  EXPECT_EQ(refusal("o1", kBlock, "r9", LocationNow{}), "r9 is not a location in the world");
  EXPECT_EQ(refusal("o1", kBlock, "", LocationNow{}), "no location");
  LocationNow tray;
  tray.kind = LocationNow::Kind::Container;
  tray.usable = {0.284, 0.144};
  tray.capacity = 3;
  EXPECT_EQ(refusal("t1", kTray, "t1", tray), "t1 cannot go into itself");
  EXPECT_EQ(refusal("t2", kTray, "t1", tray), "t2 is a container and t1 is one: containers do not nest");
  tray.held = true;
  EXPECT_EQ(refusal("o1", kBlock, "t1", tray), "t1 is in the gripper");
  // Nesting and the gripper come before fit, fit before capacity, capacity before room.
  EXPECT_EQ(refusal("t2", kTray, "r1", region(0.2, 0, 5, 1'000'000'000)),
            "t2 does not fit in r1 (0.300 x 0.160 m; usable 0.200 x 0.200 m)");
  EXPECT_EQ(refusal("o1", kBlock, "r1", region(0.2, 2, 2, 1'000'000'000)), "r1 has no room (capacity 2)");
  // A 20 cm region holds a 3 x 3 grid of 4 cm blocks 3.5 cm apart: nine fit, a tenth never.
  const std::int64_t share = cell_units(kBlock, {0.2, 0.2}, false);
  EXPECT_GT(share, kRoomUnits / 10);
  EXPECT_LE(share, kRoomUnits / 9);
  EXPECT_EQ(refusal("o9", kBlock, "r1", region(0.2, 99, 8, 8 * share)), "");
  EXPECT_EQ(refusal("o10", kBlock, "r1", region(0.2, 99, 9, 9 * share)),
            "r1 has no room for o10 (it takes 10 % of r1; 92 % is taken)");
  // A thing exactly as large as the usable extent fits (edges may touch).
  EXPECT_EQ(refusal("o1", kBlock, "r1", region(0.04, 1)), "");
}

TEST(SpaceRules, LocationNowCountsTheThingsDirectlyThere) {
  const Scenario s = load_scenario("3-block-tray");
  Placement p = initial_placement(s);  // r1: o1, o2, o3 and the tray r3
  LocationNow r1 = location_now(s, p, "r1", "");
  EXPECT_EQ(r1.kind, LocationNow::Kind::Region);
  EXPECT_EQ(r1.capacity, 4);
  EXPECT_EQ(r1.count, 4);
  const Extent u1 = usable_extent(*s.find_region("r1"));
  EXPECT_EQ(r1.used, 3 * cell_units(body_of(s, "o1"), u1, false) + cell_units(body_of(s, "r3"), u1, false));
  EXPECT_EQ(location_now(s, p, "r1", "o2").count, 3);
  p.things["o1"].location = "r3";  // on the tray: counts there, not in r1
  EXPECT_EQ(location_now(s, p, "r1", "").count, 3);
  const LocationNow r3 = location_now(s, p, "r3", "");
  EXPECT_EQ(r3.kind, LocationNow::Kind::Container);
  EXPECT_EQ(r3.count, 1);
  EXPECT_EQ(location_now(s, p, "o2", "").kind, LocationNow::Kind::Unknown);
  EXPECT_TRUE(body_of(s, "r3").container);
  EXPECT_FALSE(new_body(s, "block", false).container);
  EXPECT_EQ(new_body(s, "crate", true).size, Container{}.size);
}

TEST(SpaceRules, AChangeThatOverfillsALocationIsAnError) {
  const Scenario s = load_scenario("3-block-tray");
  try {
    parse_changes(s, {"add o4 block r1"});
    FAIL() << "accepted a fifth thing in r1 (capacity 4)";
  } catch (const Error& e) {
    EXPECT_EQ(e.message(), "cannot put 'o4' in 'r1': r1 has no room (capacity 4)");
    EXPECT_EQ(e.where().column, 14);  // at "r1"
  }
  // With a block moved out first there is room; moving it back overfills again.
  EXPECT_EQ(parse_changes(s, {"move o2 r2", "add o4 block r1"}).size(), 2u);
  EXPECT_THROW(parse_changes(s, {"move o2 r2", "add o4 block r1", "move o2 r1"}), Error);
  // A thing may stay where it is (moving it there again).
  EXPECT_EQ(parse_changes(s, {"move o1 r1"}).size(), 1u);
  // A removed tray's contents fall into its region, one by one.
  EXPECT_EQ(parse_changes(s, {"move o1 r3", "remove-container r3"}).size(), 2u);
  EXPECT_THROW(parse_changes(s, {"move r3 r2", "add o4 block r2", "add o5 block r2", "add o6 block r2", "move o1 r3",
                                 "move o2 r3", "remove-container r3"}),
               Error);
}

}  // namespace
}  // namespace rtamp::world
