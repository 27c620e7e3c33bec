# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""point_set_curvatures.read_point_cloud: the package's readers (the tool's) from Python,
checked against independent parses of the files (numpy's text reader, the LAS header read
with struct) and on malformed files."""

import os
import struct
import subprocess

import numpy as np
import pytest

import point_set_curvatures as psc

DATA = os.environ.get("PSC_DATA_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def test_text_file_as_numpy_reads_it():
    path = os.path.join(DATA, "goursat_010000.xyz")
    expected = np.loadtxt(path)  # ('#' comments skipped)
    r = psc.read_point_cloud(path)
    assert r["points"].shape == (10000, 3) and r["points"].dtype == np.float64
    np.testing.assert_array_equal(r["points"], expected[:, :3])
    np.testing.assert_array_equal(r["normals"], expected[:, 3:])
    assert r["attributes"] == {} and r["warnings"] == []


def test_las_file_as_its_header_says():
    path = os.path.join(DATA, "real", "sample_c.las")
    with open(path, "rb") as f:
        header = f.read(375)
        minor = header[25]
        offset_to_points = struct.unpack_from("<I", header, 96)[0]
        record_length = struct.unpack_from("<H", header, 105)[0]
        count = struct.unpack_from("<I", header, 107)[0]
        if minor >= 4 and count == 0:
            count = struct.unpack_from("<Q", header, 247)[0]
        scale = struct.unpack_from("<3d", header, 131)
        offset = struct.unpack_from("<3d", header, 155)
        f.seek(offset_to_points)
        first = struct.unpack("<3i", f.read(12))
        f.seek(offset_to_points + (count - 1) * record_length)
        last = struct.unpack("<3i", f.read(12))
    r = psc.read_point_cloud(path)
    assert r["points"].shape == (count, 3) and r["normals"] is None
    for row, xyz in ((0, first), (count - 1, last)):
        np.testing.assert_allclose(r["points"][row], [xyz[a] * scale[a] + offset[a] for a in range(3)], rtol=0,
                                   atol=1e-9)
    a = r["attributes"]
    assert a["intensity"].dtype == np.uint16 and a["classification"].dtype == np.uint8
    assert len(a["gps_time"]) == count
    assert psc.read_point_cloud(path, attributes=False)["attributes"] == {}


def test_columns_and_attributes(tmp_path):
    rng = np.random.default_rng(3)
    p = rng.normal(size=(20, 3))
    n = p / np.linalg.norm(p, axis=1)[:, None]
    rgb = rng.integers(0, 255, size=(20, 3))
    path = tmp_path / "c.txt"
    np.savetxt(path, np.hstack([p, rgb, n]), fmt="%.17g")
    for columns in ("x,y,z,r,g,b,nx,ny,nz", ["x", "y", "z", "r", "g", "b", "nx", "ny", "nz"]):
        r = psc.read_point_cloud(path, columns=columns)
        np.testing.assert_array_equal(r["points"], p)
        np.testing.assert_array_equal(r["normals"], n)
        np.testing.assert_array_equal(r["attributes"]["g"], rgb[:, 1])
    skipped = psc.read_point_cloud(str(path).encode(), columns="x,y,z,_,_,_,nx,ny,nz")
    assert skipped["attributes"] == {}
    np.testing.assert_array_equal(skipped["normals"], n)


def test_bad_files_and_arguments(tmp_path):
    (tmp_path / "short.xyz").write_text("0 0 0\n1 0\n")
    with pytest.raises(ValueError, match="line 2"):
        psc.read_point_cloud(tmp_path / "short.xyz")
    (tmp_path / "c.laz").write_bytes(b"LASF")
    with pytest.raises(ValueError, match="laszip"):
        psc.read_point_cloud(tmp_path / "c.laz")
    with pytest.raises(FileNotFoundError):
        psc.read_point_cloud(tmp_path / "missing.ply")
    (tmp_path / "dir.ply").mkdir()
    with pytest.raises(ValueError, match="directory"):
        psc.read_point_cloud(tmp_path / "dir.ply")
    with pytest.raises(ValueError, match="--columns"):
        psc.read_point_cloud(tmp_path / "short.xyz", columns="x,y")
    with pytest.raises(psc.ArgumentTypeError):
        psc.read_point_cloud(3)
    with pytest.raises(psc.ArgumentTypeError):
        psc.read_point_cloud(tmp_path / "short.xyz", attributes="yes")


@pytest.mark.skipif(not os.environ.get("PSC_TOOL_EXE"), reason="the tool's path (PSC_TOOL_EXE) is not given")
def test_python_steps_give_the_tools_default_run(tmp_path):
    # A LAS file without normals: read, normals by the automatic scale oriented "auto", the
    # robust ASO by the automatic scale blended with the position fit: the tool's default run,
    # value for value (its CSV prints every double exactly).
    path = os.path.join(DATA, "real", "sample_c.las")
    out = tmp_path / "tool.csv"
    subprocess.run([os.environ["PSC_TOOL_EXE"], path, str(out), "--quiet", "--fields", "normal,mean,k_min,valid"],
                   check=True)
    tool = np.genfromtxt(out, delimiter=",", names=True)
    cloud = psc.read_point_cloud(path)
    normals = psc.estimate_normals(cloud["points"], neighbors="auto", orientation="auto")
    r = psc.estimate_curvatures(cloud["points"], normals, neighbors="auto", position_fit_blend=0.5)
    valid = r["status"] == psc.Status.VALID
    assert valid.sum() > 0.99 * len(valid)
    np.testing.assert_array_equal(tool["valid"], valid)
    for a, c in enumerate("xyz"):
        np.testing.assert_array_equal(tool["n" + c], r["normal"][:, a])
    np.testing.assert_array_equal(tool["mean"], r["mean"])
    np.testing.assert_array_equal(tool["k_min"], r["k_min"])


@pytest.mark.skipif(not os.environ.get("PSC_TOOL_EXE"), reason="the tool's path (PSC_TOOL_EXE) is not given")
def test_python_defaults_are_the_tools(tmp_path):
    # Positions only, no option on either side: estimate_curvatures(points) is the tool's
    # default run on a .xyz file, value for value (normals estimated with the automatic scale,
    # oriented "mst"; the robust ASO by the automatic scale with the position blend); and a
    # method without the automatic scale takes 40 neighbours in both. With noise of about a third
    # of the spacing, so that the automatic scale climbs (a clean surface stays at 40).
    points = np.loadtxt(os.path.join(DATA, "goursat_010000.xyz"))[:, :3]
    points = points + np.random.default_rng(5).normal(scale=0.1, size=points.shape)
    path = tmp_path / "positions.xyz"
    np.savetxt(path, points, fmt="%.17g")
    for method, options in (("aso", []), ("pss", ["--method", "pss"])):
        out = tmp_path / f"{method}.csv"
        subprocess.run([os.environ["PSC_TOOL_EXE"], str(path), str(out), "--quiet", "--fields",
                        "normal,mean,k_min,neighbors,valid"] + options, check=True)
        tool = np.genfromtxt(out, delimiter=",", names=True)
        with pytest.warns(UserWarning, match="no normals given: estimating them"):
            r = psc.estimate_curvatures(points, method=method)
        valid = r["status"] == psc.Status.VALID
        assert valid.sum() > 0.99 * len(valid), method
        np.testing.assert_array_equal(tool["valid"], valid)
        np.testing.assert_array_equal(tool["neighbors"], r["neighbors"])
        for a, c in enumerate("xyz"):
            np.testing.assert_array_equal(tool["n" + c], r["normal"][:, a])
        np.testing.assert_array_equal(tool["mean"], r["mean"])
        np.testing.assert_array_equal(tool["k_min"], r["k_min"])
        if method == "aso":
            assert (r["neighbors"][valid] >= 80).sum() > 0.5 * valid.sum()  # the automatic scale climbed
        else:
            # (a neighbour tied with the 40th, within 1e-6 of its distance, counts too: one point here)
            counts = r["neighbors"][valid]
            assert (counts >= psc.DEFAULT_NEIGHBORS).all()
            assert (counts != psc.DEFAULT_NEIGHBORS).sum() <= 2
