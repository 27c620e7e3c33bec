// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Fixed-radius neighbours of arbitrary positions (the APSS projection evaluates the fit at
// points that are not in the cloud). Neighbor_grid answers every-point queries cell by cell in
// sorted order; this index answers one query anywhere, from any thread: the points are sorted
// by cubic cell of side >= r, the non-empty cells' keys kept sorted, and a query visits the 9
// rows of 3 consecutive cells around its cell, each found by one binary search.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_POSITION_INDEX_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_POSITION_INDEX_H

#include <CGAL/Point_set_curvatures/internal/neighbor_grid.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

class Position_index
{
public:
  typedef std::uint64_t Key;

  // Indexes `n` points (xyz, finite) for queries of radius `radius`; reorders `xyz` (and the
  // parallel `attribute` array of `stride` doubles per point, and `ids`) in cell order.
  void build(std::vector<double>& xyz, std::vector<double>& attribute, std::size_t stride,
             std::vector<std::size_t>& ids, double radius)
  {
    m_radius = radius;
    const std::size_t n = xyz.size() / 3;
    m_keys.clear();
    m_start.clear();
    if(n == 0)
      return;
    double lo[3], hi[3];
    for(int a = 0; a < 3; ++a)
      lo[a] = hi[a] = xyz[a];
    for(std::size_t i = 1; i < n; ++i)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], xyz[3 * i + a]);
        hi[a] = std::max(hi[a], xyz[3 * i + a]);
      }
    m_cell = grid_cell_size(lo, hi, radius, 0, m_dim);
    for(int a = 0; a < 3; ++a)
      m_base[a] = grid_cell_coordinate(lo[a], m_cell);

    std::vector<std::pair<Key, std::size_t> > keyed(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      double c[3];
      cell_of(&xyz[3 * i], c);
      keyed[i] = std::make_pair(key(c[0], c[1], c[2]), i);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<double> sorted_xyz(3 * n), sorted_attribute(stride * n);
    std::vector<std::size_t> sorted_ids(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t i = keyed[k].second;
      std::copy(&xyz[3 * i], &xyz[3 * i] + 3, &sorted_xyz[3 * k]);
      std::copy(attribute.begin() + stride * i, attribute.begin() + stride * (i + 1),
                sorted_attribute.begin() + stride * k);
      sorted_ids[k] = ids[i];
      if(k == 0 || keyed[k].first != keyed[k - 1].first)
      {
        m_keys.push_back(keyed[k].first);
        m_start.push_back(k);
      }
    }
    m_start.push_back(n);
    xyz.swap(sorted_xyz);
    attribute.swap(sorted_attribute);
    ids.swap(sorted_ids);
  }

  // Calls f(k) for every indexed point k (position in the sorted order) at distance < r from
  // x, in increasing k. `xyz` is the array reordered by build().
  template <class Function>
  void for_each_neighbor(const double* xyz, const double x[3], Function&& f) const
  {
    if(m_keys.empty())
      return;
    double c[3];
    cell_of(x, c);
    double first[3], last[3];
    for(int a = 0; a < 3; ++a)
    {
      // c is a double, so positions far outside the grid cannot overflow an integer
      first[a] = std::max(c[a] - 1, 0.0);
      last[a] = std::min(c[a] + 1, m_dim[a] - 1);
      if(first[a] > last[a])
        return;  // no cell of the grid within r
    }
    const double r2 = m_radius * m_radius;
    for(double iz = first[2]; iz <= last[2]; ++iz)
      for(double iy = first[1]; iy <= last[1]; ++iy)
      {
        const Key row_first = key(first[0], iy, iz), row_last = key(last[0], iy, iz);
        std::size_t cell = std::lower_bound(m_keys.begin(), m_keys.end(), row_first) - m_keys.begin();
        for(; cell < m_keys.size() && m_keys[cell] <= row_last; ++cell)
          for(std::size_t k = m_start[cell]; k < m_start[cell + 1]; ++k)
          {
            const double dx = xyz[3 * k] - x[0], dy = xyz[3 * k + 1] - x[1], dz = xyz[3 * k + 2] - x[2];
            if(dx * dx + dy * dy + dz * dz < r2)
              f(k);
          }
      }
  }

private:
  // cell coordinates (integral doubles; may lie outside [0, dim) for positions outside)
  void cell_of(const double* x, double c[3]) const
  {
    for(int a = 0; a < 3; ++a)
    {
      c[a] = grid_cell_coordinate(x[a], m_cell) - m_base[a];
      if(!(c[a] > -2))
        c[a] = -2;  // far below (or NaN): no neighbour cell
      else if(c[a] > m_dim[a] + 1)
        c[a] = m_dim[a] + 1;
    }
  }

  Key key(double ix, double iy, double iz) const
  {
    return static_cast<Key>(ix) +
           static_cast<Key>(m_dim[0]) * (static_cast<Key>(iy) + static_cast<Key>(m_dim[1]) * static_cast<Key>(iz));
  }

  double m_radius = 1, m_cell = 1;
  double m_base[3] = {0, 0, 0};  // lattice cell coordinate of the grid's first cell
  double m_dim[3] = {1, 1, 1};
  std::vector<Key> m_keys;           // sorted keys of the non-empty cells
  std::vector<std::size_t> m_start;  // first point of each cell, plus the total
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
