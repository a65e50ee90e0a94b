// Chooser (py_trees 2.0 semantics) versus Fallback/ReactiveFallback, and the
// paper's action-condition subtree shape (Fig. 3b).
#include <gtest/gtest.h>

#include "probes.hpp"
#include "rtamp/bt/bt.hpp"

namespace rtamp::bt {
namespace {

using testing::Flag;
using testing::flag_condition;
using testing::make;
using testing::Probe;
using testing::probe_action;

// [ Sequence(ready_hi?, hi), lo ] under the given selector.
template <class Selector>
struct PriorityCase {
  Flag ready;
  Probe hi, lo;
  Tree tree;
  PriorityCase() {
    ready.value = false;
    hi.next = Status::Running;
    lo.next = Status::Running;
    tree.set_root(
        make<Selector>("sel", make<Sequence>("high", flag_condition("ready", ready), probe_action("hi", hi)),
                       probe_action("lo", lo)));
  }
};

TEST(Chooser, KeepsTheRunningChildWhenAHigherPriorityChildBecomesReady) {
  PriorityCase<Chooser> c;
  EXPECT_EQ(c.tree.tick(), Status::Running);
  EXPECT_EQ(c.lo.starts, 1);
  EXPECT_EQ(c.ready.checks, 1);
  c.ready.value = true;
  EXPECT_EQ(c.tree.tick(), Status::Running);
  EXPECT_EQ(c.tree.tick(), Status::Running);
  EXPECT_EQ(c.ready.checks, 1) << "higher-priority siblings are not even evaluated while committed";
  EXPECT_EQ(c.hi.ticks(), 0);
  EXPECT_EQ(c.lo.runs, 2);
  EXPECT_EQ(c.lo.halts, 0);
  // lo finishes: the next tick picks afresh from the top.
  c.lo.next = Status::Success;
  EXPECT_EQ(c.tree.tick(), Status::Success);
  EXPECT_EQ(c.tree.tick(), Status::Running);
  EXPECT_EQ(c.hi.starts, 1);
  EXPECT_EQ(static_cast<Chooser*>(c.tree.root())->committed_index(), 0u);
}

TEST(ReactiveFallback, PreemptsAndHaltsTheRunningChildWhenAHigherPriorityChildBecomesReady) {
  PriorityCase<ReactiveFallback> c;
  EXPECT_EQ(c.tree.tick(), Status::Running);
  c.ready.value = true;
  EXPECT_EQ(c.tree.tick(), Status::Running);
  EXPECT_EQ(c.lo.halts, 1);
  EXPECT_EQ(c.hi.starts, 1);
  EXPECT_EQ(c.tree.root()->child(1).status(), Status::Invalid);
}

TEST(Fallback, WithMemoryAlsoKeepsTheRunningChild) {
  PriorityCase<Fallback> c;
  EXPECT_EQ(c.tree.tick(), Status::Running);
  c.ready.value = true;
  EXPECT_EQ(c.tree.tick(), Status::Running);
  EXPECT_EQ(c.ready.checks, 1);
  EXPECT_EQ(c.lo.halts, 0);
}

TEST(Chooser, CommittedChildFailureIsReturnedWithoutFallingThrough) {
  Probe a, b;
  a.next = Status::Running;
  Tree tree;
  tree.set_root(make<Chooser>("ch", probe_action("a", a), probe_action("b", b)));
  EXPECT_EQ(tree.tick(), Status::Running);
  a.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(b.ticks(), 0) << "no fall-through to later children in the same tick";
  // Next tick: fresh pick, a fails, b succeeds.
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(b.starts, 1);
}

TEST(Fallback, FallsThroughWhenTheRunningChildFails) {
  Probe a, b;
  a.next = Status::Running;
  Tree tree;
  tree.set_root(make<Fallback>("fb", probe_action("a", a), probe_action("b", b)));
  EXPECT_EQ(tree.tick(), Status::Running);
  a.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(b.starts, 1);
}

TEST(Chooser, FreshPickIsASelector) {
  Probe a, b, c;
  a.next = Status::Failure;
  b.next = Status::Success;
  Tree tree;
  tree.set_root(make<Chooser>("ch", probe_action("a", a), probe_action("b", b), probe_action("c", c)));
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(c.ticks(), 0);
  a.next = Status::Failure;
  b.next = Status::Failure;
  c.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(c.starts, 1);
  EXPECT_EQ(static_cast<Chooser*>(tree.root())->committed_index(), Chooser::kNone);
}

TEST(Chooser, HaltReleasesTheCommitment) {
  Probe a, b;
  b.next = Status::Running;
  a.next = Status::Failure;
  Tree tree;
  tree.set_root(make<Chooser>("ch", probe_action("a", a), probe_action("b", b)));
  EXPECT_EQ(tree.tick(), Status::Running);
  tree.halt();
  EXPECT_EQ(b.halts, 1);
  a.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(b.starts, 1);
}

// The paper's action-condition tree: root over subtrees
//   Chooser( Sequence(post-condition), Sequence(pre-condition, action) ).
// A world of one counter: action i moves the counter from i to i+1 in 2 ticks.
TEST(PaperShape, ActionConditionSubtreesExecuteThePlanAndRecoverFromSetbacks) {
  int state = 0;
  std::vector<int> started;
  Tree tree;
  auto root = std::make_unique<Sequence>("plan");
  for (int i = 0; i < 3; ++i) {
    auto chooser = std::make_unique<Chooser>("step" + std::to_string(i));
    auto post = std::make_unique<Sequence>("done?");
    post->emplace<Condition>("post", [&state, i] { return state >= i + 1; });
    auto run = std::make_unique<Sequence>("do");
    run->emplace<Condition>("pre", [&state, i] { return state == i; });
    auto left = std::make_shared<int>(0);
    run->emplace<Action>("act", Action::Callbacks{[&started, left, i](Node&) {
                                                    started.push_back(i);
                                                    *left = 1;
                                                    return Status::Running;
                                                  },
                                                  [&state, left, i](Node&) {
                                                    if (--*left > 0) return Status::Running;
                                                    state = i + 1;
                                                    return Status::Success;
                                                  },
                                                  {}});
    chooser->add(std::move(post));
    chooser->add(std::move(run));
    root->add(std::move(chooser));
  }
  tree.set_root(std::move(root));
  Status s = Status::Running;
  int ticks = 0;
  while (s == Status::Running && ticks < 50) {
    s = tree.tick();
    ++ticks;
  }
  EXPECT_EQ(s, Status::Success);
  EXPECT_EQ(state, 3);
  EXPECT_EQ(started, (std::vector<int>{0, 1, 2}));
  // A setback (someone undoes step 2): a new run skips steps 0 and 1 by their
  // post-conditions and redoes only step 2.
  state = 2;
  started.clear();
  s = Status::Running;
  while (s == Status::Running) s = tree.tick();
  EXPECT_EQ(s, Status::Success);
  EXPECT_EQ(started, (std::vector<int>{2}));
}

}  // namespace
}  // namespace rtamp::bt
