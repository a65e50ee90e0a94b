// Changing the tree between ticks (the basis of Algorithm 2): insert, remove and
// replace subtrees; ids; running state elsewhere untouched; non-interruptible
// subtrees; conditions updated in place.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "probes.hpp"
#include "rtamp/bt/bt.hpp"

namespace rtamp::bt {
namespace {

using testing::Flag;
using testing::flag_condition;
using testing::make;
using testing::Probe;
using testing::probe_action;

std::set<NodeId> ids_of(const Tree& t) {
  std::set<NodeId> out;
  t.for_each([&out](const Node& n, int) { out.insert(n.id()); });
  return out;
}

TEST(TreeChanges, IdsAreIssuedOnceAndStayStable) {
  Probe p;
  Tree tree;
  const NodeId root = tree.set_root(make<Sequence>("root", probe_action("a", p), probe_action("b", p)));
  const NodeId a = tree.root()->child(0).id();
  const NodeId b = tree.root()->child(1).id();
  EXPECT_NE(root, kNoId);
  EXPECT_EQ(ids_of(tree), (std::set<NodeId>{root, a, b}));
  EXPECT_EQ(tree.size(), 3u);
  const NodeId c = tree.insert(root, 0, probe_action("c", p));
  EXPECT_GT(c, std::max({root, a, b}));
  EXPECT_EQ(tree.root()->child(1).id(), a);
  EXPECT_EQ(tree.root()->child(2).id(), b);
  tree.remove(a);
  EXPECT_EQ(tree.find(a), nullptr);
  const NodeId d = tree.insert(root, 1, make<Fallback>("d", probe_action("e", p)));
  EXPECT_GT(d, c) << "ids are never reused";
  EXPECT_GT(tree.root()->child(1).child(0).id(), d);
  EXPECT_EQ(&tree.at(b), &tree.root()->child(2));
  EXPECT_EQ(tree.find_by_name("e"), &tree.root()->child(1).child(0));
  EXPECT_THROW(tree.at(a), rtamp::Error);
}

TEST(TreeChanges, InsertBeforeTheRunningChildOfASequenceWithMemoryKeepsItRunning) {
  Probe done, running, fresh;
  running.next = Status::Running;
  Tree tree;
  const NodeId root =
      tree.set_root(make<Sequence>("seq", probe_action("done", done), probe_action("run", running)));
  EXPECT_EQ(tree.tick(), Status::Running);
  auto& seq = static_cast<Sequence&>(*tree.root());
  EXPECT_EQ(seq.current_index(), 1u);
  tree.insert(root, 0, probe_action("fresh", fresh));
  EXPECT_EQ(seq.current_index(), 2u);
  EXPECT_EQ(tree.root()->child(2).status(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(running.runs, 1) << "the running action continues (on_running), not restarted";
  EXPECT_EQ(running.starts, 1);
  EXPECT_EQ(running.halts, 0);
  EXPECT_EQ(fresh.ticks(), 0) << "inserted before the running child: not part of this run";
  EXPECT_EQ(done.ticks(), 1);
}

TEST(TreeChanges, RemoveBeforeTheRunningChildKeepsItRunning) {
  Probe a, b, run;
  run.next = Status::Running;
  Tree tree;
  tree.set_root(make<Sequence>("seq", probe_action("a", a), probe_action("b", b), probe_action("run", run)));
  EXPECT_EQ(tree.tick(), Status::Running);
  tree.remove(tree.root()->child(0).id());
  auto& seq = static_cast<Sequence&>(*tree.root());
  EXPECT_EQ(seq.current_index(), 1u);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(run.runs, 1);
  EXPECT_EQ(run.halts, 0);
  EXPECT_EQ(b.ticks(), 1);
}

TEST(TreeChanges, RemovingARunningSubtreeHaltsIt) {
  Probe run, next;
  run.next = Status::Running;
  Tree tree;
  const NodeId root = tree.set_root(
      make<Sequence>("seq", make<Sequence>("sub", probe_action("run", run)), probe_action("next", next)));
  EXPECT_EQ(tree.tick(), Status::Running);
  std::vector<std::pair<NodeId, Status>> halted;
  tree.add_status_observer([&halted](const StatusChange& c) {
    if (c.current == Status::Invalid) halted.emplace_back(c.id, c.previous);
  });
  const NodeId sub = tree.root()->child(0).id();
  const NodeId act = tree.root()->child(0).child(0).id();
  std::unique_ptr<Node> removed = tree.remove(sub);
  EXPECT_EQ(run.halts, 1);
  EXPECT_EQ(removed->status(), Status::Invalid);
  EXPECT_EQ(removed->child(0).status(), Status::Invalid);
  EXPECT_FALSE(removed->attached());
  EXPECT_EQ(halted, (std::vector<std::pair<NodeId, Status>>{{act, Status::Running}, {sub, Status::Running}}));
  EXPECT_EQ(tree.size(), 2u);
  // The sequence resumes at the child that took the removed one's place.
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(next.starts, 1);
  (void)root;
}

TEST(TreeChanges, ChangesElsewhereDoNotDisturbARunningAction) {
  Probe run, other;
  run.next = Status::Running;
  Tree tree;
  // A Parallel keeps both branches live; branch 2 is edited while branch 1 runs.
  tree.set_root(std::make_unique<Parallel>("par", -1, 1));
  const NodeId root = tree.root()->id();
  tree.append(root, make<Sequence>("left", probe_action("run", run)));
  const NodeId right = tree.append(root, make<ReactiveSequence>("right", probe_action("other", other)));
  other.next = Status::Running;
  EXPECT_EQ(tree.tick(), Status::Running);
  Probe x, y;
  x.next = Status::Running;
  tree.insert(right, 0, probe_action("x", x));
  tree.remove(tree.at(right).child(1).id());  // "other" is running: halted
  EXPECT_EQ(other.halts, 1);
  tree.replace(tree.at(right).child(0).id(), probe_action("y", y));
  EXPECT_EQ(tree.tick(), Status::Running);  // y succeeds, right is done; left still runs
  EXPECT_EQ(tree.at(right).status(), Status::Success);
  EXPECT_EQ(y.starts, 1);
  EXPECT_EQ(x.ticks(), 0) << "x was replaced before it was ever ticked";
  EXPECT_EQ(run.starts, 1);
  EXPECT_EQ(run.runs, 1);
  EXPECT_EQ(run.halts, 0) << "the other branch's running action is untouched by the edits";
}

TEST(TreeChanges, RunningActionInAnotherSubtreeOfAReactiveRootKeepsRunning) {
  // Root ReactiveSequence(cond, Sequence(act)); edit the condition subtree while act runs.
  Flag ok;
  Probe act;
  act.next = Status::Running;
  Tree tree;
  const NodeId root = tree.set_root(make<ReactiveSequence>("root", flag_condition("ok", ok),
                                                           make<Sequence>("work", probe_action("act", act))));
  EXPECT_EQ(tree.tick(), Status::Running);
  Flag ok2;
  tree.replace(tree.root()->child(0).id(), flag_condition("ok2", ok2));
  Flag extra;
  tree.insert(root, 0, flag_condition("extra", extra));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(act.starts, 1);
  EXPECT_EQ(act.runs, 1);
  EXPECT_EQ(act.halts, 0);
  EXPECT_EQ(ok.checks, 1);
  EXPECT_EQ(ok2.checks, 1);
}

TEST(TreeChanges, ChooserKeepsItsCommitmentAcrossChanges) {
  Probe a, b, c;
  a.next = Status::Failure;
  b.next = Status::Running;
  Tree tree;
  const NodeId ch = tree.set_root(make<Chooser>("ch", probe_action("a", a), probe_action("b", b)));
  EXPECT_EQ(tree.tick(), Status::Running);
  auto& chooser = static_cast<Chooser&>(*tree.root());
  EXPECT_EQ(chooser.committed_index(), 1u);
  c.next = Status::Success;
  tree.insert(ch, 0, probe_action("c", c));
  EXPECT_EQ(chooser.committed_index(), 2u);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(c.ticks(), 0);
  EXPECT_EQ(b.runs, 1);
  // Replacing the committed child drops the commitment: fresh pick next tick.
  Probe d;
  tree.replace(tree.root()->child(2).id(), probe_action("d", d));
  EXPECT_EQ(b.halts, 1);
  EXPECT_EQ(chooser.committed_index(), Chooser::kNone);
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(c.starts, 1);
}

TEST(TreeChanges, NonInterruptibleRunningSubtreeIsNotCutUnlessForced) {
  Probe run;
  run.next = Status::Running;
  Tree tree;
  const NodeId root = tree.set_root(make<Sequence>("root", make<Sequence>("sub", probe_action("run", run))));
  const NodeId sub = tree.root()->child(0).id();
  tree.root()->child(0).child(0).set_interruptible(false);
  EXPECT_TRUE(tree.can_cut(sub)) << "not running yet";
  tree.tick();
  EXPECT_FALSE(tree.can_cut(sub));
  EXPECT_FALSE(tree.can_cut(root));
  EXPECT_THROW(tree.remove(sub), rtamp::Error);
  Probe p;
  EXPECT_THROW(tree.replace(sub, probe_action("p", p)), rtamp::Error);
  EXPECT_EQ(run.halts, 0);
  EXPECT_EQ(tree.at(sub).status(), Status::Running);
  // Insertion never cuts anything.
  tree.insert(root, 1, probe_action("later", p));
  // When it returns, it can be cut.
  run.next = Status::Success;
  tree.tick();
  EXPECT_TRUE(tree.can_cut(sub));
  // Forced removal of a running one halts it.
  run.next = Status::Running;
  tree.tick();
  tree.remove(sub, Cut::Force);
  EXPECT_EQ(run.halts, 1);
}

TEST(TreeChanges, ConditionsAreUpdatedInPlace) {
  Tree tree;
  int state = 1;
  const NodeId root = tree.set_root(make<Sequence>("root"));
  const NodeId cond = tree.append(root, std::make_unique<Condition>(
                                            "o1 in r1", [&state] { return state == 1; }, "ObjectAt"));
  tree.at(cond).set_port("object", "o1");
  tree.at(cond).set_port("region", "r1");
  EXPECT_EQ(tree.tick(), Status::Success);
  auto& c = static_cast<Condition&>(tree.at(cond));
  c.set_predicate([&state](Node&) { return state == 2; });
  c.set_port("region", "r2");
  c.set_name("o1 in r2");
  EXPECT_EQ(tree.tick(), Status::Failure);
  state = 2;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(tree.at(cond).id(), cond);
  EXPECT_EQ(*tree.at(cond).port("region"), "r2");
  EXPECT_EQ(tree.at(cond).user_ports().size(), 2u);
  EXPECT_THROW(tree.at(cond).set_port("bad name", "x"), rtamp::Error);
}

TEST(TreeChanges, ReplaceDecoratorChildAndRoot) {
  Probe a, b;
  Tree tree;
  const NodeId inv = tree.set_root(std::make_unique<Inverter>(probe_action("a", a)));
  const NodeId child = tree.root()->child(0).id();
  EXPECT_THROW(tree.remove(child), rtamp::Error) << "a decorator's only child is replaced, not removed";
  b.next = Status::Failure;
  const NodeId nb = tree.replace(child, probe_action("b", b));
  EXPECT_EQ(tree.root()->child(0).id(), nb);
  EXPECT_EQ(tree.tick(), Status::Success);
  std::unique_ptr<Node> old;
  const NodeId nr = tree.replace(inv, make<Sequence>("new root"), Cut::IfInterruptible, &old);
  EXPECT_EQ(tree.root()->id(), nr);
  EXPECT_EQ(old->name(), "Inverter");
  EXPECT_EQ(tree.size(), 1u);
  std::unique_ptr<Node> r = tree.remove(nr);
  EXPECT_EQ(tree.root(), nullptr);
  EXPECT_EQ(tree.size(), 0u);
}

TEST(TreeChanges, AMovedSubtreeKeepsItsIds) {
  Probe p;
  Tree tree;
  const NodeId root = tree.set_root(
      make<Sequence>("root", make<Sequence>("sub", probe_action("a", p)), probe_action("b", p)));
  const NodeId sub = tree.root()->child(0).id();
  const NodeId a = tree.root()->child(0).child(0).id();
  auto moved = tree.remove(sub);
  EXPECT_EQ(tree.insert(root, 1, std::move(moved)), sub);
  EXPECT_EQ(tree.root()->child(1).child(0).id(), a);
  // A subtree from another tree gets fresh ids here.
  Tree other;
  other.set_root(make<Sequence>("x", probe_action("y", p)));
  other.set_root(make<Sequence>("x2"));
  auto foreign = make<Sequence>("z", probe_action("w", p));
  const NodeId z = tree.append(root, std::move(foreign));
  EXPECT_GT(z, a);
}

TEST(TreeChanges, ErrorsAreClear) {
  Probe p;
  Tree tree;
  const NodeId root = tree.set_root(make<Sequence>("root", probe_action("a", p)));
  const NodeId leaf = tree.root()->child(0).id();
  EXPECT_THROW(tree.insert(leaf, 0, probe_action("x", p)), rtamp::Error);
  EXPECT_THROW(tree.insert(root, 5, probe_action("x", p)), rtamp::Error);
  EXPECT_THROW(tree.insert(12345, 0, probe_action("x", p)), rtamp::Error);
  EXPECT_THROW(tree.insert(root, 0, nullptr), rtamp::Error);
  EXPECT_EQ(tree.size(), 2u);
}

TEST(TreeChanges, ChangeObserverAndCount) {
  Probe p;
  Tree tree;
  std::vector<TreeChange::Kind> kinds;
  tree.add_change_observer([&kinds](const TreeChange& c) { kinds.push_back(c.kind); });
  const NodeId root = tree.set_root(make<Sequence>("root"));
  const NodeId a = tree.append(root, probe_action("a", p));
  tree.replace(a, probe_action("b", p));
  tree.remove(tree.root()->child(0).id());
  using K = TreeChange::Kind;
  EXPECT_EQ(kinds, (std::vector<K>{K::SetRoot, K::Insert, K::Replace, K::Remove}));
  EXPECT_EQ(tree.change_count(), 4u);
}

// Random edits of a reactive root with one subtree that keeps running: the running
// action is never disturbed, ids stay unique and match the registry, and the set of
// ids in the tree is exactly what a model of the edits predicts.
TEST(TreeChanges, RandomEditsNeverDisturbTheRunningSubtree) {
  std::mt19937 rng(7);
  Probe run;
  run.next = Status::Running;
  Tree tree;
  const NodeId root = tree.set_root(std::make_unique<ReactiveSequence>("root"));
  const NodeId keep = tree.append(root, make<Sequence>("keep", probe_action("run", run)));
  std::vector<NodeId> model{keep};  // children of root, in order
  std::vector<std::unique_ptr<Probe>> probes;
  NodeId max_id = keep + 1;
  EXPECT_EQ(tree.tick(), Status::Running);
  for (int step = 0; step < 400; ++step) {
    const int op = static_cast<int>(rng() % 3);
    const std::size_t pos_keep = std::find(model.begin(), model.end(), keep) - model.begin();
    if (op == 0 || model.size() == 1) {
      // insert a succeeding subtree anywhere before the running one (after it would not be ticked)
      const std::size_t pos = rng() % (pos_keep + 1);
      probes.push_back(std::make_unique<Probe>());
      const NodeId id = tree.insert(root, pos, make<Chooser>("s", probe_action("p", *probes.back())));
      EXPECT_GT(id, max_id);
      max_id = id + 1;
      model.insert(model.begin() + static_cast<std::ptrdiff_t>(pos), id);
    } else {
      std::size_t pos = rng() % model.size();
      if (model[pos] == keep) continue;
      if (op == 1) {
        tree.remove(model[pos]);
        model.erase(model.begin() + static_cast<std::ptrdiff_t>(pos));
      } else {
        probes.push_back(std::make_unique<Probe>());
        const NodeId id = tree.replace(model[pos], make<Sequence>("r", probe_action("q", *probes.back())));
        EXPECT_GT(id, max_id);
        max_id = id + 1;
        model[pos] = id;
      }
    }
    if (rng() % 2 == 0) {
      EXPECT_EQ(tree.tick(), Status::Running);
    }
    ASSERT_EQ(tree.root()->child_count(), model.size());
    for (std::size_t i = 0; i < model.size(); ++i) ASSERT_EQ(tree.root()->child(i).id(), model[i]);
    ASSERT_EQ(run.halts, 0);
    ASSERT_EQ(run.starts, 1);
    std::size_t count = 0;
    tree.for_each([&](const Node& n, int) {
      ++count;
      ASSERT_EQ(tree.find(n.id()), &n);
    });
    ASSERT_EQ(count, tree.size());
  }
}

}  // namespace
}  // namespace rtamp::bt
