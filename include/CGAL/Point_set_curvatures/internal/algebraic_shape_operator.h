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
//   grad S = 4 sum t g q,   Hess S = sum g (8 q q^T - 4 t I)      (t = 1 - |q|^2, w = t^2).
//
// Two passes over the neighbours, constant memory:
//   1. the sums and their gradients (30 numbers, Aso_first_order_sums), pushed through the
//      three formulas as second-order jets whose Hessians start at zero. This gives u_q, u_l,
//      grad u_l, grad u_c and the part of Hess u_c made of products of first derivatives,
//      sum_kl d2u_c/dS_k dS_l grad S_k grad S_l^T.
//   2. the remaining part of Hess u_c, sum_k du_c/dS_k Hess S_k, which is linear in the
//      per-neighbour Hessians: with the adjoints F_k = du_c/dS_k (reverse mode, u_c_adjoint),
//      it is sum_i gamma_i (8 q_i q_i^T - 4 t_i I) with gamma_i = sum_k F_k g_k(i): 7 numbers.
// This is the same field and the same derivatives as a single pass over all second-order
// moments (75 numbers per neighbour), at half the arithmetic.
//
// Tangent plane of Equation 27. By default P spans the plane orthogonal to grad f, the
// corrected normal that is returned, and W = P^T Hess f P / |grad f| is the shape operator
// of the level set of f through x: principal directions are exactly tangent. The authors'
// implementation (STORM-IRIT/algebraic-shape-operator, used for data/reference)
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
#include <CGAL/Point_set_curvatures/internal/normal_field_fit.h>
#include <CGAL/Point_set_curvatures/internal/quadric_fit.h>
#include <CGAL/Point_set_curvatures/internal/second_order_jet.h>
#include <CGAL/Point_set_curvatures/internal/weight_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Pass 1: the five sums of the sphere fit and the moments giving their gradients, in the
// scaled centred frame. grad A = 4 tq, grad B_a = 4 tqq[a, .], grad C_a = 4 tnq[a, .],
// grad D = 4 tqnq, grad E = 4 (tq - B) (since q.q = 1 - t).
struct Aso_first_order_sums
{
  double A = 0, B[3] = {}, C[3] = {}, D = 0, E = 0;
  double tq[3] = {};    // sum t q
  double tqq[6] = {};   // sum t q q^T, packed xx xy xz yy yz zz
  double tnq[9] = {};   // sum t n_a q_b, row a
  double tqnq[3] = {};  // sum t (q.n) q
};

// The variants of the ASO beyond the paper's (issue "an ASO that stays accurate on real
// sampling and imperfect normals"), all keeping the derivatives through the kernel exact:
// - Kernel: Power_kernel<P>, w = (1 - |q|^2)^P (weight_kernel.h); the paper's is P = 2.
// - Weighted: every neighbour's weight is multiplied by its sample weight a_i
//   (nb.sample_weight, e.g. the area of its tangent Voronoi cell, tangent_voronoi_area.h): the
//   sums become a quadrature of the surface integrals with area weights instead of equal
//   weights. a_i does not depend on the evaluation point, so it multiplies w, grad w and
//   Hess w alike.
// - Oriented: every neighbour's normal is used flipped if it disagrees with the reference
//   orientation `ref` (the weighted sum of the neighbourhood's normals), so that a few
//   flipped input normals do not bias the fit.
// - Blended: where the neighbourhood is one-sided, the tensor is blended with a least-squares
//   fit of the normal field (normal_field_fit.h), accumulated in pass 2.
// With the paper's choices (P = 2, no weights, no orientation, no blend) the arithmetic is the
// one of the original code, bitwise.

// The normal of neighbour i, flipped (Oriented) to agree with `ref`.
template <bool Oriented>
inline void neighbor_normal(const Neighborhood& nb, std::size_t i, const double ref[3], double n[3])
{
  n[0] = nb.nx[i];
  n[1] = nb.ny[i];
  n[2] = nb.nz[i];
  if constexpr(Oriented)
  {
    const double side = n[0] * ref[0] + n[1] * ref[1] + n[2] * ref[2] < 0 ? -1.0 : 1.0;
    n[0] *= side;
    n[1] *= side;
    n[2] *= side;
  }
}

// Pass 1 as one rank-1 update per neighbour, M += a g^T with a = (w, t^(P-1) q) (times the
// sample weight) and g = (1, q, n, q.n): row 0 of M holds A, B, C, D, rows 1-3 the gradient
// moments. The 4-row columns are contiguous, so the update vectorises (SSE2: 2 lanes, AVX: 4).
template <class Kernel, bool Weighted, bool Oriented>
inline Aso_first_order_sums aso_first_pass(const Neighborhood& nb, const double ref[3])
{
  double M[8][4] = {};  // M[j][r] = sum a_r g_j
  double E = 0;         // sum w q.q
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double qx = nb.qx[i], qy = nb.qy[i], qz = nb.qz[i];
    const double s = qx * qx + qy * qy + qz * qz;
    const double t = Kernel::t_of(s);
    double w = Kernel::weight(t), tg = Kernel::gradient_weight(t);
    if constexpr(Weighted)
    {
      w *= nb.sample_weight[i];
      tg *= nb.sample_weight[i];
    }
    double n[3];
    neighbor_normal<Oriented>(nb, i, ref, n);
    const double a[4] = {w, tg * qx, tg * qy, tg * qz};
    const double g[8] = {1.0, qx, qy, qz, n[0], n[1], n[2], qx * n[0] + qy * n[1] + qz * n[2]};
    for(int j = 0; j < 8; ++j)
      for(int r = 0; r < 4; ++r)
        M[j][r] += a[r] * g[j];
    E += w * s;
  }
  Aso_first_order_sums m;
  m.A = M[0][0];
  m.D = M[7][0];
  m.E = E;
  for(int c = 0; c < 3; ++c)
  {
    m.B[c] = M[1 + c][0];
    m.C[c] = M[4 + c][0];
    m.tq[c] = M[0][1 + c];
    m.tqnq[c] = M[7][1 + c];
    for(int d = 0; d < 3; ++d)
    {
      m.tnq[3 * c + d] = M[4 + c][1 + d];  // sum t n_c q_d
      if(d >= c)
        m.tqq[sym_index(c, d)] = M[1 + c][1 + d];
    }
  }
  return m;
}

// Jet of a sum with its value and gradient gradient_factor * moment; its Hessian is left
// to pass 2.
template <class Kernel>
inline Second_order_jet first_order_jet(double value, const double moment[3])
{
  Second_order_jet s;
  s.v = value;
  for(int i = 0; i < 3; ++i)
    s.g[i] = Kernel::gradient_factor * moment[i];
  return s;
}

// du_c/dS for S = (A, B, C, D, E), by reverse differentiation of Equations 2-4 at the sums'
// values (every quantity below is a value, not a jet).
struct Sums_adjoint
{
  double A = 0, B[3] = {0, 0, 0}, C[3] = {0, 0, 0}, D = 0, E = 0;
};

inline Sums_adjoint u_c_adjoint(const Aso_first_order_sums& m)
{
  const double* B = m.B;
  const double* C = m.C;
  const double BB = B[0] * B[0] + B[1] * B[1] + B[2] * B[2];
  const double BC = B[0] * C[0] + B[1] * C[1] + B[2] * C[2];
  const double num = m.A * m.D - BC, den = m.A * m.E - BB;
  const double u_q = num / (2 * den), inv_A = 1 / m.A;
  double u_l[3];
  for(int i = 0; i < 3; ++i)
    u_l[i] = (C[i] - 2 * u_q * B[i]) * inv_A;
  const double P = u_l[0] * B[0] + u_l[1] * B[1] + u_l[2] * B[2] + u_q * m.E;  // u_c = -P / A

  Sums_adjoint F;
  const double P_bar = -inv_A;
  F.A = P * inv_A * inv_A;
  double u_l_bar[3];
  for(int i = 0; i < 3; ++i)
  {
    u_l_bar[i] = P_bar * B[i];
    F.B[i] = P_bar * u_l[i];
  }
  double u_q_bar = P_bar * m.E;
  F.E = P_bar * u_q;
  // through u_l = (C - 2 u_q B) / A
  double ulb_B = 0, ulb_ul = 0;
  for(int i = 0; i < 3; ++i)
  {
    F.C[i] = u_l_bar[i] * inv_A;
    F.B[i] -= 2 * u_q * inv_A * u_l_bar[i];
    ulb_B += u_l_bar[i] * B[i];
    ulb_ul += u_l_bar[i] * u_l[i];
  }
  u_q_bar -= 2 * inv_A * ulb_B;
  F.A -= inv_A * ulb_ul;
  // through u_q = num / (2 den), num = A D - B.C, den = A E - B.B
  const double num_bar = u_q_bar / (2 * den);
  const double den_bar = -u_q_bar * u_q / den;
  F.A += num_bar * m.D + den_bar * m.E;
  F.D = num_bar * m.A;
  F.E += den_bar * m.A;
  for(int i = 0; i < 3; ++i)
  {
    F.B[i] -= num_bar * C[i] + 2 * den_bar * B[i];
    F.C[i] -= num_bar * B[i];
  }
  return F;
}

// Pass 2: sum_k F_k Hess S_k = sum_i gamma_i (c1 t^(P-2) q q^T + c2 t^(P-1) I) (times the
// sample weight), packed xx xy xz yy yz zz; for P = 2, 8 q q^T - 4 t I.
// With Fit, the same loop also accumulates the normal-field fit (normal_field_fit.h) in the
// tangent basis (t1, t2), with the fit's weights.
template <class Kernel, bool Weighted, bool Oriented, bool Fit = false>
inline void aso_second_pass(const Neighborhood& nb, const Sums_adjoint& F, const double ref[3], double hessian[6],
                            const double* t1 = nullptr, const double* t2 = nullptr, Normal_field_sums* fit = nullptr)
{
  double gxx = 0, gxy = 0, gxz = 0, gyy = 0, gyz = 0, gzz = 0, gt = 0;
  // the fit's sums (Normal_field_sums), in locals so that the compiler keeps them in registers
  double fw = 0, fu = 0, fv = 0, fuu = 0, fuv = 0, fvv = 0, fa = 0, fb = 0, fau = 0, fav = 0, fbu = 0, fbv = 0;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double qx = nb.qx[i], qy = nb.qy[i], qz = nb.qz[i];
    double n[3];
    neighbor_normal<Oriented>(nb, i, ref, n);
    const double s = qx * qx + qy * qy + qz * qz;
    const double t = Kernel::t_of(s);
    double gamma = F.A + F.B[0] * qx + F.B[1] * qy + F.B[2] * qz + F.C[0] * n[0] + F.C[1] * n[1] + F.C[2] * n[2] +
                   F.D * (qx * n[0] + qy * n[1] + qz * n[2]) + F.E * s;
    if constexpr(Weighted)
      gamma *= nb.sample_weight[i];
    if constexpr(Fit)
    {
      double w = Kernel::weight(t);
      if constexpr(Weighted)
        w *= nb.sample_weight[i];
      const double u = qx * t1[0] + qy * t1[1] + qz * t1[2], v = qx * t2[0] + qy * t2[1] + qz * t2[2];
      const double a = n[0] * t1[0] + n[1] * t1[1] + n[2] * t1[2], b = n[0] * t2[0] + n[1] * t2[1] + n[2] * t2[2];
      const double wu = w * u, wv = w * v;
      fw += w;
      fu += wu;
      fv += wv;
      fuu += wu * u;
      fuv += wu * v;
      fvv += wv * v;
      fa += w * a;
      fb += w * b;
      fau += wu * a;
      fav += wv * a;
      fbu += wu * b;
      fbv += wv * b;
    }
    const double gh = gamma * Kernel::hessian_weight(t);
    const double gx = gh * qx, gy = gh * qy, gz = gh * qz;
    gxx += gx * qx;
    gxy += gx * qy;
    gxz += gx * qz;
    gyy += gy * qy;
    gyz += gy * qz;
    gzz += gz * qz;
    gt += gamma * Kernel::gradient_weight(t);
  }
  if constexpr(Fit)
    *fit = Normal_field_sums{fw, fu, fv, fuu, fuv, fvv, fa, fb, fau, fav, fbu, fbv};
  const double g[6] = {gxx, gxy, gxz, gyy, gyz, gzz};
  for(int k = 0; k < 6; ++k)
    hessian[k] = Kernel::hessian_qq_factor * g[k];
  for(int k : {0, 3, 5})
    hessian[k] += Kernel::hessian_identity_factor * gt;
}

// Minimal number of neighbours (query included) for the sphere fit and the ASO.
constexpr std::size_t aso_min_neighbors = 3;

// The authors' projection: W = B^T (Hess / |g| - N N^T Hess) B, with B an orthonormal basis
// of the plane orthogonal to u_l, symmetrised (their code, include/AlgebraicShapeOperator.h).
inline bool set_authors_shape_operator(const double gradient[3], const double hessian[6], const double u_l[3],
                                       double inverse_length_unit, Local_estimate& e)
{
  const double g = std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] + gradient[2] * gradient[2]);
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
  set_principal_curvatures(form(t1, t1), 0.5 * (form(t1, t2) + form(t2, t1)), form(t2, t2), t1, t2, e);
  return std::isfinite(e.k_min) && std::isfinite(e.k_max);
}

// The choices of an ASO run (the named parameters of estimate_aso_curvatures()).
struct Aso_settings
{
  Aso_projection projection = Aso_projection::CORRECTED_NORMAL;
  int kernel_exponent = 2;        // P of (1 - d^2/r^2)^P: 2, 3 or 4
  bool orient_neighbors = false;  // flip neighbour normals against the majority
  // blend in the normal-field fit where the neighbourhood is one-sided (normal_field_fit.h);
  // with the CORRECTED_NORMAL projection only
  bool normal_field_blend = false;
  // weight of the shape operator of a quadric fitted to the positions alone (quadric_fit.h),
  // for normals estimated from the positions, falling to 0 where the neighbourhood is
  // one-sided; with the CORRECTED_NORMAL projection only
  double position_fit_blend = 0;
};

// The ASO from the first-pass sums `m` of a neighbourhood (normals flipped against `ref` if
// Oriented), with a kernel and a variant fixed at compile time.
template <class Kernel, bool Weighted, bool Oriented>
inline Local_estimate aso_from_first_pass(const Neighborhood& nb, const Aso_first_order_sums& m, const double ref[3],
                                          const Aso_settings& settings)
{
  // Degenerate fit: the weighted variance of the positions, (A E - B.B) / A^2, vanishes
  // when the neighbours coincide (relative to r^2, as q is scaled by 1/r); neighbours
  // without tangent spread (a line, a planar curve) leave a curvature unmeasured.
  const double BB = m.B[0] * m.B[0] + m.B[1] * m.B[1] + m.B[2] * m.B[2];
  if(!(m.A > 0) || !(m.A * m.E - BB > 1e-12 * m.A * m.A) || lacks_tangent_spread(m.tqq, m.C))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);

  typedef Second_order_jet Jet;
  const Jet A = first_order_jet<Kernel>(m.A, m.tq);
  Jet B[3], C[3];
  for(int a = 0; a < 3; ++a)
  {
    const double tqa_q[3] = {m.tqq[sym_index(a, 0)], m.tqq[sym_index(a, 1)], m.tqq[sym_index(a, 2)]};
    B[a] = first_order_jet<Kernel>(m.B[a], tqa_q);
    C[a] = first_order_jet<Kernel>(m.C[a], m.tnq + 3 * a);
  }
  const Jet D = first_order_jet<Kernel>(m.D, m.tqnq);
  // sum t^(P-1) (q.q) q = sum t^(P-1) q - sum t^P q, since q.q = 1 - t
  const double ts_q[3] = {m.tq[0] - m.B[0], m.tq[1] - m.B[1], m.tq[2] - m.B[2]};
  const Jet E = first_order_jet<Kernel>(m.E, ts_q);

  // Equations 2-4 (pass 1: the Hessians hold only products of first derivatives).
  const Jet u_q = 0.5 * ((A * D - (B[0] * C[0] + B[1] * C[1] + B[2] * C[2])) *
                         reciprocal(A * E - (B[0] * B[0] + B[1] * B[1] + B[2] * B[2])));
  const Jet inv_A = reciprocal(A);
  Jet u_l[3];
  for(int a = 0; a < 3; ++a)
    u_l[a] = (C[a] - 2.0 * (u_q * B[a])) * inv_A;
  const Jet u_c = -1.0 * ((u_l[0] * B[0] + u_l[1] * B[1] + u_l[2] * B[2] + u_q * E) * inv_A);

  // Equation 28 at the evaluation point (the origin of the frame): the gradient, hence the
  // corrected normal, is known before pass 2.
  double gradient[3];
  for(int i = 0; i < 3; ++i)
    gradient[i] = u_c.g[i] + u_l[i].v;
  Local_estimate e;
  double t1[3], t2[3];
  const bool corrected_normal = settings.projection == Aso_projection::CORRECTED_NORMAL;
  const double gradient_norm = corrected_normal ? gradient_frame(gradient, e.normal, t1, t2) : 0.0;
  if(corrected_normal && gradient_norm == 0)
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);

  // How one-sided the neighbourhood is (the tangential offset of the weighted centroid B / A,
  // units of r) and how much wider it spreads one way than the other (the axes of the
  // tangential moments sum t^(P-1) q q^T), hence the weight of the normal-field fit
  // (normal_field_fit.h).
  // The one-sidedness also takes the position fit out (position_fit_blend).
  double blend = 0, one_sided = 0;
  if(corrected_normal && (settings.normal_field_blend || settings.position_fit_blend > 0))
  {
    const double c[3] = {m.B[0] / m.A, m.B[1] / m.A, m.B[2] / m.A};
    const double cu = c[0] * t1[0] + c[1] * t1[1] + c[2] * t1[2];
    const double cv = c[0] * t2[0] + c[1] * t2[1] + c[2] * t2[2];
    one_sided = normal_field_blend_weight(std::sqrt(cu * cu + cv * cv));
  }
  if(corrected_normal && settings.normal_field_blend)
  {
    const double m11 = symmetric_form(m.tqq, t1, t1), m12 = symmetric_form(m.tqq, t1, t2),
                 m22 = symmetric_form(m.tqq, t2, t2);
    blend = std::max(one_sided, normal_field_anisotropy_weight(axis_ratio(m11, m12, m22)));
  }

  // Pass 2: the part of Hess u_c linear in the sums' Hessians (and the normal-field fit).
  double linear_part[6];
  Normal_field_sums fit;
  if(blend > 0)
    aso_second_pass<Kernel, Weighted, Oriented, true>(nb, u_c_adjoint(m), ref, linear_part, t1, t2, &fit);
  else
    aso_second_pass<Kernel, Weighted, Oriented>(nb, u_c_adjoint(m), ref, linear_part);

  // Equation 29 at the evaluation point.
  double hessian[6];
  for(int i = 0; i < 3; ++i)
    for(int j = i; j < 3; ++j)
    {
      const int k = sym_index(i, j);
      hessian[k] = u_c.h[k] + linear_part[k] + u_l[i].g[j] + u_l[j].g[i] + (i == j ? 2.0 * u_q.v : 0.0);
    }

  // Equations 27 and 31-35; derivatives are per unit of the scaled frame, hence 1/r.
  if(corrected_normal)
  {
    double W[3], S[3];
    shape_operator_in_basis(gradient_norm, hessian, 1.0 / nb.radius, t1, t2, W);
    if(blend > 0 && fit.solve(S))
    {
      // S is signed by the neighbours' normals, W by grad f: they agree unless the corrected
      // normal opposes the normals' weighted sum C (a degenerate fit; then S is turned)
      const double side = e.normal[0] * m.C[0] + e.normal[1] * m.C[1] + e.normal[2] * m.C[2] < 0 ? -1.0 : 1.0;
      for(int k = 0; k < 3; ++k)
        W[k] = (1 - blend) * W[k] + blend * side * S[k] / nb.radius;
    }
    // The position fit, not where the neighbourhood is one-sided: there the quadric extrapolates
    // from one side (on the outermost of airborne lines 5:1 with range noise of 0.3 spacings,
    // which it sees with one or two others, benchmark/scan_experiments: blended in, a mean
    // |H - H*| of 0.31 against the ASO's 0.05). Irregular sampling can make a neighbourhood
    // one-sided inside a patch too.
    const double position_weight = settings.position_fit_blend * (1 - one_sided);
    if(position_weight > 0)
    {
      Quadric_fit quadric;
      double Q[3];
      if(quadric.compute(nb) && quadric.shape_operator_in(e.normal, t1, t2, 1.0 / nb.radius, Q))
        for(int k = 0; k < 3; ++k)
          W[k] = (1 - position_weight) * W[k] + position_weight * Q[k];
    }
    set_principal_curvatures(W[0], W[1], W[2], t1, t2, e);
    if(!std::isfinite(e.k_min) || !std::isfinite(e.k_max))
      return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  }
  else
  {
    const double u_l_value[3] = {u_l[0].v, u_l[1].v, u_l[2].v};
    if(!set_authors_shape_operator(gradient, hessian, u_l_value, 1.0 / nb.radius, e))
      return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  }
  if(corrected_normal)  // (the authors' projection may read normals that are not unit)
    e.normal_coherence = normal_coherence(m.A, m.C);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

// The ASO of one neighbourhood with a kernel and sample weights fixed at compile time. With
// the robust orientation, the reference (the weighted sum of the normals) is the first pass's
// sum C, so the first pass runs on the normals as given; only if some neighbour disagrees with
// it (rare: flipped normals, two sheets) are the orientation test and the first pass run again
// on the flipped normals. The result is the same as flipping from the start.
template <class Kernel, bool Weighted>
inline Local_estimate aso_with_kernel(const Neighborhood& nb, const Aso_settings& s)
{
  const double none[3] = {0, 0, 0};
  const Aso_first_order_sums m = aso_first_pass<Kernel, Weighted, false>(nb, none);
  if(s.orient_neighbors)
  {
    double ref[3];
    orientation_reference(m.C, nb.query_normal, ref);
    if(has_disagreeing_normal(nb, ref))
    {
      if(!majority_orientation<Kernel>(nb, ref))
        return Local_estimate::invalid(Curvature_estimate_status::TWO_SHEETS);
      return aso_from_first_pass<Kernel, Weighted, true>(nb, aso_first_pass<Kernel, Weighted, true>(nb, ref), ref, s);
    }
  }
  return aso_from_first_pass<Kernel, Weighted, false>(nb, m, none, s);
}

template <class Kernel>
inline Local_estimate algebraic_shape_operator_kernel(const Neighborhood& nb, const Aso_settings& s)
{
  return nb.sample_weight != nullptr ? aso_with_kernel<Kernel, true>(nb, s) : aso_with_kernel<Kernel, false>(nb, s);
}

// ASO estimate (Equations 27-35) of a neighbourhood; sample weights where the neighbourhood
// carries them.
inline Local_estimate algebraic_shape_operator(const Neighborhood& nb, const Aso_settings& s)
{
  if(nb.size < aso_min_neighbors)
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);
  switch(s.kernel_exponent)
  {
    case 3: return algebraic_shape_operator_kernel<Power_kernel<3> >(nb, s);
    case 4: return algebraic_shape_operator_kernel<Power_kernel<4> >(nb, s);
    default: return algebraic_shape_operator_kernel<Power_kernel<2> >(nb, s);
  }
}

// The paper's ASO with a projection (kept for the per-query class and the tests).
inline Local_estimate algebraic_shape_operator(const Neighborhood& nb,
                                               Aso_projection projection = Aso_projection::CORRECTED_NORMAL)
{
  Aso_settings s;
  s.projection = projection;
  return algebraic_shape_operator(nb, s);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
