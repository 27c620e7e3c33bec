// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Unsigned mean curvature from the distance to the PCA plane of the neighbourhood,
// Digne, Morel, Souzani, Lartigue, "Scale space meshing of raw data point sets", CGF 2011,
// Theorem 2 (cited in Table 1 of Lejemble et al. 2021).
//
// The regression plane of the points in the ball of radius r around p passes through
// their barycenter b, whose height above the tangent plane is H r²/4 + O(r³)
// (barycenter.h), and its normal is the surface normal up to O(r). The distance from p to
// that plane is therefore |H| r²/4 + O(r³): |H| ≈ 4 |n_pca . (p - b)| / r². Unlike the
// distance to the barycenter, the tangential drift of b (non-uniform sampling) does not
// enter. The sign is lost with the orientation of the PCA normal.
//
// Also the unweighted PCA of a neighbourhood, which Wavejets use for their initial frame.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_PCA_PLANE_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_PCA_PLANE_H

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/symmetric_eigen_3.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Unweighted principal component analysis of a neighbourhood (scaled centred frame).
struct Neighborhood_pca
{
  double centroid[3] = {0, 0, 0};
  double values[3] = {0, 0, 0};  // ascending
  double vectors[3][3] = {};     // vectors[0]: normal of the regression plane

  // False if the covariance is not finite or the neighbours do not span a plane (the two
  // largest eigenvalues must be positive, the middle one at least 1e-12 times the largest:
  // otherwise the neighbours are collinear or coincident and the plane is undefined).
  bool compute(const Neighborhood& nb)
  {
    if(nb.size == 0)
      return false;
    const double inv = 1.0 / double(nb.size);
    for(std::size_t i = 0; i < nb.size; ++i)
    {
      centroid[0] += nb.qx[i];
      centroid[1] += nb.qy[i];
      centroid[2] += nb.qz[i];
    }
    for(double& c : centroid)
      c *= inv;
    double cov[6] = {0, 0, 0, 0, 0, 0};
    for(std::size_t i = 0; i < nb.size; ++i)
    {
      const double d[3] = {nb.qx[i] - centroid[0], nb.qy[i] - centroid[1], nb.qz[i] - centroid[2]};
      cov[0] += d[0] * d[0];
      cov[1] += d[0] * d[1];
      cov[2] += d[0] * d[2];
      cov[3] += d[1] * d[1];
      cov[4] += d[1] * d[2];
      cov[5] += d[2] * d[2];
    }
    for(double& c : cov)
      c *= inv;
    if(!symmetric_eigen_3(cov, values, vectors))
      return false;
    return values[2] > 0 && values[1] > 1e-12 * values[2];
  }
};

// Below three points there is no regression plane.
constexpr std::size_t pca_plane_min_neighbors = 3;

// |H| in `mean` (1/length) and the PCA normal oriented like the query's input normal in
// `normal`; every other field NaN.
inline Local_estimate pca_plane_mean_curvature(const Neighborhood& nb)
{
  if(nb.size < pca_plane_min_neighbors)
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);
  Neighborhood_pca pca;
  if(!pca.compute(nb))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  const double* n = pca.vectors[0];
  // distance from the query (the origin) to the plane through the centroid, over r
  const double distance = std::abs(n[0] * pca.centroid[0] + n[1] * pca.centroid[1] + n[2] * pca.centroid[2]);
  Local_estimate e;
  orient_like(n, nb.query_normal, e.normal);
  e.mean = 4.0 * distance / nb.radius;  // |H| = 4 d / r², d = distance * r
  e.status = Curvature_estimate_status::VALID;
  return e;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
