// Tests of `rtamp serve`'s server (serve/server.hpp, client_session.hpp,
// live_episode.hpp, replay.hpp) with real WebSocket clients (Boost.Beast) on
// the symbolic world, whose episodes are deterministic: hostile clients must
// not change an episode's end metrics (the oracle is run_episode, what `rtamp
// run --world symbolic` runs, with the same seed); an intervention sent over
// the WebSocket is applied, logged like a scripted one and reacted to within
// one step; a refused one says why; only loopback is bound by default; a
// replay reaches the logged end state and seeks; a MuJoCo episode with camera
// perception (built on this thread, rendered on the loop's) sends its camera images,
// at most 5 a second, the latest to a page that joins late; a page that joins
// an episode nobody watched gets the present (hello's time and first frame, the
// tree's statuses); the tree's statuses are final at the end, logged, and
// replayed at the time shown.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include <boost/asio/ip/udp.hpp>
#include <boost/beast/http.hpp>

#include "rtamp/episode/episode.hpp"
#include "rtamp/serve/live_episode.hpp"
#include "rtamp/serve/replay.hpp"
#include "rtamp/serve/server.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "served_episode.hpp"
#include "ws_client.hpp"

namespace rtamp::serve {
namespace {

using test::json;
using test::Served;
using test::symbolic_options;
using test::temp_dir;
using test::WsClient;
namespace fs = std::filesystem;

std::vector<json> read_log(const fs::path& p) {
  std::vector<json> v;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) v.push_back(json::parse(line));
  return v;
}

void expect_same_metrics(const exec::EpisodeMetrics& a, const exec::EpisodeMetrics& b) {
  EXPECT_EQ(a.success, b.success);
  EXPECT_EQ(a.end, b.end);
  EXPECT_EQ(a.reason, b.reason);
  ASSERT_EQ(a.completion_time.has_value(), b.completion_time.has_value());
  if (a.completion_time) {
    EXPECT_NEAR(*a.completion_time, *b.completion_time, 1e-9);
  }
  EXPECT_NEAR(a.motion_cost, b.motion_cost, 1e-9);
  EXPECT_EQ(a.replans, b.replans);
  EXPECT_EQ(a.tree_changes, b.tree_changes);
  EXPECT_EQ(a.interventions, b.interventions);
  EXPECT_EQ(a.interventions_applied, b.interventions_applied);
  EXPECT_EQ(a.actions_succeeded, b.actions_succeeded);
  EXPECT_EQ(a.actions_failed, b.actions_failed);
  EXPECT_EQ(a.run_length, b.run_length);
  EXPECT_NEAR(a.world_time, b.world_time, 1e-9);
}

TEST(ServeServer, HelloDescribesTheSceneAndTheApiServesIt) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode = symbolic_options();
  o.paused = true;
  Served sv(s, o);
  WsClient c(sv.port());
  const auto hello = c.read();
  ASSERT_TRUE(hello);
  EXPECT_EQ((*hello)["type"], "hello");
  EXPECT_EQ((*hello)["mode"], "live");
  EXPECT_EQ((*hello)["world"], "symbolic");
  EXPECT_EQ((*hello)["task"], s.task);
  std::set<std::string> names;
  for (const auto& t : (*hello)["scene"]["things"]) names.insert(t["name"].get<std::string>());
  EXPECT_EQ(names, (std::set<std::string>{"o1", "o2", "o3", "r3"}));
  EXPECT_EQ((*hello)["scene"]["regions"].size(), 2u);
  EXPECT_EQ((*hello)["scene"]["robot"]["dh"]["d"].size(), 6u);
  EXPECT_GE((*hello)["automaton"]["states"].size(), 1u);
  // A frame follows the hello: every present thing, and joint angles (solved for the
  // symbolic world's tool point: serve/arm_angles.hpp; ServeArmAngles checks them).
  const auto frame = c.read_until([](const json& m) { return m["type"] == "frame"; });
  ASSERT_TRUE(frame);
  EXPECT_EQ((*frame)["q"].size(), 6u);
  EXPECT_EQ((*frame)["things"].size(), 4u);

  // GET /api/hello: the same hello.
  namespace http = boost::beast::http;
  const test::HttpAnswer res = test::http_request(sv.port(), http::verb::get, "/api/hello");
  EXPECT_EQ(res.status, 200);
  const json api = json::parse(res.body);
  EXPECT_EQ(api["type"], "hello");
  EXPECT_EQ(api["scene"], (*hello)["scene"]);
  // A path outside the page, and a POST, are refused.
  EXPECT_EQ(test::http_request(sv.port(), http::verb::get, "/../../etc/passwd").status, 404);
  EXPECT_EQ(test::http_request(sv.port(), http::verb::post, "/api/hello").status, 405);
}

// A non-loopback address of this machine (the source address of a route out), or "".
std::string non_loopback_address() {
  try {
    test::net::io_context ioc;
    test::net::ip::udp::socket u(ioc);
    u.connect(test::net::ip::udp::endpoint(test::net::ip::make_address("192.0.2.1"), 9));  // sends nothing
    const auto a = u.local_endpoint().address();
    if (!a.is_loopback() && !a.is_unspecified()) return a.to_string();
  } catch (const std::exception&) {
  }
  return "";
}

// A base64 PNG's width and height, from its IHDR chunk (0, 0 if it is not a PNG).
std::pair<int, int> png_size(const std::string& b64) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  unsigned v = 0;
  int bits = 0;
  for (std::size_t i = 0; i < b64.size() && bytes.size() < 24; ++i) {
    v = v << 6 | static_cast<unsigned>(alphabet.find(b64[i]));
    if ((bits += 6) >= 8) bytes += static_cast<char>(v >> (bits -= 8) & 0xff);
  }
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || bytes.compare(12, 4, "IHDR") != 0) return {0, 0};
  const auto be32 = [&](std::size_t at) {
    int n = 0;
    for (std::size_t k = 0; k < 4; ++k) n = n << 8 | static_cast<unsigned char>(bytes[at + k]);
    return n;
  };
  return {be32(16), be32(20)};
}

TEST(ServeServer, CameraImagesComeFromTheLoopThreadAtMostFiveASecond) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode.world_settings.perception = "camera";
  o.episode.loop.max_time = 300;
  Served sv(s, o);  // the episode (and its EGL contexts) made on this thread, run on another
  WsClient c(sv.port());
  const auto is_camera = [](const json& m) { return m.value("type", "") == "camera"; };
  const auto first = c.read_until(is_camera, std::chrono::seconds(30));
  ASSERT_TRUE(first) << "no camera message";
  EXPECT_EQ((*first)["camera"], "overhead");
  const int width = (*first)["width"], height = (*first)["height"];
  EXPECT_EQ(png_size((*first)["png"]), std::make_pair(width, height));
  EXPECT_EQ(std::make_pair(width, height), std::make_pair(640, 480));
  ASSERT_GE((*first)["boxes"].size(), 3u);
  for (const json& b : (*first)["boxes"]) {
    EXPECT_GE(b["x0"].get<double>(), 0);
    EXPECT_LT(b["x0"].get<double>(), b["x1"].get<double>());
    EXPECT_LE(b["x1"].get<double>(), width);
    EXPECT_GE(b["y0"].get<double>(), 0);
    EXPECT_LT(b["y0"].get<double>(), b["y1"].get<double>());
    EXPECT_LE(b["y1"].get<double>(), height);
    EXPECT_EQ(b["label"], (b["name"].get<std::string>().empty() ? b["cls"] : b["name"]).get<std::string>() + " " +
                              b["state"].get<std::string>());
  }
  // For 3 s of wall time: the episode renders on (no error ends it), images come at most
  // 5 a second (the camera takes 10 a world second, the episode runs at 1x).
  const auto start = std::chrono::steady_clock::now();
  int images = 0;
  double last_t = (*first)["t"];
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(3)) {
    const auto m = c.read(std::chrono::seconds(5));
    ASSERT_TRUE(m);
    if (!is_camera(*m)) continue;
    ++images;
    EXPECT_GT((*m)["t"].get<double>(), last_t);
    last_t = (*m)["t"];
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(images, 3) << "over " << wall << " s";
  EXPECT_LE(images, 5 * wall + 1) << "over " << wall << " s";
  EXPECT_FALSE(sv.episode.ended());
  // A page that joins now gets the latest image right after its hello and frame (Hub::join
  // sends the three before any broadcast reaches it).
  WsClient late(sv.port());
  for (const char* type : {"hello", "frame", "camera"}) {
    const auto m = late.read();
    ASSERT_TRUE(m);
    EXPECT_EQ((*m)["type"], type);
    if (is_camera(*m)) {
      EXPECT_GE((*m)["t"].get<double>(), last_t);
    }
  }
}

TEST(ServeServer, OnlyLoopbackIsBoundByDefault) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode = symbolic_options();
  o.paused = true;
  Served sv(s, o);
  EXPECT_EQ(sv.server.address(), "127.0.0.1");
  const std::string other = non_loopback_address();
  if (other.empty()) GTEST_SKIP() << "this machine has no non-loopback address to try";
  test::net::io_context ioc;
  test::tcp::socket sock(ioc);
  boost::system::error_code ec;
  sock.connect(test::tcp::endpoint(test::net::ip::make_address(other), sv.port()), ec);
  EXPECT_TRUE(ec) << "connected to " << other << ":" << sv.port();
}

// --host 0.0.0.0 (asked for): the page is served on the machine's other addresses too.
TEST(ServeServer, TheNetworkIsServedWhenAsked) {
  const std::string other = non_loopback_address();
  if (other.empty()) GTEST_SKIP() << "this machine has no non-loopback address to try";
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode = symbolic_options();
  o.paused = true;
  ServerOptions so;
  so.host = "0.0.0.0";
  Served sv(s, o, so);
  EXPECT_EQ(sv.server.address(), "0.0.0.0");
  WsClient c(sv.port(), other);
  const auto hello = c.read();
  ASSERT_TRUE(hello);
  EXPECT_EQ(hello->at("type"), "hello");
}

// Hostile clients: they connect and disconnect, send malformed JSON, unknown
// types and names, oversize and binary messages, and flood — each refused with
// a reply — while the episode runs; its end metrics equal an unserved run's.
TEST(ServeServer, HostileClientsDoNotDisturbTheEpisode) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const exec::EpisodeMetrics oracle = episode::run_episode(s, symbolic_options());
  ASSERT_TRUE(oracle.success) << oracle.reason;

  LiveOptions o;
  o.episode = symbolic_options();
  o.paused = true;
  o.speed = 20;
  Served sv(s, o);

  // Each kind of bad request gets one refusal that says what is wrong.
  WsClient c(sv.port());
  ASSERT_TRUE(c.read());  // hello
  c.send(std::string("{\"type\": \"intervene\", \"id\": 1,"));
  auto r = c.read_until([](const json& m) { return m["type"] == "reply"; });
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("malformed JSON"), std::string::npos);
  c.send(json{{"type", "launch"}, {"id", 2}});
  r = c.reply(2);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("unknown request type 'launch'"), std::string::npos);
  c.send(json{{"type", "intervene"}, {"id", 3}, {"kind", "relocate"}, {"subject", "o9"}, {"location", "r2"}});
  r = c.reply(3);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("unknown object or container 'o9'"), std::string::npos)
      << (*r)["error"];
  c.send(json{{"type", "intervene"}, {"id", 4}, {"kind", "relocate"}, {"subject", "o1"}, {"location", "r7"}});
  r = c.reply(4);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("unknown location 'r7'"), std::string::npos) << (*r)["error"];
  c.send(json{{"type", "intervene"}, {"id", 5}, {"kind", "add"}, {"subject", "in"}, {"location", "r1"}});
  r = c.reply(5);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("reserved word"), std::string::npos) << (*r)["error"];
  c.send(json{{"type", "intervene"}, {"id", 6}, {"kind", "add"}, {"subject", "x"}, {"class", "tray"}, {"location", "r1"}});
  r = c.reply(6);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("is already the class of containers"), std::string::npos) << (*r)["error"];
  c.send(json{{"type", "control"}, {"id", 7}, {"action", "seek"}, {"value", 3}});
  r = c.reply(7);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  c.send(std::string(70000, ' '));
  r = c.read_until([](const json& m) { return m["type"] == "reply"; });
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("over the limit of 65536 bytes"), std::string::npos);

  // While the episode runs: flooders, churners (connect, read hello, drop), a sender of garbage.
  std::atomic<bool> stop{false};
  std::atomic<int> throttled{0}, churned{0};
  std::vector<std::thread> threads;
  // A client thread ends quietly when the server drops it.
  auto guarded = [](auto body) {
    return [body] {
      try {
        body();
      } catch (const std::exception&) {
      }
    };
  };
  threads.emplace_back(guarded([&] {
    WsClient f(sv.port());
    for (int i = 0; i < 3000 && !stop; ++i)
      if (!f.send("{\"type\":\"control\",\"id\":" + std::to_string(i) + ",\"action\":\"fly\"}")) break;
    while (!stop) {
      auto m = f.read(std::chrono::milliseconds(200));
      if (!m) {
        if (f.closed()) break;
        continue;
      }
      if ((*m)["type"] == "reply" && (*m).value("error", "").find("throttled") != std::string::npos) ++throttled;
    }
  }));
  for (int k = 0; k < 2; ++k)
    threads.emplace_back(guarded([&] {
      while (!stop) {
        WsClient ch(sv.port());
        if (ch.read()) ++churned;
        ch.drop();
      }
    }));
  threads.emplace_back(guarded([&] {
    WsClient g(sv.port());
    for (int i = 0; !stop; ++i) {
      g.send(i % 2 ? std::string("[1,2,3]")
                   : json{{"type", "intervene"}, {"id", i}, {"kind", "remove"}, {"subject", "zz"}}.dump());
      g.read(std::chrono::milliseconds(50));
    }
  }));
  c.send(json{{"type", "control"}, {"id", 8}, {"action", "resume"}});
  r = c.reply(8);
  ASSERT_TRUE(r);
  EXPECT_TRUE((*r)["ok"]);
  const exec::EpisodeMetrics m = sv.episode.wait();
  stop = true;
  for (auto& t : threads) t.join();
  expect_same_metrics(m, oracle);
  EXPECT_GT(throttled.load(), 0);
  EXPECT_GT(churned.load(), 0);
}

// An intervention from a page is applied through the world, logged as an
// `intervention` record like a scripted one, and the loop reacts (handled by
// the tree, or a replan) before its next tick.
TEST(ServeServer, InterventionIsAppliedLoggedAndReactedTo) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const fs::path dir = temp_dir("intervene");
  LiveOptions o;
  o.episode = symbolic_options((dir / "ep.jsonl").string());
  o.episode.scripted_operator = false;
  o.paused = true;
  o.speed = 5;
  Served sv(s, o);
  WsClient c(sv.port());
  ASSERT_TRUE(c.read());
  c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
  ASSERT_TRUE(c.reply(1));
  // Once the tray has been moved to r2, put it back in r1 (undoing work: the loop must notice).
  const auto finished = c.read_until([](const json& m) {
    return m["type"] == "log" && m["record"]["ev"] == "action" && m["record"]["what"] == "finished";
  });
  ASSERT_TRUE(finished);
  // "move(o2, r3)": the thing just moved goes back to where it was.
  const std::string action = (*finished)["record"]["action"];
  const std::string moved = action.substr(5, action.find(',') - 5);
  // Every first move leaves r1 (blocks into the tray or to r2, or the tray to r2): back to r1 is a change.
  c.send(json{{"type", "intervene"}, {"id", 2}, {"kind", "relocate"}, {"subject", moved}, {"location", "r1"}});
  auto r = c.reply(2);
  ASSERT_TRUE(r);
  EXPECT_TRUE((*r)["ok"]) << r->dump();
  EXPECT_GE((*r)["server_ms"].get<double>(), 0);
  // The log record, then the reaction before the second tick after it.
  ASSERT_TRUE(c.read_until([&](const json& m) {
    return m["type"] == "log" && m["record"]["ev"] == "intervention" && m["record"]["subject"] == moved;
  }));
  int ticks = 0;
  const auto reaction = c.read_until([&](const json& m) {
    if (m["type"] != "log") return false;
    const std::string ev = m["record"]["ev"];
    if (ev == "tick") ++ticks;
    return ev == "handled_by_tree" || ev == "replan" || ticks >= 2;
  });
  ASSERT_TRUE(reaction);
  EXPECT_NE((*reaction)["record"]["ev"], "tick") << "no reaction before the second tick";
  // A refused one says why.
  c.send(json{{"type", "intervene"}, {"id", 3}, {"kind", "relocate"}, {"subject", "r3"}, {"location", "o2"}});
  r = c.reply(3);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("unknown location 'o2'"), std::string::npos) << (*r)["error"];
  const exec::EpisodeMetrics m = sv.episode.wait();
  EXPECT_TRUE(m.success) << m.reason;
  EXPECT_EQ(m.interventions_applied, 1);
  // The file log holds the intervention exactly as the page saw it.
  const auto log = read_log(dir / "ep.jsonl");
  int found = 0;
  for (const auto& rec : log)
    if (rec["ev"] == "intervention") {
      ++found;
      EXPECT_EQ(rec["kind"], "relocate");
      EXPECT_EQ(rec["subject"], moved);
      EXPECT_EQ(rec["applied"], true);
    }
  EXPECT_EQ(found, 1);
  fs::remove_all(dir);
}

// A page gives a running episode a new task: the reply accepts it, the log's
// `task` record carries the new automaton, the episode ends satisfying it (all
// blocks in r3, not r2); a malformed formula is refused with the reason and the
// caret line; a page that joins later has the task record in its history and
// the new task and automaton in its hello; the resulting log replays, a replay's
// hello names the task in force at the time shown, and a replay refuses a task request.
TEST(ServeServer, APageGivesANewTaskAndTheLogReplays) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const fs::path dir = temp_dir("task");
  {
    LiveOptions o;
    o.episode = symbolic_options((dir / "ep.jsonl").string());
    o.episode.scripted_operator = false;
    o.paused = true;
    o.speed = 5;
    Served sv(s, o);
    WsClient c(sv.port());
    auto hello = c.read();
    ASSERT_TRUE(hello);
    // Refused: a formula that does not parse, with the caret under the column.
    c.send(json{{"type", "task"}, {"id", 1}, {"task", "F G ((all_in_r2"}});
    auto r = c.reply(1);
    ASSERT_TRUE(r);
    EXPECT_FALSE((*r)["ok"]);
    EXPECT_FALSE((*r)["error"].get<std::string>().empty());
    ASSERT_TRUE((*r)["detail"].is_string()) << r->dump();
    EXPECT_NE((*r)["detail"].get<std::string>().find('^'), std::string::npos) << r->dump();
    // Refused: an unknown proposition, named.
    c.send(json{{"type", "task"}, {"id", 2}, {"task", "F all_in_r9"}});
    r = c.reply(2);
    ASSERT_TRUE(r);
    EXPECT_FALSE((*r)["ok"]);
    EXPECT_NE((*r)["error"].get<std::string>().find("all_in_r9"), std::string::npos) << r->dump();
    // Accepted: the blocks in r3 (before anything moved: the arm goes there).
    c.send(json{{"type", "task"}, {"id", 3}, {"task", "F G \"all block in r3\""}});
    r = c.reply(3);
    ASSERT_TRUE(r);
    EXPECT_TRUE((*r)["ok"]) << r->dump();
    c.send(json{{"type", "control"}, {"id", 4}, {"action", "resume"}});
    ASSERT_TRUE(c.reply(4));
    const auto task = c.read_until([](const json& m) {
      return m["type"] == "log" && m["record"]["ev"] == "task" && m["record"]["applied"] == true;
    });
    ASSERT_TRUE(task);
    const json& rec = (*task)["record"];
    EXPECT_EQ(rec["by"], "page");
    EXPECT_EQ(rec["task"], "F G \"all block in r3\"");
    EXPECT_EQ(rec["automaton_states"].get<std::size_t>(), rec["automaton"]["states"].size());
    EXPECT_FALSE(rec["automaton"]["edges"].empty());
    EXPECT_NE(rec["automaton"].dump(), (*hello)["automaton"].dump());
    // A page that joins now has the task change in its history.
    WsClient late(sv.port());
    auto h2 = late.read();
    ASSERT_TRUE(h2);
    bool seen = false;
    for (const auto& x : (*h2)["history"]) seen = seen || (x["ev"] == "task" && x["applied"] == true);
    EXPECT_TRUE(seen);
    EXPECT_EQ((*hello)["task"], s.task);
    EXPECT_EQ((*h2)["task"], rec["task"]);
    EXPECT_EQ((*h2)["automaton"], rec["automaton"]);
    const exec::EpisodeMetrics m = sv.episode.wait();
    EXPECT_TRUE(m.success) << m.reason;
    // The end placement satisfies the new task: every block in r3.
    const auto log = read_log(dir / "ep.jsonl");
    ASSERT_EQ(log.back()["ev"], "end");
    for (const auto& [thing, where] : log.back()["placement"].items())
      if (thing.rfind("o", 0) == 0) {
        EXPECT_EQ(where, "r3") << thing;
      }
  }
  // The log with the task change replays (the checker accepts `task` records).
  ReplayOptions ro;
  ro.speed = 0;
  ro.paused = true;
  Replay replay(s, (dir / "ep.jsonl").string(), ro);
  Server server({"127.0.0.1", 0, ""}, replay);
  server.start();
  replay.start();
  WsClient c(server.port());
  ASSERT_TRUE(c.read());
  c.send(json{{"type", "task"}, {"id", 1}, {"task", "F all_in_r2"}});
  auto r = c.reply(1);
  ASSERT_TRUE(r);
  EXPECT_FALSE((*r)["ok"]);
  EXPECT_NE((*r)["error"].get<std::string>().find("replay"), std::string::npos) << r->dump();
  // Seek to the end: the hello's history holds the task change.
  c.send(json{{"type", "control"}, {"id", 2}, {"action", "seek"}, {"value", 1e6}});
  const auto hello = c.read_until([](const json& m) { return m["type"] == "hello"; });
  ASSERT_TRUE(hello);
  bool replayed = false;
  json change;
  for (const auto& x : (*hello)["history"])
    if (x["ev"] == "task" && x["applied"] == true) {
      replayed = true;
      change = x;
    }
  ASSERT_TRUE(replayed);
  EXPECT_EQ((*hello)["task"], change["task"]);
  EXPECT_EQ((*hello)["automaton"], change["automaton"]);
  // Back to the start: the scenario's task, with the automaton the episode record logged.
  c.send(json{{"type", "control"}, {"id", 3}, {"action", "seek"}, {"value", 0}});
  const auto start = c.read_until([](const json& m) { return m["type"] == "hello"; });
  ASSERT_TRUE(start);
  EXPECT_EQ((*start)["task"], s.task);
  ASSERT_FALSE((*start)["history"].empty());
  EXPECT_EQ((*start)["automaton"], (*start)["history"][0]["automaton"]);
  EXPECT_NE((*start)["automaton"], change["automaton"]);
  replay.stop();
  server.stop();
  fs::remove_all(dir);
}

// A person fixes the scene while the episode is paused (before the first move):
// the intervention is applied at once and logged when the loop goes on.
TEST(ServeServer, InterventionWhilePausedIsLoggedAfterResume) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode = symbolic_options();
  o.episode.scripted_operator = false;
  o.paused = true;
  o.speed = 20;
  Served sv(s, o);
  WsClient c(sv.port());
  ASSERT_TRUE(c.read());
  c.send(json{{"type", "intervene"}, {"id", 1}, {"kind", "add"}, {"class", "block"}, {"location", "r2"}});
  auto r = c.reply(1);
  ASSERT_TRUE(r);
  ASSERT_TRUE((*r)["ok"]) << r->dump();
  EXPECT_EQ((*r)["subject"], "o4");
  c.send(json{{"type", "control"}, {"id", 2}, {"action", "resume"}});
  ASSERT_TRUE(c.reply(2));
  const auto is_record = [](const json& m) {
    return m["type"] == "log" && m["record"]["ev"] == "intervention" && m["record"]["subject"] == "o4";
  };
  // The resumed loop may log it before the reply to resume is queued: it may be among what reply() read.
  std::optional<json> rec;
  for (const auto& m : c.seen)
    if (is_record(m)) rec = m;
  if (!rec) rec = c.read_until(is_record);
  ASSERT_TRUE(rec);
  EXPECT_EQ((*rec)["record"]["applied"], true);
  const exec::EpisodeMetrics m = sv.episode.wait();
  EXPECT_EQ(m.interventions_applied, 1);
  EXPECT_TRUE(m.success) << m.reason;
}

// GET /api/hello (the hello a page joining now would get).
json api_hello(unsigned short port) {
  return json::parse(test::http_request(port, boost::beast::http::verb::get, "/api/hello").body);
}

// The statuses of a tree message's nodes, one letter each (as a status message has them).
std::string shown_statuses(const json& tree) {
  std::string s;
  for (const json& n : tree["nodes"]) s += n["status"].get<std::string>().front();
  return s;
}

// A page that joins an episode no page watched sees the present: its hello's
// time and first frame are not older than any record its history has.
TEST(ServeServer, APageThatJoinsLateSeesThePresent) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode = symbolic_options();
  o.speed = 4;
  Served sv(s, o);
  const auto latest = [](const json& hello) {
    double t = 0;
    for (const json& r : hello["history"]) t = std::max(t, r["t"].get<double>());
    return t;
  };
  for (int i = 0; i < 3000 && latest(api_hello(sv.port())) < 3; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  WsClient late(sv.port());
  const auto hello = late.read();
  ASSERT_TRUE(hello);
  ASSERT_EQ((*hello)["type"], "hello");
  const double t = (*hello)["t"];
  EXPECT_GE(latest(*hello), 3) << "the episode is not under way";
  EXPECT_GE(t + 1e-4, latest(*hello)) << "hello's time is older than its history (records are logged to 1e-4 s)";
  const auto frame = late.read();
  ASSERT_TRUE(frame);
  ASSERT_EQ((*frame)["type"], "frame");
  EXPECT_EQ((*frame)["t"].get<double>(), t);
}

// The tree a joining page gets shows the statuses of the latest tick: at the
// end of an episode no page watched, those a page watching the same episode
// all along shows last (the symbolic episode is the same with or without pages).
TEST(ServeServer, APageThatJoinsLateSeesTheTreesStatuses) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  LiveOptions o;
  o.episode = symbolic_options();
  o.speed = 0;
  o.paused = true;
  std::string watched;
  {
    Served sv(s, o);
    WsClient c(sv.port());
    const auto hello = c.read();
    ASSERT_TRUE(hello);
    if (!(*hello)["tree"].is_null()) watched = shown_statuses((*hello)["tree"]);
    c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
    ASSERT_TRUE(c.read_until([&watched](const json& m) {
      if (m["type"] == "tree") watched = shown_statuses(m);
      if (m["type"] == "status") watched = m["s"];  // I R S F: the statuses' first letters
      return m["type"] == "state" && m["ended"] == true;
    }));
    EXPECT_TRUE(sv.episode.wait().success);
  }
  EXPECT_NE(watched.find_first_not_of('I'), std::string::npos) << watched;
  o.paused = false;
  Served sv(s, o);
  EXPECT_TRUE(sv.episode.wait().success);
  WsClient late(sv.port());
  const auto hello = late.read();
  ASSERT_TRUE(hello);
  EXPECT_EQ(shown_statuses((*hello)["tree"]), watched);
}

// Replays: a served episode's log (with frame records) and a `run` log (without)
// both reach the logged end state; seek cuts the history at t.
TEST(ServeServer, ReplayReachesTheLoggedEndStateAndSeeks) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const fs::path dir = temp_dir("replay");
  {
    LiveOptions o;
    o.episode = symbolic_options((dir / "served.jsonl").string());
    o.speed = 0;
    LiveEpisode live(s, o);
    live.start();
    ASSERT_TRUE(live.wait().success);
  }
  episode::run_episode(s, symbolic_options((dir / "run.jsonl").string()));
  for (const char* name : {"served.jsonl", "run.jsonl"}) {
    SCOPED_TRACE(name);
    const auto log = read_log(dir / name);
    ASSERT_FALSE(log.empty());
    const json end = log.back();
    ASSERT_EQ(end["ev"], "end");
    bool frames = false;
    for (const auto& rec : log) frames = frames || rec["ev"] == "frame";
    EXPECT_EQ(frames, std::string(name) == "served.jsonl");

    ReplayOptions ro;
    ro.speed = 0;
    ro.paused = true;
    Replay replay(s, (dir / name).string(), ro);
    Server server({"127.0.0.1", 0, ""}, replay);
    server.start();
    replay.start();
    WsClient c(server.port());
    auto hello = c.read();
    ASSERT_TRUE(hello);
    EXPECT_EQ((*hello)["mode"], "replay");
    EXPECT_NEAR((*hello)["replay"]["duration"].get<double>(), end["t"].get<double>(), 1e-9);
    EXPECT_TRUE((*hello)["history"].empty());
    // Seek to the middle: a new hello whose history is every non-frame record up to t.
    const double mid = end["t"].get<double>() / 2;
    c.send(json{{"type", "control"}, {"id", 1}, {"action", "seek"}, {"value", mid}});
    hello = c.read_until([](const json& m) { return m["type"] == "hello"; });
    ASSERT_TRUE(hello);
    std::size_t expect = 0;
    for (const auto& rec : log)
      expect += rec["t"].get<double>() <= mid + 1e-9 && rec["ev"] != "frame" && rec["ev"] != "statuses";
    EXPECT_EQ((*hello)["history"].size(), expect);
    for (const auto& rec : (*hello)["history"]) EXPECT_LE(rec["t"].get<double>(), mid + 1e-9);
    // Play to the end: every record arrives, the last frame shows the end placement.
    c.send(json{{"type", "control"}, {"id", 2}, {"action", "resume"}});
    const auto ended = c.read_until([](const json& m) { return m["type"] == "state" && m["ended"] == true; });
    ASSERT_TRUE(ended);
    json last_frame;
    std::size_t records = (*hello)["history"].size();
    for (const auto& m : c.seen) {
      if (m["type"] == "frame") last_frame = m;
      if (m["type"] == "log") ++records;
    }
    std::size_t non_frame = 0;
    for (const auto& rec : log) non_frame += rec["ev"] != "frame" && rec["ev"] != "statuses";
    EXPECT_EQ(records, non_frame);
    ASSERT_FALSE(last_frame.is_null());
    std::map<std::string, std::string> at;
    for (const auto& t : last_frame["things"]) at[t["name"]] = t["at"];
    std::map<std::string, std::string> expected;
    for (const auto& [n, l] : end["placement"].items()) expected[n] = l;
    EXPECT_EQ(at, expected);
  }
  fs::remove_all(dir);
}


// The nodes of a tree message without their statuses (what a replay can know).
std::string tree_shape(const json& tree) {
  json out = json::array();
  for (const auto& n : tree["nodes"])
    out.push_back({n["id"], n["parent"], n["name"], n["kind"], n["category"]});
  return out.dump();
}

// A replay sends the behavior tree the live episode had after each change —
// rebuilt from the log's plan and tree records (node names, kinds, categories,
// parents) — and a hello after a seek holds the tree at
// that time; a thing added mid-episode has the class its intervention record
// names (here a container of class "crate", not the default "tray"), in a log
// with frame records and in one without. The handover scenario replans when the
// tray arrives; in both condition forms (their nodes are named differently).
TEST(ServeServer, ReplaySendsTheLoggedTreesAndAddedThingsClasses) {
  world::Scenario s = world::load_scenario("3-block-tray-handover");
  ASSERT_FALSE(s.interventions.empty());
  ASSERT_EQ(s.interventions[0].kind, world::Change::Kind::AddContainer);
  s.interventions[0].cls = "crate";
  const std::string added = s.interventions[0].subject;
  const fs::path dir = temp_dir("replay_tree");
  for (const exec::ConditionMode mode : {exec::ConditionMode::Action, exec::ConditionMode::State}) {
    SCOPED_TRACE(exec::to_string(mode));
    const fs::path served_log = dir / (std::string(exec::to_string(mode)) + "_served.jsonl");
    const fs::path run_log = dir / (std::string(exec::to_string(mode)) + "_run.jsonl");
    // Live, watched from the first plan on: the tree after each change.
    std::vector<std::pair<double, std::string>> live;
    {
      LiveOptions o;
      o.episode = symbolic_options(served_log.string());
      o.episode.loop.conditions = mode;
      o.speed = 0;
      o.paused = true;
      Served sv(s, o);
      WsClient c(sv.port());
      const auto hello = c.read();
      ASSERT_TRUE(hello);
      // The first tree: in hello if the first plan was made before the page joined, else a message.
      if ((*hello)["tree"].is_object())
        live.emplace_back((*hello)["tree"]["t"].get<double>(), tree_shape((*hello)["tree"]));
      c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
      ASSERT_TRUE(c.read_until([](const json& m) { return m["type"] == "state" && m["ended"] == true; }));
      for (const auto& m : c.seen)
        if (m["type"] == "tree" && (live.empty() || tree_shape(m) != live.back().second))
          live.emplace_back(m["t"].get<double>(), tree_shape(m));
      EXPECT_TRUE(sv.episode.wait().success);
    }
    ASSERT_GE(live.size(), 2u) << "no replan: nothing to compare";
    {
      auto o = symbolic_options(run_log.string());
      o.loop.conditions = mode;
      ASSERT_TRUE(episode::run_episode(s, o).success);
    }
    for (const fs::path& log : {served_log, run_log}) {
      SCOPED_TRACE(log.filename().string());
      bool classed = false;
      for (const auto& rec : read_log(log))
        classed = classed || (rec["ev"] == "intervention" && rec["subject"] == added && rec["class"] == "crate");
      EXPECT_TRUE(classed) << "the intervention record names the added thing's class";
      ReplayOptions ro;
      ro.speed = 0;
      ro.paused = true;
      Replay replay(s, log.string(), ro);
      Server server({"127.0.0.1", 0, ""}, replay);
      server.start();
      replay.start();
      WsClient c(server.port());
      ASSERT_TRUE(c.read());
      // Played from the start: the same trees, in the same order, at the logged times.
      c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
      ASSERT_TRUE(c.read_until([](const json& m) { return m["type"] == "state" && m["ended"] == true; }));
      std::vector<std::pair<double, std::string>> replayed;
      json last_frame;
      for (const auto& m : c.seen) {
        if (m["type"] == "tree" && (replayed.empty() || tree_shape(m) != replayed.back().second))
          replayed.emplace_back(m["t"].get<double>(), tree_shape(m));
        if (m["type"] == "frame") last_frame = m;
      }
      ASSERT_EQ(replayed.size(), live.size());
      for (std::size_t i = 0; i < live.size(); ++i) {
        EXPECT_EQ(replayed[i].second, live[i].second) << "tree " << i;
        EXPECT_NEAR(replayed[i].first, live[i].first, 1e-4) << "tree " << i;
      }
      // The added container is drawn as what it is.
      ASSERT_FALSE(last_frame.is_null());
      bool drawn = false;
      for (const auto& t : last_frame["things"])
        if (t["name"] == added) {
          drawn = true;
          EXPECT_EQ(t["class"], "crate");
          EXPECT_EQ(t["kind"], "container");
        }
      EXPECT_TRUE(drawn);
      // A seek just before and just after the first replan's tree: hello's tree is the tree then.
      const double t1 = replayed[1].first;
      c.send(json{{"type", "control"}, {"id", 2}, {"action", "seek"}, {"value", t1 - 1e-3}});
      auto hello = c.read_until([](const json& m) { return m["type"] == "hello"; });
      ASSERT_TRUE(hello);
      EXPECT_EQ(tree_shape((*hello)["tree"]), live[0].second);
      c.send(json{{"type", "control"}, {"id", 3}, {"action", "seek"}, {"value", t1}});
      hello = c.read_until([](const json& m) { return m["type"] == "hello"; });
      ASSERT_TRUE(hello);
      EXPECT_EQ(tree_shape((*hello)["tree"]), live[1].second);
      replay.stop();
    }
  }
  fs::remove_all(dir);
}


// The node statuses of a served episode: its log holds every status string the
// pages were sent, in order (`statuses` records, after each tick that changed
// some and each tree change); the end shows the tree's final statuses — those of
// the end record — not the last running ones: a finished tree keeps its
// statuses (the root SUCCESS), one cut by the time limit while a move runs is
// halted (nothing RUNNING); and a replay of the log, seeked back and forth,
// shows at each time the statuses the log has then.
TEST(ServeServer, StatusesAreFinalAtTheEndAndReplayedAtTheTimeShown) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const fs::path dir = temp_dir("statuses");
  for (const double max_time : {300.0, 3.0}) {
    SCOPED_TRACE(max_time);
    const fs::path log_path = dir / "served.jsonl";
    std::vector<std::string> sent;  // the statuses the page was sent, in order
    {
      LiveOptions o;
      o.episode = symbolic_options(log_path.string());
      o.episode.loop.max_time = max_time;
      o.speed = 0;
      o.paused = true;
      Served sv(s, o);
      WsClient c(sv.port());
      const auto hello = c.read();
      ASSERT_TRUE(hello);
      if ((*hello)["tree"].is_object()) sent.push_back(shown_statuses((*hello)["tree"]));
      c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
      ASSERT_TRUE(c.read_until([&sent](const json& m) {
        if (m["type"] == "tree") sent.push_back(shown_statuses(m));
        if (m["type"] == "status") sent.push_back(m["s"]);
        return m["type"] == "state" && m["ended"] == true;
      }));
      EXPECT_EQ(sv.episode.wait().success, max_time > 100);
    }
    const auto log = read_log(log_path);
    std::vector<std::pair<double, std::string>> logged;
    for (const auto& r : log)
      if (r["ev"] == "statuses") logged.emplace_back(r["t"].get<double>(), r["s"].get<std::string>());
    ASSERT_FALSE(logged.empty());
    const std::string final = log.back()["statuses"];
    // What the page last showed is the end's statuses.
    EXPECT_EQ(sent.back(), final);
    EXPECT_EQ(final.find('R'), std::string::npos) << final;
    if (max_time > 100) {
      EXPECT_EQ(final.front(), 'S') << "the finished tree keeps its statuses";
    } else {
      EXPECT_EQ(final.find_first_not_of('I'), std::string::npos) << "the running tree was halted: " << final;
      EXPECT_NE(logged.back().second.find('R'), std::string::npos) << "a move ran when the time was up";
    }
    // The log's statuses are the ones sent, those of the paused start (t = 0) the page
    // joined at shown as the latest of them (with hello's tree).
    const auto changes = [&](const std::vector<std::string>& all) {
      std::vector<std::string> v;
      for (const auto& st : all)
        if (v.empty() || v.back() != st) v.push_back(st);
      if (v.back() != final) v.push_back(final);
      return v;
    };
    std::vector<std::string> all;
    std::size_t at_start = 0;  // changes logged at the start's time (before or after the page joined)
    for (const auto& [t, st] : logged) all.push_back(st);
    const std::vector<std::string> expected = changes(all);
    for (const auto& [t, st] : logged) at_start += t <= logged.front().first && (at_start == 0 || st != expected[at_start - 1]);
    // Whether `got` is the log's changes, less some of those at the start.
    const auto matches = [&](const std::vector<std::string>& got) {
      for (std::size_t skip = 0; skip < std::max<std::size_t>(at_start, 1); ++skip)
        if (got == std::vector<std::string>(expected.begin() + static_cast<long>(skip), expected.end())) return true;
      return false;
    };
    ASSERT_FALSE(sent.empty());
    EXPECT_TRUE(matches(changes(sent))) << testing::PrintToString(changes(sent)) << " vs the log's "
                                        << testing::PrintToString(expected);

    // The replay, seeked to times back and forth: hello's tree has the log's statuses then.
    ReplayOptions ro;
    ro.speed = 0;
    ro.paused = true;
    Replay replay(s, log_path.string(), ro);
    Server server({"127.0.0.1", 0, ""}, replay);
    server.start();
    replay.start();
    WsClient c(server.port());
    ASSERT_TRUE(c.read());
    const auto at = [&](double t) {
      std::string st;
      for (const auto& [tt, x] : logged)
        if (tt <= t + 1e-9) st = x;
      return t >= log.back()["t"].get<double>() ? final : st;
    };
    std::vector<double> times;
    for (std::size_t i = logged.size(); i-- > 0;) times.push_back(logged[i].first + 1e-3);  // backwards
    times.push_back(log.back()["t"].get<double>());
    times.push_back(logged[logged.size() / 2].first);
    int id = 2;
    int with_running = 0;
    for (const double t : times) {
      c.send(json{{"type", "control"}, {"id", id++}, {"action", "seek"}, {"value", t}});
      const auto hello = c.read_until([](const json& m) { return m["type"] == "hello"; });
      ASSERT_TRUE(hello);
      ASSERT_TRUE((*hello)["tree"].is_object()) << t;
      EXPECT_EQ(shown_statuses((*hello)["tree"]), at(t)) << "at t = " << t;
      with_running += at(t).find('R') != std::string::npos;
    }
    EXPECT_GT(with_running, 0) << "some time shown has a running node";
    // Played from the start: the status messages are the log's, in order.
    c.send(json{{"type", "control"}, {"id", id++}, {"action", "seek"}, {"value", 0}});
    const auto start = c.read_until([](const json& m) { return m["type"] == "hello"; });
    ASSERT_TRUE(start);
    const std::size_t from = c.seen.size();
    c.send(json{{"type", "control"}, {"id", id++}, {"action", "resume"}});
    ASSERT_TRUE(c.read_until([](const json& m) { return m["type"] == "state" && m["ended"] == true; }));
    std::vector<std::string> replayed;
    if ((*start)["tree"].is_object()) replayed.push_back(shown_statuses((*start)["tree"]));
    for (std::size_t i = from; i < c.seen.size(); ++i)
      if (c.seen[i]["type"] == "status" && (replayed.empty() || replayed.back() != c.seen[i]["s"]))
        replayed.push_back(c.seen[i]["s"]);
    ASSERT_FALSE(replayed.empty());
    EXPECT_TRUE(matches(changes(replayed))) << testing::PrintToString(changes(replayed)) << " vs the log's "
                                            << testing::PrintToString(expected);
    replay.stop();
  }
  fs::remove_all(dir);
}

// Server::drain, what `rtamp serve --exit-at-end` does before it stops: a page
// attached from the start has been sent every record of the log, the end
// included, by the time the server goes (without it, what was still queued
// when the episode ended was dropped).
TEST(ServeServer, DrainDeliversEveryRecordBeforeTheServerStops) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  const fs::path dir = temp_dir("drain");
  const fs::path log = dir / "ep.jsonl";
  LiveOptions o;
  o.episode = symbolic_options(log.string());
  o.speed = 0;
  o.paused = true;
  LiveEpisode live(s, o);
  Server server({"127.0.0.1", 0, ""}, live);
  server.start();
  live.start();
  WsClient c(server.port());
  const auto hello = c.read();
  ASSERT_TRUE(hello);
  c.send(json{{"type", "control"}, {"id", 1}, {"action", "resume"}});
  ASSERT_TRUE(live.wait().success);
  server.drain(std::chrono::seconds(30));
  EXPECT_EQ(live.hub().unsent(), 0);
  server.stop();
  // Everything was written before the connection closed: read it now.
  std::size_t records = (*hello)["history"].size();
  bool end = false;
  // (stop() leaves the socket open until the server is destroyed: the last read times out.)
  while (const auto m = c.read(std::chrono::seconds(2)))
    if ((*m)["type"] == "log") {
      ++records;
      end = end || (*m)["record"]["ev"] == "end";
    }
  EXPECT_TRUE(end);
  std::size_t expect = 0;
  for (const auto& rec : read_log(log)) expect += rec["ev"] != "frame" && rec["ev"] != "statuses";
  EXPECT_EQ(records, expect);
  // The tick records (one a step) came in batches: fewer messages than records.
  EXPECT_LT(c.log_messages, static_cast<int>(records - (*hello)["history"].size()));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rtamp::serve
