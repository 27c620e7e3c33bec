// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_APSS_CURVATURES_H
#define CGAL_ESTIMATE_APSS_CURVATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Algebraic_sphere_fit.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>

#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Per-point APSS: the five sums of the sphere fit, then Equations 6-8.
struct Apss_estimator : Estimator_base
{
  // weight kernel (named parameter weight_kernel)
  Apss_weight_kernel kernel = Apss_weight_kernel::SMOOTH;
  bool orient_neighbors = false;  // robust_orientation

  Apss_estimator()
  {
    check_tangent_spread = false;  // tested by fit_algebraic_sphere
    min_neighbors = default_min_neighbors::apss;
    takes_weight_map = true;
  }
  template <class NamedParameters>
  explicit Apss_estimator(const NamedParameters& np) : Apss_estimator()
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    kernel = weight_kernel_parameter(np);
    orient_neighbors = choose_parameter(get_parameter(np, internal_np::robust_orientation), false);
    area_weights = choose_parameter(get_parameter(np, internal_np::sample_weights), Sample_weights::UNIFORM) ==
                   Sample_weights::TANGENT_VORONOI_AREA;
  }

  template <class Kernel>
  Local_estimate fit(const Neighborhood& nb) const
  {
    Algebraic_sphere_sums<Kernel> sums;
    double ref[3];
    if(orient_neighbors && !majority_orientation<Kernel>(nb, ref))
      return Local_estimate::invalid(Curvature_estimate_status::TWO_SHEETS);
    sums.add(nb, orient_neighbors ? ref : nullptr);
    return algebraic_sphere_estimate(sums, nb.radius);
  }

  Local_estimate operator()(const Neighborhood& nb) const
  {
    return with_weight_kernel(kernel, [&](auto k) { return fit<decltype(k)>(nb); });
  }
};

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates, at every point of an oriented point cloud, the corrected normal and the
/// signed mean curvature of the APSS algebraic sphere fit (Guennebaud and Gross 2007), as
/// analysed by Lejemble et al. 2021 (Section 3, Equations 2-8): the fitted sphere's
/// normalised gradient and inverse radius `2 û_q`, which converges to the mean curvature.
///
/// Same neighbourhoods, kernel `(1 - d²/radius²)²`, named parameters, statuses and sign
/// convention as `CGAL::estimate_aso_curvatures()`. Valid estimates fill `normal`,
/// `mean_curvature` and `neighbor_count`; the principal curvatures and directions and the
/// Gaussian curvature are NaN (a sphere cannot measure them).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB).
/// \tparam PointRange a model of `ConstRange`; its iterator value type is the key type of
///         the point and normal maps.
///
/// \param points input oriented point cloud
/// \param radius radius `r` of the neighbourhoods and of the weight kernel, in the unit of
///        the coordinates
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
///       `points` (required, except for `CGAL::Point_set_3`); normalised on input}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Vector_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel` with a floating-point `FT`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the fraction of points processed so far (in `[0,1]`)
///       from the calling thread; returning `false` cancels, the points not processed keep
///       the status `NOT_COMPUTED`}
///     \cgalParamType{an instance of `std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::weight_kernel}
///     \cgalParamDescription{the weight kernel of the fit: `SMOOTH` `(1 - d²/radius²)²`,
///       `SMOOTH_CUBIC` and `SMOOTH_QUARTIC` (exponents 3 and 4) or `CONSTANT` (1 inside the
///       ball, the weight of the paper's asymptotic analysis)}
///     \cgalParamType{`CGAL::Apss_weight_kernel`}
///     \cgalParamDefault{`CGAL::Apss_weight_kernel::SMOOTH`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::sample_weights}
///     \cgalParamDescription{the quadrature weights of the samples, as for
///       `estimate_aso_curvatures()`}
///     \cgalParamType{`CGAL::Sample_weights`}
///     \cgalParamDefault{`CGAL::Sample_weights::UNIFORM`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::sample_weight_map}
///     \cgalParamDescription{the quadrature weights of the samples given per point (for
///       instance the areas of `estimate_tangent_voronoi_areas()`, computed once for several
///       estimators): read instead of computed, whatever `sample_weights` says;
///       finite and non-negative (`std::invalid_argument` otherwise)}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of the
///       iterator of `PointRange` and whose value type converts to `double`}
///     \cgalParamDefault{none: the weights of `sample_weights`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::robust_orientation}
///     \cgalParamDescription{neighbours' normals oriented by their weighted majority, as for
///       `estimate_aso_curvatures()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`CGAL::Point_set_curvatures::default_min_neighbors::apss`, the measured minimum
///       of this estimator (user manual, "Neighbourhoods and scale")}
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
/// \throws std::invalid_argument if `radius` is not positive and finite.
///
/// \sa `CGAL::Algebraic_sphere_fit` for a single evaluation point.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_apss_curvatures(const PointRange& points, double radius,
                         const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, true, radius, np, Point_set_curvatures::internal::Apss_estimator(np), "estimate_apss_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`; each point's radius is the
/// distance to its `k`-th nearest neighbour (itself counted), enlarged by a factor
/// `1 + 2^-20` so that the `k` nearest are inside (see `neighbor_count`).
/// \throws std::invalid_argument if `neighbor_count` is missing or 0.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
typename Point_set_curvatures::internal::Estimates_without_radius<PointRange, NamedParameters>::type
estimate_apss_curvatures(const PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, false, 0.0, np, Point_set_curvatures::internal::Apss_estimator(np), "estimate_apss_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<Curvature_estimate<typename Kernel_traits<typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_apss_curvatures(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius)
{
  return estimate_apss_curvatures<ConcurrencyTag>(points, radius,
                                                  parameters::point_map(point_map).normal_map(normal_map));
}

}  // namespace CGAL

#endif
