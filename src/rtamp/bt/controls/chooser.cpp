#include "rtamp/bt/controls/chooser.hpp"

namespace rtamp::bt {

Status Chooser::on_tick() {
  const std::size_t n = children_.size();
  if (status() == Status::Running && current_ < n) {
    const std::size_t i = current_;
    const Status s = children_[i]->tick();
    note_ticked(i);
    return s;  // committed: no fall-through, no re-evaluation of higher priorities
  }
  current_ = kNone;
  for (std::size_t i = 0; i < n; ++i) {
    const Status s = children_[i]->tick();
    note_ticked(i);
    if (s != Status::Failure) {
      current_ = i;
      reset_from(i + 1);
      return s;
    }
  }
  return Status::Failure;
}

void Chooser::child_inserted(std::size_t pos) {
  if (current_ != kNone && pos <= current_) ++current_;
}

void Chooser::child_removed(std::size_t pos) {
  if (current_ == kNone) return;
  if (pos < current_) {
    --current_;
  } else if (pos == current_) {
    current_ = kNone;
  }
}

void Chooser::child_replaced(std::size_t pos) {
  if (pos == current_) current_ = kNone;
}

}  // namespace rtamp::bt
