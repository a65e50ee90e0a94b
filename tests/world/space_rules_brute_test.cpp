// The rule book of space (world/space_rules.hpp, world/fit.hpp) against brute
// force on small lattices: how many things of one size the rule admits into an
// empty region (or a container) is compared with the largest packing a search
// finds, and for sets of two sizes whether the rule admits the set with whether
// the search can place it. The oracle shares none of the rule's reasoning (no
// grid counts, no shares, no floating point): sizes are whole numbers of cells
// of a lattice on which the clearance d is whole too; a thing of size s grown by
// d / 2 per side is an (s + d) rectangle, an area u an (u + d) box, and disjoint
// grown rectangles in the box are exactly arrangements that keep d. Pushing
// every rectangle down and then left until it touches a wall or another one
// puts its corner on sums of the sizes, so searching the lattice's corners is
// exact. The search is a branch and bound over the first undecided cell (a
// rectangle's corner there, or the cell left empty); its bounds come from the
// free cells only and are checked against plain exhaustive search.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "rtamp/world/space_rules.hpp"

namespace rtamp::world {
namespace {

constexpr int kMaxCells = 63;  // box sides, so that a row is one 64-bit word with a spare bit

// A rectangle of w x h cells (x, y).
struct Rect {
  int w = 0, h = 0;
};

// A box of w x h cells; set bits are decided cells (under a rectangle, or left empty).
struct Lattice {
  int w = 0, h = 0;
  std::array<std::uint64_t, kMaxCells> rows{};

  Lattice(int width, int height) : w(width), h(height) {}
  std::uint64_t full() const { return (std::uint64_t{1} << w) - 1; }
  static std::uint64_t span(int c, int n) { return ((std::uint64_t{1} << n) - 1) << c; }
  bool free(int r, int c, const Rect& t) const {
    if (c + t.w > w || r + t.h > h) return false;
    for (int y = r; y < r + t.h; ++y)
      if (rows[y] & span(c, t.w)) return false;
    return true;
  }
  void flip(int r, int c, const Rect& t) {
    for (int y = r; y < r + t.h; ++y) rows[y] ^= span(c, t.w);
  }
  // The first undecided cell in row-major order from row r, false if none.
  bool first_free(int& r, int& c) const {
    while (r < h && rows[r] == full()) ++r;
    if (r == h) return false;
    c = std::countr_zero(~rows[r]);
    return true;
  }
  // The columns' decided cells as rows of the transposed box.
  Lattice transposed() const {
    Lattice t(h, w);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (rows[y] >> x & 1) t.rows[x] |= std::uint64_t{1} << y;
    return t;
  }
  int free_cells() const {
    int n = 0;
    for (int y = 0; y < h; ++y) n += w - std::popcount(rows[y]);
    return n;
  }
};

// How many pieces of `len` cells the free runs of a row hold.
int row_pieces(std::uint64_t free_bits, int len) {
  int n = 0;
  while (free_bits) {
    const int c = std::countr_zero(free_bits);
    const int run = std::countr_one(free_bits >> c);
    n += run / len;
    free_bits &= ~Lattice::span(c, run);
  }
  return n;
}

// The most intervals of `len` consecutive rows with at most cap[y] of them
// crossing row y: the least cap of a set of rows that meets every window of
// `len` rows (interval matrices are totally unimodular, so the two are equal).
int most_intervals(const std::vector<int>& cap, int len) {
  const int n = static_cast<int>(cap.size());
  if (n < len) return 0;
  std::vector<int> cost(n);
  for (int p = 0; p < n; ++p) {
    int before = p < len ? 0 : 1 << 29;
    for (int q = std::max(0, p - len); q < p; ++q) before = std::min(before, cost[q]);
    cost[p] = cap[p] + before;
  }
  return *std::min_element(cost.begin() + (n - len), cost.end());
}

// The largest number of w x h rectangles in a box, by branch and bound. The
// bound is the free cells' area and, if `strong`, also the rows' and columns'
// room: a rectangle crosses h rows, in each taking w cells of one free run.
class MostRects {
 public:
  MostRects(int box_w, int box_h, Rect t, bool strong, long node_limit = 1L << 40)
      : box_(box_w, box_h), t_(t), strong_(strong), limit_(node_limit) {}

  // The largest count, or nullopt if the search gave up.
  std::optional<int> solve() {
    // A first-fit packing in row-major order to start from.
    Lattice greedy = box_;
    for (int r = 0; r < greedy.h; ++r)
      for (int c = 0; c < greedy.w; ++c)
        if (greedy.free(r, c, t_)) {
          greedy.flip(r, c, t_);
          ++best_;
        }
    free_ = box_.free_cells();
    search(0, 0);
    if (nodes_ > limit_) return std::nullopt;
    return best_;
  }
  long nodes() const { return nodes_; }

 private:
  int bound() const {
    int b = free_ / (t_.w * t_.h);
    if (!strong_ || b == 0) return b;
    auto through = [](const Lattice& l, int across, int along) {
      std::vector<int> cap(l.h);
      for (int y = 0; y < l.h; ++y) cap[y] = row_pieces(~l.rows[y] & l.full(), across);
      return most_intervals(cap, along);
    };
    b = std::min(b, through(box_, t_.w, t_.h));
    if (b == 0) return 0;
    return std::min(b, through(box_.transposed(), t_.h, t_.w));
  }

  void search(int placed, int r) {
    if (++nodes_ > limit_) return;
    int c = 0;
    if (!box_.first_free(r, c)) {
      best_ = std::max(best_, placed);
      return;
    }
    if (placed + bound() <= best_) return;
    if (box_.free(r, c, t_)) {
      box_.flip(r, c, t_);
      free_ -= t_.w * t_.h;
      search(placed + 1, r);
      free_ += t_.w * t_.h;
      box_.flip(r, c, t_);
    }
    box_.rows[r] |= std::uint64_t{1} << c;  // the cell stays empty
    --free_;
    search(placed, r);
    ++free_;
    box_.rows[r] &= ~(std::uint64_t{1} << c);
  }

  Lattice box_;
  Rect t_;
  bool strong_;
  long limit_;
  long nodes_ = 0;
  int best_ = 0;
  int free_ = 0;
};

// Whether n[i] rectangles t[i] (i = 0, 1) can all be placed in a box, nullopt
// if the search gave up. Bounds: the free area, and the rows' (columns') room
// for the rectangles crossing them counted with the narrowest width (height).
class CanPlace {
 public:
  CanPlace(int box_w, int box_h, std::array<Rect, 2> t, std::array<int, 2> n, long node_limit)
      : box_(box_w, box_h), t_(t), n_(n), limit_(node_limit) {}

  std::optional<bool> solve() {
    free_ = box_.free_cells();
    const bool found = search(0);
    if (!found && nodes_ > limit_) return std::nullopt;
    return found;
  }

 private:
  bool hopeless() const {
    int area = 0, rows = 0, cols = 0;
    for (int i = 0; i < 2; ++i) {
      area += n_[i] * t_[i].w * t_[i].h;
      rows += n_[i] * t_[i].h;
      cols += n_[i] * t_[i].w;
    }
    if (area > free_) return true;
    auto room = [](const Lattice& l, int len) {
      int n = 0;
      for (int y = 0; y < l.h; ++y) n += row_pieces(~l.rows[y] & l.full(), len);
      return n;
    };
    const int narrowest = std::min(n_[0] ? t_[0].w : 99, n_[1] ? t_[1].w : 99);
    const int lowest = std::min(n_[0] ? t_[0].h : 99, n_[1] ? t_[1].h : 99);
    return rows > room(box_, narrowest) || cols > room(box_.transposed(), lowest);
  }

  bool search(int r) {
    if (n_[0] == 0 && n_[1] == 0) return true;
    if (++nodes_ > limit_) return false;
    int c = 0;
    if (!box_.first_free(r, c) || hopeless()) return false;
    for (int i = 0; i < 2; ++i) {
      if (n_[i] == 0 || !box_.free(r, c, t_[i])) continue;
      box_.flip(r, c, t_[i]);
      --n_[i];
      free_ -= t_[i].w * t_[i].h;
      const bool found = search(r);
      free_ += t_[i].w * t_[i].h;
      ++n_[i];
      box_.flip(r, c, t_[i]);
      if (found) return true;
    }
    box_.rows[r] |= std::uint64_t{1} << c;
    --free_;
    const bool found = search(r);
    ++free_;
    box_.rows[r] &= ~(std::uint64_t{1} << c);
    return found;
  }

  Lattice box_;
  std::array<Rect, 2> t_;
  std::array<int, 2> n_;
  long limit_;
  long nodes_ = 0;
  int free_ = 0;
};

// A lattice of cell g on which a clearance of d_cells cells is the rules' clearance:
// a side of n cells grown by that clearance is (n - d_cells) g metres.
struct Scale {
  double g;
  int d_cells;
  double metres(int cells) const { return (cells - d_cells) * g; }
};
// Objects keep kPlaceGap = 0.035 m = 5 cells of 7 mm; containers in a region keep
// min(kPlaceGap, kContainerGap) = 0.015 m = 1 cell of 15 mm.
constexpr Scale kObjects{0.007, 5};
constexpr Scale kContainers{0.015, 1};
static_assert(kPlaceGap == 0.035 && kContainerGap == 0.015);

Body body(const Scale& sc, Rect t, bool container) {
  return {{sc.metres(t.w), sc.metres(t.h), 0.04}, container};
}

// How many of `b` the rules admit into an empty location of `usable` extent, one after another.
int admitted(const Body& b, Extent usable, LocationNow::Kind kind) {
  LocationNow at;
  at.kind = kind;
  at.usable = usable;
  at.capacity = 100'000;
  int n = 0;
  while (n < 10'000 && refusal("t", b, "l", at).empty()) {
    ++n;
    ++at.count;
    at.used += cell_units(b, usable, kind == LocationNow::Kind::Container);
  }
  return n;
}

std::string cells(Rect t) { return std::to_string(t.w) + "x" + std::to_string(t.h); }
// The size in metres a rectangle of cells stands for.
std::string metres(const Scale& sc, Rect t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3fx%.3f", sc.metres(t.w), sc.metres(t.h));
  return buf;
}

// Every pair (x, y) of the sides.
std::vector<Rect> pairs(const std::vector<int>& sides) {
  std::vector<Rect> out;
  for (int x : sides)
    for (int y : sides) out.push_back({x, y});
  return out;
}

// The oracle itself: its bounds prune nothing plain exhaustive search would keep.
TEST(SpaceRulesBrute, TheBoundsAgreeWithExhaustiveSearch) {
  int checked = 0;
  for (const Rect t : pairs({5, 6, 7}))
    for (const Rect box : pairs({4, 6, 8, 9, 11, 12, 14, 15})) {
      const auto strong = MostRects(box.w, box.h, t, true).solve();
      const auto plain = MostRects(box.w, box.h, t, false, 20'000'000).solve();
      ASSERT_TRUE(strong.has_value());
      if (!plain) continue;
      ++checked;
      EXPECT_EQ(*strong, *plain) << "box " << cells(box) << ", rectangles " << cells(t);
      // The set search agrees: the most can be placed, one more cannot.
      const std::array<Rect, 2> one{t, Rect{1, 1}};
      EXPECT_EQ(CanPlace(box.w, box.h, one, {*plain, 0}, 20'000'000).solve(), std::optional<bool>(true));
      EXPECT_EQ(CanPlace(box.w, box.h, one, {*plain + 1, 0}, 20'000'000).solve(), std::optional<bool>(false))
          << "box " << cells(box) << ", rectangles " << cells(t);
    }
  std::printf("bounds vs exhaustive search: %d boxes checked\n", checked);
  EXPECT_EQ(checked, 9 * 64);
}

// One size in a region: the rule's claim that k of one size always fit and k + 1 never do,
// with k the most that any arrangement (not only a grid) can hold.
TEST(SpaceRulesBrute, OneSizeInARegionIsTheLargestPacking) {
  const auto run = [](const Scale& sc, bool container, const std::vector<int>& things,
                      const std::vector<int>& boxes) {
    int checked = 0, agree = 0;
    for (const Rect t : pairs(things))
      for (const Rect box : pairs(boxes)) {
        const Body b = body(sc, t, container);
        const Extent usable{sc.metres(box.w), sc.metres(box.h)};
        const int rule = admitted(b, usable, LocationNow::Kind::Region);
        const int most = t.w <= box.w && t.h <= box.h ? *MostRects(box.w, box.h, t, true).solve() : 0;
        ++checked;
        agree += rule == most;
        EXPECT_EQ(rule, most) << (container ? "containers " : "objects ") << b.size[0] << " x " << b.size[1]
                              << " m in a region of " << usable.x << " x " << usable.y << " m (cells "
                              << cells(t) << " in " << cells(box) << ")";
      }
    std::printf("one size, %s in regions: %d cases, %d agree\n", container ? "containers" : "objects",
                checked, agree);
  };
  // Objects 0.035..0.112 m in regions 0.028..0.406 m (7 mm cells); containers 0.105..0.30 m
  // in regions 0.105..0.735 m (15 mm cells); sides on and just off the multiples.
  run(kObjects, false, {10, 11, 13, 16, 21}, {9, 10, 15, 20, 21, 26, 31, 32, 33, 39, 40, 42, 48, 52, 63});
  run(kContainers, true, {8, 11, 13, 17, 21}, {7, 8, 15, 16, 17, 22, 23, 26, 30, 34, 40, 45, 50});
}

// One size in a container: the arm fills a container from its centre, and the rule
// promises exactly that grid (the largest odd number of a size per side), never more than
// the largest packing. How often the centred grid holds fewer is printed.
TEST(SpaceRulesBrute, OneSizeInAContainerIsTheCentredGrid) {
  int checked = 0, agree = 0, fewer = 0;
  std::string examples;
  for (const Rect t : pairs({10, 11, 13, 16}))
    for (const Rect box : pairs({10, 14, 20, 21, 27, 31, 33, 40, 45})) {
      const Body b = body(kObjects, t, false);
      const Extent usable{kObjects.metres(box.w), kObjects.metres(box.h)};
      const int rule = admitted(b, usable, LocationNow::Kind::Container);
      // m things of s with gaps d take m (s + d) - d: the largest odd m with m (s + d) <= u + d.
      auto odd = [](int u, int s) { return u < s ? 0 : (u / s - 1) / 2 * 2 + 1; };
      const int centred = odd(box.w, t.w) * odd(box.h, t.h);
      const int most = centred == 0 ? 0 : *MostRects(box.w, box.h, t, true).solve();
      ++checked;
      agree += rule == centred;
      EXPECT_EQ(rule, centred) << "objects " << cells(t) << " in a container of " << cells(box) << " cells";
      EXPECT_LE(rule, most) << "objects " << cells(t) << " in a container of " << cells(box) << " cells";
      if (rule < most && ++fewer <= 3)
        examples += " " + metres(kObjects, t) + " in " + metres(kObjects, box) +
                    " m: " + std::to_string(rule) + " of " + std::to_string(most) + ";";
    }
  std::printf(
      "one size, objects in containers: %d cases, %d are the centred grid, %d hold fewer than the most "
      "(%s)\n",
      checked, agree, fewer, examples.c_str());
}

// Two sizes in a region, documented as an estimate: whether the rule admits a set
// (one size, then the other) against whether it can be placed. Disagreements are
// counted both ways and printed; asserted is only the area bound the shares keep
// (the rule never admits a set whose grown rectangles exceed the room).
TEST(SpaceRulesBrute, TwoSizesInARegionAreAnEstimate) {
  std::mt19937 rng(20261203);
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int sets = 0, both = 0, neither = 0, over = 0, conservative = 0, undecided = 0;
  std::string over_examples, conservative_examples;
  while (sets < 400) {
    const Rect box{pick(20, 40), pick(20, 40)};
    const std::array<Rect, 2> t{Rect{pick(10, 20), pick(10, 20)}, Rect{pick(10, 20), pick(10, 20)}};
    if (t[0].w == t[1].w && t[0].h == t[1].h) continue;
    if (t[0].w > box.w || t[0].h > box.h || t[1].w > box.w || t[1].h > box.h) continue;
    const Extent usable{kObjects.metres(box.w), kObjects.metres(box.h)};
    const std::array<Body, 2> b{body(kObjects, t[0], false), body(kObjects, t[1], false)};
    // Counts near what fits: up to what the rule admits of each size alone, and one more.
    const std::array<int, 2> n{pick(1, admitted(b[0], usable, LocationNow::Kind::Region)),
                               pick(1, admitted(b[1], usable, LocationNow::Kind::Region) + 1)};
    ++sets;
    LocationNow at;
    at.kind = LocationNow::Kind::Region;
    at.usable = usable;
    at.capacity = 100'000;
    bool rule = true;
    for (int i = 0; i < 2 && rule; ++i)
      for (int k = 0; k < n[i] && rule; ++k) {
        rule = refusal("t", b[i], "l", at).empty();
        ++at.count;
        at.used += cell_units(b[i], usable, false);
      }
    const int area = n[0] * t[0].w * t[0].h + n[1] * t[1].w * t[1].h;
    if (rule) {
      EXPECT_LE(area, box.w * box.h) << "admitted " << n[0] << " x " << cells(t[0]) << " + " << n[1] << " x "
                                     << cells(t[1]) << " in " << cells(box);
    }
    const std::optional<bool> fits_all = CanPlace(box.w, box.h, t, n, 2'000'000).solve();
    const std::string what = " " + std::to_string(n[0]) + " x " + metres(kObjects, t[0]) + " + " +
                             std::to_string(n[1]) + " x " + metres(kObjects, t[1]) + " in " +
                             metres(kObjects, box) + " m;";
    if (!fits_all) {
      ++undecided;
    } else if (rule && *fits_all) {
      ++both;
    } else if (!rule && !*fits_all) {
      ++neither;
    } else if (rule) {
      if (++over <= 4) over_examples += what;
    } else {
      if (++conservative <= 4) conservative_examples += what;
    }
  }
  std::printf(
      "two sizes, objects in regions: %d sets; admitted and placeable %d, refused and not placeable %d; "
      "admitted but not placeable (over-promise) %d, refused but placeable (conservative) %d, search gave up "
      "%d\n",
      sets, both, neither, over, conservative, undecided);
  std::printf("  over-promises:%s\n  conservative:%s\n", over_examples.c_str(),
              conservative_examples.c_str());
}

}  // namespace
}  // namespace rtamp::world
