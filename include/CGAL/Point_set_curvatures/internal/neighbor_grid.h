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
// (42 neighbours each) building this grid and visiting all neighbourhoods takes 0.48 s,
// against 3.17 s for CGAL's Kd_tree with Fuzzy_sphere on spatially sorted points
// (benchmark/aso_speed, one run); it needs 4 bytes per point besides the sorted coordinates
// (and 32 bytes per point while it is sorted).

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

// Cell coordinate of x along an axis of a lattice of cubic cells of side `side` anchored at
// the origin: the exact floor(x / side), an integral double. The quotient is rounded, so it is
// corrected with the exact sign of x - q side (fma rounds once and keeps the sign). Exact
// cells make two points at distance < side fall in the same or adjacent cells, and anchoring
// at the origin rather than at the cloud's corner makes a point's cell independent of the
// other points: a tile of a cloud is sorted in the same relative order as the whole cloud.
// Valid for |x / side| < 2^52, which grid_cell_size() guarantees; an infinite side gives 0.
inline double grid_cell_coordinate(double x, double side)
{
  if(std::isinf(side))
    return 0.0;
  double q = std::floor(x / side);
  if(std::fma(-q, side, x) < 0)
    q -= 1;
  else if(std::fma(-(q + 1), side, x) >= 0)
    q += 1;
  return q;
}

// Side of the cubic cells of a uniform grid over the points of [lo, hi] searched with radius
// `radius`: `radius`, doubled while the grid of (cells spanned per axis + extra_cells) cells
// would not fit 62-bit keys (very sparse clouds), or while a coordinate exceeds 2^50 cells
// from the origin (where cell coordinates would lose their exactness); `dims` receives the
// counts per axis. Extents that overflow (coordinates near +-1e308) give an infinite side:
// one cell holds everything.
inline double grid_cell_size(const double lo[3], const double hi[3], double radius, double extra_cells, double dims[3])
{
  double side = radius;
  if(!(std::isfinite(hi[0] - lo[0]) && std::isfinite(hi[1] - lo[1]) && std::isfinite(hi[2] - lo[2]) &&
       std::isfinite(radius)))
    side = std::numeric_limits<double>::infinity();
  constexpr double max_cell = 1125899906842624.0;  // 2^50
  for(;;)
  {
    if(std::isinf(side))
    {
      for(int i = 0; i < 3; ++i)
        dims[i] = 1 + extra_cells;
      return side;
    }
    double cells = 1;
    bool exact = true;
    for(int i = 0; i < 3; ++i)
    {
      exact = exact && std::abs(lo[i] / side) < max_cell && std::abs(hi[i] / side) < max_cell;
      dims[i] = exact ? grid_cell_coordinate(hi[i], side) - grid_cell_coordinate(lo[i], side) + 1 + extra_cells : 0;
      cells *= dims[i];
    }
    if(exact && cells < 4.0e18)
      return side;
    side *= 2;
  }
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
      m_base[i] = grid_cell_coordinate(lo[i], m_cell) - 1;
    m_stride_y = static_cast<Key>(m_dim[0]);
    m_stride_z = m_stride_y * static_cast<Key>(m_dim[1]);
  }

  Key key(double x, double y, double z) const
  {
    const Key ix = static_cast<Key>(grid_cell_coordinate(x, m_cell) - m_base[0]);
    const Key iy = static_cast<Key>(grid_cell_coordinate(y, m_cell) - m_base[1]);
    const Key iz = static_cast<Key>(grid_cell_coordinate(z, m_cell) - m_base[2]);
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
  // The cell holding the point at position p of the sorted order (p < number_of_points()).
  std::size_t cell_of_point(std::uint32_t p) const
  {
    return static_cast<std::size_t>(std::upper_bound(m_start.begin(), m_start.end() - 1, p) - m_start.begin()) - 1;
  }

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
      cursor[r] = std::lower_bound(m_keys.begin(), m_keys.end(), k0 + offset[r] - 1 - shift) - m_keys.begin();

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
  double m_base[3] = {0, 0, 0};  // lattice cell coordinate of the grid's first (empty) cell
  double m_dim[3] = {0, 0, 0};
  double m_cell = 1;
  Key m_stride_y = 0, m_stride_z = 0;
  std::vector<Key> m_keys;             // sorted keys of the non-empty cells
  std::vector<std::uint32_t> m_start;  // first point of each cell, plus the total
};

// Runs f(0), ..., f(n - 1) in order: the sequential chunk runner of sort_by_key_then_index().
struct Run_chunks_in_order
{
  template <class F>
  void operator()(std::size_t n, const F& f) const
  {
    for(std::size_t c = 0; c < n; ++c)
      f(c);
  }
};

// Sorts (cell key, index) pairs that come in increasing index order by key, ties by index:
// the order std::sort gives them, in linear time. A stable least-significant-digit radix sort
// on the keys' significant bits, 11 bits per pass: two passes for up to 4 million cells
// (1M points on an ellipsoid: 0.07 s less than std::sort per grid, the same order). The
// input is cut into chunks of at least 64K pairs, counted and scattered by
// `run_chunks(number_of_chunks, f)`, which may run f(chunk) concurrently (the driver's does
// with Parallel_tag); chunks only decide who writes where, so the order does not depend on
// them. `scratch` is working memory of the same size.
template <class Keyed, class RunChunks = Run_chunks_in_order>
void sort_by_key_then_index(std::vector<Keyed>& v, std::vector<Keyed>& scratch,
                            const RunChunks& run_chunks = RunChunks())
{
  const std::size_t n = v.size();
  if(n < 2048)
  {
    std::sort(v.begin(), v.end());
    return;
  }
  std::uint64_t max_key = 0;
  for(const Keyed& e : v)
    max_key = std::max<std::uint64_t>(max_key, e.first);
  constexpr int digit_bits = 11;
  constexpr std::size_t buckets = std::size_t(1) << digit_bits;
  constexpr std::uint64_t mask = buckets - 1;
  const std::size_t chunks = std::min<std::size_t>(64, (n + 65535) / 65536);
  auto chunk_begin = [&](std::size_t c) { return c * n / chunks; };
  scratch.resize(n);
  // start[c * buckets + d]: where chunk c writes its next pair of digit d
  std::vector<std::size_t> start(chunks * buckets);
  for(int shift = 0; shift < 64 && (max_key >> shift) != 0; shift += digit_bits)
  {
    run_chunks(chunks, [&](std::size_t c) {
      std::size_t* count = &start[c * buckets];
      std::fill(count, count + buckets, std::size_t(0));
      const std::size_t end = chunk_begin(c + 1);
      for(std::size_t i = chunk_begin(c); i < end; ++i)
        ++count[(v[i].first >> shift) & mask];
    });
    std::size_t sum = 0;  // digit by digit, and chunk by chunk within a digit: stable
    for(std::size_t d = 0; d < buckets; ++d)
      for(std::size_t c = 0; c < chunks; ++c)
      {
        const std::size_t count = start[c * buckets + d];
        start[c * buckets + d] = sum;
        sum += count;
      }
    run_chunks(chunks, [&](std::size_t c) {
      std::size_t* next = &start[c * buckets];
      const std::size_t end = chunk_begin(c + 1);
      for(std::size_t i = chunk_begin(c); i < end; ++i)
        scratch[next[(v[i].first >> shift) & mask]++] = v[i];
    });
    v.swap(scratch);
  }
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
