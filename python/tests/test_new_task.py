"""A new task while the robot works (docs/python.md): ReactiveLoop.set_task from the
main thread between steps and from another thread while run() runs, scheduled
new_tasks on the loop and on episodes, the metrics' tasks, the observer's on_task
and on_redirect, and the errors. Runs are judged with rtamp.holds (direct LTL
semantics) on the observed run from task_from, the last state repeated."""

import json
import os
import re
import subprocess
import threading

import pytest

import rtamp

ALL_IN_R1 = {"all_in_r1": "all block in r1"}


def letters(placement):
    """The atoms these tests use, true in a placement (the 3-block scene: blocks o1..o3)."""
    loc = placement.locations()
    out = {f"{o}_in_{r}" for o, r in loc.items()}
    for r in ("r1", "r2"):
        if all(loc[o] == r for o in ("o1", "o2", "o3")):
            out.add(f"all_in_{r}")
    return out


def holds_from(loop, formula, start):
    """Does the observed run from `start`, its last state repeated forever, satisfy `formula`?"""
    run = [letters(p) for p in loop.observed_run[start:]]
    return rtamp.holds(formula, run[:-1], run[-1:])


class Recorder(rtamp.Observer):
    def __init__(self):
        super().__init__()
        self.events = []

    def on_action(self, t, what, action, why):
        self.events.append((what, action))

    def on_task(self, t, d):
        self.events.append(("task", d))

    def on_redirect(self, t, action, rule):
        self.events.append(("redirect", action, rule))

    def finished(self):
        return any(e[0] == "finished" for e in self.events)

    def tasks(self):
        return [e[1] for e in self.events if e[0] == "task"]


@pytest.fixture
def blocks():
    return rtamp.load_scenario("3-block")


def stepped_loop(s, formula, propositions=None, **kw):
    """A loop on the symbolic world that is given `formula` after its first finished move."""
    world = rtamp.SymbolicWorld(s)
    loop = rtamp.ReactiveLoop(world, s, planning="inline", **kw)
    rec = Recorder()
    loop.add_observer(rec)
    given = False
    while loop.step():
        if not given and rec.finished():
            loop.set_task(formula, propositions)
            given = True
    assert given
    return loop, rec, world


def test_a_new_task_between_steps_is_done_on_the_run_from_its_switch(blocks):
    loop, rec, world = stepped_loop(blocks, "F G all_in_r1", ALL_IN_R1)
    m = loop.metrics
    assert m.success and m.end == "task-done"
    # judged from the state it took effect in: one block had gone to r2 before
    start = loop.task_from
    assert start > 0 and loop.observed_run[start].location_of("o1") == "r2"
    assert holds_from(loop, "F G all_in_r1", start)
    assert not holds_from(loop, "F G all_in_r2", start)
    assert loop.observed_run[-1].locations() == world.truth.locations() == {"o1": "r1", "o2": "r1", "o3": "r1"}
    # the metrics list both tasks, each with its outcome
    assert [(x.task, x.by, x.outcome) for x in m.tasks] == [
        ("F G all_in_r2", "scenario", "superseded"), ("F G all_in_r1", "api", "task-done")]
    assert m.tasks[0].time == 0 and m.tasks[1].time > 0 and m.tasks[1].automaton_states >= 1
    assert "TaskOutcome 'F G all_in_r1' by api" in repr(m.tasks[1])
    # the observer heard of it once, applied, with its proposition
    (d,) = rec.tasks()
    assert d == {"task": "F G all_in_r1", "by": "api", "applied": True, "refused": "",
                 "automaton_states": m.tasks[1].automaton_states, "propositions": ALL_IN_R1}


class Gate(rtamp.Observer):
    """Holds the loop's thread at the first finished move until another thread has given a task."""

    def __init__(self):
        super().__init__()
        self.reached = threading.Event()
        self.given = threading.Event()
        self.tasks = []

    def on_action(self, t, what, action, why):
        if what == "finished" and not self.reached.is_set():
            self.reached.set()
            assert self.given.wait(60), "the other thread did not give the task"

    def on_task(self, t, d):
        self.tasks.append(d)


@pytest.mark.parametrize("planning", ["inline", "worker"])
def test_a_new_task_from_another_thread_while_run_runs(blocks, planning):
    loop = rtamp.ReactiveLoop(rtamp.SymbolicWorld(blocks), blocks, planning=planning)
    gate = Gate()
    loop.add_observer(gate)
    errors = []

    def give():
        gate.reached.wait(60)
        try:
            loop.set_task("F G all_in_r1", ALL_IN_R1)
        except Exception as e:  # reported below, on the test's thread
            errors.append(e)
        gate.given.set()

    th = threading.Thread(target=give)
    th.start()
    m = loop.run()
    th.join()
    assert errors == []
    assert m.end == "task-done" and [x.outcome for x in m.tasks] == ["superseded", "task-done"]
    assert [d["task"] for d in gate.tasks] == ["F G all_in_r1"] and gate.tasks[0]["applied"]
    assert loop.task_from > 0 and holds_from(loop, "F G all_in_r1", loop.task_from)


def test_a_running_move_that_would_break_the_new_task_is_redirected(blocks):
    # o2 is on its way to r2 when the task forbids o2 in r2: the move is halted, o3 goes instead.
    task = 'G !"o2 in r2" & F "o3 in r2"'
    loop, rec, world = stepped_loop(blocks, task)
    assert loop.metrics.end == "task-done"
    redirects = [e for e in rec.events if e[0] == "redirect"]
    assert [e[1] for e in redirects] == ["move(o2, r2)"] and "no accepting future" in redirects[0][2]
    assert ("halted", "move(o2, r2)") in rec.events
    assert holds_from(loop, "G !o2_in_r2 & F o3_in_r2", loop.task_from)
    assert world.truth.location_of("o2") == "r1" and world.truth.location_of("o3") == "r2"
    assert rec.tasks()[0]["propositions"] == {}


def test_a_task_the_current_state_satisfies_ends_at_once(blocks):
    loop, rec, world = stepped_loop(blocks, 'F "o1 in r2"')
    assert loop.metrics.end == "task-done" and loop.task_from == len(loop.observed_run) - 1
    assert [x.outcome for x in loop.metrics.tasks] == ["superseded", "task-done"]


def test_a_task_the_current_state_cannot_satisfy_ends_unsatisfiable(blocks):
    loop, _, _ = stepped_loop(blocks, 'G "o1 in r1"')
    m = loop.metrics
    assert m.end == "unsatisfiable" and not m.success and "G \"o1 in r1\"" in m.reason
    assert [x.outcome for x in m.tasks] == ["superseded", "unsatisfiable"]


def test_a_task_done_at_once_holds_in_the_world_too(blocks):
    # At t = 5 the arm carries o1 out of r1; the belief still has every block in r1.
    world = rtamp.SymbolicWorld(blocks)
    loop = rtamp.ReactiveLoop(world, blocks, planning="inline", new_tasks=[(5, "F G all_in_r1", ALL_IN_R1)])
    m = loop.run()
    assert m.end == "task-done"
    assert world.truth.locations() == {"o1": "r1", "o2": "r1", "o3": "r1"}


def fresh_loop(s):
    loop = rtamp.ReactiveLoop(rtamp.SymbolicWorld(s), s, planning="inline")
    rec = Recorder()
    loop.add_observer(rec)
    assert loop.step()
    return loop, rec


def test_a_bad_formula_raises_with_where_and_caret_and_the_episode_goes_on(blocks):
    loop, rec = fresh_loop(blocks)
    with pytest.raises(rtamp.Error) as e:
        loop.set_task("F G (all_in_r2 &")
    err = e.value
    assert err.file == "set_task(formula)" and err.line == 1 and err.column == 17
    assert "expected an operand after '&'" in err.message and "new task at t = " in err.message
    assert err.detail.splitlines() == ["  F G (all_in_r2 &", " " * 18 + "^"]
    assert loop.step()  # the refusal is reported at the next step; the old task stays in force
    (d,) = rec.tasks()
    assert d["applied"] is False and "expected an operand" in d["refused"] and d["automaton_states"] is None
    m = loop.run()
    assert m.end == "task-done" and [x.task for x in m.tasks] == ["F G all_in_r2"]


def test_an_unknown_proposition_raises_naming_it(blocks):
    loop, _ = fresh_loop(blocks)
    with pytest.raises(rtamp.Error, match=r"'all_in_r3', which is not a proposition.*all_in_r2") as e:
        loop.set_task("F G all_in_r3")
    assert e.value.column == 5 and "^" in e.value.detail


def test_a_bad_or_redefined_proposition_raises_naming_it(blocks):
    loop, _ = fresh_loop(blocks)
    with pytest.raises(rtamp.Error) as e:
        loop.set_task("F G home", {"home": "all block on r1"})
    assert e.value.file == "set_task(propositions['home'])" and "expected 'in'" in e.value.message
    with pytest.raises(rtamp.Error, match="'all_in_r2' is already defined"):
        loop.set_task("F G all_in_r2", {"all_in_r2": "all block in r1"})
    # the same name with the same meaning is not a redefinition
    loop.set_task("F G all_in_r2", {"all_in_r2": "all block in r2"})


def test_set_task_after_the_end_raises(blocks):
    loop = rtamp.ReactiveLoop(rtamp.SymbolicWorld(blocks), blocks, planning="inline")
    assert loop.run().success and loop.ended
    with pytest.raises(rtamp.Error, match="the episode has ended"):
        loop.set_task("F G all_in_r1", ALL_IN_R1)
    assert len(loop.metrics.tasks) == 1


def test_scheduled_new_tasks_on_the_loop(blocks):
    world = rtamp.SymbolicWorld(blocks)
    loop = rtamp.ReactiveLoop(world, blocks, planning="inline",
                              new_tasks=[(12.5, "F G all_in_r1", ALL_IN_R1), (5, 'F G "o3 in r2"')])
    rec = Recorder()
    loop.add_observer(rec)
    m = loop.run()
    # taken in time order, each judged from its own switch
    assert [(x.task, x.by, x.outcome) for x in m.tasks] == [
        ("F G all_in_r2", "scenario", "superseded"), ('F G "o3 in r2"', "api", "superseded"),
        ("F G all_in_r1", "api", "task-done")]
    assert 5 <= m.tasks[1].time < 12.5 <= m.tasks[2].time
    assert [d["task"] for d in rec.tasks()] == ['F G "o3 in r2"', "F G all_in_r1"]
    assert holds_from(loop, "F G all_in_r1", loop.task_from)
    # it took effect on the work of the one before (o1 in r2), while o3 was on its way to r2:
    # that move, not defeating the new task, was finished
    assert loop.observed_run[loop.task_from].location_of("o1") == "r2"
    assert not holds_from(loop, "G !o3_in_r2", loop.task_from)
    assert world.truth.locations() == {"o1": "r1", "o2": "r1", "o3": "r1"}


def test_scheduled_new_tasks_are_checked_before_anything_runs(blocks):
    world = rtamp.SymbolicWorld(blocks)
    with pytest.raises(rtamp.Error) as e:
        rtamp.ReactiveLoop(world, blocks, new_tasks=[(1, "F G all_in_r1", ALL_IN_R1), (2, "F (")])
    assert e.value.file == "new_tasks[1](formula)"
    with pytest.raises(rtamp.Error, match="time"):
        rtamp.ReactiveLoop(world, blocks, new_tasks=[(-1, "F G all_in_r2")])
    with pytest.raises(TypeError):
        rtamp.ReactiveLoop(world, blocks, new_tasks=[("soon", "F G all_in_r2")])


def test_new_tasks_in_an_episode(blocks):
    o = rtamp.EpisodeOptions(world="symbolic", new_tasks=[(5, "F G all_in_r1", ALL_IN_R1)])
    assert o.new_tasks == [(5.0, "F G all_in_r1", ALL_IN_R1)]
    m = rtamp.run_episode(blocks, o)
    assert m.end == "task-done"
    assert [(x.task, x.by, x.outcome) for x in m.tasks] == [
        ("F G all_in_r2", "scenario", "superseded"), ("F G all_in_r1", "api", "task-done")]
    m = rtamp.run_episode(blocks, world="symbolic", new_tasks=[(5, 'F "o3 in r2"')])
    assert [x.outcome for x in m.tasks] == ["superseded", "task-done"]
    with pytest.raises(rtamp.Error, match="not a proposition"):
        rtamp.run_episode(blocks, world="symbolic", new_tasks=[(5, "F G all_in_r1")])


def docs_example():
    """The python block of docs/python.md's section "A new task while the robot works"."""
    path = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "python.md")
    with open(path) as f:
        text = f.read()
    section = text.split("### A new task while the robot works", 1)[1].split("\n#", 1)[0]
    (block,) = re.findall(r"```python\n(.*?)```", section, re.S)
    return block


def test_the_docs_example_runs_as_written(capsys):
    exec(compile(docs_example(), "docs/python.md", "exec"), {"rtamp": rtamp})
    out = capsys.readouterr().out
    assert "superseded" in out and "task-done" in out


def test_python_and_the_cli_give_the_same_new_tasks(blocks):
    """`rtamp run --new-task TIME@LTL --json` and run_episode(new_tasks=...) run the same episode."""
    binary = os.environ.get("RTAMP_BINARY")
    if not binary:
        pytest.skip("RTAMP_BINARY not set")
    tasks = [(5.0, 'F G "o3 in r2"'), (12.5, 'F G "o1 in r1" & F G "o3 in r1"')]
    args = [a for t, f in tasks for a in ("--new-task", f"{t:g}@{f}")]
    out = subprocess.run([binary, "run", "3-block", "--world", "symbolic", *args, "--json", "--quiet"],
                         capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    cli = json.loads(out.stdout)
    m = rtamp.run_episode(blocks, world="symbolic", new_tasks=tasks)
    mine = [{"time": x.time, "task": x.task, "by": x.by, "automaton_states": x.automaton_states,
             "cycles": x.cycles, "outcome": x.outcome} for x in m.tasks]
    theirs = [dict(x, by="api" if x["by"] == "command line" else x["by"]) for x in cli["tasks"]]
    assert mine == theirs and [x["outcome"] for x in mine] == ["superseded", "superseded", "task-done"]
    assert (cli["end"], cli["world_time"]) == (m.end, pytest.approx(m.world_time, abs=1e-9))
