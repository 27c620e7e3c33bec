#!/usr/bin/env python3
# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Differential fuzzer of the tool's tiled runs (issue 30).

Each case is a small cloud written by this script in one of the tool's formats (.xyz, .csv,
.ply ASCII and binary, .off, .las), mutated the way adversarial files are (too few points for
the neighbourhood, outliers whose coordinates overflow the extent, a LAS scale near the
largest double, coincident, collinear and non-finite points, zero normals, a few bytes of the
file changed), with options drawn at random (method, scale by count or radius, estimated
normals and their orientation, output format and fields). The built tool runs it

  - whole (the cloud fits in memory) and with --threads 1 (twice for VCM): the same exit
    status and bytes (sequential == parallel; other processes, so that results depending on
    memory addresses differ, as VCM's did);
  - in tiles, with --memory-limit at two of several small limits: the same exit status and
    the same output bytes as the whole run (VCM, which the tiles refuse by design, may instead
    exit 2 with one line; so may --orient mst below the memory its gathered normals need, which
    is why its cases also get a limit that holds them).

Every run must exit 0, 2 (one line on stderr, no output file) or 3 (no valid estimate: the
output written, the reason on the last line of stderr) within --timeout seconds;
a run past it gets SIGTERM and must end within a second. The first failure stops the run
(exit status 1), leaving the case's input and commands in OUT/failure-N/.

  test/fuzz/fuzz_tiles.py --tool build/tools/point_set_curvatures [--cases 250] [--seed 1]
                          [--out build-fuzz/tiles] [--timeout 5] [--methods aso,vcm] [--keep-going]

The cases depend only on the seed: a failure is reproduced by the same command. Run on the
tool before the fixes of issue 30, the 250 cases of seed 1 find its three classes: tiled runs
exiting 1 ("the tile's halo inf is too small", and "0.2 too small; 0.2 suffices"), tiled runs
that hang and ignore SIGTERM (coordinates at 1e308), and VCM differing between two runs.
"""

import argparse
import math
import os
import random
import shutil
import signal
import struct
import subprocess
import sys
import time

# ---------------------------------------------------------------------------------------
# Clouds: lists of (x, y, z, nx, ny, nz)


def sphere(n, radius, centre):
    golden = math.pi * (3 - math.sqrt(5))
    pts = []
    for i in range(n):
        z = 1 - 2 * (i + 0.5) / n
        rho = math.sqrt(max(0.0, 1 - z * z))
        u = (rho * math.cos(golden * i), rho * math.sin(golden * i), z)
        pts.append([centre[k] + radius * u[k] for k in range(3)] + list(u))
    return pts


def terrain(n, rng, size):
    pts = []
    for _ in range(n):
        x, y = rng.uniform(0, size), rng.uniform(0, size)
        z = 0.1 * size * math.sin(3 * x / size) * math.cos(2 * y / size)
        g = (-0.3 * math.cos(3 * x / size) * math.cos(2 * y / size), 0.2 * math.sin(3 * x / size) * math.sin(2 * y / size), 1)
        length = math.sqrt(sum(c * c for c in g))
        pts.append([x, y, z] + [c / length for c in g])
    return pts


def line(n, spacing):
    return [[spacing * i, 0.0, 0.0, 0.0, 0.0, 1.0] for i in range(n)]


def clusters(n, rng, count, spread, distance):
    pts = []
    for i in range(n):
        c = i % count
        pts.append([c * distance + rng.gauss(0, spread), rng.gauss(0, spread), rng.gauss(0, spread), 0.0, 0.0, 1.0])
    return pts


def make_cloud(rng):
    n = rng.choice([1, 2, 3, 5, 8, 12, 19, 20, 39, 40, 41, 60, 80, 120, 200])
    shape = rng.choice(["sphere", "sphere", "terrain", "terrain", "line", "clusters"])
    if shape == "sphere":
        pts = sphere(n, rng.choice([0.5, 1.0, 2.0]), (rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)))
    elif shape == "terrain":
        pts = terrain(n, rng, rng.choice([1.0, 4.0]))
    elif shape == "line":
        pts = line(n, rng.choice([0.01, 0.1]))
    else:
        pts = clusters(n, rng, rng.choice([1, 2, 3]), rng.choice([0.0, 1e-3, 0.1]), rng.choice([0.5, 5.0]))
    mutations = []
    for _ in range(rng.choice([0, 0, 1, 1, 2, 3])):
        m = rng.choice(["overflow", "overflow", "far", "scale", "translate", "duplicate", "nonfinite", "normal",
                        "shuffle", "flat"])
        mutations.append(m)
        if m == "overflow":
            # two points whose distance is not a double (the extent overflows)
            axis = rng.randrange(3)
            big = rng.choice([1e308, 1.7e308, 9e307, 1.79e308])
            for sign in (-1, 1):
                p = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0]
                p[axis] = sign * big
                pts.insert(rng.randrange(len(pts) + 1), p)
        elif m == "far":
            p = list(rng.choice(pts)) if pts else [0.0] * 3 + [0.0, 0.0, 1.0]
            p[rng.randrange(3)] += rng.choice([1.0, -1.0]) * 10.0 ** rng.choice([1, 3, 30, 154, 155, 200, 300])
            pts.insert(rng.randrange(len(pts) + 1), p)
        elif m == "scale":
            s = 10.0 ** rng.choice([-300, -160, -100, -20, 20, 100, 150, 160, 300])
            pts = [[c * s for c in p[:3]] + p[3:] for p in pts]
        elif m == "translate":
            t = rng.choice([1e6, 1e15, -1e9])
            pts = [[c + t for c in p[:3]] + p[3:] for p in pts]
        elif m == "duplicate" and pts:
            for _ in range(rng.randint(1, 30)):
                pts.insert(rng.randrange(len(pts) + 1), list(rng.choice(pts)))
        elif m == "nonfinite" and pts:
            p = rng.choice(pts)
            p[rng.randrange(3)] = rng.choice([math.nan, math.inf, -math.inf])
        elif m == "normal" and pts:
            p = rng.choice(pts)
            p[3:] = rng.choice([[0.0, 0.0, 0.0], [1e-6, 0.0, 0.0], [math.nan, 0.0, 1.0], [1e9, 0.0, 0.0]])
        elif m == "shuffle":
            rng.shuffle(pts)
        elif m == "flat":
            pts = [p[:2] + [0.0] + p[3:] for p in pts]
    return pts, shape, mutations


# ---------------------------------------------------------------------------------------
# Files

def text_number(v):
    return repr(float(v)) if math.isfinite(v) else ("nan" if math.isnan(v) else ("inf" if v > 0 else "-inf"))


def write_text(pts, normals, form):
    lines = []
    if form == "csv":
        lines.append("x,y,z,nx,ny,nz" if normals else "x,y,z")
    for p in pts:
        values = p if normals else p[:3]
        lines.append((", " if form == "csv" else " ").join(text_number(v) for v in values))
    return ("\n".join(lines) + "\n").encode()


def write_off(pts, normals):
    head = ("NOFF" if normals else "OFF") + "\n%d 0 0\n" % len(pts)
    return (head + "".join(" ".join(text_number(v) for v in (p if normals else p[:3])) + "\n" for p in pts)).encode()


def write_ply(pts, normals, binary, attribute):
    names = ["x", "y", "z"] + (["nx", "ny", "nz"] if normals else [])
    head = "ply\nformat %s 1.0\nelement vertex %d\n" % ("binary_little_endian" if binary else "ascii", len(pts))
    head += "".join("property double %s\n" % name for name in names)
    if attribute:
        head += "property ushort intensity\n"
    head += "end_header\n"
    out = bytearray(head.encode())
    for i, p in enumerate(pts):
        values = p[:len(names)]
        if binary:
            out += struct.pack("<%dd" % len(values), *values)
            if attribute:
                out += struct.pack("<H", (37 * i) % 65536)
        else:
            out += (" ".join(text_number(v) for v in values) + (" %d" % ((37 * i) % 65536) if attribute else "") +
                    "\n").encode()
    return bytes(out)


LAS_RECORD = {0: 20, 1: 28, 4: 57}


def write_las(pts, rng):
    """LAS 1.2 (formats 0, 1) or 1.3 (format 4, with pulse directions from the origin, for
    --orient scanner); integer coordinates with a scale that is sometimes near the largest
    double (the coordinates then overflow the extent)."""
    fmt = rng.choice([0, 1, 4, 4])
    minor = 3 if fmt == 4 else 2
    header = 235 if minor == 3 else 227
    record = LAS_RECORD[fmt]
    huge = rng.random() < 0.25
    scale = [1.5e304 if huge and a == 0 else 1e-3 for a in range(3)]
    h = bytearray(header)
    h[0:4] = b"LASF"
    h[24], h[25] = 1, minor
    struct.pack_into("<H", h, 94, header)
    struct.pack_into("<I", h, 96, header)
    h[104] = fmt
    struct.pack_into("<H", h, 105, record)
    body = bytearray()
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    kept = 0
    for i, p in enumerate(pts):
        if not all(math.isfinite(c) for c in p[:3]):
            continue
        r = bytearray(record)
        for a in range(3):
            if huge and a == 0:
                q = rng.choice([-12000, -6000, 0, 6000, 12000]) if i % 10 == 0 else p[0] * 100
            else:
                q = p[a] / scale[a]
            q = int(round(q)) if abs(q) < 2 ** 31 - 1 else 0
            struct.pack_into("<i", r, 4 * a, q)
            v = q * scale[a]
            lo[a], hi[a] = min(lo[a], v), max(hi[a], v)
        struct.pack_into("<H", r, 12, (37 * i) % 65536)
        if fmt == 4:
            r[28] = 1
            struct.pack_into("<I", r, 37, 256)
            struct.pack_into("<f", r, 41, 1000.0)
            for a in range(3):
                v = p[a] * 1e-3
                struct.pack_into("<f", r, 45 + 4 * a, v if abs(v) < 1e30 else 0.0)
        body += r
        kept += 1
    struct.pack_into("<I", h, 107, kept)
    for a in range(3):
        struct.pack_into("<d", h, 131 + 8 * a, scale[a])
        struct.pack_into("<d", h, 155 + 8 * a, 0.0)
        struct.pack_into("<d", h, 179 + 16 * a, hi[a] if kept and math.isfinite(hi[a]) else 0.0)
        struct.pack_into("<d", h, 187 + 16 * a, lo[a] if kept and math.isfinite(lo[a]) else 0.0)
    return bytes(h + body), fmt


def mutate_bytes(data, rng):
    """A few bytes changed, inserted or removed (the file stays mostly valid)."""
    data = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        if not data:
            break
        at = rng.randrange(len(data))
        what = rng.randrange(3)
        if what == 0:
            data[at] = rng.randrange(256)
        elif what == 1:
            data[at:at] = bytes([rng.choice(b"0123456789-.e \n")])
        else:
            del data[at]
    return bytes(data)


# ---------------------------------------------------------------------------------------
# Cases

METHODS = ["aso", "aso", "aso", "apss", "jet", "wavejet", "pss", "pca_plane", "barycenter", "vcm", "vcm"]
LIMITS = ["100", "1K", "2K", "4K", "16K"]


def finite_extent(pts):
    finite = [p for p in pts if all(math.isfinite(c) and abs(c) < 1e100 for c in p[:3])]
    if not finite:
        return 1.0
    lo = [min(p[a] for p in finite) for a in range(3)]
    hi = [max(p[a] for p in finite) for a in range(3)]
    return max(hi[a] - lo[a] for a in range(3)) or 1.0


def make_case(rng, methods):
    """(input bytes, extension, output extension, options, memory limits, the limits that may be
    refused, description)"""
    pts, shape, mutations = make_cloud(rng)
    normals = rng.random() < 0.55
    form = rng.choice(["xyz", "csv", "ply", "plyb", "off", "las", "las"])
    if form == "las":
        data, las_format = write_las(pts, rng)
        normals = False
        extension = ".las"
    elif form in ("xyz", "csv"):
        data, extension = write_text(pts, normals, form), "." + form
    elif form == "off":
        data, extension = write_off(pts, normals), ".off"
    else:
        data, extension = write_ply(pts, normals, form == "plyb", rng.random() < 0.5), ".ply"
    if rng.random() < 0.15:
        data = mutate_bytes(data, rng)
        mutations.append("bytes")
    method = rng.choice(methods)
    options = ["--method", method]
    if method == "aso" and rng.random() < 0.3:
        options += ["--variant", "paper"]
    if rng.random() < 0.5:
        options += ["--neighbors", str(rng.choice([1, 2, 3, 5, 12, 20, 39, 40, 41, 100]))]
    else:
        extent = finite_extent(pts)
        radius = extent * rng.choice([0.02, 0.1, 0.3, 1.0, 3.0])
        options += ["--radius", repr(radius) if math.isfinite(radius) and radius > 0 else "0.3"]
    if rng.random() < 0.2:
        options += ["--min-neighbors", str(rng.choice([1, 3, 30]))]
    if not normals:
        choices = ["+z", "+z", "-x", "viewpoint:0,0,0", "mst"]
        if form == "las" and las_format == 4:
            choices += ["scanner", "scanner"]
        orient = rng.choice(choices)
        options += ["--orient", orient]
        if rng.random() < 0.6:
            options += ["--normal-neighbors", str(rng.choice([3, 6, 12, 40, 200]))]
    output = rng.choice([".ply", ".ply", ".csv"])
    if output == ".ply" and rng.random() < 0.3:
        options.append("--ascii")
    if rng.random() < 0.2:
        options.append("--float")
    if rng.random() < 0.2:
        options += ["--color", rng.choice(["mean", "k_max"])]
    if rng.random() < 0.2:
        options += ["--fields", "normal,mean,neighbors,valid"]
    limits = rng.sample(LIMITS, 2)
    # the limits at which the tiles may refuse (exit 2): VCM's, and the small ones of the
    # spanning tree, whose normals gathered from the tiles need about 448 bytes a point; its
    # cases also get a limit between that and what a run in memory counts (480 at least)
    if not normals and orient == "mst":
        limits = [str(int(len(pts) * rng.choice([455, 465, 475]))), limits[0]]
        refusable = {limits[1]}
    else:
        refusable = set()
    if method == "vcm":
        refusable = set(limits)
    what = "%s, %d points, %s%s, %s" % (shape, len(pts), extension, " with normals" if normals else "",
                                         "+".join(mutations) or "no mutation")
    return data, extension, output, options, limits, refusable, what


# ---------------------------------------------------------------------------------------
# Runs

class Outcome:
    def __init__(self, status, stderr, output, seconds, note=""):
        self.status, self.stderr, self.output, self.seconds, self.note = status, stderr, output, seconds, note


def run_tool(tool, args, output, timeout):
    if os.path.exists(output):
        os.remove(output)
    start = time.monotonic()
    process = subprocess.Popen([tool] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    note = ""
    try:
        _, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        process.send_signal(signal.SIGTERM)
        try:
            _, err = process.communicate(timeout=1.0)
            note = "ran past %g s (ended by SIGTERM)" % timeout
        except subprocess.TimeoutExpired:
            process.kill()
            _, err = process.communicate()
            note = "ran past %g s and did not answer SIGTERM within 1 s" % timeout
    seconds = time.monotonic() - start
    data = None
    if os.path.exists(output):
        with open(output, "rb") as f:
            data = f.read()
    return Outcome(process.returncode, err.decode(errors="replace"), data, seconds, note)


def contract_violation(o):
    """What is wrong with one run by itself, or None."""
    if o.note:
        return o.note
    if o.status not in (0, 2, 3):
        return "exit status %d: %s" % (o.status, o.stderr.strip()[-300:])
    if o.status == 3:
        # no valid estimate: the output written, the reason on the last line of stderr
        if not o.stderr.strip("\n").split("\n")[-1].startswith("point_set_curvatures: error: no valid estimate: "):
            return "exit 3 without its reason on the last line of stderr"
        if o.output is None:
            return "exit 3 without an output file"
    elif o.status == 2:
        lines = o.stderr.strip("\n").split("\n")
        if len(lines) != 1:
            return "exit 2 with %d lines on stderr" % len(lines)
        if o.output is not None:
            return "exit 2 left an output file"
    elif o.output is None:
        return "exit 0 without an output file"
    return None


def difference(a, b):
    """How run b differs from run a, or None."""
    if a.status != b.status:
        return "exit status %d against %d (%s)" % (b.status, a.status, (b.stderr or a.stderr).strip()[-300:])
    if a.output != b.output:
        if a.output is None or b.output is None:
            return "an output file in one run only"
        first = next((i for i in range(min(len(a.output), len(b.output))) if a.output[i] != b.output[i]),
                     min(len(a.output), len(b.output)))
        return "outputs differ from byte %d (%d and %d bytes)" % (first, len(a.output), len(b.output))
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tool", required=True, help="the built point_set_curvatures")
    parser.add_argument("--cases", type=int, default=250)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="build-fuzz/tiles")
    parser.add_argument("--timeout", type=float, default=5.0, help="seconds a run may take")
    parser.add_argument("--methods", default=",".join(METHODS), help="the methods drawn from (comma-separated)")
    parser.add_argument("--keep-going", action="store_true", help="report every failing case, not only the first")
    args = parser.parse_args()
    tool = os.path.abspath(args.tool)
    if not os.access(tool, os.X_OK):
        sys.exit("fuzz_tiles: no tool at %s: build the target point_set_curvatures_tool first" % tool)
    os.makedirs(args.out, exist_ok=True)
    out = os.path.abspath(args.out)
    rng = random.Random(args.seed)
    failures = 0
    runs = 0
    tiled_ok = 0
    start = time.monotonic()
    slowest = 0.0
    for case in range(args.cases):
        data, extension, output_ext, options, limits, refusable, what = make_case(rng, args.methods.split(","))
        path = os.path.join(out, "case" + extension)
        with open(path, "wb") as f:
            f.write(data)
        commands = []
        problems = []

        def run(name, extra):
            output = os.path.join(out, name + output_ext)
            command = [path, output] + options + extra
            commands.append(" ".join([tool] + command))
            o = run_tool(tool, command, output, args.timeout)
            problem = contract_violation(o)
            if problem:
                problems.append("%s: %s" % (name, problem))
            return o

        whole = run("whole", [])
        # other processes, other addresses: a result depending on them differs (VCM's did, one
        # run of three: twice for it)
        for _ in range(2 if "vcm" in options else 1):
            sequential = run("sequential", ["--threads", "1"])
            d = difference(whole, sequential)
            if d:
                problems.append("--threads 1 against the whole run: " + d)
            runs += 1
        for limit in limits:
            tiled = run("tiled_" + limit, ["--memory-limit", limit])
            d = difference(whole, tiled)
            if d and not (limit in refusable and tiled.status == 2 and not contract_violation(tiled)):
                problems.append("--memory-limit %s against the whole run: %s" % (limit, d))
            elif not d and tiled.status == 0:
                tiled_ok += 1
            slowest = max(slowest, tiled.seconds)
        runs += 1 + len(limits)
        slowest = max(slowest, whole.seconds, sequential.seconds)
        if problems:
            failures += 1
            keep = os.path.join(out, "failure-%d" % failures)
            os.makedirs(keep, exist_ok=True)
            shutil.copy(path, os.path.join(keep, "case" + extension))
            with open(os.path.join(keep, "commands.txt"), "w") as f:
                f.write("# seed %d, case %d: %s\n" % (args.seed, case, what))
                f.write("\n".join(problems) + "\n")
                f.write("\n".join(commands) + "\n")
            print("fuzz_tiles: case %d (%s; %s) failed:\n  %s\n  input and commands in %s" %
                  (case, what, " ".join(options), "\n  ".join(problems), keep), file=sys.stderr)
            if not args.keep_going:
                break
    seconds = time.monotonic() - start
    case = case + 1 if args.cases > 0 else 0
    print("fuzz_tiles: %d cases, %d runs in %.1f s (slowest run %.2f s), %d tiled runs matched a successful "
          "whole run; %s" % (case, runs, seconds, slowest, tiled_ok,
                             "%d failing cases" % failures if failures else "no failure"), file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
