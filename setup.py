# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The build of the Python package for pip and python -m build (metadata: pyproject.toml).

The extension point_set_curvatures._core is built by CMake, from this repository, as the
target point_set_curvatures_python only (the tests, examples, benchmarks and tool are not
configured), with the interpreter running this build (-DPython3_EXECUTABLE), then copied
into the package. The version is the CMake project's, read from CMakeLists.txt; the module
reports the same one (point_set_curvatures.__version__, compiled in from PROJECT_VERSION).

Environment:
  CMAKE_ARGS                            extra arguments of the CMake configuration (split on
                                        spaces), e.g. "-DCMAKE_CXX_COMPILER=clang++"
  CMAKE_BUILD_PARALLEL_LEVEL            parallel compile jobs (default: the number of cores;
                                        build_ext --parallel N too)
  POINT_SET_CURVATURES_CMAKE_BUILD_DIR  an already configured CMake build tree of this
                                        repository to build the target in instead of a fresh
                                        one (it must use the same Python interpreter); "fresh"
                                        for a fresh one always

Without it, the README's build tree (build/ beside this file) is reused where it is a Release
build, without sanitizers, of the same interpreter (a venv of it counts): after the README's
second command the extension is already built there, and pip takes it instead of compiling
everything again (minutes).
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
TARGET = "point_set_curvatures_python"


def cmake_project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(\s*Point_set_curvatures\s+VERSION\s+([0-9][0-9.]*)", f.read())
    if not m:
        raise RuntimeError("setup.py: no 'project(Point_set_curvatures VERSION x.y.z' in CMakeLists.txt")
    return m.group(1)


def cmake_cache(build_dir):
    """The entries NAME:TYPE=VALUE of a build tree's CMakeCache.txt, {} without one."""
    entries = {}
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt"), encoding="utf-8", errors="replace") as f:
            for line in f:
                m = re.match(r"([A-Za-z0-9_]+):[A-Z]+=(.*)$", line.rstrip("\n"))
                if m:
                    entries[m.group(1)] = m.group(2)
    except OSError:
        pass
    return entries


def reusable_build_tree(root=ROOT, interpreter=None):
    """root/build where pip can build the extension in it (see the module's docstring), else
    None; `interpreter`: the one running this build (default: this one's, a venv's base)."""
    build_dir = os.path.join(root, "build")
    cache = cmake_cache(build_dir)
    if not cache or cache.get("CMAKE_BUILD_TYPE") != "Release" or cache.get("POINT_SET_CURVATURES_SANITIZE"):
        return None
    if cache.get("POINT_SET_CURVATURES_BUILD_PYTHON") != "ON" or not cache.get("Python3_EXECUTABLE"):
        return None
    home = cache.get("CMAKE_HOME_DIRECTORY")
    if not home or os.path.realpath(home) != os.path.realpath(root):
        return None
    # the interpreter the tree was configured for against this one (a venv's: its base interpreter)
    if interpreter is None:
        interpreter = getattr(sys, "_base_executable", None) or sys.executable
    if os.path.realpath(cache["Python3_EXECUTABLE"]) != os.path.realpath(interpreter):
        return None
    return build_dir


class CMakeBuildExt(build_ext):
    """build_ext for one extension built by CMake (its sources are CMake's, not setuptools')."""

    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if cmake is None:
            raise RuntimeError("point_set_curvatures: CMake is needed to build the extension "
                               "(Debian: apt-get install cmake g++ libcgal-dev libeigen3-dev libtbb-dev)")
        build_dir = os.environ.get("POINT_SET_CURVATURES_CMAKE_BUILD_DIR")
        if build_dir == "fresh":
            build_dir = None
        elif not build_dir:
            build_dir = reusable_build_tree()
            if build_dir:
                print(f"point_set_curvatures: reusing the build tree {build_dir} (CMake builds the extension there "
                      "if it is not up to date; POINT_SET_CURVATURES_CMAKE_BUILD_DIR=fresh for a fresh build)",
                      flush=True)
        if build_dir:
            build_dir = os.path.abspath(build_dir)
            if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
                raise RuntimeError(f"POINT_SET_CURVATURES_CMAKE_BUILD_DIR={build_dir}: not a configured CMake "
                                   "build tree (no CMakeCache.txt); unset it to build in a fresh one")
        else:
            build_dir = os.path.join(os.path.abspath(self.build_temp), "cmake")
            os.makedirs(build_dir, exist_ok=True)
            args = [
                cmake, "-S", ROOT, "-B", build_dir,
                "-DCMAKE_BUILD_TYPE=Release",
                f"-DPython3_EXECUTABLE={sys.executable}",
                "-DPOINT_SET_CURVATURES_BUILD_PYTHON=ON",
                "-DPOINT_SET_CURVATURES_BUILD_TESTS=OFF",
                "-DPOINT_SET_CURVATURES_BUILD_EXAMPLES=OFF",
                "-DPOINT_SET_CURVATURES_BUILD_BENCHMARKS=OFF",
                "-DPOINT_SET_CURVATURES_BUILD_TOOL=OFF",
                "-DPOINT_SET_CURVATURES_INSTALL=OFF",
            ] + shlex.split(os.environ.get("CMAKE_ARGS", ""))
            self._run(args)
        jobs = self.parallel or os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or os.cpu_count() or 1
        self._run([cmake, "--build", build_dir, "--target", TARGET, "--config", "Release", "--parallel", str(jobs)])

        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = os.path.join(build_dir, "python", "point_set_curvatures", "_core" + suffix)
        if not os.path.exists(built):
            raise RuntimeError(f"point_set_curvatures: CMake did not produce {built} (a build tree configured "
                               f"for another Python than {sys.executable}?)")
        destination = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(destination), exist_ok=True)
        shutil.copyfile(built, destination)
        shutil.copymode(built, destination)

    def _run(self, args):
        print(" ".join(shlex.quote(a) for a in args), flush=True)
        subprocess.run(args, check=True)


# (setuptools runs this file as __main__; python/tests/test_packaging.py imports it for its functions)
if __name__ == "__main__":
    setup(
        version=cmake_project_version(),
        package_dir={"": "python"},
        packages=["point_set_curvatures"],
        package_data={"point_set_curvatures": ["*.pyi", "py.typed"]},
        zip_safe=False,
        # no sources: CMake compiles them (the Extension makes the wheel platform-specific)
        ext_modules=[Extension("point_set_curvatures._core", sources=[])],
        cmdclass={"build_ext": CMakeBuildExt},
        # setuptools' own build files under build/pip, apart from a CMake build tree in build/
        options={"build": {"build_base": os.path.join("build", "pip")}},
    )
