// The Python Planner (plan.cpp): plan::Planner plus what Python needs around
// it — a reference that keeps a Python cost model alive as long as the planner
// and a mutex, so Python threads may share a planner (each call releases the
// GIL before it waits for the mutex, so a cost model's callback can never
// deadlock against it). Used by plan.cpp and loop.cpp.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "bindings.hpp"
#include "plan_view.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::python {

struct PlannerConfig {
  plan::PlannerOptions options;
  PyRef model_ref;  // the Python CostModel, if the model is one
};

// Options from Python arguments; `cost` is a model name or a CostModel.
PlannerConfig planner_config(const world::Scenario& scenario, const std::string& algorithm, const py::object& cost,
                             const std::string& graph, bool symmetry, bool diagnose_capacity, double time_limit,
                             std::size_t max_nodes,
                             std::size_t max_memory_bytes = plan::SearchLimits{}.max_memory_bytes);
std::shared_ptr<plan::MotionCostModel> builtin_cost_model(const std::string& name, const world::Scenario& scenario);

class PyPlanner {
 public:
  PyPlanner(world::Scenario scenario, PlannerConfig config);
  ~PyPlanner();
  PlanView plan();
  // Runs f on the planner without the GIL, holding the planner's mutex.
  template <class F>
  void locked(F&& f) {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    f(*planner_);
  }
  plan::Planner& raw() { return *planner_; }

 private:
  PyRef model_ref_;  // declared first: outlives planner_
  std::mutex mutex_;
  std::unique_ptr<plan::Planner> planner_;
};

}  // namespace rtamp::python
