"""Options of the module's tests, and CTest's SKIP: a run whose tests all passed
but left some out because the program or the shared meshes were missing exits
77 (test_python_module's SKIP_RETURN_CODE), never a silent pass."""
import os

import pytest

# the start of every skip reason that means "an input of the test is missing"
MISSING_INPUT = "missing input: "
missing_inputs = []


def pytest_addoption(parser):
    parser.addoption("--direction-field", default="", help="the command-line program, to compare with")
    parser.addoption("--shared", default="", help="the shared mesh folder (tests that need it skip without it)")
    parser.addoption("--installed-in", default="", help="a virtual environment the package must be imported from")


@pytest.fixture
def program(request):
    path = request.config.getoption("--direction-field")
    if not path:
        pytest.skip(MISSING_INPUT + "no direction_field given")
    return path


@pytest.fixture
def shared(request):
    folder = request.config.getoption("--shared")
    if not folder or not os.path.isdir(folder):
        pytest.skip(MISSING_INPUT + "no shared meshes")
    return folder


def pytest_configure(config):
    # the tests of an installed package run on that package, not on a build folder's
    folder = config.getoption("--installed-in")
    if folder:
        import surface_mesh_direction_fields as smdf
        if not smdf.__file__.startswith(folder):
            raise pytest.UsageError(f"surface_mesh_direction_fields imported from {smdf.__file__}, not {folder}")


def pytest_runtest_logreport(report):
    if report.skipped and MISSING_INPUT in str(report.longrepr):
        missing_inputs.append(report.nodeid)


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session, exitstatus):
    if exitstatus == 0 and missing_inputs:
        print(f"\nSKIPPED: {len(missing_inputs)} tests without their inputs (program or shared meshes)")
        session.exitstatus = 77
