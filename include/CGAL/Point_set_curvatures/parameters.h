// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Named parameters of the package that CGAL's closed list (CGAL::parameters) does not have.
// They live in CGAL::Point_set_curvatures::parameters and chain with CGAL's own ones by
// taking them as last argument:
//
//   namespace PSC = CGAL::Point_set_curvatures;
//   auto np = PSC::parameters::aso_projection(CGAL::Aso_projection::AUTHORS_IMPLEMENTATION,
//               CGAL::parameters::point_map(pm).normal_map(nm));

#ifndef CGAL_POINT_SET_CURVATURES_PARAMETERS_H
#define CGAL_POINT_SET_CURVATURES_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_curvatures/Tile.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
/// Tangent plane on which the Algebraic Shape Operator is projected (Equation 27 of
/// Lejemble et al. 2021 leaves it implicit).
enum class Aso_projection {
  /// The plane orthogonal to `grad f`, the corrected normal that is returned: `W` is the
  /// shape operator of the level set of the fitted field, directions are exactly tangent.
  /// Default.
  CORRECTED_NORMAL,
  /// As in the authors' implementation (STORM-IRIT/algebraic-shape-operator): the plane
  /// orthogonal to the linear coefficient `u_l`, the tensor `Hess f/|grad f| - N N^T Hess f`,
  /// input normals used without normalisation. Reproduces their values to about 1e-12;
  /// directions are then orthogonal to `u_l`, not exactly to the returned normal.
  AUTHORS_IMPLEMENTATION
};

namespace Point_set_curvatures {

class Scale_choices;

namespace internal_np {

enum aso_projection_t { aso_projection };
enum neighbor_count_t { neighbor_count };
enum automatic_scale_t { automatic_scale };
enum scale_choices_t { scale_choices };

}  // namespace internal_np

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter selecting the tangent plane of `estimate_aso_curvatures()` (default
/// `CGAL::Aso_projection::CORRECTED_NORMAL`). Chains with CGAL named parameters passed as
/// `np`.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Aso_projection, internal_np::aso_projection_t, NamedParameters>
aso_projection(Aso_projection projection, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Aso_projection, internal_np::aso_projection_t, NamedParameters>(projection,
                                                                                                         np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter selecting neighbourhoods by count, so that the scale follows the sampling
/// density (LiDAR). Each point's kernel radius is `(1 + 2^-20)` times the distance to its
/// `k`-th nearest usable point (the point itself counted as the first): the neighbourhood
/// holds the `k` nearest and any point tied with the `k`-th, so at least `k` points (all of
/// them if the cloud has fewer), and the `k`-th point's weight is negligible (about 4e-12).
/// Use it with the overloads of the estimation functions that take no radius.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<std::size_t, internal_np::neighbor_count_t, NamedParameters>
neighbor_count(std::size_t k, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<std::size_t, internal_np::neighbor_count_t, NamedParameters>(k, np);
}

/// Named parameter of `estimate_aso_curvatures()` (by count) and `estimate_oriented_normals()`
/// (`Normal_fit::QUADRIC`): the scale is chosen per point among the neighbour counts `k`,
/// `2k`, `4k`, ... up to `largest` (`k` that of `neighbor_count`), for clouds with position
/// noise (scans). A quadric fitted to the positions at each count gives the mean curvature
/// (for normals: the normal) and its standard error under the noise that its residuals
/// show; the count kept is the largest whose value agrees with those of every smaller count
/// within three standard errors (the intersection of confidence intervals, a Lepski-type
/// rule). Without noise (less than half of the smallest count's residuals) the smallest
/// count is kept and the estimate is that of `neighbor_count(k)`. Where a larger count is
/// chosen, the mean curvature is that of the APSS sphere on its neighbourhood when it agrees
/// with the quadric's (three standard errors) and with the ASO's (four; not required where the
/// ASO's normals disagree, `normal_coherence` below 0.95, or its standard error times the
/// radius exceeds 0.05), the difference of the principal curvatures and the directions the
/// ASO's, computed there without `position_fit_blend` and with the quartic kernel in place of the
/// cubic one (the rule tolerates a bias of about one standard error, which both reduce on
/// simulated noisy scans); where a count was chosen for noise, the sphere is not taken and the
/// ASO's mean curvature lies more than 30 standard errors from the quadric's (the first and last
/// profiles of a scan: one-sided neighbourhoods, estimated normals that bend), the curvatures
/// are the quadric's, the normal the ASO's. `Curvature_estimate::neighbor_count` is then the
/// chosen count and `Curvature_estimate::mean_curvature_error` the standard error of the mean
/// curvature there.
/// The counts are climbed in passes (2k for every point, then 4k, 8k, ... only where the
/// previous pass kept its largest): a point pays at most twice the neighbourhood it ends
/// with. Default: none (the scale of `neighbor_count`); 0 is none too. Not supported with a
/// radius, nor with `normal_refinement`.
/// Measurements: benchmark/README.md, "Automatic scale".
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<std::size_t, internal_np::automatic_scale_t, NamedParameters>
automatic_scale(std::size_t largest, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<std::size_t, internal_np::automatic_scale_t, NamedParameters>(largest, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_oriented_normals()` and `estimate_aso_curvatures()` with
/// `automatic_scale`: the normals' passes record in `choices` the count the curvatures' rule
/// chooses at each point they climb for (the rule fits the same rungs of the same
/// neighbourhoods), and the curvatures read it, searching each such point's neighbourhood once,
/// at its count, instead of the ladder's (the same estimates, bit for bit; see
/// `Scale_choices`). The tool passes it whenever it estimates the normals in memory.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Scale_choices*, internal_np::scale_choices_t, NamedParameters>
scale_choices(Scale_choices& choices, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Scale_choices*, internal_np::scale_choices_t, NamedParameters>(&choices, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// `scale_choices` by pointer: null for none.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Scale_choices*, internal_np::scale_choices_t, NamedParameters>
scale_choices(Scale_choices* choices, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Scale_choices*, internal_np::scale_choices_t, NamedParameters>(choices, np);
}

}  // namespace parameters

/// \ingroup PkgPointSetCurvaturesRef
/// The ladder of counts that the command-line tool's default scale (`--neighbors auto`) and
/// Python's `neighbors="auto"` use: `parameters::neighbor_count(smallest)` with
/// `parameters::automatic_scale(largest)`, the counts 40, 80, ..., 640 (chosen by measurement:
/// benchmark/README.md, "Automatic scale").
namespace automatic_scale_ladder {
/// The smallest count, that of clean surfaces.
constexpr std::size_t smallest = 40;
/// The largest count.
constexpr std::size_t largest = 640;
}  // namespace automatic_scale_ladder

}  // namespace Point_set_curvatures

// ---- Validity and tiles: options of every per-point function ----
namespace Point_set_curvatures {
namespace internal_np {

enum min_neighbors_t { min_neighbors };
enum accept_unnormalized_normals_t { accept_unnormalized_normals };
enum tile_t { tile };

}  // namespace internal_np

/// \ingroup PkgPointSetCurvaturesRef
/// The default of `parameters::min_neighbors()` for each estimation function: its measured
/// least neighbour count (query point included), the smallest count from which its mean error
/// stays within 3 times its error at 40 neighbours on four Goursat clouds (blue noise 10K and
/// 50K, i.i.d. random 10K, simulated LiDAR scan lines; measured with `paper_experiments --only
/// neighbors`, user manual, "Neighbourhoods and scale"). Below it errors grow 5 to 1000 times
/// (jets, wavejets and PSS on scan lines). The tool and the Python bindings read these values.
namespace default_min_neighbors {
/// `estimate_aso_curvatures()`
constexpr std::size_t aso = 12;
/// `estimate_apss_curvatures()`
constexpr std::size_t apss = 12;
/// `estimate_algebraic_sphere_features()`
constexpr std::size_t sphere_features = apss;
/// `estimate_barycenter_curvatures()`
constexpr std::size_t barycenter = 20;
/// `estimate_pca_plane_curvatures()`
constexpr std::size_t pca_plane = 10;
/// `estimate_jet_curvatures()`
constexpr std::size_t jet = 12;
/// `estimate_wavejet_curvatures()`
constexpr std::size_t wavejet = 12;
/// `estimate_pss_curvatures()`
constexpr std::size_t pss = 15;
/// `estimate_vcm_curvatures()`
constexpr std::size_t vcm = 20;
}  // namespace default_min_neighbors

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of every estimation function: the least number of neighbours (points at
/// distance `< r`, the query point included) for which an estimate is computed; below it the
/// estimate is `TOO_FEW_NEIGHBORS`, with NaN fields and its `neighbor_count` set.
///
/// The default of each function is its measured minimum, the constant of its name in
/// `CGAL::Point_set_curvatures::default_min_neighbors`. A smaller value is raised to what the
/// fit itself needs (3 for the sphere fits, the barycenter, the PCA plane and VCM, 6 for PSS,
/// wavejets and order-2 jets).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<std::size_t, internal_np::min_neighbors_t, NamedParameters>
min_neighbors(std::size_t count, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<std::size_t, internal_np::min_neighbors_t, NamedParameters>(count, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of every function reading normals: by default (`false`) a normal whose
/// length lies outside `[1e-3, 1e3]` is `INVALID_NORMAL` (and the point is nobody's
/// neighbour), since such a vector is almost surely not a normal (colours read as normals,
/// unscaled integers); `true` accepts any finite non-zero length, for the estimators that use
/// the input normals unnormalised on purpose (`aso_projection(AUTHORS_IMPLEMENTATION)`).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<bool, internal_np::accept_unnormalized_normals_t, NamedParameters>
accept_unnormalized_normals(bool accept, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<bool, internal_np::accept_unnormalized_normals_t, NamedParameters>(accept, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of every estimation function: estimates only the own points of `tile` (the
/// range holds them and their halo, see `CGAL::Point_set_curvatures::Tile`), bitwise as in
/// the whole-cloud run; the other points get `NOT_COMPUTED` (unusable points
/// keep `NON_FINITE_POINT` or `INVALID_NORMAL`). With a halo too small for that,
/// the function throws `CGAL::Point_set_curvatures::Halo_too_small` (neighbourhoods by count)
/// or `std::invalid_argument` (by radius: the halo must be at least the radius, twice the
/// radius with sample weights, the default of `estimate_aso_curvatures()`; by count with
/// sample weights, the areas of the own points' neighbours must also be exact, which is
/// checked after the estimation). Not supported with `normal_refinement`
/// (`std::invalid_argument`). `Tile::whole_space()` is the same as no tile (no restriction).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Tile, internal_np::tile_t, NamedParameters>
tile(const Tile& t, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Tile, internal_np::tile_t, NamedParameters>(t, np);
}

}  // namespace parameters
}  // namespace Point_set_curvatures
// ---- end of the validity and tile options ----

// ---- Beyond the paper: sample weights, robust orientation, refinement, variants ----

/// \ingroup PkgPointSetCurvaturesRef
/// Quadrature weights of the samples in the sums of the sphere fit and of the ASO.
enum class Sample_weights {
  /// Every neighbour counts once (the paper).
  UNIFORM,
  /// Every neighbour's kernel weight is multiplied by the area of its Voronoi cell taken in
  /// its own tangent plane (among its neighbours, within a disk of radius `r/4`): the sums
  /// become a quadrature of the surface integrals that does not depend on how evenly the
  /// samples are spread (i.i.d. samples, scan lines, density varying with range). Computed in
  /// one more pass of the neighbourhood driver; it does not depend on the evaluation point,
  /// so the ASO's derivatives stay exact.
  TANGENT_VORONOI_AREA
};

/// \ingroup PkgPointSetCurvaturesRef
/// A preset of the options of `estimate_aso_curvatures()` (see
/// `CGAL::Point_set_curvatures::parameters::aso_variant()`); explicit options override it.
enum class Aso_variant {
  /// The estimator of Lejemble et al. 2021: kernel `(1 - d²/r²)²`, uniform sample weights,
  /// input normals used as given, no normal-field blend. With `aso_projection(Aso_projection::AUTHORS_IMPLEMENTATION)`
  /// it reproduces the authors' published values.
  PAPER,
  /// The package's default, chosen by measurement (user manual, "Beyond the paper"): kernel
  /// `(1 - d²/r²)³`, tangent Voronoi area weights, neighbours' normals oriented by the
  /// weighted majority, a normal-field fit blended in where the neighbourhood is one-sided.
  ROBUST
};

namespace Point_set_curvatures {
namespace internal_np {

enum sample_weights_t { sample_weights };
enum robust_orientation_t { robust_orientation };
enum normal_refinement_t { normal_refinement };
enum aso_variant_t { aso_variant };
enum normal_field_blend_t { normal_field_blend };
enum sample_weight_map_t { sample_weight_map };
enum position_fit_blend_t { position_fit_blend };

}  // namespace internal_np

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()` and `estimate_apss_curvatures()`: the
/// quadrature weights of the samples (`CGAL::Sample_weights`). Default: that of the variant
/// (`TANGENT_VORONOI_AREA` for `Aso_variant::ROBUST`, `UNIFORM` for `PAPER` and for APSS).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Sample_weights, internal_np::sample_weights_t, NamedParameters>
sample_weights(Sample_weights weights, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Sample_weights, internal_np::sample_weights_t, NamedParameters>(weights, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter: a property map whose value type converts to `double`, the quadrature
/// weight of every point of the range (its key type is the range's value type).
/// `estimate_tangent_voronoi_areas()` writes the areas into it; `estimate_aso_curvatures()`,
/// `estimate_apss_curvatures()` and `estimate_algebraic_sphere_features()` read the weights
/// from it instead of computing them, whatever `sample_weights` and `aso_variant` say, so that
/// one area pass serves every estimator of a run. Weights must be finite and non-negative
/// (`std::invalid_argument` otherwise); an estimate whose neighbours all weigh 0 is
/// `DEGENERATE_FIT`. With the areas of `estimate_tangent_voronoi_areas()` at the same scale,
/// the estimates are bitwise those the functions give with `TANGENT_VORONOI_AREA` alone. With
/// `tile`, the map must hold the whole cloud's weights (the halo then needs one radius, not the
/// area pass's reach): areas computed on the tile's range alone are not the whole cloud's near
/// the halo's edge. The other estimators ignore the map.
template <class PropertyMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<PropertyMap, internal_np::sample_weight_map_t, NamedParameters>
sample_weight_map(const PropertyMap& map, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<PropertyMap, internal_np::sample_weight_map_t, NamedParameters>(map, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()` and `estimate_apss_curvatures()`: if
/// `true`, the normal of every neighbour that disagrees with the weighted majority of the
/// neighbourhood's normals is used flipped (in the same pass), so that flipped patches of
/// estimated normals do not bias the fit; the returned normal follows the majority. Default:
/// that of the variant (`true` for `Aso_variant::ROBUST`, `false` for `PAPER` and for APSS).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<bool, internal_np::robust_orientation_t, NamedParameters>
robust_orientation(bool robust, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<bool, internal_np::robust_orientation_t, NamedParameters>(robust, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()`: if `true`, where the neighbourhood is
/// one-sided (the border of a scan, the silhouette seen from a scanner, very irregular
/// sampling), the ASO's tensor is blended with a weighted least-squares fit of the normal
/// field, `n_t = n_0 + S (u, v)` in the tangent plane of the corrected normal, exact on spheres
/// and not biased by one-sided neighbourhoods, where the ASO underestimates the curvature
/// across the border. The blend weight is a smooth step of the tangential offset of the
/// weighted centroid of the neighbourhood: 0 below 0.02 r, 1 above 0.06 r. Measured mean error
/// of `H` (×1e-3): simulated LiDAR scan of the Goursat surface 3.35 without, 1.30 with; i.i.d.
/// samples 2.79 and 2.28; blue noise unchanged (0.255). Ignored with
/// `aso_projection(AUTHORS_IMPLEMENTATION)`. Default: that of the variant (`true` for
/// `Aso_variant::ROBUST`, `false` for `PAPER`).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<bool, internal_np::normal_field_blend_t, NamedParameters>
normal_field_blend(bool blend, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<bool, internal_np::normal_field_blend_t, NamedParameters>(blend, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()`, for normals estimated from the positions
/// (`CGAL::estimate_oriented_normals()`): the weight `w` in `[0, 1]` of a fit of the positions
/// alone in the shape operator, `(1 - w) ASO + w Q`, where `Q` is the shape operator of a
/// quadric fitted to the neighbours by weighted least squares (the fit of
/// `Normal_fit::QUADRIC`, in the same neighbourhood). The ASO differentiates the normal field,
/// so the small point-to-point errors of estimated normals pass into its tensor; those of the
/// quadric are partly independent. Measured on simulated scans without normals
/// (benchmark/README.md, "Scans without normals"; normals of `Normal_fit::QUADRIC` at 40
/// neighbours, curvatures at 40): mean error of `H` with `w = 0` / `0.5` / exact normals, a
/// terrestrial scan of a torus 2.7e-3 / 2.5e-3 / 1.9e-3, airborne scan lines 1.1e-3 / 0.85e-3 /
/// 0.80e-3, two terrestrial scans merged 0.35e-3 / 0.23e-3 / 0.24e-3. With exact normals it
/// costs accuracy. Where the quadric has no fit (neighbours along one line) the ASO is kept
/// alone. With `automatic_scale`, it is left out where the rule chose a count above the smallest
/// one because noise dominates: the normals come from large neighbourhoods there, and the
/// quadric's bias at that scale exceeds what it saves (simulated scans, range noise 0.3 spacings:
/// airborne lines 0.0116 -> 0.0099, a torus 0.0261 -> 0.0237; benchmark/README.md section 9);
/// there the ASO also takes the quartic kernel in place of the cubic one (see `automatic_scale`).
/// Ignored with `aso_projection(AUTHORS_IMPLEMENTATION)`. Default 0.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<double, internal_np::position_fit_blend_t, NamedParameters>
position_fit_blend(double weight, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<double, internal_np::position_fit_blend_t, NamedParameters>(weight, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()`: before the estimation, `iterations`
/// passes each replace the input normals by corrected normals (points without a valid fit
/// keep their input normal): those of the APSS sphere fitted with the paper's kernel
/// `(1 - d²/r²)²` and the estimation's sample weights and orientation, which is wider than the
/// default ASO's kernel and so passes less of the normals' noise on (on Goursat 50K with
/// every normal tilted by 30°, mean error of `H` 50.7e-3 without, 8.9e-3 with one pass, 4.0e-3
/// with two; refining with the ASO's own normals gave 16.3e-3 and 6.0e-3). The sample
/// weights are computed once. For noisy input normals; on clean ones it costs accuracy
/// (0.26e-3 to 0.70e-3 on the same cloud). Default 0. Not supported with `tile`.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<std::size_t, internal_np::normal_refinement_t, NamedParameters>
normal_refinement(std::size_t iterations, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<std::size_t, internal_np::normal_refinement_t, NamedParameters>(iterations,
                                                                                                         np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()`: a preset of the kernel, the sample
/// weights, the orientation and the blend (`CGAL::Aso_variant`); `weight_kernel`,
/// `sample_weights`, `robust_orientation` and `normal_field_blend` given explicitly override it. `Aso_variant::PAPER` restores the
/// paper's estimator exactly. Default: `Aso_variant::ROBUST`.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Aso_variant, internal_np::aso_variant_t, NamedParameters>
aso_variant(Aso_variant variant, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Aso_variant, internal_np::aso_variant_t, NamedParameters>(variant, np);
}

}  // namespace parameters
}  // namespace Point_set_curvatures
// ---- end of the options beyond the paper ----

// ---- Baseline estimators: options of estimate_vcm_curvatures() ----
namespace Point_set_curvatures {
namespace internal_np {

enum vcm_offset_radius_t { vcm_offset_radius };

}  // namespace internal_np

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_vcm_curvatures()`: the offset radius `R` of the Voronoi
/// Covariance Measure (each Voronoi cell is cut by a ball of radius `R` around its point), in
/// the unit of the coordinates, positive and finite. Default: the neighbourhood radius `r`
/// (with neighbourhoods by count, the median of the per-point radii). Lejemble et al. 2021
/// use `R = 0.5 r`. Chains with CGAL named parameters passed as `np`.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<double, internal_np::vcm_offset_radius_t, NamedParameters>
vcm_offset_radius(double offset_radius, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<double, internal_np::vcm_offset_radius_t, NamedParameters>(offset_radius, np);
}

}  // namespace parameters
}  // namespace Point_set_curvatures
// ---- end of the baseline estimators' options ----

// ---- Algebraic sphere features, projection and flow: weight kernel, normals ----
/// \ingroup PkgPointSetCurvaturesRef
/// Weight kernel of the APSS algebraic sphere fit (Equation 5 of Lejemble et al. 2021), for
/// a neighbour at distance `d` from the evaluation point and a radius `r`; also that of the
/// ASO, which fits the same sphere (the name is the paper's). `SMOOTH` is the paper's kernel,
/// the least smooth of the three polynomial ones at `d = r`.
enum class Apss_weight_kernel {
  /// `(1 - d²/r²)²` for `d < r`: the kernel of the paper, differentiable (the Algebraic
  /// Shape Operator needs it; its scale derivatives are exact on the samples). Default of the
  /// APSS functions and of `Aso_variant::PAPER`.
  SMOOTH,
  /// `1` for `d < r`: the constant weight of the paper's asymptotic analysis (Section 4.1),
  /// under which its asymptotic constants hold as printed. It has no spatial derivative, so
  /// the Algebraic Shape Operator rejects it; its derivative in the scale `r` is a boundary
  /// term, estimated as documented in `Algebraic_sphere_features::geometric_variation`.
  CONSTANT,
  /// `(1 - d²/r²)³`: its Hessian vanishes at `d = r`, so points entering the ball do not make
  /// the ASO jump. Default of `Aso_variant::ROBUST`. Accepted by every function that takes a
  /// kernel, with exact derivatives (spatial for the ASO, in the scale for the sphere
  /// features).
  SMOOTH_CUBIC,
  /// `(1 - d²/r²)⁴`, narrower still. Accepted by every function that takes a kernel.
  SMOOTH_QUARTIC
};

namespace Point_set_curvatures {
namespace internal_np {

enum weight_kernel_t { weight_kernel };
enum update_normals_t { update_normals };

}  // namespace internal_np

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter selecting the weight kernel of `estimate_apss_curvatures()`,
/// `estimate_algebraic_sphere_features()`, `CGAL::Algebraic_point_set_surface` and
/// `apss_smooth_point_set()` (default `CGAL::Apss_weight_kernel::SMOOTH`). Chains with CGAL
/// named parameters passed as `np`.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Apss_weight_kernel, internal_np::weight_kernel_t, NamedParameters>
weight_kernel(Apss_weight_kernel kernel, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Apss_weight_kernel, internal_np::weight_kernel_t, NamedParameters>(kernel, np);
}

}  // namespace parameters

/// \ingroup PkgPointSetCurvaturesRef
/// The options that a variant of `estimate_aso_curvatures()` (`CGAL::Aso_variant`) uses
/// where they are not given explicitly. The library's presets, for callers that pass every
/// option explicitly (the Python bindings) and must not restate them.
struct Aso_variant_options
{
  /// `weight_kernel`: `SMOOTH` for the paper, `SMOOTH_CUBIC` for the robust variant.
  Apss_weight_kernel weight_kernel;
  /// `sample_weights`: `UNIFORM` for the paper, `TANGENT_VORONOI_AREA` for the robust variant.
  Sample_weights sample_weights;
  /// `robust_orientation`: `false` for the paper, `true` for the robust variant.
  bool robust_orientation;
  /// `normal_field_blend`: `false` for the paper, `true` for the robust variant.
  bool normal_field_blend;
};

/// \ingroup PkgPointSetCurvaturesRef
/// The preset of `variant`: what `estimate_aso_curvatures()` uses for every option of
/// `Aso_variant_options` that the named parameters do not give.
inline Aso_variant_options aso_variant_options(Aso_variant variant)
{
  if(variant == Aso_variant::PAPER)
    return {Apss_weight_kernel::SMOOTH, Sample_weights::UNIFORM, false, false};
  return {Apss_weight_kernel::SMOOTH_CUBIC, Sample_weights::TANGENT_VORONOI_AREA, true, true};
}

namespace internal_np {

enum aso_options_t { aso_options };

}  // namespace internal_np

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `estimate_aso_curvatures()`: the four options of
/// `CGAL::Point_set_curvatures::Aso_variant_options` as one value, in place of the preset of
/// `aso_variant()` (so the variant no longer matters for them), for example a preset with one
/// option changed:
///
///     namespace PSC = CGAL::Point_set_curvatures;
///     PSC::Aso_variant_options o = PSC::aso_variant_options(CGAL::Aso_variant::ROBUST);
///     o.sample_weights = CGAL::Sample_weights::UNIFORM;
///     CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(points, r, PSC::parameters::aso_options(o));
///
/// `weight_kernel()`, `sample_weights()`, `robust_orientation()` and `normal_field_blend()`
/// given as well override the corresponding member. Default: the preset of the variant.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Aso_variant_options, internal_np::aso_options_t, NamedParameters>
aso_options(const Aso_variant_options& options, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Aso_variant_options, internal_np::aso_options_t, NamedParameters>(options, np);
}

}  // namespace parameters

namespace internal {

// P of the kernel (1 - d^2/r^2)^P; 0 for the constant kernel.
inline int kernel_exponent(Apss_weight_kernel k)
{
  switch(k)
  {
    case Apss_weight_kernel::SMOOTH: return 2;
    case Apss_weight_kernel::SMOOTH_CUBIC: return 3;
    case Apss_weight_kernel::SMOOTH_QUARTIC: return 4;
    default: return 0;
  }
}

// The weight kernel of a named parameter pack (default SMOOTH).
template <class NamedParameters>
Apss_weight_kernel weight_kernel_parameter(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::weight_kernel),
                                            Apss_weight_kernel::SMOOTH);
}

}  // namespace internal

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `apss_smooth_point_set()`: if `true`, each iteration replaces the normals
/// by those of the fitted spheres at the moved points (used by the next iteration, and written
/// through the normal map at the end, which must then be writable); if `false` (default), the
/// input normals are used throughout and left untouched. Chains with CGAL named parameters.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<bool, internal_np::update_normals_t, NamedParameters>
update_normals(bool update, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<bool, internal_np::update_normals_t, NamedParameters>(update, np);
}

}  // namespace parameters
}  // namespace Point_set_curvatures
// ---- end of the algebraic sphere features' options ----
}  // namespace CGAL

#endif
