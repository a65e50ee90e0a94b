#include "rtamp/batch/trials.hpp"

#include <algorithm>
#include <charconv>

#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::batch {

namespace {

// The names, in the grid's canonical order, from the tables their layers own
// (world::random_change_kinds() then "none"; exec::tree_variants()).
std::vector<std::string_view> change_names() {
  std::vector<std::string_view> out;
  for (const auto& n : world::random_change_kinds()) out.push_back(n.name);
  out.push_back("none");
  return out;
}
std::vector<std::string_view> bt_names() {
  std::vector<std::string_view> out;
  for (const auto& n : exec::tree_variants()) out.push_back(n.name);
  return out;
}
const std::vector<std::string_view>& changes() {
  static const auto v = change_names();
  return v;
}
const std::vector<std::string_view>& bt_variants() {
  static const auto v = bt_names();
  return v;
}

int rank_in(const std::vector<std::string_view>& names, std::string_view s) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == s) return static_cast<int>(i);
  return static_cast<int>(names.size());
}

std::string joined(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) out += ", ";
    out += names[i];
  }
  return out;
}

template <typename E>
E parse_in(const std::vector<std::string_view>& names, std::string_view s, const char* what) {
  const int r = rank_in(names, s);
  if (r == static_cast<int>(names.size()))
    throw Error("unknown " + std::string(what) + " '" + std::string(s) + "' (expected one of: " + joined(names) + ")");
  return static_cast<E>(r);
}

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

template <typename T>
std::vector<T> unique_kept(const std::vector<T>& v) {
  std::vector<T> out;
  for (const T& x : v)
    if (std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
  return out;
}

int parse_int(std::string_view s, std::string_view whole) {
  int v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size())
    throw Error("bad shard '" + std::string(whole) + "' (expected K/N with 1 <= K <= N, e.g. 2/4)");
  return v;
}

}  // namespace

const char* to_string(ChangeKind c) { return changes()[static_cast<std::size_t>(c)].data(); }
const char* to_string(BtVariant v) { return bt_variants()[static_cast<std::size_t>(v)].data(); }

ChangeKind parse_change_kind(std::string_view s) { return parse_in<ChangeKind>(changes(), s, "change kind"); }
BtVariant parse_bt_variant(std::string_view s) { return parse_in<BtVariant>(bt_variants(), s, "BT variant"); }

int algorithm_rank(std::string_view name) {
  const auto& all = plan::algorithms();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].name == name) return static_cast<int>(i);
  return static_cast<int>(all.size());
}
int change_rank(std::string_view name) { return rank_in(changes(), name); }
int bt_rank(std::string_view name) { return rank_in(bt_variants(), name); }

std::uint64_t trial_seed(int index, std::uint64_t base) {
  // Two rounds so that neighbouring (index, base) pairs land far apart and
  // (index, base) != (base, index) in general.
  return splitmix64(splitmix64(base) ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(index)) *
                                        0xD6E8FEB86659FD93ull));
}

std::vector<Trial> make_trials(const Grid& grid) {
  if (grid.trials < 1) throw Error("--trials must be at least 1 (got " + std::to_string(grid.trials) + ")");
  const auto algos = unique_kept(grid.algorithms);
  const auto changes = unique_kept(grid.changes);
  const auto bts = unique_kept(grid.bt_variants);
  if (algos.empty()) throw Error("no algorithm selected");
  if (changes.empty()) throw Error("no change kind selected");
  if (bts.empty()) throw Error("no BT variant selected");
  std::vector<Trial> out;
  out.reserve(static_cast<std::size_t>(grid.trials) * algos.size() * changes.size() * bts.size());
  for (int t = 1; t <= grid.trials; ++t) {
    const std::uint64_t seed = trial_seed(t, grid.base_seed);
    for (ChangeKind c : changes)
      for (plan::Algorithm a : algos)
        for (BtVariant b : bts) out.push_back(Trial{a, c, b, t, seed});
  }
  return out;
}

Shard parse_shard(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos)
    throw Error("bad shard '" + std::string(text) + "' (expected K/N with 1 <= K <= N, e.g. 2/4)");
  Shard s{parse_int(text.substr(0, slash), text), parse_int(text.substr(slash + 1), text)};
  if (s.n < 1 || s.k < 1 || s.k > s.n)
    throw Error("bad shard '" + std::string(text) + "' (expected K/N with 1 <= K <= N, e.g. 2/4)");
  return s;
}

std::vector<Trial> select_shard(const std::vector<Trial>& trials, Shard shard) {
  std::vector<Trial> out;
  for (std::size_t i = static_cast<std::size_t>(shard.k - 1); i < trials.size(); i += static_cast<std::size_t>(shard.n))
    out.push_back(trials[i]);
  return out;
}

}  // namespace rtamp::batch
