// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ALGEBRAIC_SHAPE_OPERATOR_FIT_H
#define CGAL_ALGEBRAIC_SHAPE_OPERATOR_FIT_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_shape_operator.h>
#include <CGAL/Point_set_curvatures/internal/local_frame.h>

#include <CGAL/property_map.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The ASO's settings from the named parameters of estimate_aso_curvatures() and
// Algebraic_shape_operator_fit: the preset of aso_options, else of aso_variant (default
// `default_variant`), overridden by weight_kernel, robust_orientation and normal_field_blend;
// aso_projection and position_fit_blend. `area_weights`, if given, receives whether the
// sample weights are the tangent Voronoi areas (the preset, overridden by sample_weights).
// The constant kernel is refused (the ASO differentiates the weights).
template <class NamedParameters>
Aso_settings aso_settings_from(const NamedParameters& np, Aso_variant default_variant, const char* function_name,
                               bool* area_weights = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  const Aso_variant_options preset = choose_parameter(
    get_parameter(np, internal_np::aso_options),
    aso_variant_options(choose_parameter(get_parameter(np, internal_np::aso_variant), default_variant)));
  const Apss_weight_kernel kernel = is_default_parameter<NamedParameters, internal_np::weight_kernel_t>::value
                                      ? preset.weight_kernel
                                      : weight_kernel_parameter(np);
  if(kernel == Apss_weight_kernel::CONSTANT)
    throw std::invalid_argument(std::string(function_name) +
                                ": parameter 'weight_kernel': the ASO differentiates "
                                "the kernel, Apss_weight_kernel::CONSTANT is not supported");
  Aso_settings settings;
  settings.projection =
    choose_parameter(get_parameter(np, internal_np::aso_projection), Aso_projection::CORRECTED_NORMAL);
  settings.kernel_exponent = kernel_exponent(kernel);
  settings.orient_neighbors =
    choose_parameter(get_parameter(np, internal_np::robust_orientation), preset.robust_orientation);
  settings.normal_field_blend =
    choose_parameter(get_parameter(np, internal_np::normal_field_blend), preset.normal_field_blend);
  settings.position_fit_blend = choose_parameter(get_parameter(np, internal_np::position_fit_blend), 0.0);
  if(!(settings.position_fit_blend >= 0 && settings.position_fit_blend <= 1))
    throw std::invalid_argument(std::string(function_name) + ": parameter 'position_fit_blend' must lie in [0, 1]");
  if(area_weights)
    *area_weights = choose_parameter(get_parameter(np, internal_np::sample_weights), preset.sample_weights) ==
                    Sample_weights::TANGENT_VORONOI_AREA;
  return settings;
}

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// The Algebraic Shape Operator of Lejemble et al. (2021) at one evaluation point, from
/// neighbours that the caller provides: use it to evaluate at positions that are not
/// input points, or with your own neighbourhoods. `estimate_aso_curvatures()` runs the
/// same computation at every point of a cloud.
///
/// Neighbours are added one at a time; those at distance `>= radius` from the evaluation
/// point, or with a non-finite position or a zero normal, are ignored. Add the evaluation
/// point itself if it is a sample of the cloud. The fit keeps the accepted neighbours (48
/// bytes each, the ASO makes two passes over them); `reset()` starts a new fit reusing that
/// storage, so a loop over many evaluation points allocates only while neighbourhoods grow.
///
/// \tparam GeomTraits a model of `Kernel` with a floating-point `FT`.
template <class GeomTraits>
class Algebraic_shape_operator_fit
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  /// Starts a fit at `evaluation_point` with the kernel `(1 - d²/radius²)²`, projected on
  /// the tangent plane chosen by `projection` (see `CGAL::Aso_projection`): the paper's
  /// estimator, or with another `kernel` (`SMOOTH`, `SMOOTH_CUBIC` or `SMOOTH_QUARTIC`).
  /// \throws std::invalid_argument if `radius` is not positive and finite, the evaluation
  /// point is not finite, or `kernel` is `CONSTANT`.
  Algebraic_shape_operator_fit(const Point_3& evaluation_point, FT radius,
                               Aso_projection projection = Aso_projection::CORRECTED_NORMAL,
                               Apss_weight_kernel kernel = Apss_weight_kernel::SMOOTH)
      : Algebraic_shape_operator_fit(evaluation_point, radius,
                                     Point_set_curvatures::parameters::aso_projection(
                                       projection, Point_set_curvatures::parameters::weight_kernel(kernel)))
  {}

  /// Starts a fit at `evaluation_point` with the estimator that these named parameters of
  /// `estimate_aso_curvatures()` choose, with the same meanings: `aso_variant` (default
  /// `Aso_variant::PAPER`, as the constructor above; `Aso_variant::ROBUST` is the cloud
  /// function's default), `aso_options`, `weight_kernel`, `robust_orientation`,
  /// `normal_field_blend`, `aso_projection`, `position_fit_blend`. The sample weights are
  /// given per neighbour to `add_neighbor()`: `sample_weights` is not read.
  /// \throws std::invalid_argument as above, or if `position_fit_blend` is outside [0, 1].
  template <class NamedParameters>
  Algebraic_shape_operator_fit(const Point_3& evaluation_point, FT radius, const NamedParameters& np)
      : m_settings(
          Point_set_curvatures::internal::aso_settings_from(np, Aso_variant::PAPER, "Algebraic_shape_operator_fit")),
        m_frame(evaluation_point, CGAL::to_double(radius), "Algebraic_shape_operator_fit",
                m_settings.projection == Aso_projection::CORRECTED_NORMAL)
  {}

  /// Adds the oriented point `(p, n)` with the quadrature weight `sample_weight` (positive:
  /// the area it stands for; 1 for the paper's equal weights); returns `true` if it lies at
  /// distance `< radius` and was used. `n` need not be unit: it is normalised (except with
  /// `Aso_projection::AUTHORS_IMPLEMENTATION`, which uses it as given).
  bool add_neighbor(const Point_3& p, const Vector_3& n, double sample_weight = 1.0)
  {
    double q[3], nn[3];
    if(!m_frame.to_frame(p, n, q, nn))
      return false;
    for(int i = 0; i < 3; ++i)
    {
      m_columns[i].push_back(q[i]);
      m_columns[3 + i].push_back(nn[i]);
    }
    m_weights.push_back(sample_weight);
    m_weighted = m_weighted || sample_weight != 1.0;
    return true;
  }

  /// Starts a new fit at `evaluation_point` with `radius`, keeping the projection and the
  /// storage. \throws std::invalid_argument as the constructor.
  void reset(const Point_3& evaluation_point, FT radius)
  {
    m_frame = Frame(evaluation_point, CGAL::to_double(radius), "Algebraic_shape_operator_fit",
                    m_settings.projection == Aso_projection::CORRECTED_NORMAL);
    for(auto& c : m_columns)
      c.clear();
    m_weights.clear();
    m_weighted = false;
  }

  /// Adds every element of `range`, read through `point_map` and `normal_map`.
  template <class Range, class PointMap, class NormalMap>
  void add_neighbors(const Range& range, PointMap point_map, NormalMap normal_map)
  {
    for(const auto& item : range)
      add_neighbor(get(point_map, item), get(normal_map, item));
  }

  /// number of neighbours used so far
  std::size_t neighbor_count() const { return m_columns[0].size(); }

  /// Normal, principal curvatures and directions, mean and Gaussian curvature of the
  /// neighbours added so far. Invalid with `TOO_FEW_NEIGHBORS` below `min_neighbors`
  /// neighbours (by default `CGAL::Point_set_curvatures::default_min_neighbors::aso`, the
  /// measured minimum of `estimate_aso_curvatures()`; never below 3), or `DEGENERATE_FIT`.
  Curvature_estimate<GeomTraits>
  estimate(std::size_t min_neighbors = Point_set_curvatures::default_min_neighbors::aso) const
  {
    if(neighbor_count() < min_neighbors)
      return Point_set_curvatures::internal::to_curvature_estimate<GeomTraits>(
        Point_set_curvatures::internal::Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS),
        neighbor_count());
    Point_set_curvatures::internal::Neighborhood nb;
    nb.size = neighbor_count();
    nb.qx = m_columns[0].data();
    nb.qy = m_columns[1].data();
    nb.qz = m_columns[2].data();
    nb.nx = m_columns[3].data();
    nb.ny = m_columns[4].data();
    nb.nz = m_columns[5].data();
    nb.radius = m_frame.radius();
    nb.sample_weight = m_weighted ? m_weights.data() : nullptr;
    return Point_set_curvatures::internal::to_curvature_estimate<GeomTraits>(
      Point_set_curvatures::internal::algebraic_shape_operator(nb, m_settings), nb.size);
  }

private:
  typedef Point_set_curvatures::internal::Local_frame<GeomTraits> Frame;
  Point_set_curvatures::internal::Aso_settings m_settings;  // (before m_frame, which reads it)
  Frame m_frame;
  std::vector<double> m_columns[6];  // q (scaled centred frame) and n of the neighbours
  std::vector<double> m_weights;     // their sample weights
  bool m_weighted = false;           // some sample weight differs from 1
};

}  // namespace CGAL

#endif
