// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The APSS algebraic sphere fit (Section 3 of Lejemble et al. 2021; Guennebaud and Gross
// 2007): f(x) = u_c + u_l . x + u_q x.x fitted to oriented points around the evaluation
// point, its Pratt normalisation (Equation 6) and the APSS estimators (Equations 7-8).
//
// Computed in the scaled centred frame q = (p - x) / r (see weight_kernel.h), where the
// evaluation point is the origin.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_ALGEBRAIC_SPHERE_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_ALGEBRAIC_SPHERE_H

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/weight_kernel.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The five weighted sums of Equations 2-4, A = sum w, B = sum w q, C = sum w n,
// D = sum w q.n, E = sum w q.q.
template <class WeightKernel = Smooth_kernel>
struct Algebraic_sphere_sums
{
  std::size_t count = 0;
  double A = 0, B[3] = {}, C[3] = {}, D = 0, E = 0;
  // sum w q q^T (packed xx xy xz yy yz zz): not part of the fit, it tells whether the
  // neighbours spread in two tangent directions (any positive weights will do)
  double qq[6] = {};

  void add(double qx, double qy, double qz, double nx, double ny, double nz)
  {
    const double s = qx * qx + qy * qy + qz * qz;
    const double w = WeightKernel::weight(1.0 - s);
    ++count;
    A += w;
    B[0] += w * qx;
    B[1] += w * qy;
    B[2] += w * qz;
    C[0] += w * nx;
    C[1] += w * ny;
    C[2] += w * nz;
    D += w * (qx * nx + qy * ny + qz * nz);
    E += w * s;
    const double wx = w * qx, wy = w * qy, wz = w * qz;
    qq[0] += wx * qx;
    qq[1] += wx * qy;
    qq[2] += wx * qz;
    qq[3] += wy * qy;
    qq[4] += wy * qz;
    qq[5] += wz * qz;
  }

  // Whole neighbourhood at once; local accumulators so that the compiler keeps them in
  // registers (members could alias the input arrays). Each kernel weight is multiplied by
  // the neighbour's sample weight if the neighbourhood has them; with `ref`, each normal is
  // flipped to agree with it (robust orientation). Without either, the paper's arithmetic.
  void add(const Neighborhood& nb, const double* ref = nullptr)
  {
    if(nb.sample_weight)
      ref ? add_variant<true, true>(nb, ref) : add_variant<true, false>(nb, ref);
    else
      ref ? add_variant<false, true>(nb, ref) : add_variant<false, false>(nb, ref);
  }

private:
  template <bool Weighted, bool Oriented>
  void add_variant(const Neighborhood& nb, const double* ref)
  {
    double a = 0, b0 = 0, b1 = 0, b2 = 0, c0 = 0, c1 = 0, c2 = 0, d = 0, e = 0;
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    for(std::size_t i = 0; i < nb.size; ++i)
    {
      const double qx = nb.qx[i], qy = nb.qy[i], qz = nb.qz[i];
      double nx = nb.nx[i], ny = nb.ny[i], nz = nb.nz[i];
      if constexpr(Oriented)
      {
        const double side = nx * ref[0] + ny * ref[1] + nz * ref[2] < 0 ? -1.0 : 1.0;
        nx *= side;
        ny *= side;
        nz *= side;
      }
      const double s = qx * qx + qy * qy + qz * qz;
      double w = WeightKernel::weight(1.0 - s);
      if constexpr(Weighted)
        w *= nb.sample_weight[i];
      a += w;
      b0 += w * qx;
      b1 += w * qy;
      b2 += w * qz;
      c0 += w * nx;
      c1 += w * ny;
      c2 += w * nz;
      d += w * (qx * nx + qy * ny + qz * nz);
      e += w * s;
      const double wx = w * qx, wy = w * qy, wz = w * qz;
      xx += wx * qx;
      xy += wx * qy;
      xz += wx * qz;
      yy += wy * qy;
      yz += wy * qz;
      zz += wz * qz;
    }
    count += nb.size;
    A += a;
    B[0] += b0;
    B[1] += b1;
    B[2] += b2;
    C[0] += c0;
    C[1] += c1;
    C[2] += c2;
    D += d;
    E += e;
    qq[0] += xx;
    qq[1] += xy;
    qq[2] += xz;
    qq[3] += yy;
    qq[4] += yz;
    qq[5] += zz;
  }
};

// Coefficients of the fitted sphere in the scaled centred frame.
struct Algebraic_sphere
{
  double u_c = 0, u_l[3] = {0, 0, 0}, u_q = 0;
  // Pratt norm sqrt(|u_l|^2 - 4 u_c u_q) of the unnormalised coefficients.
  double pratt_norm = 0;
  bool valid = false;
};

// Minimal number of neighbours (query included) for the sphere fit.
constexpr std::size_t apss_min_neighbors = 3;

// Equations 2-4 and the Pratt norm. `valid` is false for a degenerate fit (the
// neighbours coincide or lie on a curve, or the normals cancel out so that the field has
// no gradient).
template <class WeightKernel>
Algebraic_sphere fit_algebraic_sphere(const Algebraic_sphere_sums<WeightKernel>& s)
{
  Algebraic_sphere sphere;
  const double BB = s.B[0] * s.B[0] + s.B[1] * s.B[1] + s.B[2] * s.B[2];
  const double BC = s.B[0] * s.C[0] + s.B[1] * s.C[1] + s.B[2] * s.C[2];
  const double den = s.A * s.E - BB;
  // (A E - B.B) / A^2 is the weighted variance of the positions, in units of r^2.
  if(!(s.A > 0) || !(den > 1e-12 * s.A * s.A))
    return sphere;
  sphere.u_q = 0.5 * (s.A * s.D - BC) / den;
  for(int i = 0; i < 3; ++i)
    sphere.u_l[i] = (s.C[i] - 2.0 * sphere.u_q * s.B[i]) / s.A;
  sphere.u_c = -(sphere.u_l[0] * s.B[0] + sphere.u_l[1] * s.B[1] + sphere.u_l[2] * s.B[2] + sphere.u_q * s.E) / s.A;
  const double ll = sphere.u_l[0] * sphere.u_l[0] + sphere.u_l[1] * sphere.u_l[1] + sphere.u_l[2] * sphere.u_l[2];
  const double pratt2 = ll - 4.0 * sphere.u_c * sphere.u_q;
  sphere.pratt_norm = std::sqrt(pratt2);
  // Neighbours without spread in two tangent directions (one scan line, a planar curve)
  // fit a sphere whose curvature across them is not measured but assumed: not a fit of
  // the surface (this also guards the features, the projection and the flow).
  sphere.valid = (pratt2 > 1e-24) && (ll > 1e-24) && std::isfinite(pratt2) && !lacks_tangent_spread(s.qq, s.C);
  return sphere;
}

// APSS normal and mean curvature (Equations 7-8), other fields NaN.
template <class WeightKernel>
Local_estimate algebraic_sphere_estimate(const Algebraic_sphere_sums<WeightKernel>& s, double radius)
{
  if(s.count < apss_min_neighbors)
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);
  const Algebraic_sphere sphere = fit_algebraic_sphere(s);
  if(!sphere.valid)
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  Local_estimate e;
  const double ul =
    std::sqrt(sphere.u_l[0] * sphere.u_l[0] + sphere.u_l[1] * sphere.u_l[1] + sphere.u_l[2] * sphere.u_l[2]);
  for(int i = 0; i < 3; ++i)
    e.normal[i] = sphere.u_l[i] / ul;
  // H = 2 u_q / p in the scaled frame, divided by r to return to input units.
  e.mean = 2.0 * sphere.u_q / (sphere.pratt_norm * radius);
  e.normal_coherence = normal_coherence(s.A, s.C);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
