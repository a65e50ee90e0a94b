// rtamp::bt::to_dot — a tree as a Graphviz digraph, for pictures of the tree
// after each change. Node n<id> (or n<k>, pre-order index, for detached nodes)
// labelled "<type>\n<name>"; controls are boxes, decorators hexagons, conditions
// ellipses, actions rounded boxes; with statuses, fill colours show them
// (running yellow, success green, failure red, invalid white).
#pragma once

#include <string>

#include "rtamp/bt/tree.hpp"

namespace rtamp::bt {

struct DotOptions {
  std::string graph_name = "behavior_tree";
  bool show_status = true;
  bool show_ids = true;
};

std::string to_dot(const Tree& tree, const DotOptions& options = {});
std::string to_dot(const Node& root, const DotOptions& options = {});

}  // namespace rtamp::bt
