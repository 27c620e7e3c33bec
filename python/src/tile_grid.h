// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: point_set_curvatures.TileGrid, the library's tiling (Tile.h), for
// splitting a cloud across processes.

#ifndef PSC_PYTHON_TILE_GRID_H
#define PSC_PYTHON_TILE_GRID_H

#include "input_arrays.h"
#include "output_arrays.h"

#include <CGAL/Point_set_curvatures/Tile.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace psc_py {

namespace py = pybind11;

// The library's tiling (Tile.h), for splitting a cloud across processes.
class Tile_grid_py
{
public:
  Tile_grid_py(const std::vector<double>& lo, const std::vector<double>& hi, const py::object& side,
               const py::object& counts)
  {
    if(lo.size() != 3 || hi.size() != 3)
      throw py::value_error("TileGrid: box_min and box_max must have 3 coordinates");
    const CGAL::Bbox_3 box(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    if(side.is_none() == counts.is_none())
      throw py::value_error("TileGrid: give either tile_side or counts");
    if(!side.is_none())
      m_grid = CGAL::Point_set_curvatures::Tile_grid(box, side.cast<double>());
    else
    {
      const auto c = counts.cast<std::vector<long long> >();
      if(c.size() != 3 || c[0] < 1 || c[1] < 1 || c[2] < 1)
        throw py::value_error("TileGrid: counts must be 3 positive integers");
      m_grid = CGAL::Point_set_curvatures::Tile_grid(
        box, std::array<std::size_t, 3>{std::size_t(c[0]), std::size_t(c[1]), std::size_t(c[2])});
    }
  }

  std::size_t size() const { return m_grid.size(); }
  py::tuple counts() const { return py::make_tuple(m_grid.count(0), m_grid.count(1), m_grid.count(2)); }

  py::tuple core(std::size_t i) const
  {
    if(i >= m_grid.size())
      throw py::index_error("TileGrid: tile index out of range");
    const CGAL::Bbox_3 b = m_grid.tile(i, 0).core;
    return py::make_tuple(py::make_tuple(b.xmin(), b.ymin(), b.zmin()), py::make_tuple(b.xmax(), b.ymax(), b.zmax()));
  }

  py::array_t<std::int64_t> tile_of(const py::handle& points) const
  {
    checked_rows(points, "points");
    const py::array a = py::reinterpret_borrow<py::array>(points);
    auto out = array_1<std::int64_t>(static_cast<std::size_t>(a.shape(0)));
    std::int64_t* p = out.mutable_data();
    for_each_row(
      a, [&](py::ssize_t i, const double* x) { p[i] = static_cast<std::int64_t>(m_grid.tile_of(x[0], x[1], x[2])); });
    return out;
  }

  // For each point, the tiles whose halo holds it: (point indices, tile indices), sorted by
  // tile then point (so that each tile's points are in input order).
  py::tuple tiles_near(const py::handle& points, double halo) const
  {
    checked_rows(points, "points");
    const py::array a = py::reinterpret_borrow<py::array>(points);
    std::vector<std::pair<std::int64_t, std::int64_t> > pairs;  // (tile, point)
    for_each_row(a, [&](py::ssize_t i, const double* x) {
      m_grid.for_each_tile_near(x[0], x[1], x[2], halo, [&](std::size_t t) { pairs.emplace_back(t, i); });
    });
    std::stable_sort(pairs.begin(), pairs.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
    auto pi = array_1<std::int64_t>(pairs.size()), ti = array_1<std::int64_t>(pairs.size());
    for(std::size_t j = 0; j < pairs.size(); ++j)
    {
      ti.mutable_data()[j] = pairs[j].first;
      pi.mutable_data()[j] = pairs[j].second;
    }
    return py::make_tuple(pi, ti);
  }

private:
  CGAL::Point_set_curvatures::Tile_grid m_grid;
};

// The rules every driver of tiles follows (Tile.h), for point_set_curvatures.dask: the tiles'
// box, a tile's range and own points.

// The box of the tiles over the rows of `points` (tile_grid_box() of their Tile_box_sample,
// the tool's box for the same cloud): ((xmin, ymin, zmin), (xmax, ymax, zmax)).
inline py::tuple tile_grid_box_py(const py::handle& points)
{
  checked_rows(points, "points");
  CGAL::Point_set_curvatures::Tile_box_sample sample;
  for_each_row(py::reinterpret_borrow<py::array>(points),
               [&](py::ssize_t, const double* x) { sample.add(x[0], x[1], x[2]); });
  const CGAL::Bbox_3 b = sample.box();
  return py::make_tuple(py::make_tuple(b.xmin(), b.ymin(), b.zmin()), py::make_tuple(b.xmax(), b.ymax(), b.zmax()));
}

// The tile of core [lo, hi) and `halo`.
inline CGAL::Point_set_curvatures::Tile tile_of_core(const std::vector<double>& lo, const std::vector<double>& hi,
                                                     double halo)
{
  if(lo.size() != 3 || hi.size() != 3)
    throw py::value_error("tile: core_min and core_max must have 3 coordinates");
  return CGAL::Point_set_curvatures::Tile(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), halo);
}

// `f(x)` for each row x of `points`, in order, as an array of T.
template <class T, class F>
py::array_t<T> for_each_row_of(const py::handle& points, const F& f)
{
  checked_rows(points, "points");
  const py::array a = py::reinterpret_borrow<py::array>(points);
  auto out = array_1<T>(static_cast<std::size_t>(a.shape(0)));
  T* o = out.mutable_data();
  for_each_row(a, [&](py::ssize_t i, const double* x) { o[i] = f(x); });
  return out;
}

// The Tile_range of the tile of core [lo, hi) and `halo` over the rows of `points`: (the mask
// of the rows taken, their number, the distance to the core of the nearest finite row left out).
inline py::tuple tile_range_py(const std::vector<double>& lo, const std::vector<double>& hi, double halo,
                               const py::handle& points)
{
  CGAL::Point_set_curvatures::Tile_range range(tile_of_core(lo, hi, halo));
  const auto mask = for_each_row_of<bool>(points, [&range](const double* x) { return range.take(x[0], x[1], x[2]); });
  return py::make_tuple(mask, range.finite_taken(), range.nearest_left_out());
}

// Tile::owns of each row of `points`.
inline py::array_t<bool> tile_owns_py(const std::vector<double>& lo, const std::vector<double>& hi,
                                      const py::handle& points)
{
  const CGAL::Point_set_curvatures::Tile tile = tile_of_core(lo, hi, 0);
  return for_each_row_of<bool>(points, [&tile](const double* x) { return tile.owns(x[0], x[1], x[2]); });
}

}  // namespace psc_py

#endif
