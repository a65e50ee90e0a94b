"""rtamp: reactive task and motion planning under LTL, from Python.

LTL formula -> Buchi automaton -> product with the workspace transition system ->
minimum-motion-cost lasso plan -> behavior tree -> executed by the reactive loop on
a world: the symbolic world, the MuJoCo UR5, or a World you write in Python.

    import rtamp
    s = rtamp.load_scenario("3-block-tray")
    plan = rtamp.Planner(s).plan()
    print(plan.cost, plan.moves)

The compiled core is rtamp._rtamp; behavior-tree node specs are in rtamp.bt and
Dask batches in rtamp.batch. rtamp.__version__ is the C++ project's version. Errors a user can cause are rtamp.Error (a
ValueError) with message, file, line and column. See docs/python.md.
"""

from rtamp._rtamp import *  # noqa: F401,F403
from rtamp._rtamp import Error, __doc__ as _core_doc, __version__  # noqa: F401
from rtamp import batch, bt, toy  # noqa: F401,E402
from rtamp import _arguments, _rtamp

_arguments.name_arguments(globals(), _rtamp)  # TypeErrors that name the argument
del _arguments

__all__ = [n for n in dir() if not n.startswith("_")]
