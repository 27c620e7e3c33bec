// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ALGEBRAIC_SPHERE_FIT_H
#define CGAL_ALGEBRAIC_SPHERE_FIT_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere.h>
#include <CGAL/Point_set_curvatures/internal/local_frame.h>

#include <CGAL/property_map.h>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
///
/// The APSS algebraic sphere fit (Guennebaud and Gross 2007) at one evaluation point, from
/// neighbours that the caller provides, and its normal and mean curvature estimates
/// (Equations 7-8 of Lejemble et al. 2021). `estimate_apss_curvatures()` runs the same
/// computation at every point of a cloud.
///
/// Neighbours at distance `>= radius`, with a non-finite position or a zero normal are
/// ignored. Memory is constant; nothing is allocated.
///
/// \tparam GeomTraits a model of `Kernel` with a floating-point `FT`.
template <class GeomTraits>
class Algebraic_sphere_fit
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  /// Starts a fit at `evaluation_point` with the kernel `(1 - d²/radius²)²`.
  /// \throws std::invalid_argument if `radius` is not positive and finite or the
  /// evaluation point is not finite.
  Algebraic_sphere_fit(const Point_3& evaluation_point, FT radius)
      : m_frame(evaluation_point, CGAL::to_double(radius), "Algebraic_sphere_fit")
  {}

  /// Adds the oriented point `(p, n)`; returns `true` if it lies at distance `< radius`
  /// and was used. `n` need not be unit: it is normalised.
  bool add_neighbor(const Point_3& p, const Vector_3& n)
  {
    double q[3], nn[3];
    if(!m_frame.to_frame(p, n, q, nn))
      return false;
    m_sums.add(q[0], q[1], q[2], nn[0], nn[1], nn[2]);
    return true;
  }

  /// Adds every element of `range`, read through `point_map` and `normal_map`.
  template <class Range, class PointMap, class NormalMap>
  void add_neighbors(const Range& range, PointMap point_map, NormalMap normal_map)
  {
    for(const auto& item : range)
      add_neighbor(get(point_map, item), get(normal_map, item));
  }

  /// number of neighbours used so far
  std::size_t neighbor_count() const { return m_sums.count; }

  /// APSS normal and mean curvature; the principal fields are NaN. Invalid with
  /// `TOO_FEW_NEIGHBORS` below `min_neighbors` neighbours (by default
  /// `CGAL::Point_set_curvatures::default_min_neighbors::apss`, the measured minimum of
  /// `estimate_apss_curvatures()`; never below 3), or `DEGENERATE_FIT`.
  Curvature_estimate<GeomTraits>
  estimate(std::size_t min_neighbors = Point_set_curvatures::default_min_neighbors::apss) const
  {
    namespace I = Point_set_curvatures::internal;
    if(m_sums.count < min_neighbors)
      return I::to_curvature_estimate<GeomTraits>(
        I::Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS), m_sums.count);
    return I::to_curvature_estimate<GeomTraits>(I::algebraic_sphere_estimate(m_sums, m_frame.radius()), m_sums.count);
  }

private:
  Point_set_curvatures::internal::Local_frame<GeomTraits> m_frame;
  Point_set_curvatures::internal::Algebraic_sphere_sums<> m_sums;
};

}  // namespace CGAL

#endif
