// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A scalar carried together with its gradient and Hessian with respect to the
// evaluation point x (forward-mode differentiation to second order). The Algebraic
// Shape Operator needs the first and second derivatives of the sphere coefficients
// u_c, u_l, u_q (Equations 2-4 of Lejemble et al. 2021), which are rational
// functions of a few weighted sums; pushing jets of those sums through the same
// formulas gives the derivatives exactly, with no hand-expanded quotient rules.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_SECOND_ORDER_JET_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_SECOND_ORDER_JET_H

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Index of the symmetric 3x3 entry (i, j) in the packed order xx xy xz yy yz zz.
inline constexpr int sym_index(int i, int j)
{
  return (i <= j) ? (i == 0 ? j : (i == 1 ? 2 + j : 5)) : (j == 0 ? i : (j == 1 ? 2 + i : 5));
}

struct Second_order_jet
{
  double v = 0;      // value
  double g[3] = {};  // gradient
  double h[6] = {};  // Hessian, packed xx xy xz yy yz zz
};

inline Second_order_jet operator+(const Second_order_jet& a, const Second_order_jet& b)
{
  Second_order_jet r;
  r.v = a.v + b.v;
  for(int i = 0; i < 3; ++i)
    r.g[i] = a.g[i] + b.g[i];
  for(int i = 0; i < 6; ++i)
    r.h[i] = a.h[i] + b.h[i];
  return r;
}

inline Second_order_jet operator-(const Second_order_jet& a, const Second_order_jet& b)
{
  Second_order_jet r;
  r.v = a.v - b.v;
  for(int i = 0; i < 3; ++i)
    r.g[i] = a.g[i] - b.g[i];
  for(int i = 0; i < 6; ++i)
    r.h[i] = a.h[i] - b.h[i];
  return r;
}

inline Second_order_jet operator*(double s, const Second_order_jet& a)
{
  Second_order_jet r;
  r.v = s * a.v;
  for(int i = 0; i < 3; ++i)
    r.g[i] = s * a.g[i];
  for(int i = 0; i < 6; ++i)
    r.h[i] = s * a.h[i];
  return r;
}

// Product rule: (ab)'' = a''b + a b'' + a' b'^T + b' a'^T.
inline Second_order_jet operator*(const Second_order_jet& a, const Second_order_jet& b)
{
  Second_order_jet r;
  r.v = a.v * b.v;
  for(int i = 0; i < 3; ++i)
    r.g[i] = a.v * b.g[i] + b.v * a.g[i];
  for(int i = 0; i < 3; ++i)
    for(int j = i; j < 3; ++j)
    {
      const int k = sym_index(i, j);
      r.h[k] = a.v * b.h[k] + b.v * a.h[k] + a.g[i] * b.g[j] + a.g[j] * b.g[i];
    }
  return r;
}

// 1/b: value 1/v, gradient -g/v^2, Hessian -h/v^2 + 2 g g^T / v^3.
inline Second_order_jet reciprocal(const Second_order_jet& b)
{
  const double iv = 1.0 / b.v, iv2 = iv * iv, two_iv3 = 2.0 * iv2 * iv;
  Second_order_jet r;
  r.v = iv;
  for(int i = 0; i < 3; ++i)
    r.g[i] = -iv2 * b.g[i];
  for(int i = 0; i < 3; ++i)
    for(int j = i; j < 3; ++j)
    {
      const int k = sym_index(i, j);
      r.h[k] = -iv2 * b.h[k] + two_iv3 * b.g[i] * b.g[j];
    }
  return r;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
