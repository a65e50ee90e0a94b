#include "rtamp/bt/controls/sequence.hpp"

namespace rtamp::bt {

Status Sequence::on_tick() {
  if (status() != Status::Running) index_ = 0;
  const std::size_t n = children_.size();
  while (index_ < n) {
    const std::size_t i = index_;
    const Status s = children_[i]->tick();
    note_ticked(i);
    if (s == Status::Running) {
      reset_from(i + 1);
      return Status::Running;
    }
    if (s == Status::Failure) {
      reset_from(i + 1);
      index_ = 0;
      return Status::Failure;
    }
    ++index_;
    if (yield_ && index_ < n && yield_()) return Status::Running;
  }
  index_ = 0;
  return Status::Success;
}

void Sequence::child_inserted(std::size_t pos) {
  if (status() == Status::Running && pos <= index_) ++index_;
}

void Sequence::child_removed(std::size_t pos) {
  if (status() == Status::Running && pos < index_) --index_;
}

}  // namespace rtamp::bt
