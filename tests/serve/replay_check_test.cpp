// `rtamp serve --replay` holds up (docs/serve.md "Replay", docs/formats.md
// "Episode logs"): the logs rtamp writes (served, with frame records, and run)
// pass the check; each way of breaking one — a line nested or sized beyond the
// limits, no or two `episode` records, an `end` mid-log, a frame with three
// joint angles or an unknown thing, a plan moving an unknown thing, records out
// of time order — is refused with the line it is on, before anything is served;
// a served log with a page's interventions (refused by the world, applied) replays.
// Playing: a step while paused plays the next record; speed changes while paused; a seek back while
// playing sticks (the frames go on from the seek, not from before it).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "rtamp/episode/episode.hpp"
#include "rtamp/serve/live_episode.hpp"
#include "rtamp/episode/log_check.hpp"
#include "rtamp/serve/replay.hpp"
#include "rtamp/serve/server.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "ws_client.hpp"

namespace rtamp::serve {
namespace {

using test::json;
using test::WsClient;
namespace fs = std::filesystem;

class ReplayCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rtamp_replay_check_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    episode::EpisodeOptions o;
    o.world = "symbolic";
    o.loop.planning = exec::PlanningMode::Inline;
    o.seed = 7;
    o.loop.max_time = 300;
    o.outputs.log = (dir_ / "served.jsonl").string();
    LiveOptions lo;
    lo.episode = o;
    lo.speed = 0;
    {
      LiveEpisode live(scenario(), lo);
      live.start();
      ASSERT_TRUE(live.wait().success);
    }
    o.outputs.log = (dir_ / "run.jsonl").string();
    ASSERT_TRUE(episode::run_episode(scenario(), o).success);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static const world::Scenario& scenario() {
    static const world::Scenario s = world::load_scenario("3-block-tray");
    return s;
  }
  static std::vector<std::string> lines(const std::string& name) {
    std::vector<std::string> v;
    std::ifstream in(dir_ / name);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
  }
  static std::string write(const std::string& name, const std::vector<std::string>& ls) {
    const fs::path p = dir_ / name;
    std::ofstream out(p);
    for (const auto& l : ls) out << l << '\n';
    return p.string();
  }
  // The index of the first line whose record is of kind `ev`.
  static std::size_t first(const std::vector<std::string>& ls, const std::string& ev) {
    for (std::size_t i = 0; i < ls.size(); ++i)
      if (json::parse(ls[i])["ev"] == ev) return i;
    ADD_FAILURE() << "no " << ev << " record";
    return 0;
  }
  // The error replaying `ls` gives ("" if it is accepted).
  static std::string refusal(const std::string& name, const std::vector<std::string>& ls) {
    const std::string p = write(name, ls);
    try {
      Replay r(scenario(), p);
    } catch (const Error& e) {
      return e.message();
    }
    return "";
  }
  static void expect_refused(const std::string& name, const std::vector<std::string>& ls, std::size_t line,
                             const std::string& why) {
    const std::string e = refusal(name, ls);
    const std::string where = "--replay: " + (dir_ / name).string() + ":" + std::to_string(line) + ": ";
    EXPECT_EQ(e.rfind(where, 0), 0u) << name << ": '" << e << "' does not start with '" << where << "'";
    EXPECT_NE(e.find(why), std::string::npos) << name << ": '" << e << "' lacks '" << why << "'";
  }

  static inline fs::path dir_;
};

TEST_F(ReplayCheck, TheLogsRtampWritesPass) {
  for (const char* name : {"served.jsonl", "run.jsonl"}) {
    EXPECT_EQ(refusal(std::string("copy_") + name, lines(name)), "") << name;
  }
  bool frames = false;
  for (const auto& l : lines("served.jsonl")) frames = frames || json::parse(l)["ev"] == "frame";
  EXPECT_TRUE(frames);
}

TEST_F(ReplayCheck, LinesBeyondTheLimitsAreRefusedWithTheirLine) {
  auto ls = lines("run.jsonl");
  ls.insert(ls.begin() + 2, std::string(100000, '[') + std::string(100000, ']'));
  expect_refused("deep.jsonl", ls, 3, "nested deeper than 16 levels");
  // Brackets inside strings do not count.
  ls = lines("run.jsonl");
  json r = json::parse(ls[1]);
  r["why"] = std::string(100, '[');
  r["ev"] = "replan";
  ls[1] = r.dump();
  EXPECT_EQ(refusal("brackets.jsonl", ls), "");
  ls[1] = std::string("{\"ev\":\"replan\",\"why\":\"") + std::string(episode::kMaxLineBytes, 'x') + "\",\"t\":0}";
  expect_refused("long.jsonl", ls, 2, "a line longer than 8 MiB");
}

TEST_F(ReplayCheck, BrokenLogsAreRefusedWithTheirLine) {
  const auto served = lines("served.jsonl");
  const auto run = lines("run.jsonl");
  {  // no episode record
    auto ls = run;
    ls.erase(ls.begin());
    expect_refused("no_episode.jsonl", ls, 1, "not `episode`");
  }
  {  // two
    auto ls = run;
    ls.insert(ls.begin() + 3, ls[0]);
    expect_refused("two_episodes.jsonl", ls, 4, "a second `episode` record");
  }
  {  // the end mid-log: the record after it is refused
    auto ls = run;
    const std::string end = ls.back();
    ls.pop_back();
    json e = json::parse(end);
    e["t"] = json::parse(ls[4])["t"];
    ls.insert(ls.begin() + 5, e.dump());
    expect_refused("end_mid_log.jsonl", ls, 7, "after the `end` record");
  }
  {  // no end
    auto ls = run;
    ls.pop_back();
    const std::string e = refusal("no_end.jsonl", ls);
    EXPECT_NE(e.find("no `end` record"), std::string::npos) << e;
  }
  // The first record of kind `ev` changed by `edit`: refused at its line with `why`.
  auto edited = [](const char* name, std::vector<std::string> ls, const std::string& ev,
                   const std::function<void(json&)>& edit, const std::string& why) {
    const std::size_t i = first(ls, ev);
    json r = json::parse(ls[i]);
    edit(r);
    ls[i] = r.dump();
    expect_refused(name, ls, i + 1, why);
  };
  edited("three_angles.jsonl", served, "frame", [](json& f) { f["q"] = {0.1, 0.2, 0.3}; }, "\"q\" must be 6 numbers");
  edited("unknown_thing.jsonl", served, "frame", [](json& f) { f["things"][0]["name"] = "o99"; },
         "no thing 'o99' exists here");
  edited("plan_unknown.jsonl", run, "plan", [](json& p) { p["actions"][0] = "move(unicorn, r2)"; },
         "no thing 'unicorn' exists here");
  edited("plan_nowhere.jsonl", run, "plan", [](json& p) { p["actions"][0] = "move(o1, r9)"; },
         "no location 'r9' exists here");
  edited("type.jsonl", run, "tree", [](json& t) { t["applied"] = "yes"; }, "\"applied\" must be true or false");
  edited("episode_automaton.jsonl", run, "episode", [](json& e) { e["automaton"] = "F G p"; },
         "\"automaton\" must be an object");
  edited("episode_edges.jsonl", run, "episode", [](json& e) { e["automaton"].erase("edges"); },
         "`episode` record: \"edges\" is missing");
  {  // a log written before the episode record carried its automaton passes
    auto ls = run;
    json e = json::parse(ls[0]);
    ASSERT_TRUE(e.contains("automaton"));
    e.erase("automaton");
    e.erase("automaton_states");
    ls[0] = e.dump();
    EXPECT_EQ(refusal("episode_old.jsonl", ls), "");
  }
  {  // a camera record (MuJoCo with --perception camera): its belief's own names pass, a state not
     // of the belief and a position of two numbers do not
    auto ls = run;
    json cam = json::parse(
        R"({"ev":"camera","camera":"overhead","detections":[{"class":"block","at":[0.4,0.32,0],"yaw":0,"complete":true}],)"
        R"("things":[{"name":"block_seen1","class":"block","state":"visible","at":[0.4,0.32,0]}]})");
    cam["t"] = json::parse(ls[1])["t"];
    ls.insert(ls.begin() + 2, cam.dump());
    EXPECT_EQ(refusal("camera.jsonl", ls), "");
    cam["things"][0]["state"] = "gone";
    ls[2] = cam.dump();
    expect_refused("camera_state.jsonl", ls, 3, "is not a belief state");
    cam["things"][0]["state"] = "occluded";
    cam["detections"][0]["at"] = {0.4, 0.32};
    ls[2] = cam.dump();
    expect_refused("camera_at.jsonl", ls, 3, "\"at\" must be 3 numbers");
  }
  {  // an unknown kind, out of time order
    auto ls = run;
    ls[2] = R"({"ev":"teleport","t":0})";
    expect_refused("kind.jsonl", ls, 3, "unknown record kind 'teleport'");
    ls = run;
    json late = json::parse(ls[1]);
    late["t"] = 1e6;
    ls[1] = late.dump();
    expect_refused("order.jsonl", ls, 3, "out of time order");
  }
}

// A served episode started paused, planning on a worker (as with MuJoCo): its
// first plan is made before anything is resumed or stepped (docs/serve.md
// `--paused`); a block moved from the page while paused, a few steps, then
// resumed: the log's records are in time order (the intervention's record has
// the time it was applied, not before the plan's) and the log replays.
TEST_F(ReplayCheck, APausedEpisodePlansAndAnInterventionKeepsTheLogInTimeOrder) {
  LiveOptions o;
  o.episode.world = "symbolic";
  o.episode.loop.planning = exec::PlanningMode::Worker;
  o.episode.seed = 7;
  o.episode.loop.max_time = 300;
  o.episode.outputs.log = (dir_ / "paused.jsonl").string();
  o.speed = 0;
  o.paused = true;
  {
    LiveEpisode live(scenario(), o);
    Server server({"127.0.0.1", 0, ""}, live);
    server.start();
    live.start();
    WsClient c(server.port());
    const auto hello = c.read();
    ASSERT_TRUE(hello);
    bool planned = false;
    for (const auto& rec : (*hello)["history"]) planned = planned || rec["ev"] == "plan";
    if (!planned) {
      ASSERT_TRUE(c.read_until([](const json& m) { return m["type"] == "log" && m["record"]["ev"] == "plan"; }));
    }
    c.send(json{{"type", "intervene"}, {"id", 100}, {"kind", "relocate"}, {"subject", "o3"}, {"location", "r2"}});
    const auto r = c.reply(100);
    ASSERT_TRUE(r);
    EXPECT_TRUE((*r)["ok"]) << *r;
    for (int i = 0; i < 6; ++i) {
      c.send(json{{"type", "control"}, {"id", i + 1}, {"action", "step"}});
      ASSERT_TRUE(c.reply(i + 1));
    }
    c.send(json{{"type", "control"}, {"id", 101}, {"action", "resume"}});
    ASSERT_TRUE(c.reply(101));
    live.wait();
    server.stop();
  }
  const auto ls = lines("paused.jsonl");
  double t = 0;
  bool intervened = false;
  for (std::size_t i = 0; i < ls.size(); ++i) {
    const json r = json::parse(ls[i]);
    EXPECT_GE(r["t"].get<double>(), t) << "line " << i + 1 << ": " << ls[i];
    t = r["t"].get<double>();
    intervened = intervened || r["ev"] == "intervention";
  }
  EXPECT_TRUE(intervened);
  EXPECT_EQ(refusal("paused_copy.jsonl", ls), "");
}

// `serve --log X` then `serve --replay X`: interventions from a page are
// logged at the time they took effect, also one the world refuses (an add
// into r1, full at the start) sent while paused and one applied mid-episode,
// before the frame records of the world time that passed after them: the log
// is in time order and replays, with both interventions in it.
TEST_F(ReplayCheck, APagesInterventionsAreLoggedWhenTheyTookEffectAndTheLogReplays) {
  const fs::path log = dir_ / "page.jsonl";
  LiveOptions o;
  o.episode.world = "symbolic";
  o.episode.loop.planning = exec::PlanningMode::Inline;
  o.episode.seed = 7;
  o.episode.loop.max_time = 300;
  o.episode.scripted_operator = false;
  o.episode.outputs.log = log.string();
  o.speed = 0;
  o.paused = true;
  std::string moved;
  {
    LiveEpisode live(scenario(), o);
    Server server({"127.0.0.1", 0, ""}, live);
    server.start();
    live.start();
    WsClient c(server.port());
    ASSERT_TRUE(c.read());
    c.send(json{{"type", "intervene"}, {"id", 1}, {"kind", "add"}, {"class", "block"}, {"location", "r1"}});
    const auto refused = c.reply(1);
    ASSERT_TRUE(refused);
    EXPECT_FALSE((*refused)["ok"]);
    EXPECT_NE((*refused)["error"].get<std::string>().find("refused by the world"), std::string::npos) << *refused;
    c.send(json{{"type", "control"}, {"id", 2}, {"action", "speed"}, {"value", 20}});
    ASSERT_TRUE(c.reply(2));
    c.send(json{{"type", "control"}, {"id", 3}, {"action", "resume"}});
    ASSERT_TRUE(c.reply(3));
    const auto finished = c.read_until([](const json& m) {
      return m["type"] == "log" && m["record"]["ev"] == "action" && m["record"]["what"] == "finished";
    });
    ASSERT_TRUE(finished);
    const std::string action = (*finished)["record"]["action"];
    moved = action.substr(5, action.find(',') - 5);  // "move(o2, r3)": back to r1
    c.send(json{{"type", "intervene"}, {"id", 4}, {"kind", "relocate"}, {"subject", moved}, {"location", "r1"}});
    const auto applied = c.reply(4);
    ASSERT_TRUE(applied);
    EXPECT_TRUE((*applied)["ok"]) << *applied;
    c.send(json{{"type", "control"}, {"id", 5}, {"action", "speed"}, {"value", 0}});
    ASSERT_TRUE(c.reply(5));
    EXPECT_TRUE(live.wait().success);
    server.stop();
  }
  const auto ls = lines("page.jsonl");
  double t = 0;
  int interventions = 0, frames = 0;
  for (std::size_t i = 0; i < ls.size(); ++i) {
    const json r = json::parse(ls[i]);
    EXPECT_GE(r["t"].get<double>(), t) << "line " << i + 1 << ": " << ls[i];
    t = std::max(t, r["t"].get<double>());
    frames += r["ev"] == "frame";
    if (r["ev"] != "intervention") continue;
    ++interventions;
    EXPECT_EQ(r["applied"], r["kind"] == "relocate") << ls[i];
    if (r["kind"] == "relocate") {
      EXPECT_EQ(r["subject"], moved);
    }
  }
  EXPECT_EQ(interventions, 2);
  EXPECT_GT(frames, 2);
  EXPECT_EQ(refusal("page_copy.jsonl", ls), "");
  // Replayed to its end (as fast as it goes), the page's history has both.
  ReplayOptions ro;
  ro.speed = 0;
  Replay replay(scenario(), log.string(), ro);
  replay.start();
  for (int i = 0; i < 60000 && !replay.ended(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(replay.ended());
  replay.stop();
  const json hello = json::parse(replay.hub().hello());
  int seen = 0;
  for (const json& r : hello["history"]) seen += r["ev"] == "intervention";
  EXPECT_EQ(seen, 2);
}

TEST_F(ReplayCheck, StepPlaysTheNextRecordAndASeekBackSticks) {
  ReplayOptions ro;
  ro.speed = 1;
  ro.paused = true;
  Replay replay(scenario(), (dir_ / "served.jsonl").string(), ro);
  Server server({"127.0.0.1", 0, ""}, replay);
  server.start();
  replay.start();
  WsClient c(server.port());
  ASSERT_TRUE(c.read());
  // Paused, nothing plays; a step plays the first record (the log's `episode`).
  c.send(json{{"type", "control"}, {"id", 1}, {"action", "step"}});
  const auto log = c.read_until([](const json& m) { return m["type"] == "log"; });
  ASSERT_TRUE(log);
  EXPECT_EQ((*log)["record"]["ev"], "episode") << *log;
  c.send(json{{"type", "control"}, {"id", 2}, {"action", "speed"}, {"value", 4}});
  const auto st = c.read_until([](const json& m) { return m["type"] == "state" && m["speed"] == 4; });
  ASSERT_TRUE(st);
  EXPECT_TRUE((*st)["paused"]);
  // Play to t > 6, seek back to 1: the frames after the new hello go on from 1.
  c.send(json{{"type", "control"}, {"id", 3}, {"action", "resume"}});
  ASSERT_TRUE(c.read_until([](const json& m) { return m["type"] == "frame" && m["t"].get<double>() > 6; }));
  c.send(json{{"type", "control"}, {"id", 4}, {"action", "seek"}, {"value", 1.0}});
  ASSERT_TRUE(c.read_until([](const json& m) { return m["type"] == "hello"; }));
  for (int k = 0; k < 5; ++k) {
    const auto f = c.read_until([](const json& m) { return m["type"] == "frame"; });
    ASSERT_TRUE(f);
    EXPECT_LT((*f)["t"].get<double>(), 5.0) << "frame " << k << " after the seek snapped forward: " << *f;
  }
  replay.stop();
  server.stop();
}

}  // namespace
}  // namespace rtamp::serve
