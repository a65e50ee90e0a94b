#include "rtamp/bt/controls/reactive_sequence.hpp"

namespace rtamp::bt {

Status ReactiveSequence::on_tick() {
  const std::size_t n = children_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Status s = children_[i]->tick();
    note_ticked(i);
    if (s != Status::Success) {
      reset_from(i + 1);
      return s;
    }
  }
  return Status::Success;
}

}  // namespace rtamp::bt
