// Python bindings of the planning facade (paper Sections II-III.C, Algorithm 1
// lines 9-14): Planner(scenario, algorithm=..., cost=...), plan(), replanning
// after a change of the world, plans (prefix, cycle, cost, statistics, action
// tuples), and motion-cost models written in Python (CostModel, a trampoline
// over plan::MotionCostModel). plan() runs without the GIL; a Python cost
// model takes it for each call, from whatever thread the planner runs on (the
// reactive loop's worker thread, too).
#include "plan.hpp"

#include <map>

#include "choices.hpp"

#include "loop.hpp"
#include "plan_view.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/task/transition_system.hpp"

namespace rtamp::python {

using plan::MotionCostModel;
using plan::MotionQuery;

namespace {

// The Python override of `name`, or null; takes the GIL the caller must hold.
py::function override_of(const MotionCostModel* self, const char* name) {
  return py::get_override(self, name);
}

// What a CostModel method returned, as T; anything else is a TypeError naming the
// method, the type expected and the type returned (not pybind11's "Unable to cast").
template <class T>
T returned(const py::object& r, const char* method) {
  try {
    return r.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("CostModel.") + method + "() must return " +
                         py::detail::make_caster<T>::name.text + ", not " +
                         py::str(py::type::handle_of(r).attr("__name__")).cast<std::string>());
  }
}

// The trampoline: a MotionCostModel whose methods are a Python subclass's.
// Only cost() is required; the others have safe defaults (lower bound 0,
// depends on every query field, expensive: the planner caches its costs, no
// carry bound).
class PyCostModel : public MotionCostModel {
 public:
  using MotionCostModel::cost;
  std::string name() const override {
    py::gil_scoped_acquire gil;
    if (py::function f = override_of(this, "name")) return returned<std::string>(f(), "name");
    const MotionCostModel* base = this;
    py::handle self = py::detail::get_object_handle(base, py::detail::get_type_info(typeid(MotionCostModel)));
    return self ? py::str(self.get_type().attr("__name__")).cast<std::string>() : std::string("python");
  }
  double cost(const MotionQuery& q) const override {
    py::gil_scoped_acquire gil;
    if (py::function f = override_of(this, "cost")) return returned<double>(f(named(q)), "cost");
    throw Error("a CostModel subclass must define cost(query)");
  }
  double lower_bound(const MotionQuery& q, bool to_anywhere) const override {
    py::gil_scoped_acquire gil;
    if (py::function f = override_of(this, "lower_bound"))
      return returned<double>(f(named(q), to_anywhere), "lower_bound");
    return 0.0;
  }
  // The things of a scenario a Planner was built from with this model, so a
  // query names its thing (the planner's queries carry only its stable id).
  void learn_things(const world::Scenario& scenario) {
    const task::System ts(scenario);
    for (unsigned t = 0; t < ts.num_things(); ++t)
      things_[ts.thing_uid(t)] = {ts.thing_name(t), ts.thing_class(t)};
  }
  unsigned depends() const override {
    py::gil_scoped_acquire gil;
    if (py::function f = override_of(this, "depends")) return returned<unsigned>(f(), "depends");
    return plan::kDependsAll;
  }
  bool expensive() const override {
    py::gil_scoped_acquire gil;
    if (py::function f = override_of(this, "expensive")) return returned<bool>(f(), "expensive");
    return true;
  }
  double carry_bound(const world::Vec3& from, const world::Vec3& to) const override {
    py::gil_scoped_acquire gil;
    if (py::function f = override_of(this, "carry_bound")) return returned<double>(f(from, to), "carry_bound");
    return 0.0;
  }

 private:
  // The query as Python sees it: a copy with thing_name and thing_class (None
  // for a thing no scenario of this model's planners had, e.g. one a person added).
  py::object named(const MotionQuery& q) const {
    py::object o = py::cast(q);
    if (auto it = things_.find(q.thing); it != things_.end()) {
      o.attr("thing_name") = it->second.first;
      o.attr("thing_class") = it->second.second;
    }
    return o;
  }

  std::map<std::uint64_t, std::pair<std::string, std::string>> things_;  // uid -> (name, class); written with the GIL
};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

}  // namespace

// A model from the planner's registry (plan/registry.hpp): euclid, region, unit
// and ik (registered when the module is imported), with the registry's
// did-you-mean for an unknown name.
std::shared_ptr<MotionCostModel> builtin_cost_model(const std::string& name, const world::Scenario& scenario) {
  return plan::make_cost_model(name, scenario);
}

PlannerConfig planner_config(const world::Scenario& scenario, const std::string& algorithm, const py::object& cost,
                             const std::string& graph, bool symmetry, bool diagnose_capacity, double time_limit,
                             std::size_t max_nodes, std::size_t max_memory_bytes) {
  plan::PlannerOptions o;
  o.algorithm = plan::parse_algorithm(algorithm);
  o.graph = parse_name(plan::graph_constructions(), graph, "graph construction");
  o.symmetry = symmetry;
  o.diagnose_capacity = diagnose_capacity;
  o.limits.time_limit = time_limit;
  o.limits.max_nodes = max_nodes;
  o.limits.max_memory_bytes = max_memory_bytes;
  if (py::isinstance<py::str>(cost)) {
    const std::string name = cost.cast<std::string>();
    o.model = builtin_cost_model(name, scenario);
    o.cost = name;
    return PlannerConfig{std::move(o), PyRef()};
  }
  if (!py::isinstance<MotionCostModel>(cost))
    throw py::type_error("Planner(): argument 'cost' must be a cost-model name (str) or a CostModel, not " +
                         py::str(py::type::handle_of(cost).attr("__name__")).cast<std::string>());
  o.model = cost.cast<std::shared_ptr<MotionCostModel>>();
  if (auto* py_model = dynamic_cast<PyCostModel*>(o.model.get())) py_model->learn_things(scenario);
  o.cost = o.model->name();
  return PlannerConfig{std::move(o), PyRef(cost)};
}

PlanView make_view(plan::Planner& planner, const plan::PlanResult& r) {
  PlanView v;
  v.found = r.found;
  v.reason = r.found ? "none" : plan::to_string(r.reason);
  v.message = r.message;
  v.prefix_cost = r.plan.prefix_cost;
  v.cycle_cost = r.plan.cycle_cost;
  v.stats = r.stats;
  v.automaton_states = planner.automaton_states();
  if (!r.found) return v;
  const task::System& ts = planner.system();
  const auto& atoms = planner.automaton().atoms;
  auto steps = [&](const std::vector<plan::Step>& in, std::vector<StepView>& out) {
    for (const plan::Step& s : in) {
      StepView sv;
      sv.action = ts.action_name(s.action);
      if (!s.action.is_stay()) {
        sv.thing = ts.thing_name(s.action.thing);
        sv.to = ts.location_name(s.action.to);
      }
      sv.from_state = ts.to_string(s.from);
      sv.to_state = ts.to_string(s.to);
      sv.ba_from = s.ba_from;
      sv.ba_to = s.ba_to;
      sv.cost = s.cost;
      for (std::size_t i = 0; i < atoms.size(); ++i)
        if (s.label >> i & 1) sv.label.push_back(atoms[i]);
      sv.packed = s.action.packed();
      out.push_back(std::move(sv));
    }
  };
  steps(r.plan.prefix, v.prefix);
  steps(r.plan.cycle, v.cycle);
  v.actions = planner.action_tuples(r.plan);
  return v;
}

PyPlanner::PyPlanner(world::Scenario scenario, PlannerConfig config) : model_ref_(std::move(config.model_ref)) {
  py::gil_scoped_release release;
  planner_ = std::make_unique<plan::Planner>(std::move(scenario), std::move(config.options));
}

PyPlanner::~PyPlanner() = default;

PlanView PyPlanner::plan() {
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(mutex_);
  plan::PlanResult r = planner_->plan();
  return make_view(*planner_, r);
}

void bind_plan(py::module_& m) {
  py::class_<MotionQuery> query(m, "MotionQuery",
                                "What a motion cost may depend on: the moved thing (stable id, container or not;\n"
                                "thing_name and thing_class name it when the Planner's scenario has it), the hand's\n"
                                "point before the move, the thing's point and the destination's point\n"
                                "([x, y, z] metres; points are location centres).",
                                py::dynamic_attr());
  query.attr("thing_name") = py::none();   // set on the queries a planner passes to a CostModel
  query.attr("thing_class") = py::none();
  query.def(py::init<>())
      .def_readwrite("thing", &MotionQuery::thing, "Stable id of the moved thing.")
      .def_readwrite("container", &MotionQuery::container, "The moved thing is a container.")
      .def_readwrite("hand", &MotionQuery::hand, "The hand's point before the move.")
      .def_readwrite("from_", &MotionQuery::from, "The thing's point.")
      .def_readwrite("to", &MotionQuery::to, "The destination's point.");

  py::class_<MotionCostModel, PyCostModel, std::shared_ptr<MotionCostModel>>(
      m, "CostModel",
      "A motion-cost model (the edge weight w of the paper's Section III.B). Subclass it in Python:\n\n"
      "    class Manhattan(rtamp.CostModel):\n"
      "        def cost(self, q):            # required: >= 0 (inf: the move is impossible)\n"
      "            return sum(abs(a - b) for a, b in zip(q.from_, q.to))\n"
      "        def lower_bound(self, q, to_anywhere):  # optional, default 0 (always admissible)\n"
      "            return 0.0\n"
      "        def depends(self):            # optional: DEPENDS_* bits the cost reads (default all)\n"
      "            return rtamp.DEPENDS_FROM | rtamp.DEPENDS_TO\n"
      "        def expensive(self):          # optional: cache the costs (default True)\n"
      "            return True\n\n"
      "lower_bound must bound from below the cost of any move sequence that picks the thing at\n"
      "q.from_ and brings it to q.to (consistent, for the A* searches to stay optimal).\n"
      "The planner checks every value: a NaN or negative cost, or a NaN, infinite or negative\n"
      "bound, makes plan() raise rtamp.Error naming the model, the move and the value.\n"
      "The planner may call these from a worker thread; each call takes the GIL.")
      .def(py::init<>())
      .def("name", &MotionCostModel::name, "The model's name (default: the class name).")
      .def("cost", py::overload_cast<const MotionQuery&>(&MotionCostModel::cost, py::const_), py::arg("query"),
           "Cost of the move described by the query (>= 0).")
      .def("lower_bound", &MotionCostModel::lower_bound, py::arg("query"), py::arg("to_anywhere"),
           "A lower bound on the cost of bringing the thing to q.to (to_anywhere: destination unknown).")
      .def("depends", &MotionCostModel::depends, "DEPENDS_* bits: which query fields cost() reads.")
      .def("expensive", &MotionCostModel::expensive, "True: the planner caches this model's costs.");

  m.def("cost_model", &builtin_cost_model, py::arg("name"), py::arg("scenario") = world::Scenario{},
        "A built-in motion-cost model: 'euclid' (hand to thing plus thing to destination), 'region'\n"
        "(centre to centre), 'unit' (1 per move) or 'ik' (UR5 tool path from inverse kinematics).");
  m.attr("DEPENDS_THING") = static_cast<unsigned>(plan::kDependsThing);
  m.attr("DEPENDS_HAND") = static_cast<unsigned>(plan::kDependsHand);
  m.attr("DEPENDS_FROM") = static_cast<unsigned>(plan::kDependsFrom);
  m.attr("DEPENDS_TO") = static_cast<unsigned>(plan::kDependsTo);
  m.attr("DEPENDS_ALL") = static_cast<unsigned>(plan::kDependsAll);
  robot::register_ik_cost_model();  // rtamp's own registry only: nothing outside rtamp changes
  m.def("algorithms", [] {
    py::dict d;  // insertion order: the paper's Table I order
    for (const auto& a : plan::algorithms()) d[py::str(a.name)] = py::str(a.description);
    return d;
  }, "The search algorithms from the planner's registry, name -> one-line description:\n"
     "'astar-exp' (A* with experience, the default), 'astar', 'dijkstra'.");
  m.def("cost_models", [] {
    py::dict d;
    for (const auto& c : plan::cost_models()) d[py::str(c.name)] = py::str(c.description);
    return d;
  }, "The motion-cost models from the planner's registry, name -> one-line description\n"
     "(euclid, region, unit, ik).");

  py::class_<plan::SearchStats>(m, "SearchStats", "What one planning query did.")
      .def_readonly("generated", &plan::SearchStats::generated, "Product nodes created during the query.")
      .def_readonly("expanded", &plan::SearchStats::expanded, "Node expansions (prefix and cycle searches).")
      .def_readonly("successor_generations", &plan::SearchStats::successor_generations, "Expansions that had to compute their successors.")
      .def_readonly("cycle_searches", &plan::SearchStats::cycle_searches, "Cycle searches run (misses of the cycle table).")
      .def_readonly("diagnosis_nodes", &plan::SearchStats::diagnosis_nodes, "Capacity diagnosis: capacity-free product nodes explored.")
      .def_readonly("diagnosis_seconds", &plan::SearchStats::diagnosis_seconds, "Capacity diagnosis: its wall time (0 if it did not run).")
      .def_readonly("graph_nodes", &plan::SearchStats::graph_nodes, "Nodes of the product graph after the query.")
      .def_readonly("graph_edges", &plan::SearchStats::graph_edges, "Edges of the product graph after the query.")
      .def_readonly("cache_used", &plan::SearchStats::cache_used, "The motion-cost cache was consulted (astar-exp with an expensive model).")
      .def_readonly("cache_hits", &plan::SearchStats::cache_hits, "Motion costs found in the cache.")
      .def_readonly("cache_misses", &plan::SearchStats::cache_misses, "Motion costs computed by the cost model.")
      .def_readonly("reused_nodes", &plan::SearchStats::reused_nodes, "Nodes already in the graph (experience).")
      .def_readonly("reused_path_edges", &plan::SearchStats::reused_path_edges, "Plan edges taken from an earlier optimal plan (astar-exp).")
      .def_readonly("memory_bytes", &plan::SearchStats::memory_bytes, "Bytes of product graph, search arrays and cache after the query.")
      .def_readonly("construction_seconds", &plan::SearchStats::construction_seconds, "Wall time (s) of the full construction before the search (graph 'full').")
      .def_readonly("seconds", &plan::SearchStats::seconds, "Wall time of the whole query.")
      .def_readonly("hit_node_limit", &plan::SearchStats::hit_node_limit, "The search stopped at its node limit.")
      .def_readonly("hit_time_limit", &plan::SearchStats::hit_time_limit, "The search stopped at its time limit.")
      .def_readonly("hit_memory_limit", &plan::SearchStats::hit_memory_limit, "The search stopped at its memory limit.")
      .def("__repr__", [](const plan::SearchStats& s) {
        return "<rtamp.SearchStats expanded=" + std::to_string(s.expanded) + " graph_nodes=" +
               std::to_string(s.graph_nodes) + " seconds=" + std::to_string(s.seconds) + ">";
      });

  py::class_<plan::Condition>(m, "Condition", "thing is at location (a state or action condition).")
      .def_readonly("thing", &plan::Condition::thing, "The thing (object or container).")
      .def_readonly("location", &plan::Condition::location, "The region or container it is in.")
      .def("__repr__", [](const plan::Condition& c) { return c.thing + "@" + c.location; });

  py::class_<plan::ActionTuple>(m, "ActionTuple",
                                "One move of a plan as the behavior tree gets it (paper Section III.D): the\n"
                                "action, its thing, source and destination, the full state before/after (pre,\n"
                                "post) and the relaxed action conditions, the hand before/after, its cost.")
      .def_readonly("action", &plan::ActionTuple::action, "'move(o1, r2)'")
      .def_readonly("thing", &plan::ActionTuple::thing, "The thing moved.")
      .def_readonly("from_", &plan::ActionTuple::from, "Where the thing is taken from.")
      .def_readonly("to", &plan::ActionTuple::to, "Where the thing goes.")
      .def_readonly("pre", &plan::ActionTuple::pre, "The full state before the move: one Condition per thing (the state condition).")
      .def_readonly("post", &plan::ActionTuple::post, "The full state after the move.")
      .def_readonly("relaxed_pre", &plan::ActionTuple::relaxed_pre, "The action condition: the thing at its source (and where a container involved stands).")
      .def_readonly("relaxed_post", &plan::ActionTuple::relaxed_post, "The thing at its destination.")
      .def_readonly("hand_before", &plan::ActionTuple::hand_before, "Where the hand is before the move ('home' before the first).")
      .def_readonly("hand_after", &plan::ActionTuple::hand_after, "Where the hand is after the move.")
      .def_readonly("cost", &plan::ActionTuple::cost, "The move's motion cost.")
      .def_readonly("in_cycle", &plan::ActionTuple::in_cycle, "The move belongs to the plan's cycle.")
      .def("__repr__", [](const plan::ActionTuple& a) { return "<rtamp.ActionTuple " + a.action + ">"; });

  py::class_<StepView>(m, "Step",
                       "One step of a lasso plan: the action, the TS states before and after, the Büchi\n"
                       "states, the motion cost and the label (atoms true in the state it leaves).")
      .def_readonly("action", &StepView::action, "'move(o1, r2)' or 'stay'.")
      .def_readonly("thing", &StepView::thing, "The moved thing ('' for stay).")
      .def_readonly("to", &StepView::to, "The destination ('' for stay).")
      .def_readonly("from_state", &StepView::from_state, "'o1@r1 o2@r1 r3@r1 hand@home'")
      .def_readonly("to_state", &StepView::to_state, "The TS state after the step, e.g. 'o1@r2 o2@r1 r3@r1 hand@r2'.")
      .def_readonly("ba_from", &StepView::ba_from, "Büchi state before.")
      .def_readonly("ba_to", &StepView::ba_to, "Büchi state after.")
      .def_readonly("cost", &StepView::cost, "The step's motion cost.")
      .def_readonly("label", &StepView::label, "Atoms true in the state the step leaves.")
      .def("__repr__", [](const StepView& s) { return "<rtamp.Step " + s.action + " cost=" + std::to_string(s.cost) + ">"; });

  py::class_<PlanView>(m, "Plan",
                       "A planning result. found: a lasso exists; then prefix (steps to the cycle),\n"
                       "cycle (repeated forever), prefix_cost + cycle_cost = cost, actions (the moves as\n"
                       "ActionTuples for the behavior tree), stats. Otherwise reason ('unsatisfiable',\n"
                       "'no-accepting-cycle', 'capacity', 'unknown-name', 'node-limit', 'time-limit',\n"
                       "'memory-limit') and message. bool(plan) is plan.found.")
      .def_readonly("found", &PlanView::found, "A lasso plan exists.")
      .def_readonly("reason", &PlanView::reason, "Why none was found: 'unsatisfiable', 'no-accepting-cycle', 'capacity', 'unknown-name', 'node-limit', 'time-limit' or 'memory-limit' ('' if found).")
      .def_readonly("message", &PlanView::message, "A readable explanation when no plan was found.")
      .def_readonly("prefix", &PlanView::prefix, "The steps from the start to the cycle (list of Step).")
      .def_readonly("cycle", &PlanView::cycle, "The steps repeated forever (list of Step).")
      .def_readonly("prefix_cost", &PlanView::prefix_cost, "Motion cost of the prefix.")
      .def_readonly("cycle_cost", &PlanView::cycle_cost, "Motion cost of one turn of the cycle.")
      .def_property_readonly("cost", [](const PlanView& v) { return v.prefix_cost + v.cycle_cost; },
                             "prefix_cost + cycle_cost.")
      .def_readonly("actions", &PlanView::actions, "The moves as ActionTuples, prefix first (what the behavior tree executes).")
      .def_readonly("stats", &PlanView::stats, "What the query did (SearchStats).")
      .def_readonly("automaton_states", &PlanView::automaton_states, "The Büchi states it started from.")
      .def_property_readonly("moves", [](const PlanView& v) {
        std::vector<std::string> out;
        for (const auto& s : v.prefix) if (s.action != "stay") out.push_back(s.action);
        for (const auto& s : v.cycle) if (s.action != "stay") out.push_back(s.action);
        return out;
      }, "The names of the moves, prefix first, then the cycle's.")
      .def("__bool__", [](const PlanView& v) { return v.found; })
      .def("__repr__", [](const PlanView& v) {
        if (!v.found) return "<rtamp.Plan not found: " + v.reason + ">";
        std::vector<std::string> mv;
        for (const auto& a : v.actions) mv.push_back(a.action);
        return "<rtamp.Plan cost=" + std::to_string(v.prefix_cost + v.cycle_cost) + " " + join(mv) + ">";
      });

  py::class_<PyPlanner>(m, "Planner",
                        "The planning front door (OMPL SimpleSetup style):\n\n"
                        "    p = rtamp.Planner(rtamp.load_scenario('3-block-tray'))\n"
                        "    plan = p.plan()                     # cheapest lasso from the current state\n"
                        "    p.apply('move o2 r1')               # a person moved o2 back\n"
                        "    plan2 = p.plan()                    # replan (astar-exp reuses experience)\n\n"
                        "algorithm: 'astar-exp' (default), 'astar', 'dijkstra'. cost: 'euclid' (default),\n"
                        "'region', 'unit', 'ik' or a CostModel instance. graph: 'partial' or 'full'.\n"
                        "Limits of each query: time_limit (s), max_nodes (product nodes), max_memory_bytes\n"
                        "(the planner's own estimate of what it holds; default 4 GiB, 0: none).\n"
                        "Raises rtamp.Error on a bad task or option, and from plan() when a cost model\n"
                        "returns a NaN or negative cost or a NaN, infinite or negative bound.")
      .def(py::init([](const world::Scenario& s, const std::string& algorithm, const py::object& cost,
                       const std::string& graph, bool symmetry, bool diagnose_capacity, double time_limit,
                       std::size_t max_nodes, std::size_t max_memory_bytes) {
             return std::make_unique<PyPlanner>(s, planner_config(s, algorithm, cost, graph, symmetry,
                                                                  diagnose_capacity, time_limit, max_nodes,
                                                                  max_memory_bytes));
           }),
           py::arg("scenario"), py::kw_only(), py::arg("algorithm") = "astar-exp", py::arg("cost") = "euclid",
           py::arg("graph") = "partial", py::arg("symmetry") = true, py::arg("diagnose_capacity") = true,
           py::arg("time_limit") = 60.0, py::arg("max_nodes") = std::size_t{20'000'000},
           py::arg("max_memory_bytes") = plan::SearchLimits{}.max_memory_bytes)
      .def("plan", &PyPlanner::plan,
           "The cheapest lasso plan from the current state and automaton states (the GIL is\n"
           "released while it searches).")
      .def("apply",
           [](PyPlanner& p, const py::object& c, bool observed) {
             const world::Change ch =
                 py::isinstance<py::str>(c) ? world::Change::parse(c.cast<std::string>()) : c.cast<world::Change>();
             p.locked([&](plan::Planner& pl) {
               pl.apply(ch, observed ? plan::Planner::ChangeOrigin::Observed : plan::Planner::ChangeOrigin::Proposed);
             });
           },
           py::arg("change"), py::kw_only(), py::arg("observed") = false,
           "Applies a change of the world (a Change, e.g. an Intervention, or its text, e.g. 'move o1 r2').\n"
           "It must keep the rules of space (capacity, fit, room) — rtamp.Error naming the word otherwise —\n"
           "unless observed=True: what a world showed has happened is taken as it is.")
      .def("execute",
           [](PyPlanner& p, const StepView& s) {
             p.locked([&](plan::Planner& pl) { pl.execute(task::Action::unpack(s.packed)); });
           },
           py::arg("step"), "The robot executed this plan step: the state advances, experience is kept.")
      .def("set_placement",
           [](PyPlanner& p, const py::object& placement, const std::string& hand) {
             world::Placement pl = to_placement(placement, class_table(p.raw().scenario()));
             p.locked([&](plan::Planner& x) { x.set_placement(std::move(pl), hand); });
           },
           py::arg("placement"), py::arg("hand") = "",
           "Replaces the current state: a Placement or {thing: location} (hand: where the hand is).")
      .def("set_automaton_states",
           [](PyPlanner& p, std::vector<std::uint32_t> s) {
             p.locked([&](plan::Planner& x) { x.set_automaton_states(std::move(s)); });
           },
           py::arg("states"), "The Büchi states plan() starts from (default: the initial state).")
      .def_property_readonly("automaton_states", [](PyPlanner& p) { return p.raw().automaton_states(); },
                             "The Büchi states the next plan starts from.")
      .def("forbid_move",
           [](PyPlanner& p, const std::string& t, const std::string& l) {
             p.locked([&](plan::Planner& x) { x.forbid_move(t, l); });
           },
           py::arg("thing"), py::arg("location"), "move(thing, location) is in no plan until clear_forbidden_moves().")
      .def("clear_forbidden_moves", [](PyPlanner& p) { p.locked([](plan::Planner& x) { x.clear_forbidden_moves(); }); },
           "Allows every move forbid_move() forbade again.")
      .def_property_readonly("forbidden_moves", [](PyPlanner& p) { return p.raw().forbidden_moves(); },
                             "The moves forbid_move() forbade (until the world changes).")
      .def_property_readonly("scenario", [](PyPlanner& p) { return p.raw().scenario(); }, "A copy of the scenario.")
      .def_property_readonly("automaton", [](PyPlanner& p) { return p.raw().automaton(); },
                             "The task's Büchi automaton (a copy).")
      .def_property_readonly("formula", [](PyPlanner& p) -> py::object {
        const auto& f = p.raw().formula();
        if (f.is_null()) return py::none();
        return py::cast(f);
      }, "The task formula.")
      .def_property_readonly("placement", [](PyPlanner& p) { return p.raw().placement(); }, "The current state.")
      .def_property_readonly("hand", [](PyPlanner& p) { return p.raw().hand(); }, "Where the hand is ('' = home).")
      .def_property_readonly("state", [](PyPlanner& p) {
        std::string s;
        p.locked([&](plan::Planner& x) { s = x.system().to_string(x.state()); });
        return s;
      }, "The current TS state as text: 'o1@r1 o2@r1 r3@r1 hand@home'.")
      .def_property_readonly("algorithm", [](PyPlanner& p) { return std::string(plan::algorithm_info(p.raw().options().algorithm).name); },
                             "The search algorithm's name.")
      .def_property_readonly("cost_model", [](PyPlanner& p) { return p.raw().options().cost; },
                             "The motion-cost model's name.");
}

}  // namespace rtamp::python
