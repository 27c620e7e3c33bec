// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations, for the
// covariance matrices of the baselines (PCA plane, Point Set Surfaces, Wavejets, VCM).
// Jacobi keeps the small eigenvalues and their eigenvectors accurate relative to the
// large ones (the normal of a flat neighbourhood is the eigenvector of an eigenvalue
// 1e4 times smaller than the others), needs no external library and is deterministic.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_SYMMETRIC_EIGEN_3_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_SYMMETRIC_EIGEN_3_H

#include <algorithm>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

inline bool symmetric_eigen_3(const double packed[6], double values[3], double vectors[3][3]);

// Matrices whose largest entry is subnormal: multiply by 2^600 first (exact), divide the
// eigenvalues back.
inline bool symmetric_eigen_3_rescaled(const double packed[6], double scale, double values[3], double vectors[3][3])
{
  const double up = std::ldexp(1.0, 600);
  double scaled[6];
  for(int i = 0; i < 6; ++i)
    scaled[i] = packed[i] * up;
  if(!(scale * up > 0))
    return false;
  if(!symmetric_eigen_3(scaled, values, vectors))
    return false;
  for(int k = 0; k < 3; ++k)
    values[k] /= up;
  return true;
}

// `packed` = xx xy xz yy yz zz. On return values[0] <= values[1] <= values[2] and
// vectors[k] is a unit eigenvector of values[k]. Returns false on non-finite input.
inline bool symmetric_eigen_3(const double packed[6], double values[3], double vectors[3][3])
{
  // Work on the matrix divided by its largest entry: the convergence test squares entries,
  // which would underflow below 1e-154 or overflow above 1e154 (VCM covariances scale as
  // length^5) and stop the iteration before any rotation.
  double scale = 0;
  for(int i = 0; i < 6; ++i)
  {
    if(!std::isfinite(packed[i]))
      return false;
    scale = std::max(scale, std::abs(packed[i]));
  }
  const double inv = scale > 0 ? 1.0 / scale : 1.0;
  if(!std::isfinite(inv))  // scale below the smallest normal double: rescale in two steps
    return symmetric_eigen_3_rescaled(packed, scale, values, vectors);
  double a[3][3] = {{packed[0] * inv, packed[1] * inv, packed[2] * inv},
                    {packed[1] * inv, packed[3] * inv, packed[4] * inv},
                    {packed[2] * inv, packed[4] * inv, packed[5] * inv}};
  double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // columns: eigenvectors

  static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for(int sweep = 0; sweep < 32; ++sweep)
  {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if(!(off > 1e-36 * diag))  // converged (quadratically: a few sweeps)
      break;
    for(const auto& pq : pairs)
    {
      const int p = pq[0], q = pq[1], r = 3 - p - q;
      if(a[p][q] == 0)
        continue;
      // rotation zeroing a[p][q] (the smaller of the two admissible angles)
      const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
      const double t = std::abs(theta) > 1e150
                         ? 0.5 / theta
                         : std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
      const double apq = a[p][q];
      a[p][p] -= t * apq;
      a[q][q] += t * apq;
      a[p][q] = a[q][p] = 0;
      const double arp = a[r][p], arq = a[r][q];
      a[r][p] = a[p][r] = c * arp - s * arq;
      a[r][q] = a[q][r] = s * arp + c * arq;
      for(int k = 0; k < 3; ++k)
      {
        const double vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
    }
  }
  int order[3] = {0, 1, 2};
  if(a[order[0]][order[0]] > a[order[1]][order[1]])
    std::swap(order[0], order[1]);
  if(a[order[1]][order[1]] > a[order[2]][order[2]])
    std::swap(order[1], order[2]);
  if(a[order[0]][order[0]] > a[order[1]][order[1]])
    std::swap(order[0], order[1]);
  for(int k = 0; k < 3; ++k)
  {
    values[k] = a[order[k]][order[k]] * scale;
    for(int i = 0; i < 3; ++i)
      vectors[k][i] = v[i][order[k]];
  }
  return true;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
