// Python bindings of the behavior-tree engine (paper Section III.D; bt/):
// trees are built from node specifications (rtamp.bt.Sequence(...),
// Action(name, on_start, ...), ...: python/rtamp/bt.py) that C++ turns into
// bt::Node objects owned by the tree; the tree then is ticked, halted, changed
// (insert / append / remove / replace by node id, as Algorithm 2 does) and
// exported (text, BehaviorTree.CPP XML, DOT) or imported from BehaviorTree.CPP v4
// XML (Tree.from_xml / Tree.load_xml: bt/xml_import.hpp; the file's custom node IDs
// come from Python: per-ID callables or factories). Leaves are Python callables
// (no arguments): actions return a Status (or 'SUCCESS' / 'RUNNING' /
// 'FAILURE'), conditions a bool. Python exceptions in leaves propagate out of
// tick(). Node ids are the handles Python holds: stable, never reused.
#include <chrono>
#include <tuple>

#include "bindings.hpp"
#include "rtamp/bt/bt.hpp"
#include "rtamp/bt/xml_import.hpp"

namespace rtamp::python {

namespace {

using bt::Node;
using bt::Status;

Status as_bt_status(const py::handle& r) {
  if (py::isinstance<Status>(r)) return r.cast<Status>();
  if (py::isinstance<py::str>(r)) {
    const std::string s = r.cast<std::string>();
    if (s == "SUCCESS" || s == "success") return Status::Success;
    if (s == "FAILURE" || s == "failure") return Status::Failure;
    if (s == "RUNNING" || s == "running") return Status::Running;
  }
  if (py::isinstance<py::bool_>(r)) return r.cast<bool>() ? Status::Success : Status::Failure;
  throw Error("a behavior-tree action must return rtamp.Status.SUCCESS, RUNNING or FAILURE (got " +
              py::repr(r).cast<std::string>() + ")");
}

bt::Action::Tick tick_of(const py::object& f) {
  if (f.is_none()) return {};
  auto ref = std::make_shared<PyRef>(f);
  return [ref](Node&) {
    py::gil_scoped_acquire gil;
    return as_bt_status(ref->get()());
  };
}

std::string str_attr(const py::handle& spec, const char* name, const std::string& fallback = {}) {
  if (!py::hasattr(spec, name)) return fallback;
  py::object v = spec.attr(name);
  return v.is_none() ? fallback : v.cast<std::string>();
}

// A bt::Node from a spec: an object with `kind`, `name`, `children` and the
// kind's parameters (python/rtamp/bt.py defines them).
std::unique_ptr<Node> build(const py::handle& spec) {
  const std::string kind = str_attr(spec, "kind");
  const std::string name = str_attr(spec, "name", kind);
  std::unique_ptr<Node> node;
  if (kind == "Sequence") node = std::make_unique<bt::Sequence>(name);
  else if (kind == "Fallback") node = std::make_unique<bt::Fallback>(name);
  else if (kind == "ReactiveSequence") node = std::make_unique<bt::ReactiveSequence>(name);
  else if (kind == "ReactiveFallback") node = std::make_unique<bt::ReactiveFallback>(name);
  else if (kind == "Chooser") node = std::make_unique<bt::Chooser>(name);
  else if (kind == "Parallel")
    node = std::make_unique<bt::Parallel>(name, spec.attr("success_count").cast<int>(),
                                          spec.attr("failure_count").cast<int>());
  else if (kind == "Inverter") node = std::make_unique<bt::Inverter>(name);
  else if (kind == "Retry") node = std::make_unique<bt::Retry>(name, spec.attr("num_attempts").cast<int>());
  else if (kind == "Timeout")
    node = std::make_unique<bt::Timeout>(
        name, std::chrono::duration_cast<bt::Duration>(std::chrono::duration<double>(spec.attr("seconds").cast<double>())));
  else if (kind == "Action") {
    bt::Action::Callbacks cb;
    cb.on_start = tick_of(spec.attr("on_start"));
    if (!cb.on_start) throw Error("an Action needs on_start");
    cb.on_running = tick_of(spec.attr("on_running"));
    py::object halted = spec.attr("on_halted");
    if (!halted.is_none()) {
      auto ref = std::make_shared<PyRef>(halted);
      cb.on_halted = [ref](Node&) {
        py::gil_scoped_acquire gil;
        ref->get()();
      };
    }
    node = std::make_unique<bt::Action>(name, std::move(cb), str_attr(spec, "type_id", "UserAction"));
  } else if (kind == "Condition") {
    auto ref = std::make_shared<PyRef>(py::reinterpret_borrow<py::object>(spec.attr("predicate")));
    node = std::make_unique<bt::Condition>(name, bt::Condition::Predicate([ref](Node&) {
      py::gil_scoped_acquire gil;
      return py::bool_(ref->get()()).cast<bool>();
    }), str_attr(spec, "type_id", "UserCondition"));
  } else {
    throw Error("unknown behavior-tree node kind '" + kind + "'");
  }
  if (py::hasattr(spec, "ports"))
    for (auto [k, v] : py::reinterpret_borrow<py::dict>(spec.attr("ports")))
      node->set_port(py::str(k).cast<std::string>(), py::str(v).cast<std::string>());
  if (py::hasattr(spec, "interruptible")) node->set_interruptible(spec.attr("interruptible").cast<bool>());
  const py::list children = spec.attr("children");
  if (auto* c = dynamic_cast<bt::Composite*>(node.get())) {
    for (const auto& ch : children) c->add(build(ch));
  } else if (auto* d = dynamic_cast<bt::Decorator*>(node.get())) {
    if (children.size() != 1) throw Error(kind + " '" + name + "' needs exactly one child");
    d->set_child(build(children[0]));
  } else if (!children.empty()) {
    throw Error(kind + " '" + name + "' is a leaf: it takes no children");
  }
  return node;
}

// A tree and its clock: the steady clock, or a manual one that Python advances.
struct PyTree {
  std::shared_ptr<bt::ManualClock> manual;
  std::unique_ptr<bt::Tree> tree;
};

py::dict node_info(const Node& n) {
  py::dict d;
  d["id"] = n.id();
  d["name"] = n.name();
  d["kind"] = std::string(bt::to_string(n.kind()));
  d["type_id"] = std::string(n.type_id());
  d["status"] = n.status();
  py::list kids;
  for (const Node* c : n.children()) kids.append(c->id());
  d["children"] = kids;
  d["parent"] = n.parent() ? py::object(py::int_(n.parent()->id())) : py::object(py::none());
  py::dict ports;
  std::vector<bt::Port> all;
  n.collect_ports(all);
  for (const auto& p : all) ports[py::str(p.name)] = p.value;
  d["ports"] = ports;
  d["interruptible"] = n.interruptible();
  return d;
}

bt::Cut cut_of(bool force) { return force ? bt::Cut::Force : bt::Cut::IfInterruptible; }

std::unique_ptr<PyTree> make_tree(const std::string& clock) {
  auto t = std::make_unique<PyTree>();
  if (clock == "manual") {
    t->manual = std::make_shared<bt::ManualClock>();
    t->tree = std::make_unique<bt::Tree>(std::make_shared<bt::Blackboard>(), t->manual);
  } else if (clock == "steady") {
    t->tree = std::make_unique<bt::Tree>();
  } else {
    throw Error("unknown clock '" + clock + "' (expected steady or manual)");
  }
  return t;
}

// The importer's registry from Python: `nodes` maps a type ID to factory(name, ports)
// returning a node spec; `actions` a type ID to the on_start callable of every action of
// that ID; `conditions` a type ID to the predicate of every condition of that ID (for the
// IDs UserAction and UserCondition, of the Python leaves without a type_id: by node name).
bt::NodeRegistry registry_of(const py::dict& nodes, const py::dict& actions, const py::dict& conditions) {
  bt::NodeRegistry r;
  for (auto [k, v] : nodes) {
    auto ref = std::make_shared<PyRef>(py::reinterpret_borrow<py::object>(v));
    r.add(k.cast<std::string>(), [ref](const bt::NodeSpec& spec) {
      py::gil_scoped_acquire gil;
      py::dict ports;
      for (const auto& p : spec.ports) ports[py::str(p.name)] = p.value;
      const py::object made = ref->get()(spec.name, ports);
      if (py::hasattr(made, "children") && py::len(made.attr("children")) != 0)
        throw Error("the factory of '" + spec.type_id + "' returned a node with children (they come from the file)",
                    spec.where);
      return build(made);
    });
  }
  // A leaf written in Python without a type_id is exported as UserAction / UserCondition:
  // reading it back, its callable is looked up by the node's name in actions / conditions.
  for (const auto& [id, table, spec] : {std::tuple{"UserAction", actions, "Action"},
                                        std::tuple{"UserCondition", conditions, "Condition"}}) {
    if (nodes.contains(id) || table.contains(id)) continue;
    auto ref = std::make_shared<PyRef>(table);  // dropped with the GIL, whichever thread drops the registry
    r.add(id, [id = std::string(id), ref, spec = std::string(spec)](const bt::NodeSpec& n) {
      py::gil_scoped_acquire gil;
      const py::dict callables = ref->get();
      if (!callables.contains(n.name))
        throw Error("no callable for " + id + " '" + n.name + "': pass " +
                        (spec == "Action" ? "actions" : "conditions") + "={'" + n.name + "': ...} (by node name)",
                    n.where);
      return build(py::module_::import("rtamp.bt").attr(spec.c_str())(n.name, callables[py::str(n.name)]));
    });
  }
  for (auto [k, v] : actions) r.add_action(k.cast<std::string>(), {tick_of(py::reinterpret_borrow<py::object>(v)), {}, {}});
  for (auto [k, v] : conditions) {
    auto ref = std::make_shared<PyRef>(py::reinterpret_borrow<py::object>(v));
    r.add_condition(k.cast<std::string>(), [ref](Node&) {
      py::gil_scoped_acquire gil;
      return py::bool_(ref->get()()).cast<bool>();
    });
  }
  return r;
}

constexpr const char* kImportDoc =
    "Builds a tree from BehaviorTree.CPP v4 XML (a file drawn in Groot2, or one written by\n"
    "to_xml()): the engine's own node kinds are built directly; every other node ID must be\n"
    "given: nodes={ID: factory(name, ports) -> node spec without children}, actions={ID:\n"
    "on_start callable}, conditions={ID: predicate}; a UserAction / UserCondition (what to_xml()\n"
    "writes for a leaf built without type_id) is looked up by its node name in actions /\n"
    "conditions, so a tree reads back from its own XML. tree_id picks a <BehaviorTree ID>\n"
    "(default: main_tree_to_execute, or the only tree); file labels error locations. Errors\n"
    "(malformed XML, unknown IDs, bad parameters) raise rtamp.Error with file, line and column.";

}  // namespace

void bind_bt(py::module_& m) {
  py::enum_<Status>(m, "Status", "A behavior-tree node's status (py_trees / BehaviorTree.CPP meaning).")
      .value("INVALID", Status::Invalid)
      .value("RUNNING", Status::Running)
      .value("SUCCESS", Status::Success)
      .value("FAILURE", Status::Failure);

  py::class_<PyTree>(m, "Tree",
                     "A behavior tree built from node specs (rtamp.bt): tick, halt, change between ticks,\n"
                     "export. Nodes are named by id (stable, never reused). clock='manual' gives a clock\n"
                     "that only advance_clock() moves (for Timeout); default 'steady' (wall time).")
      .def(py::init([](const py::object& root, const std::string& clock) {
             auto t = make_tree(clock);
             if (!root.is_none()) t->tree->set_root(build(root));
             return t;
           }),
           py::arg("root") = py::none(), py::kw_only(), py::arg("clock") = "steady")
      .def_static("from_xml", [](const std::string& xml, const py::dict& nodes, const py::dict& actions,
                                 const py::dict& conditions, const std::string& tree_id, const std::string& file,
                                 const std::string& clock) {
        auto t = make_tree(clock);
        bt::XmlImportOptions o;
        o.tree_id = tree_id;
        o.file = file;
        auto root = bt::from_btcpp_xml(xml, registry_of(nodes, actions, conditions), o);
        if (root) t->tree->set_root(std::move(root));
        return t;
      }, py::arg("xml"), py::kw_only(), py::arg("nodes") = py::dict(), py::arg("actions") = py::dict(),
         py::arg("conditions") = py::dict(), py::arg("tree_id") = "", py::arg("file") = "",
         py::arg("clock") = "steady", kImportDoc)
      .def_static("load_xml", [](const std::string& path, const py::dict& nodes, const py::dict& actions,
                                 const py::dict& conditions, const std::string& tree_id, const std::string& clock) {
        auto t = make_tree(clock);
        bt::XmlImportOptions o;
        o.tree_id = tree_id;
        auto root = bt::load_btcpp_xml(path, registry_of(nodes, actions, conditions), o);
        if (root) t->tree->set_root(std::move(root));
        return t;
      }, py::arg("path"), py::kw_only(), py::arg("nodes") = py::dict(), py::arg("actions") = py::dict(),
         py::arg("conditions") = py::dict(), py::arg("tree_id") = "", py::arg("clock") = "steady",
         "Tree.from_xml on the file at `path` (errors name that file).")
      .def("set_root", [](PyTree& t, const py::object& spec) { return t.tree->set_root(build(spec)); },
           py::arg("spec"), "Installs a new root (the old tree is halted and dropped); returns its id.")
      .def_property_readonly("root", [](PyTree& t) -> py::object {
        return t.tree->root() ? py::object(py::int_(t.tree->root()->id())) : py::object(py::none());
      }, "The root's id, or None.")
      .def("tick", [](PyTree& t) { return t.tree->tick(); }, "Ticks the root once; returns its status.")
      .def("halt", [](PyTree& t) { t.tree->halt(); }, "Halts every node (running actions get on_halted).")
      .def_property_readonly("status", [](PyTree& t) { return t.tree->status(); }, "The root's status after the last tick.")
      .def_property_readonly("tick_count", [](PyTree& t) { return t.tree->tick_count(); }, "Ticks so far.")
      .def_property_readonly("change_count", [](PyTree& t) { return t.tree->change_count(); },
                             "Structural changes so far (inserts, removals, replacements).")
      .def("__len__", [](PyTree& t) { return t.tree->size(); })
      .def("find", [](PyTree& t, const std::string& name) -> py::object {
        Node* n = t.tree->find_by_name(name);
        return n ? py::object(py::int_(n->id())) : py::object(py::none());
      }, py::arg("name"), "The id of the first node (pre-order) of that name, or None.")
      .def("node", [](PyTree& t, bt::NodeId id) { return node_info(t.tree->at(id)); }, py::arg("id"),
           "A node as a dict: id, name, kind, type_id, status, children (ids), parent, ports, interruptible.")
      .def("nodes", [](PyTree& t) {
        py::list out;
        t.tree->for_each([&](const Node& n, int) { out.append(node_info(n)); });
        return out;
      }, "Every node (pre-order) as node() dicts.")
      .def("insert", [](PyTree& t, bt::NodeId parent, std::size_t pos, const py::object& spec) {
        return t.tree->insert(parent, pos, build(spec));
      }, py::arg("parent"), py::arg("position"), py::arg("spec"),
         "Inserts a subtree as child `position` of the composite `parent`; returns its id.")
      .def("append", [](PyTree& t, bt::NodeId parent, const py::object& spec) {
        return t.tree->append(parent, build(spec));
      }, py::arg("parent"), py::arg("spec"), "Appends a subtree to a composite; returns its id.")
      .def("remove", [](PyTree& t, bt::NodeId id, bool force) { t.tree->remove(id, cut_of(force)); },
           py::arg("id"), py::kw_only(), py::arg("force") = false,
           "Removes (halts and drops) a subtree; raises rtamp.Error if it runs a non-interruptible node\n"
           "unless force=True.")
      .def("replace", [](PyTree& t, bt::NodeId id, const py::object& spec, bool force) {
        return t.tree->replace(id, build(spec), cut_of(force));
      }, py::arg("id"), py::arg("spec"), py::kw_only(), py::arg("force") = false,
         "Puts a new subtree where `id` is; returns the new id.")
      .def("can_cut", [](PyTree& t, bt::NodeId id) { return t.tree->can_cut(id); }, py::arg("id"),
           "True if the subtree at `id` runs no non-interruptible node (remove() would succeed).")
      .def("set_port", [](PyTree& t, bt::NodeId id, std::string name, std::string value) {
        t.tree->at(id).set_port(std::move(name), std::move(value));
      }, py::arg("id"), py::arg("name"), py::arg("value"), "Sets a node's port (exported as an XML attribute).")
      .def("advance_clock", [](PyTree& t, double seconds) {
        if (!t.manual) throw Error("advance_clock needs Tree(..., clock='manual')");
        t.manual->advance(std::chrono::duration_cast<bt::Duration>(std::chrono::duration<double>(seconds)));
      }, py::arg("seconds"),
         "Moves the manual clock on (Tree(..., clock='manual') only; drives Timeout).")
      .def("on_status", [](PyTree& t, py::function f) {
        auto ref = std::make_shared<PyRef>(std::move(f));
        return t.tree->add_status_observer([ref](const bt::StatusChange& c) {
          py::gil_scoped_acquire gil;
          ref->get()(c.id, std::string(c.name), c.previous, c.current);
        });
      }, py::arg("callback"), "Calls callback(id, name, previous, current) on every status change; returns a handle.")
      .def("on_change", [](PyTree& t, py::function f) {
        auto ref = std::make_shared<PyRef>(std::move(f));
        return t.tree->add_change_observer([ref](const bt::TreeChange& c) {
          py::gil_scoped_acquire gil;
          ref->get()(std::string(bt::to_string(c.kind)), c.node, c.previous, c.parent, c.position);
        });
      }, py::arg("callback"), "Calls callback(kind, node, previous, parent, position) on every structural change.")
      .def("remove_observer", [](PyTree& t, bt::Tree::ObserverHandle h) { return t.tree->remove_observer(h); },
           py::arg("handle"),
           "Detaches an observer by the handle on_status()/on_change() returned; False if unknown.")
      .def("to_text", [](PyTree& t, bool ids) { return bt::to_text(*t.tree, {ids, -1}); }, py::kw_only(),
           py::arg("ids") = true, "The tree as indented text with status markers ([*] running, [o] success, ...).")
      .def("to_xml", [](PyTree& t, const std::string& tree_id) {
        bt::XmlOptions o;
        o.tree_id = tree_id;
        return bt::to_btcpp_xml(*t.tree, o);
      }, py::kw_only(), py::arg("tree_id") = "MainTree", "BehaviorTree.CPP v4 XML (Groot2 opens it).")
      .def("to_dot", [](PyTree& t) { return bt::to_dot(*t.tree); }, "Graphviz DOT.");
}

}  // namespace rtamp::python
