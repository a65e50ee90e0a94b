// A user's own C++ world, registered by name (episode/world_registry.hpp) and
// served by `rtamp serve`'s code path (LiveEpisode, Server, a real WebSocket
// client): a world with the intervention capability takes a page's
// intervention — applied, logged like a scripted one, reacted to, the task
// finished with the added thing — and its frames are laid out from what the
// loop perceived (it cannot draw itself); a world without the capability
// refuses the page's intervention with the reason and runs on.
#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <string>

#include "rtamp/episode/world_registry.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/serve/live_episode.hpp"
#include "rtamp/serve/server.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "ws_client.hpp"

namespace rtamp::serve {
namespace {

using test::json;
using test::WsClient;

const char* kScenario = R"yaml(
name: own-world
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.30, 0.30], capacity: 4}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.30, 0.30], capacity: 4}
objects:
  - {name: o1, class: block, position: [0.35, 0.32, 0], size: [0.04, 0.04, 0.04]}
  - {name: o2, class: block, position: [0.45, 0.32, 0], size: [0.04, 0.04, 0.04]}
propositions:
  all_in_r2: "all block in r2"
task: "F G all_in_r2"
)yaml";

// Every thing in a named location; a move takes one second to pick and one to
// carry and place. A person may relocate, add or remove a thing the arm is not
// moving (capacity is the caller's check); nothing else.
class TableWorld : public exec::World, public exec::Intervenable {
 public:
  explicit TableWorld(bool intervenable) : open_(intervenable) {}

  double time() const override { return now_; }
  void advance(double dt) override { now_ += dt; }
  double next_event_time() const override {
    if (status_ != exec::MoveStatus::Running) return std::numeric_limits<double>::infinity();
    return now_ < started_ + 1.0 ? started_ + 1.0 : started_ + 2.0;
  }
  world::Placement observe() override { return true_placement(); }
  void start(const exec::Move& m) override {
    move_ = m;
    started_ = now_;
    status_ = exec::MoveStatus::Running;
  }
  exec::MoveStatus poll(std::string* why) override {
    settle();
    if (status_ == exec::MoveStatus::Failed && why) *why = "halted";
    return status_;
  }
  void halt() override {
    if (status_ == exec::MoveStatus::Running) status_ = exec::MoveStatus::Failed;
  }
  bool busy() override { return false; }
  std::string hand() const override { return hand_; }
  std::vector<exec::WorldEvent> take_events() override { return std::exchange(events_, {}); }
  exec::Intervenable* intervenable() override { return open_ ? this : nullptr; }

  world::Placement true_placement() override {
    settle();
    world::Placement p;
    for (const auto& [thing, location] : where_) p.set(thing, location, "block");
    if (status_ == exec::MoveStatus::Running && now_ >= started_ + 1.0) p.set(move_.thing, "hand", "block");
    return p;
  }
  exec::WorldEvent apply(const world::Intervention& iv) override {
    exec::WorldEvent e{now_, iv, false, ""};
    using K = world::Intervention::Kind;
    const bool moving = status_ == exec::MoveStatus::Running && iv.subject == move_.thing;
    if (moving) {
      e.detail = "the arm is moving " + iv.subject;
    } else if (iv.kind == K::Add && !where_.count(iv.subject)) {
      where_[iv.subject] = iv.location;
      e.applied = true;
    } else if (iv.kind == K::Relocate && where_.count(iv.subject)) {
      where_[iv.subject] = iv.location;
      e.applied = true;
    } else if (iv.kind == K::Remove && where_.erase(iv.subject)) {
      e.applied = true;
    } else {
      e.detail = std::string("this world cannot ") + world::to_string(iv.kind) + " " + iv.subject;
    }
    if (e.applied) e.detail = iv.location;
    events_.push_back(e);
    return e;
  }

 private:
  void settle() {
    if (status_ != exec::MoveStatus::Running || now_ < started_ + 2.0) return;
    where_[move_.thing] = move_.to;
    hand_ = move_.to;
    status_ = exec::MoveStatus::Succeeded;
  }

  bool open_;
  double now_ = 0, started_ = 0;
  std::map<std::string, std::string> where_{{"o1", "r1"}, {"o2", "r1"}};
  std::string hand_;
  exec::Move move_;
  exec::MoveStatus status_ = exec::MoveStatus::Idle;
  std::vector<exec::WorldEvent> events_;
};

void register_table_worlds() {
  episode::register_world({"table", "a table of named locations (tests)",
                           [](const world::Scenario&, std::uint64_t, const episode::WorldSettings&) {
                             return std::make_unique<TableWorld>(true);
                           },
                           exec::PlanningMode::Inline});
  episode::register_world({"table-closed", "the same, without the intervention capability (tests)",
                           [](const world::Scenario&, std::uint64_t, const episode::WorldSettings&) {
                             return std::make_unique<TableWorld>(false);
                           },
                           exec::PlanningMode::Inline});
}

LiveOptions table_options(const std::string& world) {
  LiveOptions o;
  o.episode.world = world;
  o.episode.loop.planning = episode::find_world(world).planning;
  o.episode.loop.max_time = 120;
  o.paused = true;
  o.speed = 20;
  return o;
}

struct Served {
  LiveEpisode episode;
  Server server;
  Served(const world::Scenario& s, LiveOptions o)
      : episode(s, std::move(o)), server(ServerOptions{"127.0.0.1", 0, ""}, episode) {
    server.start();
    episode.start();
  }
  ~Served() {
    episode.stop();
    episode.wait();
  }
};

TEST(ServeOwnWorld, APageInterventionIsAppliedThroughTheWorldsCapability) {
  register_table_worlds();
  const world::Scenario s = world::parse_scenario(kScenario, "own_world_test");
  Served sv(s, table_options("table"));
  WsClient c(sv.server.port());
  const auto hello = c.read();
  ASSERT_TRUE(hello);
  EXPECT_EQ((*hello)["world"], "table");
  // A block added to r1 while paused: the task ("all blocks in r2") now needs it moved too.
  c.send(json{{"type", "intervene"}, {"id", 1}, {"kind", "add"}, {"class", "block"}, {"location", "r1"}});
  const auto r = c.reply(1);
  ASSERT_TRUE(r);
  ASSERT_TRUE((*r)["ok"]) << r->dump();
  const std::string added = (*r)["subject"];
  c.send(json{{"type", "control"}, {"id", 2}, {"action", "resume"}});
  ASSERT_TRUE(c.reply(2));
  // A frame laid out from the loop's perception shows the added block.
  const auto frame = c.read_until([&](const json& m) {
    if (m["type"] != "frame") return false;
    for (const auto& t : m["things"])
      if (t["name"] == added) return true;
    return false;
  });
  ASSERT_TRUE(frame);
  EXPECT_EQ((*frame)["q"].size(), 6u);  // solved for its tool point (serve/arm_angles.hpp)
  const exec::EpisodeMetrics m = sv.episode.wait();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions_applied, 1);
  EXPECT_EQ(m.actions_succeeded, 3) << "o1, o2 and the added block each moved to r2 once";
  bool logged = false;
  for (const auto& msg : c.seen)
    if (msg["type"] == "log" && msg["record"]["ev"] == "intervention" && msg["record"]["subject"] == added)
      logged = msg["record"]["applied"] == true;
  if (!logged)
    logged = c.read_until([&](const json& msg) {
      return msg["type"] == "log" && msg["record"]["ev"] == "intervention" && msg["record"]["subject"] == added;
    }).has_value();
  EXPECT_TRUE(logged);
}

TEST(ServeOwnWorld, AWorldWithoutTheCapabilityRefusesPageInterventions) {
  register_table_worlds();
  const world::Scenario s = world::parse_scenario(kScenario, "own_world_test");
  Served sv(s, table_options("table-closed"));
  WsClient c(sv.server.port());
  ASSERT_TRUE(c.read());
  c.send(json{{"type", "intervene"}, {"id", 1}, {"kind", "add"}, {"class", "block"}, {"location", "r1"}});
  const auto r = c.reply(1);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("takes no interventions"), std::string::npos) << r->dump();
  c.send(json{{"type", "control"}, {"id", 2}, {"action", "resume"}});
  ASSERT_TRUE(c.reply(2));
  const exec::EpisodeMetrics m = sv.episode.wait();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions, 0);
  EXPECT_EQ(m.actions_succeeded, 2);
}

}  // namespace
}  // namespace rtamp::serve
