// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A least-squares fit of the normal field, for the neighbourhoods where the ASO is biased:
// one-sided ones (the border of a scan, the silhouette seen from a scanner) and, to a lesser
// degree, very irregular ones.
//
// Why the ASO is biased there. The ASO is the curvature of the APSS surface, whose fitted
// sphere at x follows x through the kernel weights. Where the neighbourhood is cut by a border,
// the data do not move with x: moving x towards the border moves the weighted centroid of the
// neighbourhood by less. The fitted normal then turns more slowly than the surface's, and the
// curvature across the border is underestimated. Measured in the continuum (a paraboloid with
// curvatures 0.2 and 0.1, sampled on a grid of step r/140 with exact areas, r = 1.4, kernel
// (1 - d²/r²)³): the curvature across a border through x is 0.152 instead of 0.200, across a
// border at 0.25 r from x 0.176; on a saddle 0.057 and 0.129 instead of 0.200. On the
// simulated LiDAR scan of the Goursat surface the 10% of points with the most one-sided
// neighbourhoods carry two thirds of the ASO's mean error (mean |H| error 25e-3 there against
// 0.8e-3 elsewhere).
//
// The fit. In the tangent frame (t1, t2) of the corrected normal, with u, v the tangential
// coordinates of a neighbour and g = (n.t1, n.t2) the tangential part of its normal, fit
//
//   g = g0 + S (u, v)^T,   S symmetric,
//
// by weighted least squares (the fit's weights: kernel times sample weight). S is the shape
// operator in that frame (with this package's sign: a sphere of radius R with outward normals
// gives S = I / R). A least-squares fit of a linear model is not biased by where the samples
// lie, one-sided or not. It is exact on a sphere whatever the sampling and the frame: there n =
// (p - O) / R, so the tangential part of n is exactly linear in the tangential position with
// slope I / R. Its weakness is accuracy on regular samples: on Goursat 50K blue noise its mean
// |H| error is 2.1e-3 against the ASO's 0.26e-3 (the normal field is not linear at the scale r),
// and it uses the input normals directly. So it is only blended in where the neighbourhood is
// one-sided (normal_field_blend_weight below).
//
// The indicator. The offset of the fit's weighted centroid from x, tangentially, in units of
// r: sum w q / sum w projected on the tangent plane. Below 0.02 (every point of the blue-noise
// Goursat clouds with area weights) the ASO is used alone; from 0.06 the fit alone; a smooth
// step in between. Chosen by measurement (user manual, "Beyond the paper"; thresholds 0.01 to
// 0.06 measured on seven clouds).
//
// A second indicator: neighbourhoods that spread in one direction much more than in the other
// (airborne scan lines far apart against the neighbourhood: one line near the query and two
// at the rim, where the kernel nearly vanishes). Moving x across the lines then moves weight
// between whole lines: the relative derivative of a neighbour's weight, 2P |q| / (1 - |q|²)
// per unit of r, is 13 for the outer lines at 0.8 r with P = 3, and the ASO's derivatives
// follow the weights more than the surface. The least-squares fit does not differentiate the
// weights. The spread is measured by the ratio of the axes, sqrt(lambda_min / lambda_max), of
// the tangential second moments sum t^(P-1) q q^T (about x, with the kernel t^(P-1) of the
// ASO's gradient moments, one power wider than its weights). Measured at 40 neighbours: on
// airborne lines 8 times farther apart than the spacing along them, not straight, median
// 0.69; on 5:1 lines 0.93; on 3:1 and 2:1 lines, terrestrial and merged scans and the torus
// 0.97 to 0.99; 5th percentiles above 0.8 on all of those. The fit is blended in from 0.85
// down to 0.7 (fully below). With exact normals (benchmark/README.md, section 8, mean |H|
// error): the 8:1 lines 3.99e-3 before, 1.58e-3 after (PSS 1.99e-3), a mobile scan 8.39e-3
// and 0.985e-3, every other scan within 1%; the paper's Goursat benchmark: blue noise
// unchanged, i.i.d. 2.28e-3 to 2.26e-3, the simulated LiDAR 1.30e-3 to 1.32e-3.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_NORMAL_FIELD_FIT_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_NORMAL_FIELD_FIT_H

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/weight_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Offsets of the weighted centroid (tangential, in units of r) between which the normal-field
// fit is blended in: weight 0 below the first, 1 above the second.
constexpr double normal_field_blend_start = 0.02;
constexpr double normal_field_blend_end = 0.06;

// Ratios of the axes of the tangential spread between which the fit is blended in: weight 0
// above the first, 1 below the second.
constexpr double normal_field_anisotropy_start = 0.85;
constexpr double normal_field_anisotropy_end = 0.7;

// A smooth step (C^1) from 0 at `from` to 1 at `to` (either order).
inline double smooth_step(double value, double from, double to)
{
  const double x = (value - from) / (to - from);
  if(!(x > 0))
    return 0;
  if(x >= 1)
    return 1;
  return x * x * (3 - 2 * x);
}

// The weight of the normal-field fit for a tangential centroid offset (units of r): 0 up to
// normal_field_blend_start, 1 from normal_field_blend_end.
inline double normal_field_blend_weight(double offset)
{
  return smooth_step(offset, normal_field_blend_start, normal_field_blend_end);
}

// The ratio sqrt(lambda_min / lambda_max) of the axes of the 2x2 symmetric moments
// [[m11, m12], [m12, m22]]; 0 if they vanish or are not finite.
inline double axis_ratio(double m11, double m12, double m22)
{
  const double half_trace = 0.5 * (m11 + m22), det = m11 * m22 - m12 * m12;
  const double d = std::sqrt(std::max(0.0, half_trace * half_trace - det));
  const double largest = half_trace + d, least = std::max(0.0, half_trace - d);
  return largest > 0 && std::isfinite(largest) ? std::sqrt(least / largest) : 0.0;
}

// The weight of the normal-field fit for the axis ratio of the tangential spread: 0 from
// normal_field_anisotropy_start up, 1 up to normal_field_anisotropy_end.
inline double normal_field_anisotropy_weight(double ratio)
{
  return smooth_step(ratio, normal_field_anisotropy_start, normal_field_anisotropy_end);
}

// The axis ratio (axis_ratio()) of a neighbourhood's tangential spread, in the tangent plane of
// the query's normal, its moments sum t^(P-1) q q^T weighted as the ASO's gradient moments with
// the kernel (1 - d²/r²)^P (one pass; 0 without a normal). The ASO measures about the same from
// its own sums (with the sample weights, in the plane of its corrected normal); this is for a
// choice made before the ASO runs (automatic_scale.h).
template <int P>
inline double tangential_axis_ratio(const Neighborhood& nb)
{
  const double l = std::sqrt(nb.query_normal[0] * nb.query_normal[0] + nb.query_normal[1] * nb.query_normal[1] +
                             nb.query_normal[2] * nb.query_normal[2]);
  if(!(l > 0))
    return 0;
  const double n[3] = {nb.query_normal[0] / l, nb.query_normal[1] / l, nb.query_normal[2] / l};
  double t1[3], t2[3];
  tangent_basis(n, t1, t2);
  double m11 = 0, m12 = 0, m22 = 0;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double t = 1 - (nb.qx[i] * nb.qx[i] + nb.qy[i] * nb.qy[i] + nb.qz[i] * nb.qz[i]);
    if(!(t > 0))
      continue;
    const double w = power_of<P - 1>(t);
    const double u = nb.qx[i] * t1[0] + nb.qy[i] * t1[1] + nb.qz[i] * t1[2];
    const double v = nb.qx[i] * t2[0] + nb.qy[i] * t2[1] + nb.qz[i] * t2[2];
    m11 += w * u * u;
    m12 += w * u * v;
    m22 += w * v * v;
  }
  return axis_ratio(m11, m12, m22);
}

// The weighted sums of the fit over the neighbours (weight w, tangential position (u, v),
// tangential normal components (a, b) = (n.t1, n.t2)): sum w, sum w u, sum w v, sum w u²,
// sum w u v, sum w v², sum w a, sum w b, sum w a u, sum w a v, sum w b u, sum w b v. The
// ASO's second pass accumulates them (algebraic_shape_operator.h).
struct Normal_field_sums
{
  double w = 0, u = 0, v = 0, uu = 0, uv = 0, vv = 0;
  double a = 0, b = 0, au = 0, av = 0, bu = 0, bv = 0;

  // The symmetric S = [[S[0], S[1]], [S[1], S[2]]] of the fit (in the unit of the positions'
  // inverse). The constant term g0 is eliminated by centring the moments; the normal
  // equations of (s11, s12, s22) are
  //   s11 Cuu + s12 Cuv             = Cau
  //   s11 Cuv + s12 (Cuu + Cvv) + s22 Cuv = Cav + Cbu
  //             s12 Cuv + s22 Cvv   = Cbv
  // with C the centred moments. False if the positions do not spread well in two directions:
  // the ratio of the axes of their weighted spread below 1e-3 (then the slope across is ill
  // conditioned and the ASO is kept alone).
  bool solve(double S[3]) const
  {
    if(!(w > 0))
      return false;
    const double mu = u / w, mv = v / w;
    const double cuu = uu - u * mu, cuv = uv - u * mv, cvv = vv - v * mv;
    const double cau = au - a * mu, cav = av - a * mv, cbu = bu - b * mu, cbv = bv - b * mv;
    // the determinant factors: (Cuu + Cvv) (Cuu Cvv - Cuv²)
    const double spread = cuu * cvv - cuv * cuv, trace = cuu + cvv;
    if(!(spread > 1e-6 * trace * trace) || !std::isfinite(spread))
      return false;
    const double r1 = cau, r2 = cav + cbu, r3 = cbv;
    // Cramer's rule on the 3x3 system above, with its determinant trace * spread
    const double det = trace * spread;
    S[0] = (r1 * (trace * cvv - cuv * cuv) - cuv * (r2 * cvv - cuv * r3)) / det;
    S[1] = (cuu * (r2 * cvv - cuv * r3) - cuv * (r1 * cvv)) / det;
    S[2] = (cuu * (trace * r3 - cuv * r2) - cuv * (cuv * r3) + cuv * (cuv * r1)) / det;
    return std::isfinite(S[0]) && std::isfinite(S[1]) && std::isfinite(S[2]);
  }
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
