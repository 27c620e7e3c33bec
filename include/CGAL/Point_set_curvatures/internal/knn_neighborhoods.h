// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Neighbourhoods by count: each point gets its own kernel radius from its k nearest
// neighbours, so that the scale follows the sampling density (LiDAR: dense near the
// scanner, sparse far away), then the same visitor contract as for_each_neighborhood().
//
// Semantics, for a usable point x (unusable points are nobody's neighbour) and with
// d_k(x) the distance from x to its k-th nearest usable point, x itself being the first:
//   - radius r(x) = (1 + 2^-20) d_k(x). The neighbourhood is every usable point at distance
//     < r(x): the k nearest, plus the points tied with the k-th (equal distances up to a
//     relative 1e-6, so that a regular grid does not lose half of a ring of equidistant
//     points to rounding). Hence at least k points, x included. The factor only moves the
//     k-th point from the boundary of the ball, where the kernel (1 - d²/r²)² vanishes, to
//     just inside (weight about 4e-12): the fit is the one of a radius of exactly d_k.
//   - k larger than the number of usable points: every usable point is a neighbour, the
//     radius being (1 + 2^-20) times the distance to the farthest one.
//   - d_k(x) = 0 (k copies of x): the distance to the nearest usable point not at x is used
//     instead, so the neighbourhood holds the copies and that point; if every usable point
//     is at x, r = 1 (the fit is degenerate whatever the radius).
//
// Search. Most neighbourhoods come from the sorted grid of the radius driver: with cells of
// side s, the 27 cells around a point hold every point within s of it, so if at least k of
// them are within s and (1 + 2^-20) d_k <= s, the neighbourhood is exact. The side comes
// from d_k at 4096 points spread over those to visit, found with a k-d tree (point_kd_tree.h),
// by a cost model (knn_grid_side). The other points (sparser regions, isolated points, more
// copies than k, k at least the number of points) take their neighbourhood from that tree:
// the k+1 nearest tell whether points are tied with the k-th, and a ball query then gathers
// them all. Either way the neighbourhood is then listed by input position
// (sort_by_input_index), so that the result depends on the input only, never on the
// concurrency tag, the path or the tile.
//
// Cost, ASO on 1M ellipsoid points with k = 42 (benchmark/aso_speed, one run): 1.66 times
// the same run by radius sequentially, 1.64 times in parallel. The previous version, CGAL's
// Kd_tree with Orthogonal_k_neighbor_search for every point, took 3.1 times (a scratch
// program, ASO sequential: 7.3 s against 3.1 s now). With a density varying 1:10 and 1:100
// over the cloud, where more points go to the tree, the gain is 1.4 and 1.5 times. Per
// query, the tree costs several times the grid: it walks nodes and selects among its
// candidates, the grid scans contiguous memory.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_KNN_NEIGHBORHOODS_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_KNN_NEIGHBORHOODS_H

#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>

#include <CGAL/Point_set_curvatures/internal/point_kd_tree.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Relative enlargement of d_k (see the header comment): large enough to absorb rounding
// in the distances of equidistant points, small enough to leave the fit unchanged.
constexpr double knn_radius_factor = 1.0 + 1.0 / 1048576.0;

// The radius of the tree's point at position x and its neighbourhood (points at distance
// < radius, in no particular order) in `neighbors`, following the semantics of the header
// comment.
inline double knn_neighborhood(const Point_kd_tree& tree, const double* x, std::size_t k,
                               std::vector<Point_kd_tree::Candidate>& neighbors)
{
  typedef Point_kd_tree::Candidate Candidate;
  const std::size_t n = tree.size();
  std::size_t count = k < n ? k + 1 : n;
  tree.nearest_unordered(x, count, neighbors);
  const auto farthest = [&neighbors] { return std::max_element(neighbors.begin(), neighbors.end())->first; };
  if(n <= k)
  {
    // every point: the radius reaches just beyond the farthest one
    const double d2_max = farthest();
    return d2_max > 0 ? knn_radius_factor * std::sqrt(d2_max) : 1.0;
  }
  // the k nearest first, then the k+1-th (the only one left), in the order of (d2, id): the
  // tree listed the k + 1 nearest, so the k+1-th is the largest of them and the k-th the largest
  // of the others (two scans where a selection cost about 5% of a run of the automatic scale)
  std::iter_swap(std::max_element(neighbors.begin(), neighbors.end()), neighbors.begin() + k);
  double d2_k = std::max_element(neighbors.begin(), neighbors.begin() + k)->first;
  bool ties_beyond = false;
  if(d2_k == 0)
  {
    // k copies of x: the nearest point elsewhere sets the scale
    while(farthest() == 0 && count < n)
    {
      count = std::min(2 * count, n);
      tree.nearest_unordered(x, count, neighbors);
    }
    d2_k = std::numeric_limits<double>::infinity();
    for(const Candidate& c : neighbors)
      if(c.first > 0)
        d2_k = std::min(d2_k, c.first);
    if(d2_k == std::numeric_limits<double>::infinity())
      return 1.0;        // every usable point is at x
    ties_beyond = true;  // the ball may hold more copies than were listed
  }
  const double radius = knn_radius_factor * std::sqrt(d2_k);
  const double r2 = radius * radius;
  if(!ties_beyond)
  {
    ties_beyond = neighbors[k].first < r2;  // the k+1-th is inside: maybe more
    if(!ties_beyond)
      neighbors.resize(k);  // d2 <= d2_k < r2 for the k nearest, nobody else
  }
  if(ties_beyond)
    tree.ball(x, r2, neighbors);
  return radius;
}

// Scratch of one thread for the neighbourhoods by count.
struct Knn_scratch
{
  Neighbor_buffer buffer;
  std::vector<double> d2, selection;
  std::vector<Point_kd_tree::Candidate> neighbors;
  std::vector<std::uint32_t> index;
  std::vector<std::uint64_t> order;
};

// Orders a neighbourhood (grid positions) by input position. Grid and tree find the same set
// in different orders, and which one serves a point depends on the whole cloud (the grid's
// side comes from a sample): the input order is the one order a tile shares with the whole
// cloud, so that its sums, hence its estimates, are bitwise the same.
// The input positions are distinct, so the order is the one std::sort gives the keys (input
// position, grid position); from radix_sort_least_size keys on it is found by a least-significant-
// digit radix sort on the input position's bytes, skipping the bytes all keys share (the sort
// of 640 neighbours was 10% of a run of the automatic scale; the same order).
constexpr std::size_t radix_sort_least_size = 96;

inline void sort_by_input_index(const Sorted_cloud& cloud, std::uint32_t* index, std::size_t size,
                                std::vector<std::uint64_t>& order)
{
  order.resize(2 * size);
  std::uint64_t* key = order.data();
  for(std::size_t i = 0; i < size; ++i)
    key[i] = (std::uint64_t(cloud.input_index[index[i]]) << 32) | index[i];
  if(size < radix_sort_least_size)
    std::sort(key, key + size);
  else
  {
    std::uint32_t count[4][256] = {};
    for(std::size_t i = 0; i < size; ++i)
      for(int b = 0; b < 4; ++b)
        ++count[b][(key[i] >> (32 + 8 * b)) & 0xff];
    std::uint64_t* other = key + size;
    for(int b = 0; b < 4; ++b)
    {
      const int shift = 32 + 8 * b;
      if(count[b][(key[0] >> shift) & 0xff] == size)
        continue;  // every key has this byte
      std::uint32_t start[256];
      std::uint32_t sum = 0;
      for(int d = 0; d < 256; ++d)
      {
        start[d] = sum;
        sum += count[b][d];
      }
      for(std::size_t i = 0; i < size; ++i)
        other[start[(key[i] >> shift) & 0xff]++] = key[i];
      std::swap(key, other);
    }
  }
  for(std::size_t i = 0; i < size; ++i)
    index[i] = static_cast<std::uint32_t>(key[i]);
}

// With a tile, the largest halo its own points need so far: a point's neighbourhood (radius
// times `halo_radii`) must lie within the halo around the core.
class Halo_requirement
{
public:
  Halo_requirement(const Neighborhood_options& options) : m_options(options) {}
  // Records what the neighbourhood of x, of this radius, needs; false once a point (this one or
  // an earlier one) needed more than the halo: enforce() will throw, so its neighbourhood need
  // not be visited (the search goes on, for the halo that every point needs: a tile of
  // lone-star.las with neighbourhoods up to 640 grew its halo 15 times, each time after fitting
  // every point).
  bool check(const double* x, double radius)
  {
    if(!m_options.has_tile)
      return true;
    return require(m_options.halo_radii * radius - m_options.tile.distance_inside_core(x[0], x[1], x[2]));
  }
  // Records what the weights of the neighbours (grid positions `neighbors`, `size` of them) of
  // a neighbourhood need (their reach, Sorted_cloud::reach, if the cloud has it); false as
  // check().
  bool check_reach(const Sorted_cloud& cloud, const std::uint32_t* neighbors, std::size_t size)
  {
    if(cloud.reach.empty())
      return !m_exceeded.load(std::memory_order_relaxed);
    double most = 0;
    for(std::size_t i = 0; i < size; ++i)
      most = std::max(most, cloud.reach[neighbors[i]]);
    return require(most);
  }
  // Throws Halo_too_small if a point needed more than the tile's halo.
  void enforce() const
  {
    if(m_required > m_options.tile.halo)
      throw Halo_too_small(m_required, m_options.tile.halo);
  }

private:
  // Records that a point needs a halo of `need`; false once any point needed more than the
  // tile's halo.
  bool require(double need)
  {
    if(need > m_options.tile.halo)
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_required = std::max(m_required, need);
      m_exceeded.store(true, std::memory_order_relaxed);
    }
    return !m_exceeded.load(std::memory_order_relaxed);
  }

  const Neighborhood_options& m_options;
  std::mutex m_mutex;
  double m_required = 0;
  std::atomic<bool> m_exceeded{false};
};

// The k-th smallest (1-based, k <= c) of the c values d2[i] in [0, s2): a histogram of 32
// bins over [0, s2) finds the bin holding it, then a selection within that bin only (about
// 16 times fewer values than a selection over all of them, for points on a surface). At
// scales where 32 / s2 overflows, a selection over all of them.
inline double kth_smallest(const double* d2, std::size_t c, std::size_t k, double s2, std::vector<double>& bin_values)
{
  constexpr int bins = 32;
  const double scale = bins / s2;
  if(!(scale <= std::numeric_limits<double>::max()))
  {
    bin_values.assign(d2, d2 + c);
    std::nth_element(bin_values.begin(), bin_values.begin() + (k - 1), bin_values.end());
    return bin_values[k - 1];
  }
  std::size_t count[bins] = {};
  for(std::size_t i = 0; i < c; ++i)
    ++count[std::min(bins - 1, static_cast<int>(d2[i] * scale))];
  int b = 0;
  std::size_t before = 0;
  while(before + count[b] < k)
    before += count[b++];
  bin_values.clear();
  for(std::size_t i = 0; i < c; ++i)
    if(std::min(bins - 1, static_cast<int>(d2[i] * scale)) == b)
      bin_values.push_back(d2[i]);
  const std::size_t j = k - 1 - before;
  std::nth_element(bin_values.begin(), bin_values.begin() + j, bin_values.end());
  return bin_values[j];
}

// The grid part (see the header comment): visits the own points of the grid positions
// [first, last) whose neighbourhood lies within the 27 cells around them, flags the others in
// `deferred`.
template <class Visitor>
void visit_points_knn(const Sorted_cloud& cloud, std::size_t k, std::uint32_t first, std::uint32_t last,
                      Knn_scratch& scratch, std::vector<char>& deferred, Halo_requirement& halo, Visitor& visit)
{
  if(first >= last)
    return;
  const double side = cloud.grid.cell_size(), s2 = side * side;
  const double* position = cloud.position.data();
  const std::size_t first_cell = cloud.grid.cell_of_point(first);
  const std::size_t last_cell = cloud.grid.cell_of_point(last - 1) + 1;
  cloud.grid.for_each_cell(first_cell, last_cell, [&](Index_range cell, const Index_range* rows) {
    const std::size_t n_candidates = prepare_for_candidates(scratch.buffer, rows);
    if(scratch.d2.size() < n_candidates)
      scratch.d2.resize(n_candidates);
    std::uint32_t* selected = scratch.buffer.candidates();
    double* d2 = scratch.d2.data();
    const std::uint32_t query_end = std::min(cell.end, last);
    for(std::uint32_t query = std::max(cell.begin, first); query < query_end; ++query)
    {
      if(!cloud.is_own(query))
        continue;
      const double* x = position + 3 * std::size_t(query);
      // the points within the side, branch-free as in visit_points()
      std::size_t c = 0;
      for(int r = 0; r < 9; ++r)
        for(std::uint32_t j = rows[r].begin; j < rows[r].end; ++j)
        {
          const double dx = position[3 * std::size_t(j)] - x[0];
          const double dy = position[3 * std::size_t(j) + 1] - x[1];
          const double dz = position[3 * std::size_t(j) + 2] - x[2];
          const double e = dx * dx + dy * dy + dz * dz;
          selected[c] = j;
          d2[c] = e;
          c += e < s2 ? 1 : 0;
        }
      if(c < k)
      {
        deferred[query] = 1;
        continue;
      }
      double d2_k = kth_smallest(d2, c, k, s2, scratch.selection);
      if(d2_k == 0)  // k copies of x: the nearest point elsewhere sets the scale
      {
        d2_k = std::numeric_limits<double>::infinity();
        for(std::size_t i = 0; i < c; ++i)
          if(d2[i] > 0 && d2[i] < d2_k)
            d2_k = d2[i];
      }
      const double radius = knn_radius_factor * std::sqrt(d2_k);
      const double r2 = radius * radius;
      // beyond the 27 cells, or (subnormal distances) a factor lost to rounding, which the
      // tree's rule handles: the tree
      if(!(r2 <= s2) || !(d2_k < r2))
      {
        deferred[query] = 1;
        continue;
      }
      std::size_t size = 0;
      for(std::size_t i = 0; i < c; ++i)
      {
        selected[size] = selected[i];
        size += d2[i] < r2 ? 1 : 0;
      }
      if(!halo.check(x, radius) || !halo.check_reach(cloud, selected, size))
        continue;
      sort_by_input_index(cloud, selected, size, scratch.order);
      visit_neighborhood(cloud, query, radius, selected, size, scratch.buffer, visit);
    }
  });
}

// How many points knn_grid_side() samples among m: enough to cost the sides (4096 at most),
// few enough that sampling, done on one thread before the visit, stays a small share of it
// (one in 16 points; every point of a cloud of up to 512).
inline std::size_t knn_grid_samples(std::size_t m)
{
  return std::min<std::size_t>(4096, std::max<std::size_t>(512, m / 16));
}

// Side of the grid for neighbourhoods by count, from r_i = (1 + 2^-20) d_k at knn_grid_samples()
// points spread over the cloud (all of them if fewer), found with the tree (d_k = 0: the nearest
// distance that is not 0, as for the neighbourhoods). The grid may have to use larger cells
// than asked (grid_cell_size: huge extents, a far outlier), so each candidate side s is costed
// at its effective cell side c(s): a point i is served by the grid if r_i <= c(s), at a cost
// growing with the points of its 27 cells, about (9 k / pi) (c(s) / r_i)^2 on a surface;
// otherwise by the tree, at a cost growing with k. The side minimises the sum of these costs
// over the samples (measured on this machine: 0.2 us per grid query plus 3 ns per point
// scanned; 2.5 us plus 0.04 us a neighbour per tree query, 2.8, 4.1, 10.1 and 27.5 us for k =
// 10, 40, 160 and 640 on 200,000 points of a surface, where a constant 4 us sent the large counts
// of the automatic scale to the tree and made it 9% slower on data/real/sample_c.las), so that
// clouds of varying density (scans) keep their dense parts on the grid and send the sparse ones
// to the tree. The samples are taken among the m points of `xyz`: the points to visit (the tree
// holds them all; `point_at(i, x)` sets x to the coordinates of the i-th). Returns 0 if the tree
// alone is cheaper. The samples' searches run on several threads if `parallel` (they cost as
// much as a pass's grid queries at the automatic scale's large counts on a small cloud: 900
// searches of 640 on data/real/sample_c.las); the side is the same either way.
template <class Point_at>
double knn_grid_side(const Point_kd_tree& tree, const Point_at& point_at, std::size_t m, std::size_t k,
                     const double lo[3], const double hi[3], bool parallel = false)
{
  const std::size_t samples = std::min<std::size_t>(m, knn_grid_samples(m));
  const std::size_t count = std::min(k, tree.size());
  std::vector<double> sampled(samples, 0.0);  // r_i of each sample, 0 where it has none
  process_in_parallel(parallel, 0, samples, [&](std::uint32_t first, std::uint32_t last) {
    std::vector<Point_kd_tree::Candidate> nearest;
    for(std::size_t s = first; s < last; ++s)
    {
      double x[3];
      point_at((2 * s + 1) * m / (2 * samples), x);
      tree.nearest_unordered(x, count, nearest);
      // the k-th distance (the largest of the k nearest), else the nearest that is not 0
      double d2 = std::max_element(nearest.begin(), nearest.end())->first;
      if(d2 == 0)
      {
        tree.nearest(x, std::min(k + 1, tree.size()), nearest);
        for(std::size_t j = 0; d2 == 0 && j < nearest.size(); ++j)
          d2 = nearest[j].first;
      }
      const double ri = knn_radius_factor * std::sqrt(d2);
      sampled[s] = ri > 0 && std::isfinite(ri) ? ri : 0.0;
    }
  });
  std::vector<double> r;
  r.reserve(samples);
  for(double ri : sampled)
    if(ri > 0)
      r.push_back(ri);
  std::sort(r.begin(), r.end());
  std::vector<double> inverse_r2(r.size() + 1, 0.0);  // prefix sums of 1 / r_i^2
  for(std::size_t i = 0; i < r.size(); ++i)
    inverse_r2[i + 1] = inverse_r2[i] + 1.0 / (r[i] * r[i]);

  const double grid_query = 0.2, per_point = 0.003, tree_query = 2.5 + 0.04 * double(k);  // microseconds
  const double scanned = 9.0 * double(k) / 3.141592653589793;
  const double n_samples = double(std::max<std::size_t>(samples, 1));
  double best_cost = n_samples * tree_query, side = 0;  // the tree alone
  for(std::size_t i = 0; i < r.size(); ++i)
  {
    double dims[3];
    const double cell = grid_cell_size(lo, hi, r[i] * (1.0 + 1e-9), 2, dims);
    if(!std::isfinite(cell))
      break;
    const std::size_t served = std::upper_bound(r.begin(), r.end(), cell) - r.begin();
    const double cost = double(served) * grid_query + per_point * scanned * cell * cell * inverse_r2[served] +
                        (n_samples - double(served)) * tree_query;
    if(cost < best_cost)
    {
      best_cost = cost;
      side = r[i] * (1.0 + 1e-9);
    }
  }
  return side;
}

// The traversal of for_each_neighborhood_knn() (step 3): batches of the own points of
// `cloud` (sorted in a grid of side cloud.grid.cell_size()), the grid part, then `tree`
// (ids relabelled to grid positions) for the points it deferred (`use_grid` false: the tree
// for all); from several threads at once if `parallel`. Marks the points visited VALID in
// `status`; throws Halo_too_small if a tile's halo does not cover the neighbourhoods.
// Templated on the visitor only, like visit_sorted_cloud().
template <class Visitor>
void visit_cloud_knn(const Sorted_cloud& cloud, const Point_kd_tree& tree, std::size_t k, bool use_grid, bool parallel,
                     const Neighborhood_options& options, std::vector<Curvature_estimate_status>& status,
                     const Visitor& visit)
{
  const std::size_t m = cloud.input_index.size();
  std::vector<char> deferred(m, 0);
  std::vector<std::uint32_t> batch_deferred;
  Halo_requirement halo(options);
  Per_thread<Knn_scratch> scratches(parallel);
  auto from_tree = [&](std::uint32_t first, std::uint32_t last) {
    Visitor local = visit;
    Knn_scratch& s = scratches.local();
    for(std::size_t d = first; d < last; ++d)
    {
      const std::uint32_t query = batch_deferred[d];
      const double* x = &cloud.position[3 * std::size_t(query)];
      const double radius = knn_neighborhood(tree, x, k, s.neighbors);
      s.index.resize(s.neighbors.size());
      for(std::size_t j = 0; j < s.neighbors.size(); ++j)
        s.index[j] = s.neighbors[j].second;
      if(!halo.check(x, radius) || !halo.check_reach(cloud, s.index.data(), s.index.size()))
        continue;
      sort_by_input_index(cloud, s.index.data(), s.index.size(), s.order);
      s.buffer.set_size(0);
      s.buffer.reserve(s.index.size());
      visit_neighborhood(cloud, query, radius, s.index.data(), s.index.size(), s.buffer, local);
    }
    internal::end_of_range(local);
  };
  for_each_batch(
    parallel, cloud, options.callback, status,
    [&](std::uint32_t first, std::uint32_t last) {
      if(!use_grid)
      {
        std::fill(deferred.begin() + first, deferred.begin() + last, char(1));
        return;
      }
      Visitor local = visit;
      visit_points_knn(cloud, k, first, last, scratches.local(), deferred, halo, local);
      internal::end_of_range(local);
    },
    [&](std::uint32_t first, std::uint32_t last) {
      batch_deferred.clear();
      for(std::uint32_t g = first; g < last; ++g)
        if(deferred[g] && cloud.is_own(g))
          batch_deferred.push_back(g);
      process_in_parallel(parallel, 0, batch_deferred.size(), from_tree);
    });
  halo.enforce();
}

// The k-d tree of for_each_neighborhood_knn() over the usable points of a range, kept from
// one pass to the next over the same range and maps (Neighborhood_options::knn_cache, random
// access ranges only): the area pass, the estimation and the automatic scale's passes build it
// once. Its ids are input positions; `usable` lists the usable points' input positions in input
// order, `lo` and `hi` bound them.
struct Knn_search_cache
{
  Point_kd_tree tree;
  std::vector<std::uint32_t> usable;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  std::size_t range_size = 0;
  bool filled = false;
};

// Same contract as for_each_neighborhood() (validation, statuses, visitor, callback between
// batches of about 1% of the points, identical results with either concurrency tag), with
// a per-point radius: nb.radius is (1 + 2^-20) times the distance from the point to its
// k-th nearest usable point (itself counted as the first), and nb holds every usable point
// at distance < nb.radius, so at least min(k, number of usable points) points. See the
// header comment for ties and coincident points.
// Throws std::invalid_argument if k is 0.
template <class ConcurrencyTag, class PointRange, class PointMap, class NormalMap, class Visitor>
std::vector<Curvature_estimate_status>
for_each_neighborhood_knn(const PointRange& points, PointMap point_map, NormalMap normal_map, std::size_t k,
                          const Neighborhood_options& options, const Visitor& visit)
{
  check_concurrency_tag<ConcurrencyTag>();
  if(k == 0)
  {
    std::ostringstream msg;
    msg << options.function_name << ": parameter 'neighbor_count' must be at least 1";
    throw std::invalid_argument(msg.str());
  }
  const std::size_t n = static_cast<std::size_t>(std::distance(points.begin(), points.end()));
  std::vector<Curvature_estimate_status> status(n, Curvature_estimate_status::NOT_COMPUTED);
  if(n == 0)
    return status;

  // 1. The usable points (a radius larger than any extent: one cell, input order), the tree
  //    on them with ids relabelled to input positions (or both from the cache of an earlier
  //    pass over the same range), and the grid side (0: the tree serves every point; the grid
  //    then only groups the points into batches).
  typedef typename PointRange::const_iterator Iterator;
  constexpr bool random_access = std::is_convertible<typename std::iterator_traits<Iterator>::iterator_category,
                                                     std::random_access_iterator_tag>::value;
  Knn_search_cache own_cache;
  Knn_search_cache& cache = options.knn_cache && random_access ? *options.knn_cache : own_cache;
  std::vector<double> read_position;  // the usable points' coordinates in input order, if read here
  if(!cache.filled || cache.range_size != n)
  {
    cache.filled = false;
    Neighborhood_options read_options = options;
    read_options.normalize_normals = false;
    read_options.has_tile = false;
    read_options.visit = nullptr;
    Sorted_cloud input;
    read_and_sort<ConcurrencyTag>(points, point_map, normal_map, std::numeric_limits<double>::max(), read_options,
                                  status, input);
    if(input.input_index.empty())
      return status;
    cache.tree.build<ConcurrencyTag>(input.position.data(), input.input_index.size());
    cache.tree.relabel(input.input_index);
    std::copy(input.lo, input.lo + 3, cache.lo);
    std::copy(input.hi, input.hi + 3, cache.hi);
    cache.usable = std::move(input.input_index);
    read_position = std::move(input.position);
    cache.range_size = n;
    cache.filled = true;
  }
  Point_kd_tree& tree = cache.tree;
  const std::size_t m = cache.usable.size();
  // the coordinates of usable point u (rank in input order)
  const auto usable_point = [&](std::size_t u, double x[3]) {
    if(!read_position.empty())
      std::copy(&read_position[3 * u], &read_position[3 * u] + 3, x);
    else
    {
      const auto& p = get(point_map, *std::next(points.begin(), cache.usable[u]));
      x[0] = CGAL::to_double(p.x());
      x[1] = CGAL::to_double(p.y());
      x[2] = CGAL::to_double(p.z());
    }
  };
  if(options.has_tile && k > m && options.tile.halo != std::numeric_limits<double>::infinity())
  {
    // The range holds fewer than k points: its points' k nearest lie (partly) outside, at
    // distances nothing here bounds. Ask for a larger halo. (An infinite halo: the range
    // is the whole cloud, and every point is every point's neighbour, as in one piece.)
    double extent = 0;
    for(int a = 0; a < 3; ++a)
      extent = std::max(extent, cache.hi[a] - cache.lo[a]);
    throw Halo_too_small(std::max({2 * options.tile.halo, extent, std::numeric_limits<double>::min()}),
                         options.tile.halo);
  }
  k = std::min(k, m);  // at least every usable point (and no k + 1 overflow for SIZE_MAX)
  // the bounding box read_and_sort() will grid again, so that the cost model sees its cells
  const double *lo = cache.lo, *hi = cache.hi;
  double side = 1.0;
  bool use_grid = true;
  {
    // the cost model's samples among the points to visit (the automatic scale's later passes
    // visit a few)
    if(options.visit)
    {
      std::vector<double> visited;
      for(std::size_t u = 0; u < m; ++u)
        if((*options.visit)[cache.usable[u]])
        {
          visited.resize(visited.size() + 3);
          usable_point(u, &visited[visited.size() - 3]);
        }
      side = knn_grid_side(
        tree, [&visited](std::size_t i, double x[3]) { std::copy(&visited[3 * i], &visited[3 * i] + 3, x); },
        visited.size() / 3, k, lo, hi, is_parallel<ConcurrencyTag>());
    }
    else
      side = knn_grid_side(tree, usable_point, m, k, lo, hi, is_parallel<ConcurrencyTag>());
    if(side == 0)
    {
      use_grid = false;
      const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
      side = extent > 0 && std::isfinite(extent) ? extent / std::sqrt(double(m)) : 1.0;
    }
  }
  std::vector<double>().swap(read_position);

  // 2. The usable points in the grid of that side; tree ids relabelled to grid positions.
  Sorted_cloud cloud;
  read_and_sort<ConcurrencyTag>(points, point_map, normal_map, side, options, status, cloud);
  CGAL_assertion(cloud.input_index.size() == m);
  {
    std::vector<std::uint32_t> grid_position(n, 0);
    for(std::size_t g = 0; g < m; ++g)
      grid_position[cloud.input_index[g]] = static_cast<std::uint32_t>(g);
    tree.relabel(grid_position);
  }

  // 3. Batches of points: the grid part, then the tree for the points it deferred; the tree's
  //    ids back to input positions for the next pass (not if the visit throws: built again).
  cache.filled = false;
  visit_cloud_knn(cloud, tree, k, use_grid, is_parallel<ConcurrencyTag>(), options, status, visit);
  tree.relabel(cloud.input_index);
  cache.filled = true;
  return status;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
