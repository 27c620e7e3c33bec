// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: results as numpy arrays (estimates, sphere features).

#ifndef PSC_PYTHON_OUTPUT_ARRAYS_H
#define PSC_PYTHON_OUTPUT_ARRAYS_H

#include "common.h"
#include "features.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <CGAL/Point_set_curvatures/field_descriptions.h>

#include <cstdint>
#include <vector>

namespace psc_py {

namespace py = pybind11;

template <class T>
py::array_t<T> array_1(std::size_t n)
{
  return py::array_t<T>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)});
}

inline py::array_t<double> array_n3(std::size_t n)
{
  return py::array_t<double>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), 3});
}

template <class V>
void put3(double* out, std::size_t i, const V& v)
{
  out[3 * i] = CGAL::to_double(v.x());
  out[3 * i + 1] = CGAL::to_double(v.y());
  out[3 * i + 2] = CGAL::to_double(v.z());
}

// The numpy type of a field's values: doubles, int64 counts, uint8 flags.
inline const char* numpy_type(CGAL::Point_set_curvatures::Field_type type)
{
  using CGAL::Point_set_curvatures::Field_type;
  return type == Field_type::COUNT ? "<i8" : type == Field_type::FLAG ? "u1" : "<f8";
}

// The estimates as the arrays of the fields' table (CGAL::Point_set_curvatures::field_descriptions,
// the rows with a Python key, in its order, of numpy_type()): (N, 3) for a vector's components,
// N otherwise; mean_error only `with_mean_error`. One pass over the estimates.
inline py::dict estimates_to_dict(const std::vector<Estimate>& e, bool with_mean_error)
{
  namespace PSC = CGAL::Point_set_curvatures;
  const std::size_t n = e.size();
  // each field's column: where its values go (one of the three) and their stride
  struct Column
  {
    const PSC::Field_description* field;
    double* real = nullptr;
    std::int64_t* count = nullptr;
    std::uint8_t* flag = nullptr;
    std::size_t stride = 1;
  };
  std::vector<Column> columns;
  py::dict d;
  char* data = nullptr;  // the array of the field (a vector's: of its first component)
  for(const PSC::Field_description& f : PSC::field_descriptions)
  {
    if(!f.python_key || (f.automatic_scale_only && !with_mean_error))
      continue;
    if(f.component <= 0)
    {
      std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)};
      if(f.component == 0)
        shape.push_back(3);
      py::array a(py::dtype(numpy_type(f.type)), shape);
      data = static_cast<char*>(a.mutable_data());
      d[f.python_key] = a;
    }
    Column c{&f};
    if(f.type == PSC::Field_type::COUNT)
      c.count = reinterpret_cast<std::int64_t*>(data);
    else if(f.type == PSC::Field_type::FLAG)
      c.flag = reinterpret_cast<std::uint8_t*>(data);
    else
    {
      c.real = reinterpret_cast<double*>(data) + (f.component > 0 ? f.component : 0);
      c.stride = f.component >= 0 ? 3 : 1;
    }
    columns.push_back(c);
  }
  {
    py::gil_scoped_release release;
    for(std::size_t i = 0; i < n; ++i)
      for(const Column& c : columns)
      {
        const double v = PSC::field_value(e[i], *c.field);
        if(c.real)
          c.real[c.stride * i] = v;
        else if(c.count)
          c.count[i] = static_cast<std::int64_t>(v);
        else
          c.flag[i] = static_cast<std::uint8_t>(v);
      }
  }
  return d;
}

// The fields' table as the Python module gives it (fields()): per Python key, in the table's
// order, a dict with its numpy type (numpy_type()), its shape per point ((3,) for a vector, ()
// otherwise) and whether it comes with the automatic scale only.
inline py::tuple fields_to_tuple()
{
  namespace PSC = CGAL::Point_set_curvatures;
  py::list fields;
  for(const PSC::Field_description& f : PSC::field_descriptions)
  {
    if(!f.python_key || f.component > 0)
      continue;
    py::dict d;
    d["key"] = f.python_key;
    d["dtype"] = numpy_type(f.type);
    d["shape"] = f.component == 0 ? py::make_tuple(3) : py::make_tuple();
    d["automatic_scale_only"] = f.automatic_scale_only;
    fields.append(d);
  }
  return py::tuple(fields);
}

// Features of `scales` x `n` points: arrays of shape (n, ...) if `flat`, else (scales, n, ...).
inline py::dict features_to_dict(const std::vector<const std::vector<Features>*>& scales, bool flat)
{
  const std::size_t s = scales.size(), n = scales.empty() ? 0 : scales[0]->size();
  auto shape = [&](bool vec) {
    std::vector<py::ssize_t> sh;
    if(!flat)
      sh.push_back(static_cast<py::ssize_t>(s));
    sh.push_back(static_cast<py::ssize_t>(n));
    if(vec)
      sh.push_back(3);
    return sh;
  };
  py::dict d;
  auto scalar = [&](const char* name, auto get) {
    py::array_t<double> a(shape(false));
    double* p = a.mutable_data();
    for(std::size_t k = 0; k < s; ++k)
      for(std::size_t i = 0; i < n; ++i)
        p[k * n + i] = CGAL::to_double(get((*scales[k])[i]));
    d[name] = a;
  };
  auto vector = [&](const char* name, auto get) {
    py::array_t<double> a(shape(true));
    double* p = a.mutable_data();
    for(std::size_t k = 0; k < s; ++k)
      for(std::size_t i = 0; i < n; ++i)
        put3(p + 3 * k * n, i, get((*scales[k])[i]));
    d[name] = a;
  };
  scalar("u_c", [](const Features& f) { return f.u_c; });
  vector("u_l", [](const Features& f) { return f.u_l; });
  scalar("u_q", [](const Features& f) { return f.u_q; });
  scalar("pratt_norm", [](const Features& f) { return f.pratt_norm; });
  scalar("anisotropy", [](const Features& f) { return f.anisotropy; });
  vector("normal", [](const Features& f) { return f.normal; });
  scalar("mean", [](const Features& f) { return f.mean_curvature; });
  scalar("geometric_variation", [](const Features& f) { return f.geometric_variation; });
  scalar("d_u_c_dr", [](const Features& f) { return f.d_u_c_dr; });
  vector("d_normal_dr", [](const Features& f) { return f.d_normal_dr; });
  scalar("d_mean_dr", [](const Features& f) { return f.d_mean_curvature_dr; });
  vector("center", [](const Features& f) { return f.center; });
  scalar("sphere_radius", [](const Features& f) { return f.sphere_radius; });
  vector("projection", [](const Features& f) { return f.projection; });
  scalar("kernel_radius", [](const Features& f) { return f.kernel_radius; });
  py::array_t<bool> plane(shape(false));
  py::array_t<std::int64_t> count(shape(false));
  py::array_t<std::uint8_t> status(shape(false));
  bool* pp = plane.mutable_data();
  std::int64_t* pc = count.mutable_data();
  std::uint8_t* ps = status.mutable_data();
  for(std::size_t k = 0; k < s; ++k)
    for(std::size_t i = 0; i < n; ++i)
    {
      const Features& f = (*scales[k])[i];
      pp[k * n + i] = f.is_plane;
      pc[k * n + i] = static_cast<std::int64_t>(f.neighbor_count);
      ps[k * n + i] = static_cast<std::uint8_t>(f.status);
    }
  d["is_plane"] = plane;
  d["neighbors"] = count;
  d["status"] = status;
  return d;
}

}  // namespace psc_py

#endif
