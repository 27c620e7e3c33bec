# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The clouds that :func:`point_set_curvatures.dask.estimate_curvatures_file` reads in place,
block by block: binary PLY files, ``.npy`` arrays and uncompressed LAS files, with or without
normals. Their headers are read by the package's readers (the tool's), so that every file
gives the coordinates ``read_point_cloud`` gives, bitwise."""

import collections
import os

import numpy as np

from . import _core

XYZ = ("x", "y", "z")
NORMALS = ("nx", "ny", "nz")

#: One file of a cloud: its records (``dtype``, the fields of ``XYZ`` and of ``NORMALS`` if it
#: has normals) are ``rows`` from byte ``offset``; ``scale`` and ``shift`` (LAS files: integer
#: coordinates) give x = X * scale[0] + shift[0], else None.
Source = collections.namedtuple("Source", "path offset dtype rows scale shift")


def has_normals(source):
    return NORMALS[0] in source.dtype.names


def _ply_source(path):
    """The vertices of a binary PLY file, as the package's PLY reader (the tool's,
    ``_core.ply_vertex_layout``) finds them: x y z and the normals (nx ny nz or normal_x
    normal_y normal_z) if it has them, of any scalar type."""
    layout = _core.ply_vertex_layout(path)
    order = ">" if layout["big_endian"] else "<"
    roles = layout["xyz"] + (layout["normals"] or ())  # (name, numpy type code, offset) each
    names = (XYZ + NORMALS)[:len(roles)]
    record = np.dtype({"names": list(names), "formats": [order + code for _, code, _ in roles],
                       "offsets": [offset for _, _, offset in roles], "itemsize": layout["record_size"]})
    return Source(path, layout["offset"], record, layout["count"], None, None)


def _npy_source(path):
    """An (N, 6) .npy array of floats (x y z nx ny nz), or (N, 3) (x y z)."""
    try:
        a = np.load(path, mmap_mode="r", allow_pickle=False)
    except ValueError as e:
        raise ValueError(f"{path}: not a readable .npy array ({e})") from None
    shape, dtype, offset = a.shape, a.dtype, getattr(a, "offset", 0)
    fortran = a.ndim == 2 and not a.flags.c_contiguous
    del a
    if len(shape) != 2 or shape[1] not in (3, 6) or dtype.kind != "f" or dtype.fields is not None:
        raise ValueError(f"{path}: expected a .npy array of shape (N, 6) (x y z nx ny nz) or (N, 3) (x y z) of "
                         f"float32 or float64, got shape {shape} and dtype {dtype}")
    if fortran and shape[0] > 1:
        raise ValueError(f"{path}: Fortran-order .npy arrays are not supported (save a C-order array)")
    s = dtype.itemsize
    columns = shape[1]
    record = np.dtype({"names": list((XYZ + NORMALS)[:columns]), "formats": [dtype] * columns,
                       "offsets": [a * s for a in range(columns)], "itemsize": columns * s})
    return Source(path, offset, record, shape[0], None, None)


def _las_source(path):
    """The point records of an uncompressed LAS file (``_core.las_point_layout``): the int32 X
    Y Z at their start, scaled and shifted as the package's LAS reader does."""
    layout = _core.las_point_layout(path)
    record = np.dtype({"names": list(XYZ), "formats": ["<i4"] * 3, "offsets": [0, 4, 8],
                       "itemsize": layout["record_size"]})
    return Source(path, layout["offset"], record, layout["count"], tuple(layout["scale"]), tuple(layout["shift"]))


def open_sources(paths):
    """The cloud of a file or list of files, as a list of :data:`Source`; every file with
    normals or none."""
    if isinstance(paths, (str, bytes)) or hasattr(paths, "__fspath__"):
        paths = [paths]
    sources = []
    for path in paths:
        path = os.path.abspath(os.fspath(path))
        with open(path, "rb") as f:
            magic = f.read(6)
        if magic.startswith(b"ply"):
            source = _ply_source(path)
        elif magic == b"\x93NUMPY":
            source = _npy_source(path)
        elif magic.startswith(b"LASF"):
            source = _las_source(path)
        else:
            raise ValueError(f"{path}: neither a PLY, a .npy nor a LAS file")
        size = os.path.getsize(path)
        if size < source.offset + source.rows * source.dtype.itemsize:
            raise ValueError(f"{path}: truncated ({size} bytes, the header announces "
                             f"{source.offset + source.rows * source.dtype.itemsize})")
        sources.append(source)
    if not sources:
        raise ValueError("no input file")
    with_normals = [has_normals(s) for s in sources]
    if any(with_normals) and not all(with_normals):
        raise ValueError(f"{sources[with_normals.index(False)].path} has no normals, {sources[with_normals.index(True)].path} "
                         "has: give files that all have normals (they are used) or none (they are estimated)")
    return sources


def blocks(sources, block_rows):
    """Every block of the cloud: an int64 array of rows (source, first row, end row, first
    global index)."""
    out, base = [], 0
    for s, source in enumerate(sources):
        for start in range(0, source.rows, block_rows):
            out.append((s, start, min(source.rows, start + block_rows), base + start))
        base += source.rows
    return np.array(out, dtype=np.int64).reshape(-1, 4)


def read(sources, block, columns):
    """Reads `columns` (of XYZ and NORMALS) of a block as a float64 (rows, len(columns)) array
    (the block mapped only while reading: the file's pages do not stay in the worker's
    memory)."""
    s, start, stop, _ = (int(v) for v in block)
    source = sources[s]
    mm = np.memmap(source.path, dtype=source.dtype, mode="r", offset=source.offset + start * source.dtype.itemsize,
                   shape=(stop - start,))
    try:
        out = np.empty((stop - start, len(columns)))
        for a, c in enumerate(columns):
            if source.scale is None:
                out[:, a] = mm[c]
            else:  # as the LAS reader: double(X) * scale + offset
                k = XYZ.index(c)
                out[:, a] = mm[c].astype(np.float64) * source.scale[k] + source.shift[k]
        return out
    finally:
        del mm
