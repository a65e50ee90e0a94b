// The compiled part of the Python package `rtamp` (imported as rtamp._rtamp;
// python/rtamp/__init__.py re-exports it). Each area's bindings live in a file
// of their own (ltl.cpp, automata.cpp, scenario.cpp, plan.cpp, bt.cpp,
// loop.cpp, worlds.cpp, batch.cpp); errors.cpp maps rtamp::Error to rtamp.Error.
#include "bindings.hpp"

PYBIND11_MODULE(_rtamp, m) {
  m.doc() =
      "rtamp: reactive task and motion planning under LTL (C++ core).\n\n"
      "LTL -> Buchi automaton -> product with the workspace transition system -> minimum-motion-cost\n"
      "lasso plan -> behavior tree -> executed by the reactive loop on a world (symbolic, MuJoCo, or\n"
      "your own written in Python). See docs/python.md.";
  using namespace rtamp::python;
  bind_errors(m);
  bind_ltl(m);
  bind_automata(m);
  bind_scenario(m);
  bind_plan(m);
  bind_bt(m);
  bind_loop(m);
  bind_worlds(m);
  bind_batch(m);
}
