// Python bindings of the reactive loop (paper Algorithm 1; exec/reactive_loop.hpp)
// over exec::World, with a World written in Python (the PyWorld trampoline),
// episode observers written in Python, the episode's metrics and its observed
// run, and new tasks given while it runs (set_task, new_tasks). run(), step()
// and set_task() release the GIL; every call into Python (world, observer,
// cost model on the planner's worker thread) takes it again.
#include "loop.hpp"

#include <memory>

#include "plan.hpp"

#include "choices.hpp"
#include "rtamp/bt/text_render.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/world/propositions.hpp"

namespace rtamp::python {

namespace {

using exec::MoveStatus;

MoveStatus as_status(const py::handle& h) {
  if (py::isinstance<py::str>(h)) return parse_name(exec::move_statuses(), h.cast<std::string>(), "move status");
  return h.cast<MoveStatus>();
}

// The trampoline: exec::World's methods from a Python subclass. Required:
// time, advance, observe, start, poll, halt. Optional: next_event_time
// (default infinity: the loop ticks every tick_period), busy (False), hand
// (''), distance_travelled (0), take_events ([]), confirming (False); and the intervention
// capability (exec/intervenable.hpp): a subclass that defines both
// true_placement() and apply(intervention) can be driven by a Person.
class PyWorld : public exec::World, public exec::Intervenable {
 public:
  ClassTable classes;

  exec::Intervenable* intervenable() override {
    py::gil_scoped_acquire gil;
    const auto* self = static_cast<const exec::World*>(this);
    return py::get_override(self, "true_placement") && py::get_override(self, "apply") ? this : nullptr;
  }
  world::Placement true_placement() override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::World*>(this), "true_placement");
    if (!f) throw Error("a World that takes interventions must define true_placement()");
    return to_placement(f(), classes);
  }
  exec::WorldEvent apply(const world::Intervention& iv) override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::World*>(this), "apply");
    if (!f) throw Error("a World that takes interventions must define apply(intervention)");
    py::object r = f(iv);
    if (py::isinstance<exec::WorldEvent>(r)) return r.cast<exec::WorldEvent>();
    if (py::isinstance<py::bool_>(r)) return exec::WorldEvent{time(), iv, r.cast<bool>(), ""};
    throw Error("World.apply(intervention) must return a WorldEvent or a bool (applied)");
  }

  double time() const override { PYBIND11_OVERRIDE_PURE(double, exec::World, time, ); }
  void advance(double dt) override { PYBIND11_OVERRIDE_PURE(void, exec::World, advance, dt); }
  double next_event_time() const override { PYBIND11_OVERRIDE(double, exec::World, next_event_time, ); }
  world::Placement observe() override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::World*>(this), "observe");
    if (!f) throw Error("a World subclass must define observe()");
    return to_placement(f(), classes);
  }
  void start(const exec::Move& m) override { PYBIND11_OVERRIDE_PURE(void, exec::World, start, m); }
  MoveStatus poll(std::string* why) override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::World*>(this), "poll");
    if (!f) throw Error("a World subclass must define poll()");
    py::object r = f();
    if (py::isinstance<py::tuple>(r)) {
      py::tuple t = r;
      if (t.size() != 2) throw Error("World.poll() must return a status or (status, why)");
      if (why) *why = py::str(t[1]).cast<std::string>();
      return as_status(t[0]);
    }
    return as_status(r);
  }
  void halt() override { PYBIND11_OVERRIDE_PURE(void, exec::World, halt, ); }
  bool busy() override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::World*>(this), "busy");
    return f ? f().cast<bool>() : false;
  }
  std::string hand() const override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::World*>(this), "hand");
    return f ? f().cast<std::string>() : std::string();
  }
  double distance_travelled() const override { PYBIND11_OVERRIDE(double, exec::World, distance_travelled, ); }
  bool confirming() const override { PYBIND11_OVERRIDE(bool, exec::World, confirming, ); }
  std::vector<exec::WorldEvent> take_events() override {
    PYBIND11_OVERRIDE(std::vector<exec::WorldEvent>, exec::World, take_events, );
  }
};

// Observers written in Python: each callback is looked up on the subclass;
// those it does not define cost nothing but the look-up.
class PyObserver : public exec::EpisodeObserver {
 public:
  void on_begin(const exec::EpisodeInfo& i) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_begin, i);
  }
  void on_action(double t, const char* what, const std::string& action, const std::string& why) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_action, t, what, action, why);
  }
  void on_intervention(const exec::WorldEvent& e) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_intervention, e);
  }
  void on_things_changed(double t, const std::vector<std::string>& added,
                         const std::vector<std::string>& removed) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_things_changed, t, added, removed);
  }
  void on_progress(double t, const world::Placement& state, const std::vector<std::uint32_t>& states) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_progress, t, state, states);
  }
  void on_replan_request(double t, const std::string& why) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_replan_request, t, why);
  }
  void on_plan(double t, const exec::PlanEvent& e) override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::EpisodeObserver*>(this), "on_plan");
    if (!f) return;
    py::list moves;
    for (const auto& a : e.tuples) moves.append(a.action);
    py::dict d;
    d["first"] = e.first;
    d["found"] = e.result.found;
    d["cost"] = e.result.plan.cost();
    d["reason"] = e.result.found ? "none" : plan::to_string(e.result.reason);
    d["moves"] = moves;
    d["seconds"] = e.result.stats.seconds;
    d["automaton_states"] = e.automaton_states;
    f(t, d);
  }
  void on_task(double t, const exec::TaskEvent& e) override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const exec::EpisodeObserver*>(this), "on_task");
    if (!f) return;
    py::dict props;
    for (const auto& p : e.change.propositions) props[py::str(p.name)] = p.text;
    py::dict d;
    d["task"] = e.change.task;
    d["by"] = e.change.by;
    d["applied"] = e.applied;
    d["refused"] = e.refused;
    d["automaton_states"] = e.automaton ? py::object(py::int_(e.automaton->num_states())) : py::object(py::none());
    d["propositions"] = props;
    f(t, d);
  }
  void on_redirect(double t, const std::string& action, const std::string& rule) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_redirect, t, action, rule);
  }
  void on_cycle(double t, int completed) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_cycle, t, completed);
  }
  void on_end(double t, const exec::EpisodeMetrics& m, const world::Placement& p) override {
    PYBIND11_OVERRIDE(void, exec::EpisodeObserver, on_end, t, m, p);
  }
};

// The loop with what Python needs around it: references that keep the world,
// observers and a Python cost model alive, and destruction without the GIL
// (the destructor waits for a planning worker, which may need the GIL).
class PyLoop {
 public:
  PyLoop(py::object world, const world::Scenario& scenario, exec::LoopOptions options, PyRef model_ref)
      : world_ref_(world), model_ref_(std::move(model_ref)) {
    exec::World& w = world.cast<exec::World&>();
    py::gil_scoped_release release;
    loop_ = std::make_unique<exec::ReactiveLoop>(w, scenario, std::move(options));
  }
  ~PyLoop() {
    py::gil_scoped_release release;
    loop_.reset();
  }
  void add_observer(py::object o) {
    loop_->add_observer(o.cast<exec::EpisodeObserver&>());
    observers_.emplace_back(std::move(o));
  }
  exec::ReactiveLoop& loop() { return *loop_; }

 private:
  PyRef world_ref_, model_ref_;
  std::vector<PyRef> observers_;
  std::unique_ptr<exec::ReactiveLoop> loop_;
};

}  // namespace

ClassTable class_table(const world::Scenario& s) {
  ClassTable t;
  for (const auto& o : s.objects) t[o.name] = {o.cls, false};
  for (const auto& c : s.containers) t[c.name] = {c.cls, true};
  return t;
}

world::Placement to_placement(const py::handle& o, const ClassTable& classes) {
  if (py::isinstance<world::Placement>(o)) return o.cast<world::Placement>();
  if (!py::isinstance<py::dict>(o))
    throw Error("a placement must be a Placement or a dict {thing: location | (location, class[, container])}");
  world::Placement p;
  for (auto [k, v] : py::reinterpret_borrow<py::dict>(o)) {
    std::string name = py::str(k).cast<std::string>();
    world::Placement::Thing t;
    if (py::isinstance<py::str>(v)) {
      t.location = v.cast<std::string>();
      auto it = classes.find(name);
      if (it != classes.end()) {
        t.cls = it->second.first;
        t.container = it->second.second;
      } else {
        t.cls = "block";
      }
    } else if (py::isinstance<world::Placement::Thing>(v)) {
      t = v.cast<world::Placement::Thing>();
    } else {
      py::sequence seq = py::reinterpret_borrow<py::sequence>(v);
      if (seq.size() < 2 || seq.size() > 3)
        throw Error("placement of '" + name + "' must be a location or (location, class[, container])");
      t.location = seq[0].cast<std::string>();
      t.cls = seq[1].cast<std::string>();
      t.container = seq.size() == 3 && seq[2].cast<bool>();
    }
    p.things.emplace(std::move(name), std::move(t));
  }
  return p;
}

world::TaskChange task_change(double time, const std::string& formula, const PropositionTexts& propositions,
                              const std::string& origin) {
  world::TaskChange c;
  c.time = time;
  c.task = formula;
  c.task_where = SourceLocation{origin + "(formula)", 1, 1};
  c.where = SourceLocation{origin, 0, 0};
  c.by = "api";
  for (const auto& [name, text] : propositions) {
    world::Proposition p;
    p.name = name;
    p.text = text;
    p.where = SourceLocation{origin + "(propositions['" + name + "'])", 1, 1};
    p.expr = world::parse_prop_expr(p.text, p.where);
    c.propositions.push_back(std::move(p));
  }
  return c;
}

std::vector<world::TaskChange> task_changes(const std::vector<NewTask>& tasks) {
  std::vector<world::TaskChange> out;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const std::string origin = "new_tasks[" + std::to_string(i) + "]";
    std::visit(
        [&](const auto& t) {
          if constexpr (std::tuple_size_v<std::decay_t<decltype(t)>> == 2)
            out.push_back(task_change(std::get<0>(t), std::get<1>(t), {}, origin));
          else
            out.push_back(task_change(std::get<0>(t), std::get<1>(t), std::get<2>(t), origin));
        },
        tasks[i]);
  }
  return out;
}

std::vector<NewTask> new_tasks(const std::vector<world::TaskChange>& changes) {
  std::vector<NewTask> out;
  for (const auto& c : changes) {
    if (c.propositions.empty()) {
      out.emplace_back(std::tuple<double, std::string>{c.time, c.task});
      continue;
    }
    PropositionTexts props;
    for (const auto& p : c.propositions) props[p.name] = p.text;
    out.emplace_back(std::tuple<double, std::string, PropositionTexts>{c.time, c.task, std::move(props)});
  }
  return out;
}

void bind_loop(py::module_& m) {
  py::enum_<MoveStatus>(m, "MoveStatus", "The state of the world's current move.")
      .value("IDLE", MoveStatus::Idle)
      .value("RUNNING", MoveStatus::Running)
      .value("SUCCEEDED", MoveStatus::Succeeded)
      .value("FAILED", MoveStatus::Failed);

  py::class_<exec::Move>(m, "Move", "A pick-and-place move the loop asks for: pick `thing` (believed at from_), place it at `to`.")
      .def(py::init([](std::string thing, std::string from, std::string to) {
             exec::Move mv;
             mv.action = "move(" + thing + ", " + to + ")";
             mv.thing = std::move(thing);
             mv.from = std::move(from);
             mv.to = std::move(to);
             return mv;
           }),
           py::arg("thing"), py::arg("from_"), py::arg("to"))
      .def_readonly("action", &exec::Move::action, "'move(o1, r2)'")
      .def_readonly("thing", &exec::Move::thing, "The thing moved (object or container).")
      .def_readonly("from_", &exec::Move::from, "Where the thing is taken from.")
      .def_readonly("to", &exec::Move::to, "Where the thing goes.")
      .def("__repr__", [](const exec::Move& mv) { return "<rtamp.Move " + mv.action + ">"; });

  py::class_<exec::WorldEvent>(m, "WorldEvent", "An intervention of a person as the world applied (or refused) it.")
      .def(py::init([](double time, world::Intervention what, bool applied, std::string detail) {
             return exec::WorldEvent{time, std::move(what), applied, std::move(detail)};
           }),
           py::arg("time"), py::arg("what"), py::arg("applied") = true, py::arg("detail") = "")
      .def_readonly("time", &exec::WorldEvent::time, "World time (s) of the event.")
      .def_readonly("what", &exec::WorldEvent::what, "The Intervention.")
      .def_readonly("applied", &exec::WorldEvent::applied, "True if the world applied it; False if it refused it (detail says why).")
      .def_readonly("detail", &exec::WorldEvent::detail, "Where it went, or why it was refused.");

  py::class_<exec::World, PyWorld>(
      m, "World",
      "The world the reactive loop perceives and acts in. Subclass it to run rtamp on your own robot:\n\n"
      "  time() -> float               seconds since the episode began\n"
      "  advance(dt)                   let dt seconds pass\n"
      "  observe() -> {thing: location}  every present thing ('hand' when held, 'none' outside all\n"
      "                                locations); values may also be (location, class[, container])\n"
      "  start(move)                   begin move.thing -> move.to (an rtamp.Move)\n"
      "  poll() -> status | (status, why)  rtamp.MoveStatus or 'running'/'succeeded'/'failed'/'idle'\n"
      "  halt()                        stop the move; make the arm safe (busy() until done)\n"
      "optional: next_event_time() (default inf: ticked every tick_period; a discrete-event world\n"
      "returns when it next changes), busy() (False), hand() ('' = home: where the last place ended),\n"
      "distance_travelled() (0), take_events() ([] of WorldEvent), confirming() (False: True while\n"
      "its perception has seen a change it does not report yet; the task is not judged meanwhile).\n"
      "To let a simulated person act on it (rtamp.PersonWorld), define both true_placement() ->\n"
      "{thing: location} (where things truly are) and apply(intervention) -> WorldEvent | bool\n"
      "(carry it out now, or refuse it), and report the events from take_events().\n"
      "World(scenario) lets observe() give plain locations for the scenario's things (their class is\n"
      "taken from it). The loop calls these with the GIL taken, from the thread that runs it.")
      .def(py::init([](const std::optional<world::Scenario>& s) {
             auto w = std::make_unique<PyWorld>();
             if (s) w->classes = class_table(*s);
             return w;
           }),
           py::arg("scenario") = py::none())
      .def("time", &exec::World::time, "World time (s).")
      .def("advance", &exec::World::advance, py::arg("dt"), py::call_guard<py::gil_scoped_release>(),
           "Moves world time on by dt seconds (the world runs its moves and its person meanwhile).")
      .def("next_event_time", &exec::World::next_event_time,
           "When something next happens by itself (a discrete-event world); inf: tick at the loop's rate.")
      .def("observe", &exec::World::observe, "What perception sees now: where every thing is.")
      .def("confirming", &exec::World::confirming,
           "True while perception has seen a change it does not report in observe() yet (it is making sure).")
      .def("start", &exec::World::start, py::arg("move"), "Starts a Move (one at a time).")
      .def("poll",
           [](exec::World& w) {
             std::string why;
             MoveStatus s = w.poll(&why);
             return py::make_tuple(s, why);
           },
           "The running move's state as a tuple (MoveStatus, reason; the reason says why a move failed).")
      .def("halt", &exec::World::halt, "Stops the running move where it is.")
      .def("busy", &exec::World::busy, "True while the arm may not start a move (e.g. still settling).")
      .def("hand", &exec::World::hand, "Where the hand is: a location name, or '' before the first move.")
      .def("distance_travelled", &exec::World::distance_travelled, "Tool path travelled so far (m), if the world measures it.")
      .def("take_events", &exec::World::take_events,
           "The WorldEvents (interventions applied or refused) since the last call; the world forgets them.");

  py::class_<exec::TaskOutcome>(m, "TaskOutcome", "One task that was in force during an episode, and how it ended.")
      .def_readonly("time", &exec::TaskOutcome::time, "World time (s) at which it took effect (0 for the scenario's task).")
      .def_readonly("task", &exec::TaskOutcome::task, "The LTL formula, as text.")
      .def_readonly("by", &exec::TaskOutcome::by, "Who gave it: 'scenario', 'script', 'command line', 'page', 'api', ...")
      .def_readonly("automaton_states", &exec::TaskOutcome::automaton_states, "States of its automaton.")
      .def_readonly("cycles", &exec::TaskOutcome::cycles, "Cycles of a recurring task completed while it was in force.")
      .def_readonly("outcome", &exec::TaskOutcome::outcome,
                    "'superseded' (a newer task replaced it), else the episode's end ('task-done', ...).")
      .def("__repr__", [](const exec::TaskOutcome& x) {
        return "<rtamp.TaskOutcome " + py::repr(py::str(x.task)).cast<std::string>() + " by " + x.by +
               " at t=" + std::to_string(x.time) + ": " + x.outcome + ">";
      });

  py::class_<exec::EpisodeMetrics>(m, "EpisodeMetrics", "What one episode measured (the quantities of the paper's Table I).")
      .def_readonly("success", &exec::EpisodeMetrics::success, "The task was done (end == 'success').")
      .def_property_readonly("end", [](const exec::EpisodeMetrics& x) { return exec::to_string(x.end); },
                             "Why it ended: 'task-done', 'cycles', 'unsatisfiable', 'no-plan', 'gave-up', 'lost',\n"
                             "'time-limit', 'interrupted', 'error' (or 'running').")
      .def_readonly("reason", &exec::EpisodeMetrics::reason, "Why the episode ended, readable.")
      .def_readonly("first_plan_seconds", &exec::EpisodeMetrics::first_plan_seconds, "Wall time (s) of the first plan.")
      .def_readonly("replan_seconds", &exec::EpisodeMetrics::replan_seconds, "Total wall time (s) of the replans.")
      .def_readonly("replans", &exec::EpisodeMetrics::replans, "Number of replans after the first plan.")
      .def_readonly("tree_changes", &exec::EpisodeMetrics::tree_changes, "Subtrees inserted plus removed over the episode.")
      .def_readonly("completion_time", &exec::EpisodeMetrics::completion_time, "World seconds (success only).")
      .def_readonly("motion_cost", &exec::EpisodeMetrics::motion_cost, "Tool path travelled (m), when the world measures it (else 0).")
      .def_readonly("interventions", &exec::EpisodeMetrics::interventions, "Interventions the world reported, applied or refused.")
      .def_readonly("interventions_applied", &exec::EpisodeMetrics::interventions_applied, "Interventions the world applied.")
      .def_readonly("interventions_refused", &exec::EpisodeMetrics::interventions_refused, "Interventions the world refused.")
      .def_readonly("actions_succeeded", &exec::EpisodeMetrics::actions_succeeded, "Moves that succeeded.")
      .def_readonly("actions_failed", &exec::EpisodeMetrics::actions_failed, "Moves that failed.")
      .def_readonly("cycles", &exec::EpisodeMetrics::cycles, "Completed cycles of a recurring task.")
      .def_readonly("tasks", &exec::EpisodeMetrics::tasks,
                    "Every task in force, in order (the scenario's first): list of TaskOutcome.")
      .def_readonly("run_length", &exec::EpisodeMetrics::run_length, "States of the observed run.")
      .def_readonly("world_time", &exec::EpisodeMetrics::world_time, "World time (s) at the end.")
      .def_readonly("wall_seconds", &exec::EpisodeMetrics::wall_seconds, "Wall time (s) of the episode.")
      .def_readonly("real_time_factor", &exec::EpisodeMetrics::real_time_factor, "World time divided by wall time.")
      .def_readonly("seed", &exec::EpisodeMetrics::seed, "The episode's random seed.")
      .def("__repr__", [](const exec::EpisodeMetrics& x) {
        return std::string("<rtamp.EpisodeMetrics ") + exec::to_string(x.end) + (x.success ? " success" : " failure") +
               " world_time=" + std::to_string(x.world_time) + ">";
      });

  py::class_<exec::EpisodeInfo>(m, "EpisodeInfo", "What an episode runs: scenario, task, algorithm, ...")
      .def_readonly("scenario", &exec::EpisodeInfo::scenario, "The scenario's name.")
      .def_readonly("task", &exec::EpisodeInfo::task, "The LTL task, as text.")
      .def_readonly("algorithm", &exec::EpisodeInfo::algorithm, "The search algorithm's name (rtamp.algorithms()).")
      .def_readonly("conditions", &exec::EpisodeInfo::conditions, "The behavior tree's condition mode ('action' or 'state').")
      .def_readonly("reconfiguration", &exec::EpisodeInfo::reconfiguration, "How the tree changes on a replan ('online' or 'rebuild').")
      .def_readonly("world", &exec::EpisodeInfo::world, "The world's kind ('mujoco', 'symbolic' or the Python World's).")
      .def_readonly("seed", &exec::EpisodeInfo::seed, "The episode's random seed.");

  py::class_<exec::EpisodeObserver, PyObserver>(
      m, "Observer",
      "Receives what an episode does; subclass and define any of on_begin(info), on_action(t, what,\n"
      "action, why), on_intervention(event), on_things_changed(t, added, removed), on_progress(t,\n"
      "placement, automaton_states), on_replan_request(t, why), on_plan(t, dict), on_task(t, dict),\n"
      "on_redirect(t, action, rule), on_cycle(t, n), on_end(t, metrics, placement). on_task: a new task\n"
      "was taken in or refused; its dict has task, by, applied, refused (why, '' if applied),\n"
      "automaton_states (the new automaton's size; None if refused) and propositions ({name: text}).\n"
      "on_redirect: the running move was halted because finishing it would leave the new task no\n"
      "accepting future (`rule` says so). Called on the loop's thread with the GIL taken; they must\n"
      "not call back into the loop.")
      .def(py::init<>());

  py::class_<PyLoop>(m, "ReactiveLoop",
                     "The reactive loop (paper Algorithm 1) on a world: perceive, track the task, plan and\n"
                     "replan, reconfigure the behavior tree, tick. Options: algorithm, cost (a name or a\n"
                     "CostModel), conditions ('action' | 'state'), reconfiguration ('online' | 'offline'),\n"
                     "planning ('worker': plans on a worker thread while the tree ticks, charged its wall\n"
                     "time; 'inline': synchronous, deterministic), max_time, tick_period,\n"
                     "max_failures_per_move, outside_grace, cycles, seed, world_name, new_tasks (a list of\n"
                     "(time, formula) or (time, formula, {name: expression}): a new task at that world time).")
      .def(py::init([](py::object world, const world::Scenario& s, const std::string& algorithm,
                       const py::object& cost, const std::string& conditions, const std::string& reconfiguration,
                       const std::string& planning, double max_time, double tick_period, int max_failures,
                       double outside_grace, int cycles, std::uint64_t seed, const std::string& world_name,
                       double time_limit, const std::vector<NewTask>& new_task_list) {
             PlannerConfig pc = planner_config(s, algorithm, cost, "partial", true, true, time_limit, 20'000'000);
             exec::LoopOptions o;
             o.planner = pc.options;
             o.conditions = parse_name(exec::condition_modes(), conditions, "condition mode");
             o.reconfiguration = parse_name(exec::reconfigurations(), reconfiguration, "reconfiguration");
             o.planning = parse_name(exec::planning_modes(), planning, "planning mode");
             o.max_time = max_time;
             o.tick_period = tick_period;
             o.max_failures_per_move = max_failures;
             o.outside_grace = outside_grace;
             o.cycles = cycles;
             o.seed = seed;
             o.world_name = world_name;
             o.task_changes = task_changes(new_task_list);
             return std::make_unique<PyLoop>(std::move(world), s, std::move(o), std::move(pc.model_ref));
           }),
           py::arg("world"), py::arg("scenario"), py::kw_only(), py::arg("algorithm") = "astar-exp",
           py::arg("cost") = "euclid", py::arg("conditions") = "action", py::arg("reconfiguration") = "online",
           py::arg("planning") = "worker", py::arg("max_time") = 900.0, py::arg("tick_period") = 0.02,
           py::arg("max_failures_per_move") = 5, py::arg("outside_grace") = 3.0, py::arg("cycles") = 0,
           py::arg("seed") = 0, py::arg("world_name") = "python", py::arg("time_limit") = 60.0,
           py::arg("new_tasks") = std::vector<NewTask>{})
      .def("add_observer", &PyLoop::add_observer, py::arg("observer"), "Attaches an rtamp.Observer (kept alive by the loop).")
      .def("step", [](PyLoop& l) {
        py::gil_scoped_release release;
        return l.loop().step();
      }, "One iteration; False once the episode has ended (the first call plans).")
      .def("run", [](PyLoop& l) {
        py::gil_scoped_release release;
        return l.loop().run();
      }, "Steps until the episode ends; returns its EpisodeMetrics (the GIL is released meanwhile).")
      .def("stop", [](PyLoop& l) { l.loop().stop(); }, "Ends the episode at the next step (thread-safe).")
      .def(
          "set_task",
          [](PyLoop& l, const std::string& formula, const std::optional<PropositionTexts>& propositions) {
            world::TaskChange c = task_change(0, formula, propositions.value_or(PropositionTexts{}), "set_task");
            py::gil_scoped_release release;
            l.loop().set_task(std::move(c));
          },
          py::arg("formula"), py::arg("propositions") = py::none(),
          "A new task from now on (thread-safe: e.g. from another thread while run() runs), taken in at\n"
          "the next step: `formula` over the scenario's propositions, quoted expressions and the new ones\n"
          "in `propositions` ({name: expression}). The run is judged for it from the state it takes\n"
          "effect in (task_from). Raises rtamp.Error naming what is wrong (bad formula, unknown or\n"
          "redefined proposition, bad expression; the refusal is also reported to observers' on_task),\n"
          "or if the episode has ended.")
      .def_property_readonly("ended", [](PyLoop& l) { return l.loop().ended(); }, "The episode has ended.")
      .def_property_readonly("metrics", [](PyLoop& l) { return l.loop().metrics(); }, "The EpisodeMetrics so far.")
      .def_property_readonly("observed_run", [](PyLoop& l) { return l.loop().observed_run(); },
                             "The observed run: symbolic states (Placements), in order.")
      .def_property_readonly("task_from", [](PyLoop& l) { return l.loop().task_from(); },
                             "The index into observed_run at which the task in force took effect (0: the scenario's).")
      .def_property_readonly("cycle_marks", [](PyLoop& l) { return l.loop().cycle_marks(); },
                             "For recurring tasks: the index into the observed run at which each counted cycle ended.")
      .def_property_readonly("actions", [](PyLoop& l) { return l.loop().tree().tuples(); },
                             "The moves of the plan the tree runs now (ActionTuples).")
      .def("tree_text", [](PyLoop& l) { return bt::to_text(l.loop().tree().tree()); },
           "The behavior tree now, as text with status markers.");
}

}  // namespace rtamp::python
