def pytest_addoption(parser):
    parser.addoption("--direction-field", default="", help="the command-line program, to compare with")
    parser.addoption("--shared", default="", help="the shared mesh folder (tests that need it skip without it)")
