// rtamp::bt::btcpp_xsd — the XML Schema that BehaviorTree.CPP 4's writeTreeXSD()
// writes for a factory (src/xml_parsing.cpp, BehaviorTree.CPP commit 879522c,
// July 2026), so files can be checked with `xmllint --schema` without
// BehaviorTree.CPP: its built-in nodes (btcpp_builtin_models(), with their
// providedPorts()) plus custom node models — typically those a file declares in
// its <TreeNodesModel>, as if the user had registered exactly those nodes.
//
// The schema accepts only the compact form (<Sequence name=...>), the attribute
// `name`, the pre/post-condition script attributes, and each node type's ports; a
// port without a default is required. Port types map as in writeTreeXSD: int /
// unsigned → integer or {blackboard}, double → decimal, bool → boolean,
// std::string → string, output ports → {blackboard} only, anything else untyped.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/bt/xml_dom.hpp"

namespace rtamp::bt {

struct ModelPort {
  std::string name;
  std::string xsd_type;                      // writeTreeXSD's attribute type; empty: untyped
  std::optional<std::string> default_value;  // none: the attribute is required
  std::string description;                   // the port element's text
};

struct NodeModel {
  std::string id;
  std::string kind;  // Action, Condition, Control, Decorator or SubTree
  std::vector<ModelPort> ports;
};

// The nodes a default BehaviorTreeFactory registers.
const std::vector<NodeModel>& btcpp_builtin_models();

// The <TreeNodesModel> entries of a parsed file (ports: input_port, output_port,
// inout_port with their `type`, `default` and text). Throws rtamp::Error
// (file:line:col) on a malformed entry: no ID, an unknown kind, an ID declared
// twice, a port without a name, a name declared twice in one model, or a port
// name BehaviorTree.CPP refuses (port_name_problem).
std::vector<NodeModel> read_tree_nodes_model(const XmlDocument& doc, const std::string& file = {});

// Why BehaviorTree.CPP 4 refuses `name` as a port name (IsAllowedPortName: empty,
// a digit first, a reserved attribute — ID, name, anything starting with '_' —
// or a character of findForbiddenChar: whitespace, control characters,
// < > & " ' / \ : * ? | .), or "" if it is allowed.
std::string port_name_problem(std::string_view name);

// The schema for the built-ins plus `custom` (a custom model replaces a built-in of
// the same ID, as a factory registration would be refused; here it simply wins).
std::string btcpp_xsd(const std::vector<NodeModel>& custom);

// The schema for the built-ins plus the <TreeNodesModel> of this BehaviorTree.CPP file.
std::string btcpp_xsd_for(std::string_view xml, const std::string& file = {});

}  // namespace rtamp::bt
