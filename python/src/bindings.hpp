// Shared declarations of the Python module's binding files:
// one bind_<area>() per file, called in dependency order by module.cpp, and
// the helpers that several areas use (name <-> enum tables, GIL-safe
// ownership of Python objects held by C++).
// Invariants: every C++ call that may run long (planning, episodes, the
// reactive loop) releases the GIL; every call back into Python (trampolines,
// callables) takes it first, whatever thread it comes from.
#pragma once

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "rtamp/util/error.hpp"

namespace py = pybind11;

namespace rtamp::python {

void bind_errors(py::module_& m);
void bind_ltl(py::module_& m);
void bind_automata(py::module_& m);
void bind_scenario(py::module_& m);
void bind_plan(py::module_& m);
void bind_bt(py::module_& m);
void bind_loop(py::module_& m);
void bind_worlds(py::module_& m);
void bind_camera(py::module_& m);
void bind_episode(py::module_& m);
void bind_batch(py::module_& m);

// A (name, value) table for an enum that Python spells as strings, e.g.
// {"dijkstra", Algorithm::Dijkstra}. Unknown names are rtamp::Error naming
// `what` and the choices.
template <class E>
E parse_choice(const std::vector<std::pair<const char*, E>>& table, const std::string& name, const char* what) {
  std::string choices;
  for (const auto& [n, v] : table) {
    if (name == n) return v;
    choices += choices.empty() ? "" : ", ";
    choices += n;
  }
  throw Error("unknown " + std::string(what) + " '" + name + "' (expected one of: " + choices + ")");
}

template <class E>
const char* choice_name(const std::vector<std::pair<const char*, E>>& table, E v) {
  for (const auto& [n, x] : table)
    if (x == v) return n;
  return "?";
}

// A Python object kept alive by C++ state that may be destroyed without the
// GIL (e.g. by a worker thread): takes the GIL to drop the reference.
class PyRef {
 public:
  PyRef() = default;
  explicit PyRef(py::object o) : o_(new py::object(std::move(o))) {}
  PyRef(const PyRef& other) {
    if (other.o_) {
      py::gil_scoped_acquire gil;
      o_ = new py::object(*other.o_);
    }
  }
  PyRef(PyRef&& other) noexcept : o_(other.o_) { other.o_ = nullptr; }
  PyRef& operator=(const PyRef&) = delete;
  ~PyRef() {
    if (o_) {
      py::gil_scoped_acquire gil;
      delete o_;
    }
  }
  const py::object& get() const { return *o_; }
  explicit operator bool() const { return o_ != nullptr; }

 private:
  py::object* o_ = nullptr;
};

}  // namespace rtamp::python
