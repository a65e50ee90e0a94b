// BehaviorTree.CPP v4 XML import: export -> import -> export is the identity for
// every node kind (a sample tree and random trees), an imported tree ticks like
// the original (same statuses of every node, same leaf calls, tick by tick, on a
// manual clock that makes Timeouts expire), hand-written Groot2-style files
// (explicit form, SubTree, defaults, model descriptions) build the expected
// tree, and bad files fail with file:line:column.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <random>
#include <string>
#include <vector>

#include "probes.hpp"
#include "rtamp/bt/bt.hpp"
#include "rtamp/bt/xml_import.hpp"
#include "sample_trees.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::bt {
namespace {

using namespace std::chrono_literals;

// ---- leaves whose behaviour is a function of (name, tick), recorded in a log --------

struct Log {
  std::vector<std::string> events;
};

// Deterministic "random" outcome of leaf `name` at tick `t`.
unsigned mix(const std::string& name, std::uint64_t t) {
  unsigned h = 2166136261u;
  for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  h ^= static_cast<unsigned>(t * 2654435761u);
  h *= 16777619u;
  return h ^ (h >> 13);
}

Status scripted_status(const std::string& name, std::uint64_t t) {
  switch (mix(name, t) % 3) {
    case 0:
      return Status::Success;
    case 1:
      return Status::Failure;
    default:
      return Status::Running;
  }
}

std::unique_ptr<Node> scripted_action(const std::string& name, const std::string& type, Log& log) {
  return std::make_unique<Action>(
      name,
      Action::Callbacks{[&log](Node& n) {
                          log.events.push_back("start " + n.name());
                          return scripted_status(n.name(), n.tick_count());
                        },
                        [&log](Node& n) {
                          log.events.push_back("run " + n.name());
                          return scripted_status(n.name(), n.tick_count());
                        },
                        [&log](Node& n) { log.events.push_back("halt " + n.name()); }},
      type);
}

std::unique_ptr<Node> scripted_condition(const std::string& name, const std::string& type, Log& log) {
  return std::make_unique<Condition>(
      name,
      [&log](Node& n) {
        log.events.push_back("check " + n.name());
        return mix(n.name(), n.tick_count()) % 2 == 0;
      },
      type);
}

StateUpdate::Update logging_update(Log& log) {
  return [&log](Node& n) { log.events.push_back("update " + n.name()); };
}

// A registry that rebuilds the scripted leaves by type (kind from the type name).
NodeRegistry scripted_registry(Log& log) {
  NodeRegistry r;
  for (const char* type : {"Act", "MoveObject", "Probe"})
    r.add(type, [&log, type](const NodeSpec& s) { return scripted_action(s.name, type, log); });
  for (const char* type : {"Cond", "ObjectAt"})
    r.add(type, [&log, type](const NodeSpec& s) { return scripted_condition(s.name, type, log); });
  r.add("StateUpdate", [&log](const NodeSpec& s) { return std::make_unique<StateUpdate>(s.name, logging_update(log)); });
  return r;
}

// ---- random trees over every node kind ------------------------------------------------

class RandomTrees {
 public:
  RandomTrees(unsigned seed, Log& log) : rng_(seed), log_(log) {}
  std::unique_ptr<Node> make(int depth) {
    const int kind = depth >= 4 ? pick(2) : pick(12);
    const std::string name = "n" + std::to_string(counter_++);
    switch (kind) {
      case 0:
        return scripted_action(name, "Act", log_);
      case 1: {
        auto c = scripted_condition(name, "Cond", log_);
        if (pick(2) == 0) c->set_port("thing", "o" + std::to_string(pick(3)), "what to look at");
        return c;
      }
      case 2:
        return composite(std::make_unique<Sequence>(name), depth);
      case 3:
        return composite(std::make_unique<ReactiveSequence>(name), depth);
      case 4:
        return composite(std::make_unique<Fallback>(name), depth);
      case 5:
        return composite(std::make_unique<ReactiveFallback>(name), depth);
      case 6:
        return composite(std::make_unique<Chooser>(name), depth);
      case 7: {  // one draw per statement: the same trees from every compiler
        const int success = pick(5) - 2;
        const int failure = pick(5) - 2;
        auto p = composite(std::make_unique<Parallel>(name, success, failure), depth);
        // BehaviorTree.CPP (and the importer) refuse a threshold above the number of children.
        const int n = static_cast<int>(p->child_count());
        static_cast<Parallel&>(*p).set_thresholds(std::min(success, n), std::min(failure, n));
        return p;
      }
      case 8:
        return std::make_unique<Inverter>(name, make(depth + 1));
      case 9: {
        const int attempts = pick(2) == 0 ? -1 : 1 + pick(3);
        return std::make_unique<Retry>(name, attempts, make(depth + 1));
      }
      case 10:
        return std::make_unique<Timeout>(name, std::chrono::milliseconds(100 * pick(6)), make(depth + 1));
      default: {
        auto u = std::make_unique<StateUpdate>(name, logging_update(log_), make(depth + 1));
        u->set_port("effect", "e" + std::to_string(pick(9)));
        return u;
      }
    }
  }

 private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  std::unique_ptr<Node> composite(std::unique_ptr<Composite> c, int depth) {
    const int n = pick(4);  // 0..3 children: empty controls too
    for (int i = 0; i < n; ++i) c->add(make(depth + 1));
    return c;
  }
  std::mt19937 rng_;
  Log& log_;
  int counter_ = 0;
};

// Statuses of every node in pre-order.
std::string statuses(const Tree& t) {
  std::string s;
  t.for_each([&s](const Node& n, int) { s += status_marker(n.status()); });
  return s;
}

// Ticks both trees side by side; the clock advances 70 ms per tick.
void expect_same_ticks(Tree& a, Log& la, Tree& b, Log& lb, ManualClock& ca, ManualClock& cb, int ticks) {
  for (int i = 0; i < ticks; ++i) {
    SCOPED_TRACE("tick " + std::to_string(i + 1));
    ASSERT_EQ(a.tick(), b.tick());
    ASSERT_EQ(statuses(a), statuses(b));
    ASSERT_EQ(la.events, lb.events);
    ca.advance(70ms);
    cb.advance(70ms);
  }
  a.halt();
  b.halt();
  EXPECT_EQ(la.events, lb.events) << "halting runs the same on_halted callbacks";
}

TEST(XmlImport, SampleTreeRoundTripsAndTicksLikeTheOriginal) {
  Log la, lb;
  testing::Probe p;
  auto ca = std::make_shared<ManualClock>(), cb = std::make_shared<ManualClock>();
  Tree a(std::make_shared<Blackboard>(), ca);
  a.set_root(testing::every_node_type(p));
  const std::string xml = to_btcpp_xml(a);
  Tree b(std::make_shared<Blackboard>(), cb);
  b.set_root(from_btcpp_xml(xml, scripted_registry(lb)));
  EXPECT_EQ(to_btcpp_xml(b), xml);
  EXPECT_EQ(b.root()->name(), "root <&> \"quoted\"") << "the id suffix is stripped, escapes undone";
  EXPECT_EQ(b.find_by_name("empty seq")->child_count(), 0u) << "the placeholder child is dropped";
  EXPECT_EQ(*b.find_by_name("o1 in r2")->port("object"), "o1");
  const std::string tolerance = *b.find_by_name("o1 in r1")->port("tolerance");
  EXPECT_EQ(tolerance, "0.01");
  // Ticking: rebuild the original with scripted leaves (the sample's probes are not scripted).
  Tree a2(std::make_shared<Blackboard>(), ca);
  a2.set_root(from_btcpp_xml(xml, scripted_registry(la)));
  expect_same_ticks(a2, la, b, lb, *ca, *cb, 40);
}

TEST(XmlImport, RandomTreesOfEveryKindRoundTripAndTickTheSame) {
  int nodes = 0;
  for (unsigned seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Log la, lb;
    auto ca = std::make_shared<ManualClock>(), cb = std::make_shared<ManualClock>();
    Tree a(std::make_shared<Blackboard>(), ca);
    a.set_root(RandomTrees(seed, la).make(0));
    nodes += static_cast<int>(a.size());
    const std::string xml = to_btcpp_xml(a);
    Tree b(std::make_shared<Blackboard>(), cb);
    b.set_root(from_btcpp_xml(xml, scripted_registry(lb)));
    ASSERT_EQ(to_btcpp_xml(b), xml);
    XmlOptions plain;
    plain.unique_names = false;
    ASSERT_EQ(to_btcpp_xml(b, plain), to_btcpp_xml(a, plain));
    expect_same_ticks(a, la, b, lb, *ca, *cb, 25);
  }
  EXPECT_GT(nodes, 1000);
}

TEST(XmlImport, TreesAfterChangesRoundTripUpToTheirIds) {
  // After edits, ids are no longer pre-order; the importing tree issues its own.
  Log log;
  Tree a;
  auto seq = std::make_unique<Sequence>("top");
  const NodeId top = a.set_root(std::move(seq));
  a.append(top, scripted_action("x", "Act", log));
  a.insert(top, 0, scripted_condition("y", "Cond", log));
  a.remove(a.find_by_name("x")->id());
  a.append(top, scripted_action("z", "Act", log));
  const std::string xml = to_btcpp_xml(a);
  EXPECT_NE(xml.find("name=\"z #4\""), std::string::npos) << xml;
  Tree b;
  b.set_root(from_btcpp_xml(xml, scripted_registry(log)));
  EXPECT_NE(to_btcpp_xml(b).find("name=\"z #3\""), std::string::npos);
  XmlOptions plain;
  plain.unique_names = false;
  EXPECT_EQ(to_btcpp_xml(b, plain), to_btcpp_xml(a, plain));
}

TEST(XmlImport, NamesAndPortValuesSurviveEscaping) {
  const std::string awkward = "a\tb\nc\r d <&> \"q\" 'x' \xC3\xBC #12 ";
  Tree t;
  auto c = std::make_unique<Condition>(awkward, [] { return true; }, "Cond");
  c->set_port("value", awkward);
  auto root = std::make_unique<Sequence>("ctl\x01");
  root->add(std::move(c));
  t.set_root(std::move(root));
  Log log;
  const std::string xml = to_btcpp_xml(t);
  auto back = from_btcpp_xml(xml, scripted_registry(log));
  EXPECT_EQ(back->name(), "ctl\xEF\xBF\xBD") << "a control character XML cannot hold becomes U+FFFD";
  EXPECT_EQ(back->child(0).name(), awkward) << "only the last ' #<id>' is the export's";
  EXPECT_EQ(*back->child(0).port("value"), awkward);
}

TEST(XmlImport, EmptyTreeAndDetachedSubtrees) {
  Tree empty;
  EXPECT_EQ(from_btcpp_xml(to_btcpp_xml(empty), NodeRegistry{}), nullptr);
  Log log;
  auto detached = RandomTrees(3, log).make(0);
  const std::string xml = to_btcpp_xml(*detached);
  Tree t;
  t.set_root(from_btcpp_xml(xml, scripted_registry(log)));
  EXPECT_EQ(to_btcpp_xml(t), xml) << "pre-order numbers of a detached tree are the ids it gets";
}

// ---- hand-written Groot2-style files ---------------------------------------------------

std::string signature(const Node& n) {
  std::string s = std::string(n.type_id()) + "(" + n.name();
  std::vector<Port> ports;
  n.collect_ports(ports);
  for (const Port& p : ports) s += " " + p.name + "=" + p.value;
  s += ")";
  if (n.child_count() > 0) {
    s += "[";
    for (const Node* c : n.children()) s += signature(*c) + (c == n.children().back() ? "" : ",");
    s += "]";
  }
  return s;
}

// A file as Groot2 writes it, plus the explicit form, a SubTree and defaults.
std::string groot2_file() {
  std::ifstream in(RTAMP_SOURCE_DIR "/tests/bt/data/groot2_door.xml");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(XmlImport, Groot2StyleFileWithExplicitFormSubTreesAndDefaults) {
  NodeRegistry r;
  std::vector<std::string> calls;
  r.add_condition("IsDoorOpen", [&calls](Node& n) {
    calls.push_back("door " + *n.port("door"));
    return *n.port("door") == "front";
  });
  r.add_action("MoveTo", Action::Callbacks{[&calls](Node& n) {
                                             calls.push_back("move " + *n.port("goal"));
                                             return Status::Success;
                                           },
                                           {},
                                           {}});
  r.add_action("Wait", Action::Callbacks{[](Node&) { return Status::Running; }, {}, {}});
  const std::string file = groot2_file();
  ASSERT_FALSE(file.empty());
  auto root = from_btcpp_xml(file, r, {"groot.xml", {}});
  ASSERT_NE(root, nullptr);
  EXPECT_EQ(signature(*root),
            "Sequence(Sequence)[IsDoorOpen(door open? door=front),"
            "Parallel(Parallel success_count=1 failure_count=1)[MoveTo(MoveTo goal=kitchen),"
            "Timeout(Timeout msec=2500)[Wait(Wait)]],"
            "Chooser(pick)[StateUpdate(StateUpdate effect=held)[MoveTo(MoveTo goal=shelf)]],"
            "ReactiveFallback(guard)[Inverter(Inverter)[IsDoorOpen(IsDoorOpen door=back)],"
            "RetryUntilSuccessful(RetryUntilSuccessful num_attempts=-1)[MoveTo(MoveTo goal=hall)]]]");
  // The model's port description is kept.
  const Port& door = root->child(0).user_ports().at(0);
  EXPECT_EQ(door.description, "which door");
  Tree t;
  t.set_root(std::move(root));
  EXPECT_EQ(t.tick(), Status::Success);
  EXPECT_EQ(calls, (std::vector<std::string>{"door front", "move kitchen", "move shelf", "door back"}))
      << "the Inverter succeeds when the back door is closed, so the retry is not reached";
  // A tree picked by ID.
  XmlImportOptions grasp{"groot.xml", "Grasp"};
  EXPECT_EQ(signature(*from_btcpp_xml(file, r, grasp)),
            "Chooser(pick)[StateUpdate(StateUpdate effect=held)[MoveTo(MoveTo goal=shelf)]]");
}

// ---- errors: file:line:column ----------------------------------------------------------

std::string error_of(const std::string& xml, const NodeRegistry& r = {}) {
  try {
    from_btcpp_xml(xml, r, {"t.xml", {}});
  } catch (const rtamp::Error& e) {
    return e.what();
  }
  return "no error";
}

std::string wrap(const std::string& body) {
  return "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"T\">\n" + body + "\n  </BehaviorTree>\n</root>\n";
}

TEST(XmlImport, ErrorsNameFileLineAndColumn) {
  NodeRegistry r;
  r.add_action("Go", Action::Callbacks{[](Node&) { return Status::Success; }, {}, {}});
  // Malformed XML (expat's message and position).
  EXPECT_EQ(error_of(wrap("    <Sequence>\n    </Fallback>")), "t.xml:4:7: malformed XML: mismatched tag");
  EXPECT_EQ(error_of(""), "t.xml:1:1: malformed XML: no element found");
  // Unknown node kinds, at the element's start tag.
  EXPECT_EQ(error_of(wrap("    <Sequence>\n      <Fly/>\n    </Sequence>"), r),
            "t.xml:4:7: unknown node 'Fly': not a node of rtamp's engine and not in the registry");
  EXPECT_EQ(error_of(wrap("    <SequenceWithMemory/>")),
            "t.xml:3:5: unknown node 'SequenceWithMemory': not a node of rtamp's engine and not in the registry");
  EXPECT_EQ(error_of(wrap("    <AlwaysSuccess name=\"ok\"/>")),
            "t.xml:3:5: unknown node 'AlwaysSuccess': not a node of rtamp's engine and not in the registry");
  // Parameters.
  EXPECT_EQ(error_of(wrap("    <Timeout msec=\"soon\"><Go/></Timeout>"), r),
            "t.xml:3:5: port msec of <Timeout>: 'soon' is not an integer >= 0");
  EXPECT_EQ(error_of(wrap("    <Timeout><Go/></Timeout>"), r), "t.xml:3:5: <Timeout> needs the port msec");
  EXPECT_EQ(error_of(wrap("    <RetryUntilSuccessful num_attempts=\"0\"><Go/></RetryUntilSuccessful>"), r),
            "t.xml:3:5: port num_attempts of <RetryUntilSuccessful> must be positive or -1 (unlimited)");
  EXPECT_EQ(error_of(wrap("    <Sequence speed=\"2\"/>")), "t.xml:3:5: <Sequence> has no port 'speed'");
  EXPECT_EQ(error_of(wrap("    <Go target=\"{goal}\"/>"), r),
            "t.xml:3:5: port 'target' of <Go> is a blackboard reference ({goal}); rtamp's engine takes port values "
            "as written");
  EXPECT_EQ(error_of(wrap("    <Go _skipIf=\"x\"/>"), r),
            "t.xml:3:5: attribute '_skipIf' of <Go>: BehaviorTree.CPP scripts (pre/post conditions) are not "
            "supported by rtamp's engine");
  // Structure.
  EXPECT_EQ(error_of(wrap("    <Inverter><Go/><Go/></Inverter>"), r),
            "t.xml:3:5: decorator <Inverter> needs exactly one child, not 2");
  EXPECT_EQ(error_of(wrap("    <Go>\n      <Go/>\n    </Go>"), r),
            "t.xml:4:7: <Go> is a leaf (Action) and cannot have children");
  EXPECT_EQ(error_of(wrap("    <Condition ID=\"Go\"/>"), r), "t.xml:3:5: <Condition ID=\"Go\"> builds an Action node");
  EXPECT_EQ(error_of(wrap("    <SubTree ID=\"T\"/>")), "t.xml:2:3: behavior tree 'T' includes itself through <SubTree>");
  EXPECT_EQ(error_of(wrap("    <SubTree ID=\"U\" goal=\"{g}\"/>")),
            "t.xml:3:5: <SubTree ID=\"U\">: port remapping ('goal') is not supported (rtamp inlines subtrees)");
  EXPECT_EQ(error_of("<root BTCPP_format=\"3\"/>"),
            "t.xml:1:1: BTCPP_format \"3\" is not supported (only BehaviorTree.CPP v4 XML, BTCPP_format=\"4\")");
  EXPECT_EQ(error_of("<root><BehaviorTree ID=\"A\"><Go/></BehaviorTree><BehaviorTree ID=\"B\"><Go/></BehaviorTree></root>", r),
            "t.xml:1:1: several behavior trees and no main_tree_to_execute: say which to build");
  // A factory's own error gets the element's location.
  NodeRegistry bad;
  bad.add("Bad", [](const NodeSpec&) -> std::unique_ptr<Node> { throw rtamp::Error("no such robot"); });
  EXPECT_EQ(error_of(wrap("    <Bad/>"), bad), "t.xml:3:5: no such robot");
  // Kind contradicting the model.
  EXPECT_EQ(error_of("<root BTCPP_format=\"4\"><BehaviorTree ID=\"T\"><Go/></BehaviorTree>"
                     "<TreeNodesModel><Condition ID=\"Go\"/></TreeNodesModel></root>",
                     r),
            "t.xml:1:45: 'Go' is declared as a Condition in <TreeNodesModel> but builds an Action node");
}

// What BehaviorTree.CPP itself refuses is refused at import, where it is written.
TEST(XmlImport, RefusesWhatBehaviorTreeCppRefuses) {
  NodeRegistry r;
  r.add_action("Go", Action::Callbacks{[](Node&) { return Status::Success; }, {}, {}});
  EXPECT_EQ(error_of(wrap("    <Parallel success_count=\"5\"><Go/><Go/></Parallel>"), r),
            "t.xml:3:5: port success_count=\"5\" of <Parallel> is more than its 2 children (the threshold could never "
            "be met)");
  EXPECT_EQ(error_of(wrap("    <Parallel failure_count=\"2\"><Go/></Parallel>"), r),
            "t.xml:3:5: port failure_count=\"2\" of <Parallel> is more than its 1 child (the threshold could never be "
            "met)");
  EXPECT_NO_THROW(from_btcpp_xml(wrap("    <Parallel success_count=\"2\" failure_count=\"-1\"><Go/><Go/></Parallel>"), r));
  const std::string tree = "<root BTCPP_format=\"4\">\n<BehaviorTree ID=\"T\"><Go/></BehaviorTree>\n<TreeNodesModel>\n";
  EXPECT_EQ(error_of(tree + "<Action ID=\"Go\"/>\n<Condition ID=\"Go\"/>\n</TreeNodesModel></root>", r),
            "t.xml:5:1: 'Go' is declared twice in <TreeNodesModel> (as <Action> on line 4 and as <Condition> here)");
  for (const auto& [port, why] : std::vector<std::pair<std::string, std::string>>{
           {"bad name", "it holds the character ' '"},
           {"a.b", "it holds the character '.'"},
           {"1st", "it starts with a digit"},
           {"_skipIf", "it is a reserved attribute"},
           {"ID", "it is a reserved attribute"}}) {
    EXPECT_EQ(error_of(tree + "<Action ID=\"Go\"><input_port name=\"" + port + "\"/></Action>\n</TreeNodesModel></root>", r),
              "t.xml:4:17: port name '" + port + "' in the model of 'Go' is not allowed: " + why);
  }
  EXPECT_EQ(error_of(tree + "<Action ID=\"Go\"><input_port name=\"a\"/><output_port name=\"a\"/></Action>\n"
                            "</TreeNodesModel></root>",
                     r),
            "t.xml:4:39: port 'a' is declared twice in the model of 'Go'");
  EXPECT_NO_THROW(from_btcpp_xml(tree + "<Action ID=\"Go\"><input_port name=\"Tür_öffnen-2\"/></Action>\n"
                                        "</TreeNodesModel></root>",
                                 r));
  // The parser reads UTF-8: a file declaring another encoding is refused, not misread.
  EXPECT_EQ(error_of("<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n" + wrap("    <Go/>"), r),
            "t.xml:1:1: the XML declaration names encoding \"UTF-16\": rtamp reads behavior-tree files as UTF-8 "
            "(convert the file, e.g. with iconv, and declare UTF-8)");
  EXPECT_NO_THROW(from_btcpp_xml("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n" + wrap("    <Go/>"), r));
}

}  // namespace
}  // namespace rtamp::bt
