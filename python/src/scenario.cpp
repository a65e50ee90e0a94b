// Python bindings of the world layer's scenario (paper Section II: regions R,
// objects O, the task φ; Section V's scripted interventions): load a YAML file
// or a built-in, parse YAML text, write YAML, generate parametric scenes (as
// `rtamp gen` does), and the symbolic Placement (where every thing is).
// Scenario fields are plain values: reading a list (s.objects) gives a copy;
// assign the whole list back to change it.
#include "bindings.hpp"
#include "choices.hpp"
#include "rtamp/world/builtin_scenarios.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"
#include "rtamp/world/scenario_io.hpp"
#include "rtamp/world/validate.hpp"

namespace rtamp::python {

namespace {

using namespace rtamp::world;

py::object location_tuple(const SourceLocation& w) {
  if (w.file.empty() && w.line == 0) return py::none();
  return py::make_tuple(w.file, w.line, w.column);
}

}  // namespace

Intervention::Kind parse_intervention_kind(const std::string& s) {
  return parse_name(world::intervention_kinds(), s, "intervention kind");
}
const char* intervention_kind_name(Intervention::Kind k) { return world::to_string(k); }

void bind_scenario(py::module_& m) {
  py::class_<Region>(m, "Region", "A fixed region of the table: an axis-aligned box [center ± size/2] in x, y (metres).")
      .def(py::init([](std::string name, Vec3 center, Vec3 size, int capacity) {
             Region r;
             r.name = std::move(name);
             r.center = center;
             r.size = size;
             r.capacity = capacity;
             return r;
           }),
           py::arg("name"), py::arg("center") = Vec3{0, 0, 0}, py::arg("size") = Vec3{0.2, 0.2, 0},
           py::arg("capacity") = 8)
      .def_readwrite("name", &Region::name, "The region's name.")
      .def_readwrite("center", &Region::center, "[x, y, z] in metres.")
      .def_readwrite("size", &Region::size, "[x, y, z] extents (z ignored).")
      .def_readwrite("capacity", &Region::capacity, "How many movable things fit.")
      .def_property_readonly("where", [](const Region& r) { return location_tuple(r.where); },
                             "(file, line, column) where it was defined, or None.")
      .def("__repr__", [](const Region& r) { return "<rtamp.Region " + r.name + ">"; });

  py::class_<Container>(m, "Container", "A movable region (a tray): moving it carries its contents.")
      .def(py::init([](std::string name, std::string cls, Vec3 position, Vec3 size, int capacity) {
             Container c;
             c.name = std::move(name);
             c.cls = std::move(cls);
             c.position = position;
             c.size = size;
             c.capacity = capacity;
             return c;
           }),
           py::arg("name"), py::arg("cls") = "tray", py::arg("position") = Vec3{0, 0, 0},
           py::arg("size") = Vec3{0.24, 0.16, 0.03}, py::arg("capacity") = 4)
      .def_readwrite("name", &Container::name, "The container's name.")
      .def_readwrite("cls", &Container::cls, "Its class, e.g. 'tray'.")
      .def_readwrite("position", &Container::position, "Where its base centre stands (x, y, z; m).")
      .def_readwrite("size", &Container::size, "Its size (x, y, z; m).")
      .def_readwrite("capacity", &Container::capacity, "How many objects fit in it.")
      .def("__repr__", [](const Container& c) { return "<rtamp.Container " + c.name + ">"; });

  py::class_<Object>(m, "Object", "A movable object (a block).")
      .def(py::init([](std::string name, std::string cls, Vec3 position, Vec3 size) {
             Object o;
             o.name = std::move(name);
             o.cls = std::move(cls);
             o.position = position;
             o.size = size;
             return o;
           }),
           py::arg("name"), py::arg("cls") = "block", py::arg("position") = Vec3{0, 0, 0},
           py::arg("size") = Vec3{0.04, 0.04, 0.04})
      .def_readwrite("name", &Object::name, "The object's name.")
      .def_readwrite("cls", &Object::cls, "Its class, e.g. 'block'.")
      .def_readwrite("position", &Object::position, "Centre of its base, metres.")
      .def_readwrite("size", &Object::size, "Its size (x, y, z; m).")
      .def("__repr__", [](const Object& o) { return "<rtamp.Object " + o.name + ">"; });

  py::class_<Proposition>(m, "Proposition", "A named proposition over the world, e.g. all_in_r2 = 'all block in r2'.")
      .def_readonly("name", &Proposition::name, "The proposition's name (an atom of the task).")
      .def_readonly("text", &Proposition::text, "The expression as written.")
      .def("__repr__", [](const Proposition& p) { return "<rtamp.Proposition " + p.name + " = '" + p.text + "'>"; });

  py::class_<Robot>(m, "Robot", "The robot: model name, base position and yaw.")
      .def_readwrite("model", &Robot::model, "The robot model ('ur5').")
      .def_readwrite("base", &Robot::base, "Where its base stands (x, y, z; m).")
      .def_readwrite("yaw", &Robot::yaw, "Its base's turn about world z (rad).");

  py::class_<Change>(m, "Change",
                     "A change of the world (one type for the planner, the worlds and the loop): build with the\n"
                     "static constructors or Change.parse('move o1 r2' | 'add o4 block r1' | 'remove o1' |\n"
                     "'add-container t2 tray r1 3' | 'remove-container t2' | 'add-region r4 0.5 0.2 [capacity [sx sy]]').\n"
                     "Planner.apply takes one; an Intervention is a Change at a time.")
      .def_static("parse", &Change::parse, py::arg("text"),
                  "A change from its text (see the class); raises rtamp.Error with the column.")
      .def_static("relocate", &Change::relocate, py::arg("thing"), py::arg("location"), "A thing moved to a location.")
      .def_static("add_object", &Change::add_object, py::arg("object"), py::arg("cls"), py::arg("location"),
                  "A new object of class cls at a location.")
      .def_static("remove_object", &Change::remove_object, py::arg("object"), "An object taken away.")
      .def_static("add_container", &Change::add_container, py::arg("container"), py::arg("cls"), py::arg("region"),
                  py::arg("capacity") = 4, "A new container of class cls in a region.")
      .def_static("remove_container", &Change::remove_container, py::arg("container"),
                  "A container taken away (its contents stay where it stood).")
      .def_static("add_region", &Change::add_region, py::arg("region"), "A new region (a Region).")
      .def_static("take_from_gripper", &Change::take_from_gripper, py::arg("location") = "",
                  "Take what the gripper holds (to `location`, else away): for worlds; the planner refuses it.")
      .def_property_readonly("kind", [](const Change& c) { return world::to_string(c.kind); },
                             "'relocate', 'add', 'remove', 'add-container', 'remove-container',\n"
                             "'take-from-gripper' or 'add-region'.")
      .def_readonly("subject", &Change::subject, "The object, container or region ('' for take-from-gripper).")
      .def_readonly("cls", &Change::cls, "The class of an added object or container.")
      .def_readonly("location", &Change::location, "A region or container name ('' if none).")
      .def_readonly("capacity", &Change::capacity, "An added container's capacity.")
      .def("__str__", &Change::to_string)
      .def("__repr__", [](const Change& c) { return "rtamp.Change.parse('" + c.to_string() + "')"; });

  py::class_<Intervention, Change>(m, "Intervention",
                           "A person's action on the world (a Change at `time` seconds): kind 'relocate', 'add',\n"
                           "'remove', 'add-container', 'remove-container' or 'take-from-gripper'.")
      .def(py::init([](const std::string& kind, std::string subject, std::string location, std::string cls,
                       double time) {
             Intervention iv;
             iv.kind = parse_intervention_kind(kind);
             iv.subject = std::move(subject);
             iv.location = std::move(location);
             iv.cls = std::move(cls);
             iv.time = time;
             return iv;
           }),
           py::arg("kind"), py::arg("subject") = "", py::arg("location") = "", py::arg("cls") = "",
           py::arg("time") = 0.0)
      .def_property("kind", [](const Intervention& iv) { return intervention_kind_name(iv.kind); },
                    [](Intervention& iv, const std::string& k) { iv.kind = parse_intervention_kind(k); },
                    "'relocate', 'add', 'remove', 'add-container', 'remove-container' or 'take-from-gripper'.")
      .def_readwrite("time", &Intervention::time, "When it happens (s of world time from the start of the episode).")
      .def_readwrite("subject", &Intervention::subject, "The thing it concerns (the new thing's name for an add; unused by take-from-gripper).")
      .def_readwrite("cls", &Intervention::cls, "The class of an added thing.")
      .def_readwrite("location", &Intervention::location, "Where the thing goes (a region or container; '' if not given).")
      .def_readwrite("position", &Intervention::position, "[x, y, z] or None.")
      .def("__repr__", [](const Intervention& iv) {
        return std::string("<rtamp.Intervention ") + intervention_kind_name(iv.kind) + " " + iv.subject +
               (iv.location.empty() ? "" : " -> " + iv.location) + " at " + std::to_string(iv.time) + " s>";
      });

  py::class_<Scenario>(m, "Scenario",
                       "A workspace and its task: regions, containers, objects, robot, propositions, the LTL\n"
                       "task (text) and scripted interventions. Load with load_scenario(), parse_scenario()\n"
                       "or generate_scenario(); write with to_yaml(). List fields return copies.")
      .def_readwrite("name", &Scenario::name, "The scenario's name.")
      .def_readwrite("description", &Scenario::description, "A readable description.")
      .def_readwrite("regions", &Scenario::regions, "The regions (list of Region).")
      .def_readwrite("containers", &Scenario::containers, "The containers (list of Container).")
      .def_readwrite("objects", &Scenario::objects, "The objects (list of Object).")
      .def_readwrite("robot", &Scenario::robot, "The robot and where it stands.")
      .def_readonly("propositions", &Scenario::propositions, "The task's propositions (list of Proposition).")
      .def_property(
          "task", [](const Scenario& s) { return s.task; },
          [](Scenario& s, const std::string& task) {
            // A new text: errors in it are located in the text itself, not in the file it replaced.
            s.task = task;
            s.task_where = {};
            s.task_layout = {};
          },
          "The LTL task over proposition names, e.g. 'F G all_in_r2'.")
      .def_readwrite("interventions", &Scenario::interventions, "The scripted operator, sorted by time.")
      .def_property(
          "colours",
          [](const Scenario& s) {
            py::dict d;
            for (const ClassColour& c : s.colours) d[py::str(c.cls)] = py::make_tuple(c.rgb[0], c.rgb[1], c.rgb[2]);
            return d;
          },
          [](Scenario& s, const std::map<std::string, Vec3>& colours) {
            s.colours.clear();
            for (const auto& [cls, rgb] : colours) s.colours.push_back({cls, rgb, {}});
          },
          "The colours of classes, {class: (r, g, b)} with channels in [0, 1] (a copy; assign a dict to\n"
          "change them). Classes not listed take a palette colour by name (docs/scenario.md 'Colours').")
      .def_readonly("source", &Scenario::source, "The file it was loaded from ('' if generated).")
      .def("to_yaml", &to_yaml, "The scenario as YAML (parse_scenario() reads it back).")
      .def("validate", [](const Scenario& s) { validate(s); }, "Checks every invariant; raises rtamp.Error naming the first problem.")
      .def("copy", [](const Scenario& s) { return s; }, "A copy.")
      .def(py::pickle([](const Scenario& s) { return py::make_tuple(to_yaml(s), s.source); },
                      [](const py::tuple& t) {
                        Scenario s = parse_scenario(t[0].cast<std::string>(), t[1].cast<std::string>());
                        return s;
                      }))
      .def("__repr__", [](const Scenario& s) {
        return "<rtamp.Scenario '" + s.name + "': " + std::to_string(s.regions.size()) + " regions, " +
               std::to_string(s.containers.size()) + " containers, " + std::to_string(s.objects.size()) +
               " objects, task '" + s.task + "'>";
      });

  m.def("load_scenario", &load_scenario, py::arg("path_or_builtin"),
        "A built-in scenario by name ('3-block', '3-block-tray', ...: builtin_scenarios()) or a YAML\n"
        "file by path (write ./NAME to read a file named like a built-in). Errors are rtamp.Error\n"
        "with file, line and column.");
  m.def("parse_scenario", &parse_scenario, py::arg("yaml"), py::arg("source") = "<string>",
        "A scenario from YAML text (docs/scenario.md); `source` names it in error locations.");
  m.def("builtin_scenarios", &builtin_scenario_names, "Names of the built-in scenarios, sorted.");
  m.def("builtin_scenario_text",
        [](const std::string& name) -> py::object {
          auto t = builtin_scenario_text(name);
          if (!t) return py::none();
          return py::str(std::string(*t));
        },
        py::arg("name"), "The YAML text of a built-in scenario, or None.");
  m.def("initial_placement", &initial_placement, py::arg("scenario"),
        "Where every thing of the scenario starts (from its position: the region or container under it).");
  m.def("to_yaml", &to_yaml, py::arg("scenario"), "The scenario as YAML.");
  m.def("generate_scenario",
        [](int regions, int objects, int containers, const std::string& layout, std::uint64_t seed,
           const std::string& task, const std::vector<std::pair<std::string, std::string>>& propositions) {
          GeneratorOptions o;
          o.regions = regions;
          o.objects = objects;
          o.containers = containers;
          o.layout = parse_layout(layout);
          o.seed = seed;
          o.task = task;
          o.propositions = propositions;
          return generate_scenario(o);
        },
        py::kw_only(), py::arg("regions") = 2, py::arg("objects") = 3, py::arg("containers") = 0,
        py::arg("layout") = "line", py::arg("seed") = 1, py::arg("task") = "",
        py::arg("propositions") = std::vector<std::pair<std::string, std::string>>{},
        "A parametric scene, as `rtamp gen` writes it: regions r1..rM, objects o1..oN (4 cm blocks)\n"
        "in r1, trays t1..tC in rM, rM-1, ...; layout 'line' or 'random' (seeded, the same on every\n"
        "machine); proposition all_in_r2 plus `propositions` [(name, expression), ...]; task\n"
        "'F G all_in_r2' unless given.");

  py::class_<Placement::Thing>(m, "Thing", "Where one thing is: location, class, and whether it is a container.")
      .def(py::init([](std::string location, std::string cls, bool container) {
             return Placement::Thing{std::move(location), std::move(cls), container};
           }),
           py::arg("location"), py::arg("cls") = "block", py::arg("container") = false)
      .def_readwrite("location", &Placement::Thing::location, "Where the thing is: a region or container name ('none' if outside every location).")
      .def_readwrite("cls", &Placement::Thing::cls, "The thing's class.")
      .def_readwrite("container", &Placement::Thing::container, "True if the thing is a container.")
      .def("__eq__", [](const Placement::Thing& a, const Placement::Thing& b) { return a == b; })
      .def("__repr__", [](const Placement::Thing& t) {
        return "rtamp.Thing('" + t.location + "', '" + t.cls + "'" + (t.container ? ", container=True" : "") + ")";
      });

  py::class_<Placement>(m, "Placement",
                        "The symbolic state: where every movable thing is (a region, a container, 'hand' when\n"
                        "held, 'none' outside every location), with its class.")
      .def(py::init<>())
      .def_readwrite("things", &Placement::things, "{name: Thing} (a copy).")
      .def("set", &Placement::set, py::arg("name"), py::arg("location"), py::arg("cls") = "block",
           py::arg("container") = false, "Puts a thing somewhere.")
      .def("location_of",
           [](const Placement& p, const std::string& n) -> py::object {
             const std::string* l = p.location_of(n);
             return l ? py::object(py::str(*l)) : py::object(py::none());
           },
           py::arg("name"), "Where the thing is, or None.")
      .def("locations",
           [](const Placement& p) {
             std::map<std::string, std::string> out;
             for (const auto& [n, t] : p.things) out[n] = t.location;
             return out;
           },
           "{name: location}.")
      .def("__eq__", [](const Placement& a, const Placement& b) { return a == b; })
      .def("__len__", [](const Placement& p) { return p.things.size(); })
      .def("__repr__", [](const Placement& p) {
        std::string s = "rtamp.Placement({";
        bool first = true;
        for (const auto& [n, t] : p.things) {
          s += (first ? "'" : ", '") + n + "': '" + t.location + "'";
          first = false;
        }
        return s + "})";
      });
}

}  // namespace rtamp::python
