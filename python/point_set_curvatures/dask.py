# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Distributed estimation on a ``dask.distributed`` cluster, tile by tile.

The cloud is split with the library's tiling (:class:`point_set_curvatures.TileGrid`, the
C++ ``Tile_grid``): every finite point is own in exactly one tile, and each tile is
estimated from its own points and every point within its halo, in input order, with the
``tile`` option of the estimators. The result of every point is then bitwise identical to
the single-process run (the library's guarantee, tested in ``tests/test_dask.py``).

The halo is two radii with a radius (the default ASO's sample weights need two; one would do
for the other estimators). By neighbour count a point's radius is only known once its
neighbours are found: a tile whose halo is too small fails with
:class:`point_set_curvatures.HaloTooSmall`, and is resubmitted with the halo it asks for
(with the ASO's default sample weights, also when its neighbours' areas need a larger one).

:func:`estimate_curvatures` takes arrays held by the client and scatters each tile's points;
:func:`estimate_curvatures_file` takes PLY, .npy and LAS files that the workers read themselves,
tile by tile, writing their own points' rows of a .npy output (for clouds larger than the
client); files without normals get them in a first pass of tiles.

Both survive the loss of workers: a task whose worker dies is run again elsewhere (dask's
``retries``), and with :func:`estimate_curvatures` a tile whose scattered rows were lost with
their worker (scattered data cannot be recomputed: dask cancels the tasks that need it) is
scattered again from the client's arrays and resubmitted, up to ``retries`` times per tile.
The results are the same bytes as without the fault.

Any ``distributed.Client`` works: a ``LocalCluster`` on one machine, or a scheduler started
across machines with ``dask-scheduler`` and ``dask-worker tcp://SCHEDULER:8786`` (every
worker must be able to import ``point_set_curvatures``).
"""

import asyncio
import contextlib
import logging
import math
import numbers
import os
import time
import uuid
from concurrent.futures import CancelledError

import numpy as np

from . import _METHOD_OPTIONS, AUTOMATIC_NEIGHBORS, HaloTooSmall, SampleWeights, Status, TileGrid, _core, _int, _method, _real
from . import _blend_on_estimated_normals, _estimated_normal_neighbors, _orientation, _spans_whole_cloud, _threads
from . import _weights
from . import _file_sources as _files
from . import _default_neighbors, _whole_cloud_box, _whole_cloud_scale
from . import estimate_curvatures as _estimate_curvatures

__all__ = ["estimate_curvatures", "estimate_curvatures_file", "read_result", "estimate_tile", "RESULT_DTYPE",
           "AUTOMATIC_RESULT_DTYPE"]

_log = logging.getLogger(__name__)

#: The fields of a result, from the package's table (field_descriptions.h): key, numpy type,
#: shape per point, whether the automatic scale alone gives it; and the real ones (NaN where a
#: point has no estimate).
_FIELDS = _core.fields()
_REAL_FIELDS = tuple(f["key"] for f in _FIELDS if f["dtype"] == "<f8")



def _scale_of_run(method, radius, neighbors, options):
    """(radius, neighbors) of a run: as given (at most one of them; ``neighbors="auto"`` in any
    case as ``"auto"``), or with neither the single-process default (:func:`_default_neighbors`:
    the automatic scale for the robust ASO)."""
    if radius is not None and neighbors is not None:
        raise ValueError("give either radius or neighbors, not both")
    if radius is None and neighbors is None:
        return None, _default_neighbors(method, options)
    if isinstance(neighbors, str) and neighbors.lower() == "auto":
        return radius, "auto"
    return radius, neighbors


def _weight_array(options):
    """The option sample_weights if it is per-point weights (not None, not a name)."""
    weights = options.get("sample_weights")
    return None if weights is None or isinstance(weights, (str, SampleWeights)) else weights


def _check_tile(radius):
    """A tile for checking the arguments on no point: its halo the two radii a tile needs (the
    estimators refuse a smaller one, whatever the points)."""
    real = isinstance(radius, numbers.Real) and not isinstance(radius, (bool, np.bool_))
    halo = _core.halo_for_radius(float(radius)) if real and 0 < radius < math.inf else 1.0
    return ((0.0,) * 3, (1.0,) * 3, halo)


def _next_halo(required, nearest):
    """The halo of a tile resubmitted after HaloTooSmall, by the library's rule (Tile_range,
    next_halo; the tool's): the halo it asks for, at least the distance to the core of the
    nearest finite point its range left out (``nearest``; for a tile read from files, at most
    the nearest distance of the blocks it did not read, which the next range then reads). A
    range that left no point out held the whole cloud and was estimated with an infinite halo:
    asking for more is an internal error (RuntimeError), never a loop."""
    if not math.isfinite(nearest):
        raise RuntimeError("point_set_curvatures.dask: a tile holding the whole cloud asked for a larger halo")
    return _core.next_halo(float(required), float(nearest))


def _range(points, core_min, core_max, halo, finite_in_cloud):
    """A tile's range among ``points`` by the library's rules (Tile_range, the tool's): the
    indices of the finite rows at distance ``<= halo`` from the core, the halo to estimate
    them with (infinite when they are every finite point of the cloud: halo_of_range), and the
    distance of the nearest finite row left out (infinite if none)."""
    mask, taken, nearest = _core.tile_range(core_min, core_max, float(halo), points)
    return np.nonzero(mask)[0], _core.halo_of_range(float(halo), int(taken), int(finite_in_cloud)), float(nearest)


def _initial_halo(value):
    """The argument initial_halo: None, or a positive number (infinite: the whole cloud)."""
    if value is None:
        return None
    halo = _real("initial_halo", value)
    if not halo > 0:
        raise ValueError(f"initial_halo must be positive, got {value!r}")
    return halo


def _first_halo(radius, neighbors, initial_halo, lo, hi, finite_count):
    """The halo the tiles start with (the library's rule, Tile.h): twice the radius (sample
    weights reach two radii), the caller's initial_halo, or for neighbourhoods by count the
    library's first guess from the density (halo_guess_for_count)."""
    if radius is not None:
        return _core.halo_for_radius(float(radius))
    if initial_halo is not None:
        return float(initial_halo)
    if isinstance(neighbors, str):  # "auto": the largest count of the ladder
        neighbors = AUTOMATIC_NEIGHBORS[1]
    return _core.halo_guess_for_count(tuple(map(float, lo)), tuple(map(float, hi)), int(finite_count), int(neighbors))

def estimate_tile(points, normals, core_min, core_max, halo, *, method="aso", radius=None, neighbors=None,
                  threads=1, **options):
    """Estimates one tile: ``points`` and ``normals`` hold every point of the cloud within
    ``halo`` of the half-open box ``core_min <= p < core_max``, in input order. Returns
    ``(own, result)``: the boolean mask of the tile's own points among the rows, and the
    dict of :func:`point_set_curvatures.estimate_curvatures` restricted to them; or
    ``("halo", required_halo)`` when the halo is too small (neighbourhoods by count).
    Runs in a dask worker (``threads=1`` by default: one task per worker thread)."""
    tile = TileGrid.Tile(-1, core_min, core_max, halo)
    try:
        r = _estimate_curvatures(points, normals, method=method, radius=radius, neighbors=neighbors,
                                 threads=threads, tile=tile, **options)
    except HaloTooSmall as e:
        return ("halo", float(e.required_halo))
    own = tile.owns(points)
    return own, {k: v[own] for k, v in r.items()}


def _tile_side(lo, hi, count):
    """A side giving about `count` tiles over the box [lo, hi]."""
    extent = np.maximum(np.asarray(hi) - np.asarray(lo), 0.0)
    top = float(extent.max())
    if not top > 0:
        return 1.0
    side = top
    for _ in range(200):
        tiles = np.prod([max(1, math.ceil(e / side)) for e in extent])
        if tiles >= count:
            break
        side *= 0.9
    return side


def estimate_curvatures(client, points, normals, *, method="aso", radius=None, neighbors=None, tile_size=None,
                        threads=1, retries=2, initial_halo=None, **options):
    """Estimates curvatures on a dask.distributed cluster, one task per spatial tile; returns
    the dict of :func:`point_set_curvatures.estimate_curvatures`, in input order, bitwise
    equal to the single-process run.

    Parameters
    ----------
    client : distributed.Client
    points, normals : array_like, shape (N, 3)
    method, radius, neighbors, **options
        As for :func:`point_set_curvatures.estimate_curvatures` (not ``tile``, nor ``method="vcm"``,
        nor ``normal_refinement``; normals are required here, where the single-process function
        can estimate them); with neither ``radius`` nor ``neighbors``, its default (the automatic
        scale, ``neighbors="auto"``, for the robust ASO); ``sample_weights`` given as an array
        (one weight per point) is sent to each tile with its rows.
    tile_size : float or None
        The side of the tiles; default: about 4 tiles per worker thread, and at most about
        500 000 points per tile.
    threads : int or None
        Threads of each task (default 1: the workers' threads run the tasks in parallel).
    retries : int
        Retries of a task whose worker fails (dask's ``retries``); also the number of times a
        tile whose scattered rows were lost with a worker is scattered and submitted again.
    initial_halo : float or None
        By neighbour count, the first halo tried (default: a guess from the density); tiles
        that need more are resubmitted with the halo they ask for.
    """
    if "tile" in options:
        raise ValueError("option 'tile' is chosen by point_set_curvatures.dask")
    method = _method(method)
    radius, neighbors = _scale_of_run(method, radius, neighbors, options)
    retries = _int("retries", retries, 0)
    tile_size = None if tile_size is None else _real("tile_size", tile_size)
    initial_halo = _initial_halo(initial_halo)
    points = np.asarray(points)
    normals = np.asarray(normals)
    if points.ndim != 2 or points.shape[1:] != (3,) or normals.shape != points.shape:
        raise ValueError(f"points and normals must have the same shape (N, 3), got {points.shape} and {normals.shape}")
    n = len(points)
    # output arrays, the single-process values of non-finite points
    out = {}
    for f in _FIELDS:
        if neighbors == "auto" or not f["automatic_scale_only"]:
            shape = (n,) + tuple(f["shape"])
            out[f["key"]] = np.full(shape, np.nan) if f["dtype"] == "<f8" else np.zeros(shape, dtype=f["dtype"])
    out["status"][:] = Status.NON_FINITE_POINT
    finite = np.isfinite(points).all(axis=1)
    if not finite.any():
        # nothing to distribute: validate the arguments as the single-process run does
        return _estimate_curvatures(points, normals, method=method, radius=radius, neighbors=neighbors,
                                    threads=threads, **options)
    # the checks of the single-process run (a tile sees only a part of the cloud), before any
    # data travels: the arguments (on no point), then the scale against the whole cloud
    _estimate_curvatures(np.zeros((0, 3)), np.zeros((0, 3)), method=method, radius=radius, neighbors=neighbors,
                         threads=threads, tile=_check_tile(radius),
                         **{k: v for k, v in options.items() if k != "sample_weights" or _weight_array(options) is None})
    if points.dtype.kind == "f":
        radius, neighbors = _whole_cloud_scale(points, radius, neighbors)
    # the tiles' box: the library's (tile_grid_box: quantiles that ignore outliers), the tool's
    lo, hi = _core.tile_grid_box(points)
    finite_count = int(finite.sum())
    if tile_size is None:
        workers = max(1, sum(client.nthreads().values()))
        tile_size = _tile_side(lo, hi, max(4 * workers, math.ceil(n / 500_000)))
    grid = TileGrid(lo, hi, float(tile_size))
    owner = grid.tile_of(points)
    counts = np.bincount(owner, minlength=len(grid) + 1)
    halo = _first_halo(radius, neighbors, initial_halo, lo, hi, finite_count)

    # sample weights given per point travel with their tile's rows (the whole cloud's weights)
    weights = _weight_array(options)
    if weights is not None:
        # checked here, with the whole cloud's indices (a tile sees only its rows)
        del options["sample_weights"]
        if "sample_weights" not in _METHOD_OPTIONS[method]:
            raise ValueError(f"option 'sample_weights' does not apply to method {method!r}")
        weights = _weights(weights)
        if weights.shape != (n,):
            raise ValueError(f"option 'sample_weights': expected an array of shape ({n},), got {weights.shape}")
        bad = np.nonzero(~(np.isfinite(weights) & (weights >= 0)))[0]
        if len(bad):
            raise ValueError(f"option 'sample_weights': the weight of point {bad[0]} is {weights[bad[0]]}, "
                             "weights must be finite and non-negative")
    kwargs = dict(method=method, radius=radius, neighbors=neighbors, threads=threads, **options)
    token = uuid.uuid4().hex[:8]

    def scatter(data):
        """Scatters `data` (a list of arrays), again if the worker chosen dies meanwhile."""
        for attempt in range(retries + 1):
            try:
                return client.scatter(data, hash=False)  # fresh keys: never those of lost or released data
            except (OSError, TimeoutError) as e:  # CommClosedError is an OSError
                error = e
                if attempt < retries:
                    _log.warning("scatter failed (%s: a worker lost?), scattering again (attempt %d of %d)",
                                 type(e).__name__, attempt + 1, retries)
        raise error

    def submit(index, h, attempt=0):
        tile = grid.tile(index, h)
        sel, tile_halo, nearest = _range(points, tile.core_min, tile.core_max, h, finite_count)
        data = [np.ascontiguousarray(points[sel]), np.ascontiguousarray(normals[sel])]
        if weights is not None:
            data.append(np.ascontiguousarray(weights[sel]))
        data = scatter(data)
        extra = {} if weights is None else {"sample_weights": data[2]}
        future = client.submit(estimate_tile, data[0], data[1], tile.core_min, tile.core_max, tile_halo,
                               key=f"psc-tile-{token}-{index}-{h!r}-{attempt}", retries=retries, **kwargs,
                               **extra)
        pending[future] = (index, sel, h, attempt, nearest)
        done.add(future)

    from distributed import as_completed

    pending = {}
    done = as_completed()
    with _cancel_on_error(client, pending):
        for i in range(len(grid)):
            if counts[i]:
                submit(i, halo)
        for future in done:
            i, sel, h, attempt, nearest = pending.pop(future)
            try:
                if future.status in ("cancelled", "lost"):
                    raise CancelledError(future.key)
                result = future.result()
            except (CancelledError, asyncio.CancelledError):
                # its scattered rows were lost with a worker before it ran, or its result after
                # (they cannot be recomputed): scattered again from the client's arrays
                future.release()
                if attempt >= retries:
                    raise
                _log.warning("tile %d was cancelled (its data lost with a worker?): scattered and submitted "
                             "again (attempt %d of %d)", i, attempt + 1, retries)
                submit(i, h, attempt + 1)
                continue
            future.release()
            if isinstance(result, tuple) and len(result) == 2 and isinstance(result[0], str):
                submit(i, _next_halo(result[1], nearest), attempt)
                continue
            own, r = result
            rows = sel[own]
            for k, v in r.items():
                out[k][rows] = v
    return out


# ---------------------------------------------------------------------------------------------
# Clouds in files: workers read their own tiles, write their own rows.
# ---------------------------------------------------------------------------------------------

#: Rows of a block: the unit of reading (one memory map at a time) and of spatial pruning.
BLOCK_ROWS = 1 << 17

#: The record of the output file (a .npy structured array, one row per input point, in input
#: order): the fields of :func:`point_set_curvatures.estimate_curvatures`, in their order,
#: little-endian, packed.
RESULT_DTYPE = np.dtype([(f["key"], f["dtype"], f["shape"]) for f in _FIELDS if not f["automatic_scale_only"]])

#: The record under the automatic scale (``neighbors="auto"``, the default of the robust ASO):
#: :data:`RESULT_DTYPE` with ``mean_error``, the standard error of ``mean`` at the chosen scale.
AUTOMATIC_RESULT_DTYPE = np.dtype([(f["key"], f["dtype"], f["shape"]) for f in _FIELDS])

def _scan_task(sources, blocks, stride):
    """Pass 1, on a worker: per block, the bounding box of its finite points and their count;
    and the finite points of the rows whose index is a multiple of ``stride``, the sample of
    the tiles' box (:func:`_sample_stride`)."""
    lo = np.full((len(blocks), 3), np.inf)
    hi = np.full((len(blocks), 3), -np.inf)
    finite = np.zeros(len(blocks), dtype=np.int64)
    samples = []
    for b, block in enumerate(blocks):
        p = _files.read(sources, block, _files.XYZ)
        sampled = p[(-int(block[3])) % stride::stride]
        samples.append(sampled[np.isfinite(sampled).all(axis=1)])
        p = p[np.isfinite(p).all(axis=1)]
        if len(p):
            lo[b], hi[b], finite[b] = p.min(axis=0), p.max(axis=0), len(p)
    return lo, hi, finite, np.concatenate(samples) if samples else np.zeros((0, 3))


def _sample_stride(rows):
    """The stride of the tiles' box sample over ``rows`` points: the least power of two that
    keeps at most TILE_BOX_SAMPLE_POINTS (2**20) of them, as the library's Tile_box_sample
    keeps of the finite points (the same sample, hence the tool's box, when every point is
    finite)."""
    stride = 1
    while -(-rows // stride) > _core.TILE_BOX_SAMPLE_POINTS:
        stride *= 2
    return stride


def _default_rows(rows, dtype, status=Status.NON_FINITE_POINT):
    """Output records of `dtype` of points no tile estimates (the single-process values for
    non-finite points): NaN, no neighbours, the given status."""
    rec = np.zeros(rows, dtype=dtype)
    for k in _REAL_FIELDS:
        if k in dtype.names:
            rec[k] = np.nan
    rec["status"] = status
    return rec


def _count_task(sources, blocks, grid_args, output):
    """Pass 2, on a worker: the number of own points of every tile. Also writes the blocks'
    rows of the output sequentially (allocating the file, so that the tiles' scattered writes
    only dirty pages already there): the final values of the non-finite points (nobody's own
    points), ``NOT_COMPUTED`` for the others until their tile writes them. Returns (counts,
    non-finite indices)."""
    grid = TileGrid(*grid_args)
    counts = np.zeros(len(grid) + 1, dtype=np.int64)
    bad = []
    path, offset, _, dtype = output
    fd = os.open(path, os.O_WRONLY)
    try:
        for block in blocks:
            owner = grid.tile_of(_files.read(sources, block, _files.XYZ))
            counts += np.bincount(owner, minlength=len(grid) + 1)
            nonfinite = owner == len(grid)
            rec = _default_rows(len(owner), dtype, Status.NOT_COMPUTED)
            rec["status"][nonfinite] = Status.NON_FINITE_POINT
            data = rec.tobytes()
            at = offset + int(block[3]) * dtype.itemsize
            while data:
                written = os.pwrite(fd, data, at)
                data, at = data[written:], at + written
            if nonfinite.any():
                bad.append(np.nonzero(nonfinite)[0] + int(block[3]))
    finally:
        os.close(fd)
    bad = np.concatenate(bad) if bad else np.zeros(0, dtype=np.int64)
    return counts[:-1], bad


def _write_rows(output, rows, records):
    path, offset, n, dtype = output
    w = dtype.itemsize
    mm = np.memmap(path, dtype=np.uint8, mode="r+", offset=offset, shape=(n, w))
    try:
        mm[rows] = records.view(np.uint8).reshape(-1, w)  # as bytes: several times faster
        mm.flush()
    finally:
        del mm


def _peak_rss():
    """Peak resident memory of this process so far, in bytes (Linux: ru_maxrss in KiB)."""
    try:
        import resource

        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    except (ImportError, OSError):
        return 0


def _halo_points(sources, blocks, core_min, core_max, halo, unread, finite, normals):
    """The range of a tile among the points of `blocks` (the library's rules, :func:`_range`;
    ``finite`` the cloud's finite points; ``unread`` a distance from the core below which lie
    none of the points of the blocks not read), in input order: (their indices in the cloud,
    points, normals, the halo to estimate them with, the distance of the nearest finite point
    left out, at most ``unread``); the normals read from the files (``normals`` "files"), from
    the (N, 3) .npy array of estimated normals at the path ``normals``, or not (None: None)."""
    index, points, given = [], [], []
    taken, nearest = 0, float(unread)
    for block in blocks:
        p = _files.read(sources, block, _files.XYZ)
        mask, count, left_out = _core.tile_range(core_min, core_max, float(halo), p)
        sel = np.nonzero(mask)[0]
        taken, nearest = taken + int(count), min(nearest, float(left_out))
        if len(sel):
            index.append(sel + int(block[3]))
            points.append(p[sel])
            if normals == "files":
                given.append(_files.read(sources, block, _files.NORMALS)[sel])
    index = np.concatenate(index) if index else np.zeros(0, dtype=np.int64)
    points = np.concatenate(points) if points else np.zeros((0, 3))
    tile_halo = _core.halo_of_range(float(halo), taken, int(finite))
    if normals is None:
        return index, points, None, tile_halo, nearest
    if normals == "files":
        return index, points, np.concatenate(given) if given else np.zeros((0, 3)), tile_halo, nearest
    estimated = np.load(normals, mmap_mode="r")
    try:
        return index, points, np.array(estimated[index], dtype=np.float64), tile_halo, nearest
    finally:
        del estimated


def _tile_summary(rows, index, t0, t1, t2, t3):
    """What a tile task returns: its own rows written, the points it read, the sums of the
    rows' indices (checked by the client), the time of each phase, the worker's memory."""
    u = rows.astype(np.uint64)
    return {
        "own": len(rows),
        "halo_points": len(index),
        "index_sum": int(np.sum(u, dtype=np.uint64)),
        "index_square_sum": int(np.sum(u * u, dtype=np.uint64)),  # modulo 2**64
        "read_seconds": t1 - t0,
        "compute_seconds": t2 - t1,
        "write_seconds": t3 - t2,
        "peak_rss": _peak_rss(),
        "pid": os.getpid(),
        "start": time.time() - (t3 - t0),
        "stop": time.time(),
    }


def _file_tile_task(sources, blocks, core_min, core_max, halo, unread, finite, output, kwargs, normals="files"):
    """A tile, on a worker: reads from the files its range among the points of `blocks` (input
    order kept; :func:`_halo_points`), and their normals (``normals``: as there), estimates
    the tile and writes its own points' rows into the output. Idempotent (a retried task
    rewrites the same bytes). Returns a summary, or ``("halo", required_halo, nearest)``
    (the nearest finite point left out, for :func:`_next_halo`)."""
    t0 = time.perf_counter()
    index, points, normals, tile_halo, nearest = _halo_points(sources, blocks, core_min, core_max, halo, unread,
                                                              finite, normals)
    t1 = time.perf_counter()
    result = estimate_tile(points, normals, core_min, core_max, tile_halo, **kwargs)
    t2 = time.perf_counter()
    if isinstance(result[0], str):
        return result + (nearest,)
    own, r = result
    rows = index[own]
    records = np.empty(len(rows), dtype=output[3])
    for k, v in r.items():
        records[k] = v
    _write_rows(output, rows, records)
    return _tile_summary(rows, index, t0, t1, t2, time.perf_counter())


def _record_dtype():
    """A point's normal record in the file of a spanning tree's pass: its unoriented normal,
    its nearest neighbours (indices of the cloud; zero past ``degree``), their number, its
    status."""
    return np.dtype([("normal", "<f8", (3,)), ("neighbor", "<u4", (_core.NORMAL_RECORD_DEGREE,)),
                     ("degree", "u1"), ("status", "u1")])


def _file_normal_tile_task(sources, blocks, core_min, core_max, halo, unread, finite, output, neighbors, orientation,
                           threads):
    """A tile of the normals' pass, on a worker: the normals of its own points, oriented
    (``orientation`` (kind, target) of a per-point orientation) or, for a spanning tree
    (``orientation`` None), their records (:func:`_record_dtype`), written into their rows of
    ``output``. Returns a summary as :func:`_file_tile_task`, or ``("halo", required_halo,
    nearest)``."""
    t0 = time.perf_counter()
    index, points, _, tile_halo, nearest = _halo_points(sources, blocks, core_min, core_max, halo, unread, finite,
                                                        None)
    t1 = time.perf_counter()
    tile = (tuple(core_min), tuple(core_max), tile_halo)
    try:
        normal, neighbor, degree, status = _core.normal_records(points, None, neighbors, 1, tile, _threads(threads),
                                                                None)
    except HaloTooSmall as e:
        return ("halo", float(e.required_halo), nearest)
    own = TileGrid.Tile(-1, core_min, core_max, halo).owns(points)
    rows = index[own]
    if orientation is None:
        records = np.zeros(len(rows), dtype=output[3])
        records["normal"] = normal[own]
        d = degree[own]
        listed = np.arange(neighbor.shape[1]) < d[:, None]
        records["neighbor"] = np.where(listed, index[neighbor[own]], 0)  # (as indices of the cloud)
        records["degree"] = d
        records["status"] = status[own]
    else:
        kind, target = orientation
        oriented = _core.orient_normal_records(normal, neighbor, degree, status, points, kind, list(target), 1, None)
        records = np.ascontiguousarray(oriented[own])
    t2 = time.perf_counter()
    _write_rows(output, rows, records)
    return _tile_summary(rows, index, t0, t1, t2, time.perf_counter())


def _orient_task(sources, blocks, records_path, output, nonfinite, orientation, threads):
    """The spanning tree's pass, on one worker: the records of every point (their file at
    ``records_path``; the non-finite points', which no tile wrote, marked so) oriented over the
    whole cloud as ``estimate_normals`` orients them, written to ``output``. Returns
    {"seconds", "peak_rss"}."""
    t0 = time.perf_counter()
    records = np.load(records_path, mmap_mode="r")
    try:
        status = np.array(records["status"])
        status[nonfinite] = Status.NON_FINITE_POINT
        xyz = np.concatenate([_files.read(sources, b, _files.XYZ) for b in blocks]) if len(blocks) else np.zeros((0, 3))
        kind, target = orientation
        normals = _core.orient_normal_records(records["normal"], records["neighbor"], records["degree"], status, xyz,
                                              kind, list(target), _threads(threads), None)
    finally:
        del records
    _write_rows(output, np.arange(len(normals)), normals)
    return {"seconds": time.perf_counter() - t0, "peak_rss": _peak_rss()}


@contextlib.contextmanager
def _cancel_on_error(client, pending):
    """On an exception (a tile raised, KeyboardInterrupt), cancels the tiles still pending
    so that the cluster does not go on computing them, then lets the exception through."""
    try:
        yield
    except BaseException:
        if pending:
            client.cancel(list(pending))
            pending.clear()
        raise


def _release(futures):
    for f in futures:
        f.release()
    futures.clear()


def read_result(path):
    """The output of :func:`estimate_curvatures_file` as the dict of
    :func:`point_set_curvatures.estimate_curvatures` (views on a read-only memory map)."""
    a = np.load(path, mmap_mode="r")
    return {k: a[k] for k in a.dtype.names}


def estimate_curvatures_file(client, input_path, output_path, *, method="aso", radius=None, neighbors=None,
                             tile_size=None, threads=1, retries=2, initial_halo=None, block_rows=BLOCK_ROWS,
                             normal_orientation=None, **options):
    """Estimates curvatures of a cloud stored in files on a dask.distributed cluster, the
    workers reading their own tiles from the files and writing their own points' results.

    Parameters
    ----------
    client : distributed.Client
    input_path : path or list of paths
        A binary PLY file (little- or big-endian; vertex properties ``x y z`` and, if it has
        them, ``nx ny nz`` or ``normal_x normal_y normal_z``, of any scalar type, other scalar
        properties ignored, no list property in or before the vertex element; its header is
        read by the package's PLY reader, the tool's), a ``.npy`` array of shape (N, 6) (x y z
        nx ny nz) or (N, 3) (x y z) (float32 or float64, C order), or an uncompressed LAS file
        (1.0 to 1.4, any point format; its coordinates as the package's LAS reader gives them,
        its other fields not read); a list of such files is one cloud, concatenated in order,
        every file with normals or none.
    output_path : path
        Written as a ``.npy`` structured array of N records of :data:`RESULT_DTYPE` (the fields
        of :func:`point_set_curvatures.estimate_curvatures`), or of :data:`AUTOMATIC_RESULT_DTYPE`
        under the automatic scale (with ``mean_error``), row i for input point i; read it with
        :func:`read_result` or ``np.load(path, mmap_mode="r")``.
    method, radius, neighbors, tile_size, threads, retries, initial_halo, **options
        As for :func:`estimate_curvatures` (``sample_weights`` not as an array): with neither
        ``radius`` nor ``neighbors``, the single-process default (the automatic scale for the
        robust ASO, the default method).
    block_rows : int
        Rows read at a time, and the unit of spatial pruning.
    normal_orientation : str or tuple or None
        For files without normals, which are then estimated as
        :func:`point_set_curvatures.estimate_curvatures` estimates them (the automatic scale
        with the automatic scale, else the 40 nearest; and ``position_fit_blend`` the library's
        default for estimated normals, 0.5 for the robust ASO), their orientation, as :func:`point_set_curvatures.estimate_normals` takes it.
        Default: ``"auto"`` for LAS files (the tool's default for LAS files without pulse
        directions, which the Dask route does not read: +z on 2.5-D scans), else ``"mst"``
        (``estimate_curvatures(points, None)``'s). ``"mst"`` and ``"auto"`` need the whole
        cloud: the tiles write each point's unoriented normal and 12 nearest neighbours (74
        bytes a point) to a temporary file beside the output, and one task orients them all
        (about 400 bytes a point on one worker); ``"+z"``, another axis, ``("along", v)`` or
        ``("towards", p)`` orient each point in its tile. Refused for files with normals.

    Every path must be readable (inputs) and writable (output) under the same name by the
    client and every worker (a shared file system on a cluster). The result is bitwise equal to
    :func:`point_set_curvatures.estimate_curvatures` on the concatenated arrays (converted to
    float64); without normals, to it on the normals of
    ``estimate_normals(points, neighbors=..., orientation=normal_orientation)`` with
    ``position_fit_blend=0.5`` for the robust ASO (``estimate_curvatures(points, None)`` for
    ``"mst"``).

    Returns
    -------
    dict
        A report: ``points``, ``finite_points``, ``tiles`` (tasks that estimated a non-empty
        tile), ``resubmitted`` (tiles run again with a larger halo), ``tile_side``,
        ``grid_counts``, ``seconds`` (per phase: ``scan``, ``count``, ``normals``, ``tiles``,
        ``total``), ``normals`` (files without normals: ``tiles``, ``resubmitted``,
        ``spanning_tree``, ``tile_reports``, ``orientation`` (the orienting task's ``seconds``
        and ``peak_rss``, or None), ``seconds``) and
        ``tile_reports`` (one dict per tile task: ``own``, ``halo_points``, ``read_seconds``,
        ``compute_seconds``, ``write_seconds``, ``peak_rss`` of the worker process, ``pid``,
        ``start``, ``stop``).

    How it runs: pass 1 (tasks over groups of blocks) finds each block's bounding box and
    samples the points for the tiles' box; pass 2 counts the own points of every tile of the
    grid (and writes the rows of non-finite points);
    without normals, the normals' pass (above) on the same tiles; then one task per non-empty
    tile reads only the blocks whose box meets the tile's halo box, estimates and writes. Only paths, boxes and block numbers travel in the tasks, and only
    summaries come back. The workers write disjoint rows of a preallocated memory-mapped
    output rather than sending results to the client: the client then never holds more than
    the small per-block and per-tile arrays (gathering would need the whole result, about 121
    bytes a point, in the client), and a task retried after a lost worker rewrites the same
    bytes. Every point is checked to be written by exactly one tile (own counts per tile, and
    sums of the indices), else RuntimeError.
    """
    if "tile" in options:
        raise ValueError("option 'tile' is chosen by point_set_curvatures.dask")
    if normal_orientation is not None:
        _orientation(normal_orientation)  # (checked before any file is read or written)
    if _weight_array(options) is not None:
        raise ValueError("option 'sample_weights': per-point weights (an array) are not supported for "
                         "clouds in files; use 'uniform' or 'tangent_voronoi_area'")
    method = _method(method)
    radius, neighbors = _scale_of_run(method, radius, neighbors, options)
    retries = _int("retries", retries, 0)
    block_rows = _int("block_rows", block_rows, 1)
    tile_size = None if tile_size is None else _real("tile_size", tile_size)
    initial_halo = _initial_halo(initial_halo)
    t_start = time.perf_counter()
    kwargs = dict(method=method, radius=radius, neighbors=neighbors, threads=threads, **options)
    # the arguments checked here, not by every task (dask would retry a failing task)
    _estimate_curvatures(np.zeros((0, 3)), np.zeros((0, 3)), tile=_check_tile(radius), **kwargs)
    sources = _files.open_sources(input_path)
    blocks = _files.blocks(sources, block_rows)
    n = sum(s.rows for s in sources)
    with_normals = _files.has_normals(sources[0])
    if with_normals and normal_orientation is not None:
        raise ValueError("normal_orientation: the files have normals, which are used as they are")
    if not with_normals:
        if normal_orientation is None:  # the tool's default: LAS files are scans, often 2.5-D
            normal_orientation = "auto" if all(s.scale is not None for s in sources) else "mst"
        orientation = _orientation(normal_orientation)
        if _spans_whole_cloud(orientation[0]) and n > np.iinfo(np.uint32).max:
            raise ValueError(f"a spanning tree orients at most {np.iinfo(np.uint32).max} points, the files hold {n}: "
                             "give normal_orientation='+z' (airborne scans), another axis or ('towards', scanner)")
        blend = _blend_on_estimated_normals(method, options)
        if blend is not None:
            kwargs["position_fit_blend"] = blend
    output_path = os.path.abspath(os.fspath(output_path))
    dtype = AUTOMATIC_RESULT_DTYPE if neighbors == "auto" else RESULT_DTYPE
    out = np.lib.format.open_memmap(output_path, mode="w+", dtype=dtype, shape=(n,))
    output = (output_path, out.offset, n, dtype)
    del out
    nthreads = max(1, sum(client.nthreads().values()))
    token = uuid.uuid4().hex[:8]
    groups = np.array_split(np.arange(len(blocks)), max(1, min(len(blocks), 4 * nthreads))) if len(blocks) else []

    # pass 1: bounding boxes of the blocks, and the sample of the tiles' box
    futures = [client.submit(_scan_task, sources, blocks[g], _sample_stride(n), key=f"psc-scan-{token}-{j}",
                             retries=retries) for j, g in enumerate(groups)]
    scans = client.gather(futures)
    _release(futures)
    block_lo = np.concatenate([s[0] for s in scans]) if scans else np.zeros((0, 3))
    block_hi = np.concatenate([s[1] for s in scans]) if scans else np.zeros((0, 3))
    finite = int(sum(s[2].sum() for s in scans))
    t_scan = time.perf_counter()
    report = {"points": n, "finite_points": finite, "tiles": 0, "resubmitted": 0, "tile_side": None,
              "grid_counts": None, "tile_reports": []}
    if finite == 0:
        if n:
            _write_rows(output, np.arange(n), _default_rows(n, dtype))
        t = time.perf_counter() - t_start
        report["seconds"] = {"scan": t_scan - t_start, "count": 0.0, "normals": 0.0, "tiles": 0.0, "total": t}
        return report
    lo, hi = block_lo.min(axis=0), block_hi.max(axis=0)
    radius, neighbors = _whole_cloud_box(finite, lo, hi, radius, neighbors)
    kwargs.update(radius=radius, neighbors=neighbors)
    if not with_normals:  # estimate_curvatures' own estimate of the normals
        _, normal_neighbors = _whole_cloud_box(finite, lo, hi, None, _estimated_normal_neighbors(neighbors == "auto"),
                                               "normals: ")
    # the tiles' box: the library's (tile_grid_box: quantiles that ignore outliers), the tool's,
    # on the blocks' samples (at most TILE_BOX_SAMPLE_POINTS: Tile_box_sample keeps them all)
    lo, hi = _core.tile_grid_box(np.concatenate([s[3] for s in scans]))
    if tile_size is None:
        tile_size = _tile_side(lo, hi, max(4 * nthreads, math.ceil(finite / 500_000)))
    grid_args = (tuple(lo), tuple(hi), float(tile_size))
    grid = TileGrid(*grid_args)

    # pass 2: own points per tile
    futures = [client.submit(_count_task, sources, blocks[g], grid_args, output, key=f"psc-count-{token}-{j}",
                             retries=retries) for j, g in enumerate(groups)]
    counted = client.gather(futures)
    # forgotten before any tile runs: a count task recomputed after a worker loss (the scheduler
    # recomputes lost results still referenced) would overwrite the tiles' rows
    _release(futures)
    counts = sum(c[0] for c in counted)
    nonfinite = np.concatenate([c[1] for c in counted])
    t_count = time.perf_counter()
    if int(counts.sum()) != finite or len(nonfinite) != n - finite:
        raise RuntimeError("point_set_curvatures.dask: the passes over the files disagree (files modified?)")

    def near(i, h):
        """The blocks whose box meets tile i's halo box, and a distance from the core below which
        lie none of the other blocks' points (the largest gap between the core and a block's box
        along an axis, the least over those blocks; infinite without any)."""
        tile = grid.tile(i, h)
        core_lo, core_hi = np.asarray(tile.core_min), np.asarray(tile.core_max)
        meets = np.all((block_hi >= core_lo - h) & (block_lo <= core_hi + h), axis=1)
        # (fmax: an empty block's box, inf to -inf, against an infinite side gives NaN terms)
        gap = np.fmax(np.fmax(block_lo[~meets] - core_hi, core_lo - block_hi[~meets]), 0.0).max(axis=1, initial=0.0)
        return tile, blocks[meets], float(gap.min()) if len(gap) else math.inf

    temporary = []  # files of the normals' pass, removed whatever happens
    try:
        normals = "files"
        if not with_normals:
            normals = _estimate_file_normals(client, sources, blocks, near, counts, nonfinite, lo, hi, finite,
                                             normal_neighbors, orientation, initial_halo, threads, retries, token,
                                             output_path, temporary, report)
        t_normals = time.perf_counter()

        def submit(i, h):
            tile, tile_blocks, unread = near(i, h)
            return client.submit(_file_tile_task, sources, tile_blocks, tile.core_min, tile.core_max, h, unread, finite,
                                 output, kwargs, normals, key=f"psc-tile-{token}-{i}-{h!r}", retries=retries)

        report["tile_reports"], report["resubmitted"] = _tile_pass(
            client, submit, counts, _first_halo(radius, neighbors, initial_halo, lo, hi, finite), n, nonfinite)
    finally:
        for path in temporary:
            with contextlib.suppress(OSError):
                os.remove(path)
    t_tiles = time.perf_counter()
    report.update(tiles=len(report["tile_reports"]), tile_side=float(tile_size), grid_counts=tuple(grid.counts))
    report["seconds"] = {"scan": t_scan - t_start, "count": t_count - t_scan, "normals": t_normals - t_count,
                         "tiles": t_tiles - t_normals, "total": t_tiles - t_start}
    return report


def _tile_pass(client, submit, counts, halo, n, nonfinite):
    """Runs ``submit(i, halo)`` (a future of a tile task) for every tile i with own points
    (``counts``), resubmits with a larger halo the tiles that ask for one, and checks that
    the tiles wrote every finite point of the n exactly once (own counts per tile, and sums of
    the indices); returns (the tiles' summaries, the number of resubmissions)."""
    from distributed import as_completed

    pending = {}
    for i in np.nonzero(counts)[0]:
        pending[submit(int(i), halo)] = (int(i), halo)
    reports, resubmitted = [], 0
    index_sum = index_square_sum = 0
    with _cancel_on_error(client, pending):
        done = as_completed(list(pending))
        for future in done:
            i, h = pending.pop(future)
            result = future.result()
            future.release()
            if isinstance(result, tuple):
                h = _next_halo(result[1], result[2])
                new = submit(i, h)
                pending[new] = (i, h)
                done.add(new)
                resubmitted += 1
                continue
            if result["own"] != counts[i]:
                raise RuntimeError(f"point_set_curvatures.dask: tile {i} wrote {result['own']} points, "
                                   f"{counts[i]} expected")
            result["tile"] = i
            reports.append(result)
            index_sum += result["index_sum"]
            index_square_sum += result["index_square_sum"]
    # every finite index exactly once: counts above, sums here (the squares modulo 2**64)
    bad = [int(v) for v in nonfinite]
    expected_sum = n * (n - 1) // 2 - sum(bad)
    expected_squares = ((n - 1) * n * (2 * n - 1) // 6 - sum(v * v for v in bad)) % (1 << 64)
    if index_sum != expected_sum or index_square_sum % (1 << 64) != expected_squares:
        raise RuntimeError("point_set_curvatures.dask: the tiles did not write every point exactly once")
    return reports, resubmitted


def _estimate_file_normals(client, sources, blocks, near, counts, nonfinite, lo, hi, finite, neighbors, orientation,
                           initial_halo, threads, retries, token, output_path, temporary, report):
    """The normals of a cloud whose files have none, as ``estimate_normals(points,
    neighbors=neighbors, orientation=orientation)`` gives them (bitwise): one task per tile
    estimates its own points' (and orients them, for an orientation per point); for a
    spanning tree ("mst", "auto") the tiles write each point's record (its unoriented normal
    and nearest neighbours) and one task orients them over the whole cloud. Returns the path
    of the (N, 3) .npy array of normals, a temporary file beside the output (listed in
    ``temporary``); reports in ``report["normals"]``."""
    n = int(counts.sum()) + len(nonfinite)
    kind, target = orientation
    spanning_tree = _spans_whole_cloud(kind)  # (at most 2**32 - 1 points: checked by the caller)
    t0 = time.perf_counter()
    normals_path = f"{output_path}.{token}.normals.npy"
    temporary.append(normals_path)
    mm = np.lib.format.open_memmap(normals_path, mode="w+", dtype=np.float64, shape=(n, 3))
    normals_output = (normals_path, mm.offset, n, np.dtype((np.float64, (3,))))
    del mm
    if spanning_tree:
        records_path = f"{output_path}.{token}.records.npy"
        temporary.append(records_path)
        dtype = _record_dtype()
        mm = np.lib.format.open_memmap(records_path, mode="w+", dtype=dtype, shape=(n,))
        tile_output = (records_path, mm.offset, n, dtype)
        del mm
    else:
        tile_output = normals_output

    def submit(i, h):
        tile, tile_blocks, unread = near(i, h)
        return client.submit(_file_normal_tile_task, sources, tile_blocks, tile.core_min, tile.core_max, h, unread,
                             finite, tile_output, neighbors, None if spanning_tree else (kind, target), threads,
                             key=f"psc-normals-{token}-{i}-{h!r}", retries=retries)

    tiles, resubmitted = _tile_pass(client, submit, counts, _first_halo(None, neighbors, initial_halo, lo, hi, finite),
                                    n, nonfinite)
    t1 = time.perf_counter()
    orientation_report = None
    if spanning_tree:
        future = client.submit(_orient_task, sources, blocks, records_path, normals_output, nonfinite, (kind, target),
                               threads, key=f"psc-orient-{token}", retries=retries)
        with _cancel_on_error(client, {future: None}):
            orientation_report = future.result()
        future.release()
    report["normals"] = {"tiles": len(tiles), "resubmitted": resubmitted, "tile_reports": tiles,
                         "spanning_tree": spanning_tree, "orientation": orientation_report,
                         "seconds": {"tiles": t1 - t0, "orientation": time.perf_counter() - t1}}
    return normals_path
