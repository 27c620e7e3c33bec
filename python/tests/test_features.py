# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Tests of the sphere features, the projection, the flow and the normal estimation."""

import numpy as np
import pytest

import point_set_curvatures as psc
from conftest import fibonacci_sphere


def test_sphere_features(sphere):
    points, normals = sphere
    f = psc.estimate_sphere_features(points, normals, radius=0.25)
    assert (f["status"] == psc.Status.VALID).all()
    assert np.allclose(f["mean"], 0.5, atol=1e-10) and np.allclose(f["u_q"], 0.25, atol=1e-10)
    assert np.allclose(f["sphere_radius"], 2.0, atol=1e-8) and np.allclose(f["center"], 0, atol=1e-8)
    assert np.abs(f["anisotropy"]).max() < 1e-10 and not f["is_plane"].any()
    assert f["u_l"].shape == (len(points), 3) and f["is_plane"].dtype == bool
    seq = psc.estimate_sphere_features(points, normals, radius=0.25, threads=1, weight_kernel="constant")
    par = psc.estimate_sphere_features(points, normals, radius=0.25, weight_kernel="constant")
    for k in seq:
        assert np.array_equal(seq[k], par[k], equal_nan=True), k
    knn = psc.estimate_sphere_features(points, normals, neighbors=40)
    assert np.allclose(knn["mean"], 0.5, atol=1e-10)
    for kernel in ("smooth_cubic", "smooth_quartic"):  # every kernel is exact on a sphere
        f = psc.estimate_sphere_features(points, normals, radius=0.25, weight_kernel=kernel)
        assert np.allclose(f["mean"], 0.5, atol=1e-10) and np.abs(f["geometric_variation"]).max() < 1e-10, kernel
    with pytest.raises(ValueError):
        psc.estimate_sphere_features(points, normals, radius=0.25, aso_variant="paper")


def test_multiscale(sphere):
    points, normals = sphere
    radii = [0.2, 0.3, 0.4]
    m = psc.estimate_multiscale_sphere_features(points, normals, radii)
    assert m["mean"].shape == (3, len(points)) and m["normal"].shape == (3, len(points), 3)
    one = psc.estimate_sphere_features(points, normals, radius=0.3)
    assert np.allclose(m["mean"][1], one["mean"], atol=1e-12)
    with pytest.raises(ValueError, match="radii"):
        psc.estimate_multiscale_sphere_features(points, normals, [])
    with pytest.raises(ValueError, match="radii"):
        psc.estimate_multiscale_sphere_features(points, normals, [0.2, -1])


def test_projection(sphere):
    points, normals = sphere
    s = psc.AlgebraicPointSetSurface(points, normals, 0.3)
    assert s.radius == 0.3 and s.number_of_points == len(points) and s.max_iterations == 30
    rng = np.random.default_rng(2)
    q = points[:500] * (1 + 0.03 * rng.standard_normal((500, 1)))
    q = np.vstack([q, [[np.nan, 0, 0]], [[50, 50, 50]]])
    r = s.project(q)
    assert (r["status"][:500] == psc.ProjectionStatus.CONVERGED).all()
    assert np.allclose(np.linalg.norm(r["point"][:500], axis=1), 2.0, atol=1e-8)
    assert r["status"][500] == psc.ProjectionStatus.NON_FINITE_POINT
    assert r["status"][501] == psc.ProjectionStatus.TOO_FEW_NEIGHBORS and np.isnan(r["point"][501]).all()
    r1 = s.project(q, threads=1)
    for k in r:
        assert np.array_equal(r[k], r1[k], equal_nan=True), k
    f = s.features(points[:100].astype(np.float32))
    assert np.allclose(f["mean"], 0.5, atol=1e-6)
    s.tolerance = 1e-3
    assert s.tolerance == 1e-3
    with pytest.raises(ValueError):
        s.tolerance = -1
    with pytest.raises(ValueError):
        psc.AlgebraicPointSetSurface(points, normals, float("nan"))


def test_flow():
    points, normals = fibonacci_sphere(5000, radius=1.0)
    rng = np.random.default_rng(3)
    noisy = points * (1 + 0.01 * rng.standard_normal((len(points), 1)))
    before = noisy.copy()
    r = psc.apss_smooth_point_set(noisy, normals, 0.15, iterations=3)
    assert np.array_equal(noisy, before)  # the input is not modified
    assert (r["status"] == psc.Status.VALID).all()
    err_before = np.abs(np.linalg.norm(noisy, axis=1) - 1).mean()
    err_after = np.abs(np.linalg.norm(r["points"], axis=1) - 1).mean()
    assert err_after < 0.5 * err_before
    assert np.array_equal(r["normals"], normals)
    u = psc.apss_smooth_point_set(noisy, normals, 0.15, iterations=2, update_normals=True, threads=1)
    u2 = psc.apss_smooth_point_set(noisy, normals, 0.15, iterations=2, update_normals=True)
    assert np.array_equal(u["points"], u2["points"]) and not np.array_equal(u["normals"], normals)
    seen = []
    psc.apss_smooth_point_set(noisy, normals, 0.15, iterations=2, progress=seen.append)
    assert seen and seen[-1] == 1.0
    with pytest.raises(psc.Cancelled):
        psc.apss_smooth_point_set(noisy, normals, 0.15, iterations=2, progress=lambda f: False)
    with pytest.raises(ValueError, match="radius"):
        psc.apss_smooth_point_set(noisy, normals, 0.0)


def test_normals(sphere):
    points, exact = sphere
    n = psc.estimate_normals(points)
    assert n.shape == points.shape
    assert np.einsum("ij,ij->i", n, exact).min() > 0.99  # outward, accurate
    inward = psc.estimate_normals(points, orientation=("towards", (0, 0, 0)))
    assert np.einsum("ij,ij->i", inward, exact).max() < -0.99
    up = psc.estimate_normals(points, neighbors=12, orientation="+z", threads=1)
    assert (up[:, 2] >= 0).all()
    up2 = psc.estimate_normals(points, neighbors=12, orientation=("along", (0, 0, 1)))
    assert np.array_equal(up, up2)
    by_radius = psc.estimate_normals(points, radius=0.1, orientation="+x")
    assert (by_radius[:, 0] >= 0).all()
    with pytest.raises(ValueError):
        psc.estimate_normals(points, orientation="sideways")
    with pytest.raises(ValueError):
        psc.estimate_normals(points, neighbors=0)
    with pytest.raises(psc.Cancelled):
        psc.estimate_normals(points, progress=lambda f: False)
    # curvatures from the estimated normals
    r = psc.estimate_curvatures(points, n, radius=0.25)
    assert np.abs(r["mean"] - 0.5).max() < 0.02


def test_tile_grid():
    g = psc.TileGrid((0, 0, 0), (10, 10, 10), 4.0)
    assert len(g) == 27 and g.counts == (3, 3, 3)
    t = g.tile(13, 1.0)
    assert t.core_min[0] == pytest.approx(10 / 3) and t.halo == 1.0
    assert np.isinf(g.tile(0, 1.0).core_min).all()
    ids = g.tile_of(np.array([[5.0, 5, 5], [np.nan, 0, 0], [-100, -100, -100]]))
    assert list(ids) == [13, 27, 0]
    p, t = g.tiles_near(np.array([[5.0, 5, 5], [3.4, 5, 5]]), 0.2)
    assert list(zip(t, p)) == [(12, 1), (13, 0), (13, 1)]
    with pytest.raises(ValueError):
        psc.TileGrid((0, 0, 0), (1, 1, 1), 0.0)
