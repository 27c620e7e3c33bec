// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_ASO_CURVATURES_H
#define CGAL_ESTIMATE_ASO_CURVATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Algebraic_shape_operator_fit.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/scale_choices.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_shape_operator.h>
#include <CGAL/Point_set_curvatures/internal/automatic_scale_estimation.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>
#include <CGAL/estimate_apss_curvatures.h>

#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Per-point ASO: two passes over the neighbours, then the closed-form shape operator.
struct Aso_estimator : Estimator_base
{
  Aso_settings settings;

  explicit Aso_estimator(const Aso_settings& s) : settings(s)
  {
    normalize_normals = (s.projection == Aso_projection::CORRECTED_NORMAL);
    check_tangent_spread = false;  // tested on the first pass's moments
    takes_weight_map = true;
    min_neighbors = default_min_neighbors::aso;
  }

  Local_estimate operator()(const Neighborhood& nb) const { return algebraic_shape_operator(nb, settings); }

  // The normals of the normal_refinement passes: the APSS sphere's, with the paper's wider
  // kernel (1 - d²/r²)² and the ASO's sample weights and orientation. Measured on Goursat 50K
  // at r = 1.5 with every normal tilted by 30° (mean |H| error ×1e-3): one pass 8.9, against
  // 16.3 when the ASO refined its own normals (its narrower kernel passes more of the noise
  // on); under position noise σ = 0.2 55.8 against 75.4.
  Local_estimate refinement_fit(const Neighborhood& nb) const
  {
    Apss_estimator apss;
    apss.kernel = Apss_weight_kernel::SMOOTH;
    apss.orient_neighbors = settings.orient_neighbors;
    return apss(nb);
  }
};

// The variant of estimate_aso_curvatures() when aso_variant() is not given: chosen by
// measurement (user manual, "Beyond the paper").
constexpr Aso_variant default_aso_variant = Aso_variant::ROBUST;

// The ASO from the named parameters (aso_settings_from()), its sample weights and its
// normal refinement.
template <class NamedParameters>
Aso_estimator aso_estimator_from(const NamedParameters& np)
{
  bool area_weights = false;
  Aso_estimator estimator(aso_settings_from(np, default_aso_variant, "estimate_aso_curvatures", &area_weights));
  estimator.area_weights = area_weights;
  estimator.normal_refinements = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::normal_refinement), std::size_t(0));
  return estimator;
}

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates, at every point of an oriented point cloud, the corrected normal, the
/// principal curvatures and directions, the mean and the Gaussian curvature with the
/// Algebraic Shape Operator (ASO) of Lejemble, Coeurjolly, Barthe and Mellado, "Stable and
/// efficient differential estimators on oriented point clouds", Computer Graphics Forum
/// 40(5), 2021 (Section 5, Equations 27-35).
///
/// At each point `x`, an algebraic sphere is fitted to the neighbours at distance `< radius`
/// (the point itself included) with kernel weights (APSS, Equations 2-4); the fitted scalar
/// field is differentiated twice with respect to `x`, through the weights, and its shape
/// operator is projected on the tangent plane and diagonalised. Two passes over the
/// neighbours (first-order sums, then the Hessian term contracted with adjoints), constant
/// memory per point.
///
/// **Variants.** By default (`CGAL::Aso_variant::ROBUST`, chosen by measurement: user manual,
/// "Beyond the paper") the kernel is `(1 - d²/radius²)³`, each neighbour's weight is
/// multiplied by the area of its tangent Voronoi cell (one more, cheaper neighbourhood pass),
/// neighbours whose normals disagree with the weighted majority are used flipped, and where
/// the neighbourhood is one-sided (the border of a scan) a least-squares fit of the normal
/// field is blended in. It is more accurate than the paper's estimator on clean samples, and
/// than PSS and jets on i.i.d. samples and simulated scans, and undoes flipped normals (the
/// figures: user manual, "Beyond the paper"). The kernel `^3` is narrower than the paper's
/// `^2`: under position noise, use a radius `sqrt(3/2)` times larger for the same smoothing.
/// `aso_variant(Aso_variant::PAPER)` restores the paper's estimator exactly.
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
///       estimation stops and the points not yet processed keep the status `NOT_COMPUTED` (with
///       `automatic_scale()`, also those whose count would have been chosen in a later pass)}
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
///   \cgalParamNBegin{Point_set_curvatures::parameters::aso_variant}
///     \cgalParamDescription{a preset of the kernel, the sample weights, the orientation and
///       the blend: `ROBUST` or the paper's estimator `PAPER`; the four options below, given
///       explicitly, override it}
///     \cgalParamType{`CGAL::Aso_variant`}
///     \cgalParamDefault{`CGAL::Aso_variant::ROBUST`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::aso_options}
///     \cgalParamDescription{the four options below as one value, in place of the variant's
///       preset (for example a preset with one member changed); the four options, given
///       explicitly, override it}
///     \cgalParamType{`CGAL::Point_set_curvatures::Aso_variant_options`}
///     \cgalParamDefault{`aso_variant_options(variant)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::weight_kernel}
///     \cgalParamDescription{the kernel `(1 - d²/radius²)^P`: `SMOOTH` (P = 2, the paper's),
///       `SMOOTH_CUBIC` (3) or `SMOOTH_QUARTIC` (4), with exact derivatives; `CONSTANT` is
///       refused (no derivative)}
///     \cgalParamType{`CGAL::Apss_weight_kernel`}
///     \cgalParamDefault{`SMOOTH_CUBIC` (`SMOOTH` with `Aso_variant::PAPER`); with `automatic_scale`,
///       `SMOOTH_CUBIC` is `SMOOTH_QUARTIC` where a count above the smallest is kept for noise, and
///       where a count is kept without noise over neighbours spread evenly around the point}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::sample_weights}
///     \cgalParamDescription{the quadrature weights of the samples (`CGAL::Sample_weights`):
///       equal, or the areas of their tangent Voronoi cells, computed in one more pass over
///       neighbourhoods of radius `radius/2` (or the `k/4` nearest)}
///     \cgalParamType{`CGAL::Sample_weights`}
///     \cgalParamDefault{`TANGENT_VORONOI_AREA` (`UNIFORM` with `Aso_variant::PAPER`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::sample_weight_map}
///     \cgalParamDescription{the quadrature weights of the samples given per point (for
///       instance the areas of `estimate_tangent_voronoi_areas()`, computed once for several
///       estimators): read instead of computed, whatever `sample_weights` or `aso_variant` says;
///       finite and non-negative (`std::invalid_argument` otherwise)}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of the
///       iterator of `PointRange` and whose value type converts to `double`}
///     \cgalParamDefault{none: the weights of `sample_weights`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::robust_orientation}
///     \cgalParamDescription{neighbours whose normals disagree with the weighted majority of
///       the neighbourhood are used flipped; where they form a second sheet (both sides of a
///       thin plate within the radius) the status is `TWO_SHEETS`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true` (`false` with `Aso_variant::PAPER`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::normal_field_blend}
///     \cgalParamDescription{where the tangential offset of the neighbourhood's weighted
///       centroid exceeds 0.02 `radius` (one-sided neighbourhoods: borders, silhouettes), the
///       shape operator is blended with a least-squares fit of the normal field, fully from
///       0.06 `radius` on; likewise where the neighbourhood spreads much farther one way than
///       the other (scan lines far apart, mobile profiles: the ratio of the axes of its
///       tangential moments from 0.85 down to 0.7), where the ASO's derivatives follow the
///       weights moving between lines (ignored with `Aso_projection::AUTHORS_IMPLEMENTATION`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true` (`false` with `Aso_variant::PAPER`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::position_fit_blend}
///     \cgalParamDescription{for normals estimated from the positions: the weight `w` of the
///       shape operator of a quadric fitted to the neighbours' positions alone, blended with
///       the ASO's as `(1 - w) ASO + w quadric` (`w` in `[0, 1]`; `std::invalid_argument`
///       otherwise), `w` falling to 0 where the neighbourhood is one-sided as for
///       `normal_field_blend` (there the quadric extrapolates). With 0.5 the error on simulated
///       scans without normals was 0.92 to 1.35 times that with exact normals
///       (benchmark/README.md, section 8)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::normal_refinement}
///     \cgalParamDescription{the number of passes that replace the input normals by the
///       corrected normals of an APSS sphere fit (kernel `(1 - d²/r²)²`) before the
///       estimation, for noisy input normals (30° of normal noise on Goursat 50K: mean error
///       of `H` 50.7e-3, 8.9e-3 after one pass, 4.0e-3 after two)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`CGAL::Point_set_curvatures::default_min_neighbors::aso`, the measured minimum
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
/// `weight_kernel` is `CONSTANT`, or `position_fit_blend` lies outside `[0, 1]`.
/// \throws std::length_error with 2^32 points or more.
///
/// \sa `CGAL::Algebraic_shape_operator_fit` to evaluate at other positions or with your own
/// neighbourhoods; `CGAL::estimate_apss_curvatures()` for the cheaper normal and mean curvature.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_aso_curvatures(const PointRange& points, double radius,
                        const NamedParameters& np = parameters::default_values())
{
  Point_set_curvatures::internal::automatic_scale_parameter(np, true, "estimate_aso_curvatures");
  return Point_set_curvatures::internal::estimate_at_every_point<ConcurrencyTag>(
    points, true, radius, np, Point_set_curvatures::internal::aso_estimator_from(np), "estimate_aso_curvatures");
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
  namespace I = Point_set_curvatures::internal;
  const char* name = "estimate_aso_curvatures";
  const I::Aso_estimator aso = I::aso_estimator_from(np);
  const std::size_t largest = I::automatic_scale_parameter(np, false, name);
  if(largest == 0)
    return I::estimate_at_every_point<ConcurrencyTag>(points, false, 0.0, np, aso, name);
  // (a refinement pass would read the refined normals of the points its pass visits only)
  if(aso.normal_refinements > 0)
    throw std::invalid_argument(std::string(name) + ": parameter 'automatic_scale' is not supported with "
                                                    "normal_refinement");
  I::Apss_estimator sphere;
  sphere.orient_neighbors = aso.settings.orient_neighbors;
  I::Scale_ladder ladder;
  ladder.smallest = I::checked_scale<PointRange>(0.0, false, np, name);
  ladder.largest = largest;
  // where the rule climbed for noise: without the position fit, and the cubic kernel (the robust
  // variant's) made quartic (automatic_scale.h); where it kept a rung without noise and the
  // neighbours spread evenly, the quartic kernel too (clean data: less bias, and no noise for
  // the narrower kernel to pass on); decided on the settings, however given, so that the tool
  // and Python agree
  I::Scale_estimators<I::Aso_estimator> estimators{aso, aso, aso};
  estimators.at_noise_scale.settings.position_fit_blend = 0;
  if(aso.settings.kernel_exponent == I::kernel_exponent(Apss_weight_kernel::SMOOTH_CUBIC))
  {
    const int quartic = I::kernel_exponent(Apss_weight_kernel::SMOOTH_QUARTIC);
    estimators.at_noise_scale.settings.kernel_exponent = quartic;
    estimators.where_even.settings.kernel_exponent = quartic;
    estimators.narrower_where_even = true;
  }
  Point_set_curvatures::Scale_choices* choices = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, Point_set_curvatures::internal_np::scale_choices),
    static_cast<Point_set_curvatures::Scale_choices*>(nullptr));
  return I::estimate_at_automatic_scale<ConcurrencyTag>(points, np, estimators, sphere, ladder, name,
                                                        choices ? &choices->records() : nullptr);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<Curvature_estimate<typename Kernel_traits<typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_aso_curvatures(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius)
{
  return estimate_aso_curvatures<ConcurrencyTag>(points, radius,
                                                 parameters::point_map(point_map).normal_map(normal_map));
}

}  // namespace CGAL

#endif
