// The built-in scenarios: embedded text equals the files in scenarios/, they
// load by name, match the paper's Section V set-ups, stay within the UR5's
// reach, and in 3-block-tray carrying the blocks on the tray is cheaper than
// three separate trips under the euclidean cost |p_hand - p_obj| + |p_obj - p_dest|.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/compare.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::world {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string repo_file(const std::string& name) { return std::string(RTAMP_SOURCE_DIR) + "/scenarios/" + name + ".yaml"; }

TEST(Builtins, EmbeddedTextEqualsTheFiles) {
  const std::vector<std::string> names = builtin_scenario_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "3-block"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "3-block-tray"), names.end());
  for (const std::string& n : names) {
    const auto text = builtin_scenario_text(n);
    ASSERT_TRUE(text.has_value()) << n;
    EXPECT_EQ(std::string(*text), read_file(repo_file(n))) << n << ": rebuild to re-embed scenarios/" << n << ".yaml";
  }
  EXPECT_FALSE(builtin_scenario_text("no-such-scenario").has_value());
}

TEST(Builtins, LoadByNameEqualsLoadByPath) {
  for (const std::string& n : builtin_scenario_names()) {
    const Scenario by_name = load_scenario(n);
    const Scenario by_path = load_scenario(repo_file(n));
    EXPECT_EQ(first_difference(by_name, by_path), "") << n;
    EXPECT_EQ(by_name.name, n);
    EXPECT_EQ(by_path.source, repo_file(n));
  }
}

TEST(Builtins, UnknownNameSaysWhatExists) {
  try {
    load_scenario("3-blok");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("no built-in scenario"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find("3-block-tray"), std::string::npos) << e.what();
  }
}

double dist_xy(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }
double dist(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Every corner of a footprint within the UR5's reach and no point of it
// nearer than 0.25 m to the base axis.
void expect_reachable(const Footprint& f, const Vec3& base, const std::string& what) {
  for (double x : {f.min_x(), f.max_x()})
    for (double y : {f.min_y(), f.max_y()}) EXPECT_LE(dist_xy({x, y, 0}, base), 0.80) << what;
  const double cx = std::clamp(base[0], f.min_x(), f.max_x()), cy = std::clamp(base[1], f.min_y(), f.max_y());
  EXPECT_GE(dist_xy({cx, cy, 0}, base), 0.25) << what;
}

void expect_all_reachable(const Scenario& s) {
  for (const Region& r : s.regions) expect_reachable(footprint(r), s.robot.base, s.name + " region " + r.name);
  for (const Container& c : s.containers) expect_reachable(footprint(c), s.robot.base, s.name + " container " + c.name);
  for (const Object& o : s.objects) expect_reachable(footprint(o), s.robot.base, s.name + " object " + o.name);
}

TEST(Builtins, ThreeBlock) {
  const Scenario s = load_scenario("3-block");
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.regions[0].name, "r1");
  EXPECT_EQ(s.regions[1].name, "r2");
  EXPECT_TRUE(s.containers.empty());
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.robot.model, "ur5");
  EXPECT_EQ(s.robot.base, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.task, "F G all_in_r2");
  ASSERT_EQ(s.propositions.size(), 1u);
  EXPECT_EQ(s.propositions[0].name, "all_in_r2");
  EXPECT_EQ(to_string(s.propositions[0].expr), "all block in r2");
  const Placement p = initial_placement(s);
  for (const char* o : {"o1", "o2", "o3"}) EXPECT_EQ(*p.location_of(o), "r1") << o;
  EXPECT_FALSE(evaluate(s.propositions[0].expr, p));
  Placement done = p;
  for (const char* o : {"o1", "o2", "o3"}) done.set(o, "r2", "block");
  EXPECT_TRUE(evaluate(s.propositions[0].expr, done));
  // Regions between 0.3 and 0.7 m from the base (centres), all within reach.
  for (const Region& r : s.regions) {
    EXPECT_GE(dist_xy(r.center, s.robot.base), 0.3);
    EXPECT_LE(dist_xy(r.center, s.robot.base), 0.7);
  }
  expect_all_reachable(s);
  EXPECT_TRUE(s.interventions.empty());
}

// Cost of a sequence of moves (thing, destination) under the euclidean cost,
// with destinations at location centres; things on a tray ride along with it.
double plan_cost(const Scenario& s, const std::vector<std::pair<std::string, std::string>>& moves, Vec3 hand) {
  std::map<std::string, Vec3> pos;
  std::map<std::string, std::string> loc;
  const Placement start = initial_placement(s);
  for (const Object& o : s.objects) pos[o.name] = o.position;
  for (const Container& c : s.containers) pos[c.name] = c.position;
  for (const auto& [n, t] : start.things) loc[n] = t.location;
  std::map<std::string, Vec3> centre;
  for (const Region& r : s.regions) centre[r.name] = r.center;
  double cost = 0;
  for (const auto& [thing, dest] : moves) {
    const Vec3 d = centre.count(dest) ? centre[dest] : pos[dest];
    cost += dist(hand, pos[thing]) + dist(pos[thing], d);
    for (auto& [n, l] : loc)  // contents of a moved container move with it
      if (l == thing) pos[n] = d;
    pos[thing] = d;
    loc[thing] = dest;
    hand = d;
  }
  return cost;
}

TEST(Builtins, ThreeBlockTray) {
  const Scenario s = load_scenario("3-block-tray");
  ASSERT_EQ(s.containers.size(), 1u);
  const Container& tray = s.containers[0];
  EXPECT_EQ(tray.name, "r3");
  EXPECT_EQ(tray.cls, "tray");
  EXPECT_EQ(tray.capacity, 3);
  const Placement p = initial_placement(s);
  EXPECT_EQ(*p.location_of("r3"), "r1");  // the tray stands near the blocks
  for (const char* o : {"o1", "o2", "o3"}) EXPECT_EQ(*p.location_of(o), "r1") << o;
  EXPECT_GE(dist_xy(s.find_region("r1")->center, s.find_region("r2")->center), 0.6);
  expect_all_reachable(s);

  // Same regions and blocks as 3-block.
  const Scenario plain = load_scenario("3-block");
  ASSERT_EQ(plain.regions.size(), s.regions.size());
  for (std::size_t i = 0; i < s.regions.size(); ++i) EXPECT_EQ(plain.regions[i].center, s.regions[i].center);
  for (std::size_t i = 0; i < s.objects.size(); ++i) EXPECT_EQ(plain.objects[i].position, s.objects[i].position);

  const Vec3 home = s.robot.base;
  const double trips = plan_cost(s, {{"o1", "r2"}, {"o2", "r2"}, {"o3", "r2"}}, home);
  const double tray_plan = plan_cost(
      s, {{"o1", "r3"}, {"o2", "r3"}, {"o3", "r3"}, {"r3", "r2"}, {"o1", "r2"}, {"o2", "r2"}, {"o3", "r2"}}, home);
  EXPECT_LT(tray_plan + 1.0, trips) << "tray " << tray_plan << " vs trips " << trips;

  // The scripted operator: a block goes back to r1 at about 20 s.
  ASSERT_EQ(s.interventions.size(), 1u);
  const Intervention& iv = s.interventions[0];
  EXPECT_EQ(iv.kind, Intervention::Kind::Relocate);
  EXPECT_DOUBLE_EQ(iv.time, 20.0);
  EXPECT_EQ(iv.location, "r1");
  ASSERT_TRUE(iv.position.has_value());
  EXPECT_EQ(Geometry(s).locate(*iv.position), "r1");
}

}  // namespace
}  // namespace rtamp::world
