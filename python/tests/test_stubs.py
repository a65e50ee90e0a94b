"""The type stubs rtamp/_rtamp.pyi written at build time by python/stubgen.py.

The stub parses; it names every public function, class, method and property of
the module; each function's parameters are those pybind11 reports; mypy's
stubtest (Debian's python3-mypy; skipped without it) compares it with the
module as an independent reader, and mypy type-checks a small user of it.
"""

import ast
import inspect
import os
import re
import subprocess
import sys

import pytest

import rtamp
from rtamp import _rtamp

STUB = os.path.join(os.path.dirname(_rtamp.__file__), "_rtamp.pyi")


@pytest.fixture(scope="module")
def tree():
    with open(STUB) as f:
        return ast.parse(f.read(), STUB)


def top_level(tree):
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.setdefault(node.name, []).append(node)
        elif isinstance(node, ast.AnnAssign):
            names.setdefault(node.target.id, []).append(node)
    return names


def test_every_public_name_of_the_module_has_a_stub(tree):
    names = top_level(tree)
    public = [n for n in dir(_rtamp) if not n.startswith("_")]
    assert public
    assert [n for n in public if n not in names] == []
    assert "__version__" in names


def test_every_method_and_property_of_each_class_has_a_stub(tree):
    names = top_level(tree)
    missing = []
    for n in dir(_rtamp):
        cls = getattr(_rtamp, n)
        if n.startswith("_") or not inspect.isclass(cls):
            continue
        members = {m.name if hasattr(m, "name") else m.target.id for m in names[n][0].body
                   if isinstance(m, (ast.FunctionDef, ast.AnnAssign))}
        for attr in cls.__dict__:
            if not attr.startswith("_") and attr not in members:
                missing.append(f"{n}.{attr}")
    assert missing == []


def test_function_parameters_match_what_pybind11_reports(tree):
    names = top_level(tree)
    checked = 0
    for n in dir(_rtamp):
        f = getattr(_rtamp, n)
        if n.startswith("_") or inspect.isclass(f) or not callable(f):
            continue
        doc_sigs = re.findall(rf"^(?:\d+\. )?{n}\((.*)\)(?: -> .*)?$", f.__doc__, re.M)
        stubs = names[n]
        assert len(stubs) == len(doc_sigs), n
        for s, d in zip(stubs, doc_sigs):
            a = s.args
            params = [p.arg for p in a.args + ([a.vararg] if a.vararg else []) + a.kwonlyargs + ([a.kwarg] if a.kwarg else [])]
            while re.search(r"\[[^\[\]]*\]", d):  # drop the brackets of generic types: their commas are not parameters
                d = re.sub(r"\[[^\[\]]*\]", "", d)
            assert params == re.findall(r"(?:^|, )\*{0,2}(\w+)(?=: |,|$| =)", d), n
            checked += 1
    assert checked > 20


def test_a_real_call_matches_its_stub(tree):
    # The stub of Planner.plan names the type it returns, and that is what a call returns.
    planner = next(c for c in tree.body if isinstance(c, ast.ClassDef) and c.name == "Planner")
    plan = next(m for m in planner.body if isinstance(m, ast.FunctionDef) and m.name == "plan")
    returned = ast.unparse(plan.returns)
    assert type(rtamp.Planner(rtamp.load_scenario("3-block-tray")).plan()).__name__ == returned


def mypy_available():
    return subprocess.run([sys.executable, "-c", "import mypy.stubtest"], capture_output=True).returncode == 0


@pytest.mark.skipif(not mypy_available(), reason="needs Debian's python3-mypy (stubtest)")
def test_mypy_reads_the_stub_and_checks_a_user_against_it(tmp_path):
    user = tmp_path / "user.py"
    user.write_text("import rtamp._rtamp as r\n"
                    "plan = r.Planner(r.load_scenario('3-block-tray')).plan()\n"
                    "cost: float = plan.cost\n"
                    "bad: int = r.load_scenario(3)\n")
    env = dict(os.environ, MYPYPATH=os.path.dirname(os.path.dirname(STUB)))
    r = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
                        "--ignore-missing-imports", "--follow-imports=silent", str(user)], env=env, capture_output=True, text=True, cwd=tmp_path)
    out = r.stdout
    # The wrong line is caught (a str argument, a Scenario returned); the correct lines pass.
    assert "user.py:4:" in out and "user.py:2:" not in out and "user.py:3:" not in out, out


def test_the_new_task_api_is_typed(tree):
    # Typed as the module's other names are: no Any where pybind11 knows the type.
    classes = {c.name: c for c in tree.body if isinstance(c, ast.ClassDef)}

    def member(cls, name):
        return next(m for m in classes[cls].body if isinstance(m, ast.FunctionDef) and m.name == name)

    assert ast.unparse(member("EpisodeMetrics", "tasks").returns) == "List[TaskOutcome]"
    outcome = {m.name: ast.unparse(m.returns) for m in classes["TaskOutcome"].body if isinstance(m, ast.FunctionDef)}
    assert outcome == {"automaton_states": "int", "by": "str", "cycles": "int", "outcome": "str", "task": "str",
                       "time": "float"}
    set_task = member("ReactiveLoop", "set_task")
    assert [ast.unparse(a.annotation) for a in set_task.args.args[1:]] == ["str", "Optional[Dict[str, str]]"]
    assert ast.unparse(member("ReactiveLoop", "task_from").returns) == "int"
    new_tasks = "List[Union[Tuple[float, str], Tuple[float, str, Dict[str, str]]]]"
    assert ast.unparse(member("EpisodeOptions", "new_tasks").returns) == new_tasks
    init = member("ReactiveLoop", "__init__")
    assert ast.unparse(next(a for a in init.args.kwonlyargs if a.arg == "new_tasks").annotation) == new_tasks
