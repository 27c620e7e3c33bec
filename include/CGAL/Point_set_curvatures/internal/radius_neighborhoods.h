// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Neighbourhoods by radius: the search of the driver (estimation_driver.h) in the sorted
// grid of the usable points. For every point, the points at distance < r among the
// candidates of the 27 cells around its cell are selected branch-free, then gathered into a
// reusable per-thread buffer in the point's scaled centred frame ((p - x) / r) and handed to
// the visitor. A point sees its neighbours in the order of a lattice of cells of side r
// anchored at the origin and, within a cell, of the input, so that the sums do not depend on
// the other points (tiles, outliers) nor on the threads. knn_neighborhoods.h builds the
// neighbourhoods by count on the same grid and gather.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_RADIUS_NEIGHBORHOODS_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_RADIUS_NEIGHBORHOODS_H

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/neighbor_grid.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Reusable neighbourhood storage of one thread: the candidate indices and the accepted
// neighbours' columns. It grows, never shrinks, so the hot loop allocates only when a
// neighbourhood is larger than every previous one.
class Neighbor_buffer
{
public:
  // Room for n candidates and n neighbours; the first size() neighbours are kept.
  void reserve(std::size_t n)
  {
    if(n <= m_capacity)
      return;
    std::size_t cap = std::max<std::size_t>(64, m_capacity);
    while(cap < n)
      cap *= 2;
    // Columns are padded by 8 doubles so that they are not a power of two apart: the
    // gather stores and the estimators' loads would otherwise alias modulo 4 KiB and stall.
    const std::size_t stride = cap + 8;
    std::vector<double> grown(columns * stride);
    for(int a = 0; a < columns; ++a)
      std::copy(m_data.begin() + a * m_stride, m_data.begin() + a * m_stride + m_size, grown.begin() + a * stride);
    m_data.swap(grown);
    m_index.resize(cap);
    m_capacity = cap;
    m_stride = stride;
  }
  // q (3), n (3) and the sample weight of each neighbour
  static constexpr int columns = 7;
  std::uint32_t* candidates() { return m_index.data(); }
  double* column(int a) { return m_data.data() + a * m_stride; }
  // number of neighbours stored in the columns (kept by reserve())
  void set_size(std::size_t n) { m_size = n; }
  std::size_t size() const { return m_size; }

private:
  std::vector<std::uint32_t> m_index;
  std::vector<double> m_data;
  std::size_t m_capacity = 0, m_stride = 0, m_size = 0;
};

// Usable points in grid order with their input positions.
struct Sorted_cloud
{
  Neighbor_grid grid;
  std::vector<std::uint32_t> input_index;       // grid order -> position in the input range
  std::vector<double> position;                 // xyz per point, grid order
  std::vector<double> normal;                   // normal per point (unit if asked), grid order
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // bounding box of the usable points
  // With a tile: own[k] != 0 for the tile's own points (the only ones estimated), grid order.
  // Empty without a tile: every point is estimated.
  std::vector<char> own;
  std::size_t own_count = 0;          // points estimated (own points, or every usable point)
  std::vector<double> sample_weight;  // per point, grid order; empty: equal weights
  std::vector<double> reach;          // per point, grid order (Neighborhood_options::point_reach); empty: none

  bool is_own(std::size_t k) const { return own.empty() || own[k] != 0; }
};

// Empties `buffer` and makes room for the candidates of a cell, the points of the 9 rows of
// cells around it (Neighbor_grid::for_each_cell); returns their number.
inline std::size_t prepare_for_candidates(Neighbor_buffer& buffer, const Index_range* rows)
{
  std::size_t n_candidates = 0;
  for(int r = 0; r < 9; ++r)
    n_candidates += rows[r].end - rows[r].begin;
  buffer.set_size(0);
  buffer.reserve(n_candidates);
  return n_candidates;
}

// Fills the buffer's columns with the points `index[0..size)` of `cloud` in the scaled
// centred frame of point `query` and radius `radius`, and calls visit(input_index, nb).
template <class Visitor>
void visit_neighborhood(const Sorted_cloud& cloud, std::uint32_t query, double radius, const std::uint32_t* index,
                        std::size_t size, Neighbor_buffer& buffer, Visitor& visit)
{
  const double* position = cloud.position.data();
  const double* normal = cloud.normal.data();
  const double* x = position + 3 * std::size_t(query);
  double *qx = buffer.column(0), *qy = buffer.column(1), *qz = buffer.column(2);
  double *nx = buffer.column(3), *ny = buffer.column(4), *nz = buffer.column(5);
  const double inv_r = 1.0 / radius;
  for(std::size_t s = 0; s < size; ++s)
  {
    const double* p = position + 3 * std::size_t(index[s]);
    const double* n = normal + 3 * std::size_t(index[s]);
    qx[s] = (p[0] - x[0]) * inv_r;
    qy[s] = (p[1] - x[1]) * inv_r;
    qz[s] = (p[2] - x[2]) * inv_r;
    nx[s] = n[0];
    ny[s] = n[1];
    nz[s] = n[2];
  }
  const double* sample_weight = nullptr;
  if(!cloud.sample_weight.empty())
  {
    double* a = buffer.column(6);
    for(std::size_t s = 0; s < size; ++s)
      a[s] = cloud.sample_weight[index[s]];
    sample_weight = a;
  }
  buffer.set_size(size);
  Neighborhood nb;
  nb.size = size;
  nb.qx = qx;
  nb.qy = qy;
  nb.qz = qz;
  nb.nx = nx;
  nb.ny = ny;
  nb.nz = nz;
  nb.radius = radius;
  nb.center[0] = x[0];
  nb.center[1] = x[1];
  nb.center[2] = x[2];
  for(int a = 0; a < 3; ++a)
    nb.query_normal[a] = normal[3 * std::size_t(query) + a];
  nb.index = index;
  nb.input_index = cloud.input_index.data();
  nb.position = position;
  nb.query_index = cloud.input_index[query];
  nb.sample_weight = sample_weight;
  visit(std::size_t(cloud.input_index[query]), static_cast<const Neighborhood&>(nb));
}

// Sorts the points `index[0..size)` of `cloud` in the order a grid of cells of side `side`
// anchored at the origin lists them: by cell (z, then y, then x), then by input position.
inline void sort_in_lattice_order(const Sorted_cloud& cloud, double side, std::uint32_t* index, std::size_t size)
{
  auto key = [&](std::uint32_t i) {
    const double* p = &cloud.position[3 * std::size_t(i)];
    return std::make_tuple(grid_cell_coordinate(p[2], side), grid_cell_coordinate(p[1], side),
                           grid_cell_coordinate(p[0], side), cloud.input_index[i]);
  };
  std::sort(index, index + size, [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
}

// Visits the neighbourhood of every own point of the grid positions [first, last): selects
// the points at distance < r among the candidates of the 27 cells around its cell, copies
// them into `buffer` (scaled centred frame) and calls visit(input_index, nb). A range may
// start or end inside a cell, so that a cell holding many points is shared between tasks.
template <class Visitor>
void visit_points(const Sorted_cloud& cloud, double radius, std::uint32_t first, std::uint32_t last,
                  Neighbor_buffer& buffer, Visitor& visit)
{
  if(first >= last)
    return;
  const double r2 = radius * radius;
  const double* position = cloud.position.data();
  // A grid whose cells are larger than the radius (a cloud too spread out for cells of side
  // r, see grid_cell_size) lists the neighbours in another order: restore that of cells of
  // side r, so that the sums do not depend on the other points (tiles, outliers).
  const bool canonical_order = cloud.grid.cell_size() != radius;
  const std::size_t first_cell = cloud.grid.cell_of_point(first);
  const std::size_t last_cell = cloud.grid.cell_of_point(last - 1) + 1;
  cloud.grid.for_each_cell(first_cell, last_cell, [&](Index_range cell, const Index_range* rows) {
    prepare_for_candidates(buffer, rows);
    std::uint32_t* selected = buffer.candidates();
    const std::uint32_t query_end = std::min(cell.end, last);
    for(std::uint32_t query = std::max(cell.begin, first); query < query_end; ++query)
    {
      if(!cloud.is_own(query))
        continue;
      const double x0 = position[3 * query], x1 = position[3 * query + 1], x2 = position[3 * query + 2];
      // 1. select: branch-free, the index is always written and kept if inside the ball
      std::size_t k = 0;
      for(int r = 0; r < 9; ++r)
        for(std::uint32_t j = rows[r].begin; j < rows[r].end; ++j)
        {
          const double dx = position[3 * j] - x0;
          const double dy = position[3 * j + 1] - x1;
          const double dz = position[3 * j + 2] - x2;
          selected[k] = j;
          k += (dx * dx + dy * dy + dz * dz < r2) ? 1 : 0;
        }
      if(canonical_order)
        sort_in_lattice_order(cloud, radius, selected, k);
      // 2. gather the k neighbours into the scaled centred frame, visit
      visit_neighborhood(cloud, query, radius, selected, k, buffer, visit);
    }
  });
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
