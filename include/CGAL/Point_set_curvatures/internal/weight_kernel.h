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
// Power_kernel<P> generalises it to (1 - d^2/r^2)^P (P = 3, 4: smoother at the boundary).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_WEIGHT_KERNEL_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_WEIGHT_KERNEL_H

#include <CGAL/Point_set_curvatures/parameters.h>

#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// t^k for a compile-time k >= 0.
template <int K>
inline double power_of(double t)
{
  static_assert(K >= 0, "negative power");
  if constexpr(K == 0)
    return 1.0;
  else
    return t * power_of<K - 1>(t);
}

// The kernel (1 - d^2/r^2)^P, P >= 2, in the scaled frame (r = 1). With t = 1 - |q|^2 and
// q = (p - x)/r, dt/dx = 2 q / r, so
//
//   w = t^P,   grad_x w = (1/r) 2P t^(P-1) q,
//   Hessian_x w = (1/r^2) (4P(P-1) t^(P-2) q q^T - 2P t^(P-1) I).
//
// P = 2 is the paper's kernel; P = 3 and 4 have a Hessian that vanishes at |q| = 1 (C^2 and
// C^3 at the boundary), so that points entering the ball do not make the ASO jump. The
// limits at q = 0 are the polynomials' values (grad w = 0, Hessian w = -2P I / r^2).
template <int P>
struct Power_kernel
{
  static_assert(P >= 2, "the ASO needs a twice differentiable kernel: P >= 2");
  static constexpr int exponent = P;
  // t = 1 - |q|^2, the building block of every term below
  static double t_of(double squared_norm) { return 1.0 - squared_norm; }
  static double weight(double t) { return power_of<P>(t); }

  // grad w = gradient_factor * gradient_weight(t) * q
  static constexpr double gradient_factor = 2.0 * P;
  static double gradient_weight(double t) { return power_of<P - 1>(t); }
  // Hessian w = hessian_qq_factor * hessian_weight(t) * q q^T
  //           + hessian_identity_factor * gradient_weight(t) * I
  static constexpr double hessian_qq_factor = 4.0 * P * (P - 1);
  static constexpr double hessian_identity_factor = -2.0 * P;
  static double hessian_weight(double t) { return power_of<P - 2>(t); }
};

// The kernel of the paper and the default: (1 - d^2/r^2)^2.
typedef Power_kernel<2> Smooth_kernel;

// The constant kernel of the paper's asymptotic analysis (Section 4.1): w = 1 inside the
// ball. It has no useful derivative, so only the APSS fit (not the ASO) accepts it.
struct Constant_kernel
{
  static double weight(double /* t */) { return 1.0; }
};

// Calls f(Kernel()) with the kernel type of `kernel` (CONSTANT, SMOOTH, SMOOTH_CUBIC,
// SMOOTH_QUARTIC) and returns its result: the one switch of the sphere fits' kernel.
template <class Function>
decltype(auto) with_weight_kernel(Apss_weight_kernel kernel, Function&& f)
{
  switch(kernel)
  {
    case Apss_weight_kernel::CONSTANT: return f(Constant_kernel());
    case Apss_weight_kernel::SMOOTH_CUBIC: return f(Power_kernel<3>());
    case Apss_weight_kernel::SMOOTH_QUARTIC: return f(Power_kernel<4>());
    default: return f(Smooth_kernel());
  }
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
