#include "rtamp/bt/composite.hpp"

#include <algorithm>

namespace rtamp::bt {

Node& Composite::insert_child(std::size_t pos, std::unique_ptr<Node> child) {
  Node& ref = insert_child_impl(pos, std::move(child));
  if (pos < touched_) ++touched_;
  child_inserted(pos);
  return ref;
}

std::unique_ptr<Node> Composite::remove_child(std::size_t pos) {
  std::unique_ptr<Node> out = take_child_impl(pos);
  if (pos < touched_) --touched_;
  child_removed(pos);
  return out;
}

std::unique_ptr<Node> Composite::replace_child(std::size_t pos, std::unique_ptr<Node> child) {
  std::unique_ptr<Node> out = swap_child_impl(pos, std::move(child));
  child_replaced(pos);
  return out;
}

void Composite::reset_from(std::size_t first) {
  const std::size_t end = std::min(touched_, children_.size());
  for (std::size_t i = first; i < end; ++i) children_[i]->halt();
  if (touched_ > first) touched_ = first;
}

void Composite::on_halt() {
  reset_from(0);
  on_reset();
}

}  // namespace rtamp::bt
