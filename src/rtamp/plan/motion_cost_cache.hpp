// The motion-cost cache of the paper's Section III.C ("we cache the motion
// cost of edges newly explored so far ... to avoid inverse kinematics
// recomputation"), part of A* with experience (plan/experience.hpp owns it).
// The planner uses it only for models that say their costs are expensive()
// (the ik model): a closed-form euclid cost is cheaper than a lookup.
//
// Entries are keyed by exactly what a cost depends on: the MotionQuery masked
// by the model's depends() bits (the moved thing's stable id, the hand point,
// the thing's point, the destination point; points quantised to 0.1 mm). The
// key holds no state and no indices, so an entry stays true across replanning
// queries and TS rebuilds: moving, adding or removing things never makes an
// entry wrong. forget_thing() drops the entries of a thing (used when a thing
// is removed or changes shape); clear() when the model changes.
// Open addressing with linear probing; grows at load 1/2; no allocation on a
// hit. Invariant: hits + misses == number of lookup() calls since reset_counters().
#pragma once

#include <cstdint>
#include <vector>

#include "rtamp/plan/motion_cost.hpp"

namespace rtamp::plan {

class MotionCostCache {
 public:
  explicit MotionCostCache(unsigned depends = kDependsAll) : depends_(depends) {}

  // The cached cost of q, computing it with `model` on a miss.
  double lookup(const MotionQuery& q, const MotionCostModel& model);
  void forget_thing(std::uint64_t thing_uid);
  void clear();
  void set_depends(unsigned d) {
    if (d != depends_) clear();
    depends_ = d;
  }

  std::size_t size() const { return size_; }
  std::size_t bytes() const { return slots_.capacity() * sizeof(Slot); }
  std::uint64_t hits() const { return hits_; }
  std::uint64_t misses() const { return misses_; }
  void reset_counters() { hits_ = misses_ = 0; }

 private:
  struct Key {
    std::uint64_t thing = 0;
    std::int32_t c[9] = {};
    bool operator==(const Key&) const = default;
  };
  struct Slot {
    Key key;
    double cost = 0;
    bool used = false;
  };
  Key make_key(const MotionQuery& q) const;
  static std::uint64_t hash(const Key& k);
  void grow();

  unsigned depends_;
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
  std::uint64_t hits_ = 0, misses_ = 0;
};

}  // namespace rtamp::plan
