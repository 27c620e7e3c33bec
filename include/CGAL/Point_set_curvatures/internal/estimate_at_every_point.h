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

// Per-point curvature estimation: one Curvature_estimate per element of `points`, in order,
// from `estimator` (a copyable, stateless Local_estimate(const Neighborhood&) functor with a
// `normalize_normals` member, see Estimator_base), reading the usual named parameters
// (point_map, normal_map, geom_traits, callback) and the package's neighbor_count.
// With `radius_given` (the overloads with a radius) neighbourhoods are balls of `radius`;
// without (the overloads without radius), neighbor_count must be given.
// True for CGAL named parameter packs (to tell the overloads without radius apart).
template <class T>
struct is_named_parameters : std::false_type {};
template <class T, class Tag, class Base>
struct is_named_parameters<CGAL::Named_function_parameters<T, Tag, Base> > : std::true_type {};

// Result type of the overloads without radius; no `type` unless NamedParameters is a named
// parameter pack, so that a call with a radius does not consider them (SFINAE).
template <class PointRange, class NamedParameters, bool = is_named_parameters<NamedParameters>::value>
struct Estimates_without_radius {};
template <class PointRange, class NamedParameters>
struct Estimates_without_radius<PointRange, NamedParameters, true>
{
  typedef std::vector<Curvature_estimate<
    typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> > type;
};

template <class ConcurrencyTag, class PointRange, class NamedParameters, class Estimator>
std::vector<Curvature_estimate<
  typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_at_every_point(const PointRange& points, bool radius_given, double radius,
                        const NamedParameters& np, const Estimator& estimator,
                        const char* function_name)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  static_assert(NP_helper::has_normal_map(),
                "Error: no normal map. Pass CGAL::parameters::normal_map(...): the estimators "
                "of this package need oriented normals.");

  Neighborhood_options options;
  options.normalize_normals = estimator.normalize_normals;
  options.callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  options.function_name = function_name;
  const std::size_t k = choose_parameter(
    get_parameter(np, Point_set_curvatures::internal_np::neighbor_count), std::size_t(0));
  const bool by_count = !radius_given;
  check_scale(radius, k, by_count, function_name);

  std::vector<Curvature_estimate<Geom_traits> > results(
    static_cast<std::size_t>(std::distance(points.begin(), points.end())));
  auto visit = [&results, &estimator](std::size_t i, const Neighborhood& nb) {
    Local_estimate e = estimator(nb);
    if(e.status == Curvature_estimate_status::VALID && estimator.check_tangent_spread &&
       neighborhood_lacks_tangent_spread(nb))
      e = Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
    results[i] = to_curvature_estimate<Geom_traits>(e, nb.size);
  };
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const auto normal_map = NP_helper::get_normal_map(points, np);
  const std::vector<Curvature_estimate_status> status =
    by_count ? for_each_neighborhood_knn<ConcurrencyTag>(points, point_map, normal_map, k, options, visit)
             : for_each_neighborhood<ConcurrencyTag>(points, point_map, normal_map, radius, options, visit);
  for(std::size_t i = 0; i < results.size(); ++i)
    if(status[i] != Curvature_estimate_status::VALID)
      results[i].status = status[i];  // unusable or not reached: NaN fields, count 0
  return results;
}

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
