#!/usr/bin/python3
# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Renders outputs of the point_set_curvatures tool side by side, coloured by mean curvature.

    /usr/bin/python3 benchmark/render_picture.py OUTPUT.png CLOUD.ply[:YAW,PITCH] ...

Each CLOUD.ply is a PLY written by the tool (binary or ASCII; plain or --ply-names scalar
names): one panel per cloud, seen along -z after turning it by YAW degrees about the y axis
and PITCH degrees about the x axis. Orthographic projection; each point is a disc splat in a
depth buffer, shaded by its corrected normal (Lambert, two-sided) and coloured by its mean
curvature with a diverging map: blue < 0 < red, white at 0, saturated beyond the 98th
percentile of |H| of the cloud; invalid points grey. numpy only; the PNG is written with
zlib and struct. The README's picture (doc/images/curvatures.png):

    ./build/tools/point_set_curvatures data/bunny.ply /tmp/bunny.ply
    ./build/tools/point_set_curvatures data/goursat_050000.xyz /tmp/goursat.ply --columns x,y,z,_,_,_
    /usr/bin/python3 benchmark/render_picture.py doc/images/curvatures.png /tmp/bunny.ply:0,0 \
        /tmp/goursat.ply:35,-30
"""

import struct
import sys
import zlib

import numpy as np

PANEL = 400          # pixels per panel side in the PNG
SUPERSAMPLE = 2      # rendered at this multiple, then averaged down
SPLAT_SCALE = 1.5    # splat radius in units of the mean projected spacing

PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
             "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
             "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


def read_ply(path):
    """The vertex properties of a PLY written by the tool, as a dict of numpy arrays."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt = header[1].split()[1]
    count = 0
    names, types = [], []
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            names.append(words[2])
            types.append(PLY_TYPES[words[1]])
    if fmt == "ascii":
        table = np.loadtxt(data[end:].decode("ascii").splitlines(), ndmin=2)
        columns = {n: table[:, i] for i, n in enumerate(names)}
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        dtype = np.dtype([(n, order + t) for n, t in zip(names, types)])
        rows = np.frombuffer(data, dtype=dtype, count=count, offset=end)
        columns = {n: rows[n].astype(np.float64) for n in names}
    # --ply-names scalar: scalar_mean is the mean
    return {n[len("scalar_"):] if n.startswith("scalar_") else n: v for n, v in columns.items()}


def rotation(yaw, pitch):
    a, b = np.radians(yaw), np.radians(pitch)
    about_y = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    about_x = np.array([[1, 0, 0], [0, np.cos(b), -np.sin(b)], [0, np.sin(b), np.cos(b)]])
    return about_x @ about_y


def diverging(t):
    """t in [-1, 1] to RGB in [0, 1]: blue (-1), white (0), red (+1)."""
    blue = np.array([0.23, 0.30, 0.75])
    white = np.array([0.95, 0.95, 0.95])
    red = np.array([0.71, 0.02, 0.15])
    t = np.clip(t, -1, 1)[:, None]
    return np.where(t < 0, white + (blue - white) * -t, white + (red - white) * t)


def render_panel(cloud, yaw, pitch, size):
    p = np.stack([cloud["x"], cloud["y"], cloud["z"]], axis=1)
    n = np.stack([cloud["nx"], cloud["ny"], cloud["nz"]], axis=1)
    h = cloud["mean"]
    valid = np.isfinite(h) & np.all(np.isfinite(n), axis=1)
    p = p - p.mean(axis=0)
    r = rotation(yaw, pitch)
    p = p @ r.T
    n = np.where(valid[:, None], n, 0) @ r.T

    lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
    scale = 0.92 * size / (hi - lo).max()
    centre = (lo + hi) / 2
    px = (p[:, 0] - centre[0]) * scale + size / 2
    py = size / 2 - (p[:, 1] - centre[1]) * scale
    # a splat covers about the area per point of the projected cloud (a closed surface shows half)
    visible_area = 0.5 * np.pi * ((hi - lo).max() * scale / 2) ** 2
    radius = max(1.0, SPLAT_SCALE * np.sqrt(visible_area / (0.5 * len(p))))

    limit = np.percentile(np.abs(h[valid]), 98) if valid.any() else 1.0
    color = np.where(valid[:, None], diverging(np.where(valid, h, 0) / limit), 0.6)
    light = np.array([0.3, 0.4, 1.0])
    light /= np.linalg.norm(light)
    lambert = np.abs(n @ light)
    shade = np.where(valid, 0.35 + 0.65 * lambert, 0.8)
    rgb = color * shade[:, None]

    depth = np.full(size * size, np.inf)
    index = np.full(size * size, -1, dtype=np.int64)
    reach = int(np.ceil(radius))
    offsets = [(dx, dy) for dx in range(-reach, reach + 1) for dy in range(-reach, reach + 1)
               if dx * dx + dy * dy <= radius * radius]
    # nearest point per pixel: depth buffer by np.minimum.at, then the point that reached it
    z = -p[:, 2]  # the viewer looks along -z: a larger z is nearer
    cells = []
    for dx, dy in offsets:
        ix = np.floor(px).astype(np.int64) + dx
        iy = np.floor(py).astype(np.int64) + dy
        inside = (ix >= 0) & (ix < size) & (iy >= 0) & (iy < size)
        cell = np.where(inside, iy * size + ix, -1)
        cells.append(cell)
        np.minimum.at(depth, cell[inside], z[inside])
    for cell in cells:
        inside = cell >= 0
        hit = inside.copy()
        hit[inside] = depth[cell[inside]] == z[inside]
        index[cell[hit]] = np.nonzero(hit)[0]
    image = np.ones((size * size, 3))
    covered = index >= 0
    image[covered] = rgb[index[covered]]
    return image.reshape(size, size, 3)


def write_png(path, image):
    """image: (height, width, 3) floats in [0, 1]; 8-bit RGB, each row filtered with Up."""
    pixels = np.clip(np.round(image * 255), 0, 255).astype(np.uint8)
    height, width, _ = pixels.shape
    rows = pixels.reshape(height, width * 3).astype(np.int16)
    up = np.vstack([rows[:1], (rows[1:] - rows[:-1]) % 256]).astype(np.uint8)
    filters = np.full((height, 1), 2, dtype=np.uint8)
    filters[0] = 0
    raw = np.hstack([filters, up]).tobytes()

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    size = PANEL * SUPERSAMPLE
    panels = []
    for spec in argv[2:]:
        path, _, view = spec.partition(":")
        yaw, pitch = (float(v) for v in view.split(",")) if view else (0.0, 0.0)
        panel = render_panel(read_ply(path), yaw, pitch, size)
        panel = panel.reshape(PANEL, SUPERSAMPLE, PANEL, SUPERSAMPLE, 3).mean(axis=(1, 3))
        panels.append(panel)
    write_png(argv[1], np.hstack(panels))


if __name__ == "__main__":
    main(sys.argv)
