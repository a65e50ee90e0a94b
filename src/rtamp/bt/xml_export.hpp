// rtamp::bt::to_btcpp_xml — export a tree as BehaviorTree.CPP v4 XML
// (docs/design.md: "Trees export to BehaviorTree.CPP's XML (v4) so Groot2 opens them").
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
// Every node carries name="<name> #<node id>" (unique_names, the default): the
// names are unique in the file, which BehaviorTree.CPP's TreeObserver needs (it
// keys nodes on their path, the name within the tree), and our ids stay in the
// file; a detached subtree numbers its nodes in pre-order instead. The file then
// starts with the comment kUniqueNamesMarker, by which from_btcpp_xml knows to
// strip the suffix again. No other attributes than name and ports are written, so
// the file passes the schema BehaviorTree.CPP's writeTreeXSD() writes for a
// factory holding its built-ins and the <TreeNodesModel> (xml_schema.hpp).
// A model port that some instance lacks is declared with default="".
// An empty control node gets a placeholder child with the same outcome
// (<AlwaysSuccess/> under Sequence/ReactiveSequence/Parallel, <AlwaysFailure/> under
// Fallback/ReactiveFallback/Chooser), without a name (BehaviorTree.CPP then makes
// its path unique), because BehaviorTree.CPP rejects childless controls; an empty
// tree exports <AlwaysFailure name="empty tree"/>.
// Throws rtamp::Error if a decorator has no child, or one type ID is used for two
// node kinds, or the tree ID is not usable.
#pragma once

#include <string>

#include "rtamp/bt/tree.hpp"

namespace rtamp::bt {

// The comment that opens a file written with unique_names.
inline constexpr const char* kUniqueNamesMarker = "rtamp: every node name ends in \" #<node id>\"";

struct XmlOptions {
  std::string tree_id = "MainTree";  // <BehaviorTree ID> and main_tree_to_execute
  bool unique_names = true;          // name="<name> #<node id>" (see above); false: name="<name>"
  bool include_model = true;         // the <TreeNodesModel> section
};

std::string to_btcpp_xml(const Tree& tree, const XmlOptions& options = {});
// A detached subtree (ids are 0 until attached: unique names use pre-order numbers).
std::string to_btcpp_xml(const Node& root, const XmlOptions& options = {});

// XML attribute/text escaping (& < > " '; tab, newline and CR as character
// references; other control characters, which XML 1.0 cannot hold, as U+FFFD).
std::string xml_escape(std::string_view text);

}  // namespace rtamp::bt
