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
// The k nearest are found with a CGAL Kd_tree (Orthogonal_k_neighbor_search) built once on
// the usable points in Hilbert order and queried concurrently; the k+1-th nearest tells
// whether there are ties beyond the k-th, in which case a Fuzzy_sphere range query gathers
// the whole ball. Every neighbourhood lists its points by increasing (distance, Hilbert
// rank): results do not depend on the concurrency tag.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_KNN_NEIGHBORHOODS_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_KNN_NEIGHBORHOODS_H

#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The usable points of a Sorted_cloud as CGAL points, for the spatial searching, keyed by
// their position in the cloud's order.
class Knn_search
{
public:
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point;

  struct Point_map
  {
    typedef std::uint32_t key_type;
    typedef Point value_type;
    typedef const Point& reference;
    typedef boost::lvalue_property_map_tag category;
    const Point* points = nullptr;
    friend reference get(const Point_map& m, key_type i) { return m.points[i]; }
  };

  typedef CGAL::Search_traits_adapter<std::uint32_t, Point_map, CGAL::Search_traits_3<Kernel> > Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> K_search;
  typedef K_search::Tree Tree;
  typedef K_search::Distance Distance;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

  // (squared distance, index in cloud order)
  typedef std::pair<double, std::uint32_t> Candidate;

  // Builds the tree on points[0..n) (kept by pointer: they must outlive the search).
  template <class ConcurrencyTag>
  void build(const std::vector<Point>& points)
  {
    m_points = points.data();
    m_map.points = m_points;
    std::vector<std::uint32_t> keys(points.size());
    std::iota(keys.begin(), keys.end(), std::uint32_t(0));
    m_tree.reset(new Tree(keys.begin(), keys.end(), typename Tree::Splitter(), Traits(m_map)));
    // built here, once: a lazy build on the first query would race between threads
    m_tree->template build<ConcurrencyTag>();
  }

  std::size_t size() const { return m_tree ? m_tree->size() : 0; }
  const Point& point(std::uint32_t i) const { return m_points[i]; }

  double squared_distance(std::uint32_t i, std::uint32_t j) const
  {
    // the same expression, in the same order, as the gathering below, so that a point
    // found at d2 by one is found at d2 by the other
    const double dx = m_points[j].x() - m_points[i].x();
    const double dy = m_points[j].y() - m_points[i].y();
    const double dz = m_points[j].z() - m_points[i].z();
    return dx * dx + dy * dy + dz * dz;
  }

  // The `count` nearest points of point i (itself included), by increasing (d2, index).
  void nearest(std::uint32_t i, std::size_t count, std::vector<Candidate>& out) const
  {
    out.clear();
    K_search search(*m_tree, m_points[i], static_cast<unsigned int>(count), 0.0, true,
                    Distance(m_map), false);
    for(auto it = search.begin(); it != search.end(); ++it)
      out.emplace_back(squared_distance(i, it->first), it->first);
    std::sort(out.begin(), out.end());
  }

  // The points at squared distance < r2 from point i, by increasing (d2, index).
  void ball(std::uint32_t i, double radius, double r2, std::vector<std::uint32_t>& keys,
            std::vector<Candidate>& out) const
  {
    keys.clear();
    out.clear();
    // Fuzzy_sphere with epsilon 0 reports the closed ball; the open one is kept below
    m_tree->search(std::back_inserter(keys), Sphere(m_points[i], radius, 0.0, Traits(m_map)));
    for(std::uint32_t j : keys)
    {
      const double d2 = squared_distance(i, j);
      if(d2 < r2)
        out.emplace_back(d2, j);
    }
    std::sort(out.begin(), out.end());
  }

private:
  const Point* m_points = nullptr;
  Point_map m_map;
  std::unique_ptr<Tree> m_tree;
};

// Relative enlargement of d_k (see the header comment): large enough to absorb rounding
// in the distances of equidistant points, small enough to leave the fit unchanged.
constexpr double knn_radius_factor = 1.0 + 1.0 / 1048576.0;

// The radius of point i and its neighbourhood (points at distance < radius) in
// `neighbors`, following the semantics of the header comment.
inline double knn_neighborhood(const Knn_search& search, std::uint32_t i, std::size_t k,
                               std::vector<Knn_search::Candidate>& neighbors,
                               std::vector<std::uint32_t>& keys)
{
  const std::size_t n = search.size();
  std::size_t count = k < n ? k + 1 : n;
  search.nearest(i, count, neighbors);
  if(n <= k)
  {
    // every point: the radius reaches just beyond the farthest one
    const double d2_max = neighbors.back().first;
    return d2_max > 0 ? knn_radius_factor * std::sqrt(d2_max) : 1.0;
  }
  double d2_k = neighbors[k - 1].first;
  bool ties_beyond = false;
  if(d2_k == 0)
  {
    // k copies of x: the nearest point elsewhere sets the scale
    while(neighbors.back().first == 0 && count < n)
    {
      count = std::min(2 * count, n);
      search.nearest(i, count, neighbors);
    }
    const auto elsewhere = std::find_if(neighbors.begin(), neighbors.end(),
                                        [](const Knn_search::Candidate& c) { return c.first > 0; });
    if(elsewhere == neighbors.end())
      return 1.0;  // every usable point is at x
    d2_k = elsewhere->first;
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
    search.ball(i, radius, r2, keys, neighbors);
  return radius;
}

// Same contract as for_each_neighborhood() (validation, statuses, visitor, callback between
// batches of about 1% of the points, identical results with either concurrency tag), with
// a per-point radius: nb.radius is (1 + 2^-20) times the distance from the point to its
// k-th nearest usable point (itself counted as the first), and nb holds every usable point
// at distance < nb.radius, so at least min(k, number of usable points) points. See the
// header comment for ties and coincident points.
// Throws std::invalid_argument if k is 0.
template <class ConcurrencyTag, class PointRange, class PointMap, class NormalMap, class Visitor>
std::vector<Curvature_estimate_status>
for_each_neighborhood_knn(const PointRange& points, PointMap point_map, NormalMap normal_map,
                          std::size_t k, const Neighborhood_options& options, Visitor visit)
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

  // Validation, statuses and (unit) normals as for_each_neighborhood(). A radius larger than
  // any extent gives a single grid cell, i.e. the usable points in input order: the radii
  // are not known yet, and the Hilbert order below replaces the grid's spatial order.
  Sorted_cloud cloud;
  read_and_sort<ConcurrencyTag>(points, point_map, normal_map,
                                std::numeric_limits<double>::max(), options.normalize_normals,
                                status, cloud);
  const std::size_t m = cloud.input_index.size();
  if(m == 0)
    return status;

  // Hilbert order: queries that follow each other, and the neighbours of one query, are
  // close in memory. CGAL's Hilbert sort is deterministic (fixed shuffle seed, median
  // policy) and gives the same order with either tag.
  typedef Knn_search::Point Point;
  std::vector<Point> sorted_points;
  {
    std::vector<Point> input_points;
    input_points.reserve(m);
    for(std::size_t i = 0; i < m; ++i)
      input_points.emplace_back(cloud.position[3 * i], cloud.position[3 * i + 1],
                                cloud.position[3 * i + 2]);
    std::vector<std::uint32_t> order(m);
    std::iota(order.begin(), order.end(), std::uint32_t(0));
    typedef CGAL::Spatial_sort_traits_adapter_3<
      Knn_search::Kernel, boost::iterator_property_map<const Point*,
                                                       boost::typed_identity_property_map<std::uint32_t> > >
      Sort_traits;
    CGAL::hilbert_sort<ConcurrencyTag>(order.begin(), order.end(),
                                       Sort_traits(boost::make_iterator_property_map(
                                         static_cast<const Point*>(input_points.data()),
                                         boost::typed_identity_property_map<std::uint32_t>())));
    std::vector<std::uint32_t> input_index(m);
    std::vector<double> normal(3 * m);
    sorted_points.reserve(m);
    for(std::size_t r = 0; r < m; ++r)
    {
      const std::uint32_t i = order[r];
      input_index[r] = cloud.input_index[i];
      sorted_points.push_back(input_points[i]);
      for(int a = 0; a < 3; ++a)
        normal[3 * r + a] = cloud.normal[3 * i + a];
    }
    cloud.input_index.swap(input_index);
    cloud.normal.swap(normal);
    std::vector<double>().swap(cloud.position);  // sorted_points holds the positions now
  }

  Knn_search search;
  search.template build<ConcurrencyTag>(sorted_points);

  struct Scratch
  {
    Neighbor_buffer buffer;
    std::vector<Knn_search::Candidate> neighbors;
    std::vector<std::uint32_t> keys;
  };
  const double* normal = cloud.normal.data();
  auto visit_range = [&](std::size_t first, std::size_t last, Scratch& scratch, Visitor& visitor) {
    for(std::size_t q = first; q < last; ++q)
    {
      const std::uint32_t query = static_cast<std::uint32_t>(q);
      const double radius = knn_neighborhood(search, query, k, scratch.neighbors, scratch.keys);
      const std::size_t size = scratch.neighbors.size();
      scratch.buffer.set_size(0);  // nothing to keep when the buffer grows
      scratch.buffer.reserve(size);
      double *qx = scratch.buffer.column(0), *qy = scratch.buffer.column(1), *qz = scratch.buffer.column(2);
      double *nx = scratch.buffer.column(3), *ny = scratch.buffer.column(4), *nz = scratch.buffer.column(5);
      const Point& x = search.point(query);
      const double inv_r = 1.0 / radius;
      for(std::size_t s = 0; s < size; ++s)
      {
        const std::uint32_t j = scratch.neighbors[s].second;
        const Point& p = search.point(j);
        qx[s] = (p.x() - x.x()) * inv_r;
        qy[s] = (p.y() - x.y()) * inv_r;
        qz[s] = (p.z() - x.z()) * inv_r;
        nx[s] = normal[3 * j]; ny[s] = normal[3 * j + 1]; nz[s] = normal[3 * j + 2];
      }
      scratch.buffer.set_size(size);
      Neighborhood nb;
      nb.size = size;
      nb.qx = qx; nb.qy = qy; nb.qz = qz;
      nb.nx = nx; nb.ny = ny; nb.nz = nz;
      nb.radius = radius;
      nb.center[0] = x.x(); nb.center[1] = x.y(); nb.center[2] = x.z();
      for(int a = 0; a < 3; ++a)
        nb.query_normal[a] = normal[3 * query + a];
      visitor(std::size_t(cloud.input_index[query]), static_cast<const Neighborhood&>(nb));
    }
  };

  // Batches between two progress reports, as in for_each_neighborhood().
  const std::size_t batch_points =
    options.callback ? std::max<std::size_t>(16384, m / 100) : m;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<Scratch> scratches;
#endif
  Scratch sequential_scratch;
  for(std::size_t first = 0; first < m;)
  {
    const std::size_t last = std::min(m, first + batch_points);
#ifdef CGAL_LINKED_WITH_TBB
    if(is_parallel<ConcurrencyTag>())
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 256),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Visitor local = visit;
                          visit_range(range.begin(), range.end(), scratches.local(), local);
                        });
    else
#endif
      visit_range(first, last, sequential_scratch, visit);

    for(std::size_t q = first; q < last; ++q)
      status[cloud.input_index[q]] = Curvature_estimate_status::VALID;
    first = last;
    if(options.callback && !options.callback(double(first) / double(m)))
      break;  // cancelled: the points not reached keep the NOT_COMPUTED status
  }
  return status;
}

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
