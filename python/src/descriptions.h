// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the library's description of its estimators (estimators.h) as Python
// values.

#ifndef PSC_PYTHON_DESCRIPTIONS_H
#define PSC_PYTHON_DESCRIPTIONS_H

#include <CGAL/Point_set_curvatures/estimators.h>

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

namespace psc_py {

namespace py = pybind11;

// An estimator's description as a dict: name, function, summary, fields (a tuple of the
// result's keys it fills), min_neighbors, good_neighbors, paper_variant_good_neighbors,
// supports_tiles, supports_automatic_scale, options (dicts: name, values, default, choices).
inline py::dict estimator_to_dict(const CGAL::Point_set_curvatures::Estimator_description& e)
{
  namespace F = CGAL::Point_set_curvatures::estimate_fields;
  const std::pair<unsigned, const char*> keys[] = {
    {F::normal, "normal"}, {F::principal_curvatures, "k_min"}, {F::principal_curvatures, "k_max"},
    {F::mean_curvature, "mean"}, {F::gaussian_curvature, "gaussian"}, {F::normal_coherence, "normal_coherence"},
    {F::principal_directions, "min_direction"}, {F::principal_directions, "max_direction"}};
  py::list fields, options;
  for(const auto& k : keys)
    if(e.fields & k.first)
      fields.append(k.second);
  for(const CGAL::Point_set_curvatures::Estimator_option& o : e)
  {
    py::list choices;
    for(const char* c : o.choices)
      choices.append(c);
    py::dict d;
    d["name"] = o.name;
    d["values"] = o.values;
    d["default"] = o.default_value;
    d["choices"] = py::tuple(choices);
    options.append(d);
  }
  py::dict d;
  d["name"] = e.name;
  d["function"] = e.function;
  d["summary"] = e.summary;
  d["fields"] = py::tuple(fields);
  d["min_neighbors"] = e.min_neighbors;
  d["good_neighbors"] = e.good_neighbors;
  d["paper_variant_good_neighbors"] = e.paper_variant_good_neighbors;
  d["supports_tiles"] = e.supports_tiles;
  d["supports_automatic_scale"] = e.supports_automatic_scale;
  d["options"] = py::tuple(options);
  return d;
}

} // namespace psc_py

#endif
