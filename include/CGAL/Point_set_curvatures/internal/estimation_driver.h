// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The driver shared by every per-point computation of the package:
//   1. check the radius,
//   2. read points and normals through the property maps, flag unusable points
//      (non-finite coordinates, zero or non-finite normal), which are nobody's neighbour,
//   3. sort the usable points into a Neighbor_grid (copies in sorted order, so the
//      neighbour loops read contiguous memory),
//   4. for every point, gather the points at distance < r into a small reusable buffer
//      in the point's scaled centred frame and hand it to a visitor (the search:
//      radius_neighborhoods.h), sequentially or with TBB (visit_sorted_cloud), reporting
//      progress through `callback` between batches (for_each_batch: the batch rule is
//      documented there).
// Steps 1-3 are templated on the range and the maps, step 4 on the visitor alone (the
// concurrency is a value there): a visitor of a named type, not a lambda defined in a
// function templated on the named parameters, keeps the traversal and the estimator's
// arithmetic compiled once per translation unit (test_core's objects: 124 copies of the
// traversal before this rule, 5 after).
// estimate_at_every_point() (estimate_at_every_point.h) builds the curvature functions on
// it, with knn_neighborhoods.h for neighbourhoods by count.
//
// An estimator is a copyable callable `Local_estimate operator()(const Neighborhood&)
// const` with a member `bool normalize_normals` (Estimator_base); it must not keep state
// between calls. Results do not depend on the concurrency tag nor on the other points of a
// tile (Tile.h): every point sees its neighbours in the same order, that of a lattice of
// cells anchored at the origin (neighbor_grid.h) and, within a cell, of the input.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_ESTIMATION_DRIVER_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_ESTIMATION_DRIVER_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/neighbor_grid.h>
#include <CGAL/Point_set_curvatures/internal/radius_neighborhoods.h>
#include <CGAL/Point_set_curvatures/Tile.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <CGAL/assertions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Common part of the per-point estimators: whether they want unit normals (the driver
// normalises once per point) or the input normals as given; their least neighbour count;
// and whether the driver must
// reject their valid estimates on neighbourhoods without spread in two tangent directions
// (one scan line, a planar curve: one curvature is not measured), which estimators that
// test it with their own moments (ASO, APSS) turn off.
struct Estimator_base
{
  bool normalize_normals = true;
  bool check_tangent_spread = true;
  // The least number of neighbours (query included) of a valid estimate unless the named
  // parameter min_neighbors says otherwise: the estimator's entry of default_min_neighbors
  // (local_estimate.h).
  std::size_t min_neighbors = 12;
  // Whether the driver computes tangent Voronoi areas first and hands them to the estimator
  // (nb.sample_weight), and how many times the estimation reruns on its own normals.
  bool area_weights = false;
  std::size_t normal_refinements = 0;
  // Whether the estimator multiplies its weights by nb.sample_weight, so that weights given
  // with the named parameter sample_weight_map are read (and checked) for it.
  bool takes_weight_map = false;
};

template <class ConcurrencyTag>
constexpr bool is_parallel()
{
  return std::is_convertible<ConcurrencyTag, Parallel_tag>::value;
}

template <class ConcurrencyTag>
void check_concurrency_tag()
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!is_parallel<ConcurrencyTag>(),
                "Error: CGAL::Parallel_tag needs TBB: link with TBB::tbb and define "
                "CGAL_LINKED_WITH_TBB (CMake: target_link_libraries(... CGAL::TBB_support)), "
                "or use CGAL::Sequential_tag.");
#endif
}

// Throws std::invalid_argument unless the radius is positive and finite.
inline void check_radius(double radius, const char* function_name)
{
  if(!(radius > 0) || !std::isfinite(radius))
  {
    std::ostringstream msg;
    msg << function_name << ": parameter 'radius' must be positive and finite, got " << radius;
    throw std::invalid_argument(msg.str());
  }
}

// Neighbourhood scale: a radius (overloads with a radius; neighbor_count must then be
// absent) or a neighbour count (overloads without a radius, `by_count`).
inline void check_scale(double radius, std::size_t k, bool by_count, const char* function_name)
{
  std::ostringstream msg;
  msg << function_name << ": ";
  if(by_count && k == 0)
    msg << "without a radius, give the neighbour count with "
           "CGAL::Point_set_curvatures::parameters::neighbor_count(k), k >= 1";
  else if(!by_count && k != 0)
    msg << "give either a radius or neighbor_count, not both";
  else
  {
    if(!by_count)
      check_radius(radius, function_name);
    return;
  }
  throw std::invalid_argument(msg.str());
}

// Converts a Local_estimate to the user's kernel.
template <class GeomTraits>
Curvature_estimate<GeomTraits> to_curvature_estimate(const Local_estimate& e, std::size_t count)
{
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Vector_3 Vector_3;
  Curvature_estimate<GeomTraits> r;
  r.neighbor_count = e.neighbor_count > 0 ? e.neighbor_count : count;
  r.status = e.status;
  // NaN marks a quantity the estimator does not provide; an infinite value is an overflow
  // (e.g. K = k_min k_max for curvatures near 1e160): never hand it out as valid.
  const double fields[] = {e.normal[0], e.normal[1], e.normal[2], e.mean,     e.gaussian, e.k_min,   e.k_max,
                           e.d_min[0],  e.d_min[1],  e.d_min[2],  e.d_max[0], e.d_max[1], e.d_max[2]};
  for(double f : fields)
    if(std::isinf(f))
      r.status = Curvature_estimate_status::DEGENERATE_FIT;
  if(r.status != Curvature_estimate_status::VALID)
    return r;  // every numeric field stays NaN
  r.normal = Vector_3(FT(e.normal[0]), FT(e.normal[1]), FT(e.normal[2]));
  r.mean_curvature = FT(e.mean);
  r.gaussian_curvature = FT(e.gaussian);
  r.min_curvature = FT(e.k_min);
  r.max_curvature = FT(e.k_max);
  r.min_direction = Vector_3(FT(e.d_min[0]), FT(e.d_min[1]), FT(e.d_min[2]));
  r.max_direction = Vector_3(FT(e.d_max[0]), FT(e.d_max[1]), FT(e.d_max[2]));
  r.normal_coherence = FT(e.normal_coherence);
  r.mean_curvature_error = FT(e.mean_error);
  return r;
}

struct Knn_search_cache;

// Options of the driver (for_each_neighborhood(), for_each_neighborhood_knn()).
struct Neighborhood_options
{
  bool normalize_normals = true;  // hand unit normals to the visitor
  // normals of length outside [1e-3, 1e3] are INVALID_NORMAL (accept_unnormalized_normals)
  bool check_normal_length = true;
  std::function<bool(double)> callback;                // progress in [0,1]; false cancels
  const char* function_name = "Point_set_curvatures";  // for error messages
  // A tile (Tile.h): only its own points are visited; `halo_radii` is how far, in radii, an
  // estimate depends on other points (1: its neighbourhood), which the halo must cover.
  bool has_tile = false;
  Tile tile;
  double halo_radii = 1;
  // Per input point, a weight the visitor receives per neighbour (nb.sample_weight), or null.
  const std::vector<double>* point_weights = nullptr;
  // With a tile by count: per input point, how far from the core the points its weight depends
  // on lie (a neighbour's area), or null. A neighbour reaching beyond the halo makes the search
  // ask for a larger halo, as a neighbour beyond it does, before any estimate is computed.
  const std::vector<double>* point_reach = nullptr;
  // Per input point, whether it is visited (non-zero), or null for every point: the others
  // (of the tile's own points) stay NOT_COMPUTED but are neighbours as usual.
  const std::vector<char>* visit = nullptr;
  // Neighbourhoods by count: the search's k-d tree, kept for the next pass over the same range
  // and maps (knn_neighborhoods.h), or null.
  Knn_search_cache* knn_cache = nullptr;
};

// `callback` wrapped so that `cancelled` tells whether it stopped the work: it returned false
// before the end (false at the last report, 1, cancels nothing). Empty stays empty.
inline std::function<bool(double)> noting_cancellation(const std::function<bool(double)>& callback, bool& cancelled)
{
  if(!callback)
    return callback;
  return [callback, &cancelled](double f) {
    const bool go_on = callback(f);
    cancelled = cancelled || (!go_on && f < 1.0);
    return go_on;
  };
}

// Usable normal: non-zero, finite and, unless accepted, of length in [1e-3, 1e3].
inline bool usable_normal(double squared_length, bool check_length)
{
  if(!(squared_length > 0) || !std::isfinite(squared_length))
    return false;
  return !check_length || (squared_length >= 1e-6 && squared_length <= 1e6);
}

// Runs f(first, last) over [0, n): in one piece, or in chunks of about `grain` indices (at
// least) on TBB's threads.
template <class ConcurrencyTag, class Function>
void for_index_chunks(std::size_t n, const Function& f, std::size_t grain = 4096)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(is_parallel<ConcurrencyTag>())
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#endif
  f(std::size_t(0), n);
}

// Reads the range through the maps, sets the status of unusable points and returns the
// usable points sorted in a grid of cell size >= radius, with unit normals if
// `options.normalize_normals`, and the tile's own points flagged. Every pass is parallel
// with Parallel_tag; the result does not depend on the tag (ties in the sort are broken by
// input position).
template <class ConcurrencyTag, class PointRange, class PointMap, class NormalMap>
void read_and_sort(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius,
                   const Neighborhood_options& options, std::vector<Curvature_estimate_status>& status,
                   Sorted_cloud& cloud)
{
  const bool normalize_normals = options.normalize_normals;
  typedef typename PointRange::const_iterator Iterator;
  typedef typename std::iterator_traits<Iterator>::iterator_category Category;
  constexpr bool random_access = std::is_convertible<Category, std::random_access_iterator_tag>::value;
  const std::size_t n = status.size();
  if(n >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("Point_set_curvatures: more than 2^32 - 1 points are not supported");

  // Element i of the range: direct for random access ranges, through a table otherwise.
  std::vector<Iterator> iterators;
  if(!random_access)
  {
    iterators.reserve(n);
    for(Iterator it = points.begin(); it != points.end(); ++it)
      iterators.push_back(it);
  }
  auto item = [&](std::size_t i) -> decltype(*points.begin()) {
    return random_access ? *std::next(points.begin(), i) : *iterators[i];
  };
  auto coordinates = [&](std::size_t i, double x[3]) {
    const auto& p = get(point_map, item(i));
    x[0] = CGAL::to_double(p.x());
    x[1] = CGAL::to_double(p.y());
    x[2] = CGAL::to_double(p.z());
  };

  // Pass 1: usable points and their bounding box.
  const double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  std::size_t n_usable = 0;
  std::mutex merge;
  for_index_chunks<ConcurrencyTag>(n, [&](std::size_t first, std::size_t last) {
    double clo[3] = {inf, inf, inf}, chi[3] = {-inf, -inf, -inf};
    std::size_t count = 0;
    for(std::size_t i = first; i < last; ++i)
    {
      double x[3];
      coordinates(i, x);
      if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      {
        status[i] = Curvature_estimate_status::NON_FINITE_POINT;
        continue;
      }
      const auto& v = get(normal_map, item(i));
      const double nv[3] = {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
      const double nn = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
      if(!usable_normal(nn, options.check_normal_length))
      {
        status[i] = Curvature_estimate_status::INVALID_NORMAL;
        continue;
      }
      ++count;
      for(int a = 0; a < 3; ++a)
      {
        clo[a] = std::min(clo[a], x[a]);
        chi[a] = std::max(chi[a], x[a]);
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    n_usable += count;
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], clo[a]);
      hi[a] = std::max(hi[a], chi[a]);
    }
  });
  if(n_usable == 0)
    return;
  std::copy(lo, lo + 3, cloud.lo);
  std::copy(hi, hi + 3, cloud.hi);

  // Pass 2: cell keys, sorted; unusable points get the largest key and are dropped.
  cloud.grid.set_geometry(lo, hi, radius);
  std::vector<Neighbor_grid::Keyed_index> keyed(n);
  for_index_chunks<ConcurrencyTag>(n, [&](std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
    {
      Neighbor_grid::Key key = std::numeric_limits<Neighbor_grid::Key>::max();
      if(status[i] == Curvature_estimate_status::NOT_COMPUTED)  // usable
      {
        double x[3];
        coordinates(i, x);
        key = cloud.grid.key(x[0], x[1], x[2]);
      }
      keyed[i] = Neighbor_grid::Keyed_index(key, static_cast<std::uint32_t>(i));
    }
  });
  // the usable points, in input order (so that the sort breaks ties by input position)
  keyed.erase(std::remove_if(keyed.begin(), keyed.end(),
                             [](const Neighbor_grid::Keyed_index& e) {
                               return e.first == std::numeric_limits<Neighbor_grid::Key>::max();
                             }),
              keyed.end());
  CGAL_assertion(keyed.size() == n_usable);
  {
    std::vector<Neighbor_grid::Keyed_index> scratch;
    // the sort's chunks are few and large: one per task
    sort_by_key_then_index(keyed, scratch, [](std::size_t chunks, const auto& f) {
      for_index_chunks<ConcurrencyTag>(
        chunks,
        [&f](std::size_t first, std::size_t last) {
          for(std::size_t c = first; c < last; ++c)
            f(c);
        },
        1);
    });
  }
  cloud.grid.set_cells(keyed);
  cloud.input_index.resize(n_usable);
  for_index_chunks<ConcurrencyTag>(n_usable, [&](std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k)
      cloud.input_index[k] = keyed[k].second;
  });
  std::vector<Neighbor_grid::Keyed_index>().swap(keyed);

  // Pass 3: coordinates and normals in grid order.
  cloud.position.resize(3 * n_usable);
  cloud.normal.resize(3 * n_usable);
  for_index_chunks<ConcurrencyTag>(n_usable, [&](std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k)
    {
      const std::size_t i = cloud.input_index[k];
      coordinates(i, &cloud.position[3 * k]);
      const auto& v = get(normal_map, item(i));
      double* nv = &cloud.normal[3 * k];
      nv[0] = CGAL::to_double(v.x());
      nv[1] = CGAL::to_double(v.y());
      nv[2] = CGAL::to_double(v.z());
      if(normalize_normals)
      {
        const double inv = 1.0 / std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        nv[0] *= inv;
        nv[1] *= inv;
        nv[2] *= inv;
      }
    }
  });

  // Per-point values given in input order (sample weights, the weights' reach), in grid order.
  auto to_grid_order = [&](const std::vector<double>& given, std::vector<double>& out) {
    out.resize(n_usable);
    for_index_chunks<ConcurrencyTag>(n_usable, [&](std::size_t first, std::size_t last) {
      for(std::size_t k = first; k < last; ++k)
        out[k] = given[cloud.input_index[k]];
    });
  };
  if(options.point_weights)
    to_grid_order(*options.point_weights, cloud.sample_weight);
  if(options.point_reach && options.has_tile)
    to_grid_order(*options.point_reach, cloud.reach);

  // The tile's own points (among those to visit).
  cloud.own_count = n_usable;
  if(options.has_tile || options.visit)
  {
    cloud.own.assign(n_usable, 0);
    for_index_chunks<ConcurrencyTag>(n_usable, [&](std::size_t first, std::size_t last) {
      for(std::size_t k = first; k < last; ++k)
      {
        const double* x = &cloud.position[3 * k];
        cloud.own[k] = (!options.has_tile || options.tile.owns(x[0], x[1], x[2])) &&
                           (!options.visit || (*options.visit)[cloud.input_index[k]])
                         ? 1
                         : 0;
      }
    });
    cloud.own_count = static_cast<std::size_t>(std::count(cloud.own.begin(), cloud.own.end(), char(1)));
  }
}

// Calls process(first, last) on ranges of positions covering [begin, end) of the grid order:
// one range, or (`parallel`: Parallel_tag) ranges processed concurrently by TBB's threads,
// small enough that the points of one cell, however many, are shared between threads.
// (The traversal takes the concurrency as a value, not as the tag: its code, with the
// estimator's arithmetic inlined, is compiled once for both tags.)
template <class Process>
void process_in_parallel(bool parallel, std::size_t begin, std::size_t end, const Process& process)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && end - begin > 1)
  {
    const std::size_t grain = std::max<std::size_t>(
      1, (end - begin) / (64 * std::size_t(std::max(1, tbb::this_task_arena::max_concurrency()))));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        process(static_cast<std::uint32_t>(r.begin()), static_cast<std::uint32_t>(r.end()));
                      });
    return;
  }
#else
  (void)parallel;
#endif
  process(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end));
}

// Scratch of the traversals: one T per thread that asks for it when `parallel`, else a single
// one.
template <class T>
class Per_thread
{
public:
  explicit Per_thread(bool parallel) : m_parallel(parallel) {}
  T& local()
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(m_parallel)
      return m_per_thread.local();
#endif
    return m_sequential;
  }

private:
  bool m_parallel;
  T m_sequential;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<T> m_per_thread;
#endif
};

// The batch loop of the drivers: runs `process(first, last)` over the grid positions of
// cloud.grid, then `finish(first, last)` from the calling thread, batch after batch; marks
// the own points of each batch VALID and reports progress. Without a callback, one batch.
// With a callback, the rule the documentation states: `callback(fraction of the own points
// done)` is called from the calling thread after every batch; a batch holds at most 1% of
// the points (rounded up), and fewer when the previous batches ran slower than 0.25 s per
// 1%: a batch is sized to take about 0.25 s at the speed measured so far (at least one point
// per thread). So the callback comes at least every 1% of the points and, on large inputs,
// about every 0.25 s, whatever the cell sizes (a single point taking longer delays it). It
// gets 1 after the last batch; returning false cancels, leaving the points not reached
// NOT_COMPUTED.
template <class Process, class Finish>
void for_each_batch(bool parallel, const Sorted_cloud& cloud, const std::function<bool(double)>& callback,
                    std::vector<Curvature_estimate_status>& status, Process process, Finish finish)
{
  typedef std::chrono::steady_clock Clock;
  const std::size_t n_points = cloud.grid.number_of_points();
  const double n_own = double(std::max<std::size_t>(cloud.own_count, 1));
  // batches are counted in points to estimate (own points, with a tile): 1% of them
  const std::size_t max_batch = callback ? std::max<std::size_t>(1, (cloud.own_count + 99) / 100) : n_points;
  std::size_t min_batch = 1;
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
    min_batch = std::size_t(std::max(1, tbb::this_task_arena::max_concurrency()));
#endif
  std::size_t batch = callback ? std::min(max_batch, 64 * min_batch) : n_points;
  std::size_t own_done = 0;
  for(std::size_t first = 0; first < n_points;)
  {
    std::size_t last = std::min(n_points, first + batch);
    if(!cloud.own.empty())  // `batch` own points, however many other points lie between them
    {
      std::size_t own = 0;
      last = first;
      while(last < n_points && own < batch)
        own += cloud.own[last++] ? 1 : 0;
      while(last < n_points && !cloud.own[last])
        ++last;  // the points after the last own one cost nothing
    }
    const Clock::time_point start = Clock::now();
    const std::size_t own_before = own_done;
    process_in_parallel(parallel, first, last, process);
    finish(static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last));
    for(std::size_t k = first; k < last; ++k)
      if(cloud.is_own(k))
      {
        status[cloud.input_index[k]] = Curvature_estimate_status::VALID;
        ++own_done;
      }
    const std::size_t done = std::max<std::size_t>(1, cloud.own.empty() ? last - first : own_done - own_before);
    first = last;
    if(callback)
    {
      if(!callback(first == n_points ? 1.0 : double(own_done) / n_own))
        break;
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      const double wanted = seconds > 0 ? double(done) * 0.25 / seconds : double(max_batch);
      batch = static_cast<std::size_t>(std::max(double(min_batch), std::min(double(max_batch), wanted)));
    }
  }
}

// Throws unless a tile's halo covers the reach of its estimates with a fixed radius.
inline void check_tile_halo(const Neighborhood_options& options, double radius)
{
  if(options.has_tile && !(options.tile.halo >= options.halo_radii * radius))
  {
    std::ostringstream msg;
    msg.precision(17);
    msg << options.function_name << ": parameter 'tile': the halo " << options.tile.halo << " must be at least "
        << options.halo_radii * radius << " (" << options.halo_radii << " times the radius) for exact results";
    throw std::invalid_argument(msg.str());
  }
}

// A visitor may leave part of its work to the end of a range of points (Store_results
// writes its results there, together): the traversals call end_of_range() on their copy of
// the visitor after each range, when it has one.
template <class Visitor, class = void>
struct Has_end_of_range : std::false_type
{};
template <class Visitor>
struct Has_end_of_range<Visitor, std::void_t<decltype(std::declval<Visitor&>().end_of_range())> > : std::true_type
{};
template <class Visitor>
void end_of_range(Visitor& visit)
{
  if constexpr(Has_end_of_range<Visitor>::value)
    visit.end_of_range();
}

// The traversal of the driver: calls `visit(input_index, nb)` for every own point of `cloud`
// (sorted in a grid for `radius`) with its neighbours at distance < radius, from several
// threads at once if `parallel` (a copy of `visit` per batch and thread); marks the points
// visited VALID in `status`. Templated on the visitor only: every public function that uses
// the same visitor type shares this code, whatever its ranges, maps and named parameters.
template <class Visitor>
void visit_sorted_cloud(const Sorted_cloud& cloud, double radius, bool parallel,
                        const std::function<bool(double)>& callback, std::vector<Curvature_estimate_status>& status,
                        const Visitor& visit)
{
  Per_thread<Neighbor_buffer> buffers(parallel);
  for_each_batch(
    parallel, cloud, callback, status,
    [&](std::uint32_t first, std::uint32_t last) {
      Visitor local = visit;
      visit_points(cloud, radius, first, last, buffers.local(), local);
      internal::end_of_range(local);
    },
    [](std::uint32_t, std::uint32_t) {});
}

// The driver. Calls `visit(input_index, nb)` for every usable point of `points` with the
// points at distance < radius (itself included) in its scaled centred frame; with
// Parallel_tag, from several threads at once (distinct indices). Returns, per input point,
// VALID if it was visited, NON_FINITE_POINT or INVALID_NORMAL if it is unusable (then it is
// nobody's neighbour), NOT_COMPUTED if the callback cancelled the run first or if it is not
// one of the tile's own points.
// Throws std::invalid_argument for a radius that is not positive and finite, or a tile
// whose halo is smaller than the radius.
template <class ConcurrencyTag, class PointRange, class PointMap, class NormalMap, class Visitor>
std::vector<Curvature_estimate_status> for_each_neighborhood(const PointRange& points, PointMap point_map,
                                                             NormalMap normal_map, double radius,
                                                             const Neighborhood_options& options, const Visitor& visit)
{
  check_concurrency_tag<ConcurrencyTag>();
  check_radius(radius, options.function_name);
  check_tile_halo(options, radius);
  const std::size_t n = static_cast<std::size_t>(std::distance(points.begin(), points.end()));
  std::vector<Curvature_estimate_status> status(n, Curvature_estimate_status::NOT_COMPUTED);
  if(n == 0)
    return status;

  Sorted_cloud cloud;
  read_and_sort<ConcurrencyTag>(points, point_map, normal_map, radius, options, status, cloud);
  visit_sorted_cloud(cloud, radius, is_parallel<ConcurrencyTag>(), options.callback, status, visit);
  return status;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
