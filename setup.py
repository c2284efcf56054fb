"""Builds the extension surface_mesh_direction_fields._core with the project's
CMake (the target surface_mesh_direction_fields), for pip (pyproject.toml).

The CMake build folder is outside the work tree: SMDF_CMAKE_BUILD_DIR if set
(the tests reuse theirs), else one per Python version under the user's cache
(XDG_CACHE_HOME or ~/.cache, surface-mesh-direction-fields/), so that a second
pip install recompiles only what changed. The interpreter running pip is the
one the module is built for: it needs numpy and pybind11 (Debian's
python3-pybind11, or pybind11 from pip), which are checked first.

pip shows a build's output only with -v; so the steps, the files being
compiled and the time so far are also written to the terminal (/dev/tty) when
there is one."""
import hashlib
import os
import re
import shutil
import subprocess
import sys
import threading
import time

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
NAME = "surface-mesh-direction-fields"


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(Surface_mesh_direction_fields VERSION ([0-9.]+)", f.read()).group(1)


def cache_folder():
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    interpreter = hashlib.sha256(sys.executable.encode()).hexdigest()[:10]  # one folder per interpreter
    return os.path.join(cache, NAME, f"{version}-{interpreter}")


class Terminal:
    """What the build is doing, on the terminal pip does not capture (if any), and on stdout (pip -v)."""

    def __init__(self):
        try:
            self.tty = open("/dev/tty", "w")
        except OSError:
            self.tty = None
        self.start = time.monotonic()

    def say(self, line, end="\n"):
        stamp = f"{NAME}: {line} ({time.monotonic() - self.start:.0f} s)"
        print(stamp, flush=True)
        if self.tty:
            self.tty.write("\r" + stamp + " " * 8 + end)
            self.tty.flush()


def required_modules(terminal):
    """numpy and pybind11 in the Python pip runs; pybind11's CMake files for CMake."""
    missing = []
    for module in ("numpy", "pybind11"):
        try:
            __import__(module)
        except ImportError:
            missing.append(module)
    if missing:
        sys.exit(f"{NAME}: {sys.executable} has no {' and no '.join(missing)}: install "
                 f"{' and '.join(missing)} for it (Debian's Python: apt install "
                 f"{' '.join('python3-' + m for m in missing)})")
    import pybind11
    terminal.say(f"building for {sys.executable} (Python {sys.version.split()[0]}, pybind11 {pybind11.__version__})")
    return pybind11.get_cmake_dir()


def run_cmake_build(build, terminal):
    """cmake --build of the module's target; the files being compiled and the time so far shown on the
    terminal every two seconds (CMake's own percentages count targets, not time)."""
    jobs = str(os.cpu_count() or 1)
    command = ["cmake", "--build", build, "--target", "surface_mesh_direction_fields", "-j", jobs]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    compiling = []
    done = threading.Event()

    def tick():
        while not done.wait(2.0):
            if compiling:
                terminal.say(f"compiling {', '.join(compiling)} with {jobs} jobs", end="")

    ticker = threading.Thread(target=tick, daemon=True)
    ticker.start()
    for line in process.stdout:
        print(line, end="", flush=True)
        source = re.search(r"Building CXX object .*/([^/]+)\.o$", line.strip())
        if source:
            compiling.append(source.group(1))
    done.set()
    ticker.join()
    if process.wait() != 0:
        sys.exit(f"{NAME}: the build failed ({' '.join(command)}); pip install -v shows its output")
    terminal.say("compiled")


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        terminal = Terminal()
        pybind11_cmake = required_modules(terminal)
        build = os.environ.get("SMDF_CMAKE_BUILD_DIR") or cache_folder()
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            terminal.say(f"configuring CMake in {build} (compiling takes minutes: 2 to 3 on 2 cores)")
            subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                            "-DSMDF_BUILD_PYTHON=ON", "-DSMDF_BUILD_TESTS=OFF", "-DSMDF_BUILD_EXAMPLES=OFF",
                            f"-DPYTHON_EXECUTABLE={sys.executable}", f"-Dpybind11_DIR={pybind11_cmake}"],
                           check=True, stdout=sys.stdout)
        run_cmake_build(build, terminal)
        package = os.path.join(build, "python", "surface_mesh_direction_fields")
        built = [f for f in os.listdir(package) if f.startswith("_core.") and f.endswith(".so")]
        if len(built) != 1:
            sys.exit(f"setup.py: expected one _core extension in {package}, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)
        terminal.say("extension built")


# setuptools' own folders (build/, the egg-info) in the cache too, not in the work tree
WORK = os.environ.get("SMDF_CMAKE_BUILD_DIR") or cache_folder()
os.makedirs(os.path.join(WORK, "setuptools"), exist_ok=True)  # egg_base must exist
setup(version=project_version(),
      ext_modules=[Extension("surface_mesh_direction_fields._core", sources=[])],
      cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": os.path.join(WORK, "setuptools", "build")},
               "egg_info": {"egg_base": os.path.join(WORK, "setuptools")}})
