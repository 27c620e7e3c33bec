// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_ASO_CURVATURES_H
#define CGAL_ESTIMATE_ASO_CURVATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Algebraic_shape_operator_fit.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_shape_operator.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>

#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Per-point ASO: two passes over the neighbours, then the closed-form shape operator.
struct Aso_estimator : Estimator_base
{
  Aso_projection projection = Aso_projection::CORRECTED_NORMAL;

  explicit Aso_estimator(Aso_projection p)
    : projection(p)
  {
    normalize_normals = (p == Aso_projection::CORRECTED_NORMAL);
    check_tangent_spread = false;  // tested on the first pass's moments
    min_neighbors = default_min_neighbors::aso;
  }

  Local_estimate operator()(const Neighborhood& nb) const
  {
    return algebraic_shape_operator(nb, projection);
  }
};

// The ASO from the named parameters: its projection, and a refusal of the constant kernel
// (the ASO differentiates the weights; the constant kernel has no usable derivative).
template <class NamedParameters>
Aso_estimator aso_estimator_from(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(weight_kernel_parameter(np) != Apss_weight_kernel::SMOOTH)
    throw std::invalid_argument("estimate_aso_curvatures: parameter 'weight_kernel': the ASO "
                                "differentiates the kernel, only Apss_weight_kernel::SMOOTH is "
                                "supported");
  return Aso_estimator(choose_parameter(get_parameter(np, internal_np::aso_projection),
                                        Aso_projection::CORRECTED_NORMAL));
}

} // namespace internal
} // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates, at every point of an oriented point cloud, the corrected normal, the
/// principal curvatures and directions, the mean and the Gaussian curvature with the
/// Algebraic Shape Operator (ASO) of Lejemble, Coeurjolly, Barthe and Mellado, "Stable and
/// efficient differential estimators on oriented point clouds", Computer Graphics Forum
/// 40(5), 2021 (Section 5, Equations 27-35).
///
/// At each point `x`, an algebraic sphere is fitted to the neighbours at distance `< radius`
/// (the point itself included) with the weights `(1 - d²/radius²)²` (APSS, Equations 2-4);
/// the fitted scalar field is differentiated twice with respect to `x`, through the
/// weights, and its shape operator is projected on the tangent plane and diagonalised.
/// Two passes over the neighbours (first-order sums, then the Hessian term contracted with
/// adjoints), constant memory per point.
///
/// Results: one `Curvature_estimate` per element of `points`, in the same order.
/// Curvatures are in 1/(unit of the coordinates), positive where the surface bends away
/// from the normal: a sphere of radius `R` with outward normals gives
/// `min_curvature = max_curvature = mean_curvature = 1/R`, `gaussian_curvature = 1/R²`.
/// The corrected normal is `∇f/|∇f|`, oriented like the input normals. Points that
/// cannot be estimated have a status saying why and NaN in every numeric field:
/// non-finite coordinates (`NON_FINITE_POINT`), zero or non-finite normal
/// (`INVALID_NORMAL`; such points are nobody's neighbour either), fewer than `min_neighbors` neighbours
/// (12 by default; `TOO_FEW_NEIGHBORS`), coincident neighbours, cancelling normals, or neighbours without
/// spread in two tangent directions such as a single scan line (`DEGENERATE_FIT`),
/// cancellation through `callback` (`NOT_COMPUTED`). A planar neighbourhood is valid with
/// zero curvatures. For invalid points `neighbor_count` is 0 except for `TOO_FEW_NEIGHBORS`
/// and `DEGENERATE_FIT`, which report the neighbours found.
///
/// Sequential and parallel runs return identical results.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB).
/// \tparam PointRange a model of `ConstRange`; its iterator value type is the key type of
///         the point and normal maps (`std::vector` of pairs or tuples, `CGAL::Point_set_3`).
///
/// \param points input oriented point cloud
/// \param radius radius `r` of the neighbourhoods and of the weight kernel, in the unit of
///        the coordinates. A good start is about 40 neighbours: 3.5 to 4 times the average spacing
///        of `CGAL::compute_average_spacing()` with 6 neighbours (36 to 51 neighbours
///        measured on the Goursat clouds and the bunny); smaller radii follow finer detail
///        and amplify noise.
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`; for
///       `CGAL::Point_set_3`, its point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a property map associating oriented normals to the elements of
///       `points`. Required (compile-time error without it), except for `CGAL::Point_set_3`
///       whose normal map is the default. Normals need not be unit; they are normalised.}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Vector_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel` with a floating-point `FT`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the fraction of points processed so far (in `[0,1]`),
///       from the calling thread, at least every 1% of the points and about every 0.25 s
///       on long runs; if it returns `false` the
///       estimation stops and the points not yet processed keep the status `NOT_COMPUTED`}
///     \cgalParamType{an instance of `std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::aso_projection}
///     \cgalParamDescription{the tangent plane of the shape operator: the plane orthogonal to
///       the returned corrected normal, or the authors' implementation (plane orthogonal to
///       `u_l`, input normals not normalised), which reproduces their published values}
///     \cgalParamType{`CGAL::Aso_projection`}
///     \cgalParamDefault{`CGAL::Aso_projection::CORRECTED_NORMAL`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::weight_kernel}
///     \cgalParamDescription{only `CGAL::Apss_weight_kernel::SMOOTH` is accepted: the ASO
///       differentiates the weights, the constant kernel has no usable derivative}
///     \cgalParamType{`CGAL::Apss_weight_kernel`}
///     \cgalParamDefault{`CGAL::Apss_weight_kernel::SMOOTH`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{12: the measured minimum of this estimator (user manual,
///       "Neighbourhoods and scale")}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::accept_unnormalized_normals}
///     \cgalParamDescription{by default a normal whose length lies outside `[1e-3, 1e3]` is
///       `INVALID_NORMAL` (colours or unscaled integers read as normals); `true` uses every
///       finite non-zero normal}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::tile}
///     \cgalParamDescription{estimates only the own points of a tile of a larger cloud
///       (`points` holds them and their halo), bitwise as in the whole-cloud run; the other
///       points get `NOT_COMPUTED`}
///     \cgalParamType{`CGAL::Point_set_curvatures::Tile`}
///     \cgalParamDefault{no tile: every point is estimated}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if `radius` is not positive and finite, or if
/// `weight_kernel` is not `SMOOTH`.
/// \throws std::length_error with 2^32 points or more.
///
/// \sa `CGAL::Algebraic_shape_operator_fit` to evaluate at other positions or with your own
/// neighbourhoods; `CGAL::estimate_apss_curvatures()` for the cheaper normal and mean curvature.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate<
  typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_aso_curvatures(const PointRange& points, double radius,
                        const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, true, radius, np, Point_set_curvatures::internal::aso_estimator_from(np),
    "estimate_aso_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`; each point's radius is the
/// distance to its `k`-th nearest neighbour (itself counted), enlarged by a factor
/// `1 + 2^-20` so that the `k` nearest are inside (see `neighbor_count`).
/// \throws std::invalid_argument if `neighbor_count` is missing or 0.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
typename Point_set_curvatures::internal::Estimates_without_radius<PointRange, NamedParameters>::type
estimate_aso_curvatures(const PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, false, 0.0, np, Point_set_curvatures::internal::aso_estimator_from(np),
    "estimate_aso_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<Curvature_estimate<typename Kernel_traits<
  typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_aso_curvatures(const PointRange& points, PointMap point_map, NormalMap normal_map,
                        double radius)
{
  return estimate_aso_curvatures<ConcurrencyTag>(
    points, radius, parameters::point_map(point_map).normal_map(normal_map));
}

} // namespace CGAL

#endif
