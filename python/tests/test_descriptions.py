# Copyright (c) 2026 The Point_set_curvatures authors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""The estimators' description, declared once in C++ (CGAL/Point_set_curvatures/estimators.h):
the package's method and option lists derive from it; the stubs, the docstrings and the user
manual's table of neighbour counts restate it and are checked against it here."""

import ast
import os
import re

import numpy as np
import pytest

import point_set_curvatures as psc
from conftest import fibonacci_sphere

PACKAGE = os.path.dirname(psc.__file__)
COMMON = {"min_neighbors", "accept_unnormalized_normals", "tile"}
# the options whose values are a C++ enumeration (py::enum_ of _core)
ENUMS = {"weight_kernel": psc.WeightKernel, "sample_weights": psc.SampleWeights, "aso_variant": psc.AsoVariant,
         "aso_projection": psc.AsoProjection}


def stub():
    """The parsed stub file of the package: the source's, else the installed one."""
    for d in (os.path.join(os.path.dirname(__file__), "..", "point_set_curvatures"), PACKAGE):
        p = os.path.join(d, "__init__.pyi")
        if os.path.exists(p):
            with open(p, encoding="utf-8") as f:
                return ast.parse(f.read())
    pytest.skip("__init__.pyi not found")


def literal_names(node):
    """The strings of every Literal[...] in an annotation."""
    return [n.value for n in ast.walk(node) if isinstance(n, ast.Constant) and isinstance(n.value, str)]


def stub_alias(tree, name):
    for n in tree.body:
        if isinstance(n, ast.Assign) and any(isinstance(t, ast.Name) and t.id == name for t in n.targets):
            return n.value
    raise AssertionError(f"no alias {name} in the stub")


def test_methods_and_options_are_the_library_description():
    assert psc.METHODS == ("aso", "apss", "barycenter", "pca_plane", "pss", "jet", "vcm", "wavejet")
    aso = psc.ESTIMATORS["aso"]
    assert aso["function"] == "estimate_aso_curvatures"
    assert (aso["min_neighbors"], aso["good_neighbors"], aso["paper_variant_good_neighbors"]) == (12, 12, 20)
    assert [o["name"] for o in aso["options"]][:2] == ["aso_variant", "weight_kernel"]
    assert psc.ESTIMATORS["jet"]["options"][0]["default"] == "2"
    assert psc.ESTIMATORS["apss"]["fields"] == ("normal", "mean", "normal_coherence")
    assert psc.AUTOMATIC_NEIGHBORS == (40, 640)
    assert [m for m in psc.METHODS if not psc.ESTIMATORS[m]["supports_tiles"]] == ["vcm"]
    assert [m for m in psc.METHODS if psc.ESTIMATORS[m]["supports_automatic_scale"]] == ["aso"]
    points, normals = fibonacci_sphere(200)
    with pytest.raises(ValueError, match="does not apply"):
        psc.estimate_curvatures(points, normals, method="vcm", neighbors=20, tile=((0, 0, 0), (1, 1, 1), 1.0))
    with pytest.raises(ValueError, match="'aso'"):
        psc.estimate_curvatures(points, normals, method="jet", neighbors="auto")
    with pytest.raises(TypeError):
        psc.ESTIMATORS["new"] = {}  # read-only, all the way down
    with pytest.raises(TypeError):
        psc.ESTIMATORS["aso"]["min_neighbors"] = 3
    with pytest.raises(TypeError):
        psc.ESTIMATORS["aso"]["options"][0]["default"] = "paper"


def test_enumerations_are_the_options_choices():
    # The py::enum_ of each option: its members are the option's choices in the library's
    # order, with the C++ enumerators' values, and a member is accepted where its name is.
    for name, e in psc.ESTIMATORS.items():
        for o in e["options"]:
            if o["name"] in ENUMS:
                members = ENUMS[o["name"]].__members__
                assert tuple(sorted(o["choices"])) == tuple(sorted(n.lower() for n in members)), o["name"]
    assert [int(v) for v in psc.AsoVariant.__members__.values()] == [0, 1]
    assert list(psc.WeightKernel.__members__) == ["SMOOTH", "CONSTANT", "SMOOTH_CUBIC", "SMOOTH_QUARTIC"]
    points, normals = fibonacci_sphere(300, radius=2.0)
    by_name = psc.estimate_curvatures(points, normals, neighbors=30, aso_variant="paper", weight_kernel="smooth_quartic",
                                      sample_weights="tangent_voronoi_area", aso_projection="authors_implementation")
    by_member = psc.estimate_curvatures(points, normals, neighbors=30, aso_variant=psc.AsoVariant.PAPER,
                                        weight_kernel=psc.WeightKernel.SMOOTH_QUARTIC,
                                        sample_weights=psc.SampleWeights.TANGENT_VORONOI_AREA,
                                        aso_projection=psc.AsoProjection.AUTHORS_IMPLEMENTATION)
    robust = psc.estimate_curvatures(points, normals, neighbors=30)
    np.testing.assert_array_equal(by_name["mean"], by_member["mean"])
    assert not np.array_equal(by_name["mean"], robust["mean"])
    with pytest.raises(ValueError, match="aso_variant"):
        psc.estimate_curvatures(points, normals, neighbors=30, aso_variant=psc.WeightKernel.SMOOTH)
    with pytest.raises(ValueError, match="aso_variant"):
        psc.estimate_curvatures(points, normals, neighbors=30, aso_variant=1)


def test_stubs_restate_the_description():
    tree = stub()
    assert literal_names(stub_alias(tree, "Method")) == list(psc.METHODS)
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    for enum in ENUMS.values():
        name = enum.__name__
        assert literal_names(stub_alias(tree, name + "Name")) == [n.lower() for n in enum.__members__], name
        assert [a.target.id for a in classes[name].body if isinstance(a, ast.AnnAssign)] == list(enum.__members__)
    functions = {n.name: n for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)}
    keywords = {a.arg for a in functions["estimate_curvatures"].args.kwonlyargs}
    options = {o["name"] for e in psc.ESTIMATORS.values() for o in e["options"]}
    assert COMMON | options <= keywords
    # every weight_kernel takes every kernel (the ASO refuses "constant" at run time)
    for f in functions.values():
        for a in f.args.args + f.args.kwonlyargs:
            if a.arg == "weight_kernel":
                assert "WeightKernel" in ast.unparse(a.annotation), f.name


def method_bullets(doc):
    """The docstring's option bullets: method name -> its text ("- ``"aso"``: ...")."""
    bullets = {}
    for m in re.finditer(r'- ``"(\w+)"``: (.*?)(?=\n\s*- |\n\s*\n)', doc, re.S):
        bullets[m.group(1)] = m.group(2)
    return bullets


def test_every_option_is_documented_and_accepted():
    bullets = method_bullets(psc.estimate_curvatures.__doc__)
    points, normals = fibonacci_sphere(400, radius=2.0)
    samples = {"bool": True, "count": 2, "real in [0, 1]": 0.5, "positive real": 0.5}
    for name, e in psc.ESTIMATORS.items():
        for o in e["options"]:
            assert f"``{o['name']}``" in bullets[name], (name, o["name"])
            values = o["choices"] or (samples[o["values"]],)
            for v in values:
                try:
                    r = psc.estimate_curvatures(points, normals, method=name, neighbors=30, **{o["name"]: v})
                except ValueError as error:  # refused by the estimator (the ASO's constant kernel), not by name
                    assert "option" not in str(error) and (name, v) == ("aso", "constant"), str(error)
                    continue
                assert np.count_nonzero(r["status"] == psc.Status.VALID) > 300, (name, o["name"], v)
        others = set().union(*psc._METHOD_OPTIONS.values()) - {o["name"] for o in e["options"]}
        for other in sorted(others):
            with pytest.raises(ValueError, match="does not apply"):
                psc.estimate_curvatures(points, normals, method=name, neighbors=30, **{other: 1})


def test_docstring_states_every_default_of_the_description():
    # Each option's text in the docstring (up to the next option) gives its default: the
    # description's value, or for the ASO's variant-dependent ones "default per variant",
    # whose values are then listed per variant in the description's order.
    bullets = method_bullets(psc.estimate_curvatures.__doc__)
    spelled = {"true": "True", "false": "False"}
    for name, e in psc.ESTIMATORS.items():
        if not e["options"]:
            continue
        text = " ".join(bullets[name].split())
        names = [o["name"] for o in e["options"]]
        for k, o in enumerate(e["options"]):
            start = text.index(f"``{o['name']}``")
            later = [text.index(f"``{n}``", start) for n in names[k + 1:] if f"``{n}``" in text[start:]]
            segment = text[start:min(later, default=len(text))]
            default = o["default"]
            if default.startswith("the variant's: "):
                assert "default per variant" in segment, (name, o["name"])
                expected = re.fullmatch(r"the variant's: (\S+) \(paper: (\S+)\)", default).groups()
                listed = re.search(r"the robust variant's defaults are (.*?), the paper's (.*?);", text)
                assert listed, name
                by_variant = [[v.strip("`\" ") for v in group.split(",")] for group in listed.groups()]
                index = [p["name"] for p in e["options"] if p["default"].startswith("the variant's")].index(o["name"])
                for values, value in zip(by_variant, expected):
                    assert values[index] == spelled.get(value, value), (name, o["name"], values)
                continue
            assert "default" in segment, (name, o["name"])
            if default.startswith("the radius"):
                assert "default the radius" in segment
            else:
                value = spelled.get(default, default)
                stated = ((f'default ``"{value}"``', f'``"{value}"`` default') if o["choices"] else
                          (f"default {value}",))
                assert any(s in segment for s in stated), (name, o["name"], segment)


def test_results_fill_the_declared_fields():
    points, normals = fibonacci_sphere(1000, radius=2.0)
    for name, e in psc.ESTIMATORS.items():
        r = psc.estimate_curvatures(points, normals, method=name, neighbors=30)
        valid = r["status"] == psc.Status.VALID
        assert valid.all(), name
        # (the estimators' real fields of the table: NaN where an estimator does not fill them)
        for key in (f["key"] for f in psc._core.fields() if f["dtype"] == "<f8" and not f["automatic_scale_only"]):
            filled = np.isfinite(r[key][valid]).all()
            empty = np.isnan(r[key][valid]).all()
            assert (filled, empty) == ((True, False) if key in e["fields"] else (False, True)), (name, key)


def test_results_are_the_table_of_fields():
    """The result's arrays, and Dask's records, are the package's table of fields
    (CGAL/Point_set_curvatures/field_descriptions.h), in its order, with its types."""
    import point_set_curvatures.dask as pdask
    fields = psc._core.fields()
    points, normals = fibonacci_sphere(500, radius=2.0)
    for neighbors in (30, "auto"):
        r = psc.estimate_curvatures(points, normals, method="aso", neighbors=neighbors)
        expected = [f for f in fields if neighbors == "auto" or not f["automatic_scale_only"]]
        assert list(r) == [f["key"] for f in expected], neighbors
        for f in expected:
            assert r[f["key"]].dtype == np.dtype(f["dtype"]), f["key"]
            assert r[f["key"]].shape == (len(points),) + tuple(f["shape"]), f["key"]
        dtype = pdask.AUTOMATIC_RESULT_DTYPE if neighbors == "auto" else pdask.RESULT_DTYPE
        assert list(dtype.names) == list(r), neighbors
    assert np.allclose(r["mean"], 0.5, atol=0.02)  # (a sphere of radius 2, outward normals)


def test_manual_table_of_neighbour_counts_is_the_description():
    path = os.path.join(os.path.dirname(__file__), "..", "..", "doc", "user_manual.md")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    section = text[text.index("{#psc_min_neighbors}"):]
    rows = {}
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| ") and len(cells) == 7 and re.fullmatch(r"\d+", cells[-1]):
            rows[cells[0]] = (int(cells[-2]), int(cells[-1]))
    labels = {"ASO (default variant)": "aso", "APSS, sphere features": "apss", "jets (CGAL)": "jet",
              "wavejets": "wavejet", "PSS": "pss", "PCA plane": "pca_plane", "barycenter": "barycenter",
              "VCM (CGAL)": "vcm"}
    assert set(rows) == set(labels) | {"ASO (paper's variant)"}
    for label, name in labels.items():
        e = psc.ESTIMATORS[name]
        assert rows[label] == (e["min_neighbors"], e["good_neighbors"]), label
    aso = psc.ESTIMATORS["aso"]
    assert rows["ASO (paper's variant)"] == (aso["min_neighbors"], aso["paper_variant_good_neighbors"])


def test_manual_table_of_quantities_is_the_description():
    # Section 9's table says what each baseline estimates; the fields it fills are the
    # description's.
    path = os.path.join(os.path.dirname(__file__), "..", "..", "doc", "user_manual.md")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    section = text[text.index("{#psc_baselines}"):text.index("{#psc_features}")]
    tensor = {"normal", "k_min", "k_max", "mean", "gaussian", "min_direction", "max_direction"}
    words = {r"\f$\vert H \vert\f$": {"mean"}, "normal": {"normal"}, "full tensor": tensor,
             r"\f$\vert k_{\min} \vert\f$": {"k_min"}, r"\f$\vert k_{\max} \vert\f$": {"k_max"},
             "directions": {"min_direction", "max_direction"}}
    by_function = {e["function"]: name for name, e in psc.ESTIMATORS.items()}
    rows = {}
    for line in section.splitlines():
        m = re.match(r"\| `CGAL::(\w+)\(\)` \| (.*?) \|", line)
        if m:
            rows[by_function[m.group(1)]] = set().union(*(words[w.strip()] for w in m.group(2).split(", ")))
    assert set(rows) == set(psc.METHODS) - {"aso", "apss"}
    for name, fields in rows.items():
        assert fields == set(psc.ESTIMATORS[name]["fields"]), name
