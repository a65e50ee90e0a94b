// The compiled part of the Python package `rtamp` (imported as rtamp._rtamp;
// python/rtamp/__init__.py re-exports it). Each area's bindings live in a file
// of their own (ltl.cpp, automata.cpp, scenario.cpp, plan.cpp, bt.cpp,
// loop.cpp, worlds.cpp, episode.cpp, batch.cpp); errors.cpp maps rtamp::Error to rtamp.Error.
#include "bindings.hpp"
#include "rtamp/robot/ompl_logging.hpp"
#include "rtamp/sim/mujoco_logging.hpp"

PYBIND11_MODULE(_rtamp, m) {
  m.doc() =
      "rtamp: reactive task and motion planning under LTL (C++ core).\n\n"
      "LTL -> Buchi automaton -> product with the workspace transition system -> minimum-motion-cost\n"
      "lasso plan -> behavior tree -> executed by the reactive loop on a world (symbolic, MuJoCo, or\n"
      "your own written in Python). See docs/python.md.";
  m.attr("__version__") = RTAMP_VERSION;  // the CMake project version (python/CMakeLists.txt)
  using namespace rtamp::python;
  bind_errors(m);
  bind_ltl(m);
  bind_automata(m);
  bind_scenario(m);
  bind_plan(m);
  bind_bt(m);
  bind_loop(m);
  bind_worlds(m);
  bind_camera(m);
  bind_episode(m);
  bind_batch(m);
  // Importing rtamp changes nothing process-wide; these are the CLI's two calls, on request.
  m.def("install_mujoco_log_handler", &rtamp::sim::install_mujoco_log_handler,
        "Keep MuJoCo's warnings in mjData's counters only (no MUJOCO_LOG.TXT in the working\n"
        "directory). Process-wide; what the rtamp command line does at start-up (docs/library.md).");
  m.def("quiet_ompl_logging", &rtamp::robot::quiet_ompl_logging,
        "Set OMPL's log level to errors only (no 'Info:' lines from the arm's motion planner).\n"
        "Process-wide; what the rtamp command line does at start-up (docs/library.md).");
}
