// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the algebraic sphere of the APSS fit measures besides a normal and a mean curvature
// (Sections 4.2, 4.4 and 4.5 of Lejemble et al. 2021): Pratt-normalised coefficients
// (Equation 6), the anisotropy 1 - p (Proposition 1), the algebraic distance u_c (Theorem 1),
// the GLS geometric variation v (Equation 18, Mellado et al. 2012) with its derivatives with
// respect to the scale r taken analytically through the kernel, the projection onto the
// fitted sphere (Equation 20), and the multi-scale form of all of it.
//
// Frames and units. Everything here is computed in the scaled centred frame of weight_kernel.h
// (q = (p - x) / r, |q| < 1); the conversion to input units is done by the caller:
//   u_c(input) = r u_c,  u_l(input) = u_l,  u_q(input) = u_q / r,
// and the Pratt norm p = sqrt(|u_l|^2 - 4 u_c u_q) is the same in both frames.
//
// Scale derivatives. Write delta = r d/dr, at fixed neighbours and fixed evaluation point
// (the smooth kernel; the constant kernel's derivative is a boundary term, see below).
// The input-unit sums Sbar_j = r^k_j s_j (k = 0, 1, 0, 1, 2 for A, B, C, D, E) have
// delta Sbar_j = r^k_j ds_j with ds_j the same sums in the scaled frame with the weight w
// replaced by r dw/dr (for the smooth kernel w = (1-s)^2, s = |q|^2: r dw/dr = 4 s (1 - s)).
// Every fitted quantity X(input) = r^k X(scaled) is a homogeneous function of the sums, so
// delta X(input) = r^k dX, with dX the directional derivative of the scaled formulas along
// (ds_j). Hence the three terms of Equation 18 are scale-free and computed in the scaled
// frame:  d u_c / dr = d(u_c/p),  r d n/dr = d(u_l/|u_l|),  r^2 dH/dr = d(2 u_q / p).
//
// Scale derivative of the constant kernel. w = 1 for s < 1 gives r dw/dr = 2 delta(s - 1):
// in the continuum, the derivative of a constant-kernel sum is a boundary integral over the
// sphere of radius r. On samples it does not exist (every sum is a step function of r, with
// zero derivative between the radii where neighbours enter). What it stands for is the
// boundary value 2 Phi(1) of Phi(s), the density at s of the sampled integrand (the
// contributions g_j of the points at squared scaled distance s). For a density uniform in
// the tangent plane, s is uniform on [0, 1] up to a factor 1 + O(r^2 s) (the ball is 3-D),
// and Phi is smooth, with a Taylor expansion whose s^k term is of order r^2k relative to the
// first. A weight phi with
//   int_0^1 phi(s) s^k ds = 1 for k = 0, 1, 2
// turns sum_i 2 phi(s_i) g_j(i) into 2 Phi(1), exactly for Phi of degree <= 2; degree 2 is
// the least that reaches the leading term of all three derivatives of Equation 18 (u_c and H
// need the s^2 part of Phi). Among such weights, the package takes
//   phi(s) = (1 - s)(12 - 120 s + 180 s^2),  r dw/dr := 2 phi(s) = 24 - 264 s + 600 s^2 - 360 s^3,
// which vanishes at s = 1: a neighbour entering the ball enters with weight 0, as with the
// smooth kernel. The weight of least variance under i.i.d. sampling, the reproducing kernel
// psi_2(s) = 30 s^2 - 24 s + 3 (2 psi_2(1) = 18), jumps at s = 1, and the sums then move
// with every point crossing the boundary: at 40 positions between the samples of a regular
// lattice (paraboloid of the tests, r = 0.05, spacing r/100) v / law has a standard deviation
// of 0.076 with psi_2 and 0.011 with phi; on goursat_050000.xyz at r = 1 its median is 3.2
// with psi_2 and 1.9 with phi (1.3 with the smooth kernel); under i.i.d. sampling both are
// equally noisy. Neighbourhoods by count, whose k-th neighbour sits at s = 1, give it no
// weight either.
// Accuracy of the continuum limit, against the true derivative of the continuum sums (2-D
// Gauss quadrature of the paraboloid over the 3-D ball, central difference in r): relative
// error of r dn/dr 3.9e-5 / 2.4e-6 at r = 0.1 / 0.05 (O(r^4)), of du_c/dr and r^2 dH/dr
// 9.6e-3 / 2.6e-3 (O(r^2)); a weight exact for degree 1 only leaves du_c/dr and dH/dr at
// about 0.6 and 0.4 of the truth. The same holds with a density per unit surface area and
// with any density smooth at the scale r (it is part of Phi). On samples, the derivative of
// either kernel carries the sampling noise of its sums; the boundary term is the more
// exposed (it estimates a density at the boundary from the inside), so prefer the smooth
// kernel for v on irregular scans.
//
// Asymptotic laws (surface in its principal frame at the evaluation point, normal n,
// height h(x, y) along n with derivatives a_ij; curvatures with this package's sign,
// positive where the surface bends away from n: k1 = -a_20, k2 = -a_02, H = (k1 + k2)/2,
// K = k1 k2, grad H = -((a_30 + a_12)/2, (a_03 + a_21)/2), "Delta H" = -(a_40 + 2 a_22 +
// a_04)/2, half the bilaplacian of the height as in the paper). Derived for a sampling of
// uniform density per unit area, with the weight of the true 3-D distance over the ball
// (the paper's Section 4.1 framework); the integrals over the disc use the moments of
// (1 - rho^2)^m, the derivation (exact rational arithmetic) gave:
//
//                                     constant kernel (paper)      smooth kernel (1-rho^2)^2
//   1 - p        (Proposition 1)      (k1 - k2)^2 r^2 / 16         (k1 - k2)^2 r^2 / 32
//   n_tilde - n  (Equation 15)        -grad H r^2 / 4 (*)          -grad H r^2 / 8 (*)
//   v            (Proposition 2)      |grad H|^2 r^4 / 4           |grad H|^2 r^4 / 16
//   u_c (input)  (Theorem 1)          (9H^3 - 5KH - Delta H) r^4/96   (19H^3 - 11KH - 2 Delta H) r^4/640
//   H_tilde = 2 u_q                   H + O(r^2)                   H + O(r^2)
//   (*) tangential part, up to the sign convention of grad H (the paper's is the opposite).
//
// Theorem 1 of the paper reads -(9H^3 - 5KH - Delta H) r^4 / 96 with its opposite curvature
// sign (H > 0 where the surface bends towards n); both laws vanish on a sphere, where Delta H as
// defined above is 4 H^3 (it is not the Laplace-Beltrami of H). The smooth-kernel law of v
// follows from its normal law exactly as Proposition 2 does: v = |r dn/dr|^2 + O(r^6).
//
// The derivation expands the sums of Equations 2-4 in powers of r to order 5 (height field to
// order 4, area element, normals, weight of the 3-D distance over the ball; for the constant
// kernel the boundary of the ball to first order in z^2/r^2), with the exact moments
// int_disc x^2i y^2j (1 - rho^2)^m, then Equations 2-4, 6 as truncated series. The area element
// does not change any leading term above: sampling uniformly in the tangent plane is enough.
// The tests measure every law on sampled surfaces.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_ALGEBRAIC_SPHERE_FEATURES_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_ALGEBRAIC_SPHERE_FEATURES_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/weight_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The kernels as polynomials of s = |q|^2 (scaled frame), w = sum_j c_j s^j, with their scale
// derivative r dw/dr = sum_j dc_j s^j (degree <= kernel_degree): what the multi-scale
// moments need. Degree 4: the kernel (1 - s)^4 and its derivative 8 s (1 - s)^3.
constexpr int kernel_degree = 4;
typedef std::array<double, kernel_degree + 1> Kernel_coefficients;

template <class WeightKernel>
struct Kernel_polynomial;

// The binomial coefficient C(n, k), for the expansion of (1 - s)^P.
constexpr double binomial(int n, int k)
{
  double c = 1;
  for(int j = 0; j < k; ++j)
    c = c * double(n - j) / double(j + 1);
  return c;
}

// w = (1 - s)^P = sum_j C(P, j) (-s)^j;
// r dw/dr = -2 s dw/ds = 2 P s (1 - s)^(P-1) = sum_j 2 P C(P-1, j) (-1)^j s^(j+1).
// For P = 2: 1 - 2 s + s^2 and 4 s - 4 s^2.
template <int P>
constexpr Kernel_coefficients power_kernel_weight()
{
  Kernel_coefficients c{};
  for(int j = 0; j <= P; ++j)
    c[j] = (j % 2 ? -1.0 : 1.0) * binomial(P, j);
  return c;
}
template <int P>
constexpr Kernel_coefficients power_kernel_scale_derivative()
{
  Kernel_coefficients c{};
  for(int j = 0; j <= P - 1; ++j)
    c[j + 1] = 2.0 * P * (j % 2 ? -1.0 : 1.0) * binomial(P - 1, j);
  return c;
}

template <int P>
struct Kernel_polynomial<Power_kernel<P> >
{
  static_assert(P <= kernel_degree, "raise kernel_degree for this kernel");
  static constexpr int degree = P;  // of the weight and of its scale derivative
  static constexpr Kernel_coefficients weight = power_kernel_weight<P>();
  static constexpr Kernel_coefficients scale_derivative = power_kernel_scale_derivative<P>();
};

template <>
struct Kernel_polynomial<Constant_kernel>
{
  // w = 1;  r dw/dr = 2 delta(s - 1), estimated by 2 phi(s) = 2 (1 - s)(12 - 120 s + 180 s^2)
  // = 24 - 264 s + 600 s^2 - 360 s^3 (see the header comment)
  static constexpr int degree = 3;  // of the scale derivative
  static constexpr Kernel_coefficients weight = {1.0, 0.0, 0.0, 0.0, 0.0};
  static constexpr Kernel_coefficients scale_derivative = {24.0, -264.0, 600.0, -360.0, 0.0};
};

// r dw/dr of the kernel at s (Horner).
template <class WeightKernel>
double r_dw_dr(double s)
{
  const double* c = Kernel_polynomial<WeightKernel>::scale_derivative.data();
  double value = c[kernel_degree];
  for(int j = kernel_degree - 1; j >= 0; --j)
    value = c[j] + s * value;
  return value;
}

// The five sums of Equations 2-4 without the weight type (for their scale derivatives).
struct Sphere_sums
{
  double A = 0, B[3] = {0, 0, 0}, C[3] = {0, 0, 0}, D = 0, E = 0;
};

// Scale derivative sums of a neighbourhood: the sums of Equations 2-4 with w replaced by
// r dw/dr (same scaled frame).
template <class WeightKernel>
Sphere_sums scale_derivative_sums(const Neighborhood& nb)
{
  double a = 0, b0 = 0, b1 = 0, b2 = 0, c0 = 0, c1 = 0, c2 = 0, d = 0, e = 0;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double qx = nb.qx[i], qy = nb.qy[i], qz = nb.qz[i];
    const double nx = nb.nx[i], ny = nb.ny[i], nz = nb.nz[i];
    const double s = qx * qx + qy * qy + qz * qz;
    double w = r_dw_dr<WeightKernel>(s);
    if(nb.sample_weight)
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
  }
  Sphere_sums ds;
  ds.A = a;
  ds.B[0] = b0;
  ds.B[1] = b1;
  ds.B[2] = b2;
  ds.C[0] = c0;
  ds.C[1] = c1;
  ds.C[2] = c2;
  ds.D = d;
  ds.E = e;
  return ds;
}

// Everything the features need, in the scaled frame of one evaluation point.
struct Local_sphere_features
{
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;
  std::size_t neighbor_count = 0;
  double radius = nan;      // r, input units
  Algebraic_sphere sphere;  // unnormalised coefficients and Pratt norm, scaled frame
  // delta = r d/dr of the Pratt-normalised u_c, of the unit normal and of 2 u_q / p, all in
  // the scaled frame (see the header comment).
  double d_u_c = nan, d_normal[3] = {nan, nan, nan}, d_mean = nan;
  double geometric_variation = nan;  // Equation 18, dimensionless

  bool is_valid() const { return status == Curvature_estimate_status::VALID; }
};

// Features of the sphere fitted to sums `s`, with scale derivative sums `ds`; TOO_FEW_NEIGHBORS
// below `min_count` neighbours (never below the fit's own minimum).
template <class WeightKernel>
Local_sphere_features sphere_features(const Algebraic_sphere_sums<WeightKernel>& s, const Sphere_sums& ds,
                                      double radius, std::size_t min_count = apss_min_neighbors)
{
  Local_sphere_features f;
  f.neighbor_count = s.count;
  f.radius = radius;
  if(s.count < apss_min_neighbors || s.count < min_count)
  {
    f.status = Curvature_estimate_status::TOO_FEW_NEIGHBORS;
    return f;
  }
  f.sphere = fit_algebraic_sphere(s);
  if(!f.sphere.valid)
  {
    f.status = Curvature_estimate_status::DEGENERATE_FIT;
    return f;
  }
  f.status = Curvature_estimate_status::VALID;

  // Directional derivative of Equations 2-4 and of the Pratt norm along ds.
  const Algebraic_sphere& sp = f.sphere;
  const double uq = sp.u_q, uc = sp.u_c, p = sp.pratt_norm;
  const double* ul = sp.u_l;
  auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double den = s.A * s.E - dot(s.B, s.B);
  const double d_den = ds.A * s.E + s.A * ds.E - 2.0 * dot(s.B, ds.B);
  const double d_num = ds.A * s.D + s.A * ds.D - dot(ds.B, s.C) - dot(s.B, ds.C);
  const double d_uq = (d_num - 2.0 * uq * d_den) / (2.0 * den);
  double d_ul[3];
  for(int i = 0; i < 3; ++i)
    d_ul[i] = (ds.C[i] - 2.0 * (d_uq * s.B[i] + uq * ds.B[i]) - ul[i] * ds.A) / s.A;
  const double d_uc = -(dot(d_ul, s.B) + dot(ul, ds.B) + d_uq * s.E + uq * ds.E + uc * ds.A) / s.A;
  const double d_p = (dot(ul, d_ul) - 2.0 * (d_uc * uq + uc * d_uq)) / p;

  f.d_u_c = (d_uc - uc * d_p / p) / p;
  f.d_mean = 2.0 * (d_uq - uq * d_p / p) / p;
  const double l = std::sqrt(dot(ul, ul));
  const double n[3] = {ul[0] / l, ul[1] / l, ul[2] / l};
  const double n_dul = dot(n, d_ul);
  for(int i = 0; i < 3; ++i)
    f.d_normal[i] = (d_ul[i] - n[i] * n_dul) / l;
  f.geometric_variation = f.d_u_c * f.d_u_c + dot(f.d_normal, f.d_normal) + f.d_mean * f.d_mean;
  return f;
}

// Single scale: the whole neighbourhood at its radius. The sums are those of the APSS
// estimator (same code), so normal and mean curvature agree with it exactly.
template <class WeightKernel>
Local_sphere_features sphere_features(const Neighborhood& nb, std::size_t min_count = apss_min_neighbors)
{
  Algebraic_sphere_sums<WeightKernel> sums;
  sums.add(nb);
  return sphere_features(sums, scale_derivative_sums<WeightKernel>(nb), nb.radius, min_count);
}

// Projection of the point x (scaled frame) onto the fitted sphere, Equation 20. With
// g = grad f(x) = u_l + 2 u_q x, the identity |g|^2 - p^2 = 4 u_q f(x) turns
//   x - (|g| - p) / (2 u_q |g|) g          (u_q != 0)
// into x - 2 f(x) / (|g| (|g| + p)) g, which needs no division by u_q, is exact for the plane
// u_q = 0 (where |g| = p and it is x - f g / |g|^2) and continuous in between. `normal` gets
// the unit normal of the sphere at the projection, g / |g| (same ray from the centre).
// Returns false if x is the centre of the sphere (every point of it is then closest).
inline bool project_on_sphere(const Algebraic_sphere& s, const double x[3], double projected[3], double normal[3])
{
  const double f =
    s.u_c + s.u_l[0] * x[0] + s.u_l[1] * x[1] + s.u_l[2] * x[2] + s.u_q * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  double g[3];
  for(int i = 0; i < 3; ++i)
    g[i] = s.u_l[i] + 2.0 * s.u_q * x[i];
  const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if(!(gn > 1e-12 * s.pratt_norm) || !std::isfinite(gn))
    return false;
  const double k = 2.0 * f / (gn * (gn + s.pratt_norm));
  for(int i = 0; i < 3; ++i)
  {
    projected[i] = x[i] - k * g[i];
    normal[i] = g[i] / gn;
  }
  return true;
}

// Multi-scale features: one neighbourhood gathered at the largest radius R, the features at
// every radius r_k <= R of a list. With lambda = R / r_k and sigma = |q|^2 in the frame of R,
// the kernel is a polynomial of lambda^2 sigma, so every sum at r_k is a combination of the
// moments sum sigma^j g (j <= kernel_degree) over the neighbours at distance < r_k. The neighbours are
// bucketed once by distance into the intervals between consecutive radii (a bucket sort:
// all the prefix sums need), the moments accumulated per bucket and summed over the prefix:
// one pass over the neighbourhood, O(n + number of radii), whatever the number of radii.
// Numerically the combination costs about one digit against the direct sums of the
// single-scale path (measured in the tests).
class Multiscale_sphere_features
{
public:
  // Sets the radii (positive, finite, any order, duplicates allowed) and returns the largest.
  double set_radii(const std::vector<double>& radii)
  {
    m_order.resize(radii.size());
    for(std::size_t k = 0; k < radii.size(); ++k)
      m_order[k] = k;
    std::stable_sort(m_order.begin(), m_order.end(), [&](std::size_t a, std::size_t b) { return radii[a] < radii[b]; });
    m_radii = radii;
    m_max_radius = radii.empty() ? 0.0 : radii[m_order.back()];
    m_bound.resize(radii.size());
    for(std::size_t j = 0; j < radii.size(); ++j)
    {
      // neighbours with sigma < bound_j are inside radius r_(j)
      const double t = radii[m_order[j]] / m_max_radius;
      m_bound[j] = t * t;
    }
    return m_max_radius;
  }

  // Features at every radius of one neighbourhood gathered at the largest radius
  // (nb.radius == the value returned by set_radii); out[k] for radii[k]. Not thread-safe
  // (scratch buckets): one object per thread.
  template <class WeightKernel>
  void compute(const Neighborhood& nb, Local_sphere_features* out, std::size_t min_count = apss_min_neighbors)
  {
    // the moments up to the kernel's own degree (the coefficients above it are 0)
    constexpr int degree = Kernel_polynomial<WeightKernel>::degree;
    const std::size_t n_radii = m_radii.size();
    m_buckets.assign(n_radii, Moments());
    for(std::size_t i = 0; i < nb.size; ++i)
    {
      const double qx = nb.qx[i], qy = nb.qy[i], qz = nb.qz[i];
      const double nx = nb.nx[i], ny = nb.ny[i], nz = nb.nz[i];
      const double s1 = qx * qx + qy * qy + qz * qz;
      // first radius whose ball holds the neighbour
      const std::size_t j = std::upper_bound(m_bound.begin(), m_bound.end(), s1) - m_bound.begin();
      if(j == n_radii)
        continue;  // at distance >= R up to rounding: outside every ball
      double s[degree + 2] = {1.0};
      for(int k = 1; k < degree + 2; ++k)
        s[k] = s[k - 1] * s1;
      const double qn = qx * nx + qy * ny + qz * nz;
      Moments& m = m_buckets[j];
      ++m.count;
      m.QQ[0] += qx * qx;
      m.QQ[1] += qx * qy;
      m.QQ[2] += qx * qz;
      m.QQ[3] += qy * qy;
      m.QQ[4] += qy * qz;
      m.QQ[5] += qz * qz;
      for(int k = 0; k <= degree; ++k)
      {
        m.P[k] += s[k];
        m.Q[0][k] += s[k] * qx;
        m.Q[1][k] += s[k] * qy;
        m.Q[2][k] += s[k] * qz;
        m.N[0][k] += s[k] * nx;
        m.N[1][k] += s[k] * ny;
        m.N[2][k] += s[k] * nz;
        m.QN[k] += s[k] * qn;
      }
      m.P[degree + 1] += s[degree + 1];
    }

    Moments prefix;
    for(std::size_t j = 0; j < n_radii; ++j)
    {
      prefix += m_buckets[j];
      const std::size_t k = m_order[j];
      const double radius = m_radii[k];
      const double lambda = m_max_radius / radius;
      typedef Kernel_polynomial<WeightKernel> Poly;
      Algebraic_sphere_sums<WeightKernel> sums;
      sums.count = prefix.count;
      // unweighted: only its rank matters (fit_algebraic_sphere's tangent spread test)
      std::copy(prefix.QQ, prefix.QQ + 6, sums.qq);
      Sphere_sums ds;
      combine(prefix, lambda, degree, Poly::weight.data(), sums.A, sums.B, sums.C, sums.D, sums.E);
      combine(prefix, lambda, degree, Poly::scale_derivative.data(), ds.A, ds.B, ds.C, ds.D, ds.E);
      out[k] = sphere_features(sums, ds, radius, min_count);
    }
  }

private:
  // sum over a set of neighbours of sigma^j times 1 (j <= kernel_degree + 1, for E), q, n,
  // q.n (j <= kernel_degree); and of q q^T
  struct Moments
  {
    std::size_t count = 0;
    double QQ[6] = {};
    double P[kernel_degree + 2] = {};
    double Q[3][kernel_degree + 1] = {};
    double N[3][kernel_degree + 1] = {};
    double QN[kernel_degree + 1] = {};

    Moments& operator+=(const Moments& o)
    {
      count += o.count;
      for(int k = 0; k < 6; ++k)
        QQ[k] += o.QQ[k];
      for(int k = 0; k < kernel_degree + 2; ++k)
        P[k] += o.P[k];
      for(int k = 0; k <= kernel_degree; ++k)
      {
        for(int a = 0; a < 3; ++a)
        {
          Q[a][k] += o.Q[a][k];
          N[a][k] += o.N[a][k];
        }
        QN[k] += o.QN[k];
      }
      return *this;
    }
  };

  // Sums of Equations 2-4 at the radius R / lambda for the weight sum_{j <= degree} c_j s^j
  // with s = lambda^2 sigma, in the frame of that radius (q_k = lambda q).
  static void combine(const Moments& m, double lambda, int degree, const double c[kernel_degree + 1], double& A,
                      double B[3], double C[3], double& D, double& E)
  {
    const double l2 = lambda * lambda;
    double w[kernel_degree + 1];
    double power = 1;  // l2^j
    for(int j = 0; j <= degree; ++j, power *= l2)
      w[j] = c[j] * power;
    A = E = D = 0;
    for(int a = 0; a < 3; ++a)
      B[a] = C[a] = 0;
    for(int j = 0; j <= degree; ++j)
    {
      A += w[j] * m.P[j];
      E += w[j] * m.P[j + 1];
      for(int a = 0; a < 3; ++a)
      {
        B[a] += w[j] * m.Q[a][j];
        C[a] += w[j] * m.N[a][j];
      }
      D += w[j] * m.QN[j];
    }
    E *= l2;
    for(int a = 0; a < 3; ++a)
      B[a] *= lambda;
    D *= lambda;
  }

  std::vector<double> m_radii;
  std::vector<std::size_t> m_order;  // radii indices by increasing radius
  std::vector<double> m_bound;       // (r_(j) / R)^2 in that order
  double m_max_radius = 0;
  std::vector<Moments> m_buckets;
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
