# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""point_set_curvatures.dask on a LocalCluster of 2 worker processes: bitwise equal to the
single-process run."""

import contextlib
import time

import numpy as np
import pytest

import point_set_curvatures as psc
from conftest import fibonacci_sphere

distributed = pytest.importorskip("distributed")
import point_set_curvatures.dask as psc_dask  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None, silence_logs=40)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def cloud():
    points, normals = fibonacci_sphere(200_000, radius=1.0, center=(3.0, -2.0, 1.0))
    rng = np.random.default_rng(5)
    order = rng.permutation(len(points))  # input order unrelated to space
    points, normals = points[order], normals[order]
    points[17] = np.nan  # a non-finite point: nobody's own point
    return points, normals


def assert_same(a, b):
    assert set(a) == set(b)
    for k in a:
        assert a[k].dtype == b[k].dtype and a[k].shape == b[k].shape, k
        assert np.array_equal(a[k].view(np.uint8), b[k].view(np.uint8)), k


def test_dask_by_radius(client, cloud):
    points, normals = cloud
    single = psc.estimate_curvatures(points, normals, radius=0.03)
    assert (single["status"] == psc.Status.VALID).sum() == len(points) - 1
    assert_same(single, psc_dask.estimate_curvatures(client, points, normals, radius=0.03))
    # more, smaller tiles
    assert_same(single, psc_dask.estimate_curvatures(client, points, normals, radius=0.03, tile_size=0.4))


def test_dask_by_count_and_methods(client, cloud):
    points, normals = cloud
    single = psc.estimate_curvatures(points, normals, neighbors=30, aso_variant="paper")
    # a small first halo: the tiles that need more are resubmitted (HaloTooSmall)
    assert_same(single, psc_dask.estimate_curvatures(client, points, normals, neighbors=30, aso_variant="paper",
                                                     tile_size=0.5, initial_halo=1e-3))
    # the default ASO (sample weights) by count: the areas may ask for a larger halo too
    default = psc.estimate_curvatures(points, normals, neighbors=30)
    assert_same(default, psc_dask.estimate_curvatures(client, points, normals, neighbors=30, tile_size=0.5,
                                                      initial_halo=1e-3))
    apss = psc.estimate_curvatures(points, normals, method="pss", radius=0.03)
    assert_same(apss, psc_dask.estimate_curvatures(client, points, normals, method="pss", radius=0.03))


def test_dask_automatic_scale(client, cloud, tmp_path):
    # neighbors="auto" in tiles: bitwise the single-process run (a noisy part of the sphere,
    # where the counts climb the ladder: the tiles ask for larger halos)
    points, normals = cloud
    points, normals = points[:20_000].copy(), normals[:20_000]  # (in random order: the whole sphere)
    spacing = np.sqrt(4 * np.pi / 20_000)
    points += normals * (0.3 * spacing * np.random.default_rng(3).standard_normal(len(points)))[:, None]
    single = psc.estimate_curvatures(points, normals, neighbors="auto")
    assert "mean_error" in single and np.median(single["neighbors"]) > 80
    assert_same(single, psc_dask.estimate_curvatures(client, points, normals, neighbors="auto", tile_size=1.0,
                                                     initial_halo=1e-3))
    # by default too (neither radius nor neighbors), as the single-process run
    assert_same(single, psc_dask.estimate_curvatures(client, points, normals, tile_size=1.0))
    # the same from a file, the workers reading their tiles and writing the rows (with mean_error),
    # by neighbors="auto" and by default (neither radius nor neighbors: the automatic scale of
    # the robust ASO, as the single-process run's default)
    np.save(tmp_path / "c.npy", np.hstack([points, normals]))
    assert_same(single, psc.estimate_curvatures(points, normals))
    for scale in ({"neighbors": "AUTO"}, {}):
        report = psc_dask.estimate_curvatures_file(client, tmp_path / "c.npy", tmp_path / "o.npy", tile_size=1.0,
                                                   initial_halo=1e-3, **scale)
        assert report["resubmitted"] > 0
        result = psc_dask.read_result(tmp_path / "o.npy")
        assert result["mean_error"].dtype == np.float64 and np.isnan(result["mean_error"][17])
        assert_same(single, {k: np.ascontiguousarray(v) for k, v in result.items()})
    # and a fixed count keeps the record without mean_error
    psc_dask.estimate_curvatures_file(client, tmp_path / "c.npy", tmp_path / "o.npy", neighbors=40)
    assert "mean_error" not in psc_dask.read_result(tmp_path / "o.npy")


def test_dask_error_cancels_pending_tiles(client, cloud):
    # A tile that raises stops the run and cancels the tiles still pending, so that the
    # cluster does not go on with them (the traceback keeps the caller's frame, and with it the
    # futures it held, alive): the scheduler keeps at most the tile that raised.
    points, normals = cloud
    with pytest.raises(ValueError, match="unknown option 'no_such_option'"):
        psc_dask.estimate_curvatures(client, points, normals, radius=0.03, tile_size=0.2, no_such_option=1)

    def tiles_held(dask_scheduler):
        return sum(1 for key in dask_scheduler.tasks if str(key).startswith("psc-tile"))

    # (the cancellation reaches the scheduler asynchronously: polled for up to 60 s, a watchdog
    # against a hang, not a timing; it is there within 0.1 s on an idle machine)
    for _ in range(1200):
        held = client.run_on_scheduler(tiles_held)
        if held <= 1:
            break
        time.sleep(0.05)
    assert held <= 1


def test_dask_shared_sample_weights(client, cloud):
    # weights given per point travel with each tile's rows: bitwise the single-process run with
    # them (random weights, which no tile could compute itself), by radius and by count
    points, normals = cloud
    w = np.random.default_rng(9).random(len(points)) + 0.5
    for scale in (dict(radius=0.03), dict(neighbors=30)):
        single = psc.estimate_curvatures(points, normals, sample_weights=w, **scale)
        assert not np.array_equal(single["k_max"], psc.estimate_curvatures(points, normals, **scale)["k_max"],
                                  equal_nan=True)
        assert_same(single, psc_dask.estimate_curvatures(client, points, normals, sample_weights=w, tile_size=0.5,
                                                         **scale))
    apss = psc.estimate_curvatures(points, normals, method="apss", radius=0.03, sample_weights=w)
    assert_same(apss, psc_dask.estimate_curvatures(client, points, normals, method="apss", radius=0.03,
                                                   sample_weights=w))
    # bad weights are reported with the whole cloud's index before any tile runs
    with pytest.raises(ValueError, match="sample_weights"):
        psc_dask.estimate_curvatures(client, points, normals, radius=0.03, sample_weights=w[:-1])
    bad = w.copy()
    bad[17] = np.nan  # point 17 is not finite: in no tile
    with pytest.raises(ValueError, match="weight of point 17"):
        psc_dask.estimate_curvatures(client, points, normals, radius=0.03, sample_weights=bad)
    with pytest.raises(ValueError, match="does not apply"):
        psc_dask.estimate_curvatures(client, points, normals, method="pss", radius=0.03, sample_weights=w)


def test_dask_far_outlier_and_the_tiling_rules(client, cloud, monkeypatch):
    """The tiles' rules are the library's (Tile.h), as the tool's: the box ignores a far
    outlier (quantiles), a tile's range is the finite points within the halo's distance, its
    own points those of the half-open core; with an outlier and infinite coordinates the tiles
    still give the single run."""
    points, normals = cloud[0][:20_000].copy(), cloud[1][:20_000].copy()
    points[123] = (1e6, 0, 0)
    points[124] = (-np.inf, -2, 1)
    points[125] = (np.inf, -2, 1)
    finite = points[np.isfinite(points).all(axis=1)]
    lo, hi = psc._core.tile_grid_box(points)
    # ranks floor(0.001 (m - 1)) and ceil(0.999 (m - 1)) of the m finite points on each axis
    m = len(finite)
    ranked = np.sort(finite, axis=0)
    assert lo == tuple(ranked[int(0.001 * (m - 1))]) and hi == tuple(ranked[int(np.ceil(0.999 * (m - 1)))])
    assert hi[0] < 10
    # the box the run takes
    boxes = []

    class Grid(psc.TileGrid):
        def __init__(self, box_min, box_max, *args, **kwargs):
            boxes.append((tuple(box_min), tuple(box_max)))
            super().__init__(box_min, box_max, *args, **kwargs)

    monkeypatch.setattr(psc_dask, "TileGrid", Grid)
    single = psc.estimate_curvatures(points, normals, neighbors=30, aso_variant="paper")
    assert_same(single, psc_dask.estimate_curvatures(client, points, normals, neighbors=30, aso_variant="paper",
                                                     tile_size=0.5, initial_halo=1e-3))
    assert boxes == [(lo, hi)]
    # a tile's own points and range: non-finite points are nobody's and in no range
    t = psc.TileGrid.Tile(0, (0, 0, 0), (1, 1, 1), 0.5)
    q = np.array([[0.5, 0.5, 0.5], [1, 0.5, 0.5], [0, 0, 0], [1.5, 0.5, 0.5], [np.nan, 0, 0], [-2, 0, 0]])
    assert t.owns(q).tolist() == [True, False, True, False, False, False]
    mask, taken, nearest = psc._core.tile_range(t.core_min, t.core_max, t.halo, q)  # (distances 0 0 0 0.5 NaN 2)
    assert mask.tolist() == [True, True, True, True, False, False] and taken == 4 and nearest == 2
    outer = psc.TileGrid.Tile(0, (-np.inf,) * 3, (0, 0, 0), 1.0)
    q = np.array([[-np.inf, -1, -1], [-1, -1, -1], [np.inf, -1, -1], [0.5, -1, -1], [3, -1, -1]])
    assert outer.owns(q).tolist() == [False, True, False, False, False]
    mask, taken, nearest = psc._core.tile_range(outer.core_min, outer.core_max, outer.halo, q)
    assert mask.tolist() == [False, True, False, True, False] and taken == 2 and nearest == 3
    with pytest.raises(ValueError, match="initial_halo must be positive"):
        psc_dask.estimate_curvatures(client, points, normals, neighbors=30, initial_halo=float("nan"))


def test_estimate_tile_halo_too_small(cloud):
    points, normals = cloud
    grid = psc.TileGrid((2, -3, 0), (4, -1, 2), counts=(2, 2, 2))
    t = grid.tile(0, 1e-4)
    sel = t.halo_mask(points)
    r = psc_dask.estimate_tile(points[sel], normals[sel], t.core_min, t.core_max, t.halo, neighbors=30,
                               aso_variant="paper")
    assert r[0] == "halo" and r[1] > 1e-4


# ---------------------------------------------------------------------------------------------
# The file variant: workers read their tiles from PLY / .npy files and write a .npy output.
# ---------------------------------------------------------------------------------------------

import os  # noqa: E402
import sys  # noqa: E402


def write_ply(path, points, normals, dtype="double", extra=True):
    """A binary little-endian PLY: vertices x y z nx ny nz (+ an 'intensity' uchar and a face
    element after the vertices with extra=True)."""
    n = len(points)
    fields = [(c, "<f8" if dtype == "double" else "<f4") for c in ("x", "y", "z", "nx", "ny", "nz")]
    if extra:
        fields.insert(3, ("intensity", "u1"))
    rec = np.zeros(n, dtype=np.dtype(fields))
    for a, c in enumerate("xyz"):
        rec[c] = points[:, a]
        rec["n" + c] = normals[:, a]
    header = ["ply", "format binary_little_endian 1.0", "comment written by test_dask", f"element vertex {n}"]
    for name, t in fields:
        header.append(f"property {'uchar' if t == 'u1' else dtype} {name}")
    if extra:
        header += ["element face 1", "property list uchar int vertex_indices"]
    header.append("end_header")
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        f.write(rec.tobytes())
        if extra:
            f.write(np.array([3], np.uint8).tobytes() + np.array([0, 1, 2], "<i4").tobytes())


def read_output(path):
    return {k: np.ascontiguousarray(v) for k, v in psc_dask.read_result(path).items()}


N_BIG = 1_000_000
R_BIG = 3.6 * np.sqrt(4 * np.pi / N_BIG)  # about 41 neighbours


@pytest.fixture(scope="module")
def big_files(tmp_path_factory):
    """1M points of a sphere in random order (a NaN and an infinite point among them), split
    into a PLY file and a .npy file; the single-process result on the concatenation."""
    points, normals = fibonacci_sphere(N_BIG, radius=1.0, center=(3.0, -2.0, 1.0))
    order = np.random.default_rng(7).permutation(N_BIG)
    points, normals = points[order], normals[order]
    points[123] = np.nan
    points[456_789] = (np.inf, 0.0, 0.0)
    d = tmp_path_factory.mktemp("dask_files")
    split = 400_000
    write_ply(d / "part1.ply", points[:split], normals[:split])
    np.save(d / "part2.npy", np.hstack([points[split:], normals[split:]]))
    single = psc.estimate_curvatures(points, normals, radius=R_BIG)
    assert (single["status"] == psc.Status.VALID).sum() == N_BIG - 2
    return [str(d / "part1.ply"), str(d / "part2.npy")], single, d


def check_report(report, n_finite):
    tiles = [t["tile"] for t in report["tile_reports"]]
    assert len(tiles) == len(set(tiles)) == report["tiles"] > 1  # one report per tile
    assert sum(t["own"] for t in report["tile_reports"]) == n_finite


def test_file_1m_bitwise(client, big_files):
    paths, single, d = big_files
    report = psc_dask.estimate_curvatures_file(client, paths, d / "out.npy", radius=R_BIG)
    assert report["points"] == N_BIG and report["finite_points"] == N_BIG - 2
    check_report(report, N_BIG - 2)
    assert_same(single, read_output(d / "out.npy"))


class KillOnce(distributed.WorkerPlugin):
    """Kills its worker process (os._exit) as the first tile task starts executing anywhere in
    the cluster, once: a marker file records it. At once rather than after a delay: a tile of
    the test takes about 0.1 s, and a kill after the task had finished would test no retry.
    The tile tasks of both entry points have keys psc-tile-..."""

    def __init__(self, marker):
        self.marker = marker

    def transition(self, key, start, finish, **kwargs):
        if finish == "executing" and str(key).startswith("psc-tile") and not os.path.exists(self.marker):
            try:  # created atomically: when both workers start a tile at once, only one dies
                fd = os.open(self.marker, os.O_WRONLY | os.O_CREAT | os.O_EXCL)
            except FileExistsError:
                return
            os.write(fd, f"{os.getpid()} {key}\n".encode())
            os.close(fd)
            os._exit(1)  # the task is executing: the scheduler must run it again elsewhere


def test_file_worker_killed(big_files):
    paths, single, d = big_files
    marker = d / "killed"
    with killing_cluster(marker) as client:
        pids_before = set(client.run(os.getpid).values())
        report = psc_dask.estimate_curvatures_file(client, paths, d / "out_killed.npy", radius=R_BIG,
                                                   tile_size=0.7)
    assert marker.exists()
    killed_pid = int(marker.read_text().split()[0])
    assert killed_pid in pids_before
    assert killed_pid not in {t["pid"] for t in report["tile_reports"]}  # its task ran again elsewhere
    check_report(report, N_BIG - 2)  # every point exactly once (also checked inside)
    assert_same(single, read_output(d / "out_killed.npy"))


@contextlib.contextmanager
def killing_cluster(marker):
    """A client of a LocalCluster of its own (2 worker processes) whose workers carry KillOnce
    (the nanny restarts the killed worker): a cluster per fault, closed after, so that a worker
    still restarting cannot disturb the next test."""
    import cloudpickle

    cloudpickle.register_pickle_by_value(sys.modules[__name__])  # workers need not import this file
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=":0", silence_logs=40)  # 8787 may be taken
    try:
        with distributed.Client(cluster) as client:
            client.register_worker_plugin(KillOnce(str(marker)), name="kill-once")
            yield client
    finally:
        cluster.close()
        cloudpickle.unregister_pickle_by_value(sys.modules[__name__])


@pytest.mark.parametrize("run", ["radius", "count", "weights"])
def test_in_memory_worker_killed(run, cloud, tmp_path, caplog):
    """The in-memory entry point with a worker killed as a tile starts: the tiles whose scattered
    rows died with it (dask cancels them: their data cannot be recomputed) are scattered again and
    resubmitted; the result is bitwise the single-process run. Both scales (by count, tiles also
    resubmitted with a larger halo), and per-point sample weights (scattered too)."""
    points, normals = cloud
    kwargs, dask_kwargs = {
        "radius": (dict(radius=0.03), {}),
        "count": (dict(neighbors=30, aso_variant="paper"), dict(initial_halo=1e-3)),
        "weights": (dict(radius=0.03, sample_weights=np.random.default_rng(3).random(len(points)) + 0.5), {}),
    }[run]
    single = psc.estimate_curvatures(points, normals, **kwargs)
    marker = tmp_path / "killed"
    with killing_cluster(marker) as client:
        pids_before = set(client.run(os.getpid).values())
        result = psc_dask.estimate_curvatures(client, points, normals, tile_size=0.5, **kwargs, **dask_kwargs)
    assert marker.exists()
    assert int(marker.read_text().split()[0]) in pids_before
    assert_same(single, result)
    # the tiles of the dead worker were scattered again (logged by the module)
    logged = [r.getMessage() for r in caplog.records if r.name == "point_set_curvatures.dask"]
    assert any("submitted again" in m for m in logged), logged


def test_in_memory_lost_rows_without_retries(cloud, tmp_path):
    """retries=0: the tile whose rows were lost is not resubmitted, the run fails (dask's
    CancelledError) rather than returning a partial result."""
    points, normals = cloud
    with killing_cluster(tmp_path / "killed") as client:
        with pytest.raises(Exception) as e:
            psc_dask.estimate_curvatures(client, points, normals, radius=0.03, tile_size=0.5, retries=0)
    assert (tmp_path / "killed").exists()
    # the lost rows (CancelledError), or a scatter to the dying worker (CommClosedError, an OSError)
    assert type(e.value).__name__ == "CancelledError" or isinstance(e.value, OSError), repr(e.value)


def test_dask_arguments(client, cloud, tmp_path):
    points, normals = cloud
    p, n = points[:20000], normals[:20000]
    with pytest.raises(TypeError, match="radius must be a number"):
        psc_dask.estimate_curvatures(client, p, n, radius="0.1")
    with pytest.raises(TypeError, match="tile_size must be a number"):
        psc_dask.estimate_curvatures(client, p, n, radius=0.1, tile_size="1")
    with pytest.raises(TypeError, match="retries"):
        psc_dask.estimate_curvatures(client, p, n, radius=0.1, retries=1.5)
    assert_same(psc.estimate_curvatures(p, n, method="pss", radius=0.1),
                psc_dask.estimate_curvatures(client, p, n, method="PSS", radius=0.1))
    with pytest.warns(psc.ScaleWarning, match="whole cloud"):
        psc_dask.estimate_curvatures(client, p[:500], n[:500], radius=1e300)
    # point 17 is not finite: 499 points can be neighbours (a cap at 500 made every tile ask for
    # a larger halo, forever)
    with pytest.warns(psc.ScaleWarning, match=r"\(499\): every neighbourhood is the whole cloud \(capped at 499\)"):
        r = psc_dask.estimate_curvatures(client, p[:500], n[:500], neighbors=10**12, aso_variant="paper")
    with pytest.warns(psc.ScaleWarning):
        assert_same(psc.estimate_curvatures(p[:500], n[:500], neighbors=10**12, aso_variant="paper"), r)
    # the file variant with a radius above 0.5 (its check of the arguments on no point used a halo
    # of 1, which the estimators refuse for radii above half of it), and method names in any case
    q, m = fibonacci_sphere(3000, radius=2.0)
    np.save(tmp_path / "c.npy", np.hstack([q, m]))
    psc_dask.estimate_curvatures_file(client, tmp_path / "c.npy", tmp_path / "o.npy", radius=0.6, method="ASO")
    assert_same(psc.estimate_curvatures(q, m, radius=0.6), read_output(tmp_path / "o.npy"))
    r32 = np.float32(0.6)  # any real number
    assert_same(psc.estimate_curvatures(q, m, radius=r32), psc_dask.estimate_curvatures(client, q, m, radius=r32))
    with pytest.warns(psc.ScaleWarning, match="whole cloud"):
        psc_dask.estimate_curvatures_file(client, tmp_path / "c.npy", tmp_path / "o.npy", radius=1e300)
    with pytest.raises(TypeError, match="block_rows"):
        psc_dask.estimate_curvatures_file(client, tmp_path / "c.npy", tmp_path / "o.npy", radius=0.6, block_rows="9")


def test_file_float32_ply_and_count(client, tmp_path):
    points, normals = fibonacci_sphere(30_000, radius=2.0, center=(1.0, 1.0, 1.0))
    points, normals = points.astype(np.float32), normals.astype(np.float32)
    write_ply(tmp_path / "f.ply", points, normals, dtype="float")
    single = psc.estimate_curvatures(points, normals, radius=0.1)
    report = psc_dask.estimate_curvatures_file(client, tmp_path / "f.ply", tmp_path / "o.npy", radius=0.1,
                                               block_rows=4096)
    check_report(report, 30_000)
    assert_same(single, read_output(tmp_path / "o.npy"))
    # by count, a small first halo: tiles resubmitted with the halo they ask for
    single = psc.estimate_curvatures(points, normals, neighbors=30, aso_variant="paper")
    report = psc_dask.estimate_curvatures_file(client, str(tmp_path / "f.ply"), tmp_path / "c.npy", neighbors=30,
                                               aso_variant="paper", initial_halo=1e-3, block_rows=4096)
    assert report["resubmitted"] > 0
    assert_same(single, read_output(tmp_path / "c.npy"))


def test_file_ply_header_read_as_the_tool_reads_it(client, tmp_path):
    # The workers map the vertices where the package's PLY reader (the tool's) finds them:
    # big-endian, normals named normal_x normal_y normal_z, integer properties around them.
    points, normals = fibonacci_sphere(5_000, radius=1.5)
    fields = [("flags", ">u2"), ("x", ">f8"), ("y", ">f8"), ("z", ">f8"), ("label", ">i4"),
              ("normal_x", ">f8"), ("normal_y", ">f8"), ("normal_z", ">f8")]
    rec = np.zeros(len(points), dtype=np.dtype(fields))
    rec["flags"], rec["label"] = 7, -3
    for a, c in enumerate("xyz"):
        rec[c], rec["normal_" + c] = points[:, a], normals[:, a]
    types = {">u2": "ushort", ">f8": "double", ">i4": "int"}
    header = ["ply", "format binary_big_endian 1.0", "element camera 2", "property float fx",
              f"element vertex {len(points)}"] + [f"property {types[t]} {n}" for n, t in fields] + ["end_header"]
    with open(tmp_path / "be.ply", "wb") as f:
        f.write(("\n".join(header) + "\n").encode() + bytes(8) + rec.tobytes())
    read = psc.read_point_cloud(tmp_path / "be.ply")
    np.testing.assert_array_equal(read["points"], points)
    np.testing.assert_array_equal(read["normals"], normals)
    single = psc.estimate_curvatures(points, normals, radius=0.15)
    psc_dask.estimate_curvatures_file(client, tmp_path / "be.ply", tmp_path / "o.npy", radius=0.15, block_rows=1024)
    assert_same(single, read_output(tmp_path / "o.npy"))


def test_file_bad_input(client, tmp_path):
    p, q = fibonacci_sphere(100)
    (tmp_path / "ascii.ply").write_text(
        "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n")
    np.save(tmp_path / "shape.npy", np.zeros((10, 4)))
    np.save(tmp_path / "ints.npy", np.zeros((10, 6), dtype=np.int32))
    np.save(tmp_path / "xyz.npy", p)
    (tmp_path / "list.ply").write_bytes(
        b"ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
        b"property double z\nproperty list uchar int idx\nend_header\n" + bytes(25))
    write_ply(tmp_path / "short.ply", p, q)
    with open(tmp_path / "short.ply", "r+b") as f:
        f.truncate(os.path.getsize(tmp_path / "short.ply") - 50)
    (tmp_path / "text.txt").write_text("1 2 3 0 0 1\n")
    for name, what in [("ascii.ply", "only binary"), ("shape.npy", "shape"), ("ints.npy", "float"),
                       ("list.ply", "list"), ("short.ply", "truncated"),
                       ("text.txt", "neither")]:
        with pytest.raises(ValueError, match=what):
            psc_dask.estimate_curvatures_file(client, tmp_path / name, tmp_path / "o.npy", radius=0.1)
    np.save(tmp_path / "ok.npy", np.hstack([p, q]))
    with pytest.raises(ValueError, match="has no normals"):  # one cloud: every file with normals or none
        psc_dask.estimate_curvatures_file(client, [tmp_path / "ok.npy", tmp_path / "xyz.npy"], tmp_path / "o.npy")
    with pytest.raises(ValueError, match="normal_orientation: the files have normals"):
        psc_dask.estimate_curvatures_file(client, tmp_path / "ok.npy", tmp_path / "o.npy", normal_orientation="+z")
    with pytest.raises(ValueError, match="orientation: expected"):
        psc_dask.estimate_curvatures_file(client, tmp_path / "xyz.npy", tmp_path / "o.npy", normal_orientation="up")
    with open(DATA_DIR + "/real/sample_c.las", "rb") as f:
        (tmp_path / "laz.las").write_bytes(f.read(104) + bytes([f.read(1)[0] | 0x80]) + f.read(300))
    with pytest.raises(ValueError, match="LAZ"):
        psc_dask.estimate_curvatures_file(client, tmp_path / "laz.las", tmp_path / "o.npy")
    with pytest.raises(ValueError, match="not both"):
        psc_dask.estimate_curvatures_file(client, tmp_path / "ok.npy", tmp_path / "o.npy", radius=0.5, neighbors=30)
    with pytest.raises(ValueError):
        psc_dask.estimate_curvatures_file(client, tmp_path / "ok.npy", tmp_path / "o.npy", radius=0.5,
                                          no_such_option=1)


# ---------------------------------------------------------------------------------------------
# Files without normals: the normals estimated tile by tile, as estimate_curvatures does
# ---------------------------------------------------------------------------------------------

DATA_DIR = os.environ.get("PSC_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def test_file_las_without_normals(client, tmp_path):
    """A LAS file (no normals): by default the tool's route, normals by the automatic scale
    oriented by normal_orientation 'auto' (the spanning tree's records gathered from the tiles),
    bitwise the single-process estimate on the coordinates the package's LAS reader gives; and
    with a per-point orientation (+z), oriented in the tiles."""
    path = os.path.join(DATA_DIR, "real", "sample_c.las")
    points = psc.read_point_cloud(path)["points"]
    blend = {"position_fit_blend": 0.5}
    for orientation, neighbors in [("auto", 40), ("+z", "auto")]:
        kwargs = {} if orientation == "auto" else {"normal_orientation": orientation}
        report = psc_dask.estimate_curvatures_file(client, path, tmp_path / "o.npy", neighbors=neighbors,
                                                   tile_size=60.0, **kwargs)
        normals = psc.estimate_normals(points, neighbors=None if neighbors == 40 else "auto", orientation=orientation)
        expected = psc.estimate_curvatures(points, normals, neighbors=neighbors, **blend)
        assert_same(read_output(tmp_path / "o.npy"), expected)
        assert report["normals"]["tiles"] >= 4 and report["normals"]["spanning_tree"] == (orientation == "auto")
        assert (normals[:, 2] > 0).mean() > 0.97  # an airborne tile: its normals up
        assert sorted(os.listdir(tmp_path)) == ["o.npy"]  # the normals' files removed


def test_file_npy_without_normals_as_in_memory(client, tmp_path):
    """An (N, 3) .npy file: estimate_curvatures(points, None), bitwise (a spanning tree over a
    closed noisy sphere, outward), halos too small at first in both passes."""
    points, _ = fibonacci_sphere(6000, radius=1.0, center=(1.0, 2.0, 3.0))
    points += np.random.default_rng(3).normal(scale=0.004, size=points.shape)
    points = points[np.random.default_rng(4).permutation(len(points))]
    points[11] = np.nan
    np.save(tmp_path / "c.npy", points)
    with pytest.warns(UserWarning, match="no normals given"):
        expected = psc.estimate_curvatures(points, None)
    report = psc_dask.estimate_curvatures_file(client, tmp_path / "c.npy", tmp_path / "o.npy", tile_size=0.7,
                                               initial_halo=0.05)
    result = read_output(tmp_path / "o.npy")
    assert_same(result, expected)
    assert report["normals"]["resubmitted"] > 0 and report["resubmitted"] > 0
    valid = result["status"] == psc.Status.VALID
    assert valid.mean() > 0.99 and abs(np.median(result["mean"][valid]) - 1.0) < 0.05  # outward: H = 1/R


def test_orient_normal_records_refuses_bad_records():
    """The binding of the spanning tree's pass checks the records it is given (they come from a
    temporary file): neighbour indices within the records, known statuses, unit normals where
    valid (the orientation walks rays along them)."""
    from point_set_curvatures import _core

    def records():
        normal = np.zeros((3, 3))
        normal[:, 2] = 1.0
        return (normal, np.zeros((3, _core.NORMAL_RECORD_DEGREE), np.uint32), np.zeros(3, np.uint8),
                np.zeros(3, np.uint8), np.zeros((3, 3)))

    n = _core.orient_normal_records(*records(), 0, [0.0, 0.0, 1.0], 1, None)
    assert n.shape == (3, 3) and np.all(n[:, 2] == 1.0)
    normal, neighbor, degree, status, xyz = records()
    normal[1] = 0.0
    with pytest.raises(ValueError, match="unit vector"):
        _core.orient_normal_records(normal, neighbor, degree, status, xyz, 0, [0.0, 0.0, 1.0], 1, None)
    status[1] = psc.Status.DEGENERATE_FIT  # not valid: no normal needed
    _core.orient_normal_records(normal, neighbor, degree, status, xyz, 0, [0.0, 0.0, 1.0], 1, None)
    normal, neighbor, degree, status, xyz = records()
    degree[0], neighbor[0, 0] = 1, 3
    with pytest.raises(ValueError, match="beyond the records"):
        _core.orient_normal_records(normal, neighbor, degree, status, xyz, 0, [0.0, 0.0, 1.0], 1, None)
    normal, neighbor, degree, status, xyz = records()
    status[2] = 99
    with pytest.raises(ValueError, match="unknown status"):
        _core.orient_normal_records(normal, neighbor, degree, status, xyz, 0, [0.0, 0.0, 1.0], 1, None)
