// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The passes of every estimate_*_curvatures() function (estimate_at_every_point()): the
// tangent Voronoi areas, the normal refinements, the estimation, on the common body of the
// per-point functions (evaluate_at_every_point.h).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_ESTIMATE_AT_EVERY_POINT_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_ESTIMATE_AT_EVERY_POINT_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/evaluate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/internal/tangent_voronoi_area.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// One point's record of tangent_voronoi_areas(), and its evaluation.
struct Area_record
{
  double value = 0;
  double reach = 0;
  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;
};
struct Area_at_point
{
  const Tile* tile;  // with a tile by count, else null
  Area_record operator()(const Neighborhood& nb) const
  {
    thread_local Tangent_cell_scratch scratch;
    Area_record a;
    a.value = tangent_voronoi_area(nb, 0.5, scratch);
    if(tile)
      a.reach = tile->distance_to_core(nb.center[0], nb.center[1], nb.center[2]) + nb.radius;
    a.status = Curvature_estimate_status::VALID;
    return a;
  }
};

// Per input point, the area of its tangent Voronoi cell (tangent_voronoi_area.h) among its
// neighbours, 0 for unusable points. The neighbourhoods are a quarter of the estimation's
// (radius r/2, or the k/4 nearest): a cell only depends on the nearest samples, and the
// square that bounds it (half-side a quarter of the estimation's radius) is reached only
// where samples are sparse. 5 times cheaper than the estimation's neighbourhoods for the same
// areas to 1e-3 on the Goursat clouds (measured in the session that introduced them).
//
// With `tile` (neighbourhoods by count on a tile's range), `reach` receives per point the
// distance from the core to the farthest point its area depends on (its distance to the
// core plus its neighbourhood's radius; 0 for unusable points): the area is the whole-cloud
// one wherever that reach is within the halo.
template <class ConcurrencyTag, class PointRange, class PointMap, class NormalMap>
std::vector<double> tangent_voronoi_areas(const PointRange& points, bool radius_given, double radius, std::size_t k,
                                          PointMap point_map, NormalMap normal_map, const Neighborhood_options& options,
                                          const Tile* tile = nullptr, std::vector<double>* reach = nullptr)
{
  const std::vector<Area_record> records =
    evaluate_with_maps<Area_record, ConcurrencyTag>(points, radius_given, 0.5 * radius, std::max<std::size_t>(6, k / 4),
                                                    point_map, normal_map, options, Area_at_point{tile});
  std::vector<double> areas(records.size());
  for(std::size_t i = 0; i < records.size(); ++i)
    areas[i] = records[i].status == Curvature_estimate_status::VALID ? records[i].value : 0.0;
  if(reach)
  {
    reach->resize(records.size());
    for(std::size_t i = 0; i < records.size(); ++i)
      (*reach)[i] = records[i].status == Curvature_estimate_status::VALID ? records[i].reach : 0.0;
  }
  return areas;
}

// Whether the named parameters hold sample_weight_map (weights given by the user).
template <class NamedParameters>
constexpr bool has_sample_weight_map()
{
  return !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::sample_weight_map_t>::value;
}

// The weights of the named parameter sample_weight_map, in range order (empty without it).
// Throws std::invalid_argument for a weight that is not finite and non-negative.
template <class PointRange, class NamedParameters>
std::vector<double> given_sample_weights(const PointRange& points, const NamedParameters& np, const char* function_name)
{
  std::vector<double> weights;
  if constexpr(has_sample_weight_map<NamedParameters>())
  {
    const auto map = CGAL::parameters::get_parameter(np, internal_np::sample_weight_map);
    for(auto it = points.begin(); it != points.end(); ++it)
    {
      const double a = CGAL::to_double(get(map, *it));
      if(!(a >= 0) || !std::isfinite(a))
      {
        std::ostringstream msg;
        msg << function_name << ": parameter 'sample_weight_map': the weight of point " << weights.size() << " is " << a
            << ", weights must be finite and non-negative";
        throw std::invalid_argument(msg.str());
      }
      weights.push_back(a);
    }
  }
  return weights;
}

// The largest value given to update(), from any thread.
class Atomic_max
{
public:
  void update(double v)
  {
    double current = m_value.load();
    while(v > current && !m_value.compare_exchange_weak(current, v))
    {}
  }
  double value() const { return m_value.load(); }

private:
  std::atomic<double> m_value{0.0};
};

// The normal fit of a refinement pass: estimator.refinement_fit(nb) where the estimator has
// one (the ASO: its APSS sphere with the wider kernel), else the estimator itself.
template <class Estimator, class = void>
struct Has_refinement_fit : std::false_type
{};
template <class Estimator>
struct Has_refinement_fit<Estimator, std::void_t<decltype(std::declval<const Estimator&>().refinement_fit(
                                       std::declval<const Neighborhood&>()))> > : std::true_type
{};
template <class Estimator>
Local_estimate refinement_estimate(const Estimator& estimator, const Neighborhood& nb)
{
  if constexpr(Has_refinement_fit<Estimator>::value)
    return estimator.refinement_fit(nb);
  else
    return estimator(nb);
}

// The tangent Voronoi areas of an estimator's first pass, kept for the next passes over the
// same points (they depend on the named parameters' scale only): the areas and, on a tile by
// count, how far each reaches.
struct Area_cache
{
  std::vector<double> areas, reach;
  bool filled = false;
};

// What a pass of estimate_at_every_point() may change: the neighbour count the estimator
// receives (0: that of the named parameters, which the sample weights use), the points it
// visits (null: all), the callback it reports its fraction to in place of the named
// parameters' (empty: theirs) and, if it computes the areas, the one their pass reports to
// (empty: that pass is a share of `progress`), a flag set if a callback cancels it, a cache
// of the areas (null: none) and one of the search by count (null: one for this call's passes).
struct Pass_options
{
  std::size_t visit_k = 0;
  const std::vector<char>* visit = nullptr;
  std::function<bool(double)> progress, area_progress;
  bool* cancelled = nullptr;
  Area_cache* areas = nullptr;
  Knn_search_cache* knn = nullptr;  // the search's tree over the passes (null: this call's own)
};

// The evaluation of estimate_at_every_point() at one point: TOO_FEW_NEIGHBORS below
// `min_neighbors`, DEGENERATE_FIT where the neighbours coincide up to rounding
// (neighborhood_below_precision()), else the estimator (`refining_normals`: its normal fit, for a
// refinement pass), DEGENERATE_FIT without tangent spread where the estimator asks for that test. With
// `neighbor_extent` (a tile by count, with sample weights), records how far from the core of
// `tile` the neighbours lie.
template <class Estimator, class GeomTraits>
struct Estimate_at_point
{
  const Estimator* estimator;
  std::size_t min_neighbors;
  bool refining_normals;
  Atomic_max* neighbor_extent;
  const Tile* tile;

  Curvature_estimate<GeomTraits> operator()(const Neighborhood& nb) const
  {
    if(neighbor_extent)
      neighbor_extent->update(nb.radius - tile->distance_inside_core(nb.center[0], nb.center[1], nb.center[2]));
    if(nb.size < min_neighbors)
      return to_curvature_estimate<GeomTraits>(Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS),
                                               nb.size);
    if(neighborhood_below_precision(nb))
      return to_curvature_estimate<GeomTraits>(Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT),
                                               nb.size);
    Local_estimate e = refining_normals ? refinement_estimate(*estimator, nb) : (*estimator)(nb);
    if(e.status == Curvature_estimate_status::VALID && estimator->check_tangent_spread &&
       neighborhood_lacks_tangent_spread(nb))
      e = Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
    return to_curvature_estimate<GeomTraits>(e, nb.size);
  }
};

// Progress over the passes of estimate_at_every_point(), each a share of [0, 1] in
// proportion to its cost: the area pass (a quarter of the neighbours) costs about half an
// estimation pass, a refinement pass `refinement_cost` of one (a sphere fit: half; measured
// with benchmark/aso_speed). Pass p reports in [start[p], start[p] + size[p]].
struct Pass_shares
{
  std::vector<double> start, size;
};

inline Pass_shares pass_shares(bool area_pass, std::size_t refinements, double refinement_cost)
{
  std::vector<double> cost;
  if(area_pass)
    cost.push_back(0.5);
  for(std::size_t r = 0; r < refinements; ++r)
    cost.push_back(refinement_cost);
  cost.push_back(1.0);
  double total = 0;
  for(double c : cost)
    total += c;
  Pass_shares shares;
  double start = 0;
  for(double c : cost)
  {
    shares.start.push_back(start / total);
    shares.size.push_back(c / total);
    start += c;
  }
  return shares;
}

// By count on a tile with sample weights: the halo that the areas of the own points' neighbours
// need, where those neighbours lie within `extent` of the core. A neighbour p_j of an own point
// x_i (|p_j - x_i| <= r_i) is within r_i minus x_i's depth in the core of the core, hence within
// `extent` of it; its area is the whole-cloud one if the points it depends on (`area_reach`, per
// point of the range) are within the halo: the farthest such reach, at least `extent` (the
// reach of an area computed in a truncated range only overestimates the true one).
template <class PointRange, class PointMap>
double area_halo_requirement(const PointRange& points, const PointMap& point_map, const Tile& tile, double extent,
                             const std::vector<double>& area_reach)
{
  double required = extent;
  std::size_t i = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++i)
  {
    const auto& p = get(point_map, *it);
    const double d = tile.distance_to_core(to_double(p.x()), to_double(p.y()), to_double(p.z()));
    if(d <= extent && area_reach[i] > required)
      required = area_reach[i];
  }
  return required;
}

// After the estimation: throws Halo_too_small if the areas of the own points' neighbours
// (area_halo_requirement()) reach beyond the halo.
template <class PointRange, class PointMap>
void check_area_halo(const PointRange& points, const PointMap& point_map, const Tile& tile, double extent,
                     const std::vector<double>& area_reach)
{
  const double required = area_halo_requirement(points, point_map, tile, extent, area_reach);
  if(required > tile.halo)
    throw Halo_too_small(required, tile.halo);
}

// The passes after the area pass: `refinements` passes of the normal fit, each pass's
// corrected normals the next pass's input normals (the input normal where a pass has no
// estimate), then the estimation. `options_of(r)` gives pass r's options (its share of the
// progress; its callback sets `cancelled`), `evaluation(refining_normals)` the evaluation at a
// point. Cancelled before the estimation pass: every point NOT_COMPUTED; during it: the points
// not reached are NOT_COMPUTED, as in a single pass.
template <class Estimate, class Geom_traits, class ConcurrencyTag, class PointRange, class PointMap, class NormalMap,
          class OptionsOf, class Evaluation>
std::vector<Estimate>
estimation_after_refinements(const PointRange& points, bool radius_given, double radius, std::size_t k,
                             const PointMap& point_map, const NormalMap& normal_map, std::size_t refinements,
                             const OptionsOf& options_of, const Evaluation& evaluation, const bool& cancelled)
{
  typedef std::pair<typename Geom_traits::Point_3, typename Geom_traits::Vector_3> Oriented;
  std::vector<Estimate> result;
  for(std::size_t r = 0; r <= refinements; ++r)
  {
    const bool last = r == refinements;
    Neighborhood_options o = options_of(r);
    if(r == 0)
      result = evaluate_with_maps<Estimate, ConcurrencyTag>(points, radius_given, radius, k, point_map, normal_map, o,
                                                            evaluation(!last));
    else
    {
      std::vector<Oriented> refined;
      refined.reserve(result.size());
      std::size_t i = 0;
      for(auto it = points.begin(); it != points.end(); ++it, ++i)
        refined.emplace_back(get(point_map, *it), result[i].is_valid() ? result[i].normal : get(normal_map, *it));
      o.knn_cache = nullptr;  // (another range)
      const CGAL::First_of_pair_property_map<Oriented> refined_points;
      const CGAL::Second_of_pair_property_map<Oriented> refined_normals;
      result = evaluate_with_maps<Estimate, ConcurrencyTag>(refined, radius_given, radius, k, refined_points,
                                                            refined_normals, o, evaluation(!last));
    }
    if(cancelled && !last)
      return std::vector<Estimate>(result.size());
    if(cancelled)
      break;
  }
  return result;
}

// Per-point curvature estimation, from `estimator` (a copyable, stateless
// Local_estimate(const Neighborhood&) functor deriving from Estimator_base). With
// estimator.area_weights, a first pass computes the tangent Voronoi areas (for an
// estimator with takes_weight_map, the weights of the named parameter sample_weight_map,
// if given, replace them, whatever estimator.area_weights says); with
// estimator.normal_refinements = n, n passes of its normal fit (refinement_estimate()) each replace
// the input normals by their corrected normals before the estimation. The callback sees the
// passes as consecutive shares of [0, 1] (the area pass apart with pass.area_progress);
// cancelled before the estimation pass, every point is NOT_COMPUTED (a refinement pass's
// values are not the estimator's).
template <class ConcurrencyTag, class PointRange, class NamedParameters, class Estimator>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_at_every_point(const PointRange& points, bool radius_given, double radius, const NamedParameters& np,
                        const Estimator& estimator, const char* function_name,
                        const Pass_options& pass = Pass_options())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  typedef Curvature_estimate<Geom_traits> Estimate;
  // k: the scale of the named parameters, which the sample weights use; visit_k (if not 0):
  // the neighbourhoods the estimator receives (the automatic scale's largest)
  const std::size_t k = checked_scale<PointRange>(radius, radius_given, np, function_name);
  const std::size_t visit_k = pass.visit_k > 0 ? pass.visit_k : k;
  const std::size_t min_neighbors = min_neighbors_parameter(np, estimator.min_neighbors);
  Neighborhood_options options = neighborhood_options(np, function_name, estimator.normalize_normals);
  options.visit = pass.visit;
  Knn_search_cache own_knn;  // (the area pass's tree for the estimation)
  options.knn_cache = pass.knn ? pass.knn : &own_knn;
  if(pass.progress)
    options.callback = pass.progress;
  if(options.callback && pass.cancelled)
    options.callback = [callback = options.callback, cancelled = pass.cancelled](double f) {
      const bool go_on = callback(f);
      if(!go_on)
        *cancelled = true;
      return go_on;
    };
  // With a tile, sample weights and neighbourhoods by count: how far from the core the
  // neighbours of the own points lie (see below).
  Atomic_max* neighbor_extent = nullptr;
  const auto evaluation = [&](bool refining_normals) {
    return Estimate_at_point<Estimator, Geom_traits>{&estimator, min_neighbors, refining_normals, neighbor_extent,
                                                     &options.tile};
  };
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const auto normal_map = NP_helper::get_normal_map(points, np);
  // Weights given (sample_weight_map) replace the area pass of the estimators that use sample
  // weights; they are read here, in range order. With a tile they are taken as the whole
  // cloud's (the halo needs one radius): the caller's responsibility (documented).
  const bool weights_given = has_sample_weight_map<NamedParameters>() && estimator.takes_weight_map;
  const std::vector<double> given_weights =
    weights_given ? given_sample_weights(points, np, function_name) : std::vector<double>();
  if(weights_given)
    options.point_weights = &given_weights;
  const bool area_pass = estimator.area_weights && !weights_given;
  if(!area_pass && estimator.normal_refinements == 0)
    return evaluate_with_maps<Estimate, ConcurrencyTag>(points, radius_given, radius, visit_k, point_map, normal_map,
                                                        options, evaluation(false));

  if(options.has_tile && estimator.normal_refinements > 0)
    throw std::invalid_argument(std::string(function_name) + ": parameter 'tile' is not supported with "
                                                             "normal_refinement");
  Area_cache own_areas;
  Area_cache& cache = pass.areas ? *pass.areas : own_areas;
  const bool compute_areas = area_pass && !cache.filled;
  // (the area pass on a callback of its own: not a share of this one's)
  const bool areas_apart = compute_areas && pass.area_progress && options.callback;
  const Pass_shares shares = pass_shares(compute_areas && !areas_apart, estimator.normal_refinements,
                                         Has_refinement_fit<Estimator>::value ? 0.5 : 1.0);
  std::size_t pass_index = 0;
  const std::function<bool(double)> callback = options.callback;
  bool cancelled = false;
  // the options of pass p: the callback maps its progress into the pass's share
  auto share = [&](std::size_t p) {
    Neighborhood_options o = options;
    if(callback)
      o.callback = [&callback, &cancelled, &shares, p](double f) {
        const bool go_on =
          callback(p + 1 == shares.start.size() && f == 1.0 ? 1.0 : shares.start[p] + shares.size[p] * f);
        cancelled = cancelled || !go_on;
        return go_on;
      };
    return o;
  };

  std::vector<double>& areas = cache.areas;
  // By count on a tile: per point of the range, how far from the core its area reaches.
  std::vector<double>& area_reach = cache.reach;
  Atomic_max own_neighbor_extent;
  const bool tile_by_count = options.has_tile && !radius_given;
  if(compute_areas)
  {
    // The areas of the neighbours of a tile's own points need their own neighbours: every
    // point of the range is weighted. By radius, the halo must reach two radii (a neighbour's
    // area reaches r/2 beyond it). By count, the estimation records how far from the core
    // the own points' neighbours lie, and the areas of the points that close to the core must
    // reach no farther than the halo (checked after the estimation).
    Neighborhood_options o = areas_apart ? options : share(pass_index++);
    if(areas_apart)
      o.callback = [&pass, &cancelled](double f) {
        const bool go_on = pass.area_progress(f);
        cancelled = cancelled || !go_on;
        if(!go_on && pass.cancelled)
          *pass.cancelled = true;
        return go_on;
      };
    o.has_tile = false;
    o.visit = nullptr;  // every point's area: the visited points' neighbours are weighted
    // the areas use the query's normal direction only: unit normals whatever the estimator
    // wants, so that they are bitwise those of estimate_tangent_voronoi_areas()
    o.normalize_normals = true;
    areas = tangent_voronoi_areas<ConcurrencyTag>(points, radius_given, radius, k, point_map, normal_map, o,
                                                  tile_by_count ? &options.tile : nullptr,
                                                  tile_by_count ? &area_reach : nullptr);
    if(cancelled)
      return std::vector<Estimate>(areas.size());  // every point NOT_COMPUTED
    cache.filled = true;
  }
  if(area_pass)
  {
    options.point_weights = &areas;
    options.halo_radii = radius_given ? 2 : 1;
    if(tile_by_count)
    {
      neighbor_extent = &own_neighbor_extent;
      // the search refuses a neighbour whose area reaches beyond the halo, before any estimate
      // (check_area_halo() below would refuse it only after estimating every point)
      options.point_reach = &area_reach;
    }
  }
  std::vector<Estimate> result;
  try
  {
    result = estimation_after_refinements<Estimate, Geom_traits, ConcurrencyTag>(
      points, radius_given, radius, visit_k, point_map, normal_map, estimator.normal_refinements,
      [&](std::size_t r) { return share(pass_index + r); }, evaluation, cancelled);
  }
  catch(const Halo_too_small& e)
  {
    // The search refused the halo (a neighbour, or a neighbour's area, beyond it): the next run
    // holds every point within the halo it asks for, and check_area_halo() there would refuse
    // it again, after estimating every point, for the areas of those points that reach farther.
    // Those the range holds are known: asked for at once (lone-star.las by count in tiles read
    // again 50 -> 42 times with the default, 84 -> 69 with --neighbors 40).
    if(!neighbor_extent)
      throw;
    throw Halo_too_small(area_halo_requirement(points, point_map, options.tile, e.required_halo(), area_reach),
                         options.tile.halo);
  }
  if(neighbor_extent && !cancelled)
    check_area_halo(points, point_map, options.tile, neighbor_extent->value(), area_reach);
  return result;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
