// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What each curvature estimator of the package is, declared once: its name, its function,
// the fields it fills, its measured neighbour counts and its own options. The command-line
// tool's method table and help, the Python bindings' method and option lists and enum names,
// and the tests that check the stubs and the manual's tables all read this declaration.

#ifndef CGAL_POINT_SET_CURVATURES_ESTIMATORS_H
#define CGAL_POINT_SET_CURVATURES_ESTIMATORS_H

#include <CGAL/Point_set_curvatures/parameters.h>

#include <cstddef>
#include <iterator>
#include <string_view>

namespace CGAL {
namespace Point_set_curvatures {

/// \ingroup PkgPointSetCurvaturesRef
/// The fields of `CGAL::Curvature_estimate` that an estimator fills with its default options
/// (bits of `Estimator_description::fields`); the others are NaN in its valid estimates.
/// (`normal_coherence` is NaN with the ASO's `Aso_projection::AUTHORS_IMPLEMENTATION`;
/// `mean_curvature_error` is filled by the automatic scale only.)
namespace estimate_fields {
/// `normal`
constexpr unsigned normal = 1u << 0;
/// `mean_curvature`
constexpr unsigned mean_curvature = 1u << 1;
/// `gaussian_curvature`
constexpr unsigned gaussian_curvature = 1u << 2;
/// `min_curvature` and `max_curvature`
constexpr unsigned principal_curvatures = 1u << 3;
/// `min_direction` and `max_direction`
constexpr unsigned principal_directions = 1u << 4;
/// `normal_coherence`
constexpr unsigned normal_coherence = 1u << 5;
/// Everything the full tensor gives.
constexpr unsigned tensor = normal | mean_curvature | gaussian_curvature | principal_curvatures | principal_directions;
}  // namespace estimate_fields

/// \ingroup PkgPointSetCurvaturesRef
/// The names of the values of an enumeration option, indexed by the enumerator's value (the
/// Python bindings accept them in any case, the tool's `--variant` in lower case).
struct Option_choices
{
  /// the names, `names[v]` that of the enumerator of value `v`
  const char* const* names = nullptr;
  /// their number
  std::size_t size = 0;
  /// the first name
  constexpr const char* const* begin() const { return names; }
  /// past the last name
  constexpr const char* const* end() const { return names + size; }
};

/// \ingroup PkgPointSetCurvaturesRef
/// The names of `CGAL::Aso_variant`'s values, by value.
inline constexpr const char* aso_variant_names[] = {"paper", "robust"};
/// \ingroup PkgPointSetCurvaturesRef
/// The names of `CGAL::Apss_weight_kernel`'s values, by value.
inline constexpr const char* weight_kernel_names[] = {"smooth", "constant", "smooth_cubic", "smooth_quartic"};
/// \ingroup PkgPointSetCurvaturesRef
/// The names of `CGAL::Sample_weights`'s values, by value.
inline constexpr const char* sample_weights_names[] = {"uniform", "tangent_voronoi_area"};
/// \ingroup PkgPointSetCurvaturesRef
/// The names of `CGAL::Aso_projection`'s values, by value.
inline constexpr const char* aso_projection_names[] = {"corrected_normal", "authors_implementation"};

// One name per value, each at its enumerator's value.
static_assert(std::size(aso_variant_names) == 2 &&
              std::string_view(aso_variant_names[int(Aso_variant::PAPER)]) == "paper" &&
              std::string_view(aso_variant_names[int(Aso_variant::ROBUST)]) == "robust");
static_assert(std::size(weight_kernel_names) == 4 &&
              std::string_view(weight_kernel_names[int(Apss_weight_kernel::SMOOTH)]) == "smooth" &&
              std::string_view(weight_kernel_names[int(Apss_weight_kernel::CONSTANT)]) == "constant" &&
              std::string_view(weight_kernel_names[int(Apss_weight_kernel::SMOOTH_CUBIC)]) == "smooth_cubic" &&
              std::string_view(weight_kernel_names[int(Apss_weight_kernel::SMOOTH_QUARTIC)]) == "smooth_quartic");
static_assert(std::size(sample_weights_names) == 2 &&
              std::string_view(sample_weights_names[int(Sample_weights::UNIFORM)]) == "uniform" &&
              std::string_view(sample_weights_names[int(Sample_weights::TANGENT_VORONOI_AREA)]) ==
                "tangent_voronoi_area");
static_assert(std::size(aso_projection_names) == 2 &&
              std::string_view(aso_projection_names[int(Aso_projection::CORRECTED_NORMAL)]) == "corrected_normal" &&
              std::string_view(aso_projection_names[int(Aso_projection::AUTHORS_IMPLEMENTATION)]) ==
                "authors_implementation");

/// \ingroup PkgPointSetCurvaturesRef
/// An option of an estimator beyond those every estimator takes (`min_neighbors`,
/// `accept_unnormalized_normals`, `tile`, the scale): a named parameter of
/// `CGAL::Point_set_curvatures::parameters` (or of CGAL's for the jets), the Python keyword of
/// the same name.
struct Estimator_option
{
  /// The named parameter, and the Python keyword.
  const char* name;
  /// What it takes, in words ("bool", "count", "real in [0, 1]", or the choices' names).
  const char* values;
  /// Its default, in words.
  const char* default_value;
  /// For an enumeration, the names of its values; empty otherwise.
  Option_choices choices;
};

/// \ingroup PkgPointSetCurvaturesRef
/// One curvature estimator of the package: every `estimate_*_curvatures()` function has one.
struct Estimator_description
{
  /// Its short name: the tool's `--method`, Python's `method`.
  const char* name;
  /// Its estimation function, in namespace `CGAL`.
  const char* function;
  /// One line on what it is.
  const char* summary;
  /// The fields it fills with its default options: bits of `estimate_fields`.
  unsigned fields;
  /// The default of `parameters::min_neighbors()`: `default_min_neighbors`.
  std::size_t min_neighbors;
  /// The count from which its mean error stays within twice its error at 40 neighbours (the
  /// tool warns below it); for the ASO, that of its default variant.
  std::size_t good_neighbors;
  /// `good_neighbors` of `CGAL::Aso_variant::PAPER` (the ASO); `good_neighbors` otherwise.
  std::size_t paper_variant_good_neighbors;
  /// Whether it supports `parameters::tile()` (not VCM, whose Voronoi cells need every
  /// point: it throws `std::invalid_argument`).
  bool supports_tiles;
  /// Whether it supports `parameters::automatic_scale()` (the ASO; the others ignore it).
  bool supports_automatic_scale;
  /// Its own options, `option_count` of them (null if none).
  const Estimator_option* options;
  /// The number of `options`.
  std::size_t option_count;
  /// Why it needs the whole cloud when it does not support tiles (for messages), else null.
  const char* whole_cloud_reason;

  /// The first option.
  constexpr const Estimator_option* begin() const { return options; }
  /// Past the last option.
  constexpr const Estimator_option* end() const { return options + option_count; }
  /// `paper_variant_good_neighbors` for `Aso_variant::PAPER`, else `good_neighbors`.
  constexpr std::size_t good_neighbors_of(Aso_variant variant) const
  {
    return variant == Aso_variant::PAPER ? paper_variant_good_neighbors : good_neighbors;
  }
};

namespace internal {

template <std::size_t N>
constexpr Option_choices choices_of(const char* const (&names)[N])
{
  return Option_choices{names, N};
}

inline constexpr Estimator_option aso_options[] = {
  {"aso_variant", "paper|robust", "robust", choices_of(aso_variant_names)},
  {"weight_kernel", "smooth|smooth_cubic|smooth_quartic", "the variant's: smooth_cubic (paper: smooth)",
   choices_of(weight_kernel_names)},
  {"sample_weights", "uniform|tangent_voronoi_area, or one weight per point",
   "the variant's: tangent_voronoi_area (paper: uniform)", choices_of(sample_weights_names)},
  {"robust_orientation", "bool", "the variant's: true (paper: false)", {}},
  {"normal_field_blend", "bool", "the variant's: true (paper: false)", {}},
  {"normal_refinement", "count", "0", {}},
  {"position_fit_blend", "real in [0, 1]", "0", {}},
  {"aso_projection", "corrected_normal|authors_implementation", "corrected_normal", choices_of(aso_projection_names)},
};

inline constexpr Estimator_option apss_options[] = {
  {"weight_kernel", "smooth|constant|smooth_cubic|smooth_quartic", "smooth", choices_of(weight_kernel_names)},
  {"sample_weights", "uniform|tangent_voronoi_area, or one weight per point", "uniform",
   choices_of(sample_weights_names)},
  {"robust_orientation", "bool", "false", {}},
};

inline constexpr Estimator_option jet_options[] = {
  {"degree_fitting", "count", "2", {}},
  {"degree_monge", "count", "2", {}},
};

inline constexpr Estimator_option vcm_options[] = {
  {"vcm_offset_radius", "positive real", "the radius (by count: the median radius)", {}},
};

// What an estimator supports beyond the common options.
struct Supports
{
  bool tiles = true;
  bool automatic_scale = false;
  const char* whole_cloud_reason = nullptr;  // (without tiles)
};

template <std::size_t N>
constexpr Estimator_description described(const char* name, const char* function, const char* summary, unsigned fields,
                                          std::size_t min_neighbors, std::size_t good_neighbors, std::size_t paper_good,
                                          Supports supports, const Estimator_option (&options)[N])
{
  return Estimator_description{name,
                               function,
                               summary,
                               fields,
                               min_neighbors,
                               good_neighbors,
                               paper_good,
                               supports.tiles,
                               supports.automatic_scale,
                               options,
                               N,
                               supports.whole_cloud_reason};
}

constexpr Estimator_description described(const char* name, const char* function, const char* summary, unsigned fields,
                                          std::size_t min_neighbors, std::size_t good_neighbors, Supports supports = {})
{
  return Estimator_description{name,
                               function,
                               summary,
                               fields,
                               min_neighbors,
                               good_neighbors,
                               good_neighbors,
                               supports.tiles,
                               supports.automatic_scale,
                               nullptr,
                               0,
                               supports.whole_cloud_reason};
}

}  // namespace internal

/// \ingroup PkgPointSetCurvaturesRef
/// Every curvature estimator of the package, the ASO first. The neighbour counts are measured
/// with `paper_experiments --only neighbors` (user manual, "The least neighbour count of a
/// valid estimate").
inline constexpr Estimator_description estimators[] = {
  internal::described("aso", "estimate_aso_curvatures",
                      "Algebraic Shape Operator (Lejemble et al. 2021): full curvature tensor",
                      estimate_fields::tensor | estimate_fields::normal_coherence, default_min_neighbors::aso, 12, 20,
                      internal::Supports{true, true}, internal::aso_options),
  internal::described("apss", "estimate_apss_curvatures",
                      "APSS algebraic sphere: corrected normal and mean curvature only",
                      estimate_fields::normal | estimate_fields::mean_curvature | estimate_fields::normal_coherence,
                      default_min_neighbors::apss, 20, 20, internal::Supports{}, internal::apss_options),
  internal::described("barycenter", "estimate_barycenter_curvatures", "baseline: distance to the barycentre",
                      estimate_fields::mean_curvature, default_min_neighbors::barycenter, 25),
  internal::described("pca_plane", "estimate_pca_plane_curvatures", "baseline: distance to the PCA plane",
                      estimate_fields::normal | estimate_fields::mean_curvature, default_min_neighbors::pca_plane, 15),
  internal::described("pss", "estimate_pss_curvatures", "baseline: point set surface", estimate_fields::tensor,
                      default_min_neighbors::pss, 20),
  internal::described("jet", "estimate_jet_curvatures", "baseline: osculating jet", estimate_fields::tensor,
                      default_min_neighbors::jet, 12, 12, internal::Supports{}, internal::jet_options),
  internal::described(
    "vcm", "estimate_vcm_curvatures", "baseline: Voronoi covariance measure",
    estimate_fields::normal | estimate_fields::principal_curvatures | estimate_fields::principal_directions,
    default_min_neighbors::vcm, 25, 25,
    internal::Supports{false, false, "its Voronoi cells come from the Delaunay triangulation of every point"},
    internal::vcm_options),
  internal::described("wavejet", "estimate_wavejet_curvatures", "baseline: wavejet", estimate_fields::tensor,
                      default_min_neighbors::wavejet, 12),
};

namespace internal {
// every estimator without tiles says why (the tool's message for inputs larger than memory)
constexpr bool whole_cloud_reasons_given()
{
  for(const Estimator_description& e : estimators)
    if(!e.supports_tiles && e.whole_cloud_reason == nullptr)
      return false;
  return true;
}
static_assert(whole_cloud_reasons_given(), "an estimator without tiles needs its whole_cloud_reason");
}  // namespace internal

/// \ingroup PkgPointSetCurvaturesRef
/// The defaults of the front ends (the command-line tool and the Python bindings), decided here
/// once so that both choose alike when the user gives no scale and no normals.
namespace front_end_defaults {

/// The neighbour count of a run given neither a radius nor a count, where
/// `automatic_scale()` is false.
inline constexpr std::size_t neighbor_count = 40;

/// Whether a run of `estimator` given neither a radius nor a count uses the automatic scale
/// (each point's count chosen by the noise its fits measure, `automatic_scale_ladder`): for the
/// estimators that support it, in the robust variant of the ASO (it keeps 40 neighbours where
/// the fits see no noise and grows where noise dominates, as on most real scans); the
/// paper's variant stays the paper's estimator at a fixed count.
constexpr bool automatic_scale(const Estimator_description& estimator, Aso_variant variant)
{
  return estimator.supports_automatic_scale && variant == Aso_variant::ROBUST;
}

/// `parameters::position_fit_blend()` of a run whose normals were estimated from the positions
/// (`estimate_oriented_normals()`): 0.5 for the robust ASO (on simulated scans its error was
/// then within 1.35 times that with exact normals), else 0.
constexpr double position_fit_blend(Aso_variant variant, bool normals_estimated)
{
  return normals_estimated && variant == Aso_variant::ROBUST ? 0.5 : 0.0;
}

}  // namespace front_end_defaults

/// \ingroup PkgPointSetCurvaturesRef
/// The estimator named `name` in `estimators`, null if there is none.
constexpr const Estimator_description* find_estimator(std::string_view name)
{
  for(const Estimator_description& e : estimators)
    if(name == e.name)
      return &e;
  return nullptr;
}

}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif  // CGAL_POINT_SET_CURVATURES_ESTIMATORS_H
