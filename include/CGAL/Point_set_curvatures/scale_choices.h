// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic scale's choices for the curvatures, made during the normals' passes.

#ifndef CGAL_POINT_SET_CURVATURES_SCALE_CHOICES_H
#define CGAL_POINT_SET_CURVATURES_SCALE_CHOICES_H

#include <CGAL/Point_set_curvatures/internal/automatic_scale_estimation.h>

#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {

/// \ingroup PkgPointSetCurvaturesRef
/// The automatic scale's choice of a neighbour count for the curvatures of each point, made by
/// `estimate_oriented_normals()` while it chooses the normals' count over the same
/// neighbourhoods, and read by `estimate_aso_curvatures()`, which then estimates those points
/// from the neighbourhood of their count instead of climbing the ladder's counts again: the
/// same estimates, bit for bit, in less time. Pass the same object to both with
/// `parameters::scale_choices(choices)`, the same points in the same order, and the same
/// ladder (`neighbor_count` and `automatic_scale`); a choice that does not fit the
/// curvatures' call (another ladder, another range, a point whose neighbourhood differs: a
/// neighbour without a usable normal) is not used, and the ladder decides there as without it.
class Scale_choices
{
public:
  /// The number of points it was made for (0 until `estimate_oriented_normals()` fills it, and
  /// where no point climbed past the smallest count).
  std::size_t size() const { return m_records.slot.size(); }
  /// Forgets the choices.
  void clear() { m_records = internal::Curvature_scale_records(); }

  /// \cond SKIP_IN_MANUAL
  internal::Curvature_scale_records& records() { return m_records; }
  const internal::Curvature_scale_records& records() const { return m_records; }
  /// \endcond

private:
  internal::Curvature_scale_records m_records;
};

}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
