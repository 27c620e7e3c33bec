// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_VCM_CURVATURES_H
#define CGAL_ESTIMATE_VCM_CURVATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/vcm.h>

#include <vector>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates, at every point of a point cloud, the MAGNITUDES of the principal curvatures,
/// the principal directions and the normal from the Voronoi Covariance Measure (Mérigot,
/// Ovsjanikov, Guibas, "Voronoi-based curvature and feature estimation from point clouds",
/// IEEE TVCG 17(6), 2011), with the covariance matrices of `CGAL::compute_vcm()`, a
/// baseline of Lejemble et al. 2021 (Section 6, Table 1).
///
/// As `CGAL::compute_vcm()`, it builds the Delaunay triangulation of the usable points (finite
/// coordinates and non-zero normal; CGAL's), cuts each Voronoi cell by the ball of radius `R`
/// around its point (approximated by CGAL's 20-face polytope), takes the covariance of the
/// cut cell, and sums these matrices over the points at distance at most `r` (the
/// convolution radius). The cells are cut and integrated by the package, not by CGAL, whose
/// construction depends on memory addresses (its convex hull orders edges by address: the
/// covariances of two runs differ in the last bits); the package's agree with CGAL's to about
/// 1e-14 relative and are the same bits in every run. For a smooth surface the sum is
/// about `(2π R³ r²/3) [n nᵀ + (r²/4)(k1² e1 e1ᵀ + k2² e2 e2ᵀ)]`: with `λ_n` its largest
/// eigenvalue, `|k_i| = (2/r) sqrt(λ_i / λ_n)` and the eigenvectors are the normal and the
/// principal directions. The curvatures enter squared: their signs are not available.
/// The Delaunay triangulation is sequential whatever `ConcurrencyTag`; the cells, the
/// neighbourhood counts, the convolution and the final diagonalisations follow it.
///
/// Fields: `min_curvature <= max_curvature` hold the UNSIGNED magnitudes `|k|` of the two
/// principal curvatures (>= 0), in 1/(unit of the coordinates), `min_direction` and
/// `max_direction` their directions (the smaller magnitude's direction is `min_direction`,
/// whatever the signs); `normal` the VCM normal, oriented like the input normals;
/// `mean_curvature` and `gaussian_curvature` are NaN. `neighbor_count` counts the points
/// at distance `< r` as for the other estimators.
///
/// Accuracy: coarse. Each Voronoi cell also spreads tangentially over the sampling spacing
/// `h`, which adds about `h²/(4R²)` to every `λ_i / λ_n`: the magnitudes are biased
/// upwards unless `h` is small against `R r |k|`, i.e. unless `R` approaches the local
/// feature size (CGAL's advice for `offset_radius`). The directions are better than the
/// magnitudes; `R = 0.5 r` (the paper's setting) is worse than `R = r` (measured:
/// benchmark/README.md, section 10).
///
/// Results: one `Curvature_estimate` per element of `points`, in the same order, with the
/// statuses of `CGAL::estimate_aso_curvatures()`: `NON_FINITE_POINT`, `INVALID_NORMAL`
/// (such points are nobody's neighbour either), `NOT_COMPUTED` (cancelled through
/// `callback`), `TOO_FEW_NEIGHBORS` (fewer points at distance `< r`, the query included,
/// than `min_neighbors`: 20 by default), `DEGENERATE_FIT` (the usable points are collinear, or the measure is zero).
/// Invalid estimates hold NaN in every numeric field. Sequential and parallel runs, and runs
/// of different processes, return bitwise identical results.
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
///        It is also the convolution radius of the VCM.
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
///     \cgalParamDescription{called with 0 before the Voronoi construction (which cannot be
///       interrupted), then with the fraction of points processed during the final
///       per-point stage; if it returns `false` the points not yet processed keep the status
///       `NOT_COMPUTED`}
///     \cgalParamType{an instance of `std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::vcm_offset_radius}
///     \cgalParamDescription{the offset radius `R` of the Voronoi Covariance Measure: each
///       Voronoi cell is cut by the ball of radius `R` around its point (CGAL's
///       `offset_radius`), in the unit of the coordinates}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{the radius `r` (by count: the median of the per-point radii);
///       Lejemble et al. 2021 use `0.5 r`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`CGAL::Point_set_curvatures::default_min_neighbors::vcm`, the measured minimum
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
///     \cgalParamDescription{not supported: the cells come from the Delaunay triangulation of
///       the whole cloud (and by count the offset radius is the median radius of the whole
///       cloud); `std::invalid_argument` is thrown}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if `radius` is not positive and finite, or if
///   `vcm_offset_radius` is given and not positive and finite.
/// \throws std::length_error with 2^32 points or more.
///
/// \sa `CGAL::compute_vcm()`, `CGAL::vcm_estimate_normals()`;
/// `CGAL::estimate_aso_curvatures()`, signed, more accurate and faster.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_vcm_curvatures(const PointRange& points, double radius,
                        const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_vcm_at_every_point<ConcurrencyTag>(points, true, radius, np,
                                                                                     "estimate_vcm_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`; each point's radius is the
/// distance to its `k`-th nearest neighbour (itself counted), enlarged by a factor
/// `1 + 2^-20` so that the `k` nearest are inside (see `neighbor_count`).
/// The convolution then sums each point's own neighbourhood (the points at distance `<`
/// its radius).
/// \throws std::invalid_argument if `neighbor_count` is missing or 0, or if
///   `vcm_offset_radius` is given and not positive and finite.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
typename Point_set_curvatures::internal::Estimates_without_radius<PointRange, NamedParameters>::type
estimate_vcm_curvatures(const PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::estimate_vcm_at_every_point<ConcurrencyTag>(points, false, 0.0, np,
                                                                                     "estimate_vcm_curvatures");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<Curvature_estimate<typename Kernel_traits<typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_vcm_curvatures(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius)
{
  return estimate_vcm_curvatures<ConcurrencyTag>(points, radius,
                                                 parameters::point_map(point_map).normal_map(normal_map));
}

}  // namespace CGAL

#endif
