// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The part of the public per-query fit classes that does not depend on the fit: the
// evaluation point, the radius, and the move of a neighbour into the scaled centred frame.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_LOCAL_FRAME_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_LOCAL_FRAME_H

#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

template <class GeomTraits>
class Local_frame
{
public:
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  Local_frame(const Point_3& evaluation_point, double radius, const char* class_name, bool normalize_normals = true)
      : m_radius(radius), m_normalize_normals(normalize_normals)
  {
    check_radius(radius, class_name);
    m_center[0] = CGAL::to_double(evaluation_point.x());
    m_center[1] = CGAL::to_double(evaluation_point.y());
    m_center[2] = CGAL::to_double(evaluation_point.z());
    if(!std::isfinite(m_center[0]) || !std::isfinite(m_center[1]) || !std::isfinite(m_center[2]))
    {
      std::ostringstream msg;
      msg << class_name << ": the evaluation point must have finite coordinates";
      throw std::invalid_argument(msg.str());
    }
  }

  double radius() const { return m_radius; }

  // Scaled centred coordinates q and (unit, if asked) normal n of a neighbour; false when the
  // neighbour is unusable (non-finite, zero normal) or not at distance < r.
  bool to_frame(const Point_3& p, const Vector_3& normal, double q[3], double n[3]) const
  {
    const double d[3] = {CGAL::to_double(p.x()) - m_center[0], CGAL::to_double(p.y()) - m_center[1],
                         CGAL::to_double(p.z()) - m_center[2]};
    const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if(!(d2 < m_radius * m_radius))  // also rejects NaN
      return false;
    n[0] = CGAL::to_double(normal.x());
    n[1] = CGAL::to_double(normal.y());
    n[2] = CGAL::to_double(normal.z());
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if(!(nn > 0) || !std::isfinite(nn))
      return false;
    const double inv_n = m_normalize_normals ? 1.0 / std::sqrt(nn) : 1.0;
    const double inv_r = 1.0 / m_radius;
    for(int i = 0; i < 3; ++i)
    {
      q[i] = d[i] * inv_r;
      n[i] *= inv_n;
    }
    return true;
  }

private:
  double m_center[3];
  double m_radius;
  bool m_normalize_normals;
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
