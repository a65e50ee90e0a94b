#include "rtamp/task/transition_system.hpp"

#include <bitset>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "rtamp/util/error.hpp"
#include "rtamp/world/geometry.hpp"

namespace rtamp::task {

namespace {
std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

System::System(const world::Scenario& scenario) : System(scenario, world::initial_placement(scenario)) {}

System::System(const world::Scenario& scenario, const world::Placement& placement, const std::string& hand,
               Options options)
    : scenario_(scenario), options_(options) {
  n_objects_ = static_cast<unsigned>(scenario_.objects.size());
  n_containers_ = static_cast<unsigned>(scenario_.containers.size());
  n_regions_ = static_cast<unsigned>(scenario_.regions.size());
  if (n_regions_ == 0) throw Error("the scenario has no regions");
  if (num_locations() > kMaxLocations)
    throw Error("too many locations (" + std::to_string(num_locations()) + "; at most " +
                std::to_string(kMaxLocations) + ")");
  for (const auto& o : scenario_.objects) {
    thing_names_.push_back(o.name);
    thing_classes_.push_back(o.cls);
  }
  for (const auto& c : scenario_.containers) {
    thing_names_.push_back(c.name);
    thing_classes_.push_back(c.cls);
  }
  for (const auto& n : thing_names_) uids_.push_back(fnv1a(n));
  for (const auto& r : scenario_.regions) capacities_.push_back(r.capacity);
  for (const auto& c : scenario_.containers) capacities_.push_back(c.capacity);
  build_fit_tables();

  // Field width: values 0..num_locations() (home included).
  layout_.init(std::max(1u, static_cast<unsigned>(std::bit_width(num_locations()))), num_things() + 1);
  if (layout_.words > kStateWords)
    throw Error("too many objects and containers for the packed state (" + std::to_string(num_things()) +
                " things with " + std::to_string(layout_.bits) + "-bit fields; at most " +
                std::to_string(kStateWords * layout_.per_word - 1) + ")");
  const auto& base = scenario_.robot.base;
  home_point_ = {base[0], base[1], base[2] + kHomeHeight};
  initial_ = encode(placement, hand);
  group_.assign(num_things(), -1);
  prev_.assign(num_things(), -1);
  next_.assign(num_things(), -1);
  container_group_.assign(num_things(), -1);
}

void System::build_fit_tables() {
  const unsigned T = num_things(), L = num_locations();
  const world::FitRules& rules = options_.fit;
  std::vector<world::Extent> usable;
  for (const auto& r : scenario_.regions) usable.push_back(world::usable_extent(r));
  for (const auto& c : scenario_.containers) usable.push_back(world::usable_extent(c, rules));
  auto size_of = [&](unsigned t) -> const world::Vec3& {
    return is_container(t) ? scenario_.containers[t - n_objects_].size : scenario_.objects[t].size;
  };
  fits_.assign(std::size_t{T} * L, 0);
  allowed_.assign(std::size_t{T} * L, 0);
  cells_.assign(std::size_t{T} * L, 0);
  rooms_.assign(L, options_.ignore_geometry ? std::numeric_limits<std::int64_t>::max() / 4 : world::kRoomUnits);
  for (unsigned t = 0; t < T; ++t) {
    for (unsigned l = 0; l < L; ++l) {
      const bool f = options_.ignore_geometry || world::fits(size_of(t), usable[l]);
      fits_[std::size_t{t} * L + l] = f;
      if (!options_.ignore_geometry)
        cells_[std::size_t{t} * L + l] = world::cell_units({size_of(t), is_container(t)}, usable[l], l >= n_regions_, rules);
      // Containers only into regions (never into themselves or other containers).
      allowed_[std::size_t{t} * L + l] = f && (!is_container(t) || l < n_regions_);
    }
  }
}

void System::forbid_move(unsigned thing, unsigned loc) {
  if (thing >= num_things() || loc >= num_locations() || forbidden(thing, loc)) return;
  forbidden_.emplace_back(thing, loc);
  allowed_[std::size_t{thing} * num_locations() + loc] = 0;
  // A container moved or filled differently is no longer interchangeable.
  for (const unsigned c : {thing, is_container_location(loc) ? thing_of_location(loc) : thing})
    if (container_group_[c] >= 0) {
      std::vector<std::vector<unsigned>> cgroups = container_groups_;
      for (auto& g : cgroups) g.erase(std::remove(g.begin(), g.end(), c), g.end());
      set_container_symmetry(cgroups);
    }
  if (group_[thing] < 0) return;
  // No longer interchangeable with the rest of its group.
  std::vector<std::vector<unsigned>> groups = groups_;
  for (auto& g : groups) g.erase(std::remove(g.begin(), g.end(), thing), g.end());
  set_symmetry(groups);
}

void System::forbid_moves(const std::vector<std::pair<std::string, std::string>>& moves) {
  for (const auto& [thing, loc] : moves) {
    const int t = find_thing(thing), l = find_location(loc);
    if (t >= 0 && l >= 0) forbid_move(static_cast<unsigned>(t), static_cast<unsigned>(l));
  }
}

bool System::forbidden(unsigned thing, unsigned loc) const {
  return std::find(forbidden_.begin(), forbidden_.end(), std::make_pair(thing, loc)) != forbidden_.end();
}

bool System::same_moves(unsigned a, unsigned b) const {
  if (a >= num_things() || b >= num_things()) return false;
  if (is_container(a) != is_container(b)) return false;
  const unsigned L = num_locations();
  if (!std::equal(cells_.begin() + std::ptrdiff_t(std::size_t{a} * L), cells_.begin() + std::ptrdiff_t(std::size_t{a + 1} * L),
                  cells_.begin() + std::ptrdiff_t(std::size_t{b} * L)))
    return false;
  return std::equal(allowed_.begin() + std::ptrdiff_t(std::size_t{a} * L), allowed_.begin() + std::ptrdiff_t(std::size_t{a + 1} * L),
                    allowed_.begin() + std::ptrdiff_t(std::size_t{b} * L));
}

// Groups sorted, deduplicated, those of one member dropped; every member a
// thing of the right kind (containers or not), in one group only, and
// `same(member, first)`. Throws naming the rule before anything changes.
template <class Same>
std::vector<std::vector<unsigned>> System::checked_groups(const std::vector<std::vector<unsigned>>& groups,
                                                          bool containers, Same same) const {
  const std::string what = containers ? "container symmetry group" : "symmetry group";
  std::vector<std::vector<unsigned>> clean;
  std::vector<bool> taken(num_things(), false);
  for (auto g : groups) {
    std::sort(g.begin(), g.end());
    g.erase(std::unique(g.begin(), g.end()), g.end());
    if (g.size() < 2) continue;
    for (unsigned t : g) {
      if (t >= num_things() || is_container(t) != containers || taken[t])
        throw Error("bad " + what + " (" + (containers ? "objects" : "containers") +
                    " and overlapping groups are not allowed)");
      taken[t] = true;
    }
    for (unsigned t : g)
      if (!same(t, g[0]))
        throw Error("bad " + what + " ('" + thing_names_[t] + "' and '" + thing_names_[g[0]] + "' differ in " +
                    (containers ? "footprint, capacity or forbidden moves)" : "footprint or forbidden moves)"));
    clean.push_back(std::move(g));
  }
  return clean;
}

void System::set_symmetry(const std::vector<std::vector<unsigned>>& groups) {
  // Checked before anything changes (a bad call leaves the symmetry as it was).
  std::vector<std::vector<unsigned>> clean =
      checked_groups(groups, false, [this](unsigned a, unsigned b) { return same_moves(a, b); });
  group_.assign(num_things(), -1);
  prev_.assign(num_things(), -1);
  next_.assign(num_things(), -1);
  groups_.clear();
  for (auto& g : clean) {
    const int id = static_cast<int>(groups_.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      group_[g[i]] = id;
      if (i > 0) prev_[g[i]] = static_cast<int>(g[i - 1]);
      if (i + 1 < g.size()) next_[g[i]] = static_cast<int>(g[i + 1]);
    }
    groups_.push_back(std::move(g));
  }
  has_symmetry_ = !groups_.empty();
}

bool System::same_containers(unsigned a, unsigned b) const {
  if (!same_moves(a, b) || !is_container(a)) return false;
  const unsigned L = num_locations(), la = location_of_container(a), lb = location_of_container(b);
  if (capacities_[la] != capacities_[lb] || rooms_[la] != rooms_[lb]) return false;
  for (unsigned o = 0; o < n_objects_; ++o) {
    const std::size_t row = std::size_t{o} * L;
    if (allowed_[row + la] != allowed_[row + lb] || cells_[row + la] != cells_[row + lb]) return false;
  }
  return true;
}

void System::set_container_symmetry(const std::vector<std::vector<unsigned>>& groups) {
  // Checked before anything changes (a bad call leaves the symmetry as it was).
  std::vector<std::vector<unsigned>> clean =
      checked_groups(groups, true, [this](unsigned a, unsigned b) { return same_containers(a, b); });
  container_group_.assign(num_things(), -1);
  container_groups_ = std::move(clean);
  for (std::size_t g = 0; g < container_groups_.size(); ++g)
    for (const unsigned c : container_groups_[g]) container_group_[c] = static_cast<int>(g);
}

namespace {
// Keys of the members of one container group, `width` entries each:
// region, hand (0 in it, 1 not), counts per object group, then the other
// objects it holds in ascending order (padded with 0xffffffff).
struct ContainerKeys {
  std::vector<std::uint32_t> keys;
  std::vector<unsigned> order, fill;
  unsigned width = 0;
  bool less(unsigned a, unsigned b) const {
    const std::uint32_t* ka = keys.data() + std::size_t{a} * width;
    const std::uint32_t* kb = keys.data() + std::size_t{b} * width;
    return std::lexicographical_compare(ka, ka + width, kb, kb + width);
  }
  bool equal(unsigned a, unsigned b) const {
    const std::uint32_t* ka = keys.data() + std::size_t{a} * width;
    return std::equal(ka, ka + width, keys.data() + std::size_t{b} * width);
  }
};

// Fills k.keys with the keys of the members of container group g in s.
void fill_container_keys(const System& ts, const State& s, const std::vector<unsigned>& g, unsigned n_groups,
                         ContainerKeys& k) {
  const unsigned m = static_cast<unsigned>(g.size());
  k.width = 2 + n_groups + ts.num_objects();
  k.keys.assign(std::size_t{m} * k.width, 0);
  k.fill.assign(m, 2 + n_groups);
  const std::uint32_t hand_at = ts.hand(s);
  for (unsigned i = 0; i < m; ++i) {
    std::uint32_t* key = k.keys.data() + std::size_t{i} * k.width;
    key[0] = ts.location(s, g[i]);
    key[1] = hand_at == ts.location_of_container(g[i]) ? 0 : 1;
    std::fill(key + 2 + n_groups, key + k.width, 0xffffffffu);
  }
  const int group = ts.container_group_of(g[0]);
  for (unsigned o = 0; o < ts.num_objects(); ++o) {
    const std::uint32_t l = ts.location(s, o);
    if (!ts.is_container_location(l) || ts.container_group_of(ts.thing_of_location(l)) != group) continue;
    const auto i = static_cast<unsigned>(std::find(g.begin(), g.end(), ts.thing_of_location(l)) - g.begin());
    std::uint32_t* key = k.keys.data() + std::size_t{i} * k.width;
    if (ts.group_of(o) >= 0) ++key[2 + static_cast<unsigned>(ts.group_of(o))];
    else key[k.fill[i]++] = o;
  }
}
}  // namespace

void System::order_containers(State& s, unsigned* src) const {
  thread_local ContainerKeys k;
  std::uint32_t relabel[kMaxLocations + 1];
  for (unsigned l = 0; l <= num_locations(); ++l) relabel[l] = l;
  const State old = s;
  const unsigned n_groups = static_cast<unsigned>(groups_.size());
  const std::uint32_t hand_at = hand(old);
  for (const auto& g : container_groups_) {
    const unsigned m = static_cast<unsigned>(g.size());
    fill_container_keys(*this, old, g, n_groups, k);
    // Insertion sort (groups are small; stable: equal keys keep member order).
    k.order.resize(m);
    for (unsigned i = 0; i < m; ++i) {
      unsigned j = i;
      while (j > 0 && k.less(i, k.order[j - 1])) {
        k.order[j] = k.order[j - 1];
        --j;
      }
      k.order[j] = i;
    }
    for (unsigned i = 0; i < m; ++i) {
      const unsigned from = g[k.order[i]], to = g[i];
      if (src) src[to] = from;
      layout_.set(s, to, location(old, from));
      relabel[location_of_container(from)] = location_of_container(to);
    }
  }
  for (unsigned o = 0; o < n_objects_; ++o) layout_.set(s, o, relabel[location(old, o)]);
  layout_.set(s, hand_field(), relabel[hand_at]);
}

void System::container_twins(const State& s, unsigned* first) const {
  for (unsigned c = 0; c < n_containers_; ++c) first[c] = n_objects_ + c;
  const unsigned n_groups = static_cast<unsigned>(groups_.size());
  thread_local ContainerKeys k;
  for (const auto& g : container_groups_) {
    const unsigned m = static_cast<unsigned>(g.size());
    fill_container_keys(*this, s, g, n_groups, k);
    for (unsigned i = 1; i < m; ++i)
      for (unsigned j = 0; j < i; ++j)
        if (k.equal(i, j)) {
          first[g[i] - n_objects_] = first[g[j] - n_objects_];
          break;
        }
  }
}

void System::canonical_sources(const State& s, unsigned* src) const {
  for (unsigned t = 0; t < num_things(); ++t) src[t] = t;
  if (container_groups_.empty()) return;
  State c = s;
  order_containers(c, src);
}

void System::canonicalize(State& s) const {
  if (!container_groups_.empty()) order_containers(s, nullptr);
  if (!has_symmetry_) return;
  std::uint32_t vals[kStateWords * 64];
  for (const auto& g : groups_) {
    for (std::size_t i = 0; i < g.size(); ++i) vals[i] = location(s, g[i]);
    std::sort(vals, vals + g.size());
    for (std::size_t i = 0; i < g.size(); ++i) layout_.set(s, g[i], vals[i]);
  }
}

State System::canonical_successor(const State& s, const Action& a) const {
  State r = successor(s, a);
  // The containers' order changes only if a key changes: a member moved, or
  // something (the thing, or the hand) put into or taken out of a member.
  if (!container_groups_.empty() && !a.is_stay() &&
      (container_group_[a.thing] >= 0 || interchangeable_location(a.to) ||
       interchangeable_location(location(s, a.thing)) || interchangeable_location(hand(s)))) {
    canonicalize(r);
    return r;
  }
  if (!has_symmetry_ || a.is_stay() || group_[a.thing] < 0) return r;
  // Bubble the moved member to its place; the others stay sorted.
  unsigned t = a.thing;
  const std::uint32_t v = a.to;
  while (prev_[t] >= 0 && location(r, static_cast<unsigned>(prev_[t])) > v) {
    const auto p = static_cast<unsigned>(prev_[t]);
    layout_.set(r, t, location(r, p));
    layout_.set(r, p, v);
    t = p;
  }
  while (next_[t] >= 0 && location(r, static_cast<unsigned>(next_[t])) < v) {
    const auto n = static_cast<unsigned>(next_[t]);
    layout_.set(r, t, location(r, n));
    layout_.set(r, n, v);
    t = n;
  }
  return r;
}

const std::string& System::location_name(unsigned l) const {
  static const std::string home_name = "home";
  if (l < n_regions_) return scenario_.regions[l].name;
  if (l < num_locations()) return scenario_.containers[l - n_regions_].name;
  return home_name;
}

int System::find_thing(const std::string& name) const {
  for (unsigned t = 0; t < num_things(); ++t)
    if (thing_names_[t] == name) return static_cast<int>(t);
  return -1;
}

int System::find_location(const std::string& name) const {
  for (unsigned l = 0; l < num_locations(); ++l)
    if (location_name(l) == name) return static_cast<int>(l);
  return -1;
}

void System::occupancy(const State& s, int* counts) const {
  std::fill(counts, counts + num_locations(), 0);
  for (unsigned t = 0; t < num_things(); ++t) ++counts[location(s, t)];
}

void System::occupancy(const State& s, int* counts, std::int64_t* used) const {
  std::fill(counts, counts + num_locations(), 0);
  std::fill(used, used + num_locations(), std::int64_t{0});
  for (unsigned t = 0; t < num_things(); ++t) {
    const std::uint32_t l = location(s, t);
    ++counts[l];
    if (l < num_locations()) used[l] += cells_[std::size_t{t} * num_locations() + l];
  }
}

bool System::enabled(const State& s, const Action& a) const {
  if (a.is_stay()) return true;
  if (a.thing >= num_things() || a.to >= num_locations()) return false;
  const std::uint32_t at = location(s, a.thing);
  if (a.to == at) return false;
  if (!allowed_[std::size_t{a.thing} * num_locations() + a.to]) return false;
  if (options_.ignore_capacity) return true;
  const unsigned L = num_locations();
  int n = 0;
  std::int64_t used = 0;
  for (unsigned t = 0; t < num_things(); ++t)
    if (location(s, t) == a.to) {
      ++n;
      used += cells_[std::size_t{t} * L + a.to];
    }
  return n < capacities_[a.to] && used + cells_[std::size_t{a.thing} * L + a.to] <= rooms_[a.to];
}

State System::successor(const State& s, const Action& a) const {
  if (a.is_stay()) return s;
  State r = s;
  layout_.set(r, a.thing, a.to);
  layout_.set(r, hand_field(), a.to);
  return r;
}

bool System::valid(const State& s) const {
  int counts[kMaxLocations + 1];
  std::int64_t used[kMaxLocations + 1];
  for (unsigned t = 0; t < num_things(); ++t) {
    const std::uint32_t l = location(s, t);
    if (l >= num_locations()) return false;
    if (is_container(t) && l >= n_regions_) return false;
    if (!fits(t, l)) return false;
  }
  if (hand(s) > num_locations()) return false;
  if (options_.ignore_capacity) return true;
  occupancy(s, counts, used);
  for (unsigned l = 0; l < num_locations(); ++l)
    if (counts[l] > capacities_[l] || used[l] > rooms_[l]) return false;
  return true;
}

world::Placement System::describe(const State& s) const {
  world::Placement p;
  for (unsigned t = 0; t < num_things(); ++t)
    p.set(thing_names_[t], location_name(location(s, t)), thing_classes_[t], is_container(t));
  return p;
}

State System::encode(const world::Placement& p, const std::string& hand_location) const {
  State s;
  std::bitset<kStateWords * 64> seen;  // a thing has at least one bit
  for (const auto& [thing, info] : p.things) {
    const std::string& loc = info.location;
    const int t = find_thing(thing);
    if (t < 0) throw Error("unknown object or container '" + thing + "'");
    if (loc == "none") throw Error("'" + thing + "' is not in any region or container");
    const int l = find_location(loc);
    if (l < 0) throw Error("unknown location '" + loc + "' (for '" + thing + "')");
    if (is_container(static_cast<unsigned>(t)) && l >= static_cast<int>(n_regions_))
      throw Error("container '" + thing + "' cannot be placed in '" + loc + "' (containers do not nest)");
    layout_.set(s, static_cast<unsigned>(t), static_cast<std::uint32_t>(l));
    seen[static_cast<unsigned>(t)] = true;
  }
  for (unsigned t = 0; t < num_things(); ++t)
    if (!seen[t]) throw Error("no location given for '" + thing_names_[t] + "'");
  if (hand_location.empty() || hand_location == "home") {
    layout_.set(s, hand_field(), home());
  } else {
    const int l = find_location(hand_location);
    if (l < 0) throw Error("unknown hand location '" + hand_location + "'");
    layout_.set(s, hand_field(), static_cast<std::uint32_t>(l));
  }
  return s;
}

std::string System::to_string(const State& s) const {
  std::string out;
  for (unsigned t = 0; t < num_things(); ++t) {
    if (!out.empty()) out += ' ';
    out += thing_names_[t] + "@" + location_name(location(s, t));
  }
  if (!out.empty()) out += ' ';
  out += "hand@" + location_name(hand(s));
  return out;
}

std::string System::action_name(const Action& a) const {
  if (a.is_stay()) return "stay";
  return "move(" + thing_names_[a.thing] + ", " + location_name(a.to) + ")";
}

world::Vec3 System::location_point(const State& s, unsigned loc) const {
  if (loc < n_regions_) return scenario_.regions[loc].center;
  if (loc < num_locations()) {
    const std::uint32_t r = location(s, thing_of_location(loc));
    return scenario_.regions[r < n_regions_ ? r : 0].center;
  }
  return home_point_;
}

world::Vec3 System::hand_point(const State& s) const { return location_point(s, hand(s)); }

}  // namespace rtamp::task
