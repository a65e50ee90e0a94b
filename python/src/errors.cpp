// rtamp::Error -> rtamp.Error (a ValueError) with the C++ error's location:
// `message` (the problem alone), `file`, `line`, `column` (None when unknown)
// and `detail` (e.g. the input line with a caret). str(e) is the C++ what():
// "file:line:col: message", the same line the CLI prints after "rtamp: error: ".
// A value of the wrong type that pybind11 could not convert (py::cast_error, e.g.
// what a Python override returned) is a TypeError, not pybind11's RuntimeError.
// _as_method makes a Python callable a method pybind11 takes for its own, so wrapping a
// method of a class Python overrides (rtamp/_arguments.py) is not mistaken for an override.
#include "bindings.hpp"

namespace rtamp::python {

void bind_errors(py::module_& m) {
  static py::exception<Error> error(m, "Error", PyExc_ValueError);
  error.doc() =
      "An error a user can cause (bad LTL, bad YAML, unknown names, bad options).\n\n"
      "A ValueError. Attributes: message (what is wrong), file, line, column (where; None if\n"
      "unknown), detail (extra lines, e.g. the offending input with a caret). str(e) is\n"
      "'file:line:column: message' with the unknown parts left out.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      py::object inst = py::handle(error.ptr())(py::str(e.what()));
      const SourceLocation& w = e.where();
      inst.attr("message") = py::str(e.message());
      inst.attr("file") = w.file.empty() ? py::object(py::none()) : py::object(py::str(w.file));
      inst.attr("line") = w.line > 0 ? py::object(py::int_(w.line)) : py::object(py::none());
      inst.attr("column") = w.column > 0 ? py::object(py::int_(w.column)) : py::object(py::none());
      inst.attr("detail") = py::str(e.detail());
      PyErr_SetObject(error.ptr(), inst.ptr());
    } catch (const py::cast_error& e) {
      PyErr_SetString(PyExc_TypeError, e.what());
    }
  });
  m.def(
      "_as_method",
      [](py::type cls, const std::string& name, py::function call, const std::string& doc) {
        py::options options;  // the doc is the wrapped method's, signature line included
        options.disable_function_signatures();
        return py::cpp_function([call](py::args args, py::kwargs kwargs) { return call(*args, **kwargs); },
                                py::name(name.c_str()), py::is_method(cls), py::doc(doc.c_str()));
      },
      "Internal: `call` as a method of `cls` that pybind11's override lookup takes for a C++ one.");
}

}  // namespace rtamp::python
