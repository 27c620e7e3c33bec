// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the normals of a cloud estimated tile by tile (the Dask file route on
// clouds without normals), in the two steps of CGAL::estimate_oriented_normals(): each tile's
// records (unoriented normal, nearest neighbours), then their orientation over the records of
// every tile gathered, as the tool does for files larger than its memory limit.

#ifndef POINT_SET_CURVATURES_PYTHON_NORMAL_RECORDS_H
#define POINT_SET_CURVATURES_PYTHON_NORMAL_RECORDS_H

#include "features.h"
#include "input_arrays.h"
#include "output_arrays.h"
#include "run.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

namespace psc_py {

namespace py = pybind11;

constexpr std::size_t record_degree = CGAL::Point_set_curvatures::internal::normal_graph_degree;

// The records of `points` (of the tile's own points with a tile): (normal (n, 3) float64,
// neighbor (n, record_degree) uint32, the rows' indices, zero past degree, degree (n,) uint8,
// status (n,) uint8). fit: 0 plane, 1 quadric.
inline py::tuple normal_records_py(const py::handle& points, const py::object& radius, const py::object& neighbors,
                                   int fit, const py::object& tile, long long threads, const py::object& progress)
{
  const Scale scale = read_scale(radius, neighbors, true);
  const Tile_arg t = read_tile(tile);
  Cloud cloud = read_cloud(points, py::none());
  std::vector<Normal_record> records;
  run([&](bool parallel, const Callback& cb) { records = normal_records(cloud, scale, fit, t, parallel, cb); },
      progress, threads);
  const std::size_t n = records.size();
  auto normal = array_n3(n);
  py::array_t<std::uint32_t> neighbor(std::vector<py::ssize_t>{py::ssize_t(n), py::ssize_t(record_degree)});
  auto degree = array_1<std::uint8_t>(n), status = array_1<std::uint8_t>(n);
  double* pn = normal.mutable_data();
  std::uint32_t* pe = neighbor.mutable_data();
  std::uint8_t *pd = degree.mutable_data(), *ps = status.mutable_data();
  for(std::size_t i = 0; i < n; ++i)
  {
    const Normal_record& r = records[i];
    for(int a = 0; a < 3; ++a)
      pn[3 * i + a] = r.normal[a];
    for(std::size_t e = 0; e < record_degree; ++e)
      pe[record_degree * i + e] = e < r.degree ? r.neighbor[e] : 0;
    pd[i] = r.degree;
    ps[i] = static_cast<std::uint8_t>(r.status);
  }
  return py::make_tuple(normal, neighbor, degree, status);
}

// The unit normals (n, 3) of the records gathered from every tile (neighbours as indices of
// the whole cloud) oriented as `orientation` says (0 spanning tree, 1 along `target`, 2
// towards it, 3 automatic), `xyz` the points; zero where a record is not VALID.
inline py::array_t<double> orient_normal_records_py(const py::handle& normal, const py::handle& neighbor,
                                                    const py::handle& degree, const py::handle& status,
                                                    const py::handle& xyz, int orientation,
                                                    const std::vector<double>& target, long long threads,
                                                    const py::object& progress)
{
  constexpr int c = py::array::c_style | py::array::forcecast;
  const auto pn = py::array_t<double, c>::ensure(normal);
  const auto pe = py::array_t<std::uint32_t, c>::ensure(neighbor);
  const auto pd = py::array_t<std::uint8_t, c>::ensure(degree);
  const auto ps = py::array_t<std::uint8_t, c>::ensure(status);
  const auto px = py::array_t<double, c>::ensure(xyz);
  if(!pn || !pe || !pd || !ps || !px || target.size() != 3)
    throw py::value_error("orient_normal_records: arrays of numbers and a target of 3 coordinates expected");
  const py::ssize_t n = pn.ndim() == 2 ? pn.shape(0) : -1;
  if(n < 0 || pn.shape(1) != 3 || pe.ndim() != 2 || pe.shape(0) != n || pe.shape(1) != py::ssize_t(record_degree) ||
     pd.ndim() != 1 || pd.shape(0) != n || ps.ndim() != 1 || ps.shape(0) != n || px.ndim() != 2 || px.shape(0) != n ||
     px.shape(1) != 3)
    throw py::value_error("orient_normal_records: expected normal (N, 3), neighbor (N, " +
                          std::to_string(record_degree) + "), degree (N,), status (N,) and xyz (N, 3)");
  std::vector<Normal_record> records(static_cast<std::size_t>(n));
  for(py::ssize_t i = 0; i < n; ++i)
  {
    Normal_record& r = records[std::size_t(i)];
    for(int a = 0; a < 3; ++a)
      r.normal[a] = pn.at(i, a);
    r.degree = pd.at(i);
    if(r.degree > record_degree)
      throw py::value_error("orient_normal_records: a degree above " + std::to_string(record_degree));
    for(std::size_t e = 0; e < r.degree; ++e)
    {
      r.neighbor[e] = pe.at(i, py::ssize_t(e));
      if(py::ssize_t(r.neighbor[e]) >= n)
        throw py::value_error("orient_normal_records: a neighbour index beyond the records");
    }
    const int s = ps.at(i);
    if(s > int(CGAL::Curvature_estimate_status::TWO_SHEETS))
      throw py::value_error("orient_normal_records: an unknown status " + std::to_string(s));
    r.status = CGAL::Curvature_estimate_status(s);
    // a VALID record's normal is a unit vector (the orientation walks rays along it)
    const double l2 = r.normal[0] * r.normal[0] + r.normal[1] * r.normal[1] + r.normal[2] * r.normal[2];
    if(r.status == CGAL::Curvature_estimate_status::VALID && !(l2 > 0.98 && l2 < 1.02))
      throw py::value_error("orient_normal_records: a valid record whose normal is not a unit vector");
  }
  const std::vector<double> points(px.data(), px.data() + 3 * n);
  std::vector<double> normals;
  run(
    [&](bool, const Callback& cb) { orient_normal_records(records, points, orientation, target.data(), normals, cb); },
    progress, threads);
  py::array_t<double> out = array_n3(std::size_t(n));
  std::copy(normals.begin(), normals.end(), out.mutable_data());
  return out;
}

}  // namespace psc_py

#endif
