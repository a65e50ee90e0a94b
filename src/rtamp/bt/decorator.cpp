#include "rtamp/bt/decorator.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

Decorator::Decorator(std::string name, std::unique_ptr<Node> child) : Node(std::move(name)) {
  if (child) insert_child_impl(0, std::move(child));
}

std::unique_ptr<Node> Decorator::set_child(std::unique_ptr<Node> child) {
  if (children_.empty()) {
    if (child) insert_child_impl(0, std::move(child));
    return nullptr;
  }
  if (!child) return take_child_impl(0);
  return swap_child_impl(0, std::move(child));
}

void Decorator::on_halt() {
  halt_child();
  on_reset();
}

void Decorator::throw_no_child() const {
  throw rtamp::Error("behavior-tree decorator '" + name() + "' (" + std::string(type_id()) +
                     ") has no child");
}

}  // namespace rtamp::bt
