# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Tests of point_set_curvatures.estimate_curvatures: analytic values, the C++ API bit for
bit, dtypes and layouts, bad input, progress and cancellation, determinism, tiles."""

import threading
import time

import numpy as np
import pytest

import point_set_curvatures as psc
from conftest import fibonacci_sphere

# every field of a result without the automatic scale (the package's table, field_descriptions.h)
FIELDS = tuple(f["key"] for f in psc._core.fields() if not f["automatic_scale_only"])


def assert_same(a, b, fields=FIELDS):
    """Bitwise equality of two results (NaN equal to NaN)."""
    for f in fields:
        x, y = np.asarray(a[f]), np.asarray(b[f])
        assert x.dtype == y.dtype and x.shape == y.shape, f
        assert np.array_equal(x.view(np.uint8), y.view(np.uint8)), f


# ---- analytic values ----

@pytest.mark.parametrize("method", ["aso", "pss", "jet", "wavejet"])
def test_sphere_full_tensor(sphere, method):
    points, normals = sphere
    r = psc.estimate_curvatures(points, normals, method=method, radius=0.25)
    valid = r["status"] == psc.Status.VALID
    assert valid.all()
    tol = 1e-9 if method == "aso" else 5e-3
    for f, value in (("k_min", 0.5), ("k_max", 0.5), ("mean", 0.5), ("gaussian", 0.25)):
        assert np.abs(r[f] - value).max() < tol, f
    assert np.abs(np.einsum("ij,ij->i", r["normal"], normals) - 1).max() < 1e-6
    # directions: unit, tangent, orthogonal
    for d in ("min_direction", "max_direction"):
        assert np.allclose(np.linalg.norm(r[d], axis=1), 1)
        assert np.abs(np.einsum("ij,ij->i", r[d], r["normal"])).max() < 1e-6


def test_sphere_signs(sphere):
    points, normals = sphere
    out = psc.estimate_curvatures(points, normals, radius=0.25)
    inward = psc.estimate_curvatures(points, -normals, radius=0.25)
    assert np.allclose(out["mean"], 0.5, atol=1e-12) and np.allclose(inward["mean"], -0.5, atol=1e-12)
    assert np.allclose(inward["k_min"], -0.5, atol=1e-12) and np.allclose(inward["k_max"], -0.5, atol=1e-12)
    assert np.allclose(inward["gaussian"], 0.25, atol=1e-12)
    apss = psc.estimate_curvatures(points, normals, method="apss", radius=0.25)
    assert np.allclose(apss["mean"], 0.5, atol=1e-12)
    assert np.isnan(apss["k_min"]).all()  # a sphere fit has no principal curvatures


@pytest.mark.parametrize("method", ["barycenter", "pca_plane", "vcm"])
def test_sphere_unsigned_baselines(sphere, method):
    """A cap of the sphere of radius 2 (curvature 0.5): valid everywhere, unsigned values, and
    0.5 on the points more than r from the cap's rim. Measured there (mean / largest error):
    barycenter 0.0037 / 0.022, PCA plane 0.0027 / 0.011, VCM k_min 0.034 / 0.054, k_max
    0.049 / 0.061; bounds x1.5, all far below 0.5 (the error of a constant zero)."""
    points, normals = sphere
    r = psc.estimate_curvatures(points[:5000] * 1.0, normals[:5000], method=method, radius=0.5)
    valid = r["status"] == psc.Status.VALID
    assert valid.all()
    inner = points[:5000, 2] > 1.5
    assert inner.sum() == 2500
    if method == "vcm":
        assert (r["k_min"] >= 0).all() and (r["k_max"] >= r["k_min"]).all() and np.isnan(r["mean"]).all()
        for key, mean, largest in (("k_min", 0.05, 0.082), ("k_max", 0.073, 0.091)):
            error = np.abs(r[key][inner] - 0.5)
            assert error.mean() < mean and error.max() < largest, key
    else:
        assert (r["mean"] >= 0).all()
        mean, largest = {"barycenter": (0.0056, 0.033), "pca_plane": (0.0041, 0.016)}[method]
        error = np.abs(r["mean"][inner] - 0.5)
        assert error.mean() < mean and error.max() < largest


# ---- the C++ API, bit for bit ----

CPP_CASES = [
    ("aso_r1.5", dict(radius=1.5)),
    ("aso_paper_r1.5", dict(radius=1.5, threads=1, aso_variant="paper")),
    ("aso_paper_blend_r1.5", dict(radius=1.5, aso_variant="paper", normal_field_blend=True)),
    ("aso_k30", dict(neighbors=30)),
    ("aso_k40_position_blend", dict(neighbors=40, position_fit_blend=0.5)),
    ("aso_quartic_authors_r1.5", dict(radius=1.5, weight_kernel="smooth_quartic",
                                      aso_projection="authors_implementation", min_neighbors=20)),
    ("apss_r1.5", dict(method="apss", radius=1.5)),
    ("pss_r1.5", dict(method="pss", radius=1.5)),
    ("jet_r1.5_d3", dict(method="jet", radius=1.5, degree_fitting=3, degree_monge=2)),
]


@pytest.mark.parametrize("name,kwargs", CPP_CASES, ids=[c[0] for c in CPP_CASES])
def test_same_as_cpp(reference, name, kwargs):
    points, normals, load = reference
    ref = load(name, 16)
    r = psc.estimate_curvatures(points, normals, **kwargs)
    expected = {
        "normal": ref[:, 0:3], "k_min": ref[:, 3], "k_max": ref[:, 4], "mean": ref[:, 5],
        "gaussian": ref[:, 6], "min_direction": ref[:, 7:10], "max_direction": ref[:, 10:13],
        "normal_coherence": ref[:, 13], "neighbors": ref[:, 14].astype(np.int64),
        "status": ref[:, 15].astype(np.uint8),
    }
    assert (r["status"] == psc.Status.VALID).sum() > 9000
    assert_same(r, {k: np.ascontiguousarray(v) for k, v in expected.items()})


def test_normal_field_blend_option(reference):
    points, normals, load = reference
    paper = load("aso_paper_r1.5", 16)
    blended = load("aso_paper_blend_r1.5", 16)
    # the option reaches the C++ function: on the paper's variant it changes some estimates
    assert (paper[:, 4] != blended[:, 4]).sum() > 100


def test_same_as_cpp_features_and_normals(reference):
    points, normals, load = reference
    ref = load("features_r1.5", 6)
    f = psc.estimate_sphere_features(points, normals, radius=1.5)
    for j, name in enumerate(("u_c", "u_q", "anisotropy", "geometric_variation")):
        assert np.array_equal(f[name], ref[:, j], equal_nan=True), name
    assert np.array_equal(f["neighbors"], ref[:, 4].astype(np.int64))
    assert np.array_equal(f["status"], ref[:, 5].astype(np.uint8))
    n = psc.estimate_normals(points)
    assert np.array_equal(n, load("normals_default", 3))
    # the fits and orientations of the C++ function, each reached
    plane = psc.estimate_normals(points, fit="plane")
    assert np.array_equal(plane, load("normals_plane", 3))
    assert np.array_equal(psc.estimate_normals(points, orientation="auto"), load("normals_auto", 3))
    with pytest.raises(ValueError, match="fit"):
        psc.estimate_normals(points, fit="cubic")


# ---- sample weights computed once, shared by several runs ----

def ramp_sphere(n=8000, seed=3):
    """i.i.d. points on the unit sphere with a density rising 1:10 along x, unit normals."""
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(4 * n, 3))
    v /= np.linalg.norm(v, axis=1)[:, None]
    keep = rng.random(len(v)) < 0.1 + 0.9 * (v[:, 0] + 1) / 2
    v = np.ascontiguousarray(v[keep][:n])
    return v, v.copy()


def test_shared_sample_weights_bitwise():
    points, normals = ramp_sphere()
    normals[5] = 0.0  # an unusable point: area 0
    areas = psc.estimate_tangent_voronoi_areas(points, normals, radius=0.2)
    assert areas.shape == (len(points),) and areas.dtype == np.float64
    assert areas[5] == 0 and (np.delete(areas, 5) > 0).all()
    assert np.array_equal(areas, psc.estimate_tangent_voronoi_areas(points, normals, radius=0.2, threads=1))
    # each estimator reading the array gives bitwise its own area run
    default = psc.estimate_curvatures(points, normals, radius=0.2)
    assert_same(default, psc.estimate_curvatures(points, normals, radius=0.2, sample_weights=areas))
    assert_same(psc.estimate_curvatures(points, normals, method="apss", radius=0.2,
                                        sample_weights="tangent_voronoi_area"),
                psc.estimate_curvatures(points, normals, method="apss", radius=0.2, sample_weights=list(areas)))
    own = psc.estimate_sphere_features(points, normals, radius=0.2, sample_weights="tangent_voronoi_area")
    shared = psc.estimate_sphere_features(points, normals, radius=0.2, sample_weights=areas)
    for k in own:
        assert np.array_equal(own[k], shared[k], equal_nan=True), k
    by_count = psc.estimate_tangent_voronoi_areas(points, normals, neighbors=30)
    assert_same(psc.estimate_curvatures(points, normals, neighbors=30),
                psc.estimate_curvatures(points, normals, neighbors=30, sample_weights=by_count))
    assert_same(psc.estimate_curvatures(points, normals, method="apss", neighbors=30,
                                        sample_weights="tangent_voronoi_area"),
                psc.estimate_curvatures(points, normals, method="apss", neighbors=30, sample_weights=by_count))
    # the array is what the estimator reads: weights of 1 give the uniform weights bitwise
    ones = np.ones(len(points))
    uniform = psc.estimate_curvatures(points, normals, radius=0.2, sample_weights="uniform")
    assert_same(uniform, psc.estimate_curvatures(points, normals, radius=0.2, sample_weights=ones))
    assert not np.array_equal(uniform["k_max"], default["k_max"], equal_nan=True)
    assert_same(psc.estimate_curvatures(points, normals, neighbors=30, sample_weights="uniform"),
                psc.estimate_curvatures(points, normals, neighbors=30, sample_weights=ones))
    # other dtypes are converted to float64
    assert_same(psc.estimate_curvatures(points, normals, radius=0.2, sample_weights=areas.astype(np.float32)),
                psc.estimate_curvatures(points, normals, radius=0.2,
                                        sample_weights=areas.astype(np.float32).astype(np.float64)))


def test_tangent_voronoi_areas_values(sphere):
    # evenly spread points on a sphere of radius 2: the cells tile it, their areas sum to 16 pi
    points, normals = sphere
    areas = psc.estimate_tangent_voronoi_areas(points, normals, radius=0.25)
    assert abs(areas.sum() / (16 * np.pi) - 1) < 2e-3
    assert abs(np.median(areas) / (16 * np.pi / len(points)) - 1) < 0.05
    # scale: areas in squared input units
    big = psc.estimate_tangent_voronoi_areas(points * 10, normals, radius=2.5)
    assert np.allclose(big, 100 * areas, rtol=1e-9)


def test_bad_sample_weights():
    points, normals = ramp_sphere(2000)
    n = len(points)
    for bad in (np.ones(n - 1), np.ones((n, 1)), "areas", np.full(n, -1.0), np.ones(n, dtype=complex)):
        with pytest.raises(ValueError, match="sample_weight"):
            psc.estimate_curvatures(points, normals, radius=0.3, sample_weights=bad)
    w = np.ones(n)
    w[7] = np.nan
    with pytest.raises(ValueError, match="weight of point 7"):
        psc.estimate_curvatures(points, normals, method="apss", radius=0.3, sample_weights=w)
    with pytest.raises(ValueError, match="does not apply"):
        psc.estimate_curvatures(points, normals, method="pss", radius=0.3, sample_weights=np.ones(n))
    with pytest.raises(ValueError):
        psc.estimate_tangent_voronoi_areas(points, normals, radius=-1.0)
    with pytest.raises(ValueError):
        psc.estimate_tangent_voronoi_areas(points, normals)
    with pytest.raises(psc.Cancelled):
        psc.estimate_tangent_voronoi_areas(points, normals, radius=0.3, progress=lambda f: False)


# ---- dtypes and memory layouts ----

def test_dtype_and_layout_variants(sphere):
    points, normals = sphere
    p32, n32 = points.astype(np.float32), normals.astype(np.float32)
    base = psc.estimate_curvatures(p32.astype(np.float64), n32.astype(np.float64), radius=0.25)
    assert_same(base, psc.estimate_curvatures(p32, n32, radius=0.25))
    assert_same(base, psc.estimate_curvatures(np.asfortranarray(p32), np.asfortranarray(n32), radius=0.25))
    p64f, n64f = np.asfortranarray(p32.astype(np.float64)), np.asfortranarray(n32.astype(np.float64))
    assert_same(base, psc.estimate_curvatures(p64f, n64f, radius=0.25))
    # non-contiguous views: every other column of a wider array, every other row
    wide = np.zeros((len(points), 6))
    wide[:, ::2] = p32
    assert not wide[:, ::2].flags.c_contiguous
    assert_same(base, psc.estimate_curvatures(wide[:, ::2], n32, radius=0.25))
    half = psc.estimate_curvatures(points[::2], normals[::2], radius=0.35)
    assert_same(half, psc.estimate_curvatures(points[::2].copy(), normals[::2].copy(), radius=0.35))
    # mixed dtypes, lists
    assert_same(base, psc.estimate_curvatures(p32, n32.astype(np.float64), radius=0.25))
    small = psc.estimate_curvatures(points[:100].tolist(), normals[:100].tolist(), radius=0.5)
    assert_same(small, psc.estimate_curvatures(points[:100], normals[:100], radius=0.5))


# ---- bad input ----

def test_bad_shapes_and_types(sphere):
    points, normals = sphere
    p, n = points[:200], normals[:200]
    for bad in (p[:, :2], p[:, 0], p.reshape(100, 2, 3), np.zeros((200, 4))):
        with pytest.raises(ValueError, match="shape"):
            psc.estimate_curvatures(bad, n, radius=1)
        with pytest.raises(ValueError, match="shape"):
            psc.estimate_curvatures(p, bad, radius=1)
    with pytest.raises(ValueError, match="same number of rows"):
        psc.estimate_curvatures(p, n[:100], radius=1)
    with pytest.raises(TypeError, match="dtype"):
        psc.estimate_curvatures(p.astype(np.int32), n, radius=1)
    with pytest.raises(TypeError, match="dtype"):
        psc.estimate_curvatures(p.astype(">f8"), n, radius=1)
    with pytest.raises(ValueError):
        psc.estimate_curvatures("abc", n, radius=1)


@pytest.mark.parametrize("radius", [float("nan"), 0.0, -1.0, float("inf")])
def test_bad_radius(sphere, radius):
    points, normals = sphere
    with pytest.raises(ValueError, match="radius"):
        psc.estimate_curvatures(points[:100], normals[:100], radius=radius)


def test_bad_arguments(sphere):
    points, normals = sphere
    p, n = points[:300], normals[:300]
    cases = [
        dict(radius=1, neighbors=10), dict(neighbors=0), dict(neighbors=2.5),
        dict(radius=1, threads=0), dict(radius=1, method="nope"), dict(radius=1, unknown=3),
        dict(radius=1, method="pss", robust_orientation=True), dict(radius=1, aso_variant="fast"),
        dict(radius=1, method="jet", degree_monge=5), dict(radius=1, weight_kernel="constant"),
        dict(radius=1, method="vcm", tile=((0, 0, 0), (1, 1, 1), 2)), dict(radius=1, min_neighbors=-1),
        dict(radius=1, robust_orientation=1), dict(radius=1, progress=3), dict(radius="big"),
        dict(radius=1, position_fit_blend=1.5), dict(radius=1, position_fit_blend=True),
        dict(radius=1, position_fit_blend="half"), dict(radius=1, method="pss", position_fit_blend=0.5),
    ]
    for kwargs in cases:
        with pytest.raises(ValueError):
            psc.estimate_curvatures(p, n, **kwargs)
    # the C++ message is kept
    with pytest.raises(ValueError, match="degree_monge"):
        psc.estimate_curvatures(p, n, radius=1, method="jet", degree_monge=5)
    with pytest.raises(ValueError, match="CONSTANT is not supported"):
        psc.estimate_curvatures(p, n, radius=1, weight_kernel="constant")
    with pytest.raises(ValueError, match="position_fit_blend"):
        psc.estimate_curvatures(p, n, radius=1, position_fit_blend=-0.1)


def test_defaults_without_scale_or_normals(sphere):
    # no scale: the robust ASO takes the automatic scale, the paper's variant and the other
    # methods DEFAULT_NEIGHBORS (the library's front-end defaults, the tool's too)
    points, normals = (a[:3000] for a in sphere)
    auto = psc.estimate_curvatures(points, normals)
    assert_same(auto, psc.estimate_curvatures(points, normals, neighbors="auto"))
    paper = psc.estimate_curvatures(points, normals, aso_variant="paper")
    assert_same(paper, psc.estimate_curvatures(points, normals, aso_variant="paper", neighbors=40))
    pss = psc.estimate_curvatures(points, normals, method="pss")
    assert_same(pss, psc.estimate_curvatures(points, normals, method="pss", neighbors=40))
    assert psc.DEFAULT_NEIGHBORS == 40
    # no normals: estimated with a warning, as estimate_normals then position_fit_blend=0.5
    # would; a sphere is closed: outward, H = 1/2 on the sphere of radius 2
    with pytest.warns(UserWarning, match="no normals given: estimating them"):
        without = psc.estimate_curvatures(points)
    estimated = psc.estimate_normals(points, neighbors="auto")
    assert_same(without, psc.estimate_curvatures(points, estimated, position_fit_blend=0.5))
    assert (without["status"] == psc.Status.VALID).all()
    assert np.abs(without["mean"] - 0.5).max() < 1e-3
    with pytest.warns(UserWarning, match="the 40 nearest"):
        fixed = psc.estimate_curvatures(points, None, neighbors=30, position_fit_blend=0)
    assert_same(fixed, psc.estimate_curvatures(points, psc.estimate_normals(points), neighbors=30))
    # progress covers both steps, once each: [0, 0.5] then [0.5, 1], non-decreasing
    seen = []
    with pytest.warns(UserWarning):
        psc.estimate_curvatures(points, radius=0.5, progress=seen.append)
    assert seen[-1] == 1.0 and min(seen) >= 0 and all(b >= a for a, b in zip(seen, seen[1:]))
    assert any(0 < f < 0.5 for f in seen) and any(0.5 < f < 1 for f in seen)
    # a tile's points are not the whole cloud: refused
    with pytest.raises(ValueError, match="required with tile"):
        psc.estimate_curvatures(points, radius=0.5, tile=((-3, -3, -3), (0, 3, 3), 1.0))


def test_status_names():
    statuses = np.array([0, 0, 6, 1, 0, 5], dtype=np.uint8)
    assert psc.Status.names(statuses).tolist() == [
        "valid", "valid", "two_sheets", "too_few_neighbors", "valid", "not_computed"]
    assert psc.Status.names(statuses.reshape(2, 3)).shape == (2, 3)
    assert psc.Status.counts(statuses) == {"valid": 3, "too_few_neighbors": 1, "not_computed": 1, "two_sheets": 1}
    assert list(psc.Status.counts(statuses)) == ["valid", "too_few_neighbors", "not_computed", "two_sheets"]
    assert psc.Status.counts(np.zeros(0, dtype=np.uint8)) == {}
    with pytest.raises(ValueError):
        psc.Status.names(np.array([7]))
    # the names are the C++ ones (CGAL::to_string), which the tool prints
    assert [psc.Status.names([s.value])[0] for s in psc.Status] == list(psc._core.STATUS_VALUES)


def test_empty_and_invalid_points(sphere):
    for method in psc.METHODS:
        r = psc.estimate_curvatures(np.zeros((0, 3)), np.zeros((0, 3)), method=method, radius=1.0)
        assert r["normal"].shape == (0, 3) and r["mean"].shape == (0,) and r["status"].dtype == np.uint8
    points, normals = (a[:2000].copy() for a in sphere)
    points[0] = np.nan
    normals[1] = 0
    normals[2] = 1e6  # implausible length
    r = psc.estimate_curvatures(points, normals, radius=0.5)
    assert r["status"][0] == psc.Status.NON_FINITE_POINT
    assert r["status"][1] == psc.Status.INVALID_NORMAL and r["status"][2] == psc.Status.INVALID_NORMAL
    for f in ("normal", "k_min", "k_max", "mean", "gaussian", "min_direction", "max_direction"):
        assert np.isnan(r[f][:3]).all(), f
    r = psc.estimate_curvatures(points, normals, radius=0.5, accept_unnormalized_normals=True)
    assert r["status"][2] == psc.Status.VALID
    few = psc.estimate_curvatures(points, normals, radius=0.5, min_neighbors=10**6)
    assert (few["status"][3:] == psc.Status.TOO_FEW_NEIGHBORS).all() and (few["neighbors"][3:] > 0).all()


# ---- progress, cancellation, threads ----

def test_progress_and_cancel(sphere):
    points, normals = sphere
    seen, threads = [], set()

    def progress(f):
        seen.append(f)
        threads.add(threading.get_ident())

    full = psc.estimate_curvatures(points, normals, radius=0.25, progress=progress)
    assert len(seen) >= 3 and seen[-1] == 1.0 and all(a <= b for a, b in zip(seen, seen[1:]))
    assert threads == {threading.get_ident()}  # on the calling thread
    calls = []

    def stop(f):
        calls.append(f)
        return f < 0.3

    with pytest.raises(psc.Cancelled):
        psc.estimate_curvatures(points, normals, radius=0.25, progress=stop)
    assert calls[-1] >= 0.3 and calls[-1] < 1.0
    assert issubclass(psc.Cancelled, RuntimeError)

    def fails(f):
        raise KeyError("from progress")

    with pytest.raises(KeyError, match="from progress"):
        psc.estimate_curvatures(points, normals, radius=0.25, progress=fails)
    # the module is still usable, and True / None continue
    assert_same(full, psc.estimate_curvatures(points, normals, radius=0.25, progress=lambda f: True))


@pytest.mark.parametrize("method", ["aso", "apss", "barycenter", "pca_plane", "pss", "jet", "wavejet", "vcm"])
def test_sequential_equals_parallel(method):
    points, normals = fibonacci_sphere(6000, radius=1.5)
    kwargs = dict(method=method, radius=0.15 if method != "barycenter" else 0.2)
    seq = psc.estimate_curvatures(points, normals, threads=1, **kwargs)
    assert_same(seq, psc.estimate_curvatures(points, normals, **kwargs))
    assert_same(seq, psc.estimate_curvatures(points, normals, threads=2, **kwargs))
    knn = psc.estimate_curvatures(points, normals, method=method, neighbors=30, threads=1)
    assert_same(knn, psc.estimate_curvatures(points, normals, method=method, neighbors=30))


def test_gil_released(sphere):
    """Another Python thread runs while an estimation computes: between two progress calls the
    estimation is in C++, and with the interpreter's switch interval raised to a minute the
    other thread can run there only if the GIL was released. No timing: a thread holding the
    GIL leaves the counter exactly where it was (the control below), one that releases it lets
    the counter move."""
    import sys
    points, normals = sphere
    counter = [0]
    done = threading.Event()

    def count():
        while not done.is_set():
            counter[0] += 1
            time.sleep(0)  # (gives the GIL back at once to a thread that waits for it)

    seen = []
    interval = sys.getswitchinterval()
    t = threading.Thread(target=count)
    sys.setswitchinterval(60.0)
    try:
        t.start()
        while counter[0] == 0:
            time.sleep(0)
        # control: Python code holding the GIL for a while does not let the thread run
        before = counter[0]
        sum(i * i for i in range(200000))
        held = counter[0] - before
        psc.estimate_curvatures(points, normals, method="pss", radius=0.3, threads=1,
                                progress=lambda f: seen.append(counter[0]))
    finally:
        done.set()
        sys.setswitchinterval(interval)
        t.join()
    assert held == 0
    assert len(seen) >= 3
    assert seen[-1] > seen[0]


# ---- tiles ----

def test_tiles_bitwise(reference):
    points, normals, _ = reference
    full = psc.estimate_curvatures(points, normals, radius=1.5)
    grid = psc.TileGrid(points.min(axis=0), points.max(axis=0), counts=(2, 2, 2))
    owner = grid.tile_of(points)
    out = {k: np.full_like(v, 255 if k == "status" else 0) for k, v in full.items()}
    for i in range(len(grid)):
        tile = grid.tile(i, 2 * 1.5)  # the default ASO's sample weights need two radii
        sel = np.nonzero(tile.halo_mask(points))[0]
        r = psc.estimate_curvatures(points[sel], normals[sel], radius=1.5, tile=tile)
        own = owner[sel] == i
        assert (r["status"][~own] == psc.Status.NOT_COMPUTED).all()
        for k in out:
            out[k][sel[own]] = r[k][own]
    assert_same(full, out)
    # by count (uniform sample weights): a tiny halo is too small
    tile = grid.tile(0, 1e-3)
    sel = np.nonzero(tile.halo_mask(points))[0]
    with pytest.raises(psc.HaloTooSmall) as e:
        psc.estimate_curvatures(points[sel], normals[sel], neighbors=30, aso_variant="paper", tile=tile)
    assert e.value.required_halo > 1e-3
    with pytest.raises(ValueError, match="halo"):
        psc.estimate_curvatures(points[sel], normals[sel], radius=1.5, tile=tile)


def noisy_sphere(n=20000, noise=0.0, seed=11):
    """A unit sphere of n points, moved along the normal by Gaussian noise of `noise` times
    the spacing; the exact normals."""
    points, normals = fibonacci_sphere(n)
    spacing = np.sqrt(4 * np.pi / n)
    rng = np.random.default_rng(seed)
    return points + normals * (noise * spacing * rng.standard_normal(n))[:, None], normals


def test_automatic_scale():
    # clean: the first rung (40) everywhere, H = 1 as with neighbors=40
    points, normals = noisy_sphere()
    auto = psc.estimate_curvatures(points, normals, neighbors="AUTO")
    fixed = psc.estimate_curvatures(points, normals, neighbors=40)
    assert (auto["status"] == psc.Status.VALID).all()
    assert (auto["neighbors"] < 80).all()
    np.testing.assert_allclose(auto["mean"], fixed["mean"], rtol=1e-9, atol=1e-12)
    assert "mean_error" in auto and "mean_error" not in fixed
    assert np.isfinite(auto["mean_error"]).all() and (auto["mean_error"] >= 0).all()
    # noise of 0.3 times the spacing: larger counts, H far closer to 1 than at 40; mean_error,
    # the standard error of the positions' quadric at the chosen scale, bounds the error of
    # the estimate made with exact normals (measured: mean |H - 1| 0.0026, median mean_error
    # 0.0285)
    points, normals = noisy_sphere(noise=0.3)
    auto = psc.estimate_curvatures(points, normals, neighbors="auto")
    fixed = psc.estimate_curvatures(points, normals, neighbors=40)
    error_auto = np.abs(auto["mean"] - 1).mean()
    assert np.median(auto["neighbors"]) >= 160
    assert error_auto < 0.1 * np.abs(fixed["mean"] - 1).mean()
    assert error_auto < 0.05
    assert error_auto < np.median(auto["mean_error"]) < 30 * error_auto
    # sequential == parallel, bitwise
    seq = psc.estimate_curvatures(points, normals, neighbors="auto", threads=1)
    for k in auto:
        assert np.array_equal(auto[k].view(np.uint8), seq[k].view(np.uint8)), k
    # normals: the automatic scale of the quadric fit, outward and close to the exact ones
    n_auto = psc.estimate_normals(points, neighbors="auto")
    n_fixed = psc.estimate_normals(points, neighbors=40)
    angle_auto = np.degrees(np.arccos(np.clip((n_auto * normals).sum(axis=1), -1, 1)))
    angle_fixed = np.degrees(np.arccos(np.clip((n_fixed * normals).sum(axis=1), -1, 1)))
    assert np.median(angle_auto) < 0.5 * np.median(angle_fixed)
    # a cloud smaller than the first rung: the whole cloud, with a ScaleWarning as for a count
    tiny_points, tiny_normals = fibonacci_sphere(30)
    with pytest.warns(psc.ScaleWarning, match="'auto' starts at 40"):
        tiny = psc.estimate_curvatures(tiny_points, tiny_normals, neighbors="auto")
    with pytest.warns(psc.ScaleWarning):
        # (the quartic kernel: "auto" takes it where a count is kept without noise over
        # neighbours spread evenly around the point)
        tiny_fixed = psc.estimate_curvatures(tiny_points, tiny_normals, neighbors=40, weight_kernel="smooth_quartic")
    assert (tiny["status"] == psc.Status.VALID).all() and (tiny["neighbors"] == 30).all()
    # (not bitwise: the wrapper caps a count at the points, 30, while "auto" keeps 40 for the
    # tangent Voronoi areas, whose neighbourhoods are a quarter of the count; measured 3.5e-4)
    np.testing.assert_allclose(tiny["mean"], tiny_fixed["mean"], rtol=2e-3)
    # only where the automatic scale is defined
    for call in (lambda: psc.estimate_curvatures(points, normals, method="jet", neighbors="auto"),
                 lambda: psc.estimate_sphere_features(points, normals, neighbors="auto"),
                 lambda: psc.estimate_normals(points, neighbors="auto", fit="plane"),
                 lambda: psc.estimate_curvatures(points, normals, neighbors="automatic")):
        with pytest.raises((ValueError, psc.ArgumentTypeError)):
            call()
