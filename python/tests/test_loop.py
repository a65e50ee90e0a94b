"""The reactive loop with a World written in Python (rtamp.toy.ToyWorld and small ones here),
observers written in Python, and callbacks from the planner's worker thread."""

import math
import threading

import pytest

import rtamp
from rtamp.toy import ToyWorld


class PyEuclid(rtamp.CostModel):
    def __init__(self):
        super().__init__()
        self.threads = set()

    def cost(self, q):
        self.threads.add(threading.get_ident())
        return math.dist(q.hand, q.from_) + math.dist(q.from_, q.to)

    def lower_bound(self, q, to_anywhere):
        return math.dist(q.hand, q.from_) + (0.0 if to_anywhere else math.dist(q.from_, q.to))

    def expensive(self):
        return False


class Recorder(rtamp.Observer):
    def __init__(self):
        super().__init__()
        self.events = []
        self.plans = []
        self.ended = None

    def on_begin(self, info):
        self.events.append(("begin", info.scenario))

    def on_action(self, t, what, action, why):
        self.events.append((what, action))

    def on_intervention(self, e):
        self.events.append(("intervention", e.what.subject, e.applied))

    def on_replan_request(self, t, why):
        self.events.append(("replan", why))

    def on_plan(self, t, d):
        self.plans.append(d)

    def on_end(self, t, metrics, placement):
        self.ended = (metrics.end, placement.locations())


def test_python_world_runs_the_task_inline(tray):
    w = ToyWorld(tray, move_time=2.0)
    loop = rtamp.ReactiveLoop(w, tray, planning="inline")
    rec = Recorder()
    loop.add_observer(rec)
    m = loop.run()
    assert m.success and m.end == "task-done"
    assert m.actions_succeeded == 7 and m.actions_failed == 0
    assert w.place == {"o1": "r2", "o2": "r2", "o3": "r2", "r3": "r2"}
    assert w.calls > 0 and loop.ended
    assert rec.events[0] == ("begin", "3-block-tray") and rec.plans and rec.plans[0]["first"]
    assert rec.ended[0] == "task-done"
    # the observed run, repeated at its end, satisfies the task (direct LTL semantics)
    run = loop.observed_run
    assert run[0] == rtamp.initial_placement(tray)
    final = run[-1].locations()
    assert final == {"o1": "r2", "o2": "r2", "o3": "r2", "r3": "r2"}
    assert m.completion_time == pytest.approx(7 * 2.0, abs=1.0)


def test_python_world_with_a_scripted_person_replans(tray):
    person = rtamp.Person(tray, script=[rtamp.Intervention("relocate", "o1", "r1", time=5.0),
                                        rtamp.Intervention("relocate", "o2", "r1", time=9.0)])
    w = rtamp.PersonWorld(ToyWorld(tray, move_time=2.0), person)
    rec = Recorder()
    loop = rtamp.ReactiveLoop(w, tray, planning="inline")
    loop.add_observer(rec)
    m = loop.run()
    assert m.success
    assert m.interventions == 2 and m.interventions_applied == 2
    assert ("intervention", "o1", True) in rec.events


def test_failures_are_fed_back(tray):
    w = ToyWorld(tray, move_time=1.0, fails=lambda mv: mv.thing == "r3")
    m = rtamp.ReactiveLoop(w, tray, planning="inline").run()
    assert m.success and m.actions_failed >= 1  # carried the blocks one by one instead


def test_worker_planning_calls_the_python_cost_model_from_another_thread(tray):
    model = PyEuclid()
    w = rtamp.PersonWorld(ToyWorld(tray, move_time=2.0),
                          rtamp.Person(tray, script=[rtamp.Intervention("relocate", "o1", "r1", time=3.0)]))
    loop = rtamp.ReactiveLoop(w, tray, planning="worker", cost=model)
    m = loop.run()
    assert m.success
    assert any(t != threading.get_ident() for t in model.threads), model.threads


def test_step_by_step_and_stop(tray):
    w = ToyWorld(tray)
    loop = rtamp.ReactiveLoop(w, tray, planning="inline")
    assert loop.step()
    assert loop.actions and loop.actions[0].action.startswith("move(")
    assert "[" in loop.tree_text()
    loop.stop()
    while loop.step():
        pass
    assert loop.metrics.end == "interrupted"


class ContinuousWorld(rtamp.World):
    """No next_event_time: the loop ticks it every tick_period. poll returns plain strings."""

    def __init__(self, scenario):
        super().__init__(scenario)
        self.t, self.place, self.move, self.left = 0.0, rtamp.initial_placement(scenario).locations(), None, 0

    def time(self):
        return self.t

    def advance(self, dt):
        self.t += dt
        if self.move is not None:
            self.left -= dt
            if self.left <= 0:
                self.place[self.move.thing] = self.move.to

    def observe(self):
        return {k: (v, "tray", True) if k == "r3" else v for k, v in self.place.items()}

    def start(self, move):
        self.move, self.left = move, 0.1

    def poll(self):
        if self.move is None:
            return "idle"
        return "succeeded" if self.left <= 0 else "running"

    def halt(self):
        self.move = None


def test_continuous_python_world(tray):
    m = rtamp.ReactiveLoop(ContinuousWorld(tray), tray, planning="inline", tick_period=0.05).run()
    assert m.success and m.world_time > 0.7


class ConfirmingWorld(ContinuousWorld):
    """Its perception is making sure of something it saw until t = 3: the task is not judged before."""

    def confirming(self):
        return self.t < 3.0


def test_the_task_is_not_judged_while_a_python_world_is_confirming(tray):
    m = rtamp.ReactiveLoop(ContinuousWorld(tray), tray, planning="inline", tick_period=0.05).run()
    assert m.success and m.world_time < 3.0
    m = rtamp.ReactiveLoop(ConfirmingWorld(tray), tray, planning="inline", tick_period=0.05).run()
    assert m.success and m.world_time >= 3.0


class BrokenWorld(ContinuousWorld):
    def observe(self):
        raise RuntimeError("camera unplugged")


def test_exceptions_in_a_python_world_end_the_episode(tray):
    m = rtamp.ReactiveLoop(BrokenWorld(tray), tray, planning="inline").run()
    assert not m.success and m.end == "error" and "camera unplugged" in m.reason


def test_loop_options_are_checked(tray):
    with pytest.raises(rtamp.Error):
        rtamp.ReactiveLoop(ToyWorld(tray), tray, planning="sometimes")
    with pytest.raises(rtamp.Error):
        rtamp.ReactiveLoop(ToyWorld(tray), tray, conditions="vibes")


def test_observer_payloads_are_as_docs_python_md_says(tray):
    # docs/python.md's observer table: the keys of on_plan's dict and the values of on_action's `what`.
    w = ToyWorld(tray, move_time=2.0)
    loop = rtamp.ReactiveLoop(w, tray, planning="inline")
    rec = Recorder()
    loop.add_observer(rec)
    assert loop.run().success
    plan = rec.plans[0]
    assert set(plan) == {"first", "found", "cost", "reason", "moves", "seconds", "automaton_states"}
    assert plan["first"] is True and plan["found"] is True and plan["reason"] == "none"
    assert isinstance(plan["cost"], float) and isinstance(plan["seconds"], float)
    assert all(isinstance(x, str) and x.startswith("move(") for x in plan["moves"])
    assert all(isinstance(x, int) for x in plan["automaton_states"])
    whats = {e[0] for e in rec.events if e[0] not in ("begin", "intervention", "replan")}
    assert whats and whats <= {"start", "finished", "failed", "halted"}
