#include "rtamp/plan/motion_cost_cache.hpp"

#include <cmath>

namespace rtamp::plan {

namespace {
std::int32_t quantise(double x) { return static_cast<std::int32_t>(std::lround(x * 1e4)); }
}  // namespace

MotionCostCache::Key MotionCostCache::make_key(const MotionQuery& q) const {
  Key k;
  if (depends_ & kDependsThing) k.thing = q.thing;
  for (int i = 0; i < 3; ++i) {
    if (depends_ & kDependsHand) k.c[i] = quantise(q.hand[static_cast<unsigned>(i)]);
    if (depends_ & kDependsFrom) k.c[3 + i] = quantise(q.from[static_cast<unsigned>(i)]);
    if (depends_ & kDependsTo) k.c[6 + i] = quantise(q.to[static_cast<unsigned>(i)]);
  }
  return k;
}

std::uint64_t MotionCostCache::hash(const Key& k) {
  std::uint64_t h = k.thing * 0x9e3779b97f4a7c15ull;
  for (std::int32_t c : k.c) {
    h ^= static_cast<std::uint32_t>(c) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
  }
  return h ^ (h >> 31);
}

void MotionCostCache::grow() {
  std::vector<Slot> old = std::move(slots_);
  slots_.assign(old.empty() ? 1024 : old.size() * 2, Slot{});
  size_ = 0;
  const std::size_t mask = slots_.size() - 1;
  for (const Slot& s : old) {
    if (!s.used) continue;
    std::size_t i = hash(s.key) & mask;
    while (slots_[i].used) i = (i + 1) & mask;
    slots_[i] = s;
    ++size_;
  }
}

double MotionCostCache::lookup(const MotionQuery& q, const MotionCostModel& model) {
  if ((size_ + 1) * 2 > slots_.size()) grow();
  const Key k = make_key(q);
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = hash(k) & mask;
  while (slots_[i].used) {
    if (slots_[i].key == k) {
      ++hits_;
      return slots_[i].cost;
    }
    i = (i + 1) & mask;
  }
  ++misses_;
  const double c = model.cost(q);
  slots_[i] = Slot{k, c, true};
  ++size_;
  return c;
}

void MotionCostCache::forget_thing(std::uint64_t thing_uid) {
  if (!(depends_ & kDependsThing)) return;  // entries do not depend on the thing
  std::vector<Slot> old = std::move(slots_);
  slots_.assign(old.size(), Slot{});
  size_ = 0;
  const std::size_t mask = slots_.size() - 1;
  for (const Slot& s : old) {
    if (!s.used || s.key.thing == thing_uid) continue;
    std::size_t i = hash(s.key) & mask;
    while (slots_[i].used) i = (i + 1) & mask;
    slots_[i] = s;
    ++size_;
  }
}

void MotionCostCache::clear() {
  slots_.clear();
  size_ = 0;
}

}  // namespace rtamp::plan
