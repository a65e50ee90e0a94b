"""rtamp::Error arrives as rtamp.Error, a ValueError, with message, file, line and column."""

import pytest

import rtamp


def test_error_is_a_value_error():
    assert issubclass(rtamp.Error, ValueError)


def test_ltl_syntax_error_has_line_and_column():
    with pytest.raises(rtamp.Error) as e:
        rtamp.parse("F (a &")
    err = e.value
    assert isinstance(err, ValueError)
    assert err.line == 1 and err.column is not None and err.column >= 6
    assert err.file is None
    assert err.message and err.message in str(err)
    assert "^" in err.detail


def test_yaml_error_has_file_line_column():
    text = "name: x\nregions:\n  - name: r1\n    centre: [0, 0, 0]\n"
    with pytest.raises(rtamp.Error) as e:
        rtamp.parse_scenario(text, "mine.yaml")
    err = e.value
    assert err.file == "mine.yaml"
    assert err.line == 4 and err.column == 5
    assert str(err).startswith("mine.yaml:4:5: ")


def test_unknown_names_and_options():
    s = rtamp.load_scenario("3-block")
    with pytest.raises(rtamp.Error, match="algorithm"):
        rtamp.Planner(s, algorithm="astr")
    with pytest.raises(rtamp.Error, match="cost"):
        rtamp.Planner(s, cost="nope")
    with pytest.raises(rtamp.Error):
        rtamp.load_scenario("no-such-scenario-or-file")
    p = rtamp.Planner(s)
    with pytest.raises(rtamp.Error):
        p.apply("move o9 r1")
    with pytest.raises(rtamp.Error):
        rtamp.Change.parse("teleport o1")


def test_bad_task_in_scenario():
    s = rtamp.load_scenario("3-block")
    s.task = "F (all_in_r2"
    with pytest.raises(rtamp.Error) as e:
        rtamp.Planner(s)
    assert e.value.column is not None


def test_logging_hooks_are_explicit_calls():
    # Nothing happens on import; the two calls exist and are idempotent.
    for _ in range(2):
        rtamp.install_mujoco_log_handler()
        rtamp.quiet_ompl_logging()
