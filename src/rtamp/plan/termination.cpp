#include "rtamp/plan/termination.hpp"

#include <chrono>

namespace rtamp::plan {

std::int64_t steady_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void Budget::start(const Termination& stop, std::function<std::size_t()> held_bytes) {
  stop_ = &stop;
  held_bytes_ = std::move(held_bytes);
  reason_ = StopReason::None;
  start_ns_ = steady_now_ns();
  next_progress_ns_ = start_ns_ + stop.limits.progress_interval_ns();
  best_ = kInf;
  bound_ = 0;
}

bool Budget::exhausted(const ProductGraph& g, std::uint64_t expanded) {
  if (reason_ != StopReason::None) return true;
  const SearchLimits& limits = stop_->limits;
  if (g.size() > limits.max_nodes) {
    reason_ = StopReason::NodeLimit;
    return true;
  }
  if ((++ticks_ & 127) != 0) return false;
  if (limits.max_memory_bytes && held_bytes_() > limits.max_memory_bytes) {
    reason_ = StopReason::MemoryLimit;
    return true;
  }
  if (!stop_->deadline_ns && !limits.on_progress) return false;
  const std::int64_t now = steady_now_ns();
  if (stop_->deadline_ns && now > stop_->deadline_ns) {
    reason_ = StopReason::TimeLimit;
    return true;
  }
  if (limits.on_progress && now >= next_progress_ns_) {
    next_progress_ns_ = now + limits.progress_interval_ns();
    SearchProgress p;
    p.graph_nodes = g.size();
    p.expanded = expanded;
    p.best = best_;
    p.bound = bound_;
    p.seconds = double(now - start_ns_) * 1e-9;
    limits.on_progress(p);
  }
  return false;
}

}  // namespace rtamp::plan
