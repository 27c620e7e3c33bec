// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The common body of every estimate_*_curvatures() function: named parameters, scale
// (radius or neighbour count), the neighbourhood driver, one Curvature_estimate per point.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_ESTIMATE_AT_EVERY_POINT_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_ESTIMATE_AT_EVERY_POINT_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <functional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// True for CGAL named parameter packs (to tell the overloads without radius apart).
template <class T>
struct is_named_parameters : std::false_type {};
template <class T, class Tag, class Base>
struct is_named_parameters<CGAL::Named_function_parameters<T, Tag, Base> > : std::true_type {};

// Result type `std::vector<Result<Geom_traits> >` of the overloads without radius; no `type`
// unless NamedParameters is a named parameter pack, so that a call with a radius does not
// consider them (SFINAE).
template <template <class> class Result, class PointRange, class NamedParameters,
          bool = is_named_parameters<NamedParameters>::value>
struct Results_without_radius {};
template <template <class> class Result, class PointRange, class NamedParameters>
struct Results_without_radius<Result, PointRange, NamedParameters, true>
{
  typedef std::vector<Result<
    typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> > type;
};
template <class PointRange, class NamedParameters>
using Estimates_without_radius = Results_without_radius<Curvature_estimate, PointRange, NamedParameters>;

// Driver options of a public function: its name (for messages), whether its estimator wants
// unit normals, and the named parameters `callback`, `accept_unnormalized_normals` and `tile`.
template <class NamedParameters>
Neighborhood_options neighborhood_options(const NamedParameters& np, const char* function_name,
                                          bool normalize_normals)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Neighborhood_options options;
  options.normalize_normals = normalize_normals;
  options.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback),
                                      std::function<bool(double)>());
  options.function_name = function_name;
  options.check_normal_length =
    !choose_parameter(get_parameter(np, internal_np::accept_unnormalized_normals), false);
  options.has_tile = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::tile_t>::value;
  options.tile = choose_parameter(get_parameter(np, internal_np::tile), Tile());
  return options;
}

// The least neighbour count of an estimate: the named parameter `min_neighbors` if given,
// else the estimator's measured default.
template <class NamedParameters>
std::size_t min_neighbors_parameter(const NamedParameters& np, std::size_t estimator_default)
{
  return CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::min_neighbors), estimator_default);
}

// The body of evaluate_at_every_point() below, with the maps and the scale given: balls of
// `radius` if `radius_given`, else the `k` nearest.
template <class Result, class ConcurrencyTag, class PointRange, class PointMap, class NormalMap, class Evaluate>
std::vector<Result> evaluate_with_maps(const PointRange& points, bool radius_given, double radius,
                                       std::size_t k, PointMap point_map, NormalMap normal_map,
                                       const Neighborhood_options& options, const Evaluate& evaluate)
{
  std::vector<Result> results(static_cast<std::size_t>(std::distance(points.begin(), points.end())));
  auto visit = [&results, &evaluate](std::size_t i, const Neighborhood& nb) { results[i] = evaluate(nb); };
  const std::vector<Curvature_estimate_status> status =
    radius_given
      ? for_each_neighborhood<ConcurrencyTag>(points, point_map, normal_map, radius, options, visit)
      : for_each_neighborhood_knn<ConcurrencyTag>(points, point_map, normal_map, k, options, visit);
  for(std::size_t i = 0; i < results.size(); ++i)
    if(status[i] != Curvature_estimate_status::VALID)
      results[i].status = status[i];  // unusable or not reached: NaN fields, count 0
  return results;
}

// The common body of every per-point function of the package: reads the named parameters
// (point_map, normal_map, the package's neighbor_count), checks the scale, runs the driver
// with balls of `radius` (`radius_given`: the overloads with a radius) or by count (the
// overloads without), and returns one Result per element of `points`, in order:
// `evaluate(nb)` for the points visited, a default Result with the driver's status for the
// others (unusable, or not reached after cancellation). Result needs a `status` member;
// `evaluate` must be copyable and callable from several threads at once.
template <class Result, class ConcurrencyTag, class PointRange, class NamedParameters, class Evaluate>
std::vector<Result> evaluate_at_every_point(const PointRange& points, bool radius_given,
                                            double radius, const NamedParameters& np,
                                            const Neighborhood_options& options,
                                            const Evaluate& evaluate)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  static_assert(NP_helper::has_normal_map(),
                "Error: no normal map. Pass CGAL::parameters::normal_map(...): the estimators "
                "of this package need oriented normals.");
  const std::size_t k = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Point_set_curvatures::internal_np::neighbor_count),
    std::size_t(0));
  check_scale(radius, k, !radius_given, options.function_name);

  return evaluate_with_maps<Result, ConcurrencyTag>(points, radius_given, radius, k,
                                                    NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np), options, evaluate);
}

// Per-point curvature estimation, from `estimator` (a copyable, stateless
// Local_estimate(const Neighborhood&) functor deriving from Estimator_base).
template <class ConcurrencyTag, class PointRange, class NamedParameters, class Estimator>
std::vector<Curvature_estimate<
  typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_at_every_point(const PointRange& points, bool radius_given, double radius,
                        const NamedParameters& np, const Estimator& estimator,
                        const char* function_name)
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits Geom_traits;
  const std::size_t min_neighbors = min_neighbors_parameter(np, estimator.min_neighbors);
  return evaluate_at_every_point<Curvature_estimate<Geom_traits>, ConcurrencyTag>(
    points, radius_given, radius, np,
    neighborhood_options(np, function_name, estimator.normalize_normals),
    [&estimator, min_neighbors](const Neighborhood& nb) {
      if(nb.size < min_neighbors)
        return to_curvature_estimate<Geom_traits>(
          Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS), nb.size);
      Local_estimate e = estimator(nb);
      if(e.status == Curvature_estimate_status::VALID && estimator.check_tangent_spread &&
         neighborhood_lacks_tangent_spread(nb))
        e = Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
      return to_curvature_estimate<Geom_traits>(e, nb.size);
    });
}

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
