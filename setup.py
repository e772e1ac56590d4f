"""Builds the Python module with the project's CMake (the alplan_python
target) and installs the one shared object it makes. ALPLAN_BUILD_DIR reuses
a configured build tree (scripts/build's); otherwise a fresh one is made
under the build_temp folder. Install with:

    pip install --no-build-isolation .
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    """The version in CMakeLists.txt's project(): one place for the package,
    alplan.__version__ and `alplan --version`."""
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as cmake:
        match = re.search(r"project\(alplan VERSION ([0-9.]+)", cmake.read())
    if not match:
        raise RuntimeError("no project(alplan VERSION ...) in CMakeLists.txt")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        reused = os.environ.get("ALPLAN_BUILD_DIR")
        build = reused or os.path.join(os.path.abspath(self.build_temp), "cmake")
        if not reused:
            # A build tree of its own, for the interpreter pip runs under.
            # ALPLAN_COMPONENTS=planner: the module without the monitor, on a
            # machine with only the planner's dependencies.
            subprocess.check_call(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                                   "-DALPLAN_PYTHON=" + sys.executable, "-DALPLAN_BUILD_TESTS=OFF",
                                   "-DALPLAN_BUILD_BENCHMARKS=OFF",
                                   "-DALPLAN_COMPONENTS=" + os.environ.get("ALPLAN_COMPONENTS", "all")])
        # A reused tree keeps its configuration (ALPLAN_PYTHON among it): the
        # module is built for that interpreter, which must be pip's or its venv's base.
        subprocess.check_call(["cmake", "--build", build, "--target", "alplan_python", "-j", str(os.cpu_count() or 2)])
        built = [f for f in os.listdir(os.path.join(build, "python")) if f.startswith("alplan") and f.endswith(".so")]
        if not built:
            raise RuntimeError("CMake built no alplan*.so in " + os.path.join(build, "python"))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(build, "python", built[0]), target)


# packages=[]: the folders here are C++ libraries, not Python packages.
setup(version=project_version(), packages=[], ext_modules=[CMakeExtension("alplan")], cmdclass={"build_ext": CMakeBuild})
