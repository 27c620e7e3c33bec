// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the height-field baselines (Point Set Surfaces, Wavejets) share: a weighted
// least-squares fit of a quadratic height field over a reference plane, and the
// curvatures of the fitted graph at the plane's origin.
//
// In an orthonormal frame (t1, t2, n) the surface is the graph w = h(u, v),
//
//   h(u, v) = a0 + a1 u + a2 v + a3 u² + a4 u v + a5 v²,
//
// and it is the zero set of F(y) = n.y - h(t1.y, t2.y), whose gradient points along n:
//
//   grad F = n - a1 t1 - a2 t2,
//   Hess F = -(2 a3 t1 t1ᵀ + a4 (t1 t2ᵀ + t2 t1ᵀ) + 2 a5 t2 t2ᵀ).
//
// The shape operator P Hess F P / |grad F| (set_shape_operator, local_estimate.h) then has
// the package's sign convention when n is oriented like the input normals: the cap
// h = -(u² + v²) / (2R) of a sphere of radius R seen from its outward normal gives 1/R.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_HEIGHT_FIELD_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_HEIGHT_FIELD_H

#include <CGAL/Point_set_curvatures/internal/lane_pair.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/second_order_jet.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Number of coefficients of the quadratic height field, hence the minimal number of
// neighbours (query included) of the fits built on it.
constexpr std::size_t quadratic_height_coefficients = 6;

// The Cholesky factor L (lower triangle) of the normal equations A (upper triangle) of a
// least-squares fit of N monomials. False when a monomial is numerically a combination of the
// previous ones over the samples (collinear, or too few weighted samples): its relative pivot,
// 1 minus the squared multiple correlation of that column with the previous ones, falls below
// `least_pivot`.
template <int N>
bool cholesky_factor(const double (&A)[N][N], double (&L)[N][N], double least_pivot)
{
  for(int j = 0; j < N; ++j)
  {
    double d = A[j][j];
    for(int k = 0; k < j; ++k)
      d -= L[j][k] * L[j][k];
    if(!(A[j][j] > 0) || !(d > least_pivot * A[j][j]) || !std::isfinite(d))
      return false;
    L[j][j] = std::sqrt(d);
    for(int i = j + 1; i < N; ++i)
    {
      double s = A[j][i];
      for(int k = 0; k < j; ++k)
        s -= L[i][k] * L[j][k];
      L[i][j] = s / L[j][j];
    }
  }
  return true;
}

// y = L⁻¹ b for the factor of cholesky_factor().
template <int N>
void forward_substitution(const double (&L)[N][N], const double (&b)[N], double (&y)[N])
{
  for(int i = 0; i < N; ++i)
  {
    double s = b[i];
    for(int k = 0; k < i; ++k)
      s -= L[i][k] * y[k];
    y[i] = s / L[i][i];
  }
}

// Normal equations of the weighted fit, accumulated one sample at a time (constant memory).
struct Quadratic_height_fit
{
  double ata[6][6] = {};  // sum w m mᵀ (upper triangle), m = (1, u, v, u², uv, v²)
  double atb[6] = {};     // sum w m h

  void add(double u, double v, double h, double w)
  {
    const double m[6] = {1.0, u, v, u * u, u * v, v * v};
    for(int i = 0; i < 6; ++i)
    {
      const double wm = w * m[i];
      atb[i] += wm * h;
      for(int j = i; j < 6; ++j)
        ata[i][j] += wm * m[j];
    }
  }

  // Cholesky solve (cholesky_factor() with a least relative pivot of 1e-10: its rounding error
  // is about 1e-16 times the condition number).
  bool solve(double a[6]) const
  {
    double L[6][6] = {};
    if(!cholesky_factor(ata, L, 1e-10))
      return false;
    double y[6];
    forward_substitution(L, atb, y);
    for(int i = 5; i >= 0; --i)
    {
      double s = y[i];
      for(int k = i + 1; k < 6; ++k)
        s -= L[k][i] * a[k];
      a[i] = s / L[i][i];
    }
    for(int i = 0; i < 6; ++i)
      if(!std::isfinite(a[i]))
        return false;
    return true;
  }

  // The larger of the two slopes' (a1, a2) variance factors, the diagonal entries of
  // (sum w m mᵀ)⁻¹ (infinite where solve() fails).
  double slope_variance_factor() const
  {
    double L[6][6] = {};
    if(!cholesky_factor(ata, L, 1e-10))
      return std::numeric_limits<double>::infinity();
    double largest = 0;
    for(int i = 1; i < 3; ++i)
    {
      // (L⁻¹ e_i)ᵀ (L⁻¹ e_i)
      double e[6] = {0, 0, 0, 0, 0, 0}, y[6];
      e[i] = 1;
      forward_substitution(L, e, y);
      double f = 0;
      for(double x : y)
        f += x * x;
      largest = std::max(largest, f);
    }
    return largest;
  }
};

// The same normal equations from the distinct sums they hold: sum w m mᵀ has 21 entries but 15
// distinct monomials w u^a v^b (a + b <= 4), accumulated one sample at a time without the 6 x 6
// products, then spread by fill() (the same sums up to rounding, in about half the operations).
template <class T>
struct Quadratic_sums
{
  // w times 1, u, v, u², uv, v², u³, u²v, uv², v³, u⁴, u³v, u²v², uv³, v⁴: degree d from
  // d (d + 1) / 2, by the power of v
  T s[15] = {};
  T sh[6] = {};  // sum w m h

  void add(T u, T v, T w)
  {
    const T wu = w * u, wv = w * v;
    const T wuu = wu * u, wuv = wu * v, wvv = wv * v;
    const T wuuu = wuu * u, wuuv = wuu * v, wuvv = wuv * v, wvvv = wvv * v;
    s[0] += w;
    s[1] += wu;
    s[2] += wv;
    s[3] += wuu;
    s[4] += wuv;
    s[5] += wvv;
    s[6] += wuuu;
    s[7] += wuuv;
    s[8] += wuvv;
    s[9] += wvvv;
    s[10] += wuuu * u;
    s[11] += wuuu * v;
    s[12] += wuuv * v;
    s[13] += wuvv * v;
    s[14] += wvvv * v;
  }

  void add(T u, T v, T h, T w)
  {
    add(u, v, w);
    const T wh = w * h, wuh = wh * u, wvh = wh * v;
    sh[0] += wh;
    sh[1] += wuh;
    sh[2] += wvh;
    sh[3] += wuh * u;
    sh[4] += wuh * v;
    sh[5] += wvh * v;
  }
};

struct Quadratic_moments : Quadratic_sums<double>
{
  Quadratic_moments() = default;
  // the sums of two lanes (lane_pair.h) added
  explicit Quadratic_moments(const Quadratic_sums<Lane_pair>& pair)
  {
    for(int i = 0; i < 15; ++i)
      s[i] = fold(pair.s[i]);
    for(int i = 0; i < 6; ++i)
      sh[i] = fold(pair.sh[i]);
  }

  // sum w (u² + v²)²
  double fourth() const { return s[10] + 2.0 * s[12] + s[14]; }

  // The upper triangle of sum w m mᵀ, and sum w m h if `atb`.
  void fill(double ata[6][6], double* atb = nullptr) const
  {
    // the powers (of u, of v) of m = (1, u, v, u², uv, v²)
    static constexpr int pu[6] = {0, 1, 0, 2, 1, 0}, pv[6] = {0, 0, 1, 0, 1, 2};
    for(int i = 0; i < 6; ++i)
      for(int j = i; j < 6; ++j)
      {
        const int d = pu[i] + pu[j] + pv[i] + pv[j];
        ata[i][j] = s[d * (d + 1) / 2 + pv[i] + pv[j]];
      }
    if(atb)
      for(int i = 0; i < 6; ++i)
        atb[i] = sh[i];
  }
};

// The weighted least-squares cubic height field (the quadratic's six monomials, then u³, u²v,
// uv², v³), accumulated one sample at a time, for its residual variance: what is left of a
// quadric's residuals once the third-order terms are fitted too (the second test of the automatic
// scale's first pass, automatic_scale.h); and for its slope, the normal where that pass keeps
// the first rung as clean (cubic_normal(), estimate_oriented_normals.h).
struct Cubic_height_fit
{
  // Two lanes (lane_pair.h; add() takes two neighbours, a weight of 0 for none): w u^a v^b for
  // a + b <= 6 (degree d from d (d + 1) / 2, by the power of v: the 55 entries of sum w m mᵀ
  // hold 28 distinct monomials), sum w m h, sum w h², sum w².
  Lane_pair s[28] = {};
  Lane_pair sh[10] = {};
  Lane_pair shh = {}, sw2 = {};

  void add(Lane_pair u, Lane_pair v, Lane_pair h, Lane_pair w)
  {
    Lane_pair wu[7], vp[7];  // w u^a, v^b
    wu[0] = w;
    vp[0] = broadcast(1.0);
    for(int a = 1; a < 7; ++a)
    {
      wu[a] = wu[a - 1] * u;
      vp[a] = vp[a - 1] * v;
    }
    for(int d = 0, k = 0; d < 7; ++d)
      for(int b = 0; b <= d; ++b, ++k)
        s[k] += b == 0 ? wu[d] : wu[d - b] * vp[b];
    // sum w m h: w u^a v^b h for a + b <= 3, as s's first 10
    const Lane_pair wh = w * h;
    const Lane_pair uu = u * u;
    const Lane_pair m[10] = {broadcast(1.0), u, v, uu, u * v, vp[2], uu * u, uu * v, u * vp[2], vp[3]};
    for(int i = 0; i < 10; ++i)
      sh[i] += wh * m[i];
    shh += wh * h;
    sw2 += w * w;
  }

  // One neighbour.
  void add(double u, double v, double h, double w) { add(lanes(u, 0), lanes(v, 0), lanes(h, 0), lanes(w, 0)); }

  // The weighted mean squared residual times n_eff / (n_eff - 10), n_eff = (sum w)² / sum w²
  // (as Quadric_fit::variance_factors() gives the quadric's with 6); the residuals' sum of squares
  // is sum w h² less |L⁻¹ atb|² (rounding: about 1e-16 of sum w h², far below any noise where the
  // heights are measured from a point of the neighbourhood). False where n_eff <= 10.5, or where a
  // monomial's relative pivot (cholesky_factor()) is below `least_pivot`.
  bool residual_variance(double least_pivot, double& sigma2) const
  {
    double L[10][10], y[10], n_eff;
    if(!factor(least_pivot, L, y, n_eff))
      return false;
    double fitted = 0;
    for(double x : y)
      fitted += x * x;
    sigma2 = std::max(0.0, fold(shh) - fitted) / fold(s[0]) * n_eff / (n_eff - 10.0);
    return std::isfinite(sigma2);
  }

  // The coefficients of h = a0 + a1 u + a2 v + a3 u² + a4 u v + a5 v² + a6 u³ + a7 u² v + a8 u v²
  // + a9 v³, under the conditions of residual_variance(), and the ratio of its residual variance
  // to the quadratic's over the same points and weights (`share`: near 0 where the quadratic's
  // residuals are the surface's third-order terms, about 1 where they are noise).
  bool solve(double least_pivot, double a[10], double& share) const
  {
    double L[10][10], y[10], n_eff;
    if(!factor(least_pivot, L, y, n_eff))
      return false;
    // (the quadratic's monomials come first: its fit is the first 6 of y)
    double quadratic = fold(shh);
    for(int i = 0; i < 6; ++i)
      quadratic -= y[i] * y[i];
    double cubic = quadratic;
    for(int i = 6; i < 10; ++i)
      cubic -= y[i] * y[i];
    // (NaN where the quadratic fits exactly; where it nearly does, a ratio of rounding errors, but
    // then both slopes are exact)
    share = std::max(0.0, cubic) / (n_eff - 10.0) / (std::max(0.0, quadratic) / (n_eff - 6.0));
    for(int i = 9; i >= 0; --i)  // Lᵀ a = y
    {
      double x = y[i];
      for(int k = i + 1; k < 10; ++k)
        x -= L[k][i] * a[k];
      a[i] = x / L[i][i];
      if(!std::isfinite(a[i]))
        return false;
    }
    return true;
  }

private:
  // The Cholesky factor L of the normal equations, y = L⁻¹ atb and n_eff (residual_variance()).
  bool factor(double least_pivot, double (&L)[10][10], double (&y)[10], double& n_eff) const
  {
    const double sw = fold(s[0]), sum_w2 = fold(sw2);
    n_eff = sum_w2 > 0 ? sw * sw / sum_w2 : 0.0;
    // the normal equations: entry (i, j) is the monomial of the summed powers
    static constexpr int pu[10] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0}, pv[10] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3};
    double ata[10][10] = {}, atb[10];
    for(int i = 0; i < 10; ++i)
    {
      for(int j = i; j < 10; ++j)
      {
        const int d = pu[i] + pu[j] + pv[i] + pv[j];
        ata[i][j] = fold(s[d * (d + 1) / 2 + pv[i] + pv[j]]);
      }
      atb[i] = fold(sh[i]);
    }
    for(auto& row : L)
      std::fill(row, row + 10, 0.0);
    if(!(n_eff > 10.5) || !cholesky_factor(ata, L, least_pivot))
      return false;
    forward_substitution(L, atb, y);
    return true;
  }
};

// The gradient and Hessian (packed xx xy xz yy yz zz) of F(y) = n.y - h(t1.y, t2.y) at
// u = v = 0, for the graph of h (coefficients `a`) over the frame (t1, t2, n).
inline void height_field_gradient_hessian(const double a[6], const double t1[3], const double t2[3], const double n[3],
                                          double gradient[3], double hessian[6])
{
  for(int i = 0; i < 3; ++i)
    gradient[i] = n[i] - a[1] * t1[i] - a[2] * t2[i];
  for(int i = 0; i < 3; ++i)
    for(int j = i; j < 3; ++j)
      hessian[sym_index(i, j)] =
        -(2.0 * a[3] * t1[i] * t1[j] + a[4] * (t1[i] * t2[j] + t2[i] * t1[j]) + 2.0 * a[5] * t2[i] * t2[j]);
}

// Normal, principal curvatures and directions of the graph of h (coefficients `a`) over
// the frame (t1, t2, n) at u = v = 0, in 1/length with `inverse_length_unit` = 1/r for
// coefficients fitted in the scaled frame. Returns false if the result is not finite.
inline bool set_height_field_curvatures(const double a[6], const double t1[3], const double t2[3], const double n[3],
                                        double inverse_length_unit, Local_estimate& e)
{
  double gradient[3], hessian[6];
  height_field_gradient_hessian(a, t1, t2, n, gradient, hessian);
  return set_shape_operator(gradient, hessian, inverse_length_unit, e);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
