// Exported BehaviorTree.CPP XML against BehaviorTree.CPP's own schema (the XSD its
// writeTreeXSD() writes for the built-ins plus the file's <TreeNodesModel>),
// checked by a second tool, xmllint (Debian libxml2-utils; scripts/install-deps
// installs it). Negative controls show the schema does reject what it must: the
// old `_uid` attribute, a missing required port, an unknown node. Also: node
// paths are unique for BehaviorTree.CPP's TreeObserver.
#include <gtest/gtest.h>

#include <random>

#include "btcpp_checks.hpp"
#include "probes.hpp"
#include "rtamp/bt/bt.hpp"
#include "rtamp/bt/xml_schema.hpp"
#include "sample_trees.hpp"

namespace rtamp::bt {
namespace {

#define RTAMP_REQUIRE_XMLLINT()                                                                         \
  if (!testing::have_xmllint()) GTEST_SKIP() << "xmllint is missing: install libxml2-utils (scripts/install-deps)"

std::string sample_xml() {
  testing::Probe p;
  Tree tree;
  tree.set_root(testing::every_node_type(p));
  return to_btcpp_xml(tree);
}

TEST(XmlSchema, ExportedSampleTreeValidates) {
  RTAMP_REQUIRE_XMLLINT();
  const std::string xml = sample_xml();
  EXPECT_EQ(testing::schema_errors(xml), "") << xml;
  // Also without the model: the schema is then the built-ins only, and the custom
  // nodes must fail (the check is not vacuous).
  testing::Probe p;
  Tree tree;
  tree.set_root(testing::every_node_type(p));
  XmlOptions no_model;
  no_model.include_model = false;
  const std::string bare = to_btcpp_xml(tree, no_model);
  EXPECT_NE(testing::xmllint_errors(bare, btcpp_xsd({})).find("Chooser"), std::string::npos);
  EXPECT_EQ(testing::xmllint_errors(bare, btcpp_xsd_for(xml)), "") << "the model of the full file covers it";
}

TEST(XmlSchema, TheSchemaRejectsUidAttributesMissingPortsAndUnknownNodes) {
  RTAMP_REQUIRE_XMLLINT();
  const std::string xml = sample_xml();
  std::string with_uid = xml;
  with_uid.replace(with_uid.find(" name="), 0, " _uid=\"1\"");
  EXPECT_NE(testing::schema_errors(with_uid).find("_uid"), std::string::npos)
      << "BehaviorTree.CPP's schema has no _uid attribute: the reason rtamp no longer writes it";
  std::string no_msec = xml;
  no_msec.replace(no_msec.find(" msec=\"1500\""), 12, "");
  EXPECT_NE(testing::schema_errors(no_msec).find("msec"), std::string::npos);
  std::string unknown = xml;
  unknown.replace(unknown.find("<Inverter"), 9, "<Invertor");
  unknown.replace(unknown.find("</Inverter>"), 11, "</Invertor>");
  EXPECT_NE(testing::schema_errors(unknown).find("Invertor"), std::string::npos);
}

TEST(XmlSchema, RandomTreesValidateAndHaveUniqueObserverPaths) {
  RTAMP_REQUIRE_XMLLINT();
  // Trees whose names all repeat (the state-condition trees' problem, made worse).
  std::mt19937 rng(11);
  for (int round = 0; round < 12; ++round) {
    auto root = std::make_unique<Sequence>("same");
    for (int i = 0; i < 6; ++i) {
      auto c = std::make_unique<ReactiveFallback>("same");
      c->add(std::make_unique<Condition>("same", [] { return true; }, rng() % 2 ? "Cond" : "Other"));
      auto a = std::make_unique<Action>("same", [] { return Status::Success; }, "Act");
      if (rng() % 2) a->set_port("target", "t" + std::to_string(i));  // a port some instances lack
      c->add(std::make_unique<Timeout>("same", std::chrono::milliseconds(rng() % 1000), std::move(a)));
      if (rng() % 3 == 0) c->add(std::make_unique<Parallel>("same", 1, 1));  // empty: placeholder child
      root->add(std::move(c));
    }
    Tree t;
    t.set_root(std::move(root));
    const std::string xml = to_btcpp_xml(t);
    EXPECT_EQ(testing::schema_errors(xml), "") << xml;
    EXPECT_EQ(testing::repeated_paths(xml), std::vector<std::string>{}) << xml;
    XmlOptions plain;
    plain.unique_names = false;
    EXPECT_FALSE(testing::repeated_paths(to_btcpp_xml(t, plain)).empty()) << "the oracle sees repeats";
  }
}

TEST(XmlSchema, BuiltinModelsMatchBehaviorTreeCpp) {
  // Spot checks of the table against BehaviorTree.CPP's providedPorts().
  std::map<std::string, const NodeModel*> m;
  for (const NodeModel& n : btcpp_builtin_models()) m[n.id] = &n;
  EXPECT_EQ(m.size(), 42u);  // the registrations in BehaviorTreeFactory's constructor
  ASSERT_EQ(m.at("Parallel")->ports.size(), 2u);
  EXPECT_EQ(*m.at("Parallel")->ports[0].default_value, "-1");
  EXPECT_FALSE(m.at("Timeout")->ports[0].default_value.has_value()) << "msec is required";
  EXPECT_EQ(m.at("Timeout")->ports[0].xsd_type, "integerOrBlackboardType");
  EXPECT_EQ(m.at("RetryUntilSuccessful")->kind, "Decorator");
  EXPECT_EQ(m.at("AlwaysSuccess")->kind, "Action");
  EXPECT_EQ(m.at("Switch3")->ports.size(), 4u);
}

}  // namespace
}  // namespace rtamp::bt
