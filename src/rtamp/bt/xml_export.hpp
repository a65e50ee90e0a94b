// rtamp::bt::to_btcpp_xml — export a tree as BehaviorTree.CPP v4 XML
// (DESIGN.md: "Trees export to BehaviorTree.CPP's XML (v4) so Groot2 opens them").
//
// Mapping (see docs/behavior-trees.md):
//   Sequence → <Sequence>, ReactiveSequence → <ReactiveSequence>,
//   Fallback → <Fallback>, ReactiveFallback → <ReactiveFallback>,
//   Parallel → <Parallel success_count failure_count>, Inverter → <Inverter>,
//   Retry → <RetryUntilSuccessful num_attempts>, Timeout → <Timeout msec>;
//   custom nodes (Chooser, StateUpdate, user Actions and Conditions) are written
//   with their type ID as element name, their user ports as attributes, and are
//   declared once each in <TreeNodesModel> (<Control>/<Decorator>/<Action>/
//   <Condition ID=...> with <input_port name=... type="std::string">).
// Every node carries name="..." and, optionally, _uid="<node id>" (an attribute
// starting with '_' is not a port for BehaviorTree.CPP; it keeps our ids in the file).
// An empty control node gets a placeholder child with the same outcome
// (<AlwaysSuccess/> under Sequence/ReactiveSequence/Parallel, <AlwaysFailure/> under
// Fallback/ReactiveFallback/Chooser) because BehaviorTree.CPP rejects childless
// controls; an empty tree exports <AlwaysFailure name="empty tree"/>.
// Throws rtamp::Error if a decorator has no child, or one type ID is used for two
// node kinds, or the tree ID is not usable.
#pragma once

#include <string>

#include "rtamp/bt/tree.hpp"

namespace rtamp::bt {

struct XmlOptions {
  std::string tree_id = "MainTree";  // <BehaviorTree ID> and main_tree_to_execute
  bool include_uids = true;          // _uid="<node id>" on every node
  bool include_model = true;         // the <TreeNodesModel> section
};

std::string to_btcpp_xml(const Tree& tree, const XmlOptions& options = {});
// A detached subtree (ids are 0 until attached; _uid is then omitted).
std::string to_btcpp_xml(const Node& root, const XmlOptions& options = {});

// XML attribute/text escaping (& < > " ' and control characters).
std::string xml_escape(std::string_view text);

}  // namespace rtamp::bt
