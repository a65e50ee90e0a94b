// rtamp::bt::Clock — the time source of a tree (used by Timeout, and by user
// actions through Node::now()). Injectable because the executor runs in
// simulated time (docs/design.md "Time"): the exec layer implements Clock over the
// simulation clock; tests use ManualClock. Invariant: now() is monotonic.
#pragma once

#include <chrono>

namespace rtamp::bt {

using Duration = std::chrono::nanoseconds;

class Clock {
 public:
  virtual ~Clock() = default;
  // Time since an arbitrary, fixed origin.
  virtual Duration now() const = 0;
};

// Wall time (std::chrono::steady_clock). The default clock of a Tree.
class SteadyClock final : public Clock {
 public:
  Duration now() const override {
    return std::chrono::duration_cast<Duration>(std::chrono::steady_clock::now().time_since_epoch());
  }
};

// Time that moves only when told to — for tests and for simulated time.
class ManualClock final : public Clock {
 public:
  explicit ManualClock(Duration start = Duration::zero()) : now_(start) {}
  Duration now() const override { return now_; }
  void set(Duration t) { now_ = t; }
  void advance(Duration dt) { now_ += dt; }

 private:
  Duration now_;
};

}  // namespace rtamp::bt
