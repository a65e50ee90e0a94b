// The trial grid of a batch experiment — the design of the paper's Section VI
// ("per each method and setting, we created 30 test scenarios by randomly
// placing objects in the beginning and then introduced an additional
// environmental change ... at a random time"): algorithms × change kinds ×
// behavior-tree variants × trials 1..N.
//
// Invariants:
//  - A trial's seed depends only on (trial index, base seed), so trial k
//    places the objects the same way and makes the same intervention (for a
//    given change kind) for every algorithm and BT variant: comparisons are
//    paired. Different trial indices get unrelated seeds (SplitMix64 mixing).
//  - make_trials() lists the grid trial-major (trial 1 of every cell, then
//    trial 2, ...), cells in canonical order (rank() below).
//  - Shard K/N (1-based) holds the trials whose position p in that list has
//    p mod N == K-1: the N shards partition the list, their sizes differ by at
//    most one, and every shard sees every cell.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/plan/registry.hpp"

namespace rtamp::batch {

// The names used on the command line and in the CSV. Algorithms are the
// planner's (plan::Algorithm; names, parsing and order from plan/registry.hpp).
// A ChangeKind is the kind of random change a trial makes (or none), a grid
// axis: which change, where and when is drawn from the trial's seed when the
// episode runs (episode::EpisodeOptions::random_change), so it is a choice and
// not a change of the world (world::Change). Their names and order come from
// world::random_change_kinds() (then "none") and exec::tree_variants().
enum class ChangeKind { Relocate, Remove, Add, None };          // relocate | remove | add | none
enum class BtVariant { OnlineAction, OnlineState, Offline };    // online-action | online-state | offline

const char* to_string(ChangeKind c);
const char* to_string(BtVariant v);
// Parsing; throws rtamp::Error naming the accepted values.
ChangeKind parse_change_kind(std::string_view s);
BtVariant parse_bt_variant(std::string_view s);

// Canonical order of a name inside its kind (the paper's Table I order:
// relocate, remove, add; astar-exp, astar, dijkstra as in plan::algorithms();
// online-action, online-state, offline). Unknown names rank after all known ones.
int algorithm_rank(std::string_view name);
int change_rank(std::string_view name);
int bt_rank(std::string_view name);

// One episode to run.
struct Trial {
  plan::Algorithm algorithm = plan::Algorithm::AStarExperience;
  ChangeKind change = ChangeKind::Relocate;
  BtVariant bt = BtVariant::OnlineAction;
  int index = 1;           // 1-based trial number within its cell
  std::uint64_t seed = 0;  // trial_seed(index, base seed)
};

// The seed of trial `index` (1-based) for base seed `base`.
std::uint64_t trial_seed(int index, std::uint64_t base);

struct Grid {
  std::vector<plan::Algorithm> algorithms;
  std::vector<ChangeKind> changes;
  std::vector<BtVariant> bt_variants;
  int trials = 30;
  std::uint64_t base_seed = 1;
};

// Every trial of the grid, trial-major. Duplicated entries in the grid's
// lists are dropped (keeping the first); throws rtamp::Error on an empty list
// or trials < 1.
std::vector<Trial> make_trials(const Grid& grid);

// `--shard K/N`.
struct Shard {
  int k = 1, n = 1;  // 1 <= k <= n
};
// Parses "K/N"; throws rtamp::Error (with the offending text) unless 1 <= K <= N.
Shard parse_shard(std::string_view text);
// The K-th of N interleaved slices of `trials` (order kept).
std::vector<Trial> select_shard(const std::vector<Trial>& trials, Shard shard);

}  // namespace rtamp::batch
