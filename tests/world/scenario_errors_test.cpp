// Every kind of scenario error a user can make is an rtamp::Error that says
// what is wrong and points at the right line and column of the YAML file.
#include <gtest/gtest.h>

#include <sstream>

#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::world {
namespace {

struct Case {
  const char* label;
  std::string yaml;
  int line;
  // The error's column: where this text first starts in that line, or, if it
  // contains '^', the position of the '^' within it (the '^' itself removed).
  std::string at;
  const char* message;
};

// Lines 1-9 of a valid scenario; cases replace or append lines.
const std::string kHead =
    "name: t\n"                                                                     // 1
    "regions:\n"                                                                    // 2
    "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: 4}\n"       // 3
    "  - {name: r2, center: [0.4, -0.3, 0], size: [0.3, 0.3], capacity: 4}\n"      // 4
    "objects:\n"                                                                    // 5
    "  - {name: o1, position: [0.4, 0.3, 0]}\n"                                     // 6
    "propositions:\n"                                                               // 7
    "  p: \"all block in r2\"\n";                                                   // 8
const std::string kTask = "task: \"F G p\"\n";                                      // 9

std::string valid() { return kHead + kTask; }

// kHead with line `n` (1-based) replaced by `text` (no newline).
std::string with_line(int n, const std::string& text) {
  std::string out;
  std::string all = valid();
  int line = 1;
  std::size_t start = 0;
  while (start < all.size()) {
    const std::size_t end = all.find('\n', start);
    std::string cur = all.substr(start, end - start);
    out += (line == n ? text : cur) + "\n";
    start = end + 1;
    ++line;
  }
  return out;
}

void check(const Case& c) {
  SCOPED_TRACE(c.label);
  try {
    parse_scenario(c.yaml, "t.yaml");
    ADD_FAILURE() << "accepted:\n" << c.yaml;
  } catch (const Error& e) {
    EXPECT_NE(e.message().find(c.message), std::string::npos) << "message: " << e.message();
    EXPECT_EQ(e.where().file, "t.yaml");
    EXPECT_EQ(e.where().line, c.line) << e.what();
    std::istringstream lines(c.yaml);
    std::string text;
    for (int i = 0; i < c.line && std::getline(lines, text);) ++i;
    std::string at = c.at;
    const auto caret = at.find('^');
    if (caret != std::string::npos) at.erase(caret, 1);
    const auto col = text.find(at);
    ASSERT_NE(col, std::string::npos) << "'" << at << "' is not in line " << c.line << ": " << text;
    const int expected = static_cast<int>(col + (caret == std::string::npos ? 0 : caret)) + 1;
    EXPECT_EQ(e.where().column, expected) << e.what() << "\n" << text;
    // what() is "file:line:col: message".
    EXPECT_EQ(std::string(e.what()).rfind("t.yaml:" + std::to_string(c.line) + ":", 0), 0u) << e.what();
  }
}

TEST(ScenarioErrors, TheValidBaseParses) { EXPECT_NO_THROW(parse_scenario(valid(), "t.yaml")); }

TEST(ScenarioErrors, Syntax) {
  check({"broken flow list", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0, size: [0.3, 0.3]}"), 3, "]^}", "invalid YAML"});
  check({"tab indentation", "name: t\nregions:\n\t- {name: r1}\n", 3, "-", "invalid YAML"});
  check({"empty file", "", 1, "", "empty"});
  check({"comments only", "# nothing\n", 1, "#", "empty"});
  check({"root is a list", "- a\n- b\n", 1, "-", "must be a mapping"});
  check({"two documents", valid() + "---\nname: u\n", 10, "---", "more than one YAML document"});
  check({"content after the end marker", valid() + "...\nname: u\n", 11, "name", "more than one YAML document"});
  check({"yaml-cpp LoadAll loop input", "!(o2b,)", 1, "!", "must be a mapping"});
}

TEST(ScenarioErrors, UnknownKeys) {
  check({"root typo", with_line(5, "objets:"), 5, "objets", "unknown key 'objets' in scenario (did you mean 'objects'?)"});
  check({"region typo", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capasity: 4}"), 3,
         "capasity", "unknown key 'capasity' in region (did you mean 'capacity'?)"});
  check({"key of another kind of element", with_line(6, "  - {name: o1, position: [0.4, 0.3, 0], capacity: 2}"), 6,
         "capacity", "unknown key 'capacity' in object"});
  check({"robot typo", valid() + "robot: {model: ur5, bse: [0, 0, 0]}\n", 10, "bse", "did you mean 'base'?"});
  check({"duplicate key", valid() + "name: u\n", 10, "name", "duplicate key 'name' in scenario"});
  check({"key not used by the action", valid() + "operator:\n  - {time: 1, action: remove, object: o1, to: r1}\n", 11,
         "to:", "unknown key 'to' in operator action 'remove' (expected one of: time, action, object)"});
}

TEST(ScenarioErrors, WrongTypes) {
  check({"capacity text", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: four}"), 3,
         "four", "region 'r1': capacity must be an integer, found 'four'"});
  check({"capacity fraction", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: 2.5}"),
         3, "2.5", "must be an integer"});
  check({"capacity overflow",
         with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: 99999999999}"), 3, "999",
         "out of range"});
  check({"quoted number", with_line(6, "  - {name: o1, position: [\"0.4\", 0.3, 0]}"), 6, "\"0.4\"",
         "position must be a number, found the quoted string '0.4' (write it without quotes)"});
  check({"quoted capacity", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: \"6\"}"), 3,
         "\"6\"", "capacity must be an integer, found the quoted string '6' (write it without quotes)"});
  check({"short vector", with_line(6, "  - {name: o1, position: [0.4]}"), 6, "[0.4]",
         "position must be a list [x, y] or [x, y, z], found a list of 1 numbers"});
  check({"vector is text", with_line(6, "  - {name: o1, position: here}"), 6, "here", "must be a list"});
  check({"object size 2d", with_line(6, "  - {name: o1, position: [0.4, 0.3, 0], size: [0.04, 0.04]}"), 6,
         "[0.04, 0.04]", "size must be a list [x, y, z]"});
  check({"nan", with_line(6, "  - {name: o1, position: [nan, 0.3, 0]}"), 6, "nan", "must be a finite number"});
  check({"infinity", with_line(6, "  - {name: o1, position: [.inf, 0.3, 0]}"), 6, ".inf", "must be a number"});
  check({"regions not a list", "name: t\nregions: {r1: 1}\nobjects: []\ntask: p\n", 2, "{", "'regions' must be a list"});
  check({"region is a word", "name: t\nregions:\n  - r1\nobjects: []\ntask: p\n", 3, "r1", "a region must be a mapping"});
  check({"name is a list", with_line(6, "  - {name: [o1], position: [0.4, 0.3, 0]}"), 6, "[o1]", "must be a name"});
  check({"task is a list", kHead + "task: [F, p]\n", 9, "[", "task must be text"});
  check({"propositions a list", with_line(8, "  - p") , 8, "-", "propositions must be a mapping"});
  check({"time is text", valid() + "operator:\n  - {time: soon, action: remove, object: o1}\n", 11, "soon",
         "time must be a number"});
}

TEST(ScenarioErrors, MissingFields) {
  check({"no task", kHead, 1, "name", "missing the required key 'task'"});
  check({"no name", valid().substr(8), 1, "regions", "missing the required key 'name'"});
  check({"task without value", kHead + "task:\n", 9, "task", "'task' of scenario has no value"});
  check({"region without center", with_line(3, "  - {name: r1, size: [0.3, 0.3]}"), 3, "{",
         "region 'r1' is missing the required key 'center'"});
  check({"object without name", with_line(6, "  - {position: [0.4, 0.3, 0]}"), 6, "{",
         "object is missing the required key 'name'"});
  check({"action without object", valid() + "operator:\n  - {time: 1, action: relocate, to: r2}\n", 11, "{",
         "missing the required key 'object'"});
  check({"action without target", valid() + "operator:\n  - {time: 1, action: relocate, object: o1}\n", 11, "{",
         "needs a target"});
  check({"no regions", "name: t\nregions: []\nobjects: []\ntask: p\n", 2, "[", "no regions"});
}

TEST(ScenarioErrors, Names) {
  check({"duplicate across kinds", with_line(6, "  - {name: r1, position: [0.4, 0.3, 0]}"), 6, "r1",
         "duplicate name 'r1': already used by a region at t.yaml:3:5"});
  check({"duplicate object",
         with_line(6, "  - {name: o1, position: [0.4, 0.3, 0]}\n  - {name: o1, position: [0.45, 0.3, 0]}"), 7, "o1",
         "duplicate name 'o1': already used by an object at t.yaml:6:5"});
  check({"not an identifier", with_line(6, "  - {name: my block, position: [0.4, 0.3, 0]}"), 6, "my block",
         "object name 'my block' is not an identifier"});
  check({"keyword as a name", with_line(6, "  - {name: all, position: [0.4, 0.3, 0]}"), 6, "all", "reserved word"});
  check({"none as a name", with_line(6, "  - {name: none, position: [0.4, 0.3, 0]}"), 6, "none", "reserved word"});
  check({"hand as a name", with_line(6, "  - {name: hand, position: [0.4, 0.3, 0]}"), 6, "hand", "reserved word"});
  check({"home as a region", with_line(3, "  - {name: home, center: [0.4, 0.3, 0], size: [0.3, 0.3]}"), 3, "home",
         "region name 'home' is a reserved word"});
  check({"hand as a class", with_line(6, "  - {name: o1, class: hand, position: [0.4, 0.3, 0]}"), 6, "hand",
         "class 'hand' is a reserved word"});
  check({"class object", with_line(6, "  - {name: o1, class: object, position: [0.4, 0.3, 0]}"), 6, "object",
         "class 'object' is reserved"});
  check({"proposition name", with_line(8, "  All: \"all block in r2\""), 8, "All",
         "proposition name 'All' is not a valid atom"});
  check({"duplicate proposition", with_line(8, "  p: \"all block in r2\"\n  p: \"o1 in r1\""), 9, "p",
         "duplicate proposition 'p'"});
  check({"robot model", valid() + "robot: {model: ur10}\n", 10, "ur10", "unknown robot model 'ur10' (rtamp knows: ur5)"});
  check({"class of objects and containers",
         valid() + "containers:\n  - {name: t1, class: block, position: [0.4, -0.3, 0]}\n", 11, "block",
         "class 'block' is also the class of objects"});
}

TEST(ScenarioErrors, PropositionExpressions) {
  // The column of the offending word inside the expression.
  check({"malformed", with_line(8, "  p: \"all block r2\""), 8, "r2", "expected 'in' after 'all block'"});
  check({"unbalanced", with_line(8, "  p: \"(o1 in r1\""), 8, "(", "'(' is never closed"});
  check({"plain scalar", with_line(8, "  p: o1 in"), 8, "in^", "expected a location name"});
  check({"unknown location", with_line(8, "  p: \"all block in r3\""), 8, "r3", "unknown location 'r3'"});
  check({"unknown object", with_line(8, "  p: \"o1 in r1 & o7 in r2\""), 8, "o7", "unknown object 'o7'"});
  check({"unknown class", with_line(8, "  p: \"all blok in r2\""), 8, "blok", "unknown class 'blok' (did you mean 'block'?)"});
  check({"object as location", with_line(8, "  p: \"any block in o1\""), 8, "o1", "'o1' is an object, not a location"});
  check({"no expression", with_line(8, "  p:"), 8, "p", "has no expression"});
}

TEST(ScenarioErrors, Geometry) {
  check({"negative size", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [-0.3, 0.3], capacity: 4}"), 3,
         "[-0.3", "region 'r1': size [-0.3, 0.3, 0] must be positive"});
  check({"zero object size", with_line(6, "  - {name: o1, position: [0.4, 0.3, 0], size: [0.04, 0, 0.04]}"), 6,
         "[0.04", "must be positive"});
  check({"capacity zero", with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: 0}"), 3,
         "0}", "capacity must be at least 1 (got 0)"});
  check({"object outside", with_line(6, "  - {name: o1, position: [0.9, 0.9, 0]}"), 6, "[0.9",
         "object 'o1' at [0.9, 0.9, 0] is outside every region and container"});
  check({"object below the table", with_line(6, "  - {name: o1, position: [0.4, 0.3, -0.5]}"), 6, "[0.4",
         "outside every"});
  check({"object bigger than its region", with_line(6, "  - {name: o1, position: [0.4, 0.3, 0], size: [0.31, 0.1, 0.04]}"),
         6, "[0.31", "object 'o1' (0.31 x 0.1 m) does not fit in region 'r1' (0.3 x 0.3 m"});
  check({"overlapping regions", with_line(4, "  - {name: r2, center: [0.5, 0.35, 0], size: [0.3, 0.3], capacity: 4}"), 4,
         "{", "region 'r2' overlaps region 'r1'"});
  check({"coordinates out of range", with_line(6, "  - {name: o1, position: [4000, 0.3, 0]}"), 6, "[4000",
         "out of range"});
  // The physically impossible: things float, regions sink, the robot spins.
  check({"object above its region", with_line(6, "  - {name: o1, position: [0.4, 0.3, 5]}"), 6, "[0.4",
         "object 'o1' at [0.4, 0.3, 5] floats 5 m above the surface of 'r1'"});
  check({"region below the table", with_line(3, "  - {name: r1, center: [0.4, 0.3, -3], size: [0.3, 0.3], capacity: 4}"),
         3, "[0.4", "region 'r1': centre z = -3 is not on the table top"});
  check({"yaw out of range", valid() + "robot: {model: ur5, yaw: 1e300}\n", 10, "1e300",
         "robot: yaw 1e+300 is out of range (radians within ±2π)"});
}

TEST(ScenarioErrors, Containers) {
  const std::string tray = "containers:\n  - {name: t1, position: [0.4, -0.3, 0], capacity: 1}\n";  // lines 10-11
  check({"container outside", valid() + "containers:\n  - {name: t1, position: [2, 2, 0]}\n", 11, "[2",
         "container 't1' at [2, 2, 0] is not in any region"});
  check({"container above its region", valid() + "containers:\n  - {name: t1, position: [0.4, -0.3, 2]}\n", 11, "[0.4",
         "container 't1' at [0.4, -0.3, 2] floats 2 m above the surface of 'r2'"});
  check({"containers overlap", valid() + tray + "  - {name: t2, position: [0.45, -0.3, 0]}\n", 12, "{",
         "container 't2' overlaps container 't1'"});
  check({"container bigger than its region",
         valid() + "containers:\n  - {name: t1, position: [0.4, -0.3, 0], size: [0.4, 0.2, 0.03]}\n", 11, "[0.4, 0.2",
         "container 't1' (0.4 x 0.2 m) does not fit in region 'r2' (0.3 x 0.3 m; things keep their orientation)"});
  check({"object bigger than the floor of its tray",
         with_line(6, "  - {name: o1, position: [0.4, 0.3, 0]}\n  - {name: o2, position: [0.4, -0.3, 0], "
                      "size: [0.2, 0.15, 0.04]}") +
             tray,
         7, "[0.2", "object 'o2' (0.2 x 0.15 m) does not fit in container 't1' (its floor inside the rims is 0.224 x 0.144 m"});
  check({"container into container",
         valid() + tray + "  - {name: t2, position: [0.4, 0.3, 0], size: [0.1, 0.1, 0.03]}\n" +
             "operator:\n  - {time: 1, action: relocate, container: t2, to: t1}\n",
         14, "t1}", "cannot put container 't2' into container 't1'"});
}

TEST(ScenarioErrors, Operator) {
  const std::string ops = valid() + "operator:\n";  // actions from line 11
  check({"unknown action", ops + "  - {time: 1, action: teleport, object: o1}\n", 11, "teleport",
         "unknown operator action 'teleport'"});
  check({"unknown object", ops + "  - {time: 1, action: relocate, object: o9, to: r2}\n", 11, "o9",
         "unknown object or container 'o9' at this time"});
  check({"unknown target", ops + "  - {time: 1, action: relocate, object: o1, to: r9}\n", 11, "r9",
         "unknown location 'r9' at this time"});
  check({"negative time", ops + "  - {time: -1, action: remove, object: o1}\n", 11, "-1",
         "time must be a finite number of seconds >= 0"});
  check({"removed twice", ops + "  - {time: 1, action: remove, object: o1}\n  - {time: 2, action: remove, object: o1}\n",
         12, "o1", "unknown object 'o1' at this time"});
  check({"moved after removal (sorted by time)",
         ops + "  - {time: 2, action: relocate, object: o1, to: r2}\n  - {time: 1, action: remove, object: o1}\n", 11,
         "o1", "unknown object or container 'o1' at this time"});
  check({"add an existing name", ops + "  - {time: 1, action: add, object: r2, to: r1}\n", 11, "r2,",
         "'r2' already exists"});
  check({"remove a container with remove",
         valid() + "containers:\n  - {name: t1, position: [0.4, -0.3, 0]}\n" +
             "operator:\n  - {time: 1, action: remove, object: t1}\n",
         13, "t1", "it is a container: use remove_container"});
  check({"position outside its region",
         ops + "  - {time: 1, action: relocate, object: o1, to: r2, position: [0.4, 0.3, 0]}\n", 11, "[0.4",
         "is not inside region 'r2'"});
  check({"position off the table", ops + "  - {time: 1, action: relocate, object: o1, position: [5, 0.3, 0]}\n", 11,
         "[5", "position [5, 0.3, 0] is off the table"});
  check({"both object and container", ops + "  - {time: 1, action: relocate, object: o1, container: o1, to: r2}\n", 11,
         "o1, to", "names both an object and a container"});
  check({"added object's class clashes",
         valid() + "containers:\n  - {name: t1, position: [0.4, -0.3, 0]}\n" +
             "operator:\n  - {time: 1, action: add, object: b9, class: tray, to: r1}\n",
         13, "tray", "class 'tray' is already the class of containers"});
}

TEST(ScenarioErrors, EmptyTask) {
  // Located at the text of the task (inside the quotes).
  check({"empty string", kHead + "task: \"\"\n", 9, "\"^\"", "the task is empty"});
  check({"blank", kHead + "task: \"   \"\n", 9, "\"^ ", "the task is empty"});
}

TEST(ScenarioErrors, Capacity) {
  check({"region over capacity",
         with_line(3, "  - {name: r1, center: [0.4, 0.3, 0], size: [0.3, 0.3], capacity: 1}") +
             "containers:\n  - {name: t1, position: [0.3, 0.2, 0], size: [0.1, 0.1, 0.03]}\n",
         3, "1}", "region 'r1' initially holds 2 things but its capacity is 1"});
  check({"container over capacity",
         with_line(6, "  - {name: o1, position: [0.4, -0.3, 0]}\n  - {name: o2, position: [0.42, -0.3, 0]}") +
             "containers:\n  - {name: t1, position: [0.4, -0.3, 0], capacity: 1}\n",
         12, "1}", "container 't1' initially holds 2 objects but its capacity is 1"});
}

// Scenarios built in code get the same checks, located at the element.
TEST(ScenarioErrors, ValidateBuiltInCode) {
  Scenario s = parse_scenario(valid(), "t.yaml");
  Scenario bad = s;
  bad.regions[1].capacity = 0;
  EXPECT_THROW(validate(bad), Error);
  bad = s;
  bad.objects[0].where = {};
  bad.objects[0].position = {5, 5, 0};
  try {
    validate(bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "object 'o1' at [5, 5, 0] is outside every region and container");
  }
  bad = s;
  bad.interventions.push_back({});
  bad.interventions.back().time = 5;
  bad.interventions.back().kind = Intervention::Kind::Remove;
  bad.interventions.back().subject = "o1";
  bad.interventions.push_back(bad.interventions.back());
  bad.interventions.back().time = 1;
  EXPECT_THROW(validate(bad), Error);  // not sorted by time
  bad = s;
  bad.task = "";
  EXPECT_THROW(validate(bad), Error);
  EXPECT_NO_THROW(validate(s));
}

}  // namespace
}  // namespace rtamp::world
