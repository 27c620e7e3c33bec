// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The common body of every per-point function of the package (the estimators, the sphere
// features, the normals, the areas): named parameters, the scale (radius or neighbour count)
// checked, the neighbourhood driver, one result per input point in input order.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_EVALUATE_AT_EVERY_POINT_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_EVALUATE_AT_EVERY_POINT_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <functional>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// True for CGAL named parameter packs (to tell the overloads without radius apart).
template <class T>
struct is_named_parameters : std::false_type
{};
template <class T, class Tag, class Base>
struct is_named_parameters<CGAL::Named_function_parameters<T, Tag, Base> > : std::true_type
{};

// Result type `std::vector<Result<Geom_traits> >` of the overloads without radius; no `type`
// unless NamedParameters is a named parameter pack, so that a call with a radius does not
// consider them (SFINAE).
template <template <class> class Result, class PointRange, class NamedParameters,
          bool = is_named_parameters<NamedParameters>::value>
struct Results_without_radius
{};
template <template <class> class Result, class PointRange, class NamedParameters>
struct Results_without_radius<Result, PointRange, NamedParameters, true>
{
  typedef std::vector<Result<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
    type;
};
template <class PointRange, class NamedParameters>
using Estimates_without_radius = Results_without_radius<Curvature_estimate, PointRange, NamedParameters>;

// Driver options of a public function: its name (for messages), whether its estimator wants
// unit normals, and the named parameters `callback`, `accept_unnormalized_normals` and `tile`.
template <class NamedParameters>
Neighborhood_options neighborhood_options(const NamedParameters& np, const char* function_name, bool normalize_normals)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Neighborhood_options options;
  options.normalize_normals = normalize_normals;
  options.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  options.function_name = function_name;
  options.check_normal_length = !choose_parameter(get_parameter(np, internal_np::accept_unnormalized_normals), false);
  // a tile whose core is all of space is the whole cloud: no tile
  options.tile = choose_parameter(get_parameter(np, internal_np::tile), Tile::whole_space());
  options.has_tile = !options.tile.is_whole_space();
  return options;
}

// The least neighbour count of an estimate: the named parameter `min_neighbors` if given,
// else the estimator's measured default.
template <class NamedParameters>
std::size_t min_neighbors_parameter(const NamedParameters& np, std::size_t estimator_default)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::min_neighbors),
                                            estimator_default);
}

// The visitor of evaluate_with_maps(): stores evaluate(nb) at the point's input index. A
// named type, templated on the result and the evaluation only: the traversal it instantiates
// (visit_sorted_cloud, visit_cloud_knn) is shared by every range, map and named-parameter
// type of a translation unit. Evaluations should be named types too, for the same reason (a
// lambda in a function templated on the named parameters is a new type for each of them).
//
// The results are staged and written to `results` a few dozen at a time (and at the end of
// each range of points, end_of_range()): the traversal goes in grid order and the results
// are stored in input order, so on a cloud in random order each write misses the cache, and
// written one at a time it holds up the stores of the next point's gather; written together,
// the misses overlap (an ASO pass 7-8% faster on aso_speed's cloud of 500K points, in paired
// runs). A copy of the visitor is made per range of points; each flushes its own stage.
template <class Result, class Evaluate>
struct Store_results
{
  static constexpr std::size_t staged_capacity = 64;
  std::vector<Result>* results;
  const Evaluate* evaluate;
  std::vector<std::pair<std::size_t, Result> > staged = {};

  void operator()(std::size_t i, const Neighborhood& nb)
  {
    if(staged.capacity() == 0)
      staged.reserve(staged_capacity);
    staged.emplace_back(i, (*evaluate)(nb));
    if(staged.size() == staged_capacity)
      end_of_range();
  }
  void end_of_range()
  {
    Result* out = results->data();
    for(std::pair<std::size_t, Result>& r : staged)
      out[r.first] = std::move(r.second);
    staged.clear();
  }
};

// The body of evaluate_at_every_point() below, with the maps and the scale given: balls of
// `radius` if `radius_given`, else the `k` nearest.
template <class Result, class ConcurrencyTag, class PointRange, class PointMap, class NormalMap, class Evaluate>
std::vector<Result> evaluate_with_maps(const PointRange& points, bool radius_given, double radius, std::size_t k,
                                       PointMap point_map, NormalMap normal_map, const Neighborhood_options& options,
                                       const Evaluate& evaluate)
{
  std::vector<Result> results(static_cast<std::size_t>(std::distance(points.begin(), points.end())));
  const Store_results<Result, Evaluate> visit{&results, &evaluate};
  const std::vector<Curvature_estimate_status> status =
    radius_given ? for_each_neighborhood<ConcurrencyTag>(points, point_map, normal_map, radius, options, visit)
                 : for_each_neighborhood_knn<ConcurrencyTag>(points, point_map, normal_map, k, options, visit);
  for(std::size_t i = 0; i < results.size(); ++i)
    if(status[i] != Curvature_estimate_status::VALID)
      results[i].status = status[i];  // unusable or not reached: NaN fields, count 0
  return results;
}

// The neighbour count of the named parameters (0 without neighbor_count), after checking
// that the function's scale is given exactly once and the normal map is given.
template <class PointRange, class NamedParameters>
std::size_t checked_scale(double radius, bool radius_given, const NamedParameters& np, const char* function_name)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  static_assert(NP_helper::has_normal_map(),
                "Error: no normal map. Pass CGAL::parameters::normal_map(...): the estimators "
                "of this package need oriented normals.");
  const std::size_t k = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Point_set_curvatures::internal_np::neighbor_count), std::size_t(0));
  check_scale(radius, k, !radius_given, function_name);
  return k;
}

// The common body of every per-point function of the package: reads the named parameters
// (point_map, normal_map, the package's neighbor_count), checks the scale, runs the driver
// with balls of `radius` (`radius_given`: the overloads with a radius) or by count (the
// overloads without), and returns one Result per element of `points`, in order:
// `evaluate(nb)` for the points visited, a default Result with the driver's status for the
// others (unusable, or not reached after cancellation). Result needs a `status` member;
// `evaluate` must be copyable and callable from several threads at once.
template <class Result, class ConcurrencyTag, class PointRange, class NamedParameters, class Evaluate>
std::vector<Result> evaluate_at_every_point(const PointRange& points, bool radius_given, double radius,
                                            const NamedParameters& np, const Neighborhood_options& options,
                                            const Evaluate& evaluate)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const std::size_t k = checked_scale<PointRange>(radius, radius_given, np, options.function_name);

  return evaluate_with_maps<Result, ConcurrencyTag>(points, radius_given, radius, k,
                                                    NP_helper::get_const_point_map(points, np),
                                                    NP_helper::get_normal_map(points, np), options, evaluate);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif  // CGAL_POINT_SET_CURVATURES_INTERNAL_EVALUATE_AT_EVERY_POINT_H
