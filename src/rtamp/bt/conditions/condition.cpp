#include "rtamp/bt/conditions/condition.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

Condition::Condition(std::string name, Predicate predicate, std::string type_id)
    : Node(std::move(name)), predicate_(std::move(predicate)), type_id_(std::move(type_id)) {
  validate_type_id(type_id_);
  use_predicate_ = static_cast<bool>(predicate_);
}

Condition::Condition(std::string name, std::string type_id)
    : Node(std::move(name)), type_id_(std::move(type_id)) {
  validate_type_id(type_id_);
}

bool Condition::check() {
  if (!predicate_) throw rtamp::Error("condition '" + name() + "' has no predicate");
  return predicate_(*this);
}

}  // namespace rtamp::bt
