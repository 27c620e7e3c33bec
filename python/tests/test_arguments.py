# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Arguments that used to be accepted silently (issue 28, item 11): strings for numbers, scales
covering the whole cloud, progress callables returning 0 or None, more threads than cores,
method names in another case; and the package's version."""

import os
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

import point_set_curvatures as psc
from conftest import fibonacci_sphere


def assert_same(a, b):
    assert set(a) == set(b)
    for k in a:
        assert a[k].dtype == b[k].dtype and a[k].shape == b[k].shape, k
        assert np.array_equal(a[k].view(np.uint8), b[k].view(np.uint8)), k


@pytest.fixture(scope="module")
def small():
    return fibonacci_sphere(2000, radius=2.0)


def test_version_is_the_cmake_project_version(data_dir):
    with open(os.path.join(data_dir, "..", "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(\s*Point_set_curvatures\s+VERSION\s+([0-9.]+)", f.read())
    assert m and psc.__version__ == m.group(1)
    assert re.fullmatch(r"\d+\.\d+\.\d+", psc.__version__)


# ---- strings and other wrong types for numbers ----

def test_strings_refused_for_numbers(small):
    p, n = small
    calls = {
        "radius": lambda: psc.estimate_curvatures(p, n, radius="1.5"),
        "neighbors": lambda: psc.estimate_curvatures(p, n, neighbors="40"),
        "threads": lambda: psc.estimate_curvatures(p, n, radius=0.5, threads="2"),
        "vcm_offset_radius": lambda: psc.estimate_curvatures(p, n, method="vcm", radius=0.5,
                                                             vcm_offset_radius="0.5"),
        "position_fit_blend": lambda: psc.estimate_curvatures(p, n, radius=0.5, position_fit_blend="0.5"),
        "halo": lambda: psc.estimate_curvatures(p, n, radius=0.5, tile=((0, 0, 0), (1, 1, 1), "1")),
        "radius ": lambda: psc.estimate_sphere_features(p, n, radius="1.5"),
        "radius  ": lambda: psc.estimate_tangent_voronoi_areas(p, n, radius="1.5"),
        "radii[1]": lambda: psc.estimate_multiscale_sphere_features(p, n, [0.5, "1.0"]),
        "radii": lambda: psc.estimate_multiscale_sphere_features(p, n, "0.5"),
        "radius   ": lambda: psc.apss_smooth_point_set(p, n, "0.5"),
        "radius    ": lambda: psc.AlgebraicPointSetSurface(p, n, "0.5"),
        "tile_side": lambda: psc.TileGrid((0, 0, 0), (1, 1, 1), "0.5"),
        "neighbors ": lambda: psc.estimate_normals(p, neighbors="18"),
    }
    for name, call in calls.items():
        with pytest.raises(TypeError) as e:
            call()
        assert name.strip() in str(e.value), (name, str(e.value))
        # also a ValueError, as earlier versions raised
        assert isinstance(e.value, ValueError) and isinstance(e.value, psc.ArgumentTypeError)
    with pytest.raises(TypeError, match=r"radius must be a number, got '1.5' \(a string: convert it, e.g. float"):
        psc.estimate_curvatures(p, n, radius="1.5")
    for bad in (40.0, True, np.float64(40)):
        with pytest.raises(TypeError, match="neighbors must be an integer"):
            psc.estimate_curvatures(p, n, neighbors=bad)
    with pytest.raises(TypeError, match="radius must be a number"):
        psc.estimate_curvatures(p, n, radius=True)
    # numbers of every kind are accepted, with the same result
    base = psc.estimate_curvatures(p, n, radius=0.5)
    for r in (np.float32(0.5), np.float64(0.5)):
        assert_same(base, psc.estimate_curvatures(p, n, radius=r))
    assert_same(psc.estimate_curvatures(p, n, radius=1), psc.estimate_curvatures(p, n, radius=1.0))
    assert_same(psc.estimate_curvatures(p, n, neighbors=30), psc.estimate_curvatures(p, n, neighbors=np.int32(30)))


# ---- scales covering the whole cloud ----

def test_radius_larger_than_the_cloud_warns(small):
    p, n = small  # a sphere of radius 2: bounding-box diagonal 4 sqrt(3) = 6.93
    diagonal = float(np.linalg.norm(p.max(axis=0) - p.min(axis=0)))
    assert 6.9 < diagonal < 6.93
    with pytest.warns(psc.ScaleWarning, match=r"radius=1e\+300 is larger than the cloud's extent \(bounding-box "
                                              r"diagonal 6\.9\d*\).*neighbors=40") as w:
        r = psc.estimate_curvatures(p, n, radius=1e300)
    assert len(w) == 1 and w[0].filename == __file__  # reported at the caller's line
    assert (r["status"] == psc.Status.DEGENERATE_FIT).all()  # what the warning explains
    with pytest.warns(psc.ScaleWarning):
        psc.estimate_curvatures(p, n, radius=1.01 * diagonal, method="pss")
    for call in (lambda: psc.estimate_sphere_features(p, n, radius=1e300),
                 lambda: psc.estimate_tangent_voronoi_areas(p, n, radius=1e300),
                 lambda: psc.estimate_multiscale_sphere_features(p, n, [0.5, 1e300]),
                 lambda: psc.apss_smooth_point_set(p, n, 1e300),
                 lambda: psc.estimate_normals(p, radius=1e300)):
        with pytest.warns(psc.ScaleWarning, match="whole cloud"):
            call()
    # a large but smaller radius, a non-finite point and a tile: no warning
    q = p.copy()
    q[5] = (1e30, 0, 0)  # finite, far: part of the extent
    q[6] = np.nan
    with warnings.catch_warnings():
        warnings.simplefilter("error", psc.ScaleWarning)
        ok = psc.estimate_curvatures(p, n, radius=0.9 * diagonal)
        assert (ok["status"] == psc.Status.VALID).all()
        psc.estimate_curvatures(q, n, radius=1e10)  # the diagonal is 1e30
        psc.estimate_curvatures(p, n, radius=1e3, tile=((0, 0, 0), (1, 1, 1), 2e3))
        psc.estimate_curvatures(p[:1], n[:1], radius=1e300)  # one point: no extent
    # the warning can be made an error
    with warnings.catch_warnings():
        warnings.simplefilter("error", psc.ScaleWarning)
        with pytest.raises(psc.ScaleWarning):
            psc.estimate_curvatures(p, n, radius=1e300)


def test_neighbors_not_less_than_points_warns_and_caps(small):
    p, n = small
    with pytest.warns(psc.ScaleWarning, match=r"neighbors=1000000000000 is not less than the number of \(finite\) "
                                              r"points \(2000\): every neighbourhood is the whole cloud \(capped at 2000\)"):
        huge = psc.estimate_curvatures(p, n, neighbors=10**12)
    with pytest.warns(psc.ScaleWarning, match=r"\(2000\): every neighbourhood is the whole cloud;"):
        capped = psc.estimate_curvatures(p, n, neighbors=2000)
    assert_same(capped, huge)  # capped: exactly the run with every point
    assert (huge["neighbors"] == 2000).all()
    with warnings.catch_warnings():
        warnings.simplefilter("error", psc.ScaleWarning)
        psc.estimate_curvatures(p, n, neighbors=1999)
    # non-finite points are nobody's neighbours: not counted
    q = p.copy()
    q[3] = np.nan
    with pytest.warns(psc.ScaleWarning, match=r"number of \(finite\) points \(1999\).*capped at 1999"):
        psc.estimate_curvatures(q, n, neighbors=2000)
    with pytest.warns(psc.ScaleWarning, match="capped at 2000"):
        psc.estimate_normals(p, neighbors=10**12)
    with pytest.warns(psc.ScaleWarning, match="capped at 2000"):
        psc.estimate_sphere_features(p, n, neighbors=10**12)


# ---- progress: only False cancels ----

def test_progress_only_false_cancels(small):
    p, n = small
    base = psc.estimate_curvatures(p, n, radius=0.5)
    for value in (None, 0, 0.0, "", [], True, 1, "no"):
        calls = []

        def progress(f, value=value):
            calls.append(f)
            return value

        assert_same(base, psc.estimate_curvatures(p, n, radius=0.5, progress=progress))
        assert calls[-1] == 1.0, value  # ran to the end
    for value in (False, np.False_):
        with pytest.raises(psc.Cancelled):
            psc.estimate_curvatures(p, n, radius=0.5, progress=lambda f, value=value: value)
    with pytest.raises(TypeError, match="progress must be a callable"):
        psc.estimate_curvatures(p, n, radius=0.5, progress=0)


# ---- threads above the cores ----

def test_threads_above_the_cores_capped_silently(small):
    """More threads than TBB may use: the run is the same, and TBB prints nothing (it warned on
    stderr, once per process: hence a process of its own)."""
    many = 4 * psc._core.MAX_THREADS + 3
    code = (
        "import sys, numpy as np, point_set_curvatures as psc\n"
        "sys.path.insert(0, sys.argv[1])\n"
        "from conftest import fibonacci_sphere\n"
        "p, n = fibonacci_sphere(2000, radius=2.0)\n"
        "a = psc.estimate_curvatures(p, n, radius=0.5)\n"
        f"b = psc.estimate_curvatures(p, n, radius=0.5, threads={many})\n"
        f"c = psc.estimate_curvatures(p, n, radius=0.5, threads=10**30)\n"
        f"s = psc.AlgebraicPointSetSurface(p, n, 0.5).project(p[:100], threads={many})\n"
        "same = all(np.array_equal(a[k], b[k], equal_nan=True) and np.array_equal(a[k], c[k], equal_nan=True)"
        " for k in a)\n"
        "print(same, int((a['status'] == 0).sum()), int((s['status'] == 0).sum()))\n"
    )
    r = subprocess.run([sys.executable, "-c", code, os.path.dirname(__file__)], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["True", "2000", "100"]
    assert r.stderr == ""  # no "TBB Warning: The number of workers is currently limited to ..."


# ---- names in any case ----

def test_method_names_any_case(small):
    p, n = small
    for method in ("ASO", "Apss", "PCA_Plane", "vcm"):
        assert_same(psc.estimate_curvatures(p, n, method=method.lower(), radius=0.5),
                    psc.estimate_curvatures(p, n, method=method, radius=0.5))
    # options that only some methods take are recognised whatever the case of the method
    assert_same(psc.estimate_curvatures(p, n, method="jet", radius=0.5, degree_fitting=3),
                psc.estimate_curvatures(p, n, method="JET", radius=0.5, degree_fitting=3))
    with pytest.raises(ValueError, match="unknown method 'nope'; methods: aso, apss"):
        psc.estimate_curvatures(p, n, method="nope", radius=0.5)
    assert np.array_equal(psc.estimate_normals(p, neighbors=18, orientation="+z"),
                          psc.estimate_normals(p, neighbors=18, orientation="+Z"))
    assert np.array_equal(psc.estimate_normals(p, neighbors=18, orientation=("along", (0, 0, 1))),
                          psc.estimate_normals(p, neighbors=18, orientation=("Along", (0, 0, 1))))
