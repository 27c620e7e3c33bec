#!/usr/bin/env python3
# Per-class summary of the tool's output on a real LAS tile (binary PLY written by
# point_set_curvatures): share of normals pointing up, share of valid estimates, median |H|,
# and the vegetation-to-ground contrast of |H|. numpy only (Debian's python3-numpy).
#
#   benchmark/real_tiles.py OUTPUT.ply [OUTPUT.ply ...]
import sys
import numpy as np

PLY_TYPES = {"double": "<f8", "float": "<f4", "int": "<i4", "uint": "<u4", "short": "<i2", "ushort": "<u2",
             "char": "i1", "uchar": "u1", "int8": "i1", "uint8": "u1", "int16": "<i2", "uint16": "<u2",
             "int32": "<i4", "uint32": "<u4", "float32": "<f4", "float64": "<f8"}
CLASSES = {1: "unclassified", 2: "ground", 3: "low vegetation", 4: "medium vegetation", 5: "high vegetation",
           6: "building", 7: "low point", 9: "water"}


def read_ply(path):
    with open(path, "rb") as f:
        fields, n = [], 0
        assert f.readline().strip() == b"ply"
        while True:
            line = f.readline().decode().split()
            if not line:
                continue
            if line[0] == "format" and line[1] != "binary_little_endian":
                raise SystemExit(path + ": binary little-endian PLY expected")
            if line[0] == "element":
                n = int(line[2])
            elif line[0] == "property":
                fields.append((line[2], PLY_TYPES[line[1]]))
            elif line[0] == "end_header":
                break
        return np.frombuffer(f.read(), dtype=np.dtype(fields), count=n)


def summary(path):
    v = read_ply(path)
    print(f"{path}: {len(v)} points; normals up {100 * np.mean(v['nz'] > 0):.1f}%, valid {100 * np.mean(v['valid'] == 1):.1f}%")
    fields = v.dtype.names
    if "classification" not in fields:
        return
    cls = v["classification"] & 31
    med = {}
    for c in np.unique(cls):
        m = cls == c
        ok = m & (v["valid"] == 1)
        h = np.abs(v["mean"][ok])
        med[c] = np.median(h) if len(h) else np.nan
        extra = ""
        if "normal_coherence" in fields and ok.any():
            extra = f", median normal_coherence {np.median(v['normal_coherence'][ok]):.3g}"
        print(f"  class {c:2d} {CLASSES.get(int(c), ''):18s} {m.sum():7d} points: up {100 * np.mean(v['nz'][m] > 0):5.1f}%,"
              f" valid {100 * np.mean(v['valid'][m] == 1):5.1f}%, median |H| {med[c]:.4g}{extra}")
    veg = [c for c in (3, 4, 5) if c in med and not np.isnan(med[c])]
    if 2 in med and veg:
        vm = np.abs(v["mean"][np.isin(cls, veg) & (v["valid"] == 1)])
        print(f"  vegetation/ground contrast of median |H|: {np.median(vm) / med[2]:.2f}")


for p in sys.argv[1:]:
    summary(p)
