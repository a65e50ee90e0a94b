// Python bindings of rtamp's own worlds on the rtamp.World base: the symbolic
// world (exec/symbolic_world.hpp: exact placement, discrete-event arm, seeded
// failures and interventions; thousands of episodes a second) and the MuJoCo
// UR5 (episode/sim_world.hpp), the person and the world it acts on, and
// choices(): every named choice with its description. Whole episodes:
// episode.cpp.
#include <optional>

#include "bindings.hpp"
#include "choices.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/episode/episode.hpp"
#include "rtamp/episode/sim_world.hpp"
#include "rtamp/exec/person_world.hpp"
#include "rtamp/exec/symbolic_world.hpp"

namespace rtamp::python {

void bind_worlds(py::module_& m) {
  py::class_<exec::SymbolicWorld, exec::World>(
      m, "SymbolicWorld",
      "A world with no physics (docs/symbolic-world.md): the exact placement, a discrete-event arm\n"
      "(approach, grasp, carry, place, retreat), seeded failures, and the rules of applying a person's\n"
      "interventions (apply(); a Person drives it through PersonWorld).\n"
      "Options: seed, failure_probability, fails (a callable Move -> bool: those moves fail at the end\n"
      "of phase fails_in), speed and the phase durations.")
      .def(py::init([](const world::Scenario& s, std::uint64_t seed, double failure_probability,
                       std::optional<std::function<bool(const exec::Move&)>> fails,
                       const std::string& fails_in, double speed, double approach_base, double grasp,
                       double carry_base, double place, double retreat, double return_base) {
             exec::SymbolicWorldOptions o;
             o.seed = seed;
             o.failure_probability = failure_probability;
             if (fails) o.fails = *fails;
             o.fails_in = parse_name(exec::phases(), fails_in, "phase");
             o.speed = speed;
             o.approach_base = approach_base;
             o.grasp = grasp;
             o.carry_base = carry_base;
             o.place = place;
             o.retreat = retreat;
             o.return_base = return_base;
             return std::make_unique<exec::SymbolicWorld>(s, std::move(o));
           }),
           py::arg("scenario"), py::kw_only(), py::arg("seed") = 1, py::arg("failure_probability") = 0.0,
           py::arg("fails") = py::none(), py::arg("fails_in") = "grasp", py::arg("speed") = 0.25,
           py::arg("approach_base") = 0.5, py::arg("grasp") = 0.5, py::arg("carry_base") = 0.5,
           py::arg("place") = 0.5, py::arg("retreat") = 0.5, py::arg("return_base") = 0.5)
      .def_property_readonly("truth", &exec::SymbolicWorld::truth, "The exact placement (a held thing in 'hand').")
      .def_property_readonly("phase", [](const exec::SymbolicWorld& w) { return name_of(exec::phases(), w.phase()); },
                             "The arm's phase: 'idle', 'approach', 'grasp', 'carry', 'place', 'retreat', 'return'.")
      .def("apply", &exec::SymbolicWorld::apply, py::arg("intervention"),
           "Applies an intervention now, as a person would; returns the WorldEvent (applied or refused).")
      .def("true_placement", &exec::SymbolicWorld::true_placement, "The exact placement (as truth).")
      .def_property_readonly("history", &exec::SymbolicWorld::history, "Every intervention so far (WorldEvents).")
      .def("capacity", &exec::SymbolicWorld::capacity, py::arg("location"), "-1 if there is no such location.")
      .def("refusal", &exec::SymbolicWorld::refusal, py::arg("thing"), py::arg("location"),
           "'' if the location would take the thing now, else why not.")
      .def("check_invariants", &exec::SymbolicWorld::check_invariants, "'' if every invariant holds, else what is wrong.");

  py::class_<episode::SimWorld, exec::World>(
      m, "MujocoWorld",
      "The simulated UR5 in MuJoCo as a World: moves are the pick and place skills, perception maps\n"
      "body poses to regions, and a person's interventions are carried out between physics steps\n"
      "(apply(); a Person drives it through PersonWorld). Options: seed, perception ('truth': the\n"
      "simulation's poses; 'camera': the scenario's cameras and a belief), cameras (with 'camera': the\n"
      "names of the cameras that perceive, e.g. ['overhead', 'wrist']; default: the primary one). Use\n"
      "run_episode(..., video=...) to film.")
      .def(py::init([](const world::Scenario& s, std::uint64_t seed, const std::string& perception,
                       const std::vector<std::string>& cameras) {
             sim::SessionOptions so;
             so.seed = seed;
             so.perception.source = sim::parse_perception_source(perception);
             if (so.perception.source != sim::PerceptionSource::Camera && !cameras.empty())
               throw Error("cameras: they perceive only with perception='camera'");
             so.perception.cameras = cameras;
             py::gil_scoped_release release;
             return std::make_unique<episode::SimWorld>(s, so);
           }),
           py::arg("scenario"), py::kw_only(), py::arg("seed") = 1, py::arg("perception") = "truth",
           py::arg("cameras") = std::vector<std::string>{})
      .def("apply", &episode::SimWorld::apply, py::arg("intervention"), py::call_guard<py::gil_scoped_release>(),
           "Applies an intervention now, as a person would; returns the WorldEvent (applied or refused).")
      .def("true_placement", &episode::SimWorld::true_placement, py::call_guard<py::gil_scoped_release>(),
           "Where every present thing truly is (noise-free; a held thing in 'hand').")
      .def("snapshot", [](episode::SimWorld& w, const std::string& png) {
        py::gil_scoped_release release;
        w.session().snapshot(png);
      }, py::arg("png_path"), "Renders the scene now to a PNG file.");

  py::class_<world::Person>(
      m, "Person",
      "The person who intervenes, for every world (world/person.hpp): a script of Interventions, random\n"
      "interventions (rate per second in [start, end), kinds: names such as 'relocate', 'add'), one\n"
      "random change of a kind at a uniform time in change_window, and post() from any thread. Random\n"
      "draws are portable: a seed means the same interventions on every world. Drive a world with it\n"
      "through PersonWorld(world, person).")
      .def(py::init([](const world::Scenario& s, std::vector<world::Intervention> script, double rate, double start,
                       double end, const std::optional<std::vector<std::string>>& kinds,
                       const std::optional<std::string>& change, std::pair<double, double> change_window,
                       std::uint64_t seed) {
             world::PersonOptions o;
             o.script = std::move(script);
             o.rate = rate;
             o.start = start;
             o.end = end;
             if (kinds) {
               o.kinds.clear();
               for (const auto& k : *kinds) o.kinds.push_back(parse_intervention_kind(k));
             }
             if (change)
               o.change = world::RandomChange{parse_intervention_kind(*change), change_window.first, change_window.second};
             o.seed = seed;
             return std::make_unique<world::Person>(s, std::move(o));
           }),
           py::arg("scenario"), py::kw_only(), py::arg("script") = std::vector<world::Intervention>{},
           py::arg("rate") = 0.0, py::arg("start") = 0.0, py::arg("end") = std::numeric_limits<double>::infinity(),
           py::arg("kinds") = py::none(), py::arg("change") = py::none(),
           py::arg("change_window") = std::pair<double, double>{2.0, 20.0}, py::arg("seed") = 1)
      .def("next_time", &world::Person::next_time, "When the next intervention is due (inf: none).")
      .def("post", &world::Person::post, py::arg("intervention"),
           "Posts an intervention to be applied at once (thread-safe).");

  py::class_<exec::PersonWorld, exec::World>(
      m, "PersonWorld",
      "A world with a Person acting on it: forwards everything to `world` (which must take\n"
      "interventions: the built-in worlds do, a Python World that defines true_placement() and\n"
      "apply()) and applies the person's interventions when they are due. Run the loop on it.")
      .def(py::init([](exec::World& w, world::Person& p) { return std::make_unique<exec::PersonWorld>(w, p); }),
           py::arg("world"), py::arg("person"), py::keep_alive<1, 2>(), py::keep_alive<1, 3>());

  m.def("choices", [] {
    py::dict d;
    auto add = [&](const char* key, const auto& table) {
      py::dict t;
      for (const auto& n : table) t[py::str(n.name)] = py::str(n.description);
      d[py::str(key)] = t;
    };
    py::dict w;
    for (const auto& e : episode::worlds()) w[py::str(e.name)] = py::str(e.description);
    d["world"] = w;
    add("bt", exec::tree_variants());
    add("conditions", exec::condition_modes());
    add("reconfiguration", exec::reconfigurations());
    add("planning", exec::planning_modes());
    add("graph", plan::graph_constructions());
    add("change", world::random_change_kinds());
    add("intervention", world::intervention_kinds());
    add("phase", exec::phases());
    add("move_status", exec::move_statuses());
    return d;
  }, "Every named choice (the CLI's and run_episode's option values) -> {name: one-line description},\n"
     "from the same tables the command line reads. algorithms() and cost_models() list the planner's.");

}

}  // namespace rtamp::python
