// rtamp::bt::to_text — a compact terminal rendering of a tree with live statuses,
// in the manner of py_trees' ascii tree. One line per node, four spaces per level:
//   [*] ReactiveSequence "root" #1
//       [o] Chooser "o1: r1 -> r2" #2
// The marker is the status: [-] invalid (not ticked in this run), [*] running,
// [o] success, [x] failure; then the type ID, the name in quotes (omitted when
// equal to the type ID), and the node id.
#pragma once

#include <string>

#include "rtamp/bt/tree.hpp"

namespace rtamp::bt {

struct TextOptions {
  bool show_ids = true;
  int max_depth = -1;  // -1: everything; otherwise deeper nodes are summarised as "..."
};

std::string to_text(const Tree& tree, const TextOptions& options = {});
std::string to_text(const Node& root, const TextOptions& options = {});

}  // namespace rtamp::bt
