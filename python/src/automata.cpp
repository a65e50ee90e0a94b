// Python bindings of the automata layer (paper Definition 2: the Büchi
// automaton A_φ): translate an LTL formula; read the states, edges (guards as
// cubes over the atoms) and acceptance; HOA in and out, DOT and spin never
// claims out (and in); lasso acceptance, letters as sets of atom names.
#include <set>

#include "bindings.hpp"
#include "rtamp/automata/automaton.hpp"
#include "rtamp/automata/dot_writer.hpp"
#include "rtamp/automata/hoa_reader.hpp"
#include "rtamp/automata/hoa_writer.hpp"
#include "rtamp/automata/lasso_accept.hpp"
#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/automata/never_claim_writer.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/parser.hpp"

namespace rtamp::python {

namespace {

using automata::Automaton;
using automata::Cube;
using automata::Edge;
using automata::Letter;

const std::vector<std::pair<const char*, automata::Construction>> kConstructions = {
    {"smallest", automata::Construction::Smallest},
    {"gastin-oddoux", automata::Construction::GastinOddoux},
    {"merged", automata::Construction::MergedDestinations},
};

// A set of atom names as a letter over a's atoms (names a does not know are an error).
Letter letter_of(const Automaton& a, const std::set<std::string>& names) {
  Letter l = 0;
  for (const std::string& n : names) {
    const int i = a.find_atom(n);
    if (i < 0) throw Error("'" + n + "' is not an atom of the automaton");
    l |= Letter{1} << i;
  }
  return l;
}

std::vector<std::string> names_of(const std::vector<std::string>& atoms, Letter bits) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < atoms.size(); ++i)
    if (bits >> i & 1) out.push_back(atoms[i]);
  return out;
}

}  // namespace

void bind_automata(py::module_& m) {
  py::class_<Cube>(m, "Cube",
                   "A guard: a conjunction of literals over the automaton's atoms, as bit sets (bit i is\n"
                   "atoms[i]). pos: atoms that must be true; neg: atoms that must be false.")
      .def(py::init([](Letter pos, Letter neg) { return Cube{pos, neg}; }), py::arg("pos") = 0, py::arg("neg") = 0)
      .def_readwrite("pos", &Cube::pos, "Bits of the atoms that must be true.")
      .def_readwrite("neg", &Cube::neg, "Bits of the atoms that must be false.")
      .def("matches", &Cube::matches, py::arg("letter"), "Does the letter (a bit set over the atoms) satisfy the guard?")
      .def_property_readonly("is_true", &Cube::is_true, "The guard is `true` (no literal).")
      .def("__eq__", [](const Cube& a, const Cube& b) { return a == b; })
      .def("__repr__", [](const Cube& c) {
        return "rtamp.Cube(pos=" + std::to_string(c.pos) + ", neg=" + std::to_string(c.neg) + ")";
      });

  py::class_<Edge>(m, "Edge", "An edge of a Büchi automaton: destination, guard and acceptance marks.")
      .def_readonly("dst", &Edge::dst, "The destination state.")
      .def_readonly("guard", &Edge::guard, "The guard (a Cube).")
      .def_readonly("marks", &Edge::marks, "Acceptance marks (bit i: set i); transition-based automata only.")
      .def("__eq__", [](const Edge& a, const Edge& b) { return a == b; })
      .def("__repr__", [](const Edge& e) {
        return "rtamp.Edge(dst=" + std::to_string(e.dst) + ", pos=" + std::to_string(e.guard.pos) +
               ", neg=" + std::to_string(e.guard.neg) + ", marks=" + std::to_string(e.marks) + ")";
      });

  py::class_<Automaton>(m, "Automaton",
                        "A Büchi automaton over 2^AP (state-based Büchi, or transition-based generalized\n"
                        "Büchi). Letters are bit sets over `atoms` (bit i is atoms[i]); guards are cubes;\n"
                        "a DNF guard is several edges to the same destination.")
      .def(py::init<>(), "An empty automaton (no states); fill it with add_state/add_edge.")
      .def_readwrite("atoms", &Automaton::atoms, "Atom names; bit i of a letter is atoms[i].")
      .def_readwrite("initial", &Automaton::initial, "The initial state.")
      .def_readwrite("num_sets", &Automaton::num_sets, "Number of acceptance sets (state-based: 1).")
      .def_readwrite("state_based", &Automaton::state_based, "True: acceptance on states (state_accepting).")
      .def_readwrite("name", &Automaton::name, "Usually the formula it came from.")
      .def_property_readonly("num_states", &Automaton::num_states, "Number of states.")
      .def_property_readonly("num_edges", &Automaton::num_edges, "Number of edges (one per guard cube).")
      .def_property_readonly("states", [](const Automaton& a) {
             return py::module_::import("builtins").attr("range")(a.num_states());
           }, "range(num_states).")
      .def_property_readonly("state_accepting", [](const Automaton& a) { return a.state_accepting; },
                             "Per state: accepting (meaningful when state_based).")
      .def("edges", [](const Automaton& a, std::uint32_t q) {
             if (q >= a.num_states()) throw py::index_error("no state " + std::to_string(q));
             return a.edges[q];
           }, py::arg("state"), "The out-edges of a state.")
      .def("transitions",
           [](const Automaton& a) {
             py::list out;
             for (std::uint32_t q = 0; q < a.num_states(); ++q)
               for (const Edge& e : a.edges[q])
                 out.append(py::make_tuple(q, e.dst, automata::cube_to_string(e.guard, a.atoms), e.marks));
             return out;
           },
           "Every edge as (src, dst, guard text such as 'a & !b', marks).")
      .def("guard_text", [](const Automaton& a, const Cube& c) { return automata::cube_to_string(c, a.atoms); },
           py::arg("cube"), "A guard over atom names: 'a & !b', 'true'.")
      .def("is_accepting", &Automaton::is_accepting_state, py::arg("state"),
           "True if the state is accepting (state-based automata; False for transition-based ones).")
      .def("add_state", &Automaton::add_state, py::arg("accepting") = false, "Adds a state; returns its number.")
      .def("add_edge",
           [](Automaton& a, std::uint32_t src, std::uint32_t dst, const std::set<std::string>& pos,
              const std::set<std::string>& neg, automata::Marks marks) {
             if (src >= a.num_states() || dst >= a.num_states()) throw Error("add_edge: no such state");
             Cube c;
             for (const auto& n : pos) c.pos |= Letter{1} << a.atom_index(n);
             for (const auto& n : neg) c.neg |= Letter{1} << a.atom_index(n);
             if (c.is_false()) throw Error("add_edge: an atom is both in pos and in neg");
             a.add_edge(src, dst, c, marks);
           },
           py::arg("src"), py::arg("dst"), py::arg("pos") = std::set<std::string>{},
           py::arg("neg") = std::set<std::string>{}, py::arg("marks") = 0,
           "Adds an edge whose guard is the conjunction of the atoms in pos and the negations of\n"
           "those in neg (atoms are added to `atoms` as needed).")
      .def("accepts",
           [](const Automaton& a, const std::vector<std::set<std::string>>& prefix,
              const std::vector<std::set<std::string>>& cycle) {
             automata::LassoWord w;
             for (const auto& s : prefix) w.prefix.push_back(letter_of(a, s));
             for (const auto& s : cycle) w.cycle.push_back(letter_of(a, s));
             return automata::lasso_accept(a, w);
           },
           py::arg("prefix"), py::arg("cycle"),
           "Does the automaton accept prefix·cycle^ω? Letters are sets of atom names (the cycle must\n"
           "not be empty).")
      .def("letter_atoms", [](const Automaton& a, Letter l) { return names_of(a.atoms, l); }, py::arg("letter"),
           "The atom names set in a letter (bit set).")
      .def("to_hoa", &automata::to_hoa, "The automaton in HOA v1 (Spot's autfilt and Owl read it).")
      .def("to_dot", &automata::to_dot, "The automaton in Graphviz DOT.")
      .def("to_never_claim", &automata::to_never_claim,
           "A spin never claim (state-based automata whose atoms are Promela identifiers).")
      .def("__repr__", [](const Automaton& a) {
        return "<rtamp.Automaton '" + a.name + "': " + std::to_string(a.num_states()) + " states, " +
               std::to_string(a.num_edges()) + " edges, " + (a.state_based ? "state-based" : "transition-based") + ">";
      });

  m.def("translate",
        [](const py::object& f, bool state_based, bool simplify, bool reduce, bool shortcuts,
           const std::string& construction) {
          automata::TranslateOptions o;
          o.state_based = state_based;
          o.simplify = simplify;
          o.reduce = reduce;
          o.shortcuts = shortcuts;
          o.construction = parse_choice(kConstructions, construction, "construction");
          const ltl::Formula formula =
              py::isinstance<py::str>(f) ? ltl::parse(f.cast<std::string>()) : f.cast<ltl::Formula>();
          py::gil_scoped_release release;
          return automata::translate(formula, o);
        },
        py::arg("formula"), py::kw_only(), py::arg("state_based") = true, py::arg("simplify") = true,
        py::arg("reduce") = true, py::arg("shortcuts") = true, py::arg("construction") = "smallest",
        "Translates an LTL formula (a Formula or its text) to a Büchi automaton whose language is\n"
        "its models: state-based (default) or, with state_based=False, transition-based generalized.\n"
        "construction: 'smallest', 'gastin-oddoux' or 'merged'. Atoms are sorted by name.");
  m.def("read_hoa", &automata::read_hoa, py::arg("text"), py::arg("file") = "",
        "Every automaton of a HOA v1 stream (Büchi and generalized Büchi acceptance). Errors are\n"
        "rtamp.Error with file, line and column.");
  m.def("read_hoa_one", &automata::read_hoa_one, py::arg("text"), py::arg("file") = "",
        "Exactly one automaton from HOA text.");
  m.def("read_hoa_file", &automata::read_hoa_file, py::arg("path"), "Every automaton of a HOA file.");
  m.def("read_never_claim", &automata::read_never_claim, py::arg("text"), py::arg("file") = "",
        "A spin never claim (what spin -f and ltl2ba print) as a state-based Büchi automaton.");
}

}  // namespace rtamp::python
