# Type stubs of point_set_curvatures (Python bindings of Point_set_curvatures).
import os
from enum import IntEnum
from typing import Any, Callable, Dict, Literal, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayN3 = npt.ArrayLike
# returns False to cancel; any other value (True, None, 0, ...) continues
Progress = Optional[Callable[[float], object]]
Vec3 = Sequence[float]
Result = Dict[str, np.ndarray]
Method = Literal["aso", "apss", "barycenter", "pca_plane", "pss", "jet", "vcm", "wavejet"]
WeightKernelName = Literal["smooth", "constant", "smooth_cubic", "smooth_quartic"]
SampleWeightsName = Literal["uniform", "tangent_voronoi_area"]
AsoVariantName = Literal["paper", "robust"]
AsoProjectionName = Literal["corrected_normal", "authors_implementation"]

class _Enumeration:
    """A C++ enumeration (pybind11 enum): its members are accepted where the names are."""
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...
    def __int__(self) -> int: ...
    def __index__(self) -> int: ...

class WeightKernel(_Enumeration):
    SMOOTH: "WeightKernel"
    CONSTANT: "WeightKernel"
    SMOOTH_CUBIC: "WeightKernel"
    SMOOTH_QUARTIC: "WeightKernel"

class SampleWeights(_Enumeration):
    UNIFORM: "SampleWeights"
    TANGENT_VORONOI_AREA: "SampleWeights"

class AsoVariant(_Enumeration):
    PAPER: "AsoVariant"
    ROBUST: "AsoVariant"

class AsoProjection(_Enumeration):
    CORRECTED_NORMAL: "AsoProjection"
    AUTHORS_IMPLEMENTATION: "AsoProjection"

WeightKernelOption = Union[WeightKernelName, WeightKernel]
SampleWeightsOption = Union[SampleWeightsName, SampleWeights, npt.ArrayLike]
AsoVariantOption = Union[AsoVariantName, AsoVariant]
AsoProjectionOption = Union[AsoProjectionName, AsoProjection]
TileSpec = Union["TileGrid.Tile", Tuple[Vec3, Vec3, float]]
Orientation = Union[str, Tuple[Literal["along", "towards"], Vec3]]

# the names in lower case; any case is accepted at run time
METHODS: Tuple[str, ...]
# name -> name, function, summary, fields, min_neighbors, good_neighbors,
# paper_variant_good_neighbors, supports_tiles, supports_automatic_scale, options
ESTIMATORS: Mapping[str, Dict[str, Any]]

__version__: str

class ArgumentTypeError(TypeError, ValueError): ...
class ScaleWarning(UserWarning): ...
class Cancelled(RuntimeError): ...

class HaloTooSmall(RuntimeError):
    required_halo: float

class Status(IntEnum):
    VALID = 0
    TOO_FEW_NEIGHBORS = 1
    DEGENERATE_FIT = 2
    NON_FINITE_POINT = 3
    INVALID_NORMAL = 4
    NOT_COMPUTED = 5
    TWO_SHEETS = 6
    @classmethod
    def names(cls, statuses: npt.ArrayLike) -> npt.NDArray[np.str_]: ...
    @classmethod
    def counts(cls, statuses: npt.ArrayLike) -> Dict[str, int]: ...

class ProjectionStatus(IntEnum):
    CONVERGED = 0
    NOT_CONVERGED = 1
    TOO_FEW_NEIGHBORS = 2
    DEGENERATE_FIT = 3
    NON_FINITE_POINT = 4

AUTOMATIC_NEIGHBORS: Tuple[int, int]
DEFAULT_NEIGHBORS: int

def estimate_curvatures(
    points: ArrayN3,
    normals: Optional[ArrayN3] = None,
    *,
    method: Method = "aso",
    radius: Optional[float] = None,
    neighbors: Union[int, Literal["auto"], None] = None,
    threads: Optional[int] = None,
    progress: Progress = None,
    min_neighbors: Optional[int] = None,
    accept_unnormalized_normals: Optional[bool] = None,
    tile: Optional[TileSpec] = None,
    aso_variant: Optional[AsoVariantOption] = None,
    weight_kernel: Optional[WeightKernelOption] = None,
    sample_weights: Optional[SampleWeightsOption] = None,
    robust_orientation: Optional[bool] = None,
    normal_field_blend: Optional[bool] = None,
    normal_refinement: Optional[int] = None,
    position_fit_blend: Optional[float] = None,
    aso_projection: Optional[AsoProjectionOption] = None,
    degree_fitting: Optional[int] = None,
    degree_monge: Optional[int] = None,
    vcm_offset_radius: Optional[float] = None,
) -> Result:
    """Curvatures at every point: dict with normal (N,3), k_min, k_max, mean, gaussian,
    min_direction (N,3), max_direction (N,3), normal_coherence, with neighbors="auto" (method
    "aso") mean_error, neighbors (int64), status (uint8, Status), in this order."""

def estimate_sphere_features(
    points: ArrayN3,
    normals: ArrayN3,
    *,
    radius: Optional[float] = None,
    neighbors: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Progress = None,
    weight_kernel: Optional[WeightKernelOption] = None,
    sample_weights: Optional[SampleWeightsOption] = None,
    min_neighbors: Optional[int] = None,
    accept_unnormalized_normals: Optional[bool] = None,
    tile: Optional[TileSpec] = None,
) -> Result:
    """Algebraic sphere features at every point."""

def estimate_tangent_voronoi_areas(
    points: ArrayN3,
    normals: ArrayN3,
    *,
    radius: Optional[float] = None,
    neighbors: Optional[int] = None,
    threads: Optional[int] = None,
    progress: Progress = None,
    accept_unnormalized_normals: bool = False,
) -> np.ndarray:
    """Per point, the default ASO's sample weight (tangent Voronoi area), to pass to several
    estimators as sample_weights=..."""

def estimate_multiscale_sphere_features(
    points: ArrayN3,
    normals: ArrayN3,
    radii: Sequence[float],
    *,
    threads: Optional[int] = None,
    progress: Progress = None,
    weight_kernel: Optional[WeightKernelOption] = None,
    min_neighbors: Optional[int] = None,
    accept_unnormalized_normals: Optional[bool] = None,
) -> Result:
    """Sphere features at several radii: arrays with a leading axis len(radii)."""

class AlgebraicPointSetSurface:
    """The APSS surface of an oriented cloud: projection and features at any position."""
    def __init__(
        self, points: ArrayN3, normals: ArrayN3, radius: float, *,
        weight_kernel: WeightKernelOption = "smooth",
    ) -> None: ...
    @property
    def radius(self) -> float: ...
    @property
    def number_of_points(self) -> int: ...
    tolerance: float
    max_iterations: int
    def project(self, queries: ArrayN3, *, threads: Optional[int] = None) -> Result:
        """dict: point (M,3), normal (M,3), iterations, neighbors, status (ProjectionStatus)."""
    def features(self, queries: ArrayN3, *, threads: Optional[int] = None) -> Result:
        """Sphere features fitted at each query."""

def apss_smooth_point_set(
    points: ArrayN3,
    normals: ArrayN3,
    radius: float,
    *,
    iterations: int = 1,
    update_normals: bool = False,
    weight_kernel: WeightKernelOption = "smooth",
    threads: Optional[int] = None,
    progress: Progress = None,
) -> Result:
    """Bilaplacian flow: dict with points (N,3), normals (N,3), status."""

def estimate_normals(
    points: ArrayN3,
    *,
    neighbors: Union[int, Literal["auto"], None] = None,
    radius: Optional[float] = None,
    orientation: Orientation = "mst",
    fit: Literal["quadric", "plane"] = "quadric",
    threads: Optional[int] = None,
    progress: Progress = None,
) -> np.ndarray:
    """Oriented unit normals (N,3), zero where none can be estimated."""

def read_point_cloud(
    path: Union[str, "os.PathLike[str]"],
    *,
    columns: Union[str, Sequence[str], None] = None,
    attributes: bool = True,
    allow_truncated: bool = False,
) -> Dict[str, Any]:
    """The file's points (N,3), normals (N,3) or None, attributes and warnings, read by the tool's readers."""

class TileGrid:
    """The library's partition of space into tiles (Tile_grid)."""
    class Tile:
        index: int
        core_min: Tuple[float, float, float]
        core_max: Tuple[float, float, float]
        halo: float
        def __init__(self, index: int, core_min: Vec3, core_max: Vec3, halo: float) -> None: ...
        def halo_mask(self, points: ArrayN3) -> np.ndarray: ...
        def owns(self, points: ArrayN3) -> np.ndarray: ...
    def __init__(
        self, box_min: Vec3, box_max: Vec3, tile_side: Optional[float] = None, *,
        counts: Optional[Sequence[int]] = None,
    ) -> None: ...
    def __len__(self) -> int: ...
    @property
    def counts(self) -> Tuple[int, int, int]: ...
    def tile(self, index: int, halo: float) -> "TileGrid.Tile": ...
    def tile_of(self, points: ArrayN3) -> np.ndarray: ...
    def tiles_near(self, points: ArrayN3, halo: float) -> Tuple[np.ndarray, np.ndarray]: ...
