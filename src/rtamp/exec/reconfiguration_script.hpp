// The edit script of the paper's Algorithm 2 (BT Reconfiguration), as a pure
// function over action names, independent of the tree it is applied to.
//
// Given the actions of the current subtrees Ψ (in execution order) and of the
// new plan P, walk both from the back: where the i-th-from-last actions agree,
// the subtree is kept and only its conditions are updated (Update); where the
// plan's action occurs earlier in Ψ, the subtrees between are obsolete and are
// removed so that it lines up (Remove ..., then Update); otherwise a new
// subtree is inserted (Insert). Subtrees left over at the front are removed.
// (The paper writes the middle case as "find the index of P_A^{-i-1}"; we read
// it as aligning the plan's action with its last earlier occurrence in Ψ.)
//
// Invariant: applying the edits in order to Ψ, each at its `position` in the
// sequence as it is at that moment, yields exactly P's actions, with every
// Update/Insert naming the plan tuple it takes its conditions from.
// Deferral of edits that would cut a running subtree is the caller's job.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rtamp::exec {

struct Edit {
  enum class Kind { Update, Insert, Remove };
  Kind kind = Kind::Update;
  std::size_t position = 0;    // index in the subtree sequence when the edit is applied
  std::size_t plan_index = 0;  // Update/Insert: the plan tuple; Remove: unused
  friend bool operator==(const Edit&, const Edit&) = default;
};

std::vector<Edit> reconfiguration_script(const std::vector<std::string>& subtree_actions,
                                         const std::vector<std::string>& plan_actions);

// Applies `script` to `subtree_actions` (for tests and for callers that keep a
// parallel sequence): returns the resulting sequence of action names.
std::vector<std::string> apply_script(std::vector<std::string> subtree_actions,
                                      const std::vector<std::string>& plan_actions,
                                      const std::vector<Edit>& script);

// Number of structural tree changes in a script (inserts + removes).
std::size_t structural_changes(const std::vector<Edit>& script);

}  // namespace rtamp::exec
