"""Planning bindings: Planner, plan(), replanning after changes, plans, statistics, Python cost models."""

import math
import threading
import time

import pytest

import rtamp


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


class PyEuclid(rtamp.CostModel):
    """The built-in euclid model, written in Python: the planner must find the same optimum."""

    def __init__(self):
        super().__init__()
        self.calls = 0
        self.threads = set()

    def cost(self, q):
        self.calls += 1
        self.threads.add(threading.get_ident())
        return dist(q.hand, q.from_) + dist(q.from_, q.to)

    def lower_bound(self, q, to_anywhere):
        return dist(q.hand, q.from_) + (0.0 if to_anywhere else dist(q.from_, q.to))

    def depends(self):
        return rtamp.DEPENDS_HAND | rtamp.DEPENDS_FROM | rtamp.DEPENDS_TO


class OnlyCost(rtamp.CostModel):
    def cost(self, q):
        return 1.0


def test_first_plan_of_3_block_tray(tray):
    p = rtamp.Planner(tray)
    plan = p.plan()
    assert plan and plan.found and plan.reason == "none"
    assert plan.cost == pytest.approx(plan.prefix_cost + plan.cycle_cost)
    assert plan.cost == pytest.approx(sum(s.cost for s in plan.prefix + plan.cycle))
    # the optimal plan carries the blocks on the tray (the scenario's comment): 7 moves
    assert len(plan.moves) == 7 and "move(r3, r2)" in plan.moves
    assert [a.action for a in plan.actions] == plan.moves
    assert plan.actions[0].hand_before == "home" and plan.actions[0].pre
    assert plan.cycle and all(s.action == "stay" for s in plan.cycle)
    assert plan.prefix[0].from_state.endswith("hand@home")
    assert plan.stats.expanded > 0 and plan.stats.graph_nodes > 0 and plan.stats.seconds >= 0
    assert plan.automaton_states == [p.automaton.initial]
    assert "cost=" in repr(plan)


def test_algorithms_agree_and_python_cost_model_matches_builtin(tray):
    costs = {a: rtamp.Planner(tray, algorithm=a).plan().cost for a in rtamp.algorithms()}
    assert len(set(round(c, 9) for c in costs.values())) == 1
    py = PyEuclid()
    plan = rtamp.Planner(tray, cost=py).plan()
    assert plan.cost == pytest.approx(costs["astar-exp"])
    assert py.calls > 0
    for c in ("region", "unit"):
        assert rtamp.Planner(tray, cost=c).plan().found
    assert rtamp.Planner(tray, cost="unit").plan().cost == 3  # three blocks, one move each


def test_cost_model_defaults_and_builtins(tray):
    m = OnlyCost()
    assert m.name() == "OnlyCost" and m.depends() == rtamp.DEPENDS_ALL and m.expensive()
    assert m.lower_bound(rtamp.MotionQuery(), False) == 0.0
    p = rtamp.Planner(tray, cost=m)
    assert p.cost_model == "OnlyCost" and p.plan().cost == 3
    e = rtamp.cost_model("euclid")
    q = rtamp.MotionQuery()
    q.hand, q.from_, q.to = [0, 0, 0.5], [0.4, 0, 0], [0.4, 0.5, 0]
    assert e.cost(q) == pytest.approx(1.1403, abs=1e-4)  # the example in plan/motion_cost.hpp
    assert e.name() == "euclid" and not e.expensive()


def test_cost_model_survives_its_python_name(tray):
    p = rtamp.Planner(tray, cost=PyEuclid())  # no other reference to the model
    import gc
    gc.collect()
    assert p.plan().found


def test_a_query_names_its_thing_and_class(tray):
    """The planner's queries carry a stable id; the Python model sees the thing's name and class."""
    seen = set()

    class Naming(PyEuclid):
        def cost(self, q):
            seen.add((q.thing_name, q.thing_class, q.container))
            return super().cost(q)

        def depends(self):  # the thing too: every thing's moves are asked for
            return rtamp.DEPENDS_THING | super().depends()

    result = rtamp.Planner(tray, cost=Naming()).plan()
    assert result.found
    things = {(o.name, o.cls, False) for o in tray.objects} | {(c.name, c.cls, True) for c in tray.containers}
    assert seen and seen <= things
    assert {name for name, _, _ in seen} >= {a.thing for a in result.actions}
    # A query made in Python names nothing until a planner fills it.
    q = rtamp.MotionQuery()
    assert q.thing_name is None and q.thing_class is None


def test_replan_after_changes(tray):
    p = rtamp.Planner(tray, algorithm="astar-exp")
    first = p.plan()
    for step in first.prefix[:2]:
        p.execute(step)
    assert "o" in p.state
    p.apply("move o2 r1")
    p.apply(rtamp.Change.relocate("o3", "r1"))
    again = p.plan()
    assert again.found
    assert again.stats.reused_nodes > 0  # astar-exp keeps its graph while the TS is unchanged
    cold = rtamp.Planner(p.scenario, algorithm="dijkstra")
    cold.set_placement(p.placement, p.hand)
    assert cold.plan().cost == pytest.approx(again.cost)
    p.apply(rtamp.Change.add_object("o4", "block", "r1"))
    assert "o4" in p.placement.locations()
    with_four = p.plan()
    assert with_four.found and any("o4" in m for m in with_four.moves)
    p.apply("remove o4")
    assert p.plan().found


def test_apply_keeps_the_rules_of_space_unless_observed(tray):
    p = rtamp.Planner(tray)
    with pytest.raises(rtamp.Error, match="cannot put 'o4' in 'r1'"):
        p.apply("add o4 block r1")  # r1 (capacity 4) holds three blocks and the tray
    assert "o4" not in p.placement.locations()
    p.apply("add o4 block r1", observed=True)  # what a world showed is taken as it is
    assert p.placement.locations()["o4"] == "r1"


def test_state_controls(tray):
    p = rtamp.Planner(tray)
    p.forbid_move("r3", "r2")
    assert p.forbidden_moves == [("r3", "r2")]
    plan = p.plan()
    assert plan.found and "move(r3, r2)" not in plan.moves
    p.clear_forbidden_moves()
    p.set_placement({"o1": "r2", "o2": "r2", "o3": "r2", "r3": "r1"})
    assert p.plan().cost == 0
    p.set_automaton_states([p.automaton.initial])
    assert p.automaton_states == [p.automaton.initial]
    with pytest.raises(rtamp.Error):
        p.set_automaton_states([10_000])
    assert p.formula == rtamp.parse("F G all_in_r2")
    assert p.algorithm == "astar-exp" and p.scenario.name == "3-block-tray"


def test_not_found_has_a_reason():
    s = rtamp.load_scenario("3-block")
    s.task = "F all_in_r2 & G !all_in_r2"
    plan = rtamp.Planner(s).plan()
    assert not plan and plan.reason == "unsatisfiable" and plan.message


def test_plan_from_several_python_threads(tray):
    """Threads share one planner: each call drops the GIL, then waits for the planner's lock."""
    p = rtamp.Planner(tray, cost=PyEuclid())
    results = []
    threads = [threading.Thread(target=lambda: results.append(p.plan().cost)) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 4 and len(set(round(c, 9) for c in results)) == 1


def test_change_text():
    c = rtamp.Change.parse("move o1 r2")
    assert str(c) == "move o1 r2"
    assert str(rtamp.Change.remove_object("o1")) == "remove o1"
    assert str(rtamp.Change.add_container("t2", "tray", "r1", 3)).startswith("add-container t2")
    assert str(rtamp.Change.remove_container("t2")) == "remove-container t2"
    assert str(rtamp.Change.add_region(rtamp.Region("r7", center=[0.5, 0, 0]))).startswith("add-region r7")
    a = rtamp.Change.parse("add o9 cup r2")
    assert (a.kind, a.subject, a.cls, a.location) == ("add", "o9", "cup", "r2")
    assert rtamp.Change.take_from_gripper("r1").kind == "take-from-gripper"


def test_one_change_type_for_planner_and_worlds(tray):
    # An Intervention (a person's scripted action) is a Change: the planner takes it as it is.
    iv = rtamp.Intervention("relocate", "o1", "r3", time=2.0)
    assert isinstance(iv, rtamp.Change) and str(iv) == "move o1 r3"
    p = rtamp.Planner(tray)
    p.apply(iv)
    q = rtamp.Planner(tray)
    q.apply("move o1 r3")
    assert p.plan().cost == pytest.approx(q.plan().cost)
    # A change of a running robot's gripper is not one the planner can apply.
    with pytest.raises(rtamp.Error, match="take-from-gripper"):
        p.apply(rtamp.Change.take_from_gripper())


def test_names_come_from_the_planners_registry(tray):
    algos = rtamp.algorithms()
    assert list(algos) == ["astar-exp", "astar", "dijkstra"]
    assert all(isinstance(d, str) and d for d in algos.values())
    models = rtamp.cost_models()
    assert {"euclid", "region", "unit", "ik"} <= set(models)
    with pytest.raises(rtamp.Error, match="did you mean 'euclid'"):
        rtamp.Planner(tray, cost="eucild")
    with pytest.raises(rtamp.Error, match="did you mean 'astar'"):
        rtamp.Planner(tray, algorithm="astr")
    assert rtamp.Planner(tray, algorithm="astar").algorithm == "astar"


def bad_model(value, where="cost"):
    """A CostModel whose cost (or lower_bound) returns `value` (euclid's otherwise)."""

    class Bad(PyEuclid):
        def cost(self, q):
            return value if where == "cost" else super().cost(q)

        def lower_bound(self, q, to_anywhere):
            return value if where == "lower_bound" else super().lower_bound(q, to_anywhere)

    return Bad()


@pytest.mark.parametrize("value, text", [(-1.0, "-1"), (float("nan"), "nan"), (-math.inf, "-inf")])
def test_a_bad_cost_is_an_error_naming_the_move_at_once(tray, value, text):
    start = time.monotonic()
    with pytest.raises(rtamp.Error, match=rf"motion-cost model 'Bad' returned {text} for move\(\w+, \w+\) "
                                          r"\(\w+ from \w+, hand at home\): a cost must be >= 0") as e:
        rtamp.Planner(tray, cost=bad_model(value)).plan()
    assert isinstance(e.value, ValueError)
    assert time.monotonic() - start < 5  # at the first bad value, not after the search grew


def test_a_bad_lower_bound_is_an_error(tray):
    with pytest.raises(rtamp.Error, match=r"returned nan as lower_bound for bringing \w+ from \w+ to \w+"):
        rtamp.Planner(tray, algorithm="astar", cost=bad_model(float("nan"), "lower_bound")).plan()


def test_an_infinite_cost_is_a_move_the_model_cannot_do(tray):
    plan = rtamp.Planner(tray, cost=bad_model(math.inf)).plan()
    assert not plan and plan.reason == "no-accepting-cycle"


def test_the_memory_limit_stops_a_query_with_its_own_reason():
    # seven objects without symmetry reduction: A* passes its first memory check (128 expansions)
    s = rtamp.generate_scenario(regions=5, objects=7, layout="random", seed=3, task="F all_in_r2 & F all_in_r3",
                                propositions=[("all_in_r3", "all object in r3")])
    plan = rtamp.Planner(s, symmetry=False, max_memory_bytes=64 << 10).plan()
    assert not plan and plan.reason == "memory-limit" and plan.stats.hit_memory_limit
    assert "stopped at its memory limit (64 KiB)" in plan.message
    assert "whether a plan exists is unknown" in plan.message
    assert rtamp.Planner(s, symmetry=False, max_memory_bytes=0).plan()
