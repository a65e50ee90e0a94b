"""pytest setup for the rtamp module's tests (python/tests).

The module must come from the build tree named by PYTHONPATH (ctest sets it),
never from somewhere else; a run that collects no test fails (pytest's exit 5
is a failure in ctest too, and this hook makes it one in any runner).
"""

import os
import sys

import pytest

import rtamp


def pytest_report_header(config):
    return f"rtamp module: {rtamp.__file__}"


def pytest_collection_finish(session):
    path = os.environ.get("PYTHONPATH", "")
    if path and not os.path.abspath(rtamp.__file__).startswith(os.path.abspath(path.split(os.pathsep)[0])):
        raise pytest.UsageError(f"rtamp imported from {rtamp.__file__}, not from PYTHONPATH={path}")


def pytest_sessionfinish(session, exitstatus):
    if session.testscollected == 0:
        sys.stderr.write("rtamp python tests: no tests ran\n")
        session.exitstatus = 1


@pytest.fixture
def tray():
    return rtamp.load_scenario("3-block-tray")
