// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Fixed-radius neighbourhoods for every point of a cloud: a sorted uniform grid.
//
// Points are bucketed in cubic cells of side >= r and sorted by cell, so the points of a
// cell, and of a row of three consecutive cells along x, are contiguous in memory. The
// neighbours of any point of a cell are then in 9 contiguous ranges (one per row of the
// 3x3x3 block around the cell). Queries are answered cell by cell, in sorted order, so
// those 9 ranges are found once per cell by pointers that only move forward.
//
// Why a grid rather than a k-d tree: for every-point fixed-radius queries on 1M points
// (42 neighbours each) building this grid and visiting all neighbourhoods takes 0.59 s,
// against 2.8 s for CGAL's Kd_tree with Fuzzy_sphere on spatially sorted points
// (benchmark/aso_speed, one run); it needs 4 bytes per point besides the sorted coordinates.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_NEIGHBOR_GRID_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_NEIGHBOR_GRID_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// A range of positions in the grid's sorted order.
struct Index_range
{
  std::uint32_t begin = 0, end = 0;
};

// Side of the cubic cells of a uniform grid over [lo, hi] searched with radius `radius`:
// `radius`, doubled while a grid of floor(extent / side) + 1 + extra_cells cells per axis
// would not fit 62-bit keys (very sparse clouds); `dims` receives those counts. Extents that
// overflow (coordinates near +-1e308) give an infinite side: one cell holds everything.
inline double grid_cell_size(const double lo[3], const double hi[3], double radius,
                             double extra_cells, double dims[3])
{
  double side = radius;
  if(!(std::isfinite(hi[0] - lo[0]) && std::isfinite(hi[1] - lo[1]) &&
       std::isfinite(hi[2] - lo[2]) && std::isfinite(radius)))
    side = std::numeric_limits<double>::infinity();
  for(;;)
  {
    double cells = 1;
    for(int i = 0; i < 3; ++i)
    {
      dims[i] = std::isinf(side) ? 1 + extra_cells : std::floor((hi[i] - lo[i]) / side) + 1 + extra_cells;
      cells *= dims[i];
    }
    if(cells < 4.0e18)
      return side;
    side *= 2;
  }
}

// Cell coordinate (an integral double) of x along an axis of a grid starting at `origin`.
inline double grid_cell_coordinate(double x, double origin, double side)
{
  return std::isinf(side) ? 0.0 : std::floor((x - origin) / side);
}

class Neighbor_grid
{
public:
  typedef std::uint64_t Key;
  // (cell key, index of the point in the caller's numbering)
  typedef std::pair<Key, std::uint32_t> Keyed_index;

  // Sets the cell geometry for points inside [lo, hi] and a search radius r: cells of side
  // r, grown by powers of two if the grid would not fit 62-bit keys (very sparse clouds).
  void set_geometry(const double lo[3], const double hi[3], double radius)
  {
    // one empty cell on each side, so that cell +-1 never wraps around a row
    m_cell = grid_cell_size(lo, hi, radius, 2, m_dim);
    for(int i = 0; i < 3; ++i)
      m_origin[i] = lo[i];
    m_stride_y = static_cast<Key>(m_dim[0]);
    m_stride_z = m_stride_y * static_cast<Key>(m_dim[1]);
  }

  Key key(double x, double y, double z) const
  {
    const Key ix = static_cast<Key>(grid_cell_coordinate(x, m_origin[0], m_cell)) + 1;
    const Key iy = static_cast<Key>(grid_cell_coordinate(y, m_origin[1], m_cell)) + 1;
    const Key iz = static_cast<Key>(grid_cell_coordinate(z, m_origin[2], m_cell)) + 1;
    return ix + m_stride_y * iy + m_stride_z * iz;
  }

  // Takes the keyed points sorted by key (ties in any order) and records the cells.
  void set_cells(const std::vector<Keyed_index>& sorted)
  {
    m_keys.clear();
    m_start.clear();
    for(std::size_t i = 0; i < sorted.size(); ++i)
      if(i == 0 || sorted[i].first != sorted[i - 1].first)
      {
        m_keys.push_back(sorted[i].first);
        m_start.push_back(static_cast<std::uint32_t>(i));
      }
    m_start.push_back(static_cast<std::uint32_t>(sorted.size()));
    m_keys.shrink_to_fit();
    m_start.shrink_to_fit();
  }

  // Side of the cells (>= the radius given to set_geometry()).
  double cell_size() const { return m_cell; }
  std::size_t number_of_cells() const { return m_keys.size(); }
  std::size_t number_of_points() const { return m_start.empty() ? 0 : m_start.back(); }
  Index_range points_of_cell(std::size_t c) const { return {m_start[c], m_start[c + 1]}; }

  // Visits the cells [first_cell, last_cell) in order. For each cell, `visit(cell_points,
  // rows)` receives the cell's own points and the 9 ranges holding every point of the 27
  // surrounding cells (a superset of the points within r of any point of the cell).
  template <class Visitor>
  void for_each_cell(std::size_t first_cell, std::size_t last_cell, Visitor&& visit) const
  {
    if(first_cell >= last_cell)
      return;
    Key offset[9];
    for(int dz = -1, r = 0; dz <= 1; ++dz)
      for(int dy = -1; dy <= 1; ++dy, ++r)
        offset[r] = m_stride_z * Key(dz + 1) + m_stride_y * Key(dy + 1) + 1;
    const Key shift = m_stride_z + m_stride_y + 1;  // keys are shifted to stay unsigned

    // cursor[r]: first cell whose key is >= the start of row r of the current cell
    std::size_t cursor[9];
    const Key k0 = m_keys[first_cell];
    for(int r = 0; r < 9; ++r)
      cursor[r] = std::lower_bound(m_keys.begin(), m_keys.end(), k0 + offset[r] - 1 - shift) -
                  m_keys.begin();

    const std::size_t n_cells = m_keys.size();
    Index_range rows[9];
    for(std::size_t c = first_cell; c < last_cell; ++c)
    {
      const Key k = m_keys[c];
      for(int r = 0; r < 9; ++r)
      {
        const Key row_first = k + offset[r] - 1 - shift;  // cell (ix-1, iy+dy, iz+dz)
        const Key row_last = row_first + 2;               // cell (ix+1, iy+dy, iz+dz)
        std::size_t b = cursor[r];
        while(b < n_cells && m_keys[b] < row_first)
          ++b;
        cursor[r] = b;
        std::size_t e = b;
        while(e < n_cells && m_keys[e] <= row_last)
          ++e;
        rows[r].begin = m_start[b];
        rows[r].end = m_start[e];
      }
      visit(points_of_cell(c), static_cast<const Index_range*>(rows));
    }
  }

private:
  double m_origin[3] = {0, 0, 0};
  double m_dim[3] = {0, 0, 0};
  double m_cell = 1;
  Key m_stride_y = 0, m_stride_z = 0;
  std::vector<Key> m_keys;             // sorted keys of the non-empty cells
  std::vector<std::uint32_t> m_start;  // first point of each cell, plus the total
};

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
