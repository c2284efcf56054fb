"""Builds the extension surface_mesh_direction_fields._core with the project's
CMake (the target surface_mesh_direction_fields), for pip (pyproject.toml).

SMDF_CMAKE_BUILD_DIR: an existing CMake build folder of this project to build
the target in (the tests reuse theirs); otherwise a folder of its own under
build-pip/. The interpreter running pip is the one the module is built for."""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(Surface_mesh_direction_fields VERSION ([0-9.]+)", f.read()).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("SMDF_CMAKE_BUILD_DIR") or os.path.join(ROOT, "build-pip", "cmake")
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                            "-DSMDF_BUILD_PYTHON=ON", "-DSMDF_BUILD_TESTS=OFF", "-DSMDF_BUILD_EXAMPLES=OFF",
                            f"-DPYTHON_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", build, "--target", "surface_mesh_direction_fields",
                        "-j", str(os.cpu_count() or 1)], check=True)
        package = os.path.join(build, "python", "surface_mesh_direction_fields")
        built = [f for f in os.listdir(package) if f.startswith("_core.") and f.endswith(".so")]
        if len(built) != 1:
            sys.exit(f"setup.py: expected one _core extension in {package}, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)


os.makedirs(os.path.join(ROOT, "build-pip"), exist_ok=True)  # egg_base must exist
setup(version=project_version(),
      ext_modules=[Extension("surface_mesh_direction_fields._core", sources=[])],
      cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": os.path.join("build-pip", "setuptools")},
               "egg_info": {"egg_base": "build-pip"}})
