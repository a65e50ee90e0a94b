// Unit tests of serve's parts that need no network: request parsing
// (request.hpp), the intervention check (intervention_check.hpp, against the
// scenario validator's rules), the layout of things (thing_layout.hpp), the
// hub's ordering (hub.hpp) and the joint angles of frames without them (arm_angles.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "rtamp/exec/episode_log.hpp"
#include "rtamp/serve/arm_angles.hpp"
#include "rtamp/serve/frame.hpp"
#include "rtamp/serve/hub.hpp"
#include "rtamp/util/json_text.hpp"
#include "rtamp/serve/intervention_check.hpp"
#include "rtamp/serve/request.hpp"
#include "rtamp/exec/thing_layout.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/intervention_rules.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::serve {
namespace {

using nlohmann::json;
using K = world::Intervention::Kind;

TEST(ServeRequest, ParsesInterventionsAndControls) {
  Request r = parse_request(R"({"type":"intervene","id":7,"kind":"relocate","subject":"o1","location":"r2"})");
  ASSERT_EQ(r.type, Request::Type::Intervene) << r.error;
  EXPECT_EQ(r.id, "7");
  EXPECT_EQ(r.intervention.kind, K::Relocate);
  EXPECT_EQ(r.intervention.subject, "o1");
  EXPECT_EQ(r.intervention.location, "r2");
  r = parse_request(R"({"type":"intervene","id":"a","kind":"add","class":"block","position":[0.4,0.3,0]})");
  ASSERT_EQ(r.type, Request::Type::Intervene) << r.error;
  EXPECT_EQ(r.id, "\"a\"");
  ASSERT_TRUE(r.intervention.position);
  EXPECT_DOUBLE_EQ((*r.intervention.position)[0], 0.4);
  r = parse_request(R"({"type":"control","id":1,"action":"speed","value":2.5})");
  ASSERT_EQ(r.type, Request::Type::Control);
  EXPECT_EQ(r.action, "speed");
  EXPECT_DOUBLE_EQ(*r.value, 2.5);
}

TEST(ServeRequest, RefusesWhatIsNotARequest) {
  struct Case {
    const char* text;
    const char* error;
  };
  for (const Case& c : std::vector<Case>{
           {"{", "malformed JSON"},
           {"[1]", "one JSON object"},
           {R"({"id":1})", "needs a 'type'"},
           {R"({"type":"dance"})", "unknown request type 'dance'"},
           {R"({"type":"intervene","kind":"teleport"})", "unknown intervention kind 'teleport'"},
           {R"({"type":"intervene","kind":"relocate","subject":5})", "'subject' must be a string"},
           {R"({"type":"intervene","kind":"relocate","position":[1,2]})", "'position' must be [x, y, z]"},
           {R"({"type":"intervene","kind":"relocate","position":[1,2,1e9]})", "within ±1000 m"},
           {R"({"type":"control","action":"fly"})", "unknown control action 'fly'"},
           {R"({"type":"control","action":"speed"})", "needs a 'value'"},
           {R"({"type":"control","id":{},"action":"pause"})", "'id' must be"},
       }) {
    const Request r = parse_request(c.text);
    EXPECT_EQ(r.type, Request::Type::Invalid) << c.text;
    EXPECT_NE(r.error.find(c.error), std::string::npos) << c.text << " -> " << r.error;
  }
  // The id is echoed when it could be read.
  EXPECT_EQ(parse_request(R"({"type":"dance","id":42})").id, "42");
  const json reply = json::parse(reply_message("42", false, "bad \xff byte"));
  EXPECT_EQ(reply["id"], 42);
  EXPECT_EQ(reply["ok"], false);
}

// A page's intervention and the same intervention scripted in the
// scenario file (validate.cpp) are refused with the same words — the part of
// the message after its owner ("intervention 'add': " / "operator action
// 'add' at t=0: "), kind names spelled each input's way.
TEST(ServeInterventionCheck, RefusesAsTheScenarioFileDoes) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  InterventionCheck check(s);
  const world::Placement now = world::initial_placement(s);
  struct Case {
    K kind;
    std::string subject, location, cls;
    std::optional<world::Vec3> position;
    std::string expected;  // a part of the message
  };
  const std::vector<Case> cases = {
      {K::Relocate, "o7", "r2", "", {}, "unknown object or container 'o7' at this time (did you mean"},
      {K::Relocate, "o1", "r5", "", {}, "unknown location 'r5' at this time (did you mean"},
      {K::Relocate, "o1", "r2", "", world::Vec3{0.40, 0.32, 0}, "is not inside region 'r2'"},
      {K::Relocate, "o1", "r2", "", world::Vec3{50, 50, 0}, "position [50, 50, 0] is off the table (x in ["},
      {K::Relocate, "o1", "", "", world::Vec3{0.4, -3, 0}, "is off the table"},
      {K::Add, "o9", "", "block", world::Vec3{-2, 0, 0}, "is off the table"},
      {K::Relocate, "r3", "r3", "", {}, "containers do not nest"},
      {K::Remove, "o9", "", "", {}, "unknown object 'o9' at this time"},
      {K::Remove, "r3", "", "", {}, "it is a container: use remove"},
      {K::RemoveContainer, "o1", "", "", {}, "it is an object: use remove"},
      {K::Add, "none", "r2", "block", {}, "reserved word"},
      {K::Add, "in", "r2", "block", {}, "reserved word"},
      {K::Add, "9x", "r2", "block", {}, "is not an identifier"},
      {K::Add, "o1", "r2", "block", {}, "'o1' already exists at this time"},
      {K::Add, "r1", "r2", "block", {}, "'r1' already exists at this time"},
      {K::Add, "o9", "r2", "object", {}, "class 'object' is reserved"},
      {K::Add, "o9", "r2", "tray", {}, "class 'tray' is already the class of containers"},
      {K::AddContainer, "t9", "r2", "block", {}, "class 'block' is already the class of objects"},
      {K::AddContainer, "o1", "r2", "tray", {}, "'o1' already exists at this time"},
      {K::Remove, "o1", "", "block", {}, "a class is only given to add and add"},
      {K::TakeFromGripper, "o1", "", "", {}, "names no object"},
      {K::Add, "o9", "", "block", {}, "needs a target"},
  };
  auto kinds_as_page = [](std::string m) {
    for (const char* k : {"add_container", "remove_container", "take_from_gripper"}) {
      std::string dashed = k;
      std::replace(dashed.begin(), dashed.end(), '_', '-');
      for (auto p = m.find(k); p != std::string::npos; p = m.find(k)) m.replace(p, dashed.size(), dashed);
    }
    return m;
  };
  for (const Case& c : cases) {
    world::Intervention v;
    v.kind = c.kind;
    v.subject = c.subject;
    v.location = c.location;
    v.cls = c.cls;
    v.position = c.position;
    const std::string page = check.check(v, now);
    world::Scenario scripted = s;
    scripted.interventions = {v};
    std::string file;
    try {
      world::validate(scripted);
    } catch (const Error& e) {
      file = e.message();
    }
    const std::string page_owner = std::string("intervention '") + kind_name(c.kind) + "': ";
    const std::string file_owner = std::string("operator action '") +
                                   world::intervention_kind_name(c.kind, world::InterventionSyntax::Scenario) +
                                   "' at t=0: ";
    ASSERT_EQ(page.rfind(page_owner, 0), 0u) << page;
    ASSERT_EQ(file.rfind(file_owner, 0), 0u) << file;
    EXPECT_NE(page.find(c.expected), std::string::npos) << page;
    if (c.expected == "needs a target") continue;  // each names its own input's fields
    EXPECT_EQ(page.substr(page_owner.size()), kinds_as_page(file.substr(file_owner.size()))) << page << " | " << file;
  }
  // A page cannot bring a class the scenario does not have (a script can): the
  // palette's classes pass, others are refused (the file accepts them).
  for (const auto& [kind, cls] : std::vector<std::pair<K, std::string>>{{K::Add, "unicorn"}, {K::AddContainer, "crate"}}) {
    world::Intervention v;
    v.kind = kind;
    v.subject = "x9";
    v.location = "r2";
    v.cls = cls;
    EXPECT_NE(check.check(v, now).find("unknown class '" + cls + "'"), std::string::npos) << check.check(v, now);
    world::Scenario scripted = s;
    scripted.interventions = {v};
    EXPECT_NO_THROW(world::validate(scripted));
    v.cls = kind == K::Add ? "block" : "tray";
    EXPECT_EQ(check.check(v, now), "");
  }
  // Taking from an empty gripper passes the check in both; the world refuses it
  // with its own reason (exec's apply, the same for a scripted one).
  world::Intervention take;
  take.kind = K::TakeFromGripper;
  EXPECT_EQ(check.check(take, now), "");
}

TEST(ServeInterventionCheck, FollowsTheScenarioRules) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  InterventionCheck check(s);
  const world::Placement now = world::initial_placement(s);
  auto iv = [](K k, std::string subject, std::string location, std::string cls = {}) {
    world::Intervention v;
    v.kind = k;
    v.subject = std::move(subject);
    v.location = std::move(location);
    v.cls = std::move(cls);
    return v;
  };
  auto refused = [&](const world::Intervention& v, const std::string& why) {
    const std::string e = check.check(v, now);
    EXPECT_NE(e.find(why), std::string::npos) << "'" << e << "' lacks '" << why << "'";
  };
  EXPECT_EQ(check.check(iv(K::Relocate, "o1", "r2"), now), "");
  EXPECT_EQ(check.check(iv(K::Relocate, "o1", "r3"), now), "");  // into the tray
  EXPECT_EQ(check.check(iv(K::Add, "o4", "r2", "block"), now), "");
  EXPECT_EQ(check.check(iv(K::AddContainer, "t2", "r2", "tray"), now), "");
  EXPECT_EQ(check.check(iv(K::Remove, "o2", ""), now), "");
  EXPECT_EQ(check.check(iv(K::RemoveContainer, "r3", ""), now), "");
  EXPECT_EQ(check.check(iv(K::TakeFromGripper, "", ""), now), "");
  refused(iv(K::Relocate, "o7", "r2"), "unknown object or container 'o7'");
  refused(iv(K::Relocate, "o1", "r5"), "unknown location 'r5'");
  refused(iv(K::Relocate, "r3", "r3"), "containers do not nest");
  refused(iv(K::Relocate, "o1", ""), "needs a target");
  refused(iv(K::Add, "o1", "r2", "block"), "'o1' already exists");
  refused(iv(K::Add, "r1", "r2", "block"), "'r1' already exists");
  refused(iv(K::Add, "all_in_r2", "r2", "block"), "proposition");
  refused(iv(K::Add, "none", "r2", "block"), "reserved word");
  refused(iv(K::Add, "o9", "r2", "object"), "class 'object' is reserved");
  refused(iv(K::Add, "o9", "r2", "tray"), "is already the class of containers");
  refused(iv(K::AddContainer, "t9", "r2", "block"), "is already the class of objects");
  refused(iv(K::AddContainer, "t9", "r3", "tray"), "containers do not nest");
  refused(iv(K::Remove, "r3", ""), "it is a container");
  refused(iv(K::RemoveContainer, "o1", ""), "it is an object");
  refused(iv(K::Remove, "o1", "", "block"), "a class is only given");
  refused(iv(K::TakeFromGripper, "o1", ""), "names no object");
  // Fresh names skip every name in use.
  EXPECT_EQ(check.fresh_name(false), "o4");
  EXPECT_EQ(check.fresh_name(true), "t1");
  // A name that was an object stays one.
  world::Placement later = now;
  later.things.erase("o1");
  check.note(now);
  const std::string e = check.check(iv(K::AddContainer, "o1", "r2", "tray"), later);
  EXPECT_NE(e.find("was an object earlier"), std::string::npos) << e;
  EXPECT_EQ(check.check(iv(K::Add, "o1", "r2", "block"), later), "");  // an object again: fine
}

TEST(ServeThingLayout, ThingsInOneLocationGetDistinctSpots) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  exec::ThingLayout layout(s);
  world::Placement p = world::initial_placement(s);
  layout.update(p);
  EXPECT_DOUBLE_EQ(layout.position("o1")[0], 0.32);  // unmoved: the scenario position
  for (const char* n : {"o1", "o2", "o3"}) p.things[n].location = "r2";
  layout.update(p);
  const world::Region& r2 = *s.find_region("r2");
  const world::Footprint f = world::footprint(r2);
  for (const char* a : {"o1", "o2", "o3"}) {
    EXPECT_TRUE(f.contains_point(layout.position(a)[0], layout.position(a)[1])) << a;
    for (const char* b : {"o1", "o2", "o3"})
      if (std::string(a) < b) {
        const auto pa = layout.position(a), pb = layout.position(b);
        EXPECT_TRUE(std::abs(pa[0] - pb[0]) >= 0.04 || std::abs(pa[1] - pb[1]) >= 0.04) << a << " " << b;
      }
  }
  // Contents move with their container.
  p.things["o1"].location = "r3";
  layout.update(p);
  const auto before = layout.position("o1");
  p.things["r3"].location = "r2";
  layout.update(p);
  const auto tray = layout.position("r3");
  EXPECT_TRUE(f.contains_point(tray[0], tray[1]));
  EXPECT_NE(layout.position("o1")[1], before[1]);
}

class RecordingClient final : public Client {
 public:
  void send(std::shared_ptr<const std::string> m, Slot) override { got.push_back(json::parse(*m)); }
  std::vector<json> got;
};

// The messages written without nlohmann::json read back as the values they were
// written from: strings with quotes, backslashes, control characters and UTF-8
// (bytes that are not UTF-8 become U+FFFD: the text stays valid UTF-8),
// doubles exactly (shortest form), non-finite numbers as null.
TEST(ServeJsonText, ReadsBackAsWritten) {
  using nlohmann::json;
  for (const std::string& s : {std::string("plain"), std::string("q\"uote \\ back/slash"), std::string("tab\tnl\ncr\r\x01\x1f"),
                              std::string("caf\xc3\xa9 \xe2\x86\x92 \xf0\x9f\x98\x80"), std::string()}) {
    std::string out;
    json_text::append_string(out, s);
    EXPECT_EQ(json::parse(out).get<std::string>(), s) << out;
    EXPECT_EQ(out, json(s).dump());
  }
  for (const std::string& bad : {std::string("a\xff b"), std::string("\xc3"), std::string("\xed\xa0\x80x"), std::string("\xe2\x86")}) {
    std::string out;
    json_text::append_string(out, bad);
    const std::string back = json::parse(out).get<std::string>();  // parse() refuses text that is not UTF-8
    EXPECT_NE(back.find("\xef\xbf\xbd"), std::string::npos) << out;
    EXPECT_EQ(back.find('\xff'), std::string::npos);
  }
  for (const double v : {0.0, -0.0, 1.0, -2.5, 0.1, 1e-7, 123456789.123, 1e300, 0.32000000000000001, 44.1406}) {
    std::string out;
    json_text::append_number(out, v);
    EXPECT_EQ(json::parse(out).get<double>(), v) << out;
  }
  for (const double v : {std::nan(""), 1.0 / 0.0}) {
    std::string out;
    json_text::append_number(out, v);
    EXPECT_EQ(out, "null");
  }
  // The episode log's tick record, written directly: the text nlohmann dumps.
  exec::EpisodeLog log;
  std::vector<std::string> lines;
  log.add_sink([&](const std::string& r) { lines.push_back(r); });
  log.on_tick(1.5, bt::Status::Running, "move(o\"1, r2)\n");
  log.on_tick(2, bt::Status::Success, "");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "{\"ev\":\"tick\",\"running\":\"move(o\\\"1, r2)\\n\",\"status\":\"RUNNING\",\"t\":1.5}");
  const json tick{{"ev", "tick"}, {"status", "SUCCESS"}, {"running", ""}, {"t", 2.0}};
  EXPECT_EQ(lines[1], tick.dump());
  // A frame: every member, at full precision as a message, rounded to 1e-3 as a log record.
  serve::Frame f;
  f.t = 1.25;
  f.q = std::array<double, 6>{0.1, -1.2, 1.3, 0.0004, 1.5, 3.14159};
  f.tool = {0.4, 0.1, 0.3};
  f.held = "o\"1";
  f.things.push_back({"o\"1", "block", false, {0.3211, 0.4, 0.02}, {1, 0, 0, 0}, {0.04, 0.04, 0.04}, "hand"});
  f.things.push_back({"r3", "tray", true, {0.4, 0.25, 0}, {0.7071, 0, 0, 0.7071}, {0.3, 0.16, 0.03}, "r1"});
  const json m = json::parse(serve::frame_message(f));
  EXPECT_EQ(m["type"], "frame");
  EXPECT_EQ(m["t"].get<double>(), 1.25);
  EXPECT_EQ(m["q"][5].get<double>(), 3.14159);
  EXPECT_EQ(m["held"], "o\"1");
  ASSERT_EQ(m["things"].size(), 2u);
  EXPECT_EQ(m["things"][0]["name"], "o\"1");
  EXPECT_EQ(m["things"][0]["kind"], "object");
  EXPECT_EQ(m["things"][0]["pos"][0].get<double>(), 0.3211);
  EXPECT_EQ(m["things"][0]["at"], "hand");
  EXPECT_EQ(m["things"][1]["class"], "tray");
  EXPECT_EQ(m["things"][1]["kind"], "container");
  EXPECT_EQ(m["things"][1]["quat"][3].get<double>(), 0.7071);
  const std::string rec = serve::frame_record(f);
  EXPECT_EQ(rec.rfind("{\"ev\":\"frame\",", 0), 0u) << rec;
  const json r = json::parse(rec);
  EXPECT_FALSE(r.contains("t"));
  EXPECT_EQ(r["q"][5].get<double>(), 3.142);
  EXPECT_EQ(r["things"][0]["pos"][0].get<double>(), 0.321);
  f.q.reset();
  f.held.clear();
  const json none = json::parse(serve::frame_message(f));
  EXPECT_TRUE(none["q"].is_null());
  EXPECT_TRUE(none["held"].is_null());
}

TEST(ServeHub, ALateClientCatchesUpWithTheHistory) {
  Hub hub(R"({"mode":"live","world":"symbolic"})");
  hub.log_record(R"({"ev":"episode","t":0})");
  hub.tree(R"({"type":"tree","t":0,"nodes":[]})");
  hub.frame(0, R"({"type":"frame","t":0,"things":[]})");
  auto c = std::make_shared<RecordingClient>();
  hub.join(c);
  hub.log_record(R"({"ev":"plan","t":0.5})");
  ASSERT_EQ(c->got.size(), 3u);
  EXPECT_EQ(c->got[0]["type"], "hello");
  EXPECT_EQ(c->got[0]["protocol"], 2);
  EXPECT_EQ(c->got[0]["history"].size(), 1u);
  EXPECT_EQ(c->got[0]["tree"]["nodes"], json::array());
  EXPECT_EQ(c->got[1]["type"], "frame");
  EXPECT_EQ(c->got[2]["type"], "log");
  EXPECT_EQ(c->got[2]["records"], json::parse(R"([{"ev":"plan","t":0.5}])"));
  hub.leave(c.get());
  hub.log_record(R"({"ev":"end","t":1})");
  EXPECT_EQ(c->got.size(), 3u);
  EXPECT_EQ(hub.history_size(), 3u);
}

// hello's task and automaton are the task in force: the constructor's, then the
// latest record that put one in force (the episode record's automaton, an applied
// task record; a refused one, or another record that holds the text "ev":"task",
// changes nothing), and after a seek the latest one of the history given.
TEST(ServeHub, HelloNamesTheTaskInForce) {
  Hub hub(R"({"mode":"live","world":"symbolic","task":"F a","automaton":{"states":[],"edges":[]}})");
  const auto task_of = [&] { return json::parse(hub.hello()).at("task"); };
  const auto automaton_of = [&] { return json::parse(hub.hello()).at("automaton"); };
  EXPECT_EQ(task_of(), "F a");
  EXPECT_EQ(json::parse(hub.hello()).at("mode"), "live");
  const std::string episode = R"({"automaton":{"edges":[],"states":[{"id":0}]},"ev":"episode","task":"F a","t":0})";
  const std::string applied = R"({"applied":true,"automaton":{"edges":[],"states":[{"id":0},{"id":1}]},"by":"page","ev":"task","task":"F b","t":2})";
  hub.log_record(episode);
  EXPECT_EQ(automaton_of(), json::parse(R"({"edges":[],"states":[{"id":0}]})"));
  hub.log_record(R"({"ev":"replan","why":"a new task was given: \"ev\":\"task\"","t":1})");
  hub.log_record(R"({"automaton":{"edges":[],"states":[]},"ev":"plan","start":{"ev":"task"},"task":"F z","t":1})");
  hub.log_record(R"({"applied":false,"by":"page","ev":"task","refused":"no","task":"F c","t":1.5})");
  EXPECT_EQ(task_of(), "F a");
  hub.log_record(applied);
  EXPECT_EQ(task_of(), "F b");
  EXPECT_EQ(automaton_of()["states"].size(), 2u);
  hub.log_record(R"({"applied":true,"automaton":{"edges":[],"states":[]},"by":"api","ev":"task","propositions":{"ev":"episode"},"task":"F d","t":3})");
  EXPECT_EQ(task_of(), "F d");
  auto c = std::make_shared<RecordingClient>();
  hub.join(c);
  EXPECT_EQ(c->got.at(0)["task"], "F d");
  // A seek: the history up to the time shown decides.
  hub.reset({episode, applied}, "", "", "", {});
  EXPECT_EQ(task_of(), "F b");
  EXPECT_EQ(c->got.back()["type"], "hello");
  EXPECT_EQ(c->got.back()["task"], "F b");
  hub.reset({}, "", "", "", {});
  EXPECT_EQ(task_of(), "F a");
  EXPECT_EQ(automaton_of(), json::parse(R"({"states":[],"edges":[]})"));
}

// Records not urgent wait for the next message of any kind (or a flush, or a
// join) and go out together, in order; an urgent one takes the waiting ones with
// it. A client that joins meanwhile gets them in its hello, and never again.
TEST(ServeHub, RecordsThatAreNotUrgentGoOutTogetherInOrderAndOnce) {
  Hub hub(R"({"mode":"live","world":"symbolic"})");
  auto a = std::make_shared<RecordingClient>();
  hub.join(a);
  ASSERT_EQ(a->got.size(), 1u);  // hello
  hub.log_record(R"({"ev":"tick","t":0.02})", false);
  hub.log_record(R"({"ev":"tick","t":0.04})", false);
  EXPECT_EQ(a->got.size(), 1u) << "not urgent: held";
  hub.log_record(R"({"ev":"action","t":0.05})");
  ASSERT_EQ(a->got.size(), 2u);
  EXPECT_EQ(a->got[1]["records"].size(), 3u);
  EXPECT_EQ(a->got[1]["records"][0]["t"], 0.02);
  EXPECT_EQ(a->got[1]["records"][2]["ev"], "action");
  hub.log_record(R"({"ev":"tick","t":0.06})", false);
  hub.frame(0.06, R"({"type":"frame","t":0.06,"things":[]})");
  ASSERT_EQ(a->got.size(), 4u);
  EXPECT_EQ(a->got[2]["records"].size(), 1u) << "the frame takes the waiting record before it";
  EXPECT_EQ(a->got[3]["type"], "frame");
  hub.log_record(R"({"ev":"tick","t":0.08})", false);
  auto b = std::make_shared<RecordingClient>();
  hub.join(b);
  ASSERT_EQ(a->got.size(), 5u);
  EXPECT_EQ(a->got[4]["records"][0]["t"], 0.08) << "a join sends what waited";
  ASSERT_EQ(b->got.size(), 2u);  // hello, frame
  EXPECT_EQ(b->got[0]["history"].size(), 5u);
  hub.log_record(R"({"ev":"tick","t":0.1})", false);
  hub.flush();
  hub.flush();
  ASSERT_EQ(b->got.size(), 3u);
  EXPECT_EQ(b->got[2]["records"].size(), 1u) << "the new client gets only what came after its hello";
  EXPECT_EQ(a->got.size(), 6u);
  EXPECT_EQ(hub.history_size(), 6u);
}

}  // namespace
}  // namespace rtamp::serve

namespace rtamp::serve {
namespace {

// Frames without joint angles get the UR5's: forward kinematics (the robot
// layer's, and the page's own in the browser tests) of the filled angles puts
// the tool at the frame's tool point with elbow and wrists above it, over a
// path across both regions; a point out of reach gives home; a frame with
// angles keeps them.
TEST(ServeArmAngles, ReachTheToolPointElbowUp) {
  const world::Scenario s = world::load_scenario("3-block-tray");
  ArmAngles arm(s.robot);
  for (int i = 0; i <= 20; ++i) {
    exec::Frame f;
    f.tool = {0.40, 0.32 - 0.64 * i / 20.0, 0.02 + 0.1 * (i % 3)};
    arm.fill(f);
    ASSERT_TRUE(f.q);
    const auto frames = arm.kinematics().link_frames(*f.q);
    const Eigen::Vector3d tool = arm.kinematics().tool_point(*f.q);
    EXPECT_LT((tool - Eigen::Vector3d(f.tool[0], f.tool[1], f.tool[2])).norm(), 1e-6) << i;
    for (int k : {2, 3, 4}) EXPECT_GT(frames[static_cast<std::size_t>(k)].translation().z(), f.tool[2]) << i << " frame " << k;
  }
  exec::Frame far;
  far.tool = {3, 3, 0};
  arm.fill(far);
  EXPECT_EQ(*far.q, arm.home());
  exec::Frame given;
  given.q = std::array<double, 6>{1, 2, 3, 4, 5, 6};
  arm.fill(given);
  EXPECT_EQ((*given.q)[5], 6);
}

}  // namespace
}  // namespace rtamp::serve
