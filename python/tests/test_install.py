"""The installed package: `cmake --install` of the build tree, and `pip install .` of the source tree.

Each installs into a temporary directory and imports rtamp from a fresh
interpreter whose only addition to the path is that directory (run from an
empty directory, with no PYTHONPATH to the build tree). The build and source
trees come from ctest (RTAMP_BUILD_DIR, RTAMP_SOURCE_DIR); pip reuses the
build tree (RTAMP_CMAKE_BUILD_DIR), so nothing is compiled again.
"""

import glob
import os
import re
import subprocess
import sys

import pytest

BUILD = os.environ.get("RTAMP_BUILD_DIR")
SOURCE = os.environ.get("RTAMP_SOURCE_DIR")
pytestmark = pytest.mark.skipif(not BUILD or not SOURCE, reason="needs RTAMP_BUILD_DIR and RTAMP_SOURCE_DIR (ctest sets them)")

# What the fresh interpreter checks: where rtamp comes from, its version, that it plans,
# and that the stubs and py.typed sit next to the extension.
PROBE = """
import os, sys, rtamp
d = os.path.dirname(rtamp.__file__)
assert os.path.exists(os.path.join(d, "_rtamp.pyi")) and os.path.exists(os.path.join(d, "py.typed")), os.listdir(d)
plan = rtamp.Planner(rtamp.load_scenario("3-block-tray")).plan()
print(rtamp.__file__)
print(rtamp.__version__)
print(rtamp._rtamp.__file__)
print(len(plan.moves))
"""


def cmake_version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        return re.search(r"project\(rtamp VERSION ([0-9.]+)", f.read()).group(1)


def fresh_python(path, cwd, code=PROBE):
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": path, "PYTHONNOUSERSITE": "1", "PYTHONDONTWRITEBYTECODE": "1"}
    r = subprocess.run([sys.executable, "-c", code], env=env, cwd=cwd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout.split("\n")


def test_cmake_install_puts_an_importable_package_under_the_prefix(tmp_path):
    prefix = tmp_path / "prefix"
    r = subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix), "--component", "python"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    packages = glob.glob(str(prefix / "lib" / "python3*" / "dist-packages" / "rtamp"))
    assert len(packages) == 1, os.listdir(prefix)
    site = os.path.dirname(packages[0])
    assert f"rtamp: Python package in {packages[0]}" in r.stdout  # install says where
    (tmp_path / "empty").mkdir()
    where, version, ext, moves, _ = fresh_python(site, tmp_path / "empty")
    assert where == os.path.join(packages[0], "__init__.py")
    assert ext.startswith(packages[0] + os.sep)
    assert version == cmake_version()
    assert int(moves) > 0


def has_packaging_tools():
    r = subprocess.run([sys.executable, "-c", "import setuptools, wheel, pip"], capture_output=True)
    return r.returncode == 0


@pytest.mark.skipif(not has_packaging_tools(), reason="pip install needs Debian's python3-pip, python3-setuptools and python3-wheel")
def test_pip_install_from_the_source_tree_offline(tmp_path):
    target = tmp_path / "target"
    env = dict(os.environ, RTAMP_CMAKE_BUILD_DIR=BUILD, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)
    r = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-index",
                        "--target", str(target), SOURCE], env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    (tmp_path / "empty").mkdir()
    where, version, ext, moves, _ = fresh_python(str(target), tmp_path / "empty")
    assert where == str(target / "rtamp" / "__init__.py")
    assert ext.startswith(str(target / "rtamp") + os.sep)
    assert version == cmake_version()
    # The distribution's metadata carries the same version.
    meta = fresh_python(str(target), tmp_path / "empty", "import importlib.metadata as m; print(m.version('rtamp'))")
    assert meta[0] == cmake_version()
