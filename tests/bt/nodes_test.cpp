// Semantics of every node type (composites, decorators, leaves), observers and
// visitors. Oracles: the py_trees / BehaviorTree.CPP rules written in each
// header, and for boolean trees a direct evaluation of the formula.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "probes.hpp"
#include "rtamp/bt/bt.hpp"

namespace rtamp::bt {
namespace {

using testing::Flag;
using testing::flag_condition;
using testing::make;
using testing::Probe;
using testing::probe_action;

TEST(Sequence, ResumesAtRunningChildWithoutRetickingEarlierOnes) {
  Probe a, b;
  Tree tree;
  tree.set_root(make<Sequence>("seq", probe_action("a", a), probe_action("b", b)));
  b.next = Status::Running;
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(a.starts, 1);
  EXPECT_EQ(b.starts, 1);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(a.ticks(), 1) << "memory: the finished first child is not ticked again";
  EXPECT_EQ(b.runs, 1);
  b.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(a.ticks(), 1);
  EXPECT_EQ(b.runs, 2);
  // A new run starts from the first child again.
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(a.starts, 2);
  EXPECT_EQ(b.starts, 2);
}

TEST(Sequence, FailureEndsTheRunAndRestartsFromTheFirstChild) {
  Probe a, b, c;
  Tree tree;
  tree.set_root(make<Sequence>("seq", probe_action("a", a), probe_action("b", b), probe_action("c", c)));
  b.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(c.ticks(), 0);
  EXPECT_EQ(tree.root()->child(2).status(), Status::Invalid);
  b.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(a.starts, 2);
}

TEST(Sequence, YieldsBetweenChildrenWhileAsked) {
  Probe a, b;
  Tree tree;
  auto seq = make<Sequence>("seq", probe_action("a", a), probe_action("b", b));
  bool hold = true;
  seq->set_yield([&] { return hold; });
  tree.set_root(std::move(seq));
  EXPECT_EQ(tree.tick(), Status::Running) << "a succeeded; the sequence yields before b";
  EXPECT_EQ(a.starts, 1);
  EXPECT_EQ(b.starts, 0);
  EXPECT_EQ(tree.root()->child(1).status(), Status::Invalid);
  EXPECT_EQ(tree.tick(), Status::Success) << "the next tick resumes at b (a is not re-ticked)";
  EXPECT_EQ(a.ticks(), 1);
  EXPECT_EQ(b.starts, 1);
  hold = false;
  EXPECT_EQ(tree.tick(), Status::Success) << "not asked: a and b in one tick";
  EXPECT_EQ(a.starts, 2);
  EXPECT_EQ(b.starts, 2);
}

TEST(ReactiveSequence, RetickEarlierChildrenAndHaltRunningLaterChild) {
  Flag ok;
  Probe act;
  act.next = Status::Running;
  Tree tree;
  tree.set_root(make<ReactiveSequence>("rs", flag_condition("ok", ok), probe_action("act", act)));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(ok.checks, 2) << "the condition is re-ticked every tick";
  EXPECT_EQ(act.starts, 1);
  EXPECT_EQ(act.runs, 1);
  ok.value = false;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(act.halts, 1) << "the running action is halted when the condition fails";
  EXPECT_EQ(tree.root()->child(1).status(), Status::Invalid);
  ok.value = true;
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(act.starts, 2) << "after a halt the action starts afresh";
}

TEST(Fallback, ResumesAtRunningChild) {
  Probe a, b;
  a.next = Status::Failure;
  b.next = Status::Running;
  Tree tree;
  tree.set_root(make<Fallback>("fb", probe_action("a", a), probe_action("b", b)));
  EXPECT_EQ(tree.tick(), Status::Running);
  a.next = Status::Success;  // would win if it were re-ticked
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(a.ticks(), 1) << "memory: the failed first child is not re-ticked while b runs";
  b.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(tree.tick(), Status::Success) << "new run: a is ticked again and now succeeds";
  EXPECT_EQ(tree.root()->child(1).status(), Status::Invalid);
}

TEST(ReactiveFallback, HigherPriorityChildPreemptsRunningLowerChild) {
  Flag hi;
  hi.value = false;
  Probe lo;
  lo.next = Status::Running;
  Tree tree;
  tree.set_root(make<ReactiveFallback>("rf", flag_condition("hi", hi), probe_action("lo", lo)));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  hi.value = true;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(lo.halts, 1);
  EXPECT_EQ(tree.root()->child(1).status(), Status::Invalid);
}

TEST(Composites, EmptyOutcomes) {
  auto tick_empty = [](std::unique_ptr<Node> n) {
    Tree t;
    t.set_root(std::move(n));
    return t.tick();
  };
  EXPECT_EQ(tick_empty(std::make_unique<Sequence>()), Status::Success);
  EXPECT_EQ(tick_empty(std::make_unique<ReactiveSequence>()), Status::Success);
  EXPECT_EQ(tick_empty(std::make_unique<Fallback>()), Status::Failure);
  EXPECT_EQ(tick_empty(std::make_unique<ReactiveFallback>()), Status::Failure);
  EXPECT_EQ(tick_empty(std::make_unique<Chooser>()), Status::Failure);
  // An empty Parallel succeeds whatever its thresholds ((1, 1) used to fail).
  for (int sc = -3; sc <= 3; ++sc) {
    for (int fc = -3; fc <= 3; ++fc) {
      EXPECT_EQ(tick_empty(std::make_unique<Parallel>("par", sc, fc)), Status::Success) << sc << " " << fc;
    }
  }
  EXPECT_EQ(tick_empty(Parallel::success_on_one()), Status::Success);
  Tree empty;
  EXPECT_EQ(empty.tick(), Status::Invalid);
}

TEST(Parallel, SuccessOnAllWaitsForEveryChildAndDoesNotRetickFinishedOnes) {
  Probe a, b;
  b.next = Status::Running;
  Tree tree;
  tree.set_root(Parallel::success_on_all("par"));
  tree.append(tree.root()->id(), probe_action("a", a));
  tree.append(tree.root()->id(), probe_action("b", b));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(a.ticks(), 1) << "a finished in this run: not ticked again";
  b.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(a.ticks(), 2) << "new run";
}

TEST(Parallel, SuccessOnOneHaltsTheOthers) {
  Probe a, b;
  a.next = Status::Running;
  b.next = Status::Running;
  Tree tree;
  tree.set_root(Parallel::success_on_one("par"));
  tree.append(tree.root()->id(), probe_action("a", a));
  tree.append(tree.root()->id(), probe_action("b", b));
  EXPECT_EQ(tree.tick(), Status::Running);
  b.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(a.halts, 1);
  EXPECT_EQ(b.halts, 0);
}

TEST(Parallel, ThresholdsMatchACountingOracle) {
  // All combinations of 3 children outcomes and thresholds, one tick each.
  const Status outcomes[] = {Status::Success, Status::Failure, Status::Running};
  for (int sc = -3; sc <= 3; ++sc) {
    for (int fc = -3; fc <= 3; ++fc) {
      for (int code = 0; code < 27; ++code) {
        Probe p[3];
        std::size_t s = 0, f = 0;
        for (int k = 0, c = code; k < 3; ++k, c /= 3) {
          p[k].next = outcomes[c % 3];
          s += p[k].next == Status::Success;
          f += p[k].next == Status::Failure;
        }
        Tree tree;
        tree.set_root(std::make_unique<Parallel>("par", sc, fc));
        for (auto& q : p) tree.append(tree.root()->id(), probe_action("x", q));
        auto resolve = [](int t) -> std::size_t {
          return t >= 0 ? std::size_t(t) : std::size_t(std::max(0, 3 + t + 1));
        };
        const std::size_t S = resolve(sc), F = resolve(fc);
        Status expected = Status::Running;
        if ((F > 0 && f >= F) || 3 - f < S) {
          expected = Status::Failure;
        } else if (s >= S) {
          expected = Status::Success;
        }
        ASSERT_EQ(tree.tick(), expected) << "sc=" << sc << " fc=" << fc << " code=" << code;
        if (expected != Status::Running) {
          for (auto& q : p) EXPECT_EQ(q.halts, q.next == Status::Running ? 1 : 0);
        }
      }
    }
  }
}

TEST(Inverter, SwapsSuccessAndFailure) {
  Probe a;
  Tree tree;
  tree.set_root(std::make_unique<Inverter>(probe_action("a", a)));
  EXPECT_EQ(tree.tick(), Status::Failure);
  a.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Success);
  a.next = Status::Running;
  EXPECT_EQ(tree.tick(), Status::Running);
}

TEST(Retry, RetriesOnTheNextTickUpToNAttempts) {
  Probe a;
  a.next = Status::Failure;
  Tree tree;
  tree.set_root(std::make_unique<Retry>(3, probe_action("a", a)));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(a.starts, 3);
  // Success on the second attempt.
  EXPECT_EQ(tree.tick(), Status::Running);
  a.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(a.starts, 5);
  // A running attempt is not a failure.
  a.next = Status::Running;
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(static_cast<Retry*>(tree.root())->failures(), 0);
}

TEST(Retry, UnlimitedAttemptsNeverHangATick) {
  Probe a;
  a.next = Status::Failure;
  Tree tree;
  tree.set_root(std::make_unique<Retry>(-1, probe_action("a", a)));
  for (int i = 0; i < 100; ++i) EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(a.starts, 100);
  EXPECT_THROW(Retry(0, nullptr), rtamp::Error);
}

TEST(Timeout, FailsAndHaltsTheChildOnTheInjectedClock) {
  auto clock = std::make_shared<ManualClock>();
  Probe a;
  a.next = Status::Running;
  Tree tree(std::make_shared<Blackboard>(), clock);
  tree.set_root(std::make_unique<Timeout>(std::chrono::milliseconds(100), probe_action("a", a)));
  EXPECT_EQ(tree.tick(), Status::Running);
  clock->advance(std::chrono::milliseconds(99));
  EXPECT_EQ(tree.tick(), Status::Running);
  clock->advance(std::chrono::milliseconds(1));
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(a.halts, 1);
  EXPECT_EQ(a.runs, 1) << "the expired child is not ticked";
  // A new run restarts the timer.
  EXPECT_EQ(tree.tick(), Status::Running);
  clock->advance(std::chrono::milliseconds(50));
  a.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
}

TEST(StateUpdate, CallsTheHookWhenTheChildSucceeds) {
  Probe a;
  a.next = Status::Running;
  Tree tree;
  tree.blackboard().set<int>("state", 0);
  int calls = 0;
  tree.set_root(std::make_unique<StateUpdate>(
      "update",
      [&calls](Node& self) {
        ++calls;
        self.blackboard().get<int>("state") += 1;
      },
      probe_action("a", a)));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(calls, 0);
  a.next = Status::Success;
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(tree.blackboard().get<int>("state"), 1);
  a.next = Status::Failure;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_EQ(calls, 1);
}

TEST(Action, LifecycleStartRunningHalted) {
  Probe a;
  a.next = Status::Running;
  Tree tree;
  tree.set_root(probe_action("a", a));
  tree.tick();
  tree.tick();
  tree.tick();
  EXPECT_EQ(a.starts, 1);
  EXPECT_EQ(a.runs, 2);
  tree.halt();
  EXPECT_EQ(a.halts, 1);
  EXPECT_EQ(tree.status(), Status::Invalid);
  tree.halt();
  EXPECT_EQ(a.halts, 1) << "halting an INVALID node does nothing";
  a.next = Status::Success;
  tree.tick();
  tree.halt();
  EXPECT_EQ(a.halts, 1) << "a finished action is reset, not halted";
}

TEST(Tree, DestructionHaltsRunningActions) {
  Probe a, b;
  a.next = Status::Running;
  {
    Tree tree;
    int notified = 0;
    tree.add_status_observer([&notified](const StatusChange&) { ++notified; });
    tree.set_root(make<Sequence>("s", probe_action("a", a), probe_action("b", b)));
    tree.tick();
    EXPECT_EQ(notified, 2);
  }
  EXPECT_EQ(a.halts, 1);
  EXPECT_EQ(b.halts, 0);
}

// A user-written control node (derived from Composite) works like the built-ins and
// is exported as a custom <Control> in the model.
class FirstOnly : public Composite {
 public:
  FirstOnly() : Composite("first only") {}
  std::string_view type_id() const override { return "FirstOnly"; }

 protected:
  Status on_tick() override {
    if (children_.empty()) return Status::Failure;
    const Status s = children_[0]->tick();
    note_ticked(0);
    return s;
  }
};

TEST(CustomNode, DerivedControlTicksAndExports) {
  Probe a;
  a.next = Status::Running;
  Tree tree;
  auto root = std::make_unique<FirstOnly>();
  root->add(probe_action("a", a));
  tree.set_root(std::move(root));
  EXPECT_EQ(tree.tick(), Status::Running);
  tree.halt();
  EXPECT_EQ(a.halts, 1);
  const std::string xml = to_btcpp_xml(tree);
  EXPECT_NE(xml.find("<FirstOnly name=\"first only #1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("<Control ID=\"FirstOnly\"/>"), std::string::npos) << xml;
}

TEST(Action, ReturningInvalidIsAnError) {
  Tree tree;
  tree.set_root(std::make_unique<Action>("bad", [] { return Status::Invalid; }));
  EXPECT_THROW(tree.tick(), rtamp::Error);
}

TEST(Leaves, NullaryCallablesAndSubclasses) {
  class Counter : public Action {
   public:
    Counter() : Action("counter", "Counter") {}
    int n = 0;

   protected:
    Status on_start() override {
      n = 1;
      return Status::Running;
    }
    Status on_running() override { return ++n >= 3 ? Status::Success : Status::Running; }
  };
  class Even : public Condition {
   public:
    explicit Even(const int* v) : Condition("even", "IsEven"), v_(v) {}

   protected:
    bool check() override { return *v_ % 2 == 0; }

   private:
    const int* v_;
  };
  int v = 2;
  Tree tree;
  auto root = std::make_unique<Sequence>("s");
  root->emplace<Even>(&v);
  root->emplace<Condition>("nullary", [] { return true; });
  Counter& c = root->emplace<Counter>();
  tree.set_root(std::move(root));
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Running);
  EXPECT_EQ(tree.tick(), Status::Success);
  EXPECT_EQ(c.n, 3);
  v = 3;
  EXPECT_EQ(tree.tick(), Status::Failure);
  EXPECT_THROW(Action(
                   "x", [] { return Status::Success; }, "Sequence"),
               rtamp::Error)
      << "reserved ID";
  EXPECT_THROW(Condition(
                   "x", [] { return true; }, "bad id"),
               rtamp::Error);
}

TEST(Decorator, TickingWithoutChildIsAnError) {
  Tree tree;
  tree.set_root(std::make_unique<Inverter>());
  EXPECT_THROW(tree.tick(), rtamp::Error);
}

TEST(Observer, ReportsEveryStatusChangeWithTickNumbers) {
  Probe a;
  a.next = Status::Running;
  Tree tree;
  tree.set_root(make<Sequence>("seq", probe_action("a", a)));
  std::vector<std::tuple<NodeId, std::string, Status, Status, std::uint64_t>> log;
  auto h = tree.add_status_observer([&log](const StatusChange& c) {
    log.emplace_back(c.id, std::string(c.name), c.previous, c.current, c.tick);
  });
  tree.tick();
  tree.tick();  // nothing changes
  a.next = Status::Success;
  tree.tick();
  const NodeId seq = tree.root()->id(), act = tree.root()->child(0).id();
  using E = std::tuple<NodeId, std::string, Status, Status, std::uint64_t>;
  std::vector<E> expected = {
      E{act, "a", Status::Invalid, Status::Running, 1}, E{seq, "seq", Status::Invalid, Status::Running, 1},
      E{act, "a", Status::Running, Status::Success, 3}, E{seq, "seq", Status::Running, Status::Success, 3}};
  EXPECT_EQ(log, expected);
  EXPECT_TRUE(tree.remove_observer(h));
  EXPECT_FALSE(tree.remove_observer(h));
  tree.halt();
  EXPECT_EQ(log.size(), expected.size());
}

TEST(Visitor, PreOrderWithDepths) {
  Tree tree;
  Probe a, b;
  auto root = make<Sequence>("r", make<Fallback>("f", probe_action("a", a)), probe_action("b", b));
  tree.set_root(std::move(root));
  std::string seen;
  tree.for_each([&seen](const Node& n, int d) { seen += std::to_string(d) + n.name() + " "; });
  EXPECT_EQ(seen, "0r 1f 2a 1b ");
}

// Random boolean trees: ReactiveSequence = AND, ReactiveFallback = OR, Inverter =
// NOT over conditions; the tree's outcome must equal the formula's value.
struct Formula {
  int op;  // 0 leaf, 1 and, 2 or, 3 not
  int var = 0;
  std::vector<Formula> kids;
};

Formula random_formula(std::mt19937& rng, int depth) {
  Formula f;
  f.op = depth == 0 ? 0 : static_cast<int>(rng() % 4);
  if (f.op == 0) {
    f.var = static_cast<int>(rng() % 6);
  } else if (f.op == 3) {
    f.kids.push_back(random_formula(rng, depth - 1));
  } else {
    const int n = static_cast<int>(rng() % 4);  // 0..3 children (empty AND/OR too)
    for (int i = 0; i < n; ++i) f.kids.push_back(random_formula(rng, depth - 1));
  }
  return f;
}

bool eval(const Formula& f, const bool* vars) {
  switch (f.op) {
    case 0:
      return vars[f.var];
    case 1: {
      bool r = true;
      for (const auto& k : f.kids) r = r && eval(k, vars);
      return r;
    }
    case 2: {
      bool r = false;
      for (const auto& k : f.kids) r = r || eval(k, vars);
      return r;
    }
    default:
      return !eval(f.kids[0], vars);
  }
}

std::unique_ptr<Node> build(const Formula& f, const bool* vars, bool memory) {
  switch (f.op) {
    case 0:
      return std::make_unique<Condition>("v", [vars, v = f.var] { return vars[v]; });
    case 1: {
      std::unique_ptr<Composite> c;
      if (memory)
        c = std::make_unique<Sequence>();
      else
        c = std::make_unique<ReactiveSequence>();
      for (const auto& k : f.kids) c->add(build(k, vars, memory));
      return c;
    }
    case 2: {
      std::unique_ptr<Composite> c;
      if (memory)
        c = std::make_unique<Fallback>();
      else
        c = std::make_unique<ReactiveFallback>();
      for (const auto& k : f.kids) c->add(build(k, vars, memory));
      return c;
    }
    default:
      return std::make_unique<Inverter>(build(f.kids[0], vars, memory));
  }
}

TEST(BooleanTrees, OutcomeEqualsDirectEvaluation) {
  std::mt19937 rng(12345);
  bool vars[6];
  for (int trial = 0; trial < 300; ++trial) {
    const Formula f = random_formula(rng, 4);
    for (bool memory : {false, true}) {
      Tree tree;
      tree.set_root(build(f, vars, memory));
      for (int round = 0; round < 8; ++round) {
        for (bool& v : vars) v = rng() % 2 == 0;
        const Status expected = eval(f, vars) ? Status::Success : Status::Failure;
        ASSERT_EQ(tree.tick(), expected) << "trial " << trial;
      }
    }
  }
}

}  // namespace
}  // namespace rtamp::bt
