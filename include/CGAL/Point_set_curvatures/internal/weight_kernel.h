// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The weight kernel of the APSS fit (Equation 5 of Lejemble et al. 2021) and its exact
// derivatives with respect to the evaluation point.
//
// Every estimator works in the query's scaled, centred frame: a neighbour p seen from the
// evaluation point x is q = (p - x) / r, so |q| < 1 inside the support. In that frame
//
//   w(q)        = t^2,                t = 1 - |q|^2            (the kernel K(d) = (1 - d^2/r^2)^2)
//   grad_x w    = (1/r)   * 4 t q
//   Hessian_x w = (1/r^2) * (8 q q^T - 4 t I)
//
// The derivatives are taken with respect to x (the neighbour is fixed), hence the signs.
// They are polynomials in q, so the limit at distance 0 needs no special case:
// grad w = 0 and Hessian w = -4/r^2 I there. The kernel is C^1 but not C^2 at |q| = 1:
// points exactly on the sphere of radius r are outside the neighbourhood (d < r is strict).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_WEIGHT_KERNEL_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_WEIGHT_KERNEL_H

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The smooth kernel (1 - d^2/r^2)^2, in the scaled frame (r = 1).
struct Smooth_kernel
{
  // t = 1 - |q|^2, the building block of every term below
  static double t_of(double squared_norm) { return 1.0 - squared_norm; }
  static double weight(double t) { return t * t; }

  // grad w = gradient_factor * t * q
  static constexpr double gradient_factor = 4.0;
  // Hessian w = hessian_qq_factor * q q^T + hessian_identity_factor * t * I
  static constexpr double hessian_qq_factor = 8.0;
  static constexpr double hessian_identity_factor = -4.0;
};

// The constant kernel of the paper's asymptotic analysis (Section 4.1): w = 1 inside the
// ball. It has no useful derivative, so only the APSS fit (not the ASO) accepts it.
struct Constant_kernel
{
  static double weight(double /* t */) { return 1.0; }
};

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
