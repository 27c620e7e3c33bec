# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""setup.py's choice of the build tree pip builds the extension in (issue 42, item 6): the README's
build/ where it is a Release build without sanitizers of the same interpreter, else a fresh one."""

import importlib.util
import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


@pytest.fixture(scope="module")
def setup_py():
    spec = importlib.util.spec_from_file_location("psc_setup", os.path.join(ROOT, "setup.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)  # (not __main__: setup() is not called)
    return module


def write_cache(root, **entries):
    values = dict(CMAKE_BUILD_TYPE="Release", POINT_SET_CURVATURES_SANITIZE="", POINT_SET_CURVATURES_BUILD_PYTHON="ON",
                  Python3_EXECUTABLE=sys.executable, CMAKE_HOME_DIRECTORY=str(root))
    values.update(entries)
    os.makedirs(os.path.join(root, "build"), exist_ok=True)
    with open(os.path.join(root, "build", "CMakeCache.txt"), "w", encoding="utf-8") as f:
        f.write("# This is the CMakeCache file.\n")
        for name, value in values.items():
            if value is not None:
                f.write(f"{name}:STRING={value}\n")


def test_the_readme_build_tree_is_reused(setup_py, tmp_path):
    write_cache(tmp_path)
    assert setup_py.reusable_build_tree(str(tmp_path), sys.executable) == os.path.join(str(tmp_path), "build")
    # a venv's interpreter is a link to its base: the same file
    link = tmp_path / "python3"
    os.symlink(os.path.realpath(sys.executable), link)
    assert setup_py.reusable_build_tree(str(tmp_path), str(link)) == os.path.join(str(tmp_path), "build")


@pytest.mark.parametrize("entries", [
    dict(CMAKE_BUILD_TYPE="Debug"),
    dict(POINT_SET_CURVATURES_SANITIZE="address,undefined"),
    dict(POINT_SET_CURVATURES_BUILD_PYTHON="OFF"),
    dict(Python3_EXECUTABLE=None),
    dict(Python3_EXECUTABLE="/nonexistent/python3.99"),
    dict(CMAKE_HOME_DIRECTORY="/somewhere/else"),
])
def test_other_build_trees_are_not(setup_py, tmp_path, entries):
    write_cache(tmp_path, **entries)
    assert setup_py.reusable_build_tree(str(tmp_path), sys.executable) is None


def test_no_build_tree(setup_py, tmp_path):
    assert setup_py.reusable_build_tree(str(tmp_path), sys.executable) is None
