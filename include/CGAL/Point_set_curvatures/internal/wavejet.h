// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Order-2 Wavejets (Béarzi, Digne, Chaine, "Wavejets: A Local Frequency Framework for
// Shape Details Amplification", Computer Graphics Forum 37(2), 2018).
//
// A wavejet of order K writes the height of the surface over a tangent plane, in polar
// coordinates (ρ, θ), as f(ρ, θ) = sum_{k<=K} sum_{|m|<=k, m≡k mod 2} φ_{k,m} ρ^k e^{imθ},
// with φ_{k,-m} the conjugate of φ_{k,m} (f is real). For K = 2 the six real unknowns are
//
//   φ_{0,0},  φ_{1,1} = (a1 - i a2)/2,  φ_{2,0} = (a3 + a5)/2,  φ_{2,2} = (a3 - a5 - i a4)/4
//
// for the quadratic h = a0 + a1 u + a2 v + a3 u² + a4 uv + a5 v² (u = ρ cos θ, v = ρ sin θ):
// the two bases span the same functions, so the complex least-squares fit of the paper and
// the real fit of height_field.h have the same solution, and we solve the real one.
//
// Procedure, at the query point x (scaled frame, x at the origin):
//   1. initial frame: the normal of the unweighted PCA of the neighbourhood (Béarzi et al.
//      take no input normal; ours only orients it);
//   2. fit the order-2 wavejet with the weights exp(-ρ²/18), ρ the tangential distance in
//      units of r (nearly uniform: 0.95 at ρ = 1), as in the implementation Lejemble et al.
//      2021 compared against (ported from the authors' Matlab code);
//   3. normal correction: φ_{1,±1} measure the tilt of the frame's plane against the fitted
//      surface; the corrected normal is the fitted surface's normal above x, the initial one
//      rotated by atan(2 |φ_{1,1}|);
//   4. refit in the corrected frame. With the tilt removed, the Hessian of the height field
//      has the eigenvalues 2 φ_{2,0} ± 4 |φ_{2,2}| (the principal curvatures, negated in the
//      package's convention since heights grow along the outward normal), with eigenvectors
//      at the angles -arg(φ_{2,2})/2 modulo π/2 from t1. We take the curvatures of the graph
//      (height_field.h), which equal these and also account for the residual tilt.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_WAVEJET_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_WAVEJET_H

#include <CGAL/Point_set_curvatures/internal/height_field.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/pca_plane.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// An order-2 wavejet has 6 real degrees of freedom.
constexpr std::size_t wavejet_min_neighbors = quadratic_height_coefficients;

// Least-squares order-2 wavejet of the neighbourhood over the frame (t1, t2, n) at x, as
// the coefficients of the equivalent quadratic. False if the system is singular.
inline bool fit_order2_wavejet(const Neighborhood& nb, const double t1[3], const double t2[3], const double n[3],
                               double a[6])
{
  Quadratic_height_fit fit;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double q[3] = {nb.qx[i], nb.qy[i], nb.qz[i]};
    const double u = t1[0] * q[0] + t1[1] * q[1] + t1[2] * q[2];
    const double v = t2[0] * q[0] + t2[1] * q[1] + t2[2] * q[2];
    const double h = n[0] * q[0] + n[1] * q[1] + n[2] * q[2];
    fit.add(u, v, h, std::exp(-(u * u + v * v) / 18.0));
  }
  return fit.solve(a);
}

inline Local_estimate wavejet_estimate(const Neighborhood& nb)
{
  if(nb.size < wavejet_min_neighbors)
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);

  // 1. PCA frame oriented like the input normal
  Neighborhood_pca pca;
  if(!pca.compute(nb))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  double n[3], t1[3], t2[3];
  orient_like(pca.vectors[0], nb.query_normal, n);
  tangent_basis(n, t1, t2);

  // 2. first fit
  double a[6];
  if(!fit_order2_wavejet(nb, t1, t2, n, a))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);

  // 3. corrected normal: n - a1 t1 - a2 t2 (tilt angle atan(|(a1, a2)|) = atan(2 |φ_{1,1}|))
  double nc[3];
  for(int i = 0; i < 3; ++i)
    nc[i] = n[i] - a[1] * t1[i] - a[2] * t2[i];
  const double length = std::sqrt(nc[0] * nc[0] + nc[1] * nc[1] + nc[2] * nc[2]);
  for(double& x : nc)
    x /= length;
  tangent_basis(nc, t1, t2);

  // 4. refit in the corrected frame, curvatures of the fitted graph above x
  Local_estimate e;
  if(!fit_order2_wavejet(nb, t1, t2, nc, a) || !set_height_field_curvatures(a, t1, t2, nc, 1.0 / nb.radius, e))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
