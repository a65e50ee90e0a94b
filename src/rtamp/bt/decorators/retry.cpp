#include "rtamp/bt/decorators/retry.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

Retry::Retry(std::string name, int num_attempts, std::unique_ptr<Node> child)
    : Decorator(std::move(name), std::move(child)), num_attempts_(num_attempts) {
  if (num_attempts == 0 || num_attempts < -1) {
    throw rtamp::Error("Retry '" + this->name() + "': num_attempts must be positive or -1 (unlimited), not " +
                       std::to_string(num_attempts));
  }
}

Status Retry::on_tick() {
  if (status() != Status::Running) failures_ = 0;
  const Status s = tick_child();
  if (s != Status::Failure) return s;
  ++failures_;
  if (num_attempts_ >= 0 && failures_ >= num_attempts_) return Status::Failure;
  halt_child();  // the next attempt starts afresh on the next tick
  return Status::Running;
}

void Retry::collect_ports(std::vector<Port>& out) const {
  out.push_back(
      Port{"num_attempts", std::to_string(num_attempts_), "attempts before FAILURE (-1: unlimited)"});
}

}  // namespace rtamp::bt
