# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Fixtures of the Python tests: clouds, and the C++ reference results (psc_python_reference)."""

import os
import subprocess

import numpy as np
import pytest


# With PSC_FORBID_SKIPS=1 (set by .ci/run, whose machine has everything the tests need), a
# skipped test or module fails: CTest runs each file as one test and would count a file whose
# tests were skipped as passed (issue 45).
@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if report.skipped and os.environ.get("PSC_FORBID_SKIPS") == "1" and not hasattr(report, "wasxfail"):
        report.outcome = "failed"
        report.longrepr = f"skipped, which PSC_FORBID_SKIPS=1 forbids: {report.longrepr}"


@pytest.hookimpl(hookwrapper=True)
def pytest_make_collect_report(collector):
    outcome = yield
    report = outcome.get_result()
    if report.skipped and os.environ.get("PSC_FORBID_SKIPS") == "1":
        report.outcome = "failed"
        report.longrepr = f"module skipped, which PSC_FORBID_SKIPS=1 forbids: {report.longrepr}"


def fibonacci_sphere(n, radius=1.0, center=(0.0, 0.0, 0.0)):
    """n points spread evenly on a sphere, with their outward unit normals."""
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    theta = np.pi * (1 + 5**0.5) * i
    normals = np.stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)], axis=1)
    return radius * normals + np.asarray(center), normals


@pytest.fixture(scope="session")
def sphere():
    return fibonacci_sphere(20000, radius=2.0)


@pytest.fixture(scope="session")
def data_dir():
    d = os.environ.get("PSC_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))
    if not os.path.isdir(d):
        pytest.skip("data directory not found (set PSC_DATA_DIR)")
    return d


@pytest.fixture(scope="session")
def reference(tmp_path_factory, data_dir):
    """Runs the C++ helper on goursat_010000.xyz; returns (points, normals, load(name, width))."""
    exe = os.environ.get("PSC_REFERENCE_EXE")
    if not exe or not os.path.exists(exe):
        pytest.skip("PSC_REFERENCE_EXE not set (the CTest test sets it)")
    out = tmp_path_factory.mktemp("reference")
    subprocess.run([exe, os.path.join(data_dir, "goursat_010000.xyz"), str(out)], check=True,
                   stdout=subprocess.DEVNULL)
    raw = np.fromfile(out / "points.bin", dtype=np.float64).reshape(-1, 6)

    def load(name, width):
        return np.fromfile(out / f"{name}.bin", dtype=np.float64).reshape(-1, width)

    return np.ascontiguousarray(raw[:, :3]), np.ascontiguousarray(raw[:, 3:]), load
