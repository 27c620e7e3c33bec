// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Algebraic Shape Operator (ASO), Section 5 of Lejemble, Coeurjolly, Barthe, Mellado,
// "Stable and efficient differential estimators on oriented point clouds", CGF 2021.
//
// The APSS algebraic sphere f(x) = u_c + u_l . x + u_q x.x (Equation 1) is fitted with
// weights w_i(x) = K(|p_i - x| / r) that depend on the evaluation point x, so its
// coefficients are functions of x. The ASO is the shape operator of that field,
// W = P Hess f P / |grad f| (Equation 27), with grad f and Hess f from Equations 28-29.
//
// We evaluate in the frame centred at x, scaled by 1/r (see weight_kernel.h). There the
// evaluation point is the origin and Equations 28-29 reduce to
//
//   grad f(0) = grad u_c + u_l
//   Hess f(0) = Hess u_c + grad u_l + grad u_l^T + 2 u_q I
//
// (the terms multiplied by x vanish), so only u_q, u_l, grad u_l, grad u_c and Hess u_c
// are needed. The coefficients are rational functions of five weighted sums
//
//   A = sum w,  B = sum w q,  C = sum w n,  D = sum w q.n,  E = sum w q.q
//
// (Equations 2-4, written with unnormalised weights):
//
//   u_q = (A D - B.C) / (2 (A E - B.B)),  u_l = (C - 2 u_q B) / A,  u_c = -(u_l.B + u_q E) / A.
//
// Each sum S = sum w g (g fixed per neighbour) has, with the kernel derivatives,
//
//   grad S = 4 sum t g q,   Hess S = 8 sum g q q^T - 4 I sum t g      (t = 1 - |q|^2, w = t^2),
//
// so one pass over the neighbours accumulates 75 moments (Aso_moments), from which the
// value, gradient and Hessian of A..E are assembled as second-order jets and pushed
// through the three formulas above. E needs no moments of its own: q.q = 1 - t.
//
// Tangent plane of Equation 27. By default P spans the plane orthogonal to grad f, the
// corrected normal that is returned, and W = P^T Hess f P / |grad f| is the shape operator
// of the level set of f through x: principal directions are exactly tangent. The authors'
// implementation (STORM-IRIT/algebraic-shape-operator, used for ../shared/data/reference)
// instead projects Hess f / |grad f| - N N^T Hess f on the plane orthogonal to u_l and uses
// the input normals unnormalised; Aso_projection::AUTHORS_IMPLEMENTATION reproduces it to
// about 1e-12. Both give the same curvature accuracy on the Goursat clouds; the default
// halves the principal direction error there and keeps directions orthogonal to the normal
// (the authors' deviate from it by 3 degrees in median, 37 at most, on the bunny at r = 0.005).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_ALGEBRAIC_SHAPE_OPERATOR_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_ALGEBRAIC_SHAPE_OPERATOR_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/second_order_jet.h>
#include <CGAL/Point_set_curvatures/internal/weight_kernel.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Packed index of the symmetric third-order entry (a, b, c), a <= b <= c:
// xxx xxy xxz xyy xyz xzz yyy yyz yzz zzz.
inline int sym3_index(int a, int b, int c)
{
  // sort the three indices
  if(a > b) { int s = a; a = b; b = s; }
  if(b > c) { int s = b; b = c; c = s; }
  if(a > b) { int s = a; a = b; b = s; }
  static const int first[3] = {0, 6, 9};  // start of the block with smallest index a
  return first[a] + sym_index(b, c) - sym_index(a, a);
}

// Weighted moments of one neighbourhood, in the scaled centred frame (Smooth_kernel).
// Symmetric 3x3 blocks are packed xx xy xz yy yz zz.
struct Aso_moments
{
  std::size_t count = 0;
  double t = 0, t2 = 0, t3 = 0;     // sum t, sum t^2 (= sum w), sum t^3
  double tq[3] = {}, t2q[3] = {};   // sum t q, sum t^2 q
  double qq[6] = {}, tqq[6] = {};   // sum q q^T, sum t q q^T
  double qqq[10] = {};              // sum q (x) q (x) q
  double tn[3] = {}, t2n[3] = {};   // sum t n, sum t^2 n
  double tnq[9] = {};               // sum t n q^T, row a = n_a
  double nqq[18] = {};              // sum n_a q q^T, block a
  double t_qn = 0, t2_qn = 0;       // sum t (q.n), sum t^2 (q.n)
  double t_qn_q[3] = {};            // sum t (q.n) q
  double qn_qq[6] = {};             // sum (q.n) q q^T

  // One neighbour at q (|q| < 1, scaled frame) with unit normal n.
  void add(double qx, double qy, double qz, double nx, double ny, double nz)
  {
    const double tt = Smooth_kernel::t_of(qx * qx + qy * qy + qz * qz);
    const double tt2 = tt * tt;
    ++count;
    t += tt; t2 += tt2; t3 += tt2 * tt;
    const double q[3] = {qx, qy, qz};
    const double n[3] = {nx, ny, nz};
    const double m[6] = {qx * qx, qx * qy, qx * qz, qy * qy, qy * qz, qz * qz};
    const double qn = qx * nx + qy * ny + qz * nz;
    for(int i = 0; i < 3; ++i)
    {
      tq[i] += tt * q[i];
      t2q[i] += tt2 * q[i];
      tn[i] += tt * n[i];
      t2n[i] += tt2 * n[i];
      t_qn_q[i] += tt * qn * q[i];
      const double tni = tt * n[i];
      for(int j = 0; j < 3; ++j)
        tnq[3 * i + j] += tni * q[j];
    }
    for(int k = 0; k < 6; ++k)
    {
      qq[k] += m[k];
      tqq[k] += tt * m[k];
      qn_qq[k] += qn * m[k];
      nqq[k] += nx * m[k];
      nqq[6 + k] += ny * m[k];
      nqq[12 + k] += nz * m[k];
    }
    qqq[0] += m[0] * qx; qqq[1] += m[0] * qy; qqq[2] += m[0] * qz;
    qqq[3] += m[1] * qy; qqq[4] += m[1] * qz; qqq[5] += m[2] * qz;
    qqq[6] += m[3] * qy; qqq[7] += m[3] * qz; qqq[8] += m[4] * qz;
    qqq[9] += m[5] * qz;
    t_qn += tt * qn;
    t2_qn += tt2 * qn;
  }

  void add(const Neighborhood& nb)
  {
    for(std::size_t i = 0; i < nb.size; ++i)
      add(nb.qx[i], nb.qy[i], nb.qz[i], nb.nx[i], nb.ny[i], nb.nz[i]);
  }
};

// Jet of sum w g from the three moments sum t^2 g, sum t g q and sum g q q^T, sum t g.
inline Second_order_jet weighted_sum_jet(double sum_t2_g, const double sum_t_g_q[3],
                                         const double sum_g_qq[6], double sum_t_g)
{
  Second_order_jet s;
  s.v = sum_t2_g;
  for(int i = 0; i < 3; ++i)
    s.g[i] = Smooth_kernel::gradient_factor * sum_t_g_q[i];
  for(int k = 0; k < 6; ++k)
    s.h[k] = Smooth_kernel::hessian_qq_factor * sum_g_qq[k];
  for(int k : {0, 3, 5})
    s.h[k] += Smooth_kernel::hessian_identity_factor * sum_t_g;
  return s;
}

// Minimal number of neighbours (query included) for the sphere fit and the ASO.
constexpr std::size_t aso_min_neighbors = 3;

// The authors' projection: W = B^T (Hess / |g| - N N^T Hess) B, with B an orthonormal basis
// of the plane orthogonal to u_l, symmetrised (their code, include/AlgebraicShapeOperator.h).
inline bool set_authors_shape_operator(const double gradient[3], const double hessian[6],
                                       const double u_l[3], double inverse_length_unit,
                                       Local_estimate& e)
{
  const double g = std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] +
                             gradient[2] * gradient[2]);
  const double l = std::sqrt(u_l[0] * u_l[0] + u_l[1] * u_l[1] + u_l[2] * u_l[2]);
  if(!(g > 1e-12) || !(l > 1e-12) || !std::isfinite(g) || !std::isfinite(l))
    return false;
  double plane_normal[3], t1[3], t2[3];
  for(int i = 0; i < 3; ++i)
  {
    e.normal[i] = gradient[i] / g;
    plane_normal[i] = u_l[i] / l;
  }
  tangent_basis(plane_normal, t1, t2);
  // M = Hess / |g| - N N^T Hess (sic: the second term is not divided by |g|)
  double M[3][3];
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
    {
      double nn_h = 0;
      for(int k = 0; k < 3; ++k)
        nn_h += e.normal[i] * e.normal[k] * hessian[sym_index(k, j)];
      M[i][j] = hessian[sym_index(i, j)] / g - nn_h;
    }
  auto form = [&](const double u[3], const double v[3]) {
    double s = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        s += u[i] * M[i][j] * v[j];
    return s * inverse_length_unit;
  };
  set_principal_curvatures(form(t1, t1), 0.5 * (form(t1, t2) + form(t2, t1)), form(t2, t2),
                           t1, t2, e);
  return std::isfinite(e.k_min) && std::isfinite(e.k_max);
}

// ASO estimate (Equations 27-35) from the moments of a neighbourhood of radius r.
inline Local_estimate algebraic_shape_operator(const Aso_moments& m, double radius,
                                               Aso_projection projection = Aso_projection::CORRECTED_NORMAL)
{
  if(m.count < aso_min_neighbors)
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);

  typedef Second_order_jet Jet;
  // The five sums of the sphere fit, with their derivatives in x.
  const Jet A = weighted_sum_jet(m.t2, m.tq, m.qq, m.t);
  Jet B[3], C[3];
  for(int a = 0; a < 3; ++a)
  {
    double tqa_q[3], qa_qq[6];
    for(int b = 0; b < 3; ++b)
      tqa_q[b] = m.tqq[sym_index(a, b)];
    for(int b = 0; b < 3; ++b)
      for(int c = b; c < 3; ++c)
        qa_qq[sym_index(b, c)] = m.qqq[sym3_index(a, b, c)];
    B[a] = weighted_sum_jet(m.t2q[a], tqa_q, qa_qq, m.tq[a]);
    C[a] = weighted_sum_jet(m.t2n[a], m.tnq + 3 * a, m.nqq + 6 * a, m.tn[a]);
  }
  const Jet D = weighted_sum_jet(m.t2_qn, m.t_qn_q, m.qn_qq, m.t_qn);
  double ts_q[3], s_qq[6];  // sum t (q.q) q and sum (q.q) q q^T, with q.q = 1 - t
  for(int i = 0; i < 3; ++i) ts_q[i] = m.tq[i] - m.t2q[i];
  for(int k = 0; k < 6; ++k) s_qq[k] = m.qq[k] - m.tqq[k];
  const Jet E = weighted_sum_jet(m.t2 - m.t3, ts_q, s_qq, m.t - m.t2);

  // Degenerate fit: the weighted variance of the positions, (A E - B.B) / A^2, vanishes
  // when the neighbours coincide (relative to r^2, as q is scaled by 1/r).
  const Jet BB = B[0] * B[0] + B[1] * B[1] + B[2] * B[2];
  const Jet BC = B[0] * C[0] + B[1] * C[1] + B[2] * C[2];
  const Jet den = A * E - BB;
  if(!(A.v > 0) || !(den.v > 1e-12 * A.v * A.v))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);

  // Equations 2-4.
  const Jet u_q = 0.5 * ((A * D - BC) * reciprocal(den));
  const Jet inv_A = reciprocal(A);
  Jet u_l[3];
  for(int a = 0; a < 3; ++a)
    u_l[a] = (C[a] - 2.0 * (u_q * B[a])) * inv_A;
  const Jet u_c = -1.0 * ((u_l[0] * B[0] + u_l[1] * B[1] + u_l[2] * B[2] + u_q * E) * inv_A);

  // Equations 28-29 at the evaluation point (the origin of the frame).
  double gradient[3], hessian[6];
  for(int i = 0; i < 3; ++i)
    gradient[i] = u_c.g[i] + u_l[i].v;
  for(int i = 0; i < 3; ++i)
    for(int j = i; j < 3; ++j)
    {
      const int k = sym_index(i, j);
      hessian[k] = u_c.h[k] + u_l[i].g[j] + u_l[j].g[i] + (i == j ? 2.0 * u_q.v : 0.0);
    }

  Local_estimate e;
  // Equations 27 and 31-35; derivatives are per unit of the scaled frame, hence 1/r.
  const double u_l_value[3] = {u_l[0].v, u_l[1].v, u_l[2].v};
  const bool ok = (projection == Aso_projection::CORRECTED_NORMAL)
                    ? set_shape_operator(gradient, hessian, 1.0 / radius, e)
                    : set_authors_shape_operator(gradient, hessian, u_l_value, 1.0 / radius, e);
  if(!ok)
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
