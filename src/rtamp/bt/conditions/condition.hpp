// rtamp::bt::Condition — a leaf that checks a predicate: SUCCESS if it holds,
// FAILURE if not; never RUNNING (paper Fig. 3: pre-, post- and running
// conditions). Built from a callable — bool(Node&) (reach the blackboard through
// the node) or bool() — or by subclassing and overriding check().
//
// The predicate and the ports (its parameters, e.g. object="o1" region="r2") can
// be replaced in place between ticks; this is how Algorithm 2 updates the
// conditions of a kept subtree without touching its id or position.
// Exported as <TYPE_ID .../> with TYPE_ID in <TreeNodesModel> as a <Condition>.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

#include "rtamp/bt/node.hpp"

namespace rtamp::bt {

class Condition : public Node {
 public:
  using Predicate = std::function<bool(Node&)>;

  Condition(std::string name, Predicate predicate, std::string type_id = "UserCondition");
  template <class F>
  requires(std::is_invocable_r_v<bool, F&> && !std::is_invocable_v<F&, Node&>)
      Condition(std::string name, F predicate, std::string type_id = "UserCondition")
      : Condition(std::move(name), Predicate([f = std::move(predicate)](Node&) mutable { return f(); }),
                  std::move(type_id)) {}

  NodeKind kind() const override { return NodeKind::Condition; }
  std::string_view type_id() const override { return type_id_; }
  // Replaces the predicate (also on a subclass: the predicate then wins over check()).
  void set_predicate(Predicate predicate) {
    predicate_ = std::move(predicate);
    use_predicate_ = static_cast<bool>(predicate_);
  }

 protected:
  // For subclasses that override check().
  Condition(std::string name, std::string type_id);
  // Default: the predicate (throws rtamp::Error if there is none).
  virtual bool check();
  Status on_tick() final {
    const bool holds = use_predicate_ ? predicate_(*this) : check();  // no virtual call on the common path
    return holds ? Status::Success : Status::Failure;
  }

 private:
  Predicate predicate_;
  bool use_predicate_ = false;
  std::string type_id_;
};

}  // namespace rtamp::bt
