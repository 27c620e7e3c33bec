// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the library's description of its estimators (estimators.h) and its
// enumerations (py::enum_, named from the library's name tables).

#ifndef PSC_PYTHON_DESCRIPTIONS_H
#define PSC_PYTHON_DESCRIPTIONS_H

#include <CGAL/Point_set_curvatures/estimators.h>
#include <CGAL/Point_set_curvatures/field_descriptions.h>

#include <pybind11/pybind11.h>

#include <cctype>
#include <cstddef>
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

// The library's enumeration E as a py::enum_ of `m` named `python_name`, its values those of
// the library's name table `names` (indexed by the enumerator's value) in upper case: the
// Python options' names and values are these (point_set_curvatures/__init__.py), so that
// a string and an enumeration value name the same enumerator.
template <class E, std::size_t N>
void export_enum(py::module_& m, const char* python_name, const char* const (&names)[N], const char* doc)
{
  py::enum_<E> e(m, python_name, doc);
  for(std::size_t i = 0; i < N; ++i)
  {
    std::string upper = names[i];
    for(char& c : upper)
      c = char(std::toupper(static_cast<unsigned char>(c)));
    e.value(upper.c_str(), static_cast<E>(i));
  }
}

// The enumerations of the estimators' options: AsoVariant, WeightKernel, SampleWeights,
// AsoProjection.
inline void export_enums(py::module_& m)
{
  namespace PSC = CGAL::Point_set_curvatures;
  export_enum<CGAL::Aso_variant>(m, "AsoVariant", PSC::aso_variant_names,
                                 "The ASO's variants (CGAL::Aso_variant): option aso_variant.");
  export_enum<CGAL::Apss_weight_kernel>(m, "WeightKernel", PSC::weight_kernel_names,
                                        "The weight kernels (CGAL::Apss_weight_kernel): option weight_kernel.");
  export_enum<CGAL::Sample_weights>(m, "SampleWeights", PSC::sample_weights_names,
                                    "The sample weights (CGAL::Sample_weights): option sample_weights.");
  export_enum<CGAL::Aso_projection>(m, "AsoProjection", PSC::aso_projection_names,
                                    "The ASO's projections (CGAL::Aso_projection): option aso_projection.");
}

// An estimator's description as a dict: name, function, summary, fields (a tuple of the
// result's keys it fills), min_neighbors, good_neighbors, paper_variant_good_neighbors,
// supports_tiles, supports_automatic_scale, options (dicts: name, values, default, choices).
inline py::dict estimator_to_dict(const CGAL::Point_set_curvatures::Estimator_description& e)
{
  py::list fields, options;
  // the keys of the fields' table that the estimator fills (a vector once)
  for(const CGAL::Point_set_curvatures::Field_description& f : CGAL::Point_set_curvatures::field_descriptions)
    if(f.python_key && f.component <= 0 && (e.fields & f.filled_by))
      fields.append(f.python_key);
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

}  // namespace psc_py

#endif
