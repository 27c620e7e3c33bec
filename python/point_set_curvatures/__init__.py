# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Curvature estimation on oriented point clouds (Python bindings of Point_set_curvatures).

The functions of the C++ package on numpy arrays: every estimator of curvatures (the
Algebraic Shape Operator ``"aso"`` by default, ``"apss"`` and the baselines ``"barycenter"``,
``"pca_plane"``, ``"pss"``, ``"jet"``, ``"vcm"``, ``"wavejet"``), the algebraic sphere
features, the projection onto the APSS surface, the bilaplacian flow and the estimation of
oriented normals.

Conventions (those of the C++ package, see its user manual): one result per input point, in
input order; curvature is positive where the surface bends away from the normal (a sphere of
radius R with outward normals has k_min = k_max = mean = 1/R); points that cannot be
estimated have a ``status`` other than ``Status.VALID`` and NaN in every float field.

Inputs are ``(N, 3)`` arrays of float64 or float32 in any memory layout (C, Fortran or a
strided view); they are read once, into the C++ structure. The GIL is released while the
C++ code runs; ``progress(fraction)`` is called on the calling thread and cancels the run
(raising :class:`Cancelled`) by returning ``False`` (exactly ``False``, or a numpy
``False``): any other value (``True``, ``None``, ``0``, ...) continues. ``threads=None``
uses every core (``CGAL::Parallel_tag``), ``threads=1`` runs sequentially
(``CGAL::Sequential_tag``), ``threads=n`` runs on a TBB arena of ``n`` threads, capped to the
cores TBB may use; results do not depend on it (bit for bit, every method). Ctrl-C cancels a
run too (KeyboardInterrupt).

Invalid arguments raise ``ValueError`` (with the C++ message when the C++ code detects
them); arguments of a wrong type (a string for a number, a float for a count) raise
:class:`ArgumentTypeError`, a ``TypeError`` that is also a ``ValueError``. Method names and
option values are case-insensitive. A scale that makes every neighbourhood the whole cloud
(a radius larger than the cloud's bounding-box diagonal, ``neighbors`` not less than the
number of points) gives a :class:`ScaleWarning`.
"""

import errno
import numbers
import os
import types
import warnings
from enum import IntEnum

import numpy as np

from . import _core
from ._core import AsoProjection, AsoVariant, Cancelled, HaloTooSmall, SampleWeights, WeightKernel

#: The version of the package: the CMake project's (compiled into the extension).
__version__ = _core.__version__

__all__ = [
    "__version__",
    "ArgumentTypeError",
    "ScaleWarning",
    "Status",
    "ProjectionStatus",
    "Cancelled",
    "HaloTooSmall",
    "AsoVariant",
    "WeightKernel",
    "SampleWeights",
    "AsoProjection",
    "METHODS",
    "ESTIMATORS",
    "AUTOMATIC_NEIGHBORS",
    "DEFAULT_NEIGHBORS",
    "estimate_curvatures",
    "estimate_sphere_features",
    "estimate_multiscale_sphere_features",
    "estimate_tangent_voronoi_areas",
    "AlgebraicPointSetSurface",
    "apss_smooth_point_set",
    "estimate_normals",
    "read_point_cloud",
    "TileGrid",
]

Cancelled.__doc__ = (
    "Raised when the progress callable returned False: the run was cancelled "
    "(a subclass of RuntimeError)."
)
HaloTooSmall.__doc__ = (
    "Raised by a run on a tile (tile=...) by neighbour count when a neighbourhood reaches "
    "beyond the tile's halo; ``required_halo`` is a halo that suffices (a subclass of "
    "RuntimeError)."
)


class ArgumentTypeError(TypeError, ValueError):
    """An argument of the wrong type, for example a string where a number is expected: a
    ``TypeError``, and also a ``ValueError`` (what earlier versions raised)."""


class ScaleWarning(UserWarning):
    """The scale makes every neighbourhood the whole cloud (a radius larger than the cloud's
    bounding-box diagonal, or ``neighbors`` not less than the number of points): the
    curvatures are those of one fit to the whole cloud (meaningless unless the cloud is one
    small patch), or ``Status.DEGENERATE_FIT`` everywhere for huge radii, at a cost quadratic
    in the number of points."""


class Status(IntEnum):
    """Why an estimate is (in)valid: ``CGAL::Curvature_estimate_status``, same names and
    values. The ``status`` arrays hold these values as uint8."""

    VALID = 0  #: every field the estimator provides holds a finite value
    TOO_FEW_NEIGHBORS = 1  #: fewer neighbours than min_neighbors
    DEGENERATE_FIT = 2  #: coincident neighbours, cancelling normals, no tangent spread
    NON_FINITE_POINT = 3  #: a NaN or infinite coordinate
    INVALID_NORMAL = 4  #: zero, non-finite or implausible input normal
    NOT_COMPUTED = 5  #: not reached (cancelled), or not an own point of the tile
    TWO_SHEETS = 6  #: robust_orientation: the neighbours lie on two sheets

    @classmethod
    def names(cls, statuses):
        """The names of the values of a ``status`` array, as the tool prints them
        (``"valid"``, ``"too_few_neighbors"``, ...): an array of str of the same shape."""
        table = np.array([s.name.lower() for s in sorted(cls)])
        statuses = np.asarray(statuses)
        if statuses.size and not ((statuses >= 0) & (statuses < len(table))).all():
            raise ValueError(f"a status value outside 0..{len(table) - 1}")
        return table[statuses.astype(np.intp)]

    @classmethod
    def counts(cls, statuses):
        """``{name: count}`` of the values of a ``status`` array, the most frequent first (as
        the tool's summary: ``{"valid": 22829, "two_sheets": 86}``)."""
        values, counts = np.unique(np.asarray(statuses), return_counts=True)
        order = sorted(zip(values, counts), key=lambda vc: (-vc[1], vc[0]))
        return {cls(int(v)).name.lower(): int(c) for v, c in order}


class ProjectionStatus(IntEnum):
    """Outcome of a projection onto the APSS surface: ``CGAL::Apss_projection_status``."""

    CONVERGED = 0
    NOT_CONVERGED = 1
    TOO_FEW_NEIGHBORS = 2
    DEGENERATE_FIT = 3
    NON_FINITE_POINT = 4


# The enums above are the C++ ones: checked at import.
assert {s.name.lower(): s.value for s in Status} == dict(_core.STATUS_VALUES)
assert {s.name.lower(): s.value for s in ProjectionStatus} == dict(_core.PROJECTION_STATUS_VALUES)

#: What each estimator of ``estimate_curvatures`` is, from the C++ library's description
#: (``CGAL::Point_set_curvatures::estimators``), read-only: name -> mapping with ``name``,
#: ``function`` (the C++ function, in namespace CGAL), ``summary``, ``fields`` (the result's
#: keys it fills with its default options; NaN in the others), ``min_neighbors`` (the default
#: of the option), ``good_neighbors`` (the count from which its error stays within twice its
#: error at 40 neighbours), ``paper_variant_good_neighbors`` (the same for
#: ``aso_variant="paper"``), ``supports_tiles`` (whether it takes ``tile``),
#: ``supports_automatic_scale`` (whether it takes ``neighbors="auto"``) and ``options`` (its own options: mappings with
#: ``name``, ``values``, ``default`` and, for a choice, ``choices``).
ESTIMATORS = types.MappingProxyType(
    {
        e["name"]: types.MappingProxyType(
            dict(e, options=tuple(types.MappingProxyType(o) for o in e["options"]))
        )
        for e in _core.ESTIMATORS
    }
)

#: The estimators of ``estimate_curvatures``.
METHODS = tuple(ESTIMATORS)

_COMMON_OPTIONS = ("min_neighbors", "accept_unnormalized_normals", "tile")
_METHOD_OPTIONS = {name: tuple(o["name"] for o in e["options"]) for name, e in ESTIMATORS.items()}



class _Choices(dict):
    """An option's values: lower-case name -> the C++ enumerator's value, from an enumeration
    of ``_core`` (a ``py::enum_`` named from the library's name tables), whose members are
    accepted too."""

    def __init__(self, enum):
        super().__init__((name.lower(), int(value)) for name, value in enum.__members__.items())
        self.enum = enum


_ASO_VARIANTS, _WEIGHT_KERNELS, _SAMPLE_WEIGHTS, _ASO_PROJECTIONS = (
    _Choices(e) for e in (AsoVariant, WeightKernel, SampleWeights, AsoProjection)
)


def _choice(name, value, table):
    if isinstance(value, str) and value.lower() in table:
        return table[value.lower()]
    if isinstance(value, table.enum):
        return int(value)
    raise ValueError(
        f"option '{name}': expected one of {', '.join(repr(k) for k in table)}, got {value!r}"
    )


def _bool(name, value):
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ArgumentTypeError(f"option '{name}': expected a bool (True or False), got {value!r}")


def _type_hint(value):
    """What a wrong value is, and what to do, for the messages."""
    if isinstance(value, str):
        return f"{value!r} (a string: convert it, e.g. float({value!r}))"
    return f"{value!r} (of type {type(value).__name__})"


def _real(name, value):
    """A number (int, float, numpy scalar; not a bool, not a string) as a float."""
    if isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_)):
        return float(value)
    raise ArgumentTypeError(f"{name} must be a number, got {_type_hint(value)}")


def _float_in(name, value, low, high):
    v = _real(f"option '{name}'", value)
    if low <= v <= high:
        return v
    raise ValueError(f"option '{name}': expected a number in [{low:g}, {high:g}], got {value!r}")


def _int(name, value, least):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise ArgumentTypeError(f"option '{name}': expected an integer, got {_type_hint(value)}")
    if value < least:
        raise ValueError(f"option '{name}': must be at least {least}, got {value}")
    return int(value)


def _threads(threads):
    """0 for None (every core); n capped to 2**30 here, to the cores TBB may use by _core."""
    if threads is None:
        return 0
    return min(_int("threads", threads, 1), 1 << 30)


def _array(x, name):
    """The array itself if it is one (the C++ side checks dtype and shape), else a float64 copy."""
    if isinstance(x, np.ndarray):
        return x
    try:
        return np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name}: cannot be read as an (N, 3) array of floats: {e}") from None


def _progress(progress):
    """The callable given to _core: True to continue, False to cancel. Only False (or a numpy
    False) cancels: a callable returning None, 0 or anything else continues."""
    if progress is None:
        return None
    if not callable(progress):
        raise ArgumentTypeError(f"progress must be a callable or None, got {progress!r}")

    def call(fraction):
        r = progress(fraction)
        return not (r is False or (isinstance(r, np.bool_) and not r))

    return call


def _whole_cloud_scale(points, radius, neighbors, what="", stacklevel=3):
    """(radius, neighbors), with a ScaleWarning when every neighbourhood would be the whole
    cloud (see _whole_cloud_box). Arrays the C++ side will refuse are passed through."""
    if not (isinstance(points, np.ndarray) and points.ndim == 2 and points.shape[1] == 3
            and points.dtype.kind == "f") or (radius is None and neighbors is None):
        return radius, neighbors
    finite = np.isfinite(points).all(axis=1)
    q = points if finite.all() else points[finite]
    lo, hi = (q.min(axis=0), q.max(axis=0)) if len(q) else (None, None)
    return _whole_cloud_box(len(q), lo, hi, radius, neighbors, what, stacklevel + 1)


def _whole_cloud_box(n, lo, hi, radius, neighbors, what="", stacklevel=3):
    """(radius, neighbors) for a cloud of n finite points spanning the box [lo, hi], with a
    ScaleWarning when every neighbourhood would be the whole cloud: neighbors not less than n
    (capped at n: non-finite points are nobody's neighbours), or a radius larger than the box's
    diagonal."""
    if neighbors == "auto":
        if n and AUTOMATIC_NEIGHBORS[0] >= n:
            warnings.warn(
                f"{what}neighbors='auto' starts at {AUTOMATIC_NEIGHBORS[0]} neighbours, not less than the number "
                f"of (finite) points ({n}): every neighbourhood is the whole cloud",
                ScaleWarning, stacklevel=stacklevel)
        return radius, neighbors
    if neighbors is not None:
        if n and neighbors >= n:
            warnings.warn(
                f"{what}neighbors={neighbors} is not less than the number of (finite) points ({n}): "
                "every neighbourhood is the whole cloud"
                + (f" (capped at {n})" if neighbors > n else "")
                + "; give about 40 neighbours, fewer than the points",
                ScaleWarning, stacklevel=stacklevel)
            neighbors = min(neighbors, n)
        return radius, neighbors
    if radius is None or lo is None or not 0 < radius < np.inf or n < 2:
        return radius, neighbors
    diagonal = float(np.linalg.norm(np.asarray(hi, dtype=np.float64) - np.asarray(lo, dtype=np.float64)))
    if 0 < diagonal < radius:
        warnings.warn(
            f"{what}radius={radius:g} is larger than the cloud's extent (bounding-box diagonal "
            f"{diagonal:.6g}): every neighbourhood is the whole cloud, which gives meaningless "
            "curvatures (or degenerate_fit everywhere) at a quadratic cost; use about 3.5 to 4 "
            "times the point spacing (about 40 neighbours), or neighbors=40",
            ScaleWarning, stacklevel=stacklevel)
    return radius, neighbors


def _tile(tile):
    if tile is None:
        return None
    if isinstance(tile, TileGrid.Tile):
        return (tuple(tile.core_min), tuple(tile.core_max), float(tile.halo))
    try:
        lo, hi, halo = tile
        lo, hi = tuple(lo), tuple(hi)
    except (TypeError, ValueError):
        raise ValueError(
            "option 'tile': expected (core_min, core_max, halo) or a TileGrid.Tile"
        ) from None
    lo = tuple(_real("option 'tile': core_min", v) for v in lo)
    hi = tuple(_real("option 'tile': core_max", v) for v in hi)
    halo = _real("option 'tile': halo", halo)
    if len(lo) != 3 or len(hi) != 3:
        raise ValueError("option 'tile': core_min and core_max must have 3 coordinates")
    return (lo, hi, halo)


def _options(method, allowed, given):
    """The _core options from keyword arguments; unknown or inapplicable names raise."""
    o = _core._Options()
    tile = None
    weights = None
    for name, value in given.items():
        if name not in allowed:
            known = sorted(set(_COMMON_OPTIONS).union(*_METHOD_OPTIONS.values()))
            if name in known:
                raise ValueError(
                    f"option '{name}' does not apply to {method}; its options: "
                    f"{', '.join(sorted(allowed))}"
                )
            raise ValueError(
                f"unknown option '{name}' for {method}; its options: {', '.join(sorted(allowed))}"
            )
        if value is None:
            continue  # the default
        if name == "min_neighbors":
            o.min_neighbors = _int(name, value, 0)
        elif name == "accept_unnormalized_normals":
            o.accept_unnormalized_normals = _bool(name, value)
        elif name == "tile":
            tile = _tile(value)
        elif name == "aso_variant":
            o.aso_variant = _choice(name, value, _ASO_VARIANTS)
        elif name == "weight_kernel":
            o.weight_kernel = _choice(name, value, _WEIGHT_KERNELS)
        elif name == "sample_weights":
            if isinstance(value, (str, SampleWeights)):
                o.sample_weights = _choice(name, value, _SAMPLE_WEIGHTS)
            else:
                weights = _weights(value)
        elif name == "robust_orientation":
            o.robust_orientation = int(_bool(name, value))
        elif name == "normal_field_blend":
            o.normal_field_blend = int(_bool(name, value))
        elif name == "normal_refinement":
            o.normal_refinement = _int(name, value, 0)
        elif name == "position_fit_blend":
            o.position_fit_blend = _float_in(name, value, 0.0, 1.0)
        elif name == "aso_projection":
            o.aso_projection = _choice(name, value, _ASO_PROJECTIONS)
        elif name == "degree_fitting":
            o.degree_fitting = _int(name, value, -(2**62))
        elif name == "degree_monge":
            o.degree_monge = _int(name, value, -(2**62))
        elif name == "vcm_offset_radius":
            v = _real("option 'vcm_offset_radius'", value)
            if not (v > 0 and np.isfinite(v)):
                raise ValueError(
                    f"option 'vcm_offset_radius' must be positive and finite, got {value!r}"
                )
            o.vcm_offset_radius = v
    return o, tile, weights


def _weights(value):
    """Per-point sample weights given as an array: a float64 array of shape (N,) (the C++ side
    checks the length and that every weight is finite and non-negative)."""
    try:
        w = np.asarray(value)
        w = w.astype(np.float64) if w.dtype.kind in "biuf" else None
    except (TypeError, ValueError):
        w = None
    if w is None or w.ndim != 1:
        raise ValueError(
            "option 'sample_weights': expected 'uniform', 'tangent_voronoi_area' or an array of "
            f"shape (N,) with one weight per point, got {value!r:.80}"
        )
    return w


#: ``neighbors="auto"``: each point's count chosen among the smallest, twice it, ... up to the
#: largest (the library's ladder, that of the tool's --neighbors auto).
AUTOMATIC_NEIGHBORS = tuple(_core.AUTOMATIC_NEIGHBORS)
#: The count of a run given neither ``radius`` nor ``neighbors`` where the automatic scale is
#: not the default (every method but the robust ASO): the library's, as the tool's.
DEFAULT_NEIGHBORS = int(_core.DEFAULT_NEIGHBORS)


def _scale(radius, neighbors, automatic=False):
    """(radius, neighbors); ``neighbors="auto"`` (any case) only where ``automatic``, else a
    ValueError."""
    if radius is not None and neighbors is not None:
        raise ValueError("give either radius or neighbors, not both")
    if radius is None and neighbors is None:
        raise ValueError("give radius or neighbors")
    if radius is not None:
        return _real("radius", radius), None  # positive and finite: checked by the C++ function
    if isinstance(neighbors, str) and neighbors.lower() == "auto":
        if not automatic:
            raise ValueError("neighbors='auto' chooses the scale of estimate_curvatures with method 'aso' and of "
                             "estimate_normals with fit 'quadric' only: give a count here")
        return None, "auto"
    if isinstance(neighbors, (bool, np.bool_)) or not isinstance(neighbors, numbers.Integral):
        raise ArgumentTypeError(f"neighbors must be an integer, got {_type_hint(neighbors)}")
    return None, _int("neighbors", neighbors, 1)


def _default_neighbors(method, options):
    """The scale of a run given neither ``radius`` nor ``neighbors``, as the tool's: ``"auto"``
    where the library makes the automatic scale the default (the robust ASO), else
    :data:`DEFAULT_NEIGHBORS`. ``method`` is a name of :data:`METHODS` in lower case; the options
    are checked as :func:`estimate_curvatures` checks them."""
    allowed = set(_COMMON_OPTIONS) | set(_METHOD_OPTIONS[method])
    opts, _, _ = _options(f"method '{method}'", allowed, options)
    return "auto" if _core.automatic_scale_by_default(method, opts.aso_variant) else DEFAULT_NEIGHBORS


def _method(method):
    """The method's name in lower case; ValueError for unknown names."""
    if not isinstance(method, str) or method.lower() not in METHODS:
        raise ValueError(f"unknown method {method!r}; methods: {', '.join(METHODS)} (any case)")
    return method.lower()


def estimate_curvatures(
    points,
    normals=None,
    *,
    method="aso",
    radius=None,
    neighbors=None,
    threads=None,
    progress=None,
    **options,
):
    """Estimates the corrected normal, the principal curvatures and directions, the mean and
    the Gaussian curvature at every point of an oriented point cloud.

    Parameters
    ----------
    points, normals : array_like, shape (N, 3), float64 or float32
        Positions and consistently oriented normals (need not be unit), any memory layout.
        Without normals (``None``, the default) they are estimated as the tool estimates
        those of a file without them, with a warning: :func:`estimate_normals` with a quadric
        fit (``neighbors="auto"`` with the automatic scale, else its default 40), oriented
        along a minimum spanning tree (``"mst"``), and ``position_fit_blend=0.5`` for the robust
        ASO unless given; call :func:`estimate_normals` yourself to choose (for example
        ``orientation="auto"`` on airborne scans, ``("towards", scanner)`` on a terrestrial one).
    method : str
        ``"aso"`` (Algebraic Shape Operator, default), ``"apss"`` (normal and mean curvature),
        ``"barycenter"``, ``"pca_plane"`` (unsigned mean curvature), ``"pss"``, ``"jet"``
        (full tensor), ``"vcm"`` (unsigned principal curvatures), ``"wavejet"`` (full tensor);
        any case. :data:`ESTIMATORS` describes each.
    radius : float
        Neighbourhoods are the points at distance ``< radius`` (about 40 neighbours is a good
        start: 3.5 to 4 times the average spacing). A number (a string is refused); larger
        than the cloud's bounding-box diagonal, a :class:`ScaleWarning`.
    neighbors : int or "auto"
        Instead of a radius: each point's radius reaches its ``neighbors``-th nearest point.
        Give at most one of ``radius`` and ``neighbors``; with neither, the tool's default:
        ``"auto"`` for the robust ASO (the default method and variant), else
        :data:`DEFAULT_NEIGHBORS` (40). Not less than the number of points:
        a :class:`ScaleWarning`, and capped at the number of points. ``"auto"`` (method
        ``"aso"``): each point's count is chosen among 40, 80, ..., 640
        (:data:`AUTOMATIC_NEIGHBORS`) by the noise its fits measure (noisy scans), as the
        tool's ``--neighbors auto``; the result then has ``mean_error``.
    threads : int or None
        None: all cores; 1: sequential; n: n threads (capped to the cores). Same results
        whatever the value.
    progress : callable or None
        ``progress(fraction) -> bool | None``, called on the calling thread at least every 1%
        of the points; returning ``False`` cancels and raises :class:`Cancelled` (only
        ``False``: ``None``, ``0`` or any other value continues).
    **options
        Every option of the C++ function (ValueError for unknown names and for options the
        method does not take); a quoted value may also be given as the member of its
        enumeration (:class:`AsoVariant`, :class:`WeightKernel`, :class:`SampleWeights`,
        :class:`AsoProjection`: ``aso_variant=AsoVariant.PAPER``):

        - all methods: ``min_neighbors`` (int; least neighbour count of a valid estimate,
          default the estimator's measured minimum), ``accept_unnormalized_normals`` (bool),
          ``tile`` (``(core_min, core_max, halo)`` or a :class:`TileGrid.Tile`: estimate only
          the points in the half-open box ``core_min <= p < core_max``, the arrays holding
          every point within ``halo`` of it in input order; the others get
          ``Status.NOT_COMPUTED``; not for ``"vcm"``);
        - ``"aso"``: ``aso_variant`` (``"robust"`` default, ``"paper"``), ``weight_kernel``
          (``"smooth"``, ``"smooth_cubic"``, ``"smooth_quartic"``; default per variant),
          ``sample_weights`` (``"uniform"``, ``"tangent_voronoi_area"``, or an array of
          shape (N,): one weight per point, finite and non-negative, used instead of
          computing them, for example the areas of :func:`estimate_tangent_voronoi_areas`
          shared by several runs; with ``tile``, the weights of the whole cloud; default per
          variant), ``robust_orientation`` (bool; default per variant), ``normal_field_blend``
          (bool; default per variant), ``normal_refinement`` (int, default 0),
          ``position_fit_blend`` (float in [0, 1], default 0: the weight of a quadric
          fitted to the positions alone in the tensor; 0.5 for normals estimated by
          :func:`estimate_normals`), ``aso_projection`` (``"corrected_normal"`` default,
          ``"authors_implementation"``); the robust variant's defaults are
          ``"smooth_cubic"``, ``"tangent_voronoi_area"``, True, True, the paper's
          ``"smooth"``, ``"uniform"``, False, False;
        - ``"apss"``: ``weight_kernel`` (also ``"constant"``; default ``"smooth"``),
          ``sample_weights`` (default ``"uniform"``), ``robust_orientation`` (default False);
        - ``"jet"``: ``degree_fitting`` (default 2), ``degree_monge`` (default 2);
        - ``"vcm"``: ``vcm_offset_radius`` (float; default the radius).

    Returns
    -------
    dict of numpy arrays
        In this order (the package's table of fields): ``normal`` (N, 3), ``k_min``,
        ``k_max``, ``mean``, ``gaussian``, ``min_direction``, ``max_direction`` (N, 3),
        ``normal_coherence`` (N,; a quality value in [0, 1], the length of the weighted mean of
        the neighbours' unit normals: 1 on smooth surfaces, low in foliage; ``"aso"`` and
        ``"apss"`` only, NaN otherwise), with ``neighbors="auto"`` ``mean_error`` (N,; the
        standard error of ``mean`` at the chosen scale, from the noise the fits measure),
        ``neighbors`` (N,) int64 (with ``"auto"``: the chosen count) and ``status`` (N,) uint8
        (values of :class:`Status`). NaN where a point is invalid or the estimator does not
        provide a quantity.
    """
    method = _method(method)
    allowed = set(_COMMON_OPTIONS) | set(_METHOD_OPTIONS[method])
    if not ESTIMATORS[method]["supports_tiles"]:
        allowed.discard("tile")
    opts, tile, weights = _options(f"method '{method}'", allowed, options)
    if radius is None and neighbors is None:
        neighbors = _default_neighbors(method, options)
    radius, neighbors = _scale(radius, neighbors, automatic=ESTIMATORS[method]["supports_automatic_scale"])
    progress = _progress(progress)
    points = _array(points, "points")
    if tile is None:  # a tile's arrays are a part of the cloud
        radius, neighbors = _whole_cloud_scale(points, radius, neighbors)
    if normals is None:
        normals, progress = _estimated_normals(points, neighbors == "auto", threads, progress, tile)
        blend = _blend_on_estimated_normals(method, options)
        if blend is not None:
            opts.position_fit_blend = blend
    return _core.estimate_curvatures(
        method,
        points,
        _array(normals, "normals"),
        radius,
        neighbors,
        _threads(threads),
        progress,
        opts,
        tile,
        weights,
    )


def _blend_on_estimated_normals(method, options):
    """The option position_fit_blend of a run on normals estimate_curvatures estimated: the
    library's default for them, None where the method does not read it (only the ASO does) or
    the caller gave it. The options are those checked by estimate_curvatures."""
    if method != "aso" or options.get("position_fit_blend") is not None:
        return None
    variant = options.get("aso_variant")
    variant = _core._Options().aso_variant if variant is None else _choice("aso_variant", variant, _ASO_VARIANTS)
    return _core.default_position_fit_blend(variant, True)


def _estimated_normal_neighbors(automatic):
    """The normals' scale of estimate_curvatures without normals: the automatic scale under the
    automatic scale, else estimate_normals' default count of the quadric."""
    return "auto" if automatic else int(_core.DEFAULT_NORMAL_NEIGHBORS[0])


def _estimated_normals(points, automatic, threads, progress, tile):
    """(normals, progress of the estimation that follows) for estimate_curvatures without
    normals: as the tool's for a file without them, with its warning; the progress callable
    sees [0, 0.5] for the normals and [0.5, 1] for the curvatures."""
    if tile is not None:
        raise ValueError(
            "normals: required with tile (normals estimated on a tile would not be the whole "
            "cloud's): estimate them once with estimate_normals() and give them to each tile")
    count = f"their count chosen per point from {AUTOMATIC_NEIGHBORS[0]} to {AUTOMATIC_NEIGHBORS[1]}" if automatic \
        else f"the {_core.DEFAULT_NORMAL_NEIGHBORS[0]} nearest"
    warnings.warn(
        f"no normals given: estimating them (a quadric fitted to the nearest neighbours, {count}, "
        "oriented along a minimum spanning tree, closed parts outward, open parts up, parts seen from all sides "
        "checked point by point by the parity of the crossings along the normals); a wrong "
        "orientation flips the sign of the curvatures: call estimate_normals() to choose "
        "(orientation='auto' for airborne scans, ('towards', scanner) for a terrestrial one)",
        UserWarning, stacklevel=3)
    first = second = progress
    if progress is not None:
        first = lambda f: progress(0.5 * f)  # noqa: E731
        second = lambda f: progress(0.5 + 0.5 * f)  # noqa: E731
    with warnings.catch_warnings():  # (a cloud too small for the scale was warned of already)
        warnings.simplefilter("ignore", ScaleWarning)
        normals = estimate_normals(points, neighbors=_estimated_normal_neighbors(automatic), threads=threads,
                                   progress=first)
    return normals, second


def estimate_sphere_features(
    points,
    normals,
    *,
    radius=None,
    neighbors=None,
    threads=None,
    progress=None,
    **options,
):
    """The features of the APSS algebraic sphere fitted around every point
    (``CGAL::estimate_algebraic_sphere_features``, Sections 3-4 of Lejemble et al. 2021).

    Arguments as for :func:`estimate_curvatures`; options: ``weight_kernel`` (``"smooth"``
    default, ``"constant"``, the kernel of the paper's analysis, ``"smooth_cubic"`` or
    ``"smooth_quartic"``), ``sample_weights`` (as for :func:`estimate_curvatures`, an array too),
    ``min_neighbors``, ``accept_unnormalized_normals``, ``tile``.

    Returns
    -------
    dict of numpy arrays
        ``u_c``, ``u_l`` (N, 3), ``u_q``, ``pratt_norm``, ``anisotropy``, ``normal`` (N, 3),
        ``mean`` (mean curvature ``2 u_q``), ``geometric_variation``, ``d_u_c_dr``,
        ``d_normal_dr`` (N, 3), ``d_mean_dr``, ``is_plane`` (bool), ``center`` (N, 3),
        ``sphere_radius``, ``projection`` (N, 3), ``kernel_radius``, ``neighbors``,
        ``status`` (see ``CGAL::Algebraic_sphere_features`` for units and meaning).
    """
    allowed = {"weight_kernel", "sample_weights", "min_neighbors", "accept_unnormalized_normals", "tile"}
    opts, tile, weights = _options("estimate_sphere_features", allowed, options)
    radius, neighbors = _scale(radius, neighbors)
    progress = _progress(progress)
    points = _array(points, "points")
    if tile is None:
        radius, neighbors = _whole_cloud_scale(points, radius, neighbors)
    return _core.sphere_features(
        points,
        _array(normals, "normals"),
        radius,
        neighbors,
        _threads(threads),
        progress,
        opts,
        tile,
        weights,
    )


def estimate_tangent_voronoi_areas(
    points,
    normals,
    *,
    radius=None,
    neighbors=None,
    threads=None,
    progress=None,
    accept_unnormalized_normals=False,
):
    """Per point, the sample weight of the default ASO (``sample_weights="tangent_voronoi_area"``,
    ``CGAL::estimate_tangent_voronoi_areas``): the area of the point's Voronoi cell among its
    neighbours in its tangent plane, within a disk of radius ``radius / 4``, in squared input
    units; 0 for unusable points (non-finite position, unusable normal).

    Computed once, the array can be passed as ``sample_weights=`` to several runs of
    :func:`estimate_curvatures` (``"aso"``, ``"apss"``) and :func:`estimate_sphere_features`
    with the same scale: each then gives bitwise its own ``"tangent_voronoi_area"`` result
    without computing the areas again (they take about two thirds of the time of an ASO run
    without them).

    Arguments as for :func:`estimate_curvatures` (``radius`` or ``neighbors``, ``threads``,
    ``progress``); returns a float64 array of shape (N,).
    """
    radius, neighbors = _scale(radius, neighbors)
    progress = _progress(progress)
    points = _array(points, "points")
    radius, neighbors = _whole_cloud_scale(points, radius, neighbors)
    return _core.tangent_voronoi_areas(
        points,
        _array(normals, "normals"),
        radius,
        neighbors,
        _threads(threads),
        progress,
        _bool("accept_unnormalized_normals", accept_unnormalized_normals),
    )


def estimate_multiscale_sphere_features(
    points, normals, radii, *, threads=None, progress=None, **options
):
    """The sphere features at several radii in one pass
    (``CGAL::estimate_multiscale_algebraic_sphere_features``).

    ``radii``: a sequence of positive radii. Options: ``weight_kernel``, ``min_neighbors``,
    ``accept_unnormalized_normals``. Returns the dict of :func:`estimate_sphere_features`
    with a leading axis of length ``len(radii)`` on every array.
    """
    allowed = {"weight_kernel", "min_neighbors", "accept_unnormalized_normals"}
    opts, _, _ = _options("estimate_multiscale_sphere_features", allowed, options)
    if isinstance(radii, (str, bytes)) or not hasattr(radii, "__iter__"):
        raise ArgumentTypeError(f"radii must be a sequence of numbers, got {_type_hint(radii)}")
    radii = [_real("radii[{}]".format(i), r) for i, r in enumerate(radii)]
    progress = _progress(progress)
    points = _array(points, "points")
    if radii:
        _whole_cloud_scale(points, max(radii), None, "the largest radius: ")
    return _core.multiscale_sphere_features(
        points, _array(normals, "normals"), radii, _threads(threads), progress, opts
    )


class AlgebraicPointSetSurface:
    """The APSS surface of an oriented cloud (``CGAL::Algebraic_point_set_surface``):
    projection of any position onto it, and the sphere features at any position.

    Parameters
    ----------
    points, normals : array_like, shape (N, 3)
    radius : float
        Kernel radius; positions farther than it from every point cannot be projected.
    weight_kernel : str
        ``"smooth"`` (default), ``"constant"``, ``"smooth_cubic"`` or ``"smooth_quartic"``.
    """

    def __init__(self, points, normals, radius, *, weight_kernel="smooth"):
        self._surface = _core._Surface(
            _array(points, "points"),
            _array(normals, "normals"),
            _real("radius", radius),
            _choice("weight_kernel", weight_kernel, _WEIGHT_KERNELS),
        )

    @property
    def radius(self):
        """The kernel radius."""
        return self._surface.radius

    @property
    def number_of_points(self):
        """The number of usable points indexed (finite, with a non-zero normal)."""
        return self._surface.number_of_points

    @property
    def tolerance(self):
        """A projection stops when a step is shorter (default ``1e-10 * radius``)."""
        return self._surface.tolerance

    @tolerance.setter
    def tolerance(self, value):
        self._surface.tolerance = _real("tolerance", value)

    @property
    def max_iterations(self):
        """The maximal number of steps of a projection (default 30)."""
        return self._surface.max_iterations

    @max_iterations.setter
    def max_iterations(self, value):
        self._surface.max_iterations = _int("max_iterations", value, 0)

    def project(self, queries, *, threads=None):
        """Projects every row of ``queries`` (M, 3) onto the surface (iterated Equation 20).

        Returns a dict: ``point`` (M, 3), ``normal`` (M, 3), ``iterations``, ``neighbors``,
        ``status`` (values of :class:`ProjectionStatus`); NaN unless converged or not
        converged.
        """
        return self._surface.project(_array(queries, "queries"), _threads(threads))

    def features(self, queries, *, threads=None):
        """The sphere features fitted at every row of ``queries`` (M, 3), as returned by
        :func:`estimate_sphere_features`."""
        return self._surface.features(_array(queries, "queries"), _threads(threads))


def apss_smooth_point_set(
    points,
    normals,
    radius,
    *,
    iterations=1,
    update_normals=False,
    weight_kernel="smooth",
    threads=None,
    progress=None,
):
    """The bilaplacian flow of Section 4.5 (``CGAL::apss_smooth_point_set``): every point
    moved onto the sphere fitted around it, ``iterations`` times. The inputs are not
    modified.

    Returns a dict: ``points`` (N, 3) the moved points, ``normals`` (N, 3) (the fitted
    spheres' normals with ``update_normals=True``, else the input normals), ``status`` (the
    last iteration's, values of :class:`Status`).
    """
    progress = _progress(progress)
    opts = _core._Options()
    opts.weight_kernel = _choice("weight_kernel", weight_kernel, _WEIGHT_KERNELS)
    points = _array(points, "points")
    radius, _ = _whole_cloud_scale(points, _real("radius", radius), None)
    return _core.smooth_point_set(
        points,
        _array(normals, "normals"),
        radius,
        _int("iterations", iterations, 0),
        _bool("update_normals", update_normals),
        _threads(threads),
        progress,
        opts,
    )


_AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1)}


def _orientation(orientation):
    """(kind, target) of a normal orientation as estimate_normals() takes it (kind: 0 spanning
    tree, 1 along the target, 2 towards it, 3 automatic); ValueError for anything else."""
    if isinstance(orientation, str):
        orientation = orientation.lower()
        if orientation == "mst":
            return 0, (0.0, 0.0, 1.0)
        if orientation == "auto":
            return 3, (0.0, 0.0, 1.0)
        if orientation in _AXES:
            return 1, tuple(float(v) for v in _AXES[orientation])
        raise ValueError(f"orientation: expected 'mst', 'auto', '+x', ..., '-z', ('along', v) or ('towards', p), got {orientation!r}")
    try:
        what, target = orientation
        target = tuple(_real("orientation vector", v) for v in target)
    except (TypeError, ValueError):
        raise ValueError(f"orientation: expected ('along', (x, y, z)) or ('towards', (x, y, z)), got {orientation!r}") from None
    what = what.lower() if isinstance(what, str) else what
    if what not in ("along", "towards") or len(target) != 3:
        raise ValueError(f"orientation: expected ('along', (x, y, z)) or ('towards', (x, y, z)), got {orientation!r}")
    return (1 if what == "along" else 2), target


def _spans_whole_cloud(kind):
    """Whether an orientation kind of _orientation() needs the whole cloud (the spanning tree,
    which the automatic one may choose): the library's internal::is_global()."""
    return kind in (0, 3)


def estimate_normals(points, *, neighbors=None, radius=None, orientation="mst", fit="quadric", threads=None,
                     progress=None):
    """Oriented normals for a cloud without (``CGAL::estimate_oriented_normals``): the
    normal of a fit of the ``neighbors`` nearest points or of the ball of ``radius``, then
    oriented.

    ``fit``: ``"quadric"`` (a weighted quadric, smooth from point to point: the input the ASO
    needs; default, 40 neighbours by default, or ``neighbors="auto"``: each point's count
    chosen among 40, 80, ..., 640 by the noise its fits measure) or ``"plane"`` (the PCA
    plane, 18 neighbours by default). With estimated normals, pass ``position_fit_blend=0.5`` to
    :func:`estimate_curvatures` (method ``"aso"``): on simulated scans its error was within
    1.35 times that with exact normals.

    ``orientation``: ``"mst"`` (along a minimum spanning tree, each connected part outward if
    it is closed, up if it is open; default), ``"auto"`` (``"mst"``, then +z on the
    near-vertical normals of its open parts if the cloud is 2.5-D, as airborne scans are), ``"+x"``, ``"-x"``, ..., ``"-z"``,
    ``("along", (x, y, z))`` (every normal on the side of the vector) or
    ``("towards", (x, y, z))`` (towards a scanner).

    Returns the (N, 3) float64 array of unit normals, zero where none can be estimated
    (such points are ``Status.INVALID_NORMAL`` for the estimators).
    """
    fits = {"plane": 0, "quadric": 1}
    if not isinstance(fit, str) or fit.lower() not in fits:
        raise ValueError(f"fit: expected 'quadric' or 'plane', got {fit!r}")
    fit_code = fits[fit.lower()]
    if radius is None and neighbors is None:
        neighbors = _core.DEFAULT_NORMAL_NEIGHBORS[0 if fit_code == 1 else 1]
    radius, neighbors = _scale(radius, neighbors, automatic=fit_code == 1)
    kind, target = _orientation(orientation)
    progress = _progress(progress)
    points = _array(points, "points")
    radius, neighbors = _whole_cloud_scale(points, radius, neighbors)
    normals, _without = _core.estimate_normals(
        points, radius, neighbors, kind, [float(v) for v in target], fit_code, _threads(threads), progress
    )
    return normals


def read_point_cloud(path, *, columns=None, attributes=True, allow_truncated=False):
    """Reads a point cloud file with the package's readers (those of the command-line tool):
    ``.xyz``, ``.pwn``, ``.txt``, ``.csv``, ``.asc`` (one point per line, values separated by
    white space or commas, ``#`` comments), ``.ply`` (ASCII or binary), ``.off`` and ``.las``
    (LAS 1.0 to 1.4, uncompressed, point formats 0 to 10; coordinates scaled and offset).
    Every file is read completely and checked: nothing is guessed from a damaged one.

    ``columns``: the names of a text file's values, as the tool's ``--columns``: a string
    ``"x,y,z,_,nx,ny,nz"`` or a sequence of names (``_`` or any other name skips or keeps a
    value as an attribute); ``None`` reads a header line of names if the file has one, else 3
    values (x y z) or 6 (x y z nx ny nz). ``attributes``: keep the values other than the
    coordinates and normals (PLY properties, named text columns, LAS fields such as
    ``intensity``, ``classification``, ``gps_time``). ``allow_truncated``: read a LAS file
    whose last records are missing up to its last complete record, with a warning.

    Returns a dict: ``points``, the (N, 3) float64 coordinates in file order; ``normals``,
    (N, 3) float64, or ``None`` when the file has none (then see :func:`estimate_normals`);
    ``attributes``, a dict of name to (N,) array in the file's type; ``warnings``, a list of
    the file's problems that did not prevent reading it. Raises ``FileNotFoundError`` for a
    missing file, ``ValueError`` with the reader's message (naming the file, the line or
    element, and what is wrong) for a malformed, unreadable or unsupported one.
    """
    try:
        path = os.fspath(path)
    except TypeError:
        raise ArgumentTypeError(f"path: expected a path, got {_type_hint(path)}") from None
    if not os.path.exists(path):
        raise FileNotFoundError(errno.ENOENT, os.strerror(errno.ENOENT), path)
    if columns is None:
        columns = ""
    elif not isinstance(columns, str):
        try:
            names = list(columns)
        except TypeError:
            raise ArgumentTypeError(f"columns: expected a string or a sequence of names, got {_type_hint(columns)}") from None
        if not all(isinstance(c, str) for c in names):
            raise ArgumentTypeError("columns: expected a string or a sequence of names (str)")
        columns = ",".join(names)
    r = _core.read_point_cloud(os.fsencode(path), columns, _bool("attributes", attributes),
                               _bool("allow_truncated", allow_truncated))
    return {"points": r["points"], "normals": r["normals"], "attributes": dict(r["attributes"]),
            "warnings": list(r["warnings"])}


class TileGrid:
    """The library's partition of space into tiles (``CGAL::Point_set_curvatures::Tile_grid``):
    tiles of side about ``tile_side`` (or ``counts`` tiles per axis) over a box, the outer
    ones extending to infinity, so that every finite point is own in exactly one tile.
    Used to estimate a cloud piece by piece (see :mod:`point_set_curvatures.dask`)."""

    class Tile:
        """One tile: the half-open core box ``core_min <= p < core_max`` and the halo."""

        __slots__ = ("index", "core_min", "core_max", "halo")

        def __init__(self, index, core_min, core_max, halo):
            self.index = index
            self.core_min = tuple(core_min)
            self.core_max = tuple(core_max)
            self.halo = _real("halo", halo)

        def __repr__(self):
            return f"TileGrid.Tile({self.index}, {self.core_min}, {self.core_max}, halo={self.halo})"

        def halo_mask(self, points):
            """Boolean mask of the rows of ``points`` within the halo box of the core (the
            core grown by ``halo`` on every side: a superset of the points at distance
            ``<= halo``, which is what a tile needs)."""
            p = np.asarray(points)
            lo = np.asarray(self.core_min) - self.halo
            hi = np.asarray(self.core_max) + self.halo
            return np.all((p >= lo) & (p <= hi), axis=1)

        def owns(self, points):
            """Boolean mask of the rows of ``points`` that are the tile's own points (inside the
            half-open core, ``Tile::owns``)."""
            return _core.tile_owns(self.core_min, self.core_max, _array(points, "points"))

    def __init__(self, box_min, box_max, tile_side=None, *, counts=None):
        self._grid = _core._TileGrid(
            [_real("box_min", v) for v in box_min],
            [_real("box_max", v) for v in box_max],
            None if tile_side is None else _real("tile_side", tile_side),
            None if counts is None else [_int("counts", c, 1) for c in counts],
        )

    def __len__(self):
        return len(self._grid)

    @property
    def counts(self):
        """The number of tiles along each axis."""
        return self._grid.counts

    def tile(self, index, halo):
        """Tile ``index`` with the given halo, as a :class:`TileGrid.Tile`."""
        lo, hi = self._grid.core(int(index))
        return TileGrid.Tile(int(index), lo, hi, halo)

    def tile_of(self, points):
        """For each row of ``points``, the index of the tile owning it (``len(self)`` for
        points with a non-finite coordinate), as an int64 array."""
        return self._grid.tile_of(_array(points, "points"))

    def tiles_near(self, points, halo):
        """Every (point, tile) pair with the point at distance ``<= halo`` from the tile's
        core: two int64 arrays ``(point_indices, tile_indices)``, sorted by tile, then point."""
        return self._grid.tiles_near(_array(points, "points"), _real("halo", halo))
