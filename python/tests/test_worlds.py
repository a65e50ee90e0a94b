"""rtamp's own worlds from Python: the symbolic world (directly and in the loop) and the MuJoCo UR5."""

import json
import os
import subprocess

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


def test_mujoco_world_takes_interventions_from_python(tray):
    # The intervention capability (exec/intervenable.hpp), as `rtamp sim --do` uses it.
    w = rtamp.MujocoWorld(tray, seed=1)
    start = rtamp.initial_placement(tray).locations()
    ev = w.apply(rtamp.Intervention("relocate", "o1", "r2"))
    assert ev.applied
    truth = w.true_placement()
    assert truth.location_of("o1") == "r2" != start["o1"]
    w.advance(0.5)  # the block settles where it was put; perception sees it there
    assert w.observe().location_of("o1") == "r2"
    refused = w.apply(rtamp.Intervention("relocate", "nothing", "r2"))
    assert not refused.applied and w.true_placement().location_of("o1") == "r2"


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


def test_episode_options_are_one_struct_checked_when_set(tray, tmp_path):
    assert set(rtamp.worlds()) >= {"mujoco", "symbolic"}
    assert rtamp.EpisodeOptions().planning == "worker"
    o = rtamp.EpisodeOptions(world="symbolic", seed=3, random_change="add", change_window=(5, 10))
    assert (o.world, o.planning, o.seed, o.random_change, o.change_window) == ("symbolic", "inline", 3, "add", (5, 10))
    with pytest.raises(TypeError, match="did you mean 'random_rate'"):
        rtamp.EpisodeOptions(random_rat=1.0)
    with pytest.raises(rtamp.Error, match="did you mean 'symbolic'"):
        rtamp.EpisodeOptions(world="symbolik")
    with pytest.raises(rtamp.Error, match="no random_change"):
        rtamp.EpisodeOptions(change_window=(1, 2))
    with pytest.raises(rtamp.Error, match="unknown algorithm"):
        o.algorithm = "astr"
    # Keywords override a copy: `o` itself is unchanged.
    log = tmp_path / "a.jsonl"
    m = rtamp.run_episode(tray, o, log=str(log))
    assert o.log == "" and log.exists() and m.interventions == 2  # the scenario's script and the random add


def test_python_and_the_cli_fill_in_the_same_episode(tray):
    """The same options through `rtamp run --json` and run_episode give the same episode."""
    binary = os.environ.get("RTAMP_BINARY")
    if not binary:
        pytest.skip("RTAMP_BINARY not set")
    args = ["--world", "symbolic", "--seed", "4", "--change", "relocate", "--rate", "0.05", "--bt", "online-state",
            "--algo", "astar", "--max-time", "400"]
    out = subprocess.run([binary, "run", "3-block-tray", *args, "--json", "--quiet"], capture_output=True, text=True)
    assert out.returncode in (0, 1), out.stderr
    cli = json.loads(out.stdout)
    m = rtamp.run_episode(tray, world="symbolic", seed=4, random_change="relocate", random_rate=0.05,
                          conditions="state", algorithm="astar", max_time=400)
    assert (cli["success"], cli["end"], cli["interventions"], cli["replans"], cli["actions_succeeded"]) == \
        (m.success, m.end, m.interventions, m.replans, m.actions_succeeded)
    assert cli["world_time"] == pytest.approx(m.world_time, abs=1e-9)
