// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Curvature magnitudes from the Voronoi Covariance Measure (Mérigot, Ovsjanikov, Guibas,
// "Voronoi-based curvature and feature estimation from point clouds", IEEE TVCG 17(6),
// 2011), with the covariance matrices of CGAL::compute_vcm() (CGAL 5.5): CGAL's Delaunay
// triangulation, the cells cut by the ball and integrated by vcm_cells.h, which makes them
// reproducible bit for bit (CGAL's own construction depends on memory addresses).
//
// The VCM of a point p_i is the covariance matrix, about p_i, of its Voronoi cell cut by the
// ball of radius R (the offset radius). Summed over the points of the ball B(x, r) (the
// convolution), it approximates for a smooth surface the integral over the patch
// P = S ∩ B(x, r) of the normal segments of length 2R:
//
//   V = ∫_P ∫_{-R}^{R} t² n(p) n(p)ᵀ (1 - t k1)(1 - t k2) dt dA
//     = (2R³/3) ∫_P n nᵀ dA + O(R⁵).
//
// In the principal frame at x, n(p) = n - k1 u e1 - k2 v e2 + O(ρ²) up to sign, and
// ∫ u² dA = ∫ v² dA = π r⁴/4 over the disc, so
//
//   V ≈ (2π R³ r²/3) [ n nᵀ + (r²/4)(k1² e1 e1ᵀ + k2² e2 e2ᵀ) ]:
//
// the eigenvector of the largest eigenvalue λ_n is the normal, the two others are the
// principal directions, and |k_i| = (2/r) sqrt(λ_i / λ_n). Only magnitudes are available
// (the k_i enter squared), and the pairing of a direction with a signed curvature is lost.
//
// Discretisation bias: each Voronoi cell also spreads tangentially over the sampling
// spacing h, which adds about h²/(4 R²) to every λ_i / λ_n (an isotropic upward bias of
// the magnitudes, sizeable at 40 neighbours: see estimate_vcm_curvatures.h), and the ball
// of radius R is approximated by a 20-face polytope (CGAL's).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_VCM_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_VCM_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/evaluate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/symmetric_eigen_3.h>
#include <CGAL/Point_set_curvatures/internal/vcm_cells.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Below three points (query included) the convolved measure has no tangential spread to
// read two curvatures from.
constexpr std::size_t vcm_min_neighbors = 3;

// |k_min| <= |k_max| (magnitudes), their directions and the normal (eigenvector of the
// largest eigenvalue, oriented like `orientation`) from a convolved VCM `cov`
// (xx xy xz yy yz zz) over a ball of radius `radius`. Mean and Gaussian curvature stay NaN.
inline Local_estimate vcm_curvature_estimate(const std::array<double, 6>& cov, double radius,
                                             const double orientation[3])
{
  double values[3], vectors[3][3];
  if(!symmetric_eigen_3(cov.data(), values, vectors) || !(values[2] > 0))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  double normal[3];
  orient_like(vectors[2], orientation, normal);
  Local_estimate e;
  for(int i = 0; i < 3; ++i)
  {
    e.normal[i] = normal[i];
    e.d_min[i] = vectors[0][i];
    e.d_max[i] = vectors[1][i];
  }
  // |k_i| = (2/r) sqrt(λ_i / λ_n); rounding can leave a tiny negative λ_i
  e.k_min = 2.0 / radius * std::sqrt(std::max(values[0], 0.0) / values[2]);
  e.k_max = 2.0 / radius * std::sqrt(std::max(values[1], 0.0) / values[2]);
  if(!std::isfinite(e.k_min) || !std::isfinite(e.k_max))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

// True if the points span at least a plane (orientation predicates of Epick are exact):
// the Voronoi cells of collinear or coincident points give no surface normal.
template <class Point>
bool spans_a_plane(const std::vector<Point>& points)
{
  const std::size_t n = points.size();
  std::size_t second = 1;
  while(second < n && points[second] == points[0])
    ++second;
  if(second >= n)
    return false;
  for(std::size_t i = second + 1; i < n; ++i)
    if(!CGAL::collinear(points[0], points[second], points[i]))
      return true;
  return false;
}

// Step 1 of estimate_vcm_at_every_point() at one point: its neighbour count, radius, and
// whether the neighbours lack tangent spread or coincide up to rounding
// (neighborhood_below_precision()).
struct Vcm_neighborhood_record
{
  std::uint32_t count = 0;
  double radius = 0;
  bool no_spread = false;
  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;
};
inline Vcm_neighborhood_record vcm_neighborhood_record(const Neighborhood& nb)
{
  Vcm_neighborhood_record r;
  r.count = static_cast<std::uint32_t>(nb.size);
  r.radius = nb.radius;
  r.no_spread = neighborhood_below_precision(nb) || neighborhood_lacks_tangent_spread(nb);
  r.status = Curvature_estimate_status::VALID;
  return r;
}

// Refuses clouds that CGAL's Delaunay triangulation and the cells cannot take: coordinates
// beyond 1e150 (their squares overflow and crash CGAL's exact fallback) or an extent below
// 1e-100 (their squares underflow: the exact fallback then divides by zero, SIGFPE).
inline void check_vcm_coordinates(const std::vector<CGAL::Epick::Point_3>& vcm_points, const char* function_name)
{
  typedef CGAL::Epick::Point_3 Vcm_point;
  for(const Vcm_point& p : vcm_points)
    if(std::abs(p.x()) > 1e150 || std::abs(p.y()) > 1e150 || std::abs(p.z()) > 1e150)
    {
      std::ostringstream msg;
      msg << function_name << ": coordinates beyond 1e150 in absolute value (here " << p
          << ") overflow CGAL's Voronoi covariance measure; translate or scale the cloud";
      throw std::invalid_argument(msg.str());
    }
  {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for(const Vcm_point& p : vcm_points)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    if(extent > 0 && extent < 1e-100)
    {
      std::ostringstream msg;
      msg << function_name << ": a cloud of extent " << extent
          << " (below 1e-100) underflows CGAL's Voronoi covariance measure; scale the cloud";
      throw std::invalid_argument(msg.str());
    }
  }
}

// The Voronoi cells' adjacency: each point's Delaunay neighbours (`neighbors` from
// `neighbor_begin[j]` to `neighbor_begin[j + 1]`, by increasing index) and the point whose
// vertex holds its cell (`cell_of[j]`: itself, or the point it coincides with).
struct Vcm_adjacency
{
  std::vector<std::uint32_t> neighbor_begin, neighbors, cell_of;
};

// CGAL's Delaunay triangulation of the points (coincident points share a vertex, hence a
// cell), each point's neighbours in the order of their index (read sequentially: CGAL's
// incident_vertices() marks the vertices it visits).
inline Vcm_adjacency vcm_adjacency(const std::vector<CGAL::Epick::Point_3>& vcm_points)
{
  typedef CGAL::Epick::Point_3 Vcm_point;
  typedef CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, CGAL::Epick> Vertex_base;
  typedef CGAL::Triangulation_data_structure_3<Vertex_base> Tds;
  typedef CGAL::Delaunay_triangulation_3<CGAL::Epick, Tds> Delaunay;
  const std::size_t m = vcm_points.size();
  Vcm_adjacency a;
  a.neighbor_begin.assign(m + 1, 0);
  a.cell_of.resize(m);
  std::vector<std::pair<Vcm_point, std::uint32_t> > with_index;
  with_index.reserve(m);
  for(std::size_t j = 0; j < m; ++j)
    with_index.emplace_back(vcm_points[j], static_cast<std::uint32_t>(j));
  Delaunay dt(with_index.begin(), with_index.end());
  std::vector<typename Delaunay::Vertex_handle> vertex_of(m);
  std::vector<char> has_vertex(m, 0);
  for(typename Delaunay::Vertex_handle v : dt.finite_vertex_handles())
  {
    vertex_of[v->info()] = v;
    has_vertex[v->info()] = 1;
  }
  std::vector<typename Delaunay::Vertex_handle> around;
  std::vector<std::uint32_t> list;
  for(std::size_t j = 0; j < m; ++j)
  {
    if(!has_vertex[j])  // a point coincident with another one's vertex
      vertex_of[j] = dt.nearest_vertex(vcm_points[j]);
    a.cell_of[j] = vertex_of[j]->info();
    list.clear();
    if(a.cell_of[j] == j)
    {
      around.clear();
      dt.incident_vertices(vertex_of[j], std::back_inserter(around));
      for(const auto& w : around)
        if(!dt.is_infinite(w))
          list.push_back(w->info());
      std::sort(list.begin(), list.end());
    }
    a.neighbors.insert(a.neighbors.end(), list.begin(), list.end());
    a.neighbor_begin[j + 1] = static_cast<std::uint32_t>(a.neighbors.size());
  }
  return a;
}

// The covariance of each point's Voronoi cell cut by the ball of `offset_radius` (vcm_cells.h:
// reproducible bit for bit, in parallel with the tag), in batches of at most 1% of the points
// between reports to `callback` (in [0, 0.5]); false if it cancelled.
template <class ConcurrencyTag>
bool vcm_cell_covariances(const std::vector<CGAL::Epick::Point_3>& vcm_points, const Vcm_adjacency& a,
                          double offset_radius, const std::function<bool(double)>& callback,
                          std::vector<std::array<double, 6> >& cov)
{
  typedef CGAL::Epick::Point_3 Vcm_point;
  const std::size_t m = vcm_points.size();
  cov.assign(m, std::array<double, 6>());
  Vcm_cell_scratch ball_scratch;
  vcm_ball_polytope(offset_radius, ball_scratch);
  const Vcm_polytope ball = ball_scratch.cell;
  Per_thread<std::pair<Vcm_cell_scratch, std::vector<double> > > scratches(is_parallel<ConcurrencyTag>());
  const std::size_t batch = callback ? std::max<std::size_t>(1, (m + 99) / 100) : std::max<std::size_t>(m, 1);
  for(std::size_t first = 0; first < m; first += batch)
  {
    const std::size_t last = std::min(m, first + batch);
    process_in_parallel(is_parallel<ConcurrencyTag>(), first, last, [&](std::uint32_t b, std::uint32_t e) {
      auto& scratch = scratches.local();
      std::vector<double>& d = scratch.second;
      for(std::size_t j = b; j < e; ++j)
      {
        if(a.cell_of[j] != j)
          continue;  // (a coincident point's, copied below)
        const Vcm_point& p = vcm_points[j];
        d.clear();
        for(std::uint32_t k = a.neighbor_begin[j]; k < a.neighbor_begin[j + 1]; ++k)
        {
          const Vcm_point& q = vcm_points[a.neighbors[k]];
          d.push_back(q.x() - p.x());
          d.push_back(q.y() - p.y());
          d.push_back(q.z() - p.z());
        }
        cov[j] = vcm_covariance(ball, d.data(), d.size() / 3, scratch.first);
      }
    });
    if(callback && !callback(0.5 * double(last) / double(m)))
      return false;
  }
  for(std::size_t j = 0; j < m; ++j)
    cov[j] = cov[a.cell_of[j]];
  return true;
}

// The whole estimate_vcm_curvatures(): the neighbourhood driver (statuses, counts, per-point
// radii), the VCM of the usable points (Delaunay triangulation, cells, convolution), then one
// diagonalisation per point.
template <class ConcurrencyTag, class PointRange, class NamedParameters>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_vcm_at_every_point(const PointRange& points, bool radius_given, double radius, const NamedParameters& np,
                            const char* function_name)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  typedef CGAL::Epick::Point_3 Vcm_point;

  const bool by_count = !radius_given;
  const bool offset_given =
    !CGAL::parameters::is_default_parameter<NamedParameters,
                                            Point_set_curvatures::internal_np::vcm_offset_radius_t>::value;
  const double offset_parameter =
    choose_parameter(get_parameter(np, Point_set_curvatures::internal_np::vcm_offset_radius), 0.0);
  if(offset_given && (!(offset_parameter > 0) || !std::isfinite(offset_parameter)))
  {
    std::ostringstream msg;
    msg << function_name << ": parameter 'vcm_offset_radius' must be positive and finite, got " << offset_parameter;
    throw std::invalid_argument(msg.str());
  }
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());

  // 1. The package's neighbourhoods (the same driver as every estimator): statuses of
  // unusable points, counts, per-point radii, and whether they lack tangent spread (one
  // scan line: a curvature is not measured).
  // The cells come from the Delaunay triangulation of the whole cloud, and by count the
  // offset radius is the median radius of the whole cloud: tiles are refused rather than
  // approximated.
  if(!choose_parameter(get_parameter(np, internal_np::tile), Tile::whole_space()).is_whole_space())
    throw std::invalid_argument(std::string(function_name) + ": parameter 'tile' is not supported by VCM");
  const std::size_t min_count = (std::max)(vcm_min_neighbors, min_neighbors_parameter(np, default_min_neighbors::vcm));
  Neighborhood_options options;  // the callback reports the VCM steps below, not this pass
  options.normalize_normals = false;
  options.function_name = function_name;
  const std::vector<Vcm_neighborhood_record> records = evaluate_at_every_point<Vcm_neighborhood_record, ConcurrencyTag>(
    points, radius_given, radius, np, options, &vcm_neighborhood_record);
  const std::size_t n = records.size();
  std::vector<Curvature_estimate<Geom_traits> > results(n);
  for(std::size_t i = 0; i < n; ++i)
    results[i].status = records[i].status;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const auto normal_map = NP_helper::get_normal_map(points, np);

  // 2. Usable points only (non-finite points would break the Delaunay triangulation).
  std::vector<std::size_t> input_index;
  std::vector<Vcm_point> vcm_points;
  std::vector<std::array<double, 3> > orientation;
  {
    std::size_t i = 0;
    for(auto it = points.begin(); it != points.end(); ++it, ++i)
      if(records[i].status == Curvature_estimate_status::VALID)
      {
        const auto& p = get(point_map, *it);
        const auto& v = get(normal_map, *it);
        input_index.push_back(i);
        vcm_points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
        orientation.push_back({CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())});
      }
  }
  const std::size_t m = vcm_points.size();
  if(m == 0)
    return results;
  check_vcm_coordinates(vcm_points, function_name);
  auto set_all = [&](Curvature_estimate_status s) {
    for(std::size_t j = 0; j < m; ++j)
    {
      Curvature_estimate<Geom_traits>& r = results[input_index[j]];
      r.status = s;
      r.neighbor_count = 0;
      if(s == Curvature_estimate_status::DEGENERATE_FIT)
      {
        r.neighbor_count = records[input_index[j]].count;
        if(records[input_index[j]].count < min_count)
          r.status = Curvature_estimate_status::TOO_FEW_NEIGHBORS;
      }
    }
  };
  if(!spans_a_plane(vcm_points))
  {
    set_all(Curvature_estimate_status::DEGENERATE_FIT);
    return results;
  }

  double offset_radius = offset_parameter;
  if(!offset_given)
  {
    if(by_count)  // median of the per-point radii
    {
      std::vector<double> radii(m);
      for(std::size_t j = 0; j < m; ++j)
        radii[j] = records[input_index[j]].radius;
      std::nth_element(radii.begin(), radii.begin() + m / 2, radii.end());
      offset_radius = radii[m / 2];
    }
    else
      offset_radius = radius;
  }
  set_all(Curvature_estimate_status::NOT_COMPUTED);
  if(callback && !callback(0.0))
    return results;

  // 3. The Voronoi cells of the usable points (vcm_adjacency()), cut by the offset ball, and
  // their covariances (vcm_cell_covariances()).
  const Vcm_adjacency adjacency = vcm_adjacency(vcm_points);
  std::vector<std::array<double, 6> > cov;
  if(!vcm_cell_covariances<ConcurrencyTag>(vcm_points, adjacency, offset_radius, callback, cov))
    return results;  // every point NOT_COMPUTED

  // The convolution: each point's matrix is the sum of the cells' over its neighbourhood
  // (by radius, the points at distance at most r, CGAL's convolution; by count, at distance
  // < its own radius, as for the other estimators), summed in the order of the input index.
  typedef CGAL::Simple_cartesian<double>::Point_3 Search_point;
  std::vector<Search_point> search_points;
  typedef boost::iterator_property_map<const Search_point*, boost::typed_identity_property_map<std::uint32_t> >
    Search_map;
  typedef CGAL::Search_traits_adapter<std::uint32_t, Search_map,
                                      CGAL::Search_traits_3<CGAL::Simple_cartesian<double> > >
    Search_traits;
  typedef CGAL::Kd_tree<Search_traits> Tree;
  typedef CGAL::Fuzzy_sphere<Search_traits> Ball;
  std::unique_ptr<Tree> tree;
  {
    search_points.reserve(m);
    for(const Vcm_point& p : vcm_points)
      search_points.emplace_back(p.x(), p.y(), p.z());
    std::vector<std::uint32_t> ids(m);
    for(std::size_t j = 0; j < m; ++j)
      ids[j] = static_cast<std::uint32_t>(j);
    const Search_map search_map(search_points.data());
    tree.reset(new Tree(ids.begin(), ids.end(), typename Tree::Splitter(), Search_traits(search_map)));
    tree->build();
  }

  // 4. One diagonalisation per point.
  auto estimate = [&](std::size_t j, std::vector<std::uint32_t>& found) {
    const std::size_t i = input_index[j];
    Local_estimate e;
    if(records[i].count < min_count)
      e = Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);
    else if(records[i].no_spread)
      e = Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
    else
    {
      const double r = by_count ? records[i].radius : radius;
      const Search_point& x = search_points[j];
      std::array<double, 6> sum = {0, 0, 0, 0, 0, 0};
      found.clear();
      // (the tree's ball, slightly larger, is only a filter: the test below decides)
      tree->search(std::back_inserter(found), Ball(x, r * (1 + 1e-9), 0.0, tree->traits()));
      std::sort(found.begin(), found.end());  // summation order independent of the tree
      for(std::uint32_t f : found)
      {
        const double d2 = CGAL::squared_distance(search_points[f], x);
        if(by_count ? d2 < r * r : d2 <= r * r)
          for(int a = 0; a < 6; ++a)
            sum[a] += cov[f][a];
      }
      e = vcm_curvature_estimate(sum, r, orientation[j].data());
    }
    results[i] = to_curvature_estimate<Geom_traits>(e, records[i].count);
  };
  // batches of at most 1% of the points, as the driver's
  Per_thread<std::vector<std::uint32_t> > found(is_parallel<ConcurrencyTag>());
  const std::size_t batch = callback ? std::max<std::size_t>(1, (m + 99) / 100) : std::max<std::size_t>(m, 1);
  for(std::size_t first = 0; first < m; first += batch)
  {
    const std::size_t last = std::min(m, first + batch);
    process_in_parallel(is_parallel<ConcurrencyTag>(), first, last, [&](std::uint32_t b, std::uint32_t e) {
      std::vector<std::uint32_t>& local = found.local();
      for(std::size_t j = b; j < e; ++j)
        estimate(j, local);
    });
    if(callback && !callback(last == m ? 1.0 : 0.5 + 0.5 * double(last) / double(m)))
      break;  // the points not reached keep NOT_COMPUTED
  }
  return results;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
