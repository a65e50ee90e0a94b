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


# The head of a scenario (3 blocks, a tray, all_in_r2): the task goes on line 13.
_HEAD = """name: t
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.36, 0.36], capacity: 4}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.36, 0.36], capacity: 4}
containers:
  - {name: r3, class: tray, position: [0.40, 0.25, 0], size: [0.30, 0.16, 0.03], capacity: 3}
objects:
  - {name: o1, class: block, position: [0.32, 0.40, 0], size: [0.04, 0.04, 0.04]}
  - {name: o2, class: block, position: [0.40, 0.40, 0], size: [0.04, 0.04, 0.04]}
  - {name: o3, class: block, position: [0.48, 0.40, 0], size: [0.04, 0.04, 0.04]}
propositions:
  all_in_r2: "all block in r2"
"""


def test_planner_refuses_what_the_cli_refuses_with_the_same_location():
    # The messages and locations of tests/cli/bad_input_test.cpp's rows.
    cases = [
        ('F G "all blocks in r2"', "t.yaml:13:16: ", "unknown class 'blocks' (did you mean 'block'?)"),
        ('F G all_in_r3', "t.yaml:13:11: ", "not a proposition of the scenario"),
        ('>\n    F G all_in_r2 &\n    G "o1 in r9"\n', "t.yaml:15:14: ", "unknown location 'r9'"),
        ('|\n  F G all_in_r2\n  & & all_in_r2\n', "t.yaml:15:5: ", "expected a formula before '&'"),
    ]
    for task, where, what in cases:
        s = rtamp.parse_scenario(_HEAD + "task: " + task + "\n", "t.yaml")
        with pytest.raises(rtamp.Error) as e:
            rtamp.Planner(s)
        assert str(e.value).startswith(where), (task, str(e.value))
        assert what in str(e.value), (task, str(e.value))


def test_a_task_set_in_python_is_located_in_its_own_text():
    s = rtamp.parse_scenario(_HEAD + "task: |\n    F G all_in_r2\n", "t.yaml")
    s.task = 'F G "o1 in r9"'
    with pytest.raises(rtamp.Error) as e:
        rtamp.Planner(s)
    assert e.value.file != "t.yaml" and e.value.line == 1 and e.value.column == 12, str(e.value)


def test_planner_apply_refuses_what_plan_change_refuses():
    p = rtamp.Planner(rtamp.load_scenario("3-block-tray"))
    for change, what in [
        ("add-region in 0.4 0", "region name 'in' is a reserved word"),
        ("add o9 object r1", "class 'object' is reserved"),
        ("add-region r9 0.40 0.32", "overlaps region 'r1'"),
        ("add-region r9 0 0 99999999999999999999", "out of range"),
        ("move o1 r9", "unknown location 'r9'"),
    ]:
        with pytest.raises(rtamp.Error, match=what.replace("(", r"\(").replace(")", r"\)")):
            p.apply(change)


@pytest.mark.parametrize("option,value", [
    ("max_time", float("nan")), ("max_time", 0.0), ("max_time", -5.0),
    ("tick_period", 0.0), ("tick_period", float("nan")),
    ("outside_grace", float("nan")), ("max_failures_per_move", 0), ("cycles", -1),
])
def test_run_episode_refuses_loop_options_out_of_range(option, value, tmp_path):
    s = rtamp.load_scenario("3-block")
    log = tmp_path / "ep.jsonl"
    with pytest.raises(rtamp.Error, match="loop option " + option):
        rtamp.run_episode(s, world="symbolic", log=str(log), **{option: value})
    assert not log.exists()  # refused before the log was opened


def test_run_episode_checks_the_task_before_it_opens_the_log(tmp_path):
    s = rtamp.parse_scenario(_HEAD + 'task: F G "all blocks in r2"\n', "t.yaml")
    log = tmp_path / "ep.jsonl"
    with pytest.raises(rtamp.Error, match="t.yaml:13:16: .*unknown class 'blocks'"):
        rtamp.run_episode(s, world="symbolic", log=str(log), random_rate=0.0)
    with pytest.raises(rtamp.Error, match="rate of random interventions"):
        rtamp.run_episode(rtamp.load_scenario("3-block"), world="symbolic", log=str(log), random_rate=-1.0)
    assert not log.exists()


def test_run_episode_refuses_bad_outputs_before_it_starts(tmp_path):
    s = rtamp.load_scenario("3-block")
    with pytest.raises(rtamp.Error, match="log: cannot write '.*ep.jsonl': no directory"):
        rtamp.run_episode(s, world="symbolic", log=str(tmp_path / "no_dir" / "ep.jsonl"))
    with pytest.raises(rtamp.Error, match="MuJoCo world"):
        rtamp.run_episode(s, world="symbolic", video=str(tmp_path / "v.mp4"))
    assert not (tmp_path / "v.mp4").exists()


# Wrong types are TypeErrors that say what was expected, not pybind11's
# "Unable to cast Python instance" RuntimeError.
def test_a_wrong_argument_type_names_the_argument_and_its_type():
    with pytest.raises(TypeError, match=r"path_or_builtin: str"):
        rtamp.load_scenario(3)


@pytest.mark.parametrize("call, text", [
    (lambda s: rtamp.load_scenario(3), "load_scenario(): argument 'path_or_builtin' must be str, not int"),
    (lambda s: rtamp.Planner(3), "Planner(): argument 'scenario' must be Scenario, not int"),
    (lambda s: rtamp.Planner(s, algorithm=5), "Planner(): argument 'algorithm' must be str, not int"),
    (lambda s: rtamp.Planner(s, time_limit="soon"), "Planner(): argument 'time_limit' must be float, not str"),
    (lambda s: rtamp.Planner(s, bogus=1), "Planner(): unexpected keyword argument 'bogus'"),
    (lambda s: rtamp.Planner(s, s), "Planner(): takes 1 positional argument but 2 were given"),
    (lambda s: rtamp.Planner(s).forbid_move(1, "r2"), "Planner.forbid_move(): argument 'thing' must be str, not int"),
    (lambda s: rtamp.Change.add_object(3, "block", "r1"), "Change.add_object(): argument 'object' must be str, not int"),
])
def test_a_wrong_argument_to_a_function_or_constructor_is_named(call, text):
    s = rtamp.load_scenario("3-block")
    with pytest.raises(TypeError) as e:
        call(s)
    first, _, rest = str(e.value).partition("\n")
    assert first == text
    assert "incompatible" in rest  # pybind11's signatures kept below


def test_named_arguments_keep_the_functions_usable():
    import pickle
    assert pickle.loads(pickle.dumps(rtamp.load_scenario)) is rtamp.load_scenario
    assert rtamp.load_scenario.__doc__.startswith("load_scenario(path_or_builtin: str)")
    assert rtamp.Planner(rtamp.load_scenario("3-block"), time_limit=5).plan().found  # an int for a float


def test_a_cost_that_is_neither_a_name_nor_a_cost_model_is_a_type_error():
    s = rtamp.load_scenario("3-block")
    with pytest.raises(TypeError, match=r"argument 'cost' must be a cost-model name \(str\) or a CostModel, not int"):
        rtamp.Planner(s, cost=3)


def test_a_cost_model_returning_the_wrong_type_is_a_type_error_naming_the_method():
    class Wrong(rtamp.CostModel):
        def cost(self, q):
            return "far"

    s = rtamp.load_scenario("3-block")
    with pytest.raises(TypeError, match=r"CostModel\.cost\(\) must return float, not str"):
        rtamp.Planner(s, cost=Wrong()).plan()



def test_a_value_pybind11_cannot_convert_is_a_type_error_naming_its_type():
    # PYBIND11_DETAILED_ERROR_MESSAGES: the Python type is named, not "#define ... for details".
    p = rtamp.Planner(rtamp.load_scenario("3-block"))
    with pytest.raises(TypeError, match=r"Unable to cast Python instance of type <class 'int'>") as e:
        p.set_placement({"o1": (3, "block")})
    assert "PYBIND11_DETAILED_ERROR_MESSAGES" not in str(e.value)


# The classes Python overrides name a wrong argument too, and an override is still found.
@pytest.mark.parametrize("call, text", [
    (lambda s: rtamp.SymbolicWorld(s).advance("soon"), "World.advance(): argument 'dt' must be float, not str"),
    (lambda s: rtamp.SymbolicWorld(s).start(3), "World.start(): argument 'move' must be Move, not int"),
    (lambda s: rtamp.SymbolicWorld(s).apply("add"),
     "SymbolicWorld.apply(): argument 'intervention' must be Intervention, not str"),
    (lambda s: rtamp.cost_model("euclid", s).cost(3), "CostModel.cost(): argument 'query' must be MotionQuery, not int"),
])
def test_a_wrong_argument_to_a_method_of_an_overridable_class_is_named(call, text):
    s = rtamp.load_scenario("3-block")
    with pytest.raises(TypeError) as e:
        call(s)
    assert str(e.value).partition("\n")[0] == text


def test_overrides_are_still_found_and_defaults_still_reached():
    calls = []

    class Counting(rtamp.CostModel):
        def cost(self, q):  # lower_bound, depends, expensive: the C++ defaults
            calls.append(q.thing_name)
            return 1.0

    s = rtamp.load_scenario("3-block")
    plan = rtamp.Planner(s, cost=Counting()).plan()
    assert plan.found and calls
    model = Counting()
    assert model.expensive() is True  # the C++ defaults through the wrappers, no recursion
    assert model.depends() == rtamp.DEPENDS_ALL
    assert rtamp.CostModel.cost.__doc__.startswith("cost(self")


def test_an_override_may_call_the_cpp_default_through_super():
    class Bounded(rtamp.CostModel):
        def cost(self, q):
            return 1.0

        def lower_bound(self, q, to_anywhere):
            return super().lower_bound(q, to_anywhere)  # the C++ default (0), not this method again

    plan = rtamp.Planner(rtamp.load_scenario("3-block"), algorithm="astar", cost=Bounded()).plan()
    assert plan.found
