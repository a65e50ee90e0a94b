"""rtamp's own worlds from Python: the symbolic world (directly and in the loop) and the MuJoCo UR5."""

import json
import os

import pytest

import rtamp


def test_symbolic_world_directly(tray):
    w = rtamp.SymbolicWorld(tray, seed=3)
    assert w.observe().locations() == rtamp.initial_placement(tray).locations()
    assert w.time() == 0 and w.phase == "idle" and w.hand() == "" and not w.busy()
    w.start(rtamp.Move("o1", "r1", "r2"))
    assert w.poll()[0] == rtamp.MoveStatus.RUNNING
    while w.poll()[0] == rtamp.MoveStatus.RUNNING:
        w.advance(w.next_event_time() - w.time())
    assert w.poll()[0] == rtamp.MoveStatus.SUCCEEDED and w.truth.location_of("o1") == "r2"
    assert w.hand() == "r2" and w.check_invariants() == ""
    ev = w.apply(rtamp.Intervention("relocate", "o1", "r1"))
    assert ev.applied and w.truth.location_of("o1") == "r1"
    assert len(w.history) == 1 and w.capacity("r1") == 4 and w.capacity("zz") == -1
    assert w.refusal("o1", "r2") == ""


def test_symbolic_world_in_the_loop_with_failures(tray):
    inner = rtamp.SymbolicWorld(tray, seed=1, fails=lambda m: m.thing == "o1" and m.to == "r3")
    w = rtamp.PersonWorld(inner, rtamp.Person(tray, script=tray.interventions))
    m = rtamp.ReactiveLoop(w, tray, planning="inline", world_name="symbolic").run()
    assert m.success and m.interventions == 1


def test_run_episode_symbolic_with_log_and_timeline(tray, tmp_path):
    lines = []
    log = tmp_path / "ep.jsonl"
    m = rtamp.run_episode(tray, world="symbolic", planning="inline", seed=2, log=str(log), timeline=lines.append,
                          random_change="relocate")
    assert m.success and m.end == "task-done" and lines
    records = [json.loads(x) for x in log.read_text().splitlines()]
    assert records[-1]["ev"] == "end" and records[-1]["end"] == "task-done"
    with pytest.raises(rtamp.Error):
        rtamp.run_episode(tray, world="symbolic", video=str(tmp_path / "v.mp4"))
    with pytest.raises(rtamp.Error):
        rtamp.run_episode(tray, world="moon")


def test_mujoco_world_observes_the_scene(tray):
    w = rtamp.MujocoWorld(tray, seed=1)
    assert w.observe().locations() == rtamp.initial_placement(tray).locations()
    w.advance(0.1)
    assert w.time() == pytest.approx(0.1, abs=0.01)


@pytest.mark.skipif(os.environ.get("RTAMP_SKIP_MUJOCO_EPISODE") == "1", reason="asked to skip")
def test_mujoco_episode_short(tmp_path):
    s = rtamp.load_scenario("3-block")
    m = rtamp.run_episode(s, world="mujoco", seed=1, max_time=60, scripted_operator=False)
    assert m.success and m.world_time > 1 and m.real_time_factor > 0


def test_choices_are_the_tables_the_command_line_reads():
    import subprocess
    c = rtamp.choices()
    assert list(c["bt"]) == ["online-action", "online-state", "offline"]
    assert list(c["world"]) == ["mujoco", "symbolic"]
    assert list(c["change"]) == ["relocate", "remove", "add"]
    assert "take-from-gripper" in c["intervention"] and all(c["planning"].values())
    rtamp_bin = os.environ.get("RTAMP_BINARY")  # set by ctest
    if rtamp_bin:
        helptext = subprocess.run([rtamp_bin, "run", "--help"], capture_output=True, text=True).stdout
        for key in ("bt", "world", "planning", "change"):
            for name, description in c[key].items():
                assert name in helptext and description in " ".join(helptext.split()), (key, name)


def test_one_person_acts_alike_on_a_python_world_and_the_symbolic_world():
    from rtamp.toy import ToyWorld
    s = rtamp.load_scenario("3-block")

    def drive(world):
        person = rtamp.Person(s, rate=0.5, end=10, kinds=["relocate"], seed=4)
        w = rtamp.PersonWorld(world, person)
        seen = []
        while w.time() < 10:
            w.advance(0.02)
            seen += [(round(e.time, 9), e.what.subject, e.what.location, e.applied) for e in w.take_events()]
        return seen

    python_world = drive(ToyWorld(s))
    symbolic = drive(rtamp.SymbolicWorld(s))
    assert len(python_world) >= 2
    assert python_world == symbolic


def test_a_person_needs_a_world_that_takes_interventions():
    class Plain(rtamp.World):
        def time(self):
            return 0.0

    with pytest.raises(rtamp.Error, match="cannot take a person's interventions"):
        rtamp.PersonWorld(Plain(), rtamp.Person(rtamp.load_scenario("3-block")))
