// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_PCA_PLANE_CURVATURES_H
#define CGAL_ESTIMATE_PCA_PLANE_CURVATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/pca_plane.h>

#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Distance to the regression plane of the neighbourhood.
struct Pca_plane_estimator : Estimator_base
{
  Pca_plane_estimator() { min_neighbors = default_min_neighbors::pca_plane; }
  Local_estimate operator()(const Neighborhood& nb) const { return pca_plane_mean_curvature(nb); }
};

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates, at every point of a point cloud, the ABSOLUTE VALUE of the mean curvature
/// from the distance to the PCA plane of its neighbourhood (Digne, Morel, Souzani, Lartigue,
/// "Scale space meshing of raw data point sets", CGF 2011, Theorem 2): the least-squares
/// plane of the points at distance `< r` from `x` passes through their barycenter, at
/// distance `|H| r²/4 + O(r³)` from `x`, hence `|H| ≈ 4 dist(x, plane) / r²`. A baseline of
/// Lejemble et al. 2021 (Section 6), kept for comparisons: prefer
/// `CGAL::estimate_aso_curvatures()`.
///
/// Fields: `mean_curvature` holds `|H|` (unsigned, >= 0), in 1/(unit of the coordinates);
/// `normal` holds the unit normal of the PCA plane, oriented like the input normal of the
/// point; every other numeric field is NaN.
///
/// Accuracy: coarse, though better than the distance to the barycenter since the
/// tangential drift of the barycenter does not count; noise of amplitude `s` adds about
/// `4 s / r²`. Measured at about 40 neighbours (test_baselines): mean error 0.014 for
/// `|H| = 0.5` on a sphere (0.035 at most), 0.033 on a cylinder, 0.14 on an i.i.d. random
/// sampling of an ellipsoid (`|H|` from 0.76 to 3.0, 0.9 at most).
///
/// Results: one `Curvature_estimate` per element of `points`, in the same order, with the
/// statuses of `CGAL::estimate_aso_curvatures()`: `NON_FINITE_POINT`, `INVALID_NORMAL`
/// (such points are nobody's neighbour either), `NOT_COMPUTED` (cancelled through
/// `callback`), `TOO_FEW_NEIGHBORS` (fewer points at distance `< r`, the query included,
/// than `min_neighbors`: 10 by default), `DEGENERATE_FIT` (collinear or coincident neighbours: no plane). Invalid
/// estimates hold NaN in every numeric field. Sequential and parallel runs return identical
/// results.
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
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`CGAL::Point_set_curvatures::default_min_neighbors::pca_plane`, the measured minimum
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
/// \throws std::length_error with 2^32 points or more.
///
/// \sa `CGAL::estimate_barycenter_curvatures()`; `CGAL::estimate_apss_curvatures()` for a
/// signed mean curvature and a corrected normal.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_pca_plane_curvatures(const PointRange& points, double radius,
                              const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, true, radius, np, Point_set_curvatures::internal::Pca_plane_estimator(), "estimate_pca_plane_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`; each point's radius is the
/// distance to its `k`-th nearest neighbour (itself counted), enlarged by a factor
/// `1 + 2^-20` so that the `k` nearest are inside (see `neighbor_count`).
/// \throws std::invalid_argument if `neighbor_count` is missing or 0.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
typename Point_set_curvatures::internal::Estimates_without_radius<PointRange, NamedParameters>::type
estimate_pca_plane_curvatures(const PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, false, 0.0, np, Point_set_curvatures::internal::Pca_plane_estimator(), "estimate_pca_plane_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<Curvature_estimate<typename Kernel_traits<typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_pca_plane_curvatures(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius)
{
  return estimate_pca_plane_curvatures<ConcurrencyTag>(points, radius,
                                                       parameters::point_map(point_map).normal_map(normal_map));
}

}  // namespace CGAL

#endif
