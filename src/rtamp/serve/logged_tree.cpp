#include "rtamp/serve/detail/logged_tree.hpp"

#include <algorithm>
#include <memory>

#include <nlohmann/json.hpp>

#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/serve/tree_message.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::serve {

using nlohmann::json;

namespace {

// The moves of a rebuilt tree never run.
class NoRunner final : public exec::ActionRunner {
 public:
  bt::Status start(const plan::ActionTuple&) override { return bt::Status::Failure; }
  bt::Status running(const plan::ActionTuple&) override { return bt::Status::Failure; }
  void halt(const plan::ActionTuple&) override {}
};

// "move(o1, r2)" -> {"o1", "r2"}.
std::optional<std::pair<std::string, std::string>> parse_move(const std::string& a) {
  const std::string open = "move(";
  const std::size_t comma = a.find(", ");
  if (a.rfind(open, 0) != 0 || comma == std::string::npos || a.back() != ')') return std::nullopt;
  return std::pair{a.substr(open.size(), comma - open.size()), a.substr(comma + 2, a.size() - comma - 3)};
}

// The scenario with exactly the things of `start` (added ones: their class from `known`).
world::Scenario with_things(world::Scenario s, const world::Placement& start) {
  std::erase_if(s.objects, [&](const world::Object& o) { return !start.things.count(o.name); });
  std::erase_if(s.containers, [&](const world::Container& c) { return !start.things.count(c.name); });
  for (const auto& [name, t] : start.things) {
    if (s.find_object(name) || s.find_container(name)) continue;
    if (t.container) {
      world::Container c;
      c.name = name;
      c.cls = t.cls;
      s.containers.push_back(c);
    } else {
      world::Object o;
      o.name = name;
      o.cls = t.cls;
      s.objects.push_back(o);
    }
  }
  return s;
}

// The action tuples of a `plan` record (nullopt if its moves cannot be
// replayed); `run`: the latest `run` state, the start of a record without one.
std::optional<std::vector<plan::ActionTuple>> plan_tuples(const world::Scenario& scenario_, const json& j,
                                                          const std::optional<world::Placement>& run_,
                                                          const world::Placement& known) {
  world::Placement start;
  std::string hand;
  if (j.contains("start") && j["start"].is_object()) {
    for (const auto& [name, loc] : j["start"].items())
      if (loc.is_string()) start.set(name, loc.get<std::string>(), "", false);
    if (j.contains("hand") && j["hand"].is_string()) hand = j["hand"].get<std::string>();
  } else if (run_) {
    start = *run_;
  } else {
    return std::nullopt;
  }
  for (auto& [name, t] : start.things) {
    if (const auto* c = scenario_.find_container(name)) {
      t.cls = c->cls;
      t.container = true;
    } else if (const auto* o = scenario_.find_object(name)) {
      t.cls = o->cls;
    } else if (auto it = known.things.find(name); it != known.things.end()) {
      t.cls = it->second.cls;
      t.container = it->second.container;
    } else {
      t.cls = "block";
    }
  }
  const json& actions = j.value("actions", json::array());
  const json& costs = j.value("costs", json::array());
  const json& in_cycle = j.value("in_cycle", json::array());
  if (!actions.is_array() || costs.size() != actions.size() || in_cycle.size() != actions.size())
    return std::nullopt;
  try {
    task::System::Options o;
    o.ignore_capacity = true;
    o.ignore_geometry = true;
    const task::System ts(with_things(scenario_, start), start, hand == "home" ? "" : hand, o);
    plan::Plan p;
    task::State s = ts.encode(start, hand == "home" ? "" : hand);
    for (std::size_t i = 0; i < actions.size(); ++i) {
      const auto m = actions[i].is_string() ? parse_move(actions[i].get<std::string>()) : std::nullopt;
      if (!m) return std::nullopt;
      const int thing = ts.find_thing(m->first), to = ts.find_location(m->second);
      if (thing < 0 || to < 0) return std::nullopt;
      plan::Step st;
      st.action = task::Action::move(static_cast<std::uint16_t>(thing), static_cast<std::uint16_t>(to));
      st.from = s;
      s = ts.successor(s, st.action);
      st.to = s;
      st.cost = costs[i].is_number() ? costs[i].get<double>() : 0;
      (in_cycle[i].is_boolean() && in_cycle[i].get<bool>() ? p.cycle : p.prefix).push_back(st);
    }
    return plan::to_action_tuples(ts, p);
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace

LoggedTree::LoggedTree(world::Scenario scenario) : scenario_(std::move(scenario)) {}

std::optional<std::string> LoggedTree::record(const json& j, double t, const world::Placement& known) try {
  const std::string ev = j.value("ev", "");
  if (ev == "episode") {
    mode_ = j.value("conditions", "action") == "state" ? exec::ConditionMode::State : exec::ConditionMode::Action;
  } else if (ev == "run" && j.contains("state") && j["state"].is_object()) {
    world::Placement p;
    for (const auto& [name, loc] : j["state"].items())
      if (loc.is_string()) p.set(name, loc.get<std::string>(), "", false);
    run_ = std::move(p);
  } else if (ev == "plan") {
    planned_ = plan_tuples(scenario_, j, run_, known);
  } else if (ev == "tree" && j.value("applied", false) && planned_) {
    static NoRunner runner;
    exec::PlanTree tree(mode_, exec::Reconfiguration::Online, runner, std::make_shared<bt::ManualClock>());
    tree.set_plan(*planned_);
    return tree_message(t, tree.tree());
  }
  return std::nullopt;
} catch (const json::exception&) {
  return std::nullopt;  // a record of another shape (a field of another type): it changes no tree
}

}  // namespace rtamp::serve
