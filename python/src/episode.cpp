// Python bindings of the episode (episode/episode.hpp): EpisodeOptions — the
// one description of an episode that `rtamp run|serve|batch` fill in too,
// seen from Python as flat attributes (world, algorithm, seed, log, ...) —
// run_episode(), and the registry of worlds by name (world_registry.hpp).
// Invariant: an attribute's value is checked when it is set (names against
// the library's tables and registries); numbers are checked when the episode
// is built, before anything is written or runs. Episodes run without the GIL.
#include <optional>
#include <utility>

#include "bindings.hpp"
#include "choices.hpp"
#include "loop.hpp"
#include "rtamp/episode/episode.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/sim/perception.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::python {

namespace {

using episode::EpisodeOptions;

// Sets each keyword as an attribute of `o` (a TypeError names an unknown
// one), `world` first and `random_change` before `change_window`; without
// `planning`, a fresh options object plans as its world does by default.
void set_options(py::object o, const py::kwargs& kw, bool fresh) {
  const py::object type = py::type::of(o);
  std::vector<std::string> names, keys;
  for (const auto& k : py::module_::import("builtins").attr("dir")(type)) {
    const std::string n = py::str(k);
    if (n.rfind("_", 0) != 0) names.push_back(n);
  }
  for (const auto& [k, v] : kw) {
    const std::string key = py::str(k);
    if (key.rfind("_", 0) == 0 || !py::hasattr(type, key.c_str()))
      throw py::type_error("unknown episode option " + world::quoted(key) + world::suggestion(key, names));
    keys.push_back(key);
  }
  auto rank = [](const std::string& k) { return k == "world" ? 0 : k == "random_change" ? 1 : 2; };
  std::stable_sort(keys.begin(), keys.end(), [&](const auto& x, const auto& y) { return rank(x) < rank(y); });
  for (const auto& key : keys) py::setattr(o, key.c_str(), kw[py::str(key)]);
  if (fresh && !kw.contains("planning")) {
    EpisodeOptions& e = o.cast<EpisodeOptions&>();
    e.loop.planning = episode::find_world(e.world).planning;
  }
}

template <class E>
void def_named(py::class_<EpisodeOptions>& c, const char* name, const NameTable<E>& table, const char* what,
               E exec::LoopOptions::*field, const char* doc) {
  c.def_property(
      name, [&table, field](const EpisodeOptions& o) { return std::string(name_of(table, o.loop.*field)); },
      [&table, field, what](EpisodeOptions& o, const std::string& s) { o.loop.*field = parse_name(table, s, what); },
      doc);
}

}  // namespace

void bind_episode(py::module_& m) {
  py::class_<EpisodeOptions> cls(
      m, "EpisodeOptions",
      "One episode's options, as `rtamp run` fills them in (docs/python.md): the world by name, the\n"
      "seed, the person (scripted_operator, random_rate, random_change, change_window), the loop\n"
      "(algorithm, cost, conditions, reconfiguration, planning, max_time, tick_period, cycles,\n"
      "max_failures_per_move, outside_grace, new_tasks) and the outputs (log, trees, video, timeline).\n"
      "EpisodeOptions(**attributes); without planning, the world's own planning mode.");
  cls.def(py::init([](const py::kwargs& kw) {
          py::object o = py::cast(EpisodeOptions{}, py::return_value_policy::move);
          set_options(o, kw, true);
          return o.cast<EpisodeOptions>();
        }))
      .def_property(
          "world", [](const EpisodeOptions& o) { return o.world; },
          [](EpisodeOptions& o, const std::string& s) { o.world = episode::find_world(s).name; },
          "A registered world: 'mujoco' (the UR5), 'symbolic', or one registered in C++ (worlds())")
      .def_readwrite("seed", &EpisodeOptions::seed, "One seed: the world's, the person's and the initial layout's draws")
      .def_readwrite("randomize_initial", &EpisodeOptions::randomize_initial,
                     "Shuffle objects inside their initial locations (seeded)")
      .def_readwrite("scripted_operator", &EpisodeOptions::scripted_operator,
                     "The person follows the scenario's `operator:` script")
      .def_property(
          "failure_probability", [](const EpisodeOptions& o) { return o.world_settings.failure_probability; },
          [](EpisodeOptions& o, double p) { o.world_settings.failure_probability = p; },
          "Worlds that draw move failures (symbolic): the chance that a move fails")
      .def_property(
          "perception", [](const EpisodeOptions& o) { return o.world_settings.perception; },
          [](EpisodeOptions& o, const std::string& p) {
            sim::parse_perception_source(p);  // one of the two, or the error naming it
            o.world_settings.perception = p;
          },
          "How the robot perceives in the mujoco world: 'truth' (the simulation's poses) or 'camera' (the\n"
          "scenario's primary camera, segmented and fitted from pixels, kept in a belief)")
      .def_property(
          "random_rate", [](const EpisodeOptions& o) { return o.person.rate; },
          [](EpisodeOptions& o, double r) { o.person.rate = r; },
          "Random interventions per second of world time, of every kind (docs/person.md)")
      .def_property(
          "random_change",
          [](const EpisodeOptions& o) -> std::optional<std::string> {
            if (!o.person.change) return std::nullopt;
            return std::string(world::to_string(o.person.change->kind));
          },
          [](EpisodeOptions& o, const std::optional<std::string>& k) {
            if (!k) {
              o.person.change.reset();
              return;
            }
            world::RandomChange c = o.person.change.value_or(world::RandomChange{});
            c.kind = parse_intervention_kind(*k);
            o.person.change = c;
          },
          "One random intervention of this kind ('relocate', 'add', 'remove', ...) in change_window; None: none")
      .def_property(
          "change_window",
          [](const EpisodeOptions& o) {
            const world::RandomChange c = o.person.change.value_or(world::RandomChange{});
            return std::pair<double, double>{c.begin, c.end};
          },
          [](EpisodeOptions& o, std::pair<double, double> w) {
            if (!o.person.change) throw Error("change_window: there is no random_change to time");
            o.person.change->begin = w.first;
            o.person.change->end = w.second;
          },
          "When the random change happens: (begin, end) in s of world time (default 2-20 s)");
  cls.def_property(
      "algorithm", [](const EpisodeOptions& o) { return std::string(plan::algorithm_info(o.loop.planner.algorithm).name); },
      [](EpisodeOptions& o, const std::string& s) { o.loop.planner.algorithm = plan::parse_algorithm(s); },
      "Search algorithm: 'astar-exp', 'astar', 'dijkstra' (algorithms())");
  cls.def_property(
      "cost", [](const EpisodeOptions& o) { return o.loop.planner.cost; },
      [](EpisodeOptions& o, const std::string& s) {
        if (!plan::has_cost_model(s)) plan::make_cost_model(s);  // throws: unknown, with a did-you-mean
        o.loop.planner.cost = s;
      },
      "The planner's motion-cost model (cost_models())");
  def_named(cls, "conditions", exec::condition_modes(), "condition mode", &exec::LoopOptions::conditions,
            "The tree's conditions: 'action' or 'state'");
  def_named(cls, "reconfiguration", exec::reconfigurations(), "reconfiguration", &exec::LoopOptions::reconfiguration,
            "How the tree follows a new plan: 'online' or 'offline'");
  def_named(cls, "planning", exec::planning_modes(), "planning mode", &exec::LoopOptions::planning,
            "'worker' (plans beside the running arm) or 'inline'; default: the world's");
  cls.def_property(
       "max_time", [](const EpisodeOptions& o) { return o.loop.max_time; },
       [](EpisodeOptions& o, double v) { o.loop.max_time = v; }, "Seconds of world time before giving up")
      .def_property(
          "tick_period", [](const EpisodeOptions& o) { return o.loop.tick_period; },
          [](EpisodeOptions& o, double v) { o.loop.tick_period = v; }, "Seconds between ticks (MuJoCo: 0.02)")
      .def_property(
          "cycles", [](const EpisodeOptions& o) { return o.loop.cycles; },
          [](EpisodeOptions& o, int v) { o.loop.cycles = v; }, "Recurring tasks: succeed after this many cycles")
      .def_property(
          "max_failures_per_move", [](const EpisodeOptions& o) { return o.loop.max_failures_per_move; },
          [](EpisodeOptions& o, int v) { o.loop.max_failures_per_move = v; },
          "Failures of one move from one state before the episode gives up")
      .def_property(
          "outside_grace", [](const EpisodeOptions& o) { return o.loop.outside_grace; },
          [](EpisodeOptions& o, double v) { o.loop.outside_grace = v; },
          "Seconds a thing may be outside every location before it counts as lost")
      .def_property(
          "new_tasks", [](const EpisodeOptions& o) { return new_tasks(o.loop.task_changes); },
          [](EpisodeOptions& o, const std::vector<NewTask>& v) { o.loop.task_changes = task_changes(v); },
          "New tasks at world times, after the scenario's operator script's: a list of (time, formula)\n"
          "or (time, formula, {name: expression}) (as `rtamp run --new-task TIME@LTL`)")
      .def_property(
          "log", [](const EpisodeOptions& o) { return o.outputs.log; },
          [](EpisodeOptions& o, std::string v) {
            o.outputs.log = std::move(v);
            o.outputs.log_option = "log";  // errors name the keyword (log: cannot write 'x': ...)
          },
          "JSON Lines log file ('': none)")
      .def_property(
          "trees", [](const EpisodeOptions& o) { return o.outputs.trees; },
          [](EpisodeOptions& o, std::string v) { o.outputs.trees = std::move(v); },
          "Directory for the tree after each change, as BehaviorTree.CPP XML ('': none)")
      .def_property(
          "video", [](const EpisodeOptions& o) { return o.outputs.video; },
          [](EpisodeOptions& o, std::string v) { o.outputs.video = std::move(v); }, "MP4 of a MuJoCo run ('': none)")
      .def_property(
          "timeline", [](const EpisodeOptions& o) { return o.outputs.timeline; },
          [](EpisodeOptions& o, std::optional<std::function<void(const std::string&)>> f) {
            o.outputs.timeline = f ? *f : nullptr;
          },
          "A callable that gets each readable line as it happens (None: quiet)")
      .def("__repr__", [](const EpisodeOptions& o) {
        return "<EpisodeOptions world='" + o.world + "' seed=" + std::to_string(o.seed) + " algorithm='" +
               plan::algorithm_info(o.loop.planner.algorithm).name + "'>";
      });

  m.def(
      "run_episode",
      [](const world::Scenario& s, std::optional<EpisodeOptions> options, const py::kwargs& kw) {
        py::object o = py::cast(options ? *options : EpisodeOptions{}, py::return_value_policy::move);
        set_options(o, kw, !options);
        const EpisodeOptions opt = o.cast<EpisodeOptions>();
        exec::EpisodeMetrics r;
        {
          py::gil_scoped_release release;
          r = episode::run_episode(s, opt);
        }
        return r;
      },
      py::arg("scenario"), py::arg("options") = py::none(),
      "One episode of the reactive loop, as `rtamp run` runs it: run_episode(scenario, options=None,\n"
      "**attributes) — the attributes of EpisodeOptions (world='mujoco' or 'symbolic', seed, log, trees,\n"
      "video, timeline, ...) set on a copy of `options`. Returns the EpisodeMetrics. The GIL is\n"
      "released while it runs.");

  m.def(
      "worlds",
      [] {
        py::dict d;
        for (const auto& w : episode::worlds()) d[py::str(w.name)] = py::str(w.description);
        return d;
      },
      "The registered worlds an episode can run in: {name: one-line description}.");
}

}  // namespace rtamp::python
