// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the library's description of its estimators (estimators.h) and the names
// of its enumerations' values as Python values.

#ifndef PSC_PYTHON_DESCRIPTIONS_H
#define PSC_PYTHON_DESCRIPTIONS_H

#include <CGAL/Point_set_curvatures/estimators.h>

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

namespace psc_py {

namespace py = pybind11;

// The names of a range of C strings (the choices of an option, the names of an
// enumeration's values) as a tuple.
template <class Range>
py::tuple names_tuple(const Range& names)
{
  py::list l;
  for(const char* n : names)
    l.append(n);
  return py::tuple(l);
}

// Option -> the names of its values, indexed by the C++ enumerator's value.
inline py::dict enum_names_to_dict()
{
  namespace PSC = CGAL::Point_set_curvatures;
  py::dict enums;
  enums["aso_variant"] = names_tuple(PSC::aso_variant_names);
  enums["weight_kernel"] = names_tuple(PSC::weight_kernel_names);
  enums["sample_weights"] = names_tuple(PSC::sample_weights_names);
  enums["aso_projection"] = names_tuple(PSC::aso_projection_names);
  return enums;
}

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
    py::dict d;
    d["name"] = o.name;
    d["values"] = o.values;
    d["default"] = o.default_value;
    d["choices"] = names_tuple(o.choices);
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
