"""Behavior-tree node specs for rtamp.Tree (the engine is C++: rtamp/bt).

A spec says what to build; rtamp.Tree(spec) (and Tree.insert / append / replace)
turns it into engine nodes owned by the tree, named by id from then on:

    from rtamp import bt
    done = {"n": 0}
    def step():
        done["n"] += 1
        return rtamp.Status.SUCCESS if done["n"] >= 3 else rtamp.Status.RUNNING
    tree = rtamp.Tree(bt.Sequence("main", bt.Condition("ready", lambda: True),
                                  bt.Action("work", step)))
    while tree.tick() == rtamp.Status.RUNNING:
        pass

Leaves are Python callables without arguments: an action returns an rtamp.Status
(or 'SUCCESS' / 'RUNNING' / 'FAILURE'), a condition a bool. Semantics follow
py_trees / BehaviorTree.CPP (docs/behavior-trees.md).
"""


class Spec:
    """A node to build: kind, name, children, ports and the kind's parameters."""

    kind = ""

    def __init__(self, name=None, *children, ports=None, interruptible=True):
        self.name = name if name is not None else self.kind
        self.children = list(children)
        self.ports = dict(ports or {})
        self.interruptible = interruptible

    def __repr__(self):
        inner = ", ".join(repr(c) for c in self.children)
        return f"{self.kind}({self.name!r}{', ' if inner else ''}{inner})"


class Sequence(Spec):
    """Ticks children in order while they succeed; remembers the running child."""
    kind = "Sequence"


class Fallback(Spec):
    """Ticks children in order until one succeeds; remembers the running child."""
    kind = "Fallback"


class ReactiveSequence(Spec):
    """Like Sequence, but re-ticks every child from the first on every tick."""
    kind = "ReactiveSequence"


class ReactiveFallback(Spec):
    """Like Fallback, but re-ticks every child from the first on every tick."""
    kind = "ReactiveFallback"


class Chooser(Spec):
    """Commits to the first child that does not fail until it finishes."""
    kind = "Chooser"


class Parallel(Spec):
    """Ticks every child; succeeds when success_count succeed (-1: all), fails when failure_count fail."""
    kind = "Parallel"

    def __init__(self, name=None, *children, success_count=-1, failure_count=1, **kw):
        super().__init__(name, *children, **kw)
        self.success_count = success_count
        self.failure_count = failure_count


class Inverter(Spec):
    """SUCCESS <-> FAILURE of its one child."""
    kind = "Inverter"


class Retry(Spec):
    """Re-runs its child after a failure, up to num_attempts runs (BehaviorTree.CPP RetryUntilSuccessful)."""
    kind = "Retry"

    def __init__(self, name=None, child=None, num_attempts=3, **kw):
        super().__init__(name, *([child] if child is not None else []), **kw)
        self.num_attempts = num_attempts


class Timeout(Spec):
    """Fails (halting its child) once `seconds` have passed since the run began."""
    kind = "Timeout"

    def __init__(self, name=None, child=None, seconds=1.0, **kw):
        super().__init__(name, *([child] if child is not None else []), **kw)
        self.seconds = seconds


class Action(Spec):
    """A leaf that does something: on_start() on a new run, on_running() on later ticks while it
    runs (default: on_start again), on_halted() when halted while running."""
    kind = "Action"

    def __init__(self, name, on_start, on_running=None, on_halted=None, type_id="UserAction", **kw):
        super().__init__(name, **kw)
        self.on_start = on_start
        self.on_running = on_running
        self.on_halted = on_halted
        self.type_id = type_id


class Condition(Spec):
    """A leaf that checks predicate(): SUCCESS if true, FAILURE if not."""
    kind = "Condition"

    def __init__(self, name, predicate, type_id="UserCondition", **kw):
        super().__init__(name, **kw)
        self.predicate = predicate
        self.type_id = type_id
