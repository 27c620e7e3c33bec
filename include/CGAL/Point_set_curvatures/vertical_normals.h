// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Which normals are near-vertical and which clouds look 2.5-D: the tests of the default
// orientation (CGAL/estimate_oriented_normals.h), in a header of their own so that code that
// only counts normals (the tool's summary) does not need the estimation.

#ifndef CGAL_POINT_SET_CURVATURES_VERTICAL_NORMALS_H
#define CGAL_POINT_SET_CURVATURES_VERTICAL_NORMALS_H

#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {

/// \ingroup PkgPointSetCurvaturesRef
/// The least share of near-vertical normals of a 2.5-D cloud (see `is_two_and_a_half_d()`).
constexpr double two_and_a_half_d_min_share = 0.6;

/// \ingroup PkgPointSetCurvaturesRef
/// True if a cloud whose normals (orientation and length ignored) are `vertical` near-vertical
/// ones (within 60 degrees of the z axis, `|n_z| >= 0.5 |n|`) out of `count` non-zero ones
/// looks 2.5-D, as airborne and mobile scans seen from above do: at least 60% of them (the
/// shares measured on real and simulated clouds: benchmark/README.md, section 10). Closed
/// shapes can pass the test (a torus lying flat), which is why
/// `Normal_orientation::automatic()` keeps a closed part outward when it is seen from all
/// sides (a bottom under its top), whatever this says.
inline bool is_two_and_a_half_d(std::size_t vertical, std::size_t count)
{
  return count > 0 && double(vertical) >= two_and_a_half_d_min_share * double(count);
}

/// \ingroup PkgPointSetCurvaturesRef
/// True if `n` lies within 60 degrees of the z axis, either way (`|n_z| >= 0.5 |n|`), for
/// `is_two_and_a_half_d()`; false for a zero vector.
inline bool is_near_vertical(double nx, double ny, double nz)
{
  const double l2 = nx * nx + ny * ny + nz * nz;
  return l2 > 0 && nz * nz >= 0.25 * l2;
}

}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
