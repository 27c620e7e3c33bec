# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Type stubs of point_set_curvatures.dask."""

import os
from typing import Any, Dict, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import Orientation

_Path = Union[str, "os.PathLike[str]"]

BLOCK_ROWS: int
RESULT_DTYPE: np.dtype
AUTOMATIC_RESULT_DTYPE: np.dtype

def estimate_tile(
    points: npt.ArrayLike,
    normals: npt.ArrayLike,
    core_min: Sequence[float],
    core_max: Sequence[float],
    halo: float,
    *,
    method: str = ...,
    radius: Optional[float] = ...,
    neighbors: Union[int, Literal["auto"], None] = ...,
    threads: Optional[int] = ...,
    **options: Any,
) -> Union[Tuple[np.ndarray, Dict[str, np.ndarray]], Tuple[str, float]]: ...
def estimate_curvatures(
    client: Any,
    points: npt.ArrayLike,
    normals: npt.ArrayLike,
    *,
    method: str = ...,
    radius: Optional[float] = ...,
    neighbors: Union[int, Literal["auto"], None] = ...,
    tile_size: Optional[float] = ...,
    threads: Optional[int] = ...,
    retries: int = ...,
    initial_halo: Optional[float] = ...,
    **options: Any,
) -> Dict[str, np.ndarray]: ...
def estimate_curvatures_file(
    client: Any,
    input_path: Union[_Path, Sequence[_Path]],
    output_path: _Path,
    *,
    method: str = ...,
    radius: Optional[float] = ...,
    neighbors: Union[int, Literal["auto"], None] = ...,
    tile_size: Optional[float] = ...,
    threads: Optional[int] = ...,
    retries: int = ...,
    initial_halo: Optional[float] = ...,
    block_rows: int = ...,
    normal_orientation: Optional[Orientation] = ...,
    **options: Any,
) -> Dict[str, Any]: ...
def read_result(path: _Path) -> Dict[str, np.ndarray]: ...
