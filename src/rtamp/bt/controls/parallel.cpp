#include "rtamp/bt/controls/parallel.hpp"

namespace rtamp::bt {

std::size_t Parallel::resolve(int threshold) const {
  if (threshold >= 0) return static_cast<std::size_t>(threshold);
  const long n = static_cast<long>(children_.size()) + threshold + 1;
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

Status Parallel::on_tick() {
  const std::size_t n = children_.size();
  if (n == 0) return Status::Success;  // whatever the thresholds (a positive S would make it fail)
  if (status() != Status::Running) reset_from(0);
  std::size_t s = 0;
  std::size_t f = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Node& c = *children_[i];
    Status r = c.status();
    if (r != Status::Success && r != Status::Failure) {
      r = c.tick();
      note_ticked(i);
    }
    if (r == Status::Success) ++s;
    if (r == Status::Failure) ++f;
  }
  const std::size_t need_s = resolve(success_count_);
  const std::size_t need_f = resolve(failure_count_);
  Status out = Status::Running;
  if ((need_f > 0 && f >= need_f) || n - f < need_s) {
    out = Status::Failure;
  } else if (s >= need_s) {
    out = Status::Success;
  }
  if (out != Status::Running) {
    for (std::size_t i = 0; i < n; ++i) {
      if (children_[i]->status() == Status::Running) children_[i]->halt();
    }
  }
  return out;
}

void Parallel::collect_ports(std::vector<Port>& out) const {
  out.push_back(
      Port{"success_count", std::to_string(success_count_), "children that must succeed (-1: all)"});
  out.push_back(Port{"failure_count", std::to_string(failure_count_), "children that fail the Parallel"});
}

}  // namespace rtamp::bt
