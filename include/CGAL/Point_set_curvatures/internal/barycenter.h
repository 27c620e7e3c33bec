// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Unsigned mean curvature from the distance to the barycenter of the neighbourhood: the
// estimator Lejemble et al. 2021 (Table 1) cite as Pottmann et al. 2007, Theorem 6.
//
// In the principal frame at a point p of a smooth surface, the surface is
// z = (k1 x² + k2 y²)/2 + O(ρ³). The barycenter of the patch cut by the ball of radius r,
// for a uniform sampling, is at height
//
//   (1/(π r²)) ∫_{disc r} (k1 x² + k2 y²)/2 dx dy + O(r³) = H r²/4 + O(r³)
//
// (∫ x² over the disc is π r⁴/4), and its tangential offset vanishes by symmetry. Hence
// |H| ≈ 4 |p - b| / r². The sign is lost (the direction from p to b is only known up to
// the normal's orientation), and so is any tangential drift of b, which non-uniform
// sampling adds to |p - b|: the estimator is coarse (see estimate_barycenter_curvatures.h).
// On a sphere with uniform area sampling it is exact: the centroid of a spherical cap of
// height r²/(2R) is at height r²/(4R).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_BARYCENTER_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_BARYCENTER_H

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Below three points the barycenter does not sample a surface patch.
constexpr std::size_t barycenter_min_neighbors = 3;

// |H| in `mean`, in 1/length; every other field NaN.
inline Local_estimate barycenter_mean_curvature(const Neighborhood& nb)
{
  if(nb.size < barycenter_min_neighbors)
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);
  double b[3] = {0, 0, 0}, spread = 0;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    b[0] += nb.qx[i];
    b[1] += nb.qy[i];
    b[2] += nb.qz[i];
    spread += nb.qx[i] * nb.qx[i] + nb.qy[i] * nb.qy[i] + nb.qz[i] * nb.qz[i];
  }
  // every neighbour on the query point: no patch (scaled frame, |q| < 1)
  if(!(spread > 1e-24))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  const double inv = 1.0 / double(nb.size);
  const double distance = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]) * inv;  // |p - b| / r
  Local_estimate e;
  e.mean = 4.0 * distance / nb.radius;  // |H| = 4 |p - b| / r² = 4 (|p - b| / r) / r
  if(!std::isfinite(e.mean))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
