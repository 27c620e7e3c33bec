// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the arguments read from Python objects: (N, 3) arrays of any layout, the
// cloud (the one copy of the input), the scale and the tile.

#ifndef PSC_PYTHON_INPUT_ARRAYS_H
#define PSC_PYTHON_INPUT_ARRAYS_H

#include "common.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstring>
#include <string>
#include <vector>

namespace psc_py {

namespace py = pybind11;

// The number of rows of an (N, 3) float32 or float64 array; throws a ValueError / TypeError
// naming `what` otherwise.
inline py::ssize_t checked_rows(const py::handle& h, const char* what)
{
  if(!py::isinstance<py::array>(h))
    throw py::type_error(std::string(what) + ": expected a numpy array of shape (N, 3)");
  const py::array a = py::reinterpret_borrow<py::array>(h);
  if(!py::isinstance<py::array_t<double> >(a) && !py::isinstance<py::array_t<float> >(a))
    throw py::type_error(std::string(what) + ": expected dtype float64 or float32 (native byte order), got " +
                         std::string(py::str(a.dtype())));
  if(a.ndim() != 2 || a.shape(1) != 3)
  {
    std::string shape = "(";
    for(py::ssize_t d = 0; d < a.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(what) + ": expected shape (N, 3), got " + shape);
  }
  return a.shape(0);
}

// Reads row i of an (N, 3) array of T with any strides (C, Fortran, non-contiguous views).
template <class T>
struct Row_reader
{
  const char* data;
  py::ssize_t s0, s1;
  explicit Row_reader(const py::array& a) : data(static_cast<const char*>(a.data())), s0(a.strides(0)), s1(a.strides(1))
  {}
  void operator()(py::ssize_t i, double out[3]) const
  {
    for(int c = 0; c < 3; ++c)
    {
      T v;
      std::memcpy(&v, data + i * s0 + c * s1, sizeof(T));
      out[c] = static_cast<double>(v);
    }
  }
};

template <class F>
void for_each_row(const py::array& a, const F& f)
{
  const py::ssize_t n = a.shape(0);
  if(py::isinstance<py::array_t<double> >(a))
  {
    const Row_reader<double> r(a);
    double x[3];
    for(py::ssize_t i = 0; i < n; ++i)
    {
      r(i, x);
      f(i, x);
    }
  }
  else
  {
    const Row_reader<float> r(a);
    double x[3];
    for(py::ssize_t i = 0; i < n; ++i)
    {
      r(i, x);
      f(i, x);
    }
  }
}

// The one copy of the input: positions and normals (zero normals if `normals` is None).
inline Cloud read_cloud(const py::handle& points, const py::handle& normals)
{
  const py::ssize_t n = checked_rows(points, "points");
  Cloud cloud(static_cast<std::size_t>(n), Oriented(K::Point_3(0, 0, 0), K::Vector_3(0, 0, 0)));
  for_each_row(py::reinterpret_borrow<py::array>(points),
               [&cloud](py::ssize_t i, const double* x) { cloud[i].first = K::Point_3(x[0], x[1], x[2]); });
  if(!normals.is_none())
  {
    const py::ssize_t m = checked_rows(normals, "normals");
    if(m != n)
      throw py::value_error("points and normals must have the same number of rows, got " + std::to_string(n) + " and " +
                            std::to_string(m));
    for_each_row(py::reinterpret_borrow<py::array>(normals),
                 [&cloud](py::ssize_t i, const double* x) { cloud[i].second = K::Vector_3(x[0], x[1], x[2]); });
  }
  return cloud;
}

inline Scale read_scale(const py::object& radius, const py::object& neighbors, bool automatic = false)
{
  Scale s;
  if(!radius.is_none() && !neighbors.is_none())
    throw py::value_error("give either radius or neighbors, not both");
  if(radius.is_none() && neighbors.is_none())
    throw py::value_error("give radius or neighbors");
  if(!radius.is_none())
    s.radius = radius.cast<double>();  // checked by the C++ function (positive and finite)
  else if(py::isinstance<py::str>(neighbors))
  {
    // "auto" (where `automatic`): the library's ladder, that of the tool's --neighbors auto
    if(!automatic || neighbors.cast<std::string>() != "auto")
      throw py::value_error("neighbors: expected a count" + std::string(automatic ? " or 'auto'" : ""));
    s.by_count = true;
    s.k = CGAL::Point_set_curvatures::automatic_scale_ladder::smallest;
    s.automatic_largest = CGAL::Point_set_curvatures::automatic_scale_ladder::largest;
  }
  else
  {
    const long long k = neighbors.cast<long long>();
    if(k < 1)
      throw py::value_error("neighbors must be at least 1, got " + std::to_string(k));
    s.by_count = true;
    s.k = static_cast<std::size_t>(k);
  }
  return s;
}

inline Tile_arg read_tile(const py::object& tile)
{
  Tile_arg t;
  if(tile.is_none())
    return t;
  const py::tuple tu = tile.cast<py::tuple>();
  if(tu.size() != 3)
    throw py::value_error("tile: expected (core_min, core_max, halo)");
  const auto lo = tu[0].cast<std::vector<double> >(), hi = tu[1].cast<std::vector<double> >();
  if(lo.size() != 3 || hi.size() != 3)
    throw py::value_error("tile: core_min and core_max must have 3 coordinates");
  t.has = true;
  t.tile =
    CGAL::Point_set_curvatures::Tile(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), tu[2].cast<double>());
  return t;
}

}  // namespace psc_py

#endif
