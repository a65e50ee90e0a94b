#include "rtamp/bt/actions/action.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

Action::Action(std::string name, Callbacks callbacks, std::string type_id)
    : Node(std::move(name)), callbacks_(std::move(callbacks)), type_id_(std::move(type_id)) {
  validate_type_id(type_id_);
}

Action::Action(std::string name, std::string type_id) : Node(std::move(name)), type_id_(std::move(type_id)) {
  validate_type_id(type_id_);
}

Status Action::on_start() {
  if (!callbacks_.on_start) throw rtamp::Error("action '" + name() + "' has no on_start callback");
  return callbacks_.on_start(*this);
}

Status Action::on_running() {
  if (callbacks_.on_running) return callbacks_.on_running(*this);
  return on_start();
}

void Action::on_halted() {
  if (callbacks_.on_halted) callbacks_.on_halted(*this);
}

}  // namespace rtamp::bt
