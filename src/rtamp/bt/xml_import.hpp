// rtamp::bt::from_btcpp_xml — build a tree from BehaviorTree.CPP v4 XML (a file
// drawn in Groot2, or one written by to_btcpp_xml), for every node kind the
// engine has.
//
// Mapping (the inverse of xml_export.hpp, see docs/behavior-trees.md):
//   Sequence, ReactiveSequence, Fallback, ReactiveFallback,
//   Parallel [success_count=-1] [failure_count=1], Inverter,
//   RetryUntilSuccessful num_attempts, Timeout msec    → the engine's nodes;
//   Chooser, StateUpdate and every other ID            → the NodeRegistry's factory
//     for that ID (Chooser and StateUpdate have defaults: a Chooser, and a
//     StateUpdate without a hook); the factory gets the node's name, its
//     attributes as ports and where it is; the importer then sets the name and
//     the ports on what it returns and adds the children.
// Both the compact form (<Sequence>) and the explicit one (<Control ID="Sequence">)
// are read. <SubTree ID="X"/> without port remapping is replaced by tree X.
// A lone nameless <AlwaysSuccess/> / <AlwaysFailure/> under a control node is the
// export's placeholder for "no children" and is dropped; <AlwaysFailure name="empty
// tree"/> as the whole tree is the empty tree (nullptr). In a file that starts
// with kUniqueNamesMarker, the " #<id>" suffix of every name is stripped. Metadata
// attributes (_uid, _fullpath, _description) are ignored.
// Errors — malformed XML, an unknown node ID, a missing or bad parameter, a
// blackboard reference ({key}) or script attribute (_skipIf, ...) the engine does
// not have, a decorator without exactly one child, a leaf with children, a node
// whose kind contradicts <TreeNodesModel> — throw rtamp::Error with file, line
// and column of the element.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/bt/actions/action.hpp"
#include "rtamp/bt/conditions/condition.hpp"
#include "rtamp/bt/node.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::bt {

// What the file says about one custom node.
struct NodeSpec {
  std::string type_id;
  std::string name;
  std::vector<Port> ports;                // its attributes in file order (descriptions from the model)
  std::optional<NodeKind> declared_kind;  // from <TreeNodesModel>, if declared there
  SourceLocation where;
  // The value of a port, or nullptr.
  const std::string* port(std::string_view port_name) const;
};

using NodeFactory = std::function<std::unique_ptr<Node>(const NodeSpec&)>;

// Type ID -> factory, for the node IDs that are not the engine's built-ins.
class NodeRegistry {
 public:
  // Any node kind; a factory returning a Composite or a Decorator gets the file's
  // children added. Replaces an earlier factory of that ID.
  NodeRegistry& add(std::string type_id, NodeFactory factory);
  // A Condition / an Action of this type ID whose every instance uses these callables.
  NodeRegistry& add_condition(std::string type_id, Condition::Predicate predicate);
  NodeRegistry& add_action(std::string type_id, Action::Callbacks callbacks);
  // The factory of an ID, or nullptr.
  const NodeFactory* find(std::string_view type_id) const;

 private:
  std::map<std::string, NodeFactory, std::less<>> factories_;
};

struct XmlImportOptions {
  std::string file;     // labels error locations
  std::string tree_id;  // the <BehaviorTree ID> to build; empty: main_tree_to_execute, or the only tree
};

// The root of the tree (detached; Tree::set_root issues ids in pre-order), or
// nullptr for the empty tree.
std::unique_ptr<Node> from_btcpp_xml(std::string_view xml, const NodeRegistry& registry,
                                     const XmlImportOptions& options = {});
// Reads the file at `path` (options.file defaults to it).
std::unique_ptr<Node> load_btcpp_xml(const std::string& path, const NodeRegistry& registry,
                                     XmlImportOptions options = {});

}  // namespace rtamp::bt
