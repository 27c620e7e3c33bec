// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_JET_CURVATURES_H
#define CGAL_ESTIMATE_JET_CURVATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/osculating_jet.h>

#include <sstream>
#include <stdexcept>

#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Osculating jet of the neighbourhood, evaluated at the query point.
struct Jet_estimator : Estimator_base
{
  Jet_degrees degrees;
  explicit Jet_estimator(const Jet_degrees& d) : degrees(d) { min_neighbors = default_min_neighbors::jet; }
  Local_estimate operator()(const Neighborhood& nb) const { return osculating_jet_estimate(nb, degrees); }
};

// Reads and checks CGAL's named parameters degree_fitting and degree_monge.
template <class NamedParameters>
Jet_degrees jet_degrees(const NamedParameters& np, const char* function_name)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const long long fitting =
    static_cast<long long>(choose_parameter(get_parameter(np, CGAL::internal_np::degree_fitting), 2));
  const long long monge =
    static_cast<long long>(choose_parameter(get_parameter(np, CGAL::internal_np::degree_monge), 2));
  std::ostringstream msg;
  msg << function_name << ": ";
  if(monge < 2 || monge > 4)
    msg << "parameter 'degree_monge' must be 2, 3 or 4 (curvatures need 2), got " << monge;
  else if(fitting < monge || fitting > 12)
    msg << "parameter 'degree_fitting' must be at least degree_monge (" << monge
        << ") and at most 12 (CGAL's factorials overflow beyond), got " << fitting;
  else
  {
    Jet_degrees d;
    d.fitting = static_cast<std::size_t>(fitting);
    d.monge = static_cast<std::size_t>(monge);
    return d;
  }
  throw std::invalid_argument(msg.str());
}

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates, at every point of a point cloud, the normal, the principal curvatures and
/// directions, the mean and the Gaussian curvature with osculating jets (Cazals and Pouget,
/// "Estimating differential quantities using polynomial fitting of osculating jets", CAGD
/// 22(2), 2005), computed by `CGAL::Monge_via_jet_fitting`, a baseline of Lejemble et al.
/// 2021 (Section 6, Table 1).
///
/// At each point `x`, a bivariate polynomial of degree `degree_fitting` is fitted by
/// (unweighted) least squares to the neighbours over their PCA plane, and its Monge form is
/// computed at `x`: the point itself is passed first to `CGAL::Monge_via_jet_fitting`,
/// which evaluates at the first point of its range. The Monge form is oriented by the
/// input normal (`comply_wrt_given_normal()`) and converted to the package's sign
/// convention (CGAL's Monge coefficients are positive where the surface bends towards the
/// normal). Positions only: the input normals just orient the result. Needs Eigen 3
/// (`CGAL::Eigen3_support`).
///
/// Fields: every field, signed. Curvatures are in 1/(unit of the coordinates), positive
/// where the surface bends away from the normal (a sphere of radius `R` with outward
/// normals gives `1/R`). `normal` is the normal of the fitted jet above `x`, oriented like
/// the input normals.
///
/// Accuracy: a sphere of radius `R` is biased by about `0.25 (r/R)²` relative (measured:
/// benchmark/README.md, section 10). The cost is CGAL's: a PCA, an SVD of an `n x 6` matrix
/// and a Monge basis change per point.
///
/// Results: one `Curvature_estimate` per element of `points`, in the same order, with the
/// statuses of `CGAL::estimate_aso_curvatures()`: `NON_FINITE_POINT`, `INVALID_NORMAL`
/// (such points are nobody's neighbour either), `NOT_COMPUTED` (cancelled through
/// `callback`), `TOO_FEW_NEIGHBORS` (fewer than `(d+1)(d+2)/2` (6 by default) points at
/// distance `< r`, the query included), `DEGENERATE_FIT` (singular least-squares system,
/// condition number above 1e12: e.g. collinear neighbours). Invalid estimates hold NaN in
/// every numeric field. Sequential and parallel runs return identical results.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB).
/// \tparam PointRange a model of `ConstRange`; its iterator value type is the key type of
///         the point and normal maps (`std::vector` of pairs or tuples, `CGAL::Point_set_3`).
///
/// \param points input oriented point cloud
/// \param radius radius `r` of the neighbourhoods (every input point at distance `< r`, the
///        query point included), in the unit of the coordinates.
///        A good start is about 40 neighbours (3.5 to 4 times the average
///        spacing), as for `CGAL::estimate_aso_curvatures()`.
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is
///       `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`; for
///       `CGAL::Point_set_3`, its point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a property map associating oriented normals to the elements of
///       `points`. Required (compile-time error without it), except for `CGAL::Point_set_3`
///       whose normal map is the default.
///       The normals only orient the result (points with a zero or non-finite
///       normal are excluded, as by every estimator of the package).}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is
///       `geom_traits::Vector_3`}
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
///   \cgalParamNBegin{degree_fitting}
///     \cgalParamDescription{degree `d` of the polynomial fitted by least squares over the PCA
///       plane of the neighbourhood; needs `(d+1)(d+2)/2` points (6 for `d = 2`, 10 for
///       `d = 3`), fewer give `TOO_FEW_NEIGHBORS`}
///     \cgalParamType{an integer, from `degree_monge` to 12}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
///   \cgalParamNBegin{degree_monge}
///     \cgalParamDescription{degree of the Monge form computed from the fitted jet (CGAL's
///       `d'`); the curvatures need 2, higher degrees only add work here}
///     \cgalParamType{an integer, from 2 to `min(4, degree_fitting)`}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (6 with order-2 fitting, 10 with order 3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`CGAL::Point_set_curvatures::default_min_neighbors::jet`, the measured minimum
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
/// \throws std::invalid_argument if `radius` is not positive and finite, or if
///   `degree_fitting` or `degree_monge` is out of range.
/// \throws std::length_error with 2^32 points or more.
///
/// \sa `CGAL::estimate_aso_curvatures()`, more accurate and faster;
///   `CGAL::Monge_via_jet_fitting`.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_jet_curvatures(const PointRange& points, double radius,
                        const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, true, radius, np,
    Point_set_curvatures::internal::Jet_estimator(
      Point_set_curvatures::internal::jet_degrees(np, "estimate_jet_curvatures")),
    "estimate_jet_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`; each point's radius is the
/// distance to its `k`-th nearest neighbour (itself counted), enlarged by a factor
/// `1 + 2^-20` so that the `k` nearest are inside (see `neighbor_count`).
/// \throws std::invalid_argument if `neighbor_count` is missing or 0, or if `degree_fitting`
///   or `degree_monge` is out of range.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
typename Point_set_curvatures::internal::Estimates_without_radius<PointRange, NamedParameters>::type
estimate_jet_curvatures(const PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, false, 0.0, np,
    Point_set_curvatures::internal::Jet_estimator(
      Point_set_curvatures::internal::jet_degrees(np, "estimate_jet_curvatures")),
    "estimate_jet_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<Curvature_estimate<typename Kernel_traits<typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_jet_curvatures(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius)
{
  return estimate_jet_curvatures<ConcurrencyTag>(points, radius,
                                                 parameters::point_map(point_map).normal_map(normal_map));
}

}  // namespace CGAL

#endif
