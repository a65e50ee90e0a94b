// The behavior tree as pages see it (docs/serve.md "tree", "status"): every
// node in pre-order (its id is its index; `parent` the parent's id, -1 for the
// root; children in order) with its name, kind (the node's type, e.g.
// "Sequence", "Fallback", "Chooser", or an action's / condition's type), its
// BehaviorTree.CPP category (Action, Condition, Control, Decorator) and status;
// and the statuses alone as one character a node (I idle, R running, S
// success, F failure), sent after ticks that changed some.
#pragma once

#include <string>

#include "rtamp/bt/tree.hpp"

namespace rtamp::serve {

std::string tree_message(double t, const bt::Tree& tree);
std::string status_string(const bt::Tree& tree);
std::string status_message(double t, const std::string& statuses);
// The status name a node of the tree message has for a character of the status string.
const char* status_name(char status);

}  // namespace rtamp::serve
