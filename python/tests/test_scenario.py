"""Scenario bindings: built-ins, files, YAML text, generated scenes, placements."""

import pickle

import pytest

import rtamp


def test_builtins():
    names = rtamp.builtin_scenarios()
    assert "3-block" in names and "3-block-tray" in names
    s = rtamp.load_scenario("3-block-tray")
    assert s.name == "3-block-tray" and s.task == "F G all_in_r2"
    assert [r.name for r in s.regions] == ["r1", "r2"]
    assert [c.name for c in s.containers] == ["r3"] and s.containers[0].cls == "tray"
    assert [o.name for o in s.objects] == ["o1", "o2", "o3"]
    assert s.propositions[0].name == "all_in_r2" and s.propositions[0].text == "all block in r2"
    assert s.interventions[0].kind == "relocate" and s.interventions[0].subject == "o2"
    assert s.robot.model == "ur5"
    assert rtamp.builtin_scenario_text("3-block-tray").startswith("#")
    assert rtamp.builtin_scenario_text("nope") is None


def test_yaml_round_trip_and_file(tmp_path):
    s = rtamp.load_scenario("3-block-tray")
    y = s.to_yaml()
    assert rtamp.to_yaml(s) == y
    t = rtamp.parse_scenario(y, "copy.yaml")
    assert t.to_yaml() == y and t.source == "copy.yaml"
    p = tmp_path / "mine.yaml"
    p.write_text(y)
    u = rtamp.load_scenario(str(p))
    assert u.to_yaml() == y and u.source == str(p)
    assert pickle.loads(pickle.dumps(s)).to_yaml() == y


def test_edit_and_validate():
    s = rtamp.load_scenario("3-block")
    s.objects = s.objects + [rtamp.Object("o4", position=[0.4, 0.3, 0])]
    s.regions = s.regions + [rtamp.Region("r9", center=[0.5, 0.0, 0], size=[0.2, 0.2, 0], capacity=2)]
    s.validate()
    assert len(s.copy().objects) == 4
    s.objects = s.objects + [rtamp.Object("o4")]
    with pytest.raises(rtamp.Error):
        s.validate()


def test_generate_like_rtamp_gen():
    a = rtamp.generate_scenario(regions=5, objects=4, containers=1, layout="random", seed=3,
                                propositions=[("o1_in_r3", "o1 in r3")])
    b = rtamp.generate_scenario(regions=5, objects=4, containers=1, layout="random", seed=3,
                                propositions=[("o1_in_r3", "o1 in r3")])
    assert a.to_yaml() == b.to_yaml()
    assert len(a.regions) == 5 and len(a.objects) == 4 and len(a.containers) == 1
    assert [p.name for p in a.propositions] == ["all_in_r2", "o1_in_r3"]
    assert a.task == "F G all_in_r2"
    assert rtamp.generate_scenario(task="F o1_in_r2", propositions=[("o1_in_r2", "o1 in r2")]).task == "F o1_in_r2"
    with pytest.raises(rtamp.Error):
        rtamp.generate_scenario(regions=0)
    with pytest.raises(rtamp.Error):
        rtamp.generate_scenario(layout="spiral")


def test_placement():
    s = rtamp.load_scenario("3-block-tray")
    p = rtamp.initial_placement(s)
    assert p.locations() == {"o1": "r1", "o2": "r1", "o3": "r1", "r3": "r1"}
    assert p.things["r3"].container and p.things["o1"].cls == "block"
    assert p.location_of("o1") == "r1" and p.location_of("zz") is None
    q = rtamp.Placement()
    q.set("o1", "r2")
    assert len(q) == 1 and q.things["o1"] == rtamp.Thing("r2", "block")
    assert p != q


def test_intervention():
    iv = rtamp.Intervention("add", "o9", "r1", cls="block", time=3.0)
    assert iv.kind == "add" and iv.time == 3.0
    iv.kind = "remove"
    assert iv.kind == "remove"
    with pytest.raises(rtamp.Error):
        rtamp.Intervention("explode")
