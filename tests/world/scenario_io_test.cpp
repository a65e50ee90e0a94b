// Reading and writing scenarios: what the loader fills in (defaults, 2-D
// positions, sorting, source locations), the round trip
// parse(to_yaml(s)) == s on hand-written, built-in, generated and randomly
// perturbed scenarios, and the complete example of docs/scenario.md.
#include <gtest/gtest.h>

#include <algorithm>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/compare.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::world {
namespace {

const char* kFull = R"yaml(# a comment
name: full
description: |
  Two lines: "quoted", back\slash,
  and unicode: é ✓
robot: {model: ur5, base: [0.1, -0.2, 0.05], yaw: 1.5707963267948966}
regions:
  - name: r1
    center: [0.4, 0.3]
    size: [0.3, 0.3, 0.01]
    capacity: 5
  - {name: r2, center: [0.4, -0.3, 0], size: [0.3, 0.3]}
containers:
  - {name: t1, position: [0.4, -0.3]}
  - {name: bin, class: basket, position: [0.4, 0.3, 0], size: [0.1, 0.1, 0.08], capacity: 2}
objects:
  - {name: o1, position: [0.3, 0.4]}
  - {name: o2, class: ball, position: [0.4, 0.3, 0.01], size: [0.05, 0.05, 0.05]}
propositions:
  z_last: "count object in r2 >= 2"
  all_in_r2: all block in r2
  a_first: "!(o1 in r1) | (any ball in t1 & t1 in r2)"
task: "F G all_in_r2 & G F z_last"
operator:
  - {time: 30, action: take_from_gripper}
  - {time: 12.5, action: relocate, object: o1, to: r2}
  - {time: 12.5, action: relocate, container: t1, to: r1, position: [0.5, 0.35, 0]}
  - {time: 14, action: add, object: o9, to: t1}
  - {time: 15, action: add_container, container: t2, class: tray, position: [0.35, -0.35, 0]}
  - {time: 16, action: remove, object: o9}
  - {time: 17, action: remove_container, container: t2}
  - {time: 18, action: take_from_gripper, to: r1}
  - {time: 20, action: new_task, task: "F G in_r1", propositions: {in_r1: "all object in r1"}}
  - {time: 19, action: new_task, task: "F G all_in_r2"}
)yaml";

TEST(ScenarioIO, ReadsEveryField) {
  const Scenario s = parse_scenario(kFull, "full.yaml");
  EXPECT_EQ(s.name, "full");
  EXPECT_EQ(s.source, "full.yaml");
  EXPECT_EQ(s.description, "Two lines: \"quoted\", back\\slash,\nand unicode: é ✓\n");
  EXPECT_EQ(s.robot.base, (Vec3{0.1, -0.2, 0.05}));
  EXPECT_DOUBLE_EQ(s.robot.yaw, 1.5707963267948966);
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.regions[0].center, (Vec3{0.4, 0.3, 0}));  // [x, y]: z = 0
  EXPECT_EQ(s.regions[0].size, (Vec3{0.3, 0.3, 0.01}));
  EXPECT_EQ(s.regions[0].capacity, 5);
  EXPECT_EQ(s.regions[1].capacity, Region{}.capacity);  // default
  EXPECT_EQ(s.regions[0].where.line, 8);
  EXPECT_EQ(s.regions[0].where.column, 5);
  EXPECT_EQ(s.regions[0].where.file, "full.yaml");
  ASSERT_EQ(s.containers.size(), 2u);
  EXPECT_EQ(s.containers[0].cls, "tray");  // default class, size and capacity
  EXPECT_EQ(s.containers[0].size, Container{}.size);
  EXPECT_EQ(s.containers[0].capacity, Container{}.capacity);
  EXPECT_EQ(s.containers[1].cls, "basket");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].cls, "block");
  EXPECT_EQ(s.objects[0].size, Object{}.size);
  EXPECT_EQ(s.objects[1].position, (Vec3{0.4, 0.3, 0.01}));
  // Propositions keep the file's order, their text and a parsed expression;
  // `where` is the first character of the expression (after the quote).
  ASSERT_EQ(s.propositions.size(), 3u);
  EXPECT_EQ(s.propositions[0].name, "z_last");
  EXPECT_EQ(s.propositions[1].name, "all_in_r2");
  EXPECT_EQ(s.propositions[1].text, "all block in r2");
  EXPECT_EQ(s.propositions[2].name, "a_first");
  EXPECT_EQ(to_string(s.propositions[2].expr), "!(o1 in r1) | any ball in t1 & t1 in r2");
  EXPECT_EQ(s.propositions[0].where.line, 20);
  EXPECT_EQ(s.propositions[0].where.column, 12);
  EXPECT_EQ(s.propositions[1].where.column, 14);
  EXPECT_EQ(s.task, "F G all_in_r2 & G F z_last");
  EXPECT_EQ(s.task_where.line, 23);
  EXPECT_EQ(s.task_where.column, 8);
  // Interventions sorted by time, stable for equal times.
  ASSERT_EQ(s.interventions.size(), 8u);
  std::vector<double> times;
  for (const Intervention& iv : s.interventions) times.push_back(iv.time);
  EXPECT_EQ(times, (std::vector<double>{12.5, 12.5, 14, 15, 16, 17, 18, 30}));
  EXPECT_EQ(s.interventions[0].subject, "o1");
  EXPECT_EQ(s.interventions[1].subject, "t1");
  EXPECT_EQ(s.interventions[1].kind, Intervention::Kind::Relocate);
  ASSERT_TRUE(s.interventions[1].position.has_value());
  EXPECT_EQ(*s.interventions[1].position, (Vec3{0.5, 0.35, 0}));
  EXPECT_EQ(s.interventions[2].kind, Intervention::Kind::Add);
  EXPECT_EQ(s.interventions[2].cls, "block");  // default class of add
  EXPECT_EQ(s.interventions[2].location, "t1");
  EXPECT_EQ(s.interventions[3].kind, Intervention::Kind::AddContainer);
  EXPECT_EQ(s.interventions[3].cls, "tray");
  EXPECT_FALSE(s.interventions[3].position->at(2) != 0);
  EXPECT_EQ(s.interventions[4].kind, Intervention::Kind::Remove);
  EXPECT_EQ(s.interventions[5].kind, Intervention::Kind::RemoveContainer);
  EXPECT_EQ(s.interventions[6].kind, Intervention::Kind::TakeFromGripper);
  EXPECT_EQ(s.interventions[6].location, "r1");
  EXPECT_TRUE(s.interventions[7].location.empty());
}

void expect_round_trip(const Scenario& s) {
  const std::string yaml = to_yaml(s);
  Scenario back;
  try {
    back = parse_scenario(yaml, "round-trip.yaml");
  } catch (const Error& e) {
    FAIL() << e.what() << "\n" << yaml;
  }
  EXPECT_EQ(first_difference(s, back), "") << yaml;
  EXPECT_EQ(to_yaml(back), yaml);  // the writer is a fixed point
}

TEST(ScenarioIO, ReadsNewTasksSortedByTimeApartFromTheInterventions) {
  const Scenario s = parse_scenario(kFull, "full.yaml");
  ASSERT_EQ(s.task_changes.size(), 2u);
  EXPECT_EQ(s.interventions.size(), 8u);
  EXPECT_EQ(s.task_changes[0].time, 19);
  EXPECT_EQ(s.task_changes[0].task, "F G all_in_r2");
  EXPECT_TRUE(s.task_changes[0].propositions.empty());
  EXPECT_EQ(s.task_changes[1].task, "F G in_r1");
  ASSERT_EQ(s.task_changes[1].propositions.size(), 1u);
  EXPECT_EQ(s.task_changes[1].propositions[0].name, "in_r1");
  EXPECT_EQ(s.task_changes[1].propositions[0].text, "all object in r1");
  EXPECT_EQ(s.task_changes[1].by, "script");
  // Located in the file: the task's text, for errors with a caret.
  EXPECT_EQ(s.task_changes[1].task_where.file, "full.yaml");
  const std::string text = kFull;
  const std::size_t at = text.find("\"F G in_r1\"");
  EXPECT_EQ(s.task_changes[1].task_where.line, 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  EXPECT_EQ(s.task_changes[1].task_where.column,
            static_cast<int>(at - text.rfind('\n', at)) + 1);  // after the opening quote
}

TEST(ScenarioIO, RoundTripHandWritten) { expect_round_trip(parse_scenario(kFull, "full.yaml")); }

TEST(ScenarioIO, RoundTripBuiltins) {
  for (const std::string& n : builtin_scenario_names()) expect_round_trip(load_scenario(n));
}

TEST(ScenarioIO, RoundTripGenerated) {
  for (int seed = 1; seed <= 20; ++seed) {
    GeneratorOptions o;
    o.regions = 2 + seed % 4;
    o.objects = 1 + seed % 10;
    o.containers = seed % 2;
    o.layout = seed % 3 ? GeneratorOptions::Layout::Random : GeneratorOptions::Layout::Line;
    o.seed = static_cast<std::uint64_t>(seed);
    expect_round_trip(generate_scenario(o));
  }
}

// Text fields survive any characters YAML could misread: quotes, backslashes,
// colons, comment marks, control characters, leading blanks, unicode, and
// words that YAML would read as something other than text.
TEST(ScenarioIO, RoundTripAwkwardText) {
  const std::vector<std::string> texts = {
      "null", "true", "No", "~", "3-block", "a b", "#x", "x: y", "- x", "'q'", "\"dq\"", "back\\slash", " lead",
      "trail ", "tab\there", "line\nbreak", "bell\x07", "del\x7f", "é ✓ 漢字", "[1, 2]", "{a: b}", "&anchor", "*alias",
      "!tag", "%directive", "@at", "`tick", "|", ">", "?", ",", "---", "...", "0.5", "1e3", "0x10", ""};
  Scenario base = parse_scenario(kFull, "full.yaml");
  for (const std::string& t : texts) {
    Scenario s = base;
    if (!t.empty()) s.name = t;
    s.description = t;
    expect_round_trip(s);
  }
}

// Doubles are written in the shortest form that reads back bit for bit.
TEST(ScenarioIO, RoundTripRandomNumbers) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  Scenario base = parse_scenario(kFull, "full.yaml");
  for (int i = 0; i < 200; ++i) {
    Scenario s = base;
    for (Object& o : s.objects) {
      o.position[0] += jitter(rng) / 10;
      o.position[1] += jitter(rng) / 10;
      o.size[2] = 0.01 + std::abs(jitter(rng));
    }
    s.robot.yaw = jitter(rng) * 100;
    s.regions[0].center[2] = jitter(rng) * 1e-7;
    std::vector<double> times;
    for (std::size_t k = 0; k < s.interventions.size(); ++k) times.push_back(std::ldexp(static_cast<double>(rng() >> 12), -40));
    std::sort(times.begin(), times.end());
    for (std::size_t k = 0; k < s.interventions.size(); ++k) s.interventions[k].time = times[k];
    ASSERT_NO_THROW(validate(s));
    expect_round_trip(s);
  }
}

TEST(ScenarioIO, WriterFormat) {
  const std::string yaml = to_yaml(load_scenario("3-block"));
  EXPECT_NE(yaml.find("name: \"3-block\"\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("  - {name: r1, center: [0.4, 0.32, 0], size: [0.3, 0.3], capacity: 4}\n"), std::string::npos)
      << yaml;
  EXPECT_NE(yaml.find("  all_in_r2: \"all block in r2\"\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("task: \"F G all_in_r2\"\n"), std::string::npos) << yaml;
}

TEST(ScenarioIO, LoadsFilesAndReportsMissingOnes) {
  const std::string path = (std::filesystem::temp_directory_path() / "rtamp_world_io_test.yaml").string();
  {
    std::ofstream out(path);
    out << kFull;
  }
  const Scenario s = load_scenario(path);
  EXPECT_EQ(s.source, path);
  EXPECT_EQ(s.name, "full");
  std::remove(path.c_str());
  try {
    load_scenario(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("cannot read scenario"), std::string::npos) << e.what();
  }
}

// Document markers around a single scenario are fine.
TEST(ScenarioIO, SingleDocumentWithMarkers) {
  const std::string body = "name: m\nregions: [{name: r1, center: [0, 0], size: [1, 1]}]\nobjects: []\n"
                           "description: |\n  ---\n  ...\n  text\ntask: \"G true\"\n";
  for (const std::string& text : {body, "---\n" + body, "%YAML 1.2\n---\n" + body, body + "...\n",
                                  "# comment\n--- # start\n" + body + "... # end\n# bye\n"}) {
    Scenario s;
    ASSERT_NO_THROW(s = parse_scenario(text, "m.yaml")) << text;
    EXPECT_EQ(s.description, "---\n...\ntext\n");
  }
}

// The complete example in docs/scenario.md is a valid scenario.
TEST(ScenarioIO, DocumentationExampleParses) {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/docs/scenario.md");
  ASSERT_TRUE(in.good());
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const std::string open = "```yaml\n";
  const auto start = doc.find(open);
  ASSERT_NE(start, std::string::npos);
  const auto end = doc.find("```", start + open.size());
  ASSERT_NE(end, std::string::npos);
  const std::string example = doc.substr(start + open.size(), end - start - open.size());
  Scenario s;
  ASSERT_NO_THROW(s = parse_scenario(example, "docs/scenario.md example")) << example;
  EXPECT_FALSE(s.regions.empty());
  EXPECT_FALSE(s.containers.empty());
  EXPECT_FALSE(s.interventions.empty());
  expect_round_trip(s);
}

}  // namespace
}  // namespace rtamp::world
