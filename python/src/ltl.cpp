// Python bindings of the ltl layer (paper Section II: the specification φ):
// Formula (hash-consed, immutable; == and hash are identity), parse, print in
// Spot and spin syntax, NNF, simplify, syntactic implication, and the direct
// semantics on lasso words u·v^ω (letters are sets of atom names).
#include <set>

#include "bindings.hpp"
#include "rtamp/ltl/formula.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/nnf.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/simplify.hpp"

namespace rtamp::python {

namespace {

using ltl::Formula;
using Letters = std::vector<std::set<std::string>>;

ltl::LassoWord word(const Letters& prefix, const Letters& cycle) {
  if (cycle.empty()) throw Error("a lasso word needs a non-empty cycle");
  return ltl::LassoWord{prefix, cycle};
}

// A formula from a Formula or its text.
Formula as_formula(const py::object& o) {
  if (py::isinstance<py::str>(o)) return ltl::parse(o.cast<std::string>());
  return o.cast<Formula>();
}

}  // namespace

void bind_ltl(py::module_& m) {
  py::class_<Formula> f(m, "Formula",
                        "An LTL formula (immutable, hash-consed: structurally equal formulas are the same node,\n"
                        "so == and hash() are cheap). Build with parse() or the static constructors; combine\n"
                        "with ~ (not), & (and), | (or), >> (implies). str() prints Spot syntax, which parse()\n"
                        "reads back to the same formula.");
  f.def(py::init([](const std::string& text) { return ltl::parse(text); }), py::arg("text"),
        "Parses LTL text (Spot or spin syntax); raises rtamp.Error with line and column.")
      .def_static("true_", &Formula::tt, "The constant true.")
      .def_static("false_", &Formula::ff, "The constant false.")
      .def_static("atom", &Formula::atom, py::arg("name"), "The atomic proposition `name`.")
      .def_static("Not", &Formula::Not, py::arg("a"), "!a")
      .def_static("X", &Formula::X, py::arg("a"), "X a (next)")
      .def_static("F", &Formula::F, py::arg("a"), "F a (finally)")
      .def_static("G", &Formula::G, py::arg("a"), "G a (globally)")
      .def_static("And", py::overload_cast<std::vector<Formula>>(&Formula::And), py::arg("operands"),
                  "The n-ary conjunction (flattened, sorted, duplicates removed).")
      .def_static("Or", py::overload_cast<std::vector<Formula>>(&Formula::Or), py::arg("operands"),
                  "The n-ary disjunction (flattened, sorted, duplicates removed).")
      .def_static("Implies", &Formula::Implies, py::arg("a"), py::arg("b"), "a -> b")
      .def_static("Equiv", &Formula::Equiv, py::arg("a"), py::arg("b"), "a <-> b")
      .def_static("Xor", &Formula::Xor, py::arg("a"), py::arg("b"), "a xor b")
      .def_static("U", &Formula::U, py::arg("a"), py::arg("b"), "a U b (strong until)")
      .def_static("R", &Formula::R, py::arg("a"), py::arg("b"), "a R b (release)")
      .def_static("W", &Formula::W, py::arg("a"), py::arg("b"), "a W b (weak until)")
      .def_static("M", &Formula::M, py::arg("a"), py::arg("b"), "a M b (strong release)")
      .def_property_readonly("op", [](const Formula& x) { return std::string(ltl::op_name(x.op())); },
                             "The operator: '1', '0', 'atom', '!', 'X', 'F', 'G', '&', '|', 'xor', '->', '<->', 'U', 'R', 'W', 'M'.")
      .def_property_readonly("name", &Formula::name, "The atom's name ('' unless an atom).")
      .def_property_readonly("children", &Formula::children, "The operands, in the node's order.")
      .def_property_readonly("size", &Formula::size, "Number of nodes of the tree.")
      .def_property_readonly("depth", &Formula::depth, "Depth of the tree (1 for an atom).")
      .def_property_readonly("is_boolean", &Formula::is_boolean, "No temporal operator.")
      .def_property_readonly("is_eventual", &Formula::is_eventual, "A pure eventuality (f = F f, syntactically).")
      .def_property_readonly("is_universal", &Formula::is_universal, "Purely universal (f = G f, syntactically).")
      .def("atoms",
           [](const Formula& x) {
             std::set<std::string> out;
             std::vector<Formula> todo{x};
             while (!todo.empty()) {
               Formula g = todo.back();
               todo.pop_back();
               if (g.is(ltl::Op::Atom)) out.insert(g.name());
               for (const Formula& c : g.children()) todo.push_back(c);
             }
             return std::vector<std::string>(out.begin(), out.end());
           },
           "The atom names of the formula, sorted.")
      .def("__str__", [](const Formula& x) { return ltl::to_string(x); })
      .def("__repr__", [](const Formula& x) { return "rtamp.Formula(" + py::repr(py::str(ltl::to_string(x))).cast<std::string>() + ")"; })
      .def("__eq__", [](const Formula& a, const Formula& b) { return a == b; })
      .def("__ne__", [](const Formula& a, const Formula& b) { return a != b; })
      .def("__hash__", [](const Formula& x) { return x.hash(); })
      .def("__invert__", [](const Formula& a) { return Formula::Not(a); })
      .def("__and__", [](const Formula& a, const Formula& b) { return Formula::And(a, b); })
      .def("__or__", [](const Formula& a, const Formula& b) { return Formula::Or(a, b); })
      .def("__rshift__", [](const Formula& a, const Formula& b) { return Formula::Implies(a, b); })
      .def(py::pickle([](const Formula& x) { return ltl::to_string(x); },
                      [](const std::string& s) { return ltl::parse(s); }));

  m.def("parse", [](const std::string& text) { return ltl::parse(text); }, py::arg("text"),
        "Parses an LTL formula (Spot syntax and spin/ltl2ba syntax, mixed freely: ! & | -> <-> xor\n"
        "X F G U R W M, [] <> && || V). Raises rtamp.Error with line and column on bad input.");
  m.def("to_string", [](const py::object& x) { return ltl::to_string(as_formula(x)); }, py::arg("formula"),
        "The formula in Spot syntax (minimal parentheses; parse() reads it back to the same formula).");
  m.def("to_spin", [](const py::object& x) { return ltl::to_spin_string(as_formula(x)); }, py::arg("formula"),
        "The formula in spin/ltl2ba syntax (fully parenthesised; W, M and xor expanded).\n"
        "Raises rtamp.Error if an atom is not a spin identifier.");
  m.def("simplify", [](const py::object& x) { return ltl::simplify(as_formula(x)); }, py::arg("formula"),
        "An equivalent, usually smaller formula in negation normal form (Spot's basic rewritings,\n"
        "Etessami-Holzmann and Somenzi-Bloem rules).");
  m.def("nnf", [](const py::object& x) { return ltl::nnf(as_formula(x)); }, py::arg("formula"),
        "Negation normal form: negations only on atoms; ->, <-> and xor eliminated.");
  m.def("is_nnf", [](const py::object& x) { return ltl::is_nnf(as_formula(x)); }, py::arg("formula"),
        "True if the formula is in negation normal form.");
  m.def("implies", [](const py::object& a, const py::object& b) { return ltl::implies(as_formula(a), as_formula(b)); },
        py::arg("f"), py::arg("g"),
        "Sound, incomplete syntactic implication: True only if every word satisfying f satisfies g\n"
        "(f and g should be in NNF).");
  m.def("holds",
        [](const py::object& x, const Letters& prefix, const Letters& cycle) {
          return ltl::holds(as_formula(x), word(prefix, cycle));
        },
        py::arg("formula"), py::arg("prefix"), py::arg("cycle"),
        "Does the lasso word prefix·cycle^ω satisfy the formula? Letters are sets of the atom names\n"
        "true at that step, e.g. holds('F G a', [set()], [{'a'}]). The cycle must not be empty.");
  m.def("evaluate",
        [](const py::object& x, const Letters& prefix, const Letters& cycle) {
          return ltl::evaluate(as_formula(x), word(prefix, cycle));
        },
        py::arg("formula"), py::arg("prefix"), py::arg("cycle"),
        "The formula's truth value at each of the len(prefix) + len(cycle) positions of the lasso\n"
        "word (position 0 first).");
}

}  // namespace rtamp::python
