// BehaviorTree.CPP v4 XML export (checked by parsing it back with a tiny XML
// reader and comparing element by element with the tree), DOT and text renderings.
#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "probes.hpp"
#include "sample_trees.hpp"
#include "rtamp/bt/bt.hpp"

namespace rtamp::bt {
namespace {

using testing::make;
using testing::Probe;
using testing::probe_action;
using testing::every_node_type;

// ---- a tiny XML reader: elements, attributes, text, comments, <?xml?> ----
struct Element {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attrs;
  std::vector<Element> children;
  std::string text;
  const std::string* attr(const std::string& name) const {
    for (const auto& [k, v] : attrs) {
      if (k == name) return &v;
    }
    return nullptr;
  }
};

class XmlReader {
 public:
  explicit XmlReader(std::string s) : s_(std::move(s)) {}
  Element parse() {
    skip_misc();
    Element root = element();
    skip_misc();
    if (i_ != s_.size()) fail("trailing content");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("xml: " + what + " at " + std::to_string(i_));
  }
  void ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool starts(const char* p) const { return s_.compare(i_, std::char_traits<char>::length(p), p) == 0; }
  void skip_misc() {
    for (;;) {
      ws();
      if (starts("<?")) {
        i_ = s_.find("?>", i_) + 2;
      } else if (starts("<!--")) {
        i_ = s_.find("-->", i_) + 3;
      } else {
        return;
      }
    }
  }
  std::string name() {
    const std::size_t b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' ||
                              s_[i_] == ':' || s_[i_] == '-' || s_[i_] == '.'))
      ++i_;
    if (b == i_) fail("name expected");
    return s_.substr(b, i_ - b);
  }
  std::string unescape(const std::string& v) const {
    std::string out;
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (v[k] != '&') {
        out += v[k];
        continue;
      }
      const std::size_t e = v.find(';', k);
      const std::string ent = v.substr(k + 1, e - k - 1);
      if (ent == "amp")
        out += '&';
      else if (ent == "lt")
        out += '<';
      else if (ent == "gt")
        out += '>';
      else if (ent == "quot")
        out += '"';
      else if (ent == "apos")
        out += '\'';
      else if (!ent.empty() && ent[0] == '#')
        out += static_cast<char>(std::stoi(ent.substr(1)));
      else
        fail("bad entity " + ent);
      k = e;
    }
    return out;
  }
  Element element() {
    if (s_[i_] != '<') fail("'<' expected");
    ++i_;
    Element e;
    e.tag = name();
    for (;;) {
      ws();
      if (starts("/>")) {
        i_ += 2;
        return e;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      std::string k = name();
      ws();
      if (s_[i_] != '=') fail("'=' expected");
      ++i_;
      ws();
      const char q = s_[i_++];
      if (q != '"' && q != '\'') fail("quote expected");
      const std::size_t end = s_.find(q, i_);
      if (end == std::string::npos) fail("unterminated attribute");
      for (const auto& [ek, ev] : e.attrs) {
        if (ek == k) fail("duplicate attribute " + k);
      }
      e.attrs.emplace_back(k, unescape(s_.substr(i_, end - i_)));
      i_ = end + 1;
    }
    for (;;) {
      const std::size_t t = s_.find('<', i_);
      if (t == std::string::npos) fail("unterminated element " + e.tag);
      e.text += unescape(s_.substr(i_, t - i_));
      i_ = t;
      if (starts("<!--")) {
        i_ = s_.find("-->", i_) + 3;
      } else if (starts("</")) {
        i_ += 2;
        if (name() != e.tag) fail("mismatched end tag for " + e.tag);
        ws();
        if (s_[i_] != '>') fail("'>' expected");
        ++i_;
        return e;
      } else {
        e.children.push_back(element());
      }
    }
  }
  std::string s_;
  std::size_t i_ = 0;
};


const std::set<std::string> kBuiltins = {
    "Sequence", "ReactiveSequence",     "Fallback", "ReactiveFallback", "Parallel",
    "Inverter", "RetryUntilSuccessful", "Timeout",  "AlwaysSuccess",    "AlwaysFailure"};
const std::map<std::string, std::set<std::string>> kBuiltinPorts = {
    {"Parallel", {"success_count", "failure_count"}},
    {"RetryUntilSuccessful", {"num_attempts"}},
    {"Timeout", {"msec"}}};

// Compares an exported element with the node it came from, recursively, and checks
// every attribute against the model (custom nodes) or the built-in ports.
void check_element(const Element& e, const Node& n, const std::map<std::string, Element>& model) {
  SCOPED_TRACE(n.name());
  EXPECT_EQ(e.tag, n.type_id());
  ASSERT_NE(e.attr("name"), nullptr);
  EXPECT_EQ(*e.attr("name"), n.name() + " #" + std::to_string(n.id())) << "unique names keep our ids";
  std::set<std::string> allowed;
  if (kBuiltins.count(e.tag) != 0) {
    EXPECT_EQ(model.count(e.tag), 0u) << "built-ins are not redeclared";
    if (auto it = kBuiltinPorts.find(e.tag); it != kBuiltinPorts.end()) allowed = it->second;
  } else {
    auto it = model.find(e.tag);
    ASSERT_NE(it, model.end()) << "custom node " << e.tag << " missing from TreeNodesModel";
    const std::string kind(to_string(n.kind()));
    EXPECT_EQ(it->second.tag, kind);
    for (const Element& port : it->second.children) {
      EXPECT_EQ(port.tag, "input_port");
      allowed.insert(*port.attr("name"));
    }
  }
  for (const auto& [k, v] : e.attrs) {
    if (k == "name") continue;
    EXPECT_EQ(allowed.count(k), 1u) << "attribute " << k << " of <" << e.tag << "> is not a declared port";
  }
  for (const Port& p : n.user_ports()) {
    if (n.btcpp_builtin()) continue;
    ASSERT_NE(e.attr(p.name), nullptr) << p.name;
    EXPECT_EQ(*e.attr(p.name), p.value);
  }
  if (n.kind() == NodeKind::Control && n.child_count() == 0) {
    ASSERT_EQ(e.children.size(), 1u) << "empty control gets a placeholder";
    const bool succeeds =
        n.type_id() == "Sequence" || n.type_id() == "ReactiveSequence" || n.type_id() == "Parallel";
    EXPECT_EQ(e.children[0].tag, succeeds ? "AlwaysSuccess" : "AlwaysFailure");
    return;
  }
  ASSERT_EQ(e.children.size(), n.child_count());
  for (std::size_t i = 0; i < n.child_count(); ++i) check_element(e.children[i], n.child(i), model);
}

TEST(XmlExport, BehaviorTreeCppV4StructureRoundTrips) {
  Probe p;
  Tree tree;
  tree.set_root(every_node_type(p));
  const std::string xml = to_btcpp_xml(tree);
  Element root = XmlReader(xml).parse();
  EXPECT_EQ(root.tag, "root");
  ASSERT_NE(root.attr("BTCPP_format"), nullptr);
  EXPECT_EQ(*root.attr("BTCPP_format"), "4");
  EXPECT_EQ(*root.attr("main_tree_to_execute"), "MainTree");
  ASSERT_EQ(root.children.size(), 2u);
  const Element& bt = root.children[0];
  EXPECT_EQ(bt.tag, "BehaviorTree");
  EXPECT_EQ(*bt.attr("ID"), "MainTree");
  ASSERT_EQ(bt.children.size(), 1u);
  const Element& models = root.children[1];
  EXPECT_EQ(models.tag, "TreeNodesModel");
  std::map<std::string, Element> model;
  for (const Element& m : models.children) {
    ASSERT_NE(m.attr("ID"), nullptr);
    EXPECT_TRUE(m.tag == "Action" || m.tag == "Condition" || m.tag == "Control" || m.tag == "Decorator")
        << m.tag;
    EXPECT_TRUE(model.emplace(*m.attr("ID"), m).second) << "declared twice: " << *m.attr("ID");
  }
  EXPECT_EQ(model.size(), 5u);  // Chooser, ObjectAt, StateUpdate, MoveObject, Probe
  EXPECT_EQ(model.at("Chooser").tag, "Control");
  EXPECT_EQ(model.at("StateUpdate").tag, "Decorator");
  EXPECT_EQ(model.at("MoveObject").tag, "Action");
  EXPECT_EQ(model.at("ObjectAt").tag, "Condition");
  // Port union over instances, with the description as the element's text.
  ASSERT_EQ(model.at("ObjectAt").children.size(), 3u);
  EXPECT_EQ(*model.at("ObjectAt").children[0].attr("name"), "object");
  EXPECT_EQ(model.at("ObjectAt").children[0].text, "the object");
  EXPECT_EQ(*model.at("ObjectAt").children[2].attr("name"), "tolerance");
  check_element(bt.children[0], *tree.root(), model);
  // Parameter values.
  const Element& par = bt.children[0].children[1];
  EXPECT_EQ(*par.attr("success_count"), "2");
  EXPECT_EQ(*par.attr("failure_count"), "-1");
  const Element& timeout = bt.children[0].children[0].children[1].children[1];
  EXPECT_EQ(timeout.tag, "Timeout");
  EXPECT_EQ(*timeout.attr("msec"), "1500");
  EXPECT_EQ(*timeout.children[0].attr("num_attempts"), "3");
}

TEST(XmlExport, OptionsEmptyTreeAndErrors) {
  Tree empty;
  Element r = XmlReader(to_btcpp_xml(empty)).parse();
  EXPECT_EQ(r.children[0].children.at(0).tag, "AlwaysFailure");
  Probe p;
  Tree tree;
  tree.set_root(make<Sequence>("s", probe_action("a", p)));
  XmlOptions opt;
  opt.tree_id = "Plan";
  opt.unique_names = false;
  opt.include_model = false;
  Element r2 = XmlReader(to_btcpp_xml(tree, opt)).parse();
  EXPECT_EQ(*r2.attr("main_tree_to_execute"), "Plan");
  EXPECT_EQ(r2.children.size(), 1u);
  EXPECT_EQ(*r2.children[0].children[0].attr("name"), "s");
  opt.tree_id = "root";
  EXPECT_THROW(to_btcpp_xml(tree, opt), rtamp::Error);
  // One type ID for two kinds of node.
  Tree clash;
  clash.set_root(make<Sequence>("s",
                                std::make_unique<Condition>(
                                    "c", [] { return true; }, "Same"),
                                std::make_unique<Action>(
                                    "a", [] { return Status::Success; }, "Same")));
  EXPECT_THROW(to_btcpp_xml(clash), rtamp::Error);
  Tree childless;
  childless.set_root(std::make_unique<Inverter>());
  EXPECT_THROW(to_btcpp_xml(childless), rtamp::Error);
}

TEST(DotExport, OneNodeStatementPerNodeAndOneEdgePerParentLink) {
  Probe p;
  p.next = Status::Running;
  Tree tree;
  tree.set_root(every_node_type(p));
  tree.tick();
  const std::string dot = to_dot(tree);
  EXPECT_EQ(dot.rfind("digraph \"behavior_tree\" {", 0), 0u);
  std::size_t nodes = 0, edges = 0;
  for (std::size_t at = dot.find("[label="); at != std::string::npos; at = dot.find("[label=", at + 1))
    ++nodes;
  for (std::size_t at = dot.find(" -> n"); at != std::string::npos; at = dot.find(" -> n", at + 1)) ++edges;
  EXPECT_EQ(nodes, tree.size()) << dot;
  EXPECT_EQ(edges, tree.size() - 1);
  const std::string root_id = std::to_string(tree.root()->id());
  EXPECT_NE(dot.find("n" + root_id + " [label=\"ReactiveSequence\\nroot <&> \\\"quoted\\\""),
            std::string::npos)
      << dot;
  EXPECT_NE(dot.find("#fff3b0"), std::string::npos) << "running nodes are coloured";
}

TEST(TextRender, PyTreesStyleMarkers) {
  Probe a, b;
  a.next = Status::Failure;
  b.next = Status::Running;
  Tree tree;
  tree.set_root(make<Fallback>("root", probe_action("a", a), probe_action("b", b), probe_action("c", b)));
  tree.tick();
  const NodeId r = tree.root()->id();
  const std::string expected = "[*] Fallback \"root\" #" + std::to_string(r) + "\n" +  //
                               "    [x] Probe \"a\" #" + std::to_string(r + 1) + "\n" +
                               "    [*] Probe \"b\" #" + std::to_string(r + 2) + "\n" +
                               "    [-] Probe \"c\" #" + std::to_string(r + 3) + "\n";
  EXPECT_EQ(to_text(tree), expected);
  b.next = Status::Success;
  tree.tick();
  TextOptions opt;
  opt.show_ids = false;
  opt.max_depth = 0;
  EXPECT_EQ(to_text(tree, opt), "[o] Fallback \"root\"\n    ... (3 children)\n");
  EXPECT_EQ(to_text(Tree()), "(empty tree)\n");
}

}  // namespace
}  // namespace rtamp::bt
