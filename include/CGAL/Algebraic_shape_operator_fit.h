// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ALGEBRAIC_SHAPE_OPERATOR_FIT_H
#define CGAL_ALGEBRAIC_SHAPE_OPERATOR_FIT_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_shape_operator.h>
#include <CGAL/Point_set_curvatures/internal/local_frame.h>

#include <CGAL/property_map.h>

#include <vector>

namespace CGAL {

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
    : Algebraic_shape_operator_fit(evaluation_point, radius, projection,
                                   Point_set_curvatures::Aso_variant_options{kernel, Sample_weights::UNIFORM, false, false})
  {}

  /// Starts a fit at `evaluation_point` with the options of a variant of
  /// `estimate_aso_curvatures()`, for example
  /// `CGAL::Point_set_curvatures::aso_variant_options(CGAL::Aso_variant::ROBUST)`: its
  /// `weight_kernel`, its `robust_orientation` (neighbours' normals flipped against their
  /// weighted majority, `TWO_SHEETS` when they form a second sheet) and its
  /// `normal_field_blend` (a least-squares fit of the normal field blended in where the
  /// neighbourhood is one-sided, see
  /// `CGAL::Point_set_curvatures::parameters::normal_field_blend()`); its `sample_weights` is
  /// not read (sample weights are given per neighbour to `add_neighbor()`).
  /// \throws std::invalid_argument as above.
  Algebraic_shape_operator_fit(const Point_3& evaluation_point, FT radius, Aso_projection projection,
                               const Point_set_curvatures::Aso_variant_options& options)
    : m_frame(evaluation_point, CGAL::to_double(radius), "Algebraic_shape_operator_fit",
              projection == Aso_projection::CORRECTED_NORMAL)
  {
    if(options.weight_kernel == Apss_weight_kernel::CONSTANT)
      throw std::invalid_argument("Algebraic_shape_operator_fit: the constant kernel has no derivative");
    m_settings.projection = projection;
    m_settings.kernel_exponent = Point_set_curvatures::internal::kernel_exponent(options.weight_kernel);
    m_settings.orient_neighbors = options.robust_orientation;
    m_settings.normal_field_blend = options.normal_field_blend;
  }

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
  Curvature_estimate<GeomTraits> estimate(
    std::size_t min_neighbors = Point_set_curvatures::default_min_neighbors::aso) const
  {
    if(neighbor_count() < min_neighbors)
      return Point_set_curvatures::internal::to_curvature_estimate<GeomTraits>(
        Point_set_curvatures::internal::Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS),
        neighbor_count());
    Point_set_curvatures::internal::Neighborhood nb;
    nb.size = neighbor_count();
    nb.qx = m_columns[0].data(); nb.qy = m_columns[1].data(); nb.qz = m_columns[2].data();
    nb.nx = m_columns[3].data(); nb.ny = m_columns[4].data(); nb.nz = m_columns[5].data();
    nb.radius = m_frame.radius();
    nb.sample_weight = m_weighted ? m_weights.data() : nullptr;
    return Point_set_curvatures::internal::to_curvature_estimate<GeomTraits>(
      Point_set_curvatures::internal::algebraic_shape_operator(nb, m_settings), nb.size);
  }

private:
  typedef Point_set_curvatures::internal::Local_frame<GeomTraits> Frame;
  Frame m_frame;
  Point_set_curvatures::internal::Aso_settings m_settings;
  std::vector<double> m_columns[6];  // q (scaled centred frame) and n of the neighbours
  std::vector<double> m_weights;     // their sample weights
  bool m_weighted = false;           // some sample weight differs from 1
};

} // namespace CGAL

#endif
