// The transition system: packing, enabled actions, successors, capacities,
// containers carrying their contents, names round trip.
#include "rtamp/task/transition_system.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "rtamp/util/error.hpp"

namespace rtamp::task {
namespace {

world::Scenario scene(int regions, int objects, int containers, int cap = 8) {
  world::Scenario s;
  s.name = "t";
  for (int i = 0; i < regions; ++i) {
    world::Region r;
    r.name = "r" + std::to_string(i + 1);
    r.center = {0.5, 0.5 * i, 0};
    r.size = {0.4, 0.4, 0};  // a default tray (0.24 x 0.16) fits
    r.capacity = cap;
    s.regions.push_back(r);
  }
  for (int i = 0; i < containers; ++i) {
    world::Container c;
    c.name = "t" + std::to_string(i + 1);
    c.position = s.regions[0].center;
    c.capacity = 2;
    s.containers.push_back(c);
  }
  for (int i = 0; i < objects; ++i) {
    world::Object o;
    o.name = "o" + std::to_string(i + 1);
    o.position = s.regions[0].center;
    s.objects.push_back(o);
  }
  return s;
}

world::Placement all_in(const world::Scenario& s, const std::string& loc) {
  world::Placement p;
  for (const auto& o : s.objects) p.set(o.name, loc, o.cls);
  for (const auto& c : s.containers) p.set(c.name, s.regions[0].name, c.cls, true);
  return p;
}

TEST(TransitionSystem, IndexingAndLayout) {
  auto sc = scene(3, 4, 1);
  System ts(sc, all_in(sc, "r1"));
  EXPECT_EQ(ts.num_things(), 5u);
  EXPECT_EQ(ts.num_locations(), 4u);
  EXPECT_EQ(ts.home(), 4u);
  EXPECT_EQ(ts.layout().bits, 3u);  // values 0..4
  EXPECT_EQ(ts.thing_name(4), "t1");
  EXPECT_EQ(ts.location_name(3), "t1");
  EXPECT_TRUE(ts.is_container(4));
  EXPECT_EQ(ts.location_of_container(4), 3u);
  EXPECT_EQ(ts.hand(ts.initial()), ts.home());
  EXPECT_EQ(ts.to_string(ts.initial()), "o1@r1 o2@r1 o3@r1 o4@r1 t1@r1 hand@home");
}

TEST(TransitionSystem, PackingRoundTripsManyThings) {
  // 40 things with 3-bit fields span two words; every field reads back.
  auto sc = scene(5, 40, 0, 64);
  System ts(sc, all_in(sc, "r1"));
  EXPECT_EQ(ts.layout().words, 2u);
  std::mt19937 rng(3);
  State s = ts.initial();
  std::vector<std::uint32_t> want(40);
  for (unsigned t = 0; t < 40; ++t) {
    want[t] = rng() % 5;
    ts.layout().set(s, t, want[t]);
  }
  for (unsigned t = 0; t < 40; ++t) EXPECT_EQ(ts.location(s, t), want[t]);
  EXPECT_EQ(ts.hand(s), ts.home());
  EXPECT_EQ(ts.encode(ts.describe(s), ""), s);
}

TEST(TransitionSystem, TooManyThingsIsAnError) {
  auto sc = scene(5, 100, 0, 200);
  EXPECT_THROW(System(sc, all_in(sc, "r1")), Error);
}

TEST(TransitionSystem, MovesRespectCapacityAndNoNesting) {
  auto sc = scene(2, 3, 1, 3);  // r1 cap 3 (holds o1..o3 + t1: over-full), r2 cap 3, t1 cap 2
  world::Placement p = all_in(sc, "r2");
  p.set("o3", "r1", "block");
  System ts(sc, p);  // r1: o3, t1; r2: o1, o2
  std::set<std::string> names;
  ts.for_each_move(ts.initial(), [&](const Action& a) { names.insert(ts.action_name(a)); });
  const std::set<std::string> want{"move(o1, r1)", "move(o1, t1)", "move(o2, r1)", "move(o2, t1)",
                                   "move(o3, r2)", "move(o3, t1)", "move(t1, r2)"};
  EXPECT_EQ(names, want);
  // Fill r2 to capacity: nothing more may enter it.
  State s = ts.successor(ts.initial(), Action::move(2, 1));  // o3 -> r2: r2 = {o1, o2, o3}
  EXPECT_FALSE(ts.enabled(s, Action::move(3, 1)));           // t1 -> r2: full
  EXPECT_FALSE(ts.enabled(s, Action::move(3, 2)));           // container into a container
  EXPECT_TRUE(ts.enabled(s, Action::stay()));
  EXPECT_TRUE(ts.valid(s));
}

TEST(TransitionSystem, ContainerCarriesContentsAndHandFollows) {
  auto sc = scene(2, 2, 1);
  System ts(sc, all_in(sc, "r1"));
  State s = ts.successor(ts.initial(), Action::move(0, 2));  // o1 -> t1
  EXPECT_EQ(ts.hand(s), 2u);
  s = ts.successor(s, Action::move(2, 1));  // t1 -> r2
  EXPECT_EQ(ts.location(s, 0), 2u);         // still in the tray
  EXPECT_EQ(ts.location(s, 2), 1u);
  EXPECT_EQ(ts.hand(s), 1u);
  // The tray's point is now r2's centre, and so is o1's.
  EXPECT_EQ(ts.thing_point(s, 0), sc.regions[1].center);
  EXPECT_EQ(ts.location_point(s, 2), sc.regions[1].center);
  EXPECT_EQ(ts.successor(s, Action::stay()), s);
}

TEST(TransitionSystem, EncodeRejectsUnknownNamesAndNesting) {
  auto sc = scene(2, 1, 1);
  System ts(sc, all_in(sc, "r1"));
  world::Placement p = all_in(sc, "r1");
  p.set("zz", "r1", "block");
  EXPECT_THROW(ts.encode(p), Error);
  p = all_in(sc, "r1");
  p.set("o1", "r9", "block");
  EXPECT_THROW(ts.encode(p), Error);
  p = all_in(sc, "r1");
  p.set("t1", "t1", "tray", true);
  EXPECT_THROW(ts.encode(p), Error);
  p = all_in(sc, "r1");
  EXPECT_THROW(ts.encode(p, "nowhere"), Error);
  EXPECT_EQ(ts.hand(ts.encode(p, "r2")), 1u);
}

TEST(TransitionSystem, HomePointAboveBase) {
  auto sc = scene(1, 1, 0);
  sc.robot.base = {0.1, 0.2, 0.0};
  System ts(sc, all_in(sc, "r1"));
  EXPECT_EQ(ts.hand_point(ts.initial()), (world::Vec3{0.1, 0.2, kHomeHeight}));
}

}  // namespace
}  // namespace rtamp::task
