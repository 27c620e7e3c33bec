// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The sample weights of the estimators as a function of their own: the area of every
// point's tangent Voronoi cell (internal/tangent_voronoi_area.h), written into a property map that
// estimate_aso_curvatures(), estimate_apss_curvatures() and
// estimate_algebraic_sphere_features() then read (named parameter sample_weight_map), so that
// several estimators of one run share one area pass.

#ifndef CGAL_ESTIMATE_TANGENT_VORONOI_AREAS_H
#define CGAL_ESTIMATE_TANGENT_VORONOI_AREAS_H

#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The body of both overloads: the areas of the estimators' pass (same neighbourhoods, same
// normalisation of the normals), put into the sample_weight_map of `np` in range order.
template <class ConcurrencyTag, class PointRange, class NamedParameters>
bool tangent_voronoi_areas_into_map(PointRange& points, bool radius_given, double radius, const NamedParameters& np)
{
  static_assert(has_sample_weight_map<NamedParameters>(),
                "Error: no sample weight map. Pass CGAL::Point_set_curvatures::parameters::"
                "sample_weight_map(...): the areas are written into it.");
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const char* name = "estimate_tangent_voronoi_areas";
  const std::size_t k = checked_scale<PointRange>(radius, radius_given, np, name);
  Neighborhood_options options = neighborhood_options(np, name, true);
  if(options.has_tile)
    throw std::invalid_argument(
      std::string(name) + ": parameter 'tile' is not supported: compute the areas "
                          "of the whole cloud, or let each estimator compute them on its tile (no sample_weight_map)");
  bool cancelled = false;
  options.callback = noting_cancellation(options.callback, cancelled);
  const std::vector<double> areas =
    tangent_voronoi_areas<ConcurrencyTag>(points, radius_given, radius, k, NP_helper::get_const_point_map(points, np),
                                          NP_helper::get_normal_map(points, np), options);
  if(cancelled)
    return false;  // the map is left as it was: zeros for the points not reached would pass for areas
  const auto map = CGAL::parameters::get_parameter(np, internal_np::sample_weight_map);
  std::size_t i = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++i)
    put(map, *it, areas[i]);
  return !cancelled;
}

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Computes, for every point of an oriented point cloud, the quadrature weight that the
/// estimators use with `CGAL::Sample_weights::TANGENT_VORONOI_AREA`: the area of the point's
/// Voronoi cell among its neighbours, in the plane through the point orthogonal to its
/// normal, within a disk of radius `radius/4` (user manual, "Beyond the paper"), in the
/// squared unit of the coordinates. The areas are written into the property map of the named
/// parameter `Point_set_curvatures::parameters::sample_weight_map`; passing the same map to
/// `estimate_aso_curvatures()`, `estimate_apss_curvatures()` or
/// `estimate_algebraic_sphere_features()` with the same scale (and the same
/// `accept_unnormalized_normals`) gives bitwise their estimates with
/// `sample_weights(Sample_weights::TANGENT_VORONOI_AREA)` (the default ASO's choice), without
/// computing the areas again: one area pass for every estimator of a run (it costs about half
/// of an ASO pass). With the map, APSS and the sphere features are area-weighted too.
///
/// The neighbourhoods are those of the estimators' area pass: the points at distance
/// `< radius/2`. Points that cannot be used (non-finite coordinates, zero or invalid normal)
/// get 0. If the callback cancels, nothing is written into the map.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB); the
///         areas do not depend on it.
/// \tparam PointRange a model of `Range`; its iterator value type is the key type of the
///         maps.
///
/// \param points input oriented point cloud
/// \param radius the radius `r` of the estimators that will use the areas, in the unit of
///        the coordinates
/// \param np a sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{Point_set_curvatures::parameters::sample_weight_map}
///     \cgalParamDescription{the property map that receives the area of every point
///       (required)}
///     \cgalParamType{a model of `WritablePropertyMap` whose key type is the value type of
///       the iterator of `PointRange` and whose value type is `double`}
///   \cgalParamNEnd
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`; for
///       `CGAL::Point_set_3`, its point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a property map associating oriented normals to the elements of
///       `points` (required, except for `CGAL::Point_set_3`)}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Vector_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the fraction of points processed so far (in `[0,1]`)
///       from the calling thread; returning `false` cancels}
///     \cgalParamType{an instance of `std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::accept_unnormalized_normals}
///     \cgalParamDescription{as for `estimate_aso_curvatures()`: pass the estimators' value}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `false` if the callback cancelled the computation (the map is then unchanged),
///          `true` otherwise.
/// \throws std::invalid_argument if `radius` is not positive and finite, or with the named
///         parameter `tile` (not supported).
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
bool estimate_tangent_voronoi_areas(PointRange& points, double radius, const NamedParameters& np)
{
  return Point_set_curvatures::internal::tangent_voronoi_areas_into_map<ConcurrencyTag>(points, true, radius, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`, the estimators' `k`; the
/// areas use the `max(6, k/4)` nearest neighbours, as the estimators' area pass does.
/// \throws std::invalid_argument if `neighbor_count` is missing or 0.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
std::enable_if_t<Point_set_curvatures::internal::is_named_parameters<NamedParameters>::value, bool>
estimate_tangent_voronoi_areas(PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::tangent_voronoi_areas_into_map<ConcurrencyTag>(points, false, 0.0, np);
}

}  // namespace CGAL

#endif
