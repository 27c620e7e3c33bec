// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ESTIMATE_ALGEBRAIC_SPHERE_FEATURES_H
#define CGAL_ESTIMATE_ALGEBRAIC_SPHERE_FEATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere_features.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
///
/// What the algebraic sphere fitted by APSS around one evaluation point `x` measures
/// (Lejemble et al. 2021, Sections 3 and 4): its Pratt-normalised coefficients, the
/// anisotropy, the algebraic distance, the GLS geometric variation and its scale derivatives,
/// and the sphere itself.
///
/// The fitted field is written in coordinates centred at the evaluation point, in the unit
/// of the input coordinates (`L`): for a position `y`,
/// `f(y) = u_c + u_l · (y - x) + u_q |y - x|²`, normalised so that its Pratt norm is 1
/// (`|∇f| = 1` on the sphere `f = 0`). Sign convention of the package: the field grows
/// along the input normals, and curvature is positive where the surface bends away from the
/// normal; a sphere of radius `R` with outward normals gives `u_q = 1/(2R)`,
/// `mean_curvature = 1/R`, `u_c = 0`, `anisotropy = 0`.
///
/// Asymptotic meaning, for a surface of principal curvatures `k1, k2`, mean curvature `H`,
/// Gaussian curvature `K`, sampled with a uniform density and a kernel radius `r` (derived in
/// `internal/algebraic_sphere_features.h`; "paper" is the constant kernel of Section 4.1,
/// "smooth" the default kernel `(1 - d²/r²)²`):
/// | field | constant kernel | smooth kernel |
/// |---|---|---|
/// | `anisotropy` = `1 - p` (Prop. 1) | `(k1 - k2)² r² / 16` | `(k1 - k2)² r² / 32` |
/// | `u_c` (Th. 1) | `(9H³ - 5KH - ΔH) r⁴ / 96` | `(19H³ - 11KH - 2ΔH) r⁴ / 640` |
/// | `geometric_variation` (Prop. 2) | `|∇H|² r⁴ / 4` | `|∇H|² r⁴ / 16` |
/// | `mean_curvature` = `2 u_q` (Eq. 7) | `H + O(r²)` | `H + O(r²)` |
/// where `ΔH` is half the bilaplacian of the height function over the tangent plane, with the
/// package's sign (it is `4H³` on a sphere, where both `u_c` laws vanish), and `∇H` the
/// gradient of `H` along the surface.
///
/// Invalid results (see `status`) hold NaN in every numeric field.
///
/// \tparam GeomTraits a model of `Kernel` with a floating-point `FT`.
template <class GeomTraits>
struct Algebraic_sphere_features
{
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  static_assert(std::numeric_limits<FT>::has_quiet_NaN,
                "Error: Algebraic_sphere_features needs a kernel whose FT is a floating-point type.");

  /// Pratt-normalised constant coefficient, in `L`: the algebraic distance from the
  /// evaluation point to the fitted sphere (Theorem 1; first-order signed distance,
  /// positive on the side the normals point to). Fine 4th-order detail.
  FT u_c = nan();
  /// Pratt-normalised linear coefficient (dimensionless): the field's gradient at the
  /// evaluation point; `|u_l|² = 1 + 4 u_c u_q`, 1 when the point is on the sphere.
  Vector_3 u_l = nan_vector();
  /// Pratt-normalised quadratic coefficient, in `1/L`: half the sphere's signed curvature.
  FT u_q = nan();
  /// Pratt norm `p = sqrt(|u_l|² - 4 u_c u_q)` of the coefficients of Equations 2-4 before
  /// normalisation (dimensionless, independent of the unit and of `r`); 1 on a sphere.
  FT pratt_norm = nan();
  /// `1 - pratt_norm`: the anisotropy measure of Proposition 1 (dimensionless), 0 on spheres
  /// and planes, large on elongated features. May be slightly negative with noisy normals.
  FT anisotropy = nan();
  /// APSS normal `u_l / |u_l|` (Equation 8), unit, oriented like the input normals.
  Vector_3 normal = nan_vector();
  /// APSS mean curvature `2 u_q` (Equation 7), in `1/L`; equal to the one of
  /// `estimate_apss_curvatures()` with the same kernel and radius.
  FT mean_curvature = nan();
  /// GLS geometric variation `v = (∂u_c/∂r)² + (r ∂n/∂r)² + (r² ∂H/∂r)²` (Equation 18,
  /// Mellado et al. 2012), dimensionless. The derivatives with respect to the kernel radius
  /// `r` (evaluation point fixed) are taken analytically through the kernel, in the same
  /// pass as the fit, never by finite differences:
  /// - smooth kernels (`SMOOTH`, `SMOOTH_CUBIC`, `SMOOTH_QUARTIC`): the exact derivative of
  ///   the fit to the given samples (`r ∂w/∂r` replaces `w` in the sums);
  /// - constant kernel: the sums only change when a neighbour enters the ball, so their
  ///   derivative is the boundary term of the continuum sums (a Dirac on the sphere of
  ///   radius `r`). It is estimated from the neighbours inside with the polynomial weight
  ///   `2 (1 - s)(12 - 120 s + 180 s²)`, `s = d²/r²`, which gives the boundary value of any
  ///   integrand whose density in `s` is a polynomial of degree 2 or less (the leading order
  ///   of all three terms, in the continuum limit of a locally uniform or smoothly varying
  ///   density) and, like the smooth kernel, gives no weight to the points at `d = r`.
  ///   On samples it is noisier than the smooth kernel's derivative (it estimates a density
  ///   at the boundary from the inside), and biased near a border of the cloud or a density
  ///   jump inside the ball; see the user manual for measurements.
  FT geometric_variation = nan();
  /// `∂u_c/∂r` (dimensionless).
  FT d_u_c_dr = nan();
  /// `∂normal/∂r`, in `1/L`, orthogonal to `normal`.
  Vector_3 d_normal_dr = nan_vector();
  /// `∂mean_curvature/∂r`, in `1/L²`.
  FT d_mean_curvature_dr = nan();
  /// `true` if the fitted sphere is a plane, numerically: `|u_q| r <= 1e-12` (sphere radius
  /// above `5e11 r`). The plane is the one through `projection` orthogonal to `normal`.
  bool is_plane = false;
  /// centre of the fitted sphere, in input coordinates; NaN for a plane
  Point_3 center = nan_point();
  /// radius of the fitted sphere `1 / (2 |u_q|)`, in `L`; infinity for a plane
  FT sphere_radius = nan();
  /// the point of the fitted sphere (or plane) closest to the evaluation point (Equation 20),
  /// in input coordinates: where one step of the bilaplacian flow moves it (Proposition 3)
  Point_3 projection = nan_point();
  /// kernel radius `r` of this result, in `L` (per point with neighbourhoods by count)
  FT kernel_radius = nan();
  /// number of input points at distance `< r` from the evaluation point, itself included
  std::size_t neighbor_count = 0;
  /// why the result is (in)valid: `VALID`, `TOO_FEW_NEIGHBORS` (fewer than `min_neighbors`, 12 by default), `DEGENERATE_FIT`,
  /// `NON_FINITE_POINT`, `INVALID_NORMAL`, `NOT_COMPUTED` (cancelled), as for curvatures
  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;

  /// `true` if and only if `status == Curvature_estimate_status::VALID`
  bool is_valid() const { return status == Curvature_estimate_status::VALID; }

  static FT nan() { return std::numeric_limits<FT>::quiet_NaN(); }
  static Vector_3 nan_vector() { return Vector_3(nan(), nan(), nan()); }
  static Point_3 nan_point() { return Point_3(nan(), nan(), nan()); }
};

namespace Point_set_curvatures {
namespace internal {

// Converts the scaled-frame features of the evaluation point `x` to input units.
template <class GeomTraits>
Algebraic_sphere_features<GeomTraits> to_sphere_features(const Local_sphere_features& f, const double x[3])
{
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  Algebraic_sphere_features<GeomTraits> out;
  out.neighbor_count = f.neighbor_count;
  out.status = f.status;
  if(!f.is_valid())
    return out;
  const Algebraic_sphere& s = f.sphere;
  const double r = f.radius, p = s.pratt_norm;
  out.kernel_radius = FT(r);
  out.pratt_norm = FT(p);
  out.anisotropy = FT(1.0 - p);
  out.u_c = FT(r * s.u_c / p);
  out.u_l = Vector_3(FT(s.u_l[0] / p), FT(s.u_l[1] / p), FT(s.u_l[2] / p));
  out.u_q = FT(s.u_q / (p * r));
  const double l = std::sqrt(s.u_l[0] * s.u_l[0] + s.u_l[1] * s.u_l[1] + s.u_l[2] * s.u_l[2]);
  out.normal = Vector_3(FT(s.u_l[0] / l), FT(s.u_l[1] / l), FT(s.u_l[2] / l));
  out.mean_curvature = FT(2.0 * s.u_q / (p * r));
  if(std::isfinite(f.geometric_variation))  // otherwise a numerical failure: NaN, not garbage
  {
    out.geometric_variation = FT(f.geometric_variation);
    out.d_u_c_dr = FT(f.d_u_c);
    out.d_normal_dr = Vector_3(FT(f.d_normal[0] / r), FT(f.d_normal[1] / r), FT(f.d_normal[2] / r));
    out.d_mean_curvature_dr = FT(f.d_mean / (r * r));
  }
  // u_q / p is the scaled-frame curvature / 2: r / (2 |u_q/p|) is the sphere radius
  out.is_plane = !(std::abs(s.u_q) > 1e-12 * p);
  if(out.is_plane)
    out.sphere_radius = FT(std::numeric_limits<double>::infinity());
  else
  {
    const double k = -0.5 / s.u_q;  // centre = x + r * (-u_l / (2 u_q))
    out.center = Point_3(FT(x[0] + r * k * s.u_l[0]), FT(x[1] + r * k * s.u_l[1]), FT(x[2] + r * k * s.u_l[2]));
    out.sphere_radius = FT(r * p / (2.0 * std::abs(s.u_q)));
  }
  const double origin[3] = {0, 0, 0};
  double projected[3], n[3];
  if(project_on_sphere(s, origin, projected, n))
    out.projection = Point_3(FT(x[0] + r * projected[0]), FT(x[1] + r * projected[1]), FT(x[2] + r * projected[2]));
  return out;
}

// The evaluation of sphere_features_at_every_point() at one point (a named type: see
// Store_results).
template <class GeomTraits>
struct Sphere_features_at_point
{
  Apss_weight_kernel kernel;
  std::size_t min_count;
  Algebraic_sphere_features<GeomTraits> operator()(const Neighborhood& nb) const
  {
    Local_sphere_features f =
      with_weight_kernel(kernel, [&](auto k) { return sphere_features<decltype(k)>(nb, min_count); });
    if(f.is_valid() && neighborhood_below_precision(nb))
    {
      // (points that coincide up to rounding: no sphere)
      const auto count = f.neighbor_count;
      f = Local_sphere_features();
      f.neighbor_count = count;
      f.radius = nb.radius;
      f.status = Curvature_estimate_status::DEGENERATE_FIT;
    }
    return to_sphere_features<GeomTraits>(f, nb.center);
  }
};

// The common body of the single-scale feature functions (with a radius or by count).
template <class ConcurrencyTag, class PointRange, class NamedParameters>
std::vector<
  Algebraic_sphere_features<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
sphere_features_at_every_point(const PointRange& points, bool radius_given, double radius, const NamedParameters& np,
                               const char* function_name)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  const Apss_weight_kernel kernel = weight_kernel_parameter(np);
  const std::size_t min_count = min_neighbors_parameter(np, default_min_neighbors::sphere_features);
  Neighborhood_options options = neighborhood_options(np, function_name, true);
  // Sample weights (the quadrature argument of the ASO holds for the sums of the sphere): the
  // areas of the tangent Voronoi cells, computed first; they are taken as constant in the
  // scale r for the scale derivatives (exact where no cell reaches its bound, r/4).
  // Weights given with sample_weight_map replace them.
  std::vector<double> areas = given_sample_weights(points, np, function_name);
  if(has_sample_weight_map<NamedParameters>())
    options.point_weights = &areas;
  else if(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::sample_weights),
                                             Sample_weights::UNIFORM) == Sample_weights::TANGENT_VORONOI_AREA)
  {
    const std::size_t k = checked_scale<PointRange>(radius, radius_given, np, function_name);
    if(options.has_tile)
      throw std::invalid_argument(std::string(function_name) +
                                  ": parameter 'tile' is not supported with sample weights");
    Neighborhood_options o = options;
    o.callback = {};
    areas =
      tangent_voronoi_areas<ConcurrencyTag>(points, radius_given, radius, k, NP_helper::get_const_point_map(points, np),
                                            NP_helper::get_normal_map(points, np), o);
    options.point_weights = &areas;
  }
  return evaluate_at_every_point<Algebraic_sphere_features<Geom_traits>, ConcurrencyTag>(
    points, radius_given, radius, np, options, Sphere_features_at_point<Geom_traits>{kernel, min_count});
}

// The visitor of the multi-scale function: one Multiscale_sphere_features (scratch buckets)
// per copy, i.e. per thread with Parallel_tag.
template <class GeomTraits>
struct Multiscale_visitor
{
  std::vector<std::vector<Algebraic_sphere_features<GeomTraits> > >* results;
  const std::vector<double>* radii;
  Apss_weight_kernel kernel;
  std::size_t min_count;
  Multiscale_sphere_features scales;
  std::vector<Local_sphere_features> local;

  Multiscale_visitor(std::vector<std::vector<Algebraic_sphere_features<GeomTraits> > >* results,
                     const std::vector<double>* radii, Apss_weight_kernel kernel, std::size_t min_count)
      : results(results), radii(radii), kernel(kernel), min_count(min_count)
  {
    scales.set_radii(*radii);
    local.resize(radii->size());
  }

  void operator()(std::size_t i, const Neighborhood& nb)
  {
    with_weight_kernel(kernel, [&](auto k) { scales.compute<decltype(k)>(nb, local.data(), min_count); });
    for(std::size_t k = 0; k < local.size(); ++k)
      (*results)[k][i] = to_sphere_features<GeomTraits>(local[k], nb.center);
  }
};

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Computes, at every point of an oriented point cloud, the features of the APSS algebraic
/// sphere fitted to its neighbours (Lejemble et al. 2021, Sections 3-4): Pratt-normalised
/// coefficients `u_c, u_l, u_q` and Pratt norm (Equation 6), anisotropy `1 - p`
/// (Proposition 1), algebraic distance `u_c` (Theorem 1), GLS geometric variation `v` with
/// its analytic scale derivatives (Equation 18, Proposition 2), the sphere's centre and
/// radius (or plane), and the projection of the point onto it (Equation 20). See
/// `CGAL::Algebraic_sphere_features` for the meaning, units and asymptotic laws of each field.
///
/// Same neighbourhoods (points at distance `< radius`, the point itself included), named
/// parameters, statuses, sign convention and determinism as `CGAL::estimate_apss_curvatures()`,
/// whose normal and mean curvature it reproduces.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB).
/// \tparam PointRange a model of `ConstRange`; its iterator value type is the key type of
///         the point and normal maps (`std::vector` of pairs or tuples, `CGAL::Point_set_3`).
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
///     \cgalParamDescription{the weight kernel of the fit: `SMOOTH` `(1 - d²/r²)²`,
///       `CONSTANT` (the paper's asymptotic analysis; see `geometric_variation` for how
///       its scale derivatives are obtained), `SMOOTH_CUBIC` `(1 - d²/r²)³` or `SMOOTH_QUARTIC`
///       `(1 - d²/r²)⁴` (exact scale derivatives; the asymptotic constants documented in
///       `CGAL::Algebraic_sphere_features` are those of the first two)}
///     \cgalParamType{`CGAL::Apss_weight_kernel`}
///     \cgalParamDefault{`CGAL::Apss_weight_kernel::SMOOTH`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::sample_weights}
///     \cgalParamDescription{the quadrature weights of the samples, as for
///       `estimate_aso_curvatures()`; the areas are taken as constant in the scale for the scale
///       derivatives. Not supported by the multi-scale function nor with `tile`
///       (`std::invalid_argument`)}
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
///   \cgalParamNBegin{Point_set_curvatures::parameters::min_neighbors}
///     \cgalParamDescription{the least number of neighbours (query included) of a valid
///       estimate; below it the status is `TOO_FEW_NEIGHBORS`. Values below what the fit
///       needs (3) are raised to it}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`CGAL::Point_set_curvatures::default_min_neighbors::sphere_features`, the measured minimum
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
/// \returns one `CGAL::Algebraic_sphere_features` per element of `points`, in order.
/// \throws std::invalid_argument if `radius` is not positive and finite.
///
/// \sa `estimate_multiscale_algebraic_sphere_features()` for several radii in one pass;
/// `CGAL::Algebraic_point_set_surface` for the features at arbitrary positions.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<
  Algebraic_sphere_features<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> >
estimate_algebraic_sphere_features(const PointRange& points, double radius,
                                   const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::sphere_features_at_every_point<ConcurrencyTag>(
    points, true, radius, np, "estimate_algebraic_sphere_features");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with neighbourhoods by count: `np` must contain
/// `CGAL::Point_set_curvatures::parameters::neighbor_count(k)`; each point's radius is the
/// distance to its `k`-th nearest neighbour (itself counted), enlarged by a factor
/// `1 + 2^-20` so that the `k` nearest are inside (see `neighbor_count`); reported in
/// `kernel_radius`.
/// \throws std::invalid_argument if `neighbor_count` is missing or 0.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
typename Point_set_curvatures::internal::Results_without_radius<Algebraic_sphere_features, PointRange,
                                                                NamedParameters>::type
estimate_algebraic_sphere_features(const PointRange& points, const NamedParameters& np)
{
  return Point_set_curvatures::internal::sphere_features_at_every_point<ConcurrencyTag>(
    points, false, 0.0, np, "estimate_algebraic_sphere_features");
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the point and normal maps given explicitly.
template <typename ConcurrencyTag, typename PointRange, typename PointMap, typename NormalMap>
std::vector<
  Algebraic_sphere_features<typename Kernel_traits<typename boost::property_traits<PointMap>::value_type>::Kernel> >
estimate_algebraic_sphere_features(const PointRange& points, PointMap point_map, NormalMap normal_map, double radius)
{
  return estimate_algebraic_sphere_features<ConcurrencyTag>(points, radius,
                                                            parameters::point_map(point_map).normal_map(normal_map));
}

/// \ingroup PkgPointSetCurvaturesRef
///
/// Multi-scale form of `estimate_algebraic_sphere_features()`: the same features at every
/// point for each radius of `radii`, in one pass over the neighbourhood of the largest radius
/// (the neighbours are bucketed once by distance between consecutive radii, and the sums of
/// every radius follow from moments accumulated in that pass, as in GLS, Mellado et al.
/// 2012). Same named parameters (but `neighbor_count`). The results equal those of the
/// single-scale function at each radius up to rounding (the sums are accumulated in another
/// order), a neighbour at distance exactly a radius aside. Cost: one neighbourhood search at
/// the largest radius and a few operations per radius (measured: benchmark/README.md,
/// section 10).
///
/// \param points input oriented point cloud
/// \param radii the kernel radii, in the unit of the coordinates: positive, finite, in any
///        order (duplicates allowed)
/// \param np an optional sequence of named parameters (see
///        `estimate_algebraic_sphere_features()`)
///
/// \returns `result[k][i]`: the features of the `i`-th element of `points` at `radii[k]`.
/// \throws std::invalid_argument if `radii` is empty or holds a radius that is not positive
///         and finite, or if `neighbor_count` is given.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<std::vector<
  Algebraic_sphere_features<typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits> > >
estimate_multiscale_algebraic_sphere_features(const PointRange& points, const std::vector<double>& radii,
                                              const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace PSC = Point_set_curvatures;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  static_assert(NP_helper::has_normal_map(),
                "Error: no normal map. Pass CGAL::parameters::normal_map(...): the algebraic "
                "sphere fit needs oriented normals.");
  const char* name = "estimate_multiscale_algebraic_sphere_features";
  if(radii.empty())
    throw std::invalid_argument(std::string(name) + ": parameter 'radii' is empty");
  for(std::size_t k = 0; k < radii.size(); ++k)
    if(!(radii[k] > 0) || !std::isfinite(radii[k]))
    {
      std::ostringstream msg;
      msg << name << ": parameter 'radii' must hold positive finite radii, radii[" << k << "] = " << radii[k];
      throw std::invalid_argument(msg.str());
    }
  const std::size_t k = choose_parameter(get_parameter(np, PSC::internal_np::neighbor_count), std::size_t(0));
  if(k != 0)
    throw std::invalid_argument(std::string(name) + ": neighbor_count is not supported, give radii");

  const PSC::internal::Neighborhood_options options = PSC::internal::neighborhood_options(np, name, true);
  if(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, PSC::internal_np::sample_weights),
                                        Sample_weights::UNIFORM) != Sample_weights::UNIFORM)
    throw std::invalid_argument(std::string(name) +
                                ": parameter 'sample_weights' is not supported by the "
                                "multi-scale features (the areas depend on the scale); use the single-scale function");
  if(PSC::internal::has_sample_weight_map<NamedParameters>())
    throw std::invalid_argument(std::string(name) + ": parameter 'sample_weight_map' is not supported by the "
                                                    "multi-scale features; use the single-scale function");
  const Apss_weight_kernel kernel = PSC::internal::weight_kernel_parameter(np);

  const std::size_t n = static_cast<std::size_t>(std::distance(points.begin(), points.end()));
  std::vector<std::vector<Algebraic_sphere_features<Geom_traits> > > results(
    radii.size(), std::vector<Algebraic_sphere_features<Geom_traits> >(n));
  PSC::internal::Multiscale_visitor<Geom_traits> visit(
    &results, &radii, kernel,
    PSC::internal::min_neighbors_parameter(np, PSC::internal::default_min_neighbors::sphere_features));
  const double max_radius = *std::max_element(radii.begin(), radii.end());
  const std::vector<Curvature_estimate_status> status = PSC::internal::for_each_neighborhood<ConcurrencyTag>(
    points, NP_helper::get_const_point_map(points, np), NP_helper::get_normal_map(points, np), max_radius, options,
    visit);
  for(std::size_t i = 0; i < n; ++i)
    if(status[i] != Curvature_estimate_status::VALID)
      for(auto& scale : results)
        scale[i].status = status[i];
  return results;
}

}  // namespace CGAL

#endif
