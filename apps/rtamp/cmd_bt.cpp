// rtamp bt check — read a BehaviorTree.CPP v4 XML file (drawn in Groot2, or
// written by `rtamp run --trees`) with rtamp's importer, print the tree it
// builds, and optionally write the XSD BehaviorTree.CPP's writeTreeXSD() would
// write for its nodes (for `xmllint --schema`). Leaves are stand-ins built from
// the file's <TreeNodesModel> (an Action that succeeds, a Condition that fails):
// the check is about the file, not about running it. Errors: file:line:column,
// exit 2.
#include <fstream>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/util/output_file.hpp"
#include "rtamp/bt/text_render.hpp"
#include "rtamp/bt/tree.hpp"
#include "rtamp/bt/xml_import.hpp"
#include "rtamp/bt/xml_schema.hpp"
#include "rtamp/util/text_file.hpp"

namespace {

struct BtCheckArgs {
  std::string file;
  std::string tree_id;
  std::string xsd;
};

int run_check(const BtCheckArgs& a) {
  if (!a.xsd.empty()) {  // the schema is not the file checked (by device and inode)
    rtamp::FileSet files;
    files.input("FILE", a.file);
    files.output("--xsd", a.xsd);
  }
  const std::string xml = rtamp::read_text_file(a.file, "the behavior-tree file");
  const rtamp::bt::XmlDocument doc = rtamp::bt::parse_xml(xml, a.file);
  rtamp::bt::NodeRegistry stand_ins;
  for (const rtamp::bt::NodeModel& m : rtamp::bt::read_tree_nodes_model(doc, a.file)) {
    if (m.kind == "Action") {
      stand_ins.add_action(m.id, rtamp::bt::Action::Callbacks{
                                     [](rtamp::bt::Node&) { return rtamp::bt::Status::Success; }, {}, {}});
    } else if (m.kind == "Condition") {
      stand_ins.add_condition(m.id, [](rtamp::bt::Node&) { return false; });
    }
  }
  rtamp::bt::Tree tree;
  tree.set_root(rtamp::bt::from_btcpp_xml(xml, stand_ins, {a.file, a.tree_id}));
  std::cout << rtamp::bt::to_text(tree);
  if (!a.xsd.empty()) {
    rtamp::write_output_file(a.xsd, "--xsd", rtamp::bt::btcpp_xsd(rtamp::bt::read_tree_nodes_model(doc, a.file)));
  }
  return 0;
}

rtamp::cli::Registrar reg{
    "bt", "Behavior-tree files: check a BehaviorTree.CPP v4 XML file with rtamp's importer",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto args = std::make_shared<BtCheckArgs>();
      sub.require_subcommand(1);
      CLI::App* check = sub.add_subcommand(
          "check", "Build the tree a BehaviorTree.CPP v4 XML file describes and print it (leaves: stand-ins from its "
                   "<TreeNodesModel>)");
      check->add_option("file", args->file, "The XML file")->required();
      check->add_option("--tree", args->tree_id, "The <BehaviorTree ID> to build (default: main_tree_to_execute)");
      check->add_option("--xsd", args->xsd,
                        "Also write the XSD BehaviorTree.CPP's writeTreeXSD() writes for the file's nodes "
                        "(then: xmllint --noout --schema OUT FILE)");
      return [args]() { return run_check(*args); };
    }};

}  // namespace
