// Behavior-tree engine benchmarks (the bar: one tick of a 1,000-subtree tree
// under 20 us with no allocation per tick; insertion/removal/replacement of
// subtrees in such a tree under 1 ms). The tree has the paper's action-condition
// shape (Fig. 3b): root over 1,000 subtrees
//   Chooser( Sequence(post-condition), Sequence(pre-condition, action) ).
// Global operator new is replaced by a counting one; every benchmark reports
// allocs_per_iter (allocations per tick / per reconfiguration).
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "rtamp/bt/bt.hpp"

#include "../tests/support/counting_new.hpp"

namespace {

using namespace rtamp::bt;

struct World {
  std::vector<std::uint8_t> done;
  std::size_t cursor = 0;
};

std::unique_ptr<Node> subtree(World& w, std::size_t i) {
  auto chooser = std::make_unique<Chooser>("subtree");
  auto post = std::make_unique<Sequence>("post");
  post->emplace<Condition>(
      "post", [&w, i](Node&) { return w.done[i] != 0; }, "PostCondition");
  auto run = std::make_unique<Sequence>("run");
  run->emplace<Condition>(
      "pre", [&w, i](Node&) { return w.cursor == i; }, "PreCondition");
  run->emplace<Action>(
      "act", [](Node&) { return Status::Running; }, "MoveObject");
  chooser->add(std::move(post));
  chooser->add(std::move(run));
  return chooser;
}

// n subtrees; the first n-1 are done (post-condition holds), the last one runs.
template <class Root>
void build(Tree& tree, World& w, std::size_t n) {
  w.done.assign(n, 1);
  w.done[n - 1] = 0;
  w.cursor = n - 1;
  auto root = std::make_unique<Root>("root");
  for (std::size_t i = 0; i < n; ++i) root->add(subtree(w, i));
  tree.set_root(std::move(root));
}

// Worst case for a reactive root: every tick re-ticks all 1,000 subtrees
// (999 post-condition checks + the committed running subtree).
template <class Root>
void BM_Tick(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  World w;
  Tree tree;
  build<Root>(tree, w, n);
  if (state.range(1) != 0) tree.add_status_observer([](const StatusChange&) {});
  tree.tick();
  long ticks = 0;
  const long before = rtamp_allocations();
  for (auto _ : state) {
    benchmark::DoNotOptimize(tree.tick());
    ++ticks;
  }
  state.counters["allocs_per_iter"] =
      static_cast<double>(rtamp_allocations() - before) / static_cast<double>(ticks);
  state.counters["nodes"] = static_cast<double>(tree.size());
}
BENCHMARK(BM_Tick<ReactiveSequence>)
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Args({100, 0})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Tick<Sequence>)->Args({1000, 0})->Unit(benchmark::kMicrosecond);

// A reactive root where the running subtree is preempted and restarted every tick:
// the precondition of subtree n-1 flips, so its action is halted and started again.
void BM_TickWithPreemption(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  World w;
  Tree tree;
  build<ReactiveSequence>(tree, w, n);
  tree.tick();
  long ticks = 0;
  const long before = rtamp_allocations();
  for (auto _ : state) {
    w.cursor = (ticks % 2 == 0) ? n : n - 1;           // precondition fails every other fresh pick
    w.done[0] = static_cast<std::uint8_t>(ticks % 2);  // subtree 0 alternately done / not startable
    benchmark::DoNotOptimize(tree.tick());
    ++ticks;
  }
  state.counters["allocs_per_iter"] =
      static_cast<double>(rtamp_allocations() - before) / static_cast<double>(ticks);
}
BENCHMARK(BM_TickWithPreemption)->Arg(1000)->Unit(benchmark::kMicrosecond);

// Reconfiguration: remove 10 subtrees and insert 10 freshly built ones at random
// positions (building them included), as Algorithm 2 does for a changed plan.
void BM_Reconfigure_Remove10Insert10(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  World w;
  Tree tree;
  build<ReactiveSequence>(tree, w, n);
  tree.tick();
  const NodeId root = tree.root()->id();
  std::mt19937 rng(1);
  long iters = 0;
  const long before = rtamp_allocations();
  for (auto _ : state) {
    for (int k = 0; k < 10; ++k) {
      const std::size_t pos = rng() % (tree.root()->child_count() - 1);  // never the running last subtree
      tree.remove(tree.root()->child(pos).id());
    }
    for (int k = 0; k < 10; ++k) {
      const std::size_t pos = rng() % (tree.root()->child_count());
      tree.insert(root, pos, subtree(w, pos % (n - 1)));
    }
    ++iters;
  }
  state.counters["allocs_per_iter"] =
      static_cast<double>(rtamp_allocations() - before) / static_cast<double>(iters);
  state.counters["nodes"] = static_cast<double>(tree.size());
}
BENCHMARK(BM_Reconfigure_Remove10Insert10)->Arg(1000)->Unit(benchmark::kMicrosecond);

// Replace 10 subtrees, and update 10 conditions in place (new predicate + port).
void BM_Reconfigure_Replace10(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  World w;
  Tree tree;
  build<ReactiveSequence>(tree, w, n);
  tree.tick();
  std::mt19937 rng(2);
  for (auto _ : state) {
    for (int k = 0; k < 10; ++k) {
      const std::size_t pos = rng() % (n - 1);
      tree.replace(tree.root()->child(pos).id(), subtree(w, pos));
    }
  }
}
BENCHMARK(BM_Reconfigure_Replace10)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_Reconfigure_UpdateConditions10(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  World w;
  Tree tree;
  build<ReactiveSequence>(tree, w, n);
  tree.tick();
  std::mt19937 rng(3);
  for (auto _ : state) {
    for (int k = 0; k < 10; ++k) {
      const std::size_t pos = rng() % (n - 1);
      auto& cond = static_cast<Condition&>(tree.root()->child(pos).child(0).child(0));
      cond.set_predicate([&w, pos](Node&) { return w.done[pos] != 0; });
      cond.set_port("region", "r2");
    }
  }
}
BENCHMARK(BM_Reconfigure_UpdateConditions10)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_BuildTree(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    World w;
    Tree tree;
    build<ReactiveSequence>(tree, w, n);
    benchmark::DoNotOptimize(tree.size());
  }
}
BENCHMARK(BM_BuildTree)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_ExportXml(benchmark::State& state) {
  World w;
  Tree tree;
  build<ReactiveSequence>(tree, w, static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(to_btcpp_xml(tree).size());
}
BENCHMARK(BM_ExportXml)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
