#!/usr/bin/env python3
# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
#
# Curvature errors on a Goursat cloud of data/ against the analytic surface
#   F(x) = -8 - 2 |x|^2 + 0.03 (x^4 + y^4 + z^4) = 0   (grad F points outwards),
# for the outputs of the package's tool (CSV with a header: mean, gaussian, valid) and of
# CloudCompare (ASCII "x y z value ..." from -CURV MEAN or GAUSS, in input order).
#
#   goursat_errors.py INPUT.xyz LABEL=FILE[:KIND] ...
#
# KIND is "tool" (default), "cc_mean" or "cc_gauss". Prints one Markdown row per LABEL:
# the mean |H - H*| and | |H| - |H*| | (x1e-3), the same for K (x1e-3), and the valid points.
# Unsigned errors compare with estimators that give no sign (CloudCompare's curvatures are
# magnitudes). Needs numpy (python3-numpy).

import csv
import sys

import numpy as np


def rows_of(path):
    """The numeric rows of a whitespace- or comma-separated file, comment lines skipped."""
    rows = []
    with open(path) as f:
        for line in f:
            if not line.strip() or line[0] in "#/":
                continue
            rows.append([float(v) for v in line.replace(",", " ").split()])
    return np.array(rows)


def goursat_curvatures(points):
    """H and K of the Goursat surface at points on it (sign: positive where the surface
    bends away from the outward normal, so a sphere has H = 1/R)."""
    x = points.T
    g = -4.0 * x + 0.12 * x**3  # grad F
    h = -4.0 + 0.36 * x**2  # the Hessian of F is diagonal
    gg = (g * g).sum(0)
    mean = (gg * h.sum(0) - (g * g * h).sum(0)) / (2.0 * gg**1.5)
    gauss = (h[0] * h[1] * g[2] ** 2 + h[0] * h[2] * g[1] ** 2 + h[1] * h[2] * g[0] ** 2) / gg**2
    return mean, gauss


def tool_output(path):
    with open(path) as f:
        reader = csv.reader(f)
        head = next(reader)
        data = np.array([[float(v) if v not in ("", "nan") else np.nan for v in row] for row in reader])
    valid = data[:, head.index("valid")] > 0
    return data[:, head.index("mean")], data[:, head.index("gaussian")], valid


def main(argv):
    if len(argv) < 3:
        sys.stderr.write("usage: goursat_errors.py INPUT.xyz LABEL=FILE[:KIND] ...\n")
        return 2
    points = rows_of(argv[1])[:, :3]
    H, K = goursat_curvatures(points)
    print("| estimator | mean \\|H - H*\\| | mean \\| \\|H\\| - \\|H*\\| \\| | mean \\|K - K*\\| "
          "| mean \\| \\|K\\| - \\|K*\\| \\| | valid |")
    print("|---|---|---|---|---|---|")
    cc = {}
    for spec in argv[2:]:
        label, rest = spec.split("=", 1)
        path, _, kind = rest.partition(":")
        kind = kind or "tool"
        if kind == "tool":
            mean, gauss, valid = tool_output(path)
        else:
            values = rows_of(path)
            if values.shape[0] != len(H) or np.max(np.abs(values[:, :3] - points)) > 1e-4:
                raise SystemExit(f"{path}: not the points of {argv[1]} in the same order")
            entry = cc.setdefault(label, [np.full(len(H), np.nan), np.full(len(H), np.nan)])
            entry[0 if kind == "cc_mean" else 1] = values[:, 3]
            if np.isnan(entry[0]).all() or np.isnan(entry[1]).all():
                continue  # print when both quantities are read
            mean, gauss = entry
            valid = np.isfinite(mean) & np.isfinite(gauss)

        def err(est, truth, unsigned):
            e = np.abs(np.abs(est) - np.abs(truth)) if unsigned else np.abs(est - truth)
            return 1e3 * np.mean(e[valid])

        print(f"| {label} | {err(mean, H, False):.2f} | {err(mean, H, True):.2f} | {err(gauss, K, False):.2f} "
              f"| {err(gauss, K, True):.2f} | {valid.sum()} of {len(H)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
