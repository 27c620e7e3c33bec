# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""CTest python_pip_install (issue 28, item 9): the pip route, offline.

    check_pip_install.py SOURCE_DIR CMAKE_BUILD_DIR

Builds a wheel with `pip wheel --no-build-isolation` (pyproject.toml, setup.py's CMake
build_ext) from a copy of the packaging files, reusing the CMake build tree of the tests
(POINT_SET_CURVATURES_CMAKE_BUILD_DIR: compiling the extension afresh takes minutes), installs
it into a new venv (--system-site-packages, for Debian's numpy), and checks: the wheel's files
and metadata, the import from the venv (not from the build tree), __version__ equal to the CMake
project's version, a result, `pip list`, and that `pip uninstall` removes the package and its
dist-info. Exit status 77 (skipped) when pip or venv is missing.
"""

import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile


def run(args, **kwargs):
    print("+", " ".join(str(a) for a in args), flush=True)
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kwargs)
    if r.returncode != 0:
        print(r.stdout, r.stderr, sep="\n", file=sys.stderr)
        raise SystemExit(f"failed with exit status {r.returncode}: {' '.join(str(a) for a in args)}")
    return r.stdout


def main():
    source, build = (os.path.abspath(a) for a in sys.argv[1:3])
    for module in ("pip", "venv", "ensurepip", "wheel"):
        if subprocess.run([sys.executable, "-c", f"import {module}"], capture_output=True).returncode != 0:
            print(f"skipped: {sys.executable} has no {module} (Debian: apt-get install python3-pip python3-venv python3-wheel)")
            return 77
    with open(os.path.join(source, "CMakeLists.txt"), encoding="utf-8") as f:
        version = re.search(r"project\(\s*Point_set_curvatures\s+VERSION\s+([0-9.]+)", f.read()).group(1)

    tmp = tempfile.mkdtemp(prefix="psc_pip_")
    try:
        # the packaging files and the package's sources (the C++ ones are in the build tree)
        src = os.path.join(tmp, "src")
        for name in ("pyproject.toml", "setup.py", "CMakeLists.txt", "doc/python.md"):
            os.makedirs(os.path.dirname(os.path.join(src, name)), exist_ok=True)
            shutil.copy(os.path.join(source, name), os.path.join(src, name))
        shutil.copytree(os.path.join(source, "python", "point_set_curvatures"),
                        os.path.join(src, "python", "point_set_curvatures"),
                        ignore=shutil.ignore_patterns("__pycache__", "*.so"))
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # not the build tree
        env.update(POINT_SET_CURVATURES_CMAKE_BUILD_DIR=build, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1",
                   PYTHONDONTWRITEBYTECODE="1")

        # the wheel
        dist = os.path.join(tmp, "dist")
        run([sys.executable, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "-w", dist, src],
            cwd=src, env=env)
        wheels = glob.glob(os.path.join(dist, "*.whl"))
        assert len(wheels) == 1, wheels
        wheel = os.path.basename(wheels[0])
        assert re.fullmatch(rf"point_set_curvatures-{re.escape(version)}-cp\d+-cp\d+\w*-linux_\w+\.whl", wheel), wheel
        with zipfile.ZipFile(wheels[0]) as z:
            names = set(z.namelist())
            metadata = z.read(f"point_set_curvatures-{version}.dist-info/METADATA").decode()
        for f in ("__init__.py", "__init__.pyi", "dask.py", "dask.pyi", "py.typed"):
            assert f"point_set_curvatures/{f}" in names, f
        cores = [n for n in names if re.fullmatch(r"point_set_curvatures/_core\..*\.so", n)]
        assert len(cores) == 1, names
        assert "Name: point-set-curvatures\n" in metadata and f"Version: {version}\n" in metadata, metadata
        assert "Requires-Dist: numpy\n" in metadata, metadata

        # installed into a venv
        venv = os.path.join(tmp, "venv")
        run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", venv], env=env)
        python = os.path.join(venv, "bin", "python")
        pip = [python, "-m", "pip"]
        run(pip + ["install", "--no-deps", wheels[0]], cwd=tmp, env=env)
        check = (
            "import numpy as np, point_set_curvatures as psc, point_set_curvatures.dask\n"
            "i = np.arange(2000) + 0.5\n"
            "phi, theta = np.arccos(1 - 2 * i / 2000), np.pi * (1 + 5**0.5) * i\n"
            "n = np.stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)], axis=1)\n"
            "r = psc.estimate_curvatures(2 * n, n, radius=0.5)\n"
            "print(psc.__version__, psc.__file__, psc._core.__file__)\n"
            "print(int((r['status'] == 0).sum()), float(np.median(r['mean'])))\n"
        )
        out = run([python, "-c", check], cwd=tmp, env=env).split()
        site = run([python, "-c", "import sysconfig; print(sysconfig.get_path('platlib'))"], cwd=tmp, env=env).strip()
        assert out[0] == version, out
        assert out[1] == os.path.join(site, "point_set_curvatures", "__init__.py"), (out, site)
        assert out[2].startswith(os.path.join(site, "point_set_curvatures", "_core.")), out
        assert out[3] == "2000" and abs(float(out[4]) - 0.5) < 0.01, out  # a sphere of radius 2
        listed = {p["name"]: p["version"] for p in json.loads(run(pip + ["list", "--format=json"], cwd=tmp, env=env))}
        assert listed.get("point-set-curvatures") == version, listed
        installed = glob.glob(os.path.join(site, "point_set_curvatures*"))
        assert sorted(os.path.basename(p) for p in installed) == [
            "point_set_curvatures", f"point_set_curvatures-{version}.dist-info"], installed

        # uninstalled: nothing left in the venv
        run(pip + ["uninstall", "-y", "point-set-curvatures"], cwd=tmp, env=env)
        assert glob.glob(os.path.join(site, "point_set_curvatures*")) == [], os.listdir(site)
        listed = json.loads(run(pip + ["list", "--format=json"], cwd=tmp, env=env))
        assert "point-set-curvatures" not in {p["name"] for p in listed}
        gone = subprocess.run([python, "-c", "import point_set_curvatures as p; print(p.__file__)"], cwd=tmp, env=env,
                              capture_output=True, text=True)
        assert gone.returncode != 0 or not gone.stdout.startswith(venv), gone.stdout
        print(f"ok: {wheel} built, installed ({version}, {out[3]} valid, median H {out[4]}), listed, uninstalled")
        return 0
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
