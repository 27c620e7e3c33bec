// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Public result type shared by every curvature estimator of the package.

#ifndef CGAL_CURVATURE_ESTIMATE_H
#define CGAL_CURVATURE_ESTIMATE_H

#include <cstddef>
#include <limits>
#include <ostream>
#include <type_traits>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
/// Why an estimate is, or is not, valid. Every estimator of the package fills
/// `Curvature_estimate::status` with one of these values.
enum class Curvature_estimate_status : unsigned char {
  VALID = 0,          ///< every field the estimator provides holds a finite value
  TOO_FEW_NEIGHBORS,  ///< fewer points at distance `< r` (query included) than the estimator needs
  DEGENERATE_FIT,     ///< the neighbours (nearly) coincide, or the fit has no usable normal or tensor
  NON_FINITE_POINT,   ///< the query point has a NaN or infinite coordinate
  INVALID_NORMAL,     ///< the input normal of the query point is zero, NaN or infinite
  NOT_COMPUTED,       ///< the run was cancelled by the `callback` before this point was processed
  /// with `robust_orientation`: the neighbours with opposite normals lie on a second sheet,
  /// offset along the normal (both sides of a thin plate, two walls closer than `r`); fitting
  /// one surface to both would merge them, so no estimate is given (use a smaller radius)
  TWO_SHEETS
};

/// \ingroup PkgPointSetCurvaturesRef
/// A short, stable, human readable name of a status (`"valid"`, `"too_few_neighbors"`, ...).
inline const char* to_string(Curvature_estimate_status s)
{
  switch(s)
  {
    case Curvature_estimate_status::VALID: return "valid";
    case Curvature_estimate_status::TOO_FEW_NEIGHBORS: return "too_few_neighbors";
    case Curvature_estimate_status::DEGENERATE_FIT: return "degenerate_fit";
    case Curvature_estimate_status::NON_FINITE_POINT: return "non_finite_point";
    case Curvature_estimate_status::INVALID_NORMAL: return "invalid_normal";
    case Curvature_estimate_status::NOT_COMPUTED: return "not_computed";
    case Curvature_estimate_status::TWO_SHEETS: return "two_sheets";
  }
  return "unknown";
}

inline std::ostream& operator<<(std::ostream& os, Curvature_estimate_status s) { return os << to_string(s); }

/// \ingroup PkgPointSetCurvaturesRef
///
/// Differential quantities estimated at one point of an oriented point cloud.
///
/// Units: curvatures are in inverse length units of the input coordinates
/// (`mean_curvature`, `min_curvature`, `max_curvature` in 1/length, `gaussian_curvature`
/// in 1/length²). Sign convention: curvature is positive where the surface bends away
/// from the normal; a sphere of radius `R` with outward normals has
/// `min_curvature == max_curvature == mean_curvature == 1/R`.
///
/// An estimate that is not valid holds NaN in every numeric field, so it can never be
/// mistaken for a zero curvature. An estimator that does not provide a quantity (for
/// instance APSS has no principal curvatures) leaves that field NaN in valid estimates too.
///
/// \tparam GeomTraits a model of `Kernel` whose `FT` is a floating-point type
/// (`Simple_cartesian<double>`, `Exact_predicates_inexact_constructions_kernel`).
template <class GeomTraits>
struct Curvature_estimate
{
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Vector_3 Vector_3;

  static_assert(std::numeric_limits<FT>::has_quiet_NaN,
                "Error: Curvature_estimate needs a kernel whose FT is a floating-point type "
                "(e.g. Exact_predicates_inexact_constructions_kernel or Simple_cartesian<double>).");

  /// unit corrected normal, oriented like the input normals
  Vector_3 normal = nan_vector();
  /// mean curvature `H = (min_curvature + max_curvature) / 2`
  FT mean_curvature = nan();
  /// Gaussian curvature `K = min_curvature * max_curvature`
  FT gaussian_curvature = nan();
  /// smaller principal curvature
  FT min_curvature = nan();
  /// larger principal curvature (`min_curvature <= max_curvature`)
  FT max_curvature = nan();
  /// unit tangent direction of `min_curvature` (its sign is arbitrary)
  Vector_3 min_direction = nan_vector();
  /// unit tangent direction of `max_curvature`, orthogonal to `min_direction`
  Vector_3 max_direction = nan_vector();
  /// how consistent the neighbours' normals are, a quality value in `[0, 1]`: the length of
  /// the kernel-weighted mean of their unit normals, as the fit oriented them
  /// (`estimate_aso_curvatures()` and `estimate_apss_curvatures()`; NaN for the other
  /// estimators). 1 on a plane, close to 1 on smooth surfaces (at least 0.996 on a sphere at
  /// `r k = 0.2` with the default ASO); it falls where the
  /// normals disagree: foliage, noisy normals, edges and corners within `r`. Measured on real
  /// airborne tiles with the tool's defaults (benchmark/README.md, "Scans without normals"):
  /// medians 0.996 to 1 on ground and roofs, 0.85 to 0.93 in the vegetation classes; about 0.6
  /// for normals pointing anywhere. Filter with a threshold such as 0.95 to keep surfaces.
  FT normal_coherence = nan();
  /// with the named parameter `Point_set_curvatures::parameters::automatic_scale()`: the
  /// standard error of the mean curvature of a quadric fitted to the neighbours' positions at
  /// the chosen scale, from the noise its residuals show (0 where they show none; where the
  /// smallest count is kept because a cubic fits its positions far better than the quadric, the
  /// cubic's residual variance is taken for the noise, an upper bound). It measures
  /// the noise's share of the error, not the bias (surface variation within the
  /// neighbourhood, biased normals), and the estimate itself, which also uses the normals, is
  /// often more accurate than it says (see benchmark/README.md, "Automatic scale"); NaN
  /// otherwise
  FT mean_curvature_error = nan();
  /// number of input points at distance `< r` from the query point, the query point included
  /// (with `automatic_scale()`: at the chosen scale)
  std::size_t neighbor_count = 0;
  /// why the estimate is (in)valid
  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;

  /// `true` if and only if `status == Curvature_estimate_status::VALID`
  bool is_valid() const { return status == Curvature_estimate_status::VALID; }

  static FT nan() { return std::numeric_limits<FT>::quiet_NaN(); }
  static Vector_3 nan_vector() { return Vector_3(nan(), nan(), nan()); }
};

}  // namespace CGAL

#endif  // CGAL_CURVATURE_ESTIMATE_H
