// EpisodeMcap's messages written as text directly (no nlohmann objects): read
// back from an uncompressed file by a minimal MCAP reader written here from the
// specification, the /tree, /timeline and /automaton/tracked messages are the text
// nlohmann dumps for the same values (so they read back as before, keys in
// order, strings escaped); the arm (arm()) gives six joint states and a /tf
// chain whose composition is the UR5's forward kinematics in the world; an
// episode with task changes has every task in force on /task and its automaton
// on /automaton, in time order, as the log's `episode` and `task` records give
// them, and the log converted later gives the same messages on every channel.
#include "rtamp/episode/episode_mcap.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <png.h>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/world/camera.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {
namespace {

using nlohmann::json;

template <typename T>
T take(const std::string& b, std::size_t& at) {
  T v = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) v |= static_cast<T>(static_cast<T>(static_cast<unsigned char>(b[at + i])) << (8 * i));
  at += sizeof(T);
  return v;
}

std::string take_string(const std::string& b, std::size_t& at) {
  const auto n = take<std::uint32_t>(b, at);
  std::string s = b.substr(at, n);
  at += n;
  return s;
}

// topic -> message texts, from a file whose chunks are not compressed.
std::map<std::string, std::vector<std::string>> messages(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<std::uint16_t, std::string> topics;
  std::map<std::string, std::vector<std::string>> out;
  const auto walk = [&](const std::string& records, std::size_t at, std::size_t end, auto& self) -> void {
    while (at < end) {
      const auto op = static_cast<unsigned char>(records[at++]);
      const auto length = take<std::uint64_t>(records, at);
      std::size_t c = at;
      if (op == 0x04) {  // Channel
        const auto id = take<std::uint16_t>(records, c);
        take<std::uint16_t>(records, c);
        topics[id] = take_string(records, c);
      } else if (op == 0x05) {  // Message
        const auto channel = take<std::uint16_t>(records, c);
        c += 4 + 8 + 8;
        out[topics.at(channel)].push_back(records.substr(c, at + length - c));
      } else if (op == 0x06) {  // Chunk
        c += 8 + 8 + 8 + 4;
        EXPECT_EQ(take_string(records, c), "");
        const auto n = take<std::uint64_t>(records, c);
        const std::string inner = records.substr(c, n);
        self(inner, 0, inner.size(), self);
      } else if (op == 0x0F) {  // DataEnd: the summary repeats the channels
        return;
      }
      at += length;
    }
  };
  EXPECT_EQ(b.substr(0, 8), std::string("\x89MCAP0\r\n", 8));
  walk(b, 8, b.size() - 8, walk);
  return out;
}

std::string dumped(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

json stamp(std::uint64_t ns) { return {{"sec", ns / 1000000000ULL}, {"nsec", ns % 1000000000ULL}}; }

TEST(EpisodeMcap, MessagesWrittenDirectlyAreNlohmannsText) {
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "episode_mcap_text.mcap").string();
  const json tree{{"ev", "tree"}, {"applied", true}, {"changes", 2}, {"inserted", 3}, {"removed", 0}, {"updated", 1}, {"t", 1.5}};
  const json run{{"ev", "run"}, {"automaton_states", {0, 2}}, {"state", {{"o1", "r1"}, {"o2", "tray \"a\""}}}, {"t", 2.25}};
  const json action{{"ev", "action"}, {"what", "failed"}, {"action", "move(o1, r2)"}, {"reason", "slipped:\t\"é\"\n"}, {"t", 3.0}};
  {
    EpisodeMcap m(path, McapCompression::None, nullptr);
    m.add(R"({"ev":"episode","scenario":"not-built-in","t":0})");
    m.add(dumped(tree));
    m.add(R"js({"ev":"tick","running":"move(o1, r2)","status":"running","t":2})js");
    m.add(dumped(run));
    m.add(dumped(action));
    m.close();
  }
  const auto topics = messages(path);
  ASSERT_EQ(topics.at("/rtamp/log").size(), 5u);

  // The tree record's fields with the tick's status (after the tree record, then the tick).
  json status = tree;
  status.erase("ev");
  status.erase("t");
  status["running"] = "";
  status["status"] = "";
  status["timestamp"] = stamp(1500000000);
  ASSERT_EQ(topics.at("/tree").size(), 2u);
  EXPECT_EQ(topics.at("/tree")[0], dumped(status));
  status["running"] = "move(o1, r2)";
  status["status"] = "running";
  status["timestamp"] = stamp(2000000000);
  EXPECT_EQ(topics.at("/tree")[1], dumped(status));

  const json automaton{{"automaton_states", {0, 2}}, {"state", run.at("state")}, {"timestamp", stamp(2250000000)}};
  EXPECT_EQ(topics.at("/automaton/tracked").at(0), dumped(automaton));

  const json line{{"timestamp", stamp(3000000000)},
                  {"level", 3},
                  {"message", "failed move(o1, r2): slipped:\t\"é\"\n"},
                  {"name", "rtamp.action"},
                  {"file", ""},
                  {"line", 0}};
  EXPECT_EQ(topics.at("/timeline").back(), dumped(line));
}

std::uint64_t nanos_of(const json& stamp) { return stamp.at("sec").get<std::uint64_t>() * 1000000000ULL + stamp.at("nsec").get<std::uint64_t>(); }

// A new task at world time `time` given `by` "api", with new propositions {name, text}.
world::TaskChange task_change(double time, const std::string& task,
                              const std::vector<std::pair<std::string, std::string>>& props = {}) {
  world::TaskChange c;
  c.time = time;
  c.task = task;
  c.task_where = SourceLocation{"<test>", 1, 1};
  c.by = "api";
  for (const auto& [name, text] : props) {
    world::Proposition p;
    p.name = name;
    p.text = text;
    p.where = SourceLocation{"<test>", 1, 1};
    p.expr = world::parse_prop_expr(text, p.where);
    c.propositions.push_back(std::move(p));
  }
  return c;
}

TEST(EpisodeMcap, EveryTaskInForceOnTaskAndItsAutomaton) {
  const auto dir = std::filesystem::path(::testing::TempDir());
  const std::string log = (dir / "episode_mcap_tasks.jsonl").string(), live = (dir / "episode_mcap_tasks.mcap").string(),
                    converted = (dir / "episode_mcap_tasks_converted.mcap").string();
  EpisodeOptions o;
  o.world = "symbolic";
  o.loop.planning = exec::PlanningMode::Inline;
  o.loop.max_time = 200;
  // o1 is carried to r2 when the first change forbids r2 for it (a redirect); the
  // second brings a proposition of its own.
  o.loop.task_changes = {task_change(2, "G !\"o1 in r2\" & F G \"o2 in r2\""),
                         task_change(5, "F G all_in_r1", {{"all_in_r1", "all block in r1"}})};
  o.outputs.log = log;
  o.outputs.mcap = live;
  o.outputs.mcap_compression = McapCompression::None;
  const auto metrics = run_episode(world::load_scenario("3-block"), o);
  EXPECT_TRUE(metrics.success) << metrics.reason;
  ASSERT_EQ(metrics.tasks.size(), 3u);

  // The oracle: the log's records that put a task in force.
  std::vector<json> in_force;
  std::size_t runs = 0, redirects = 0;
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) {
    const json r = json::parse(line);
    if (r.at("ev") == "episode" || (r.at("ev") == "task" && r.at("applied") == true)) in_force.push_back(r);
    runs += r.at("ev") == "run";
    redirects += r.at("ev") == "redirect";
  }
  ASSERT_EQ(in_force.size(), 3u);
  EXPECT_GE(redirects, 1u) << "the first change redirects the carry of o1 to r2";

  const auto topics = messages(live);
  const auto& tasks = topics.at("/task");
  const auto& automata = topics.at("/automaton");
  ASSERT_EQ(tasks.size(), in_force.size());
  ASSERT_EQ(automata.size(), in_force.size());
  EXPECT_EQ(topics.at("/automaton/tracked").size(), runs);
  std::uint64_t last = 0;
  for (std::size_t i = 0; i < in_force.size(); ++i) {
    const json& r = in_force[i];
    const json task = json::parse(tasks[i]), automaton = json::parse(automata[i]);
    const std::uint64_t ns = std::llround(r.at("t").get<double>() * 1e9);
    EXPECT_EQ(nanos_of(task.at("timestamp")), ns);
    EXPECT_GE(ns, last) << "in time order";
    last = ns;
    EXPECT_EQ(task.at("task"), r.at("task"));
    EXPECT_EQ(task.at("task"), metrics.tasks[i].task);
    EXPECT_EQ(task.at("by"), i == 0 ? "scenario" : "api");
    EXPECT_EQ(task.at("automaton_states"), r.at("automaton_states"));
    EXPECT_EQ(task.at("automaton_states").get<std::size_t>(), metrics.tasks[i].automaton_states);
    EXPECT_EQ(task.at("automaton"), r.at("automaton"));
    EXPECT_EQ(task.at("automaton").at("states").size(), r.at("automaton_states").get<std::size_t>());
    EXPECT_EQ(task.contains("propositions"), i == 2);
    if (i == 2) {
      EXPECT_EQ(task.at("propositions"), json({{"all_in_r1", "all block in r1"}}));
    }
    json graph = r.at("automaton");
    graph["timestamp"] = task.at("timestamp");
    graph["task"] = r.at("task");
    EXPECT_EQ(automaton, graph);
  }
  // The timeline names each change and the redirect.
  std::size_t new_task_lines = 0, redirect_lines = 0;
  for (const std::string& m : topics.at("/timeline")) {
    const std::string text = json::parse(m).at("message");
    new_task_lines += text.rfind("new task from api: ", 0) == 0;
    redirect_lines += text.rfind("redirected move(", 0) == 0;
  }
  EXPECT_EQ(new_task_lines, 2u);
  EXPECT_EQ(redirect_lines, redirects);

  // `rtamp log to-mcap` of the log: the same messages on every channel.
  log_to_mcap(log, converted, McapCompression::None, nullptr);
  EXPECT_EQ(messages(converted), topics);
  if (!::testing::Test::HasFailure())
    for (const auto& f : {log, live, converted}) std::filesystem::remove(f);
}

TEST(EpisodeMcap, TheArmIsAChainOfTheUr5sFrames) {
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "episode_mcap_arm.mcap").string();
  const world::Scenario scenario = world::load_scenario("3-block");
  const std::array<double, 6> q{0.1, -1.2, 1.4, -0.3, 1.57, 0.25};
  {
    EpisodeMcap m(path, McapCompression::None, &scenario);
    m.arm(4.5, q);
    m.close();
  }
  const auto topics = messages(path);
  ASSERT_EQ(topics.at("/joint_states").size(), 1u);
  const json joints = json::parse(topics.at("/joint_states")[0]);
  EXPECT_EQ(joints.at("timestamp"), stamp(4500000000));
  ASSERT_EQ(joints.at("joints").size(), 6u);
  EXPECT_EQ(joints.at("joints")[0].at("name"), "shoulder_pan_joint");
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(joints.at("joints")[i].at("position").get<double>(), q[i]);

  robot::Ur5Kinematics::Config config;
  config.base = robot::Ur5Kinematics::base_pose(scenario.robot);
  const auto expected = robot::Ur5Kinematics(config).link_frames({q[0], q[1], q[2], q[3], q[4], q[5]});
  const json tf = json::parse(topics.at("/tf").at(0)).at("transforms");
  ASSERT_EQ(tf.size(), expected.size());
  Eigen::Isometry3d world = Eigen::Isometry3d::Identity();
  std::string parent = "world";
  for (std::size_t i = 0; i < tf.size(); ++i) {
    EXPECT_EQ(tf[i].at("parent_frame_id"), parent);
    parent = tf[i].at("child_frame_id").get<std::string>();
    const auto& p = tf[i].at("translation");
    const auto& r = tf[i].at("rotation");
    Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
    local.linear() = Eigen::Quaterniond(r.at("w"), r.at("x"), r.at("y"), r.at("z")).toRotationMatrix();
    local.translation() = Eigen::Vector3d(p.at("x"), p.at("y"), p.at("z"));
    world = world * local;
    EXPECT_TRUE(world.isApprox(expected[i], 1e-9)) << parent;
  }
  EXPECT_EQ(parent, "ur5/link6");
}

// Decodes base64 (the standard alphabet, padded).
std::string unbase64(const std::string& text) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned v = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const auto k = alphabet.find(c);
    if (k == std::string::npos) ADD_FAILURE() << "not base64: " << c;
    v = v << 6 | static_cast<unsigned>(k);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>(v >> bits & 0xff);
    }
  }
  return out;
}

// A PNG's size and RGB pixels (libpng), or false.
bool decode_png(const std::string& bytes, int& width, int& height, std::vector<unsigned char>& rgb) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) return false;
  image.format = PNG_FORMAT_RGB;
  rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) return false;
  width = static_cast<int>(image.width);
  height = static_cast<int>(image.height);
  return true;
}

struct CameraRun {
  std::map<std::string, std::vector<std::string>> topics;
  std::vector<double> frames;  // the camera records' times
};

// A short MuJoCo episode of 3-block-tray seen through its overhead camera, to MCAP.
CameraRun camera_run(double period) {
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "episode_mcap_camera.mcap").string();
  EpisodeOptions o;
  o.world_settings.perception = "camera";
  o.loop.max_time = 3;
  o.outputs.mcap = path;
  o.outputs.mcap_compression = McapCompression::None;
  o.outputs.mcap_image_period = period;
  run_episode(world::load_scenario("3-block-tray"), o);
  CameraRun r;
  r.topics = messages(path);
  for (const std::string& text : r.topics["/rtamp/log"]) {
    const json j = json::parse(text);
    if (j.at("ev") == "camera") r.frames.push_back(j.at("t").get<double>());
  }
  std::filesystem::remove(path);
  return r;
}

TEST(EpisodeMcap, CameraImagesAndTheirDetectionBoxes) {
  const world::Scenario scenario = world::load_scenario("3-block-tray");
  const std::vector<world::Camera> cameras = world::cameras_of(scenario);
  const world::Camera& camera = world::primary_camera(cameras);
  const std::string image_topic = "/camera/" + camera.name + "/image", boxes_topic = "/camera/" + camera.name + "/annotations";
  const CameraRun r = camera_run(1);
  ASSERT_GT(r.frames.size(), 20u);  // 10 frames a world second for 3 s
  // One image a world second: the first frame's, then the first frame 1 s or more after the last.
  std::vector<std::uint64_t> expected;
  double last = -INFINITY;
  for (const double t : r.frames)
    if (t + 1e-9 >= last + 1) expected.push_back(static_cast<std::uint64_t>(std::llround(t * 1e9))), last = t;
  ASSERT_EQ(r.topics.at(image_topic).size(), expected.size());
  ASSERT_EQ(r.topics.at(boxes_topic).size(), expected.size());
  std::set<std::string> labels;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const json image = json::parse(r.topics.at(image_topic)[i]);
    EXPECT_EQ(nanos_of(image.at("timestamp")), expected[i]);
    EXPECT_EQ(image.at("frame_id"), "camera/" + camera.name);
    EXPECT_EQ(image.at("format"), "png");
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    ASSERT_TRUE(decode_png(unbase64(image.at("data")), width, height, rgb)) << "image " << i;
    EXPECT_EQ(width, camera.width);
    EXPECT_EQ(height, camera.height);
    EXPECT_GT(*std::max_element(rgb.begin(), rgb.end()), 0) << "a black image";
    const json boxes = json::parse(r.topics.at(boxes_topic)[i]);
    EXPECT_EQ(boxes.at("points").size(), boxes.at("texts").size());
    EXPECT_GE(boxes.at("points").size(), 3u) << "the three blocks and the tray are in view";
    for (const json& box : boxes.at("points")) {
      EXPECT_EQ(nanos_of(box.at("timestamp")), expected[i]);
      EXPECT_EQ(box.at("type"), 2);
      ASSERT_EQ(box.at("points").size(), 4u);
      for (const json& p : box.at("points")) {
        EXPECT_GE(p.at("x").get<double>(), 0);
        EXPECT_LE(p.at("x").get<double>(), width);
        EXPECT_GE(p.at("y").get<double>(), 0);
        EXPECT_LE(p.at("y").get<double>(), height);
      }
    }
    for (const json& text : boxes.at("texts")) labels.insert(text.at("text").get<std::string>());
  }
  // The things are named by the belief, with its states.
  for (const char* label : {"o1 visible", "o2 visible", "o3 visible", "r3 visible"})
    EXPECT_TRUE(labels.count(label)) << label;

  // Every frame (period 0), or none (inf: no camera channels at all).
  const CameraRun every = camera_run(0);
  EXPECT_EQ(every.topics.at(image_topic).size(), every.frames.size());
  const CameraRun none = camera_run(INFINITY);
  EXPECT_FALSE(none.frames.empty());
  EXPECT_EQ(none.topics.count(image_topic), 0u);
  EXPECT_EQ(none.topics.count(boxes_topic), 0u);
}

}  // namespace
}  // namespace rtamp::episode
