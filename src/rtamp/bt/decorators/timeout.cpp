#include "rtamp/bt/decorators/timeout.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

Timeout::Timeout(std::string name, Duration timeout, std::unique_ptr<Node> child)
    : Decorator(std::move(name), std::move(child)), timeout_(timeout) {
  if (timeout < Duration::zero()) throw rtamp::Error("Timeout '" + this->name() + "': negative duration");
}

Status Timeout::on_tick() {
  if (status() != Status::Running) {
    start_ = now();
  } else if (now() - start_ >= timeout_) {
    halt_child();
    return Status::Failure;
  }
  return tick_child();
}

void Timeout::collect_ports(std::vector<Port>& out) const {
  const auto ms = std::chrono::round<std::chrono::milliseconds>(timeout_).count();
  out.push_back(Port{"msec", std::to_string(ms), "time limit of the child, in milliseconds"});
}

}  // namespace rtamp::bt
