// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What every per-point estimator receives (a neighbourhood in the query's scaled,
// centred frame) and returns (a double-precision estimate), plus the last step they
// share: principal curvatures and directions of a symmetric tensor restricted to the
// tangent plane.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_LOCAL_ESTIMATE_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_LOCAL_ESTIMATE_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The measured least neighbour counts (public: parameters.h), under their former name.
namespace default_min_neighbors = CGAL::Point_set_curvatures::default_min_neighbors;

struct Quadric_fit;  // (quadric_fit.h)

// The neighbours of one query point. Coordinates are centred at the query point and
// divided by the radius (q = (p - x) / r, so |q| < 1), which keeps every sum of the
// fits of order one whatever the units and the distance to the origin (LiDAR data sits
// near 1e6). Arrays are structure-of-arrays so the accumulation loops stream through them.
struct Neighborhood
{
  std::size_t size = 0;
  const double* qx = nullptr;
  const double* qy = nullptr;
  const double* qz = nullptr;
  const double* nx = nullptr;
  const double* ny = nullptr;
  const double* nz = nullptr;
  double radius = 1;             // r, to convert curvatures back to input units
  double center[3] = {0, 0, 0};  // x, absolute coordinates of the evaluation point
  double query_normal[3] = {0, 0, 0};
  // Which input points the neighbours are, when the cloud drivers gather them (else null):
  // neighbour i is element input_index[index[i]] of the input range. For estimators that
  // need the neighbourhood graph (normal orientation).
  const std::uint32_t* index = nullptr;
  const std::uint32_t* input_index = nullptr;
  // With `index`, where the cloud drivers gather the neighbours: the cloud's positions, neighbour
  // i at position + 3 index[i] (absolute coordinates, as `center`), from which the automatic
  // scale takes its rungs as the driver takes a neighbourhood (automatic_scale.h); else null.
  const double* position = nullptr;
  // The query's position in the input range, where the cloud drivers gather the neighbourhood.
  std::size_t query_index = 0;
  // Per-neighbour sample weights (quadrature weights such as tangent Voronoi areas), or null
  // for equal weights: the estimators that support them multiply each neighbour's kernel
  // weight by it.
  const double* sample_weight = nullptr;
  // Where the automatic scale fitted these positions with the plain quadric of its rungs
  // (automatic_scale.h), that fit, which an estimator needing the same quadric with its penalty
  // refits without a pass over the points (Quadric_fit::refit_with_penalty()); else null.
  const Quadric_fit* plain_quadric = nullptr;
};

// The reference orientation of the estimators' robust orientation (ASO, APSS) from the
// weighted sum of the neighbourhood's normals (`sum`, the fits' sum C, weighted like the fit so
// that the majority decides and the query's own normal is one vote): the sum itself, or the
// query's normal when the normals cancel out.
inline void orientation_reference(const double sum[3], const double query_normal[3], double ref[3])
{
  const double mm = sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2];
  const bool use_sum = mm > 1e-24 && std::isfinite(mm);
  for(int a = 0; a < 3; ++a)
    ref[a] = use_sum ? sum[a] : query_normal[a];
}

// True if the normal of some neighbour disagrees with `ref` (negative dot product): only then
// does the robust orientation flip anything. No kernel weight is needed, so this test is much
// cheaper than a pass of the fit.
inline bool has_disagreeing_normal(const Neighborhood& nb, const double ref[3])
{
  bool any = false;
  for(std::size_t i = 0; i < nb.size; ++i)
    any |= nb.nx[i] * ref[0] + nb.ny[i] * ref[1] + nb.nz[i] * ref[2] < 0;
  return any;
}

// Sets `ref` to the reference orientation (orientation_reference() of the weighted sum of the
// normals). Returns false if the neighbourhood holds two sheets rather than flipped normals of
// one: the neighbours whose normals oppose the query's (negative dot product) carry at least
// 10% of the weight; both groups' normals are coherent (the length of each group's weighted
// mean unit normal at least 0.7) and opposite (the cosine of the two means below -0.7); and
// along the axis between the two mean normals, the groups' weighted mean offsets differ by
// more than 0.05 r and by more than twice the offsets' spread (weighted standard deviation)
// within either group. Flipped normals of one sheet sample the same disk (the same mean
// offset, up to noise); the two sides of a thin plate, or two walls closer than r, are two
// tight layers offset by their distance. Foliage, whose normals point anywhere and whose
// points fill a volume, is one noisy surface: its estimate is given (with a low
// normal_coherence). The groups are split by the query's normal, not by the majority, which
// two sheets of equal weight leave undetermined.
template <class Kernel>
inline bool majority_orientation(const Neighborhood& nb, double ref[3])
{
  const double* up = nb.query_normal;
  const auto weight = [&nb](std::size_t i) {
    const double q2 = nb.qx[i] * nb.qx[i] + nb.qy[i] * nb.qy[i] + nb.qz[i] * nb.qz[i];
    const double w = Kernel::weight(1.0 - q2);
    return nb.sample_weight ? w * nb.sample_weight[i] : w;
  };
  const auto group = [&nb, up](std::size_t i) {
    return nb.nx[i] * up[0] + nb.ny[i] * up[1] + nb.nz[i] * up[2] < 0 ? 1 : 0;
  };
  // first the weighted sum of the normals and each group's weight (0: with the query's normal,
  // 1: against it), with a register each: the groups' moments only where both weigh (most
  // neighbourhoods have one group: a pass without them is several times cheaper)
  double m[3] = {0, 0, 0};  // sum w n
  double w0 = 0, w1 = 0;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double w = weight(i);
    m[0] += w * nb.nx[i];
    m[1] += w * nb.ny[i];
    m[2] += w * nb.nz[i];
    // (adding 0 leaves a sum as it is: each group's sum is the one of its points, in order)
    const bool against = group(i) == 1;
    w0 += against ? 0.0 : w;
    w1 += against ? w : 0.0;
  }
  const double W[2] = {w0, w1};
  orientation_reference(m, nb.query_normal, ref);
  if(!(W[1] > 0.1 * (W[0] + W[1])) || !(W[0] > 0.1 * (W[0] + W[1])))
    return true;
  // per group: sum w n / |n|, sum w q, sum w q qᵀ
  double N[2][3] = {}, Q[2][3] = {}, QQ[2][6] = {};
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double q[3] = {nb.qx[i], nb.qy[i], nb.qz[i]};
    const double w = weight(i);
    const double n[3] = {nb.nx[i], nb.ny[i], nb.nz[i]};
    const int g = group(i);
    const double l2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const double inv = l2 > 0 ? 1.0 / std::sqrt(l2) : 0.0;
    for(int a = 0; a < 3; ++a)
    {
      N[g][a] += w * n[a] * inv;
      Q[g][a] += w * q[a];
    }
    QQ[g][0] += w * q[0] * q[0];
    QQ[g][1] += w * q[0] * q[1];
    QQ[g][2] += w * q[0] * q[2];
    QQ[g][3] += w * q[1] * q[1];
    QQ[g][4] += w * q[1] * q[2];
    QQ[g][5] += w * q[2] * q[2];
  }
  double mean[2][3], length[2];
  for(int g = 0; g < 2; ++g)
  {
    for(int a = 0; a < 3; ++a)
      mean[g][a] = N[g][a] / W[g];
    length[g] = std::sqrt(mean[g][0] * mean[g][0] + mean[g][1] * mean[g][1] + mean[g][2] * mean[g][2]);
  }
  const double cosine =
    (mean[0][0] * mean[1][0] + mean[0][1] * mean[1][1] + mean[0][2] * mean[1][2]) / (length[0] * length[1]);
  if(!(length[0] >= 0.7 && length[1] >= 0.7 && cosine < -0.7))
    return true;  // normals pointing anywhere, or not opposite: not two sheets
  double axis[3] = {mean[0][0] - mean[1][0], mean[0][1] - mean[1][1], mean[0][2] - mean[1][2]};
  const double al = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for(double& x : axis)
    x /= al;
  double offset[2], spread[2];
  for(int g = 0; g < 2; ++g)
  {
    offset[g] = (axis[0] * Q[g][0] + axis[1] * Q[g][1] + axis[2] * Q[g][2]) / W[g];
    const double* M = QQ[g];
    const double second = (axis[0] * (M[0] * axis[0] + M[1] * axis[1] + M[2] * axis[2]) +
                           axis[1] * (M[1] * axis[0] + M[3] * axis[1] + M[4] * axis[2]) +
                           axis[2] * (M[2] * axis[0] + M[4] * axis[1] + M[5] * axis[2])) /
                          W[g];
    spread[g] = std::sqrt(std::max(0.0, second - offset[g] * offset[g]));
  }
  const double separation = std::abs(offset[1] - offset[0]);
  return separation <= 0.05 || separation <= 2 * std::max(spread[0], spread[1]);
}

// The length of the weighted mean of the neighbours' unit normals, |C| / A for the fits'
// sums A = sum w and C = sum w n (normals oriented as the fit uses them), in [0, 1] (1 may be
// exceeded by rounding only); NaN if it is not defined.
inline double normal_coherence(double A, const double C[3])
{
  const double c = std::sqrt(C[0] * C[0] + C[1] * C[1] + C[2] * C[2]) / A;
  if(!(A > 0) || !std::isfinite(c))
    return std::numeric_limits<double>::quiet_NaN();
  return std::min(c, 1.0);
}

// One estimate in double precision, before conversion to the kernel's types.
struct Local_estimate
{
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();

  double normal[3] = {nan, nan, nan};
  double mean = nan, gaussian = nan, k_min = nan, k_max = nan;
  double d_min[3] = {nan, nan, nan};
  double d_max[3] = {nan, nan, nan};
  double normal_coherence = nan;  // |sum w n| / sum w of the fit (ASO, APSS)
  // With the automatic scale: the standard error of `mean` estimated at the chosen scale, and
  // that scale's neighbour count (0: the driver's neighbourhood size).
  double mean_error = nan;
  std::size_t neighbor_count = 0;
  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;

  static Local_estimate invalid(Curvature_estimate_status s)
  {
    Local_estimate e;
    e.status = s;
    return e;
  }
};

// `out` = +v or -v, whichever makes a non-negative dot product with `reference` (an
// eigenvector oriented like the input normals).
inline void orient_like(const double v[3], const double reference[3], double out[3])
{
  const double side = v[0] * reference[0] + v[1] * reference[1] + v[2] * reference[2];
  for(int i = 0; i < 3; ++i)
    out[i] = side < 0 ? -v[i] : v[i];
}

// An orthonormal basis (t1, t2) of the plane orthogonal to the unit vector n
// (Duff et al. 2017, "Building an orthonormal basis, revisited"): branch-free but
// for the sign of n_z, continuous elsewhere, and exact for axis-aligned normals.
inline void tangent_basis(const double n[3], double t1[3], double t2[3])
{
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1.0 / (sign + n[2]);
  const double b = n[0] * n[1] * a;
  t1[0] = 1.0 + sign * n[0] * n[0] * a;
  t1[1] = sign * b;
  t1[2] = -sign * n[0];
  t2[0] = b;
  t2[1] = sign + n[1] * n[1] * a;
  t2[2] = -n[1];
}

// u^T M v for a symmetric 3x3 matrix M packed xx xy xz yy yz zz (second moments, Hessians).
inline double symmetric_form(const double M[6], const double u[3], const double v[3])
{
  return u[0] * (M[0] * v[0] + M[1] * v[1] + M[2] * v[2]) + u[1] * (M[1] * v[0] + M[3] * v[1] + M[4] * v[2]) +
         u[2] * (M[2] * v[0] + M[4] * v[1] + M[5] * v[2]);
}

// True if the neighbours do not spread in two tangent directions: a second moment M of
// their positions (sum weight q q^T, packed xx xy xz yy yz zz) restricted to the plane orthogonal to `normal` has rank at most
// 1 up to rounding (determinant negligible against trace^2). This is the case of points on
// a line, or on a curve in a plane containing the normal (one scan line of a LiDAR at a
// small radius): the curvature across is then not measured and the fit would silently
// report the sphere's.
inline bool lacks_tangent_spread(const double M[6], const double normal[3])
{
  const double l = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if(!(l > 0))
    return true;
  const double n[3] = {normal[0] / l, normal[1] / l, normal[2] / l};
  double t1[3], t2[3];
  tangent_basis(n, t1, t2);
  const double a = symmetric_form(M, t1, t1), b = symmetric_form(M, t1, t2), c = symmetric_form(M, t2, t2);
  return !(a * c - b * b > 1e-12 * (a + c) * (a + c));
}

// The least radius of a neighbourhood, as a share of its query's largest absolute coordinate:
// about 65,000 rounding units of that coordinate. Points closer together than that (the same
// point computed twice, merged tiles with different offsets, a simulated scan whose rays meet
// again) differ by rounding only; a neighbourhood of such near-copies has offsets that are
// rounding errors, and a fit of them, however well conditioned it looks, gives curvatures of the
// order of 1/radius (a drone's rosette scan whose 400 passes over nadir fall within 1e-15 of one
// another: mean curvatures of 1e8 to 1e11 at `--neighbors 40`, reported valid before this bound).
// Real coordinates never come that close but for copies: LAS at a scale of 1 mm and coordinates
// of 1e6 m are 1e-9 apart, 70 times the bound.
constexpr double least_radius_share = 0x1p-36;

// Whether a neighbourhood's radius is below least_radius_share of its query's coordinates: its
// points coincide up to rounding (DEGENERATE_FIT).
inline bool neighborhood_below_precision(const Neighborhood& nb)
{
  const double m = std::max(std::max(std::abs(nb.center[0]), std::abs(nb.center[1])), std::abs(nb.center[2]));
  return nb.radius < least_radius_share * m;
}

// lacks_tangent_spread() for a whole neighbourhood: its unweighted second moment around the
// query, and the mean of its normals as the normal. One pass; for the estimators that do
// not accumulate such moments themselves.
inline bool neighborhood_lacks_tangent_spread(const Neighborhood& nb)
{
  double M[6] = {0, 0, 0, 0, 0, 0}, n[3] = {0, 0, 0};
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double x = nb.qx[i], y = nb.qy[i], z = nb.qz[i];
    M[0] += x * x;
    M[1] += x * y;
    M[2] += x * z;
    M[3] += y * y;
    M[4] += y * z;
    M[5] += z * z;
    n[0] += nb.nx[i];
    n[1] += nb.ny[i];
    n[2] += nb.nz[i];
  }
  return lacks_tangent_spread(M, n);
}

// Principal curvatures and directions of the 2x2 symmetric tensor [[a, b], [b, c]]
// written in the tangent basis (t1, t2). Fills k_min <= k_max, mean, gaussian and unit,
// orthogonal, tangent directions.
inline void set_principal_curvatures(double a, double b, double c, const double t1[3], const double t2[3],
                                     Local_estimate& e)
{
  const double half_sum = 0.5 * (a + c);
  const double half_diff = 0.5 * (a - c);
  const double radius = std::hypot(half_diff, b);
  e.k_min = half_sum - radius;
  e.k_max = half_sum + radius;
  e.mean = half_sum;
  e.gaussian = e.k_min * e.k_max;
  // The eigenvector of the larger eigenvalue makes the angle theta = atan2(2b, a - c) / 2
  // with t1; atan2 stays well defined at umbilics (any direction is then principal).
  const double theta = 0.5 * std::atan2(2.0 * b, a - c);
  const double ct = std::cos(theta), st = std::sin(theta);
  for(int i = 0; i < 3; ++i)
  {
    e.d_max[i] = ct * t1[i] + st * t2[i];
    e.d_min[i] = -st * t1[i] + ct * t2[i];
  }
}

// The unit normal of a field's gradient and its tangent basis (tangent_basis()). Returns the
// gradient's length, or 0 when the gradient vanishes or is not finite (no frame).
inline double gradient_frame(const double gradient[3], double normal[3], double t1[3], double t2[3])
{
  const double norm = std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] + gradient[2] * gradient[2]);
  if(!(norm > 1e-12) || !std::isfinite(norm))
    return 0;
  for(int i = 0; i < 3; ++i)
    normal[i] = gradient[i] / norm;
  tangent_basis(normal, t1, t2);
  return norm;
}

// The shape operator W = P Hess P / |grad| of a field in the tangent basis (t1, t2) of its
// gradient_frame(), which also gives `gradient_norm`: W = [[W[0], W[1]], [W[1], W[2]]], times
// `inverse_length_unit`.
inline void shape_operator_in_basis(double gradient_norm, const double hessian[6], double inverse_length_unit,
                                    const double t1[3], const double t2[3], double W[3])
{
  const double s = inverse_length_unit / gradient_norm;
  W[0] = s * symmetric_form(hessian, t1, t1);
  W[1] = s * symmetric_form(hessian, t1, t2);
  W[2] = s * symmetric_form(hessian, t2, t2);
}

// Shape operator of a scalar field from its gradient and Hessian (Equation 27 of
// Lejemble et al. 2021): W = P Hess P / |grad|, with P the projection on the plane
// orthogonal to grad. `hessian` is packed xx xy xz yy yz zz. Returns false when the
// gradient vanishes (no normal, no tensor).
inline bool set_shape_operator(const double gradient[3], const double hessian[6], double inverse_length_unit,
                               Local_estimate& e)
{
  double t1[3], t2[3], W[3];
  const double norm = gradient_frame(gradient, e.normal, t1, t2);
  if(norm == 0)
    return false;
  shape_operator_in_basis(norm, hessian, inverse_length_unit, t1, t2, W);
  set_principal_curvatures(W[0], W[1], W[2], t1, t2, e);
  return std::isfinite(e.k_min) && std::isfinite(e.k_max);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
