// A synthetic tree shaped like the paper's action-condition trees (Fig. 3b), for
// the allocation test: root over n subtrees
//   Chooser( Sequence(post-condition), Sequence(pre-condition, action) ).
// World: done[i] is subtree i's post-condition, `cursor` the index whose
// precondition holds; the action of the cursor subtree runs until `finish` is set.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rtamp/bt/bt.hpp"

namespace rtamp::bt::testing {

struct PaperWorld {
  std::vector<std::uint8_t> done;
  std::size_t cursor = 0;
  bool finish = false;
};

inline std::unique_ptr<Node> paper_subtree(PaperWorld& w, std::size_t i) {
  auto chooser = std::make_unique<Chooser>("subtree");
  auto post = std::make_unique<Sequence>("post");
  post->emplace<Condition>(
      "post", [&w, i](Node&) { return w.done[i] != 0; }, "PostCondition");
  auto run = std::make_unique<Sequence>("run");
  run->emplace<Condition>(
      "pre", [&w, i](Node&) { return w.cursor == i; }, "PreCondition");
  run->emplace<Action>("act",
                       Action::Callbacks{[](Node&) { return Status::Running; },
                                         [&w, i](Node&) {
                                           if (!w.finish) return Status::Running;
                                           w.done[i] = 1;
                                           return Status::Success;
                                         },
                                         {}},
                       "MoveObject");
  chooser->add(std::move(post));
  chooser->add(std::move(run));
  return chooser;
}

template <class Root>
inline void build_paper_tree(Tree& tree, PaperWorld& w, std::size_t n) {
  w.done.assign(n, 0);
  auto root = std::make_unique<Root>("root");
  for (std::size_t i = 0; i < n; ++i) root->add(paper_subtree(w, i));
  tree.set_root(std::move(root));
}

}  // namespace rtamp::bt::testing
