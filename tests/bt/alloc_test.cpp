// tick() allocates nothing: counts global operator new calls while ticking a
// 1,000-subtree tree of the paper's shape (steady running, preemption and halts,
// an observer registered). This executable replaces global operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "paper_tree.hpp"
#include "probes.hpp"

#include "../support/counting_new.hpp"

namespace {
int* volatile g_sink = nullptr;  // keeps the compiler from eliding new/delete pairs
}  // namespace

namespace rtamp::bt {
namespace {

using testing::build_paper_tree;
using testing::PaperWorld;

template <class F>
long allocations_during(F&& f) {
  const long before = rtamp_allocations();
  f();
  return rtamp_allocations() - before;
}

TEST(Allocation, CountingWorks) {
  EXPECT_GE(allocations_during([] {
              g_sink = new int(3);
              delete g_sink;
            }),
            1);
}

template <class Root>
void check_no_allocation_per_tick() {
  PaperWorld w;
  Tree tree;
  build_paper_tree<Root>(tree, w, 1000);
  for (std::size_t i = 0; i + 1 < 1000; ++i) w.done[i] = 1;
  w.cursor = 999;
  ASSERT_EQ(tree.tick(), Status::Running);  // warm-up: the last subtree's action starts
  EXPECT_EQ(allocations_during([&] {
              for (int k = 0; k < 100; ++k) ASSERT_EQ(tree.tick(), Status::Running);
            }),
            0);
  // Finish it, then the whole tree succeeds; undo two subtrees (re-execution, halts).
  EXPECT_EQ(allocations_during([&] {
              w.finish = true;
              ASSERT_EQ(tree.tick(), Status::Success);
              w.finish = false;
              w.done[10] = 0;
              w.cursor = 10;
              ASSERT_EQ(tree.tick(), Status::Running);
              ASSERT_EQ(tree.tick(), Status::Running);
              tree.halt();
              ASSERT_EQ(tree.tick(), Status::Running);
            }),
            0);
}

TEST(Allocation, NonePerTickUnderAReactiveSequenceRoot) { check_no_allocation_per_tick<ReactiveSequence>(); }
TEST(Allocation, NonePerTickUnderASequenceRoot) { check_no_allocation_per_tick<Sequence>(); }

TEST(Allocation, NoneWithAnObserverAndPreemption) {
  PaperWorld w;
  Tree tree;
  build_paper_tree<ReactiveSequence>(tree, w, 1000);
  long changes = 0;
  tree.add_status_observer([&changes](const StatusChange& c) { changes += c.current != c.previous; });
  // ReactiveFallback(flag, running action): toggling the flag preempts and restarts the action.
  testing::Flag flag;
  flag.value = false;
  testing::Probe probe;
  probe.next = Status::Running;
  Tree rf;
  rf.add_status_observer([&changes](const StatusChange&) { ++changes; });
  rf.set_root(testing::make<ReactiveFallback>("rf", testing::flag_condition("flag", flag),
                                              testing::probe_action("act", probe)));
  tree.tick();
  rf.tick();
  EXPECT_EQ(allocations_during([&] {
              for (int k = 0; k < 50; ++k) {
                tree.tick();
                flag.value = (k % 2) == 0;
                rf.tick();
              }
            }),
            0);
  EXPECT_GT(changes, 0);
  EXPECT_EQ(probe.halts, 25);
}

}  // namespace
}  // namespace rtamp::bt
