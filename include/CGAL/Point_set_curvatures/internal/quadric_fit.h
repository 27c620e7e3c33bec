// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A weighted quadric fitted to the neighbours' positions alone: the second-order normals of
// estimate_oriented_normals() (Normal_fit::QUADRIC) and the position fit that the ASO blends
// in when the normals were estimated from the positions (position_fit_blend).
//
// Why a second-order, weighted fit for normals that the ASO reads: the ASO differentiates the
// normal field, so what matters is that the normals vary smoothly from point to point, more
// than their accuracy at each point. The unweighted PCA plane of the k nearest is biased by
// the curvature to first order and jumps each time the set of the k nearest changes. Here the
// weights (1 - d²/r²)² vanish at the neighbourhood's border, so the fit varies continuously
// with the query, and the quadric removes the curvature's bias (benchmark/README.md, "Scans
// without normals": a cubic was more accurate point by point but rougher, and worse for the
// ASO).
//
// At the query x (the origin of the neighbourhood's scaled frame):
// 1. the weighted covariance of the neighbours about their weighted centroid gives a frame
//    (t1, t2, n0), n0 oriented like the query's input normal, and the neighbourhood's spread:
//    neighbours spread along one direction only (one scan line) give no fit; where the weights
//    leave one line but the neighbours themselves spread in two directions (the next scan
//    lines at the kernel's rim), the unweighted covariance gives the frame
//    (weighted_line_spread_ratio);
// 2. over that frame the heights h = n0.q are fitted by weighted least squares,
//      h(u, v) = a0 + a1 u + a2 v + a3 u² + a4 u v + a5 v²,
//    the surface being the graph of h (height_field.h): its normal at u = v = 0 is
//    n0 - a1 t1 - a2 t2 normalised, its shape operator that of the graph there.
//
// The sums over the neighbours (the covariance, the normal equations, the variance factors) add
// the neighbours of even and of odd rank in two lanes (lane_pair.h), one instruction for both.
//
// Scan lines: where the neighbours lie on two lines only (airborne scans whose lines are far
// apart compared with the spacing along a line), v² is a combination of 1 and v over the
// samples, and the slope across the lines is undetermined (CGAL's unweighted jets of 30
// neighbours gave normals 1.9 degrees off on average on such a scan); on three lines it is
// badly determined. A small penalty on the anisotropic part of the quadratic term,
// lambda ((a3 - a5)² + a4²) / 2, resolves that direction with the isotropic model (the same
// curvature across the lines as along them) and barely moves well-sampled fits: lambda is
// 5e-4 of the fourth moment sum w (u² + v²)² (measured on the scans of benchmark/
// scan_experiments: 5e-3 biased the normals of the torus seen from a scanner, 5e-5 left the
// airborne lines under-determined, 2.5e-4 within 10% of 5e-4).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_QUADRIC_FIT_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_QUADRIC_FIT_H

#include <CGAL/Point_set_curvatures/internal/height_field.h>
#include <CGAL/Point_set_curvatures/internal/lane_pair.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/pca_plane.h>
#include <CGAL/Point_set_curvatures/internal/pss.h>
#include <CGAL/Point_set_curvatures/internal/symmetric_eigen_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The least ratio of the second to the first standard deviation of a neighbourhood's
// positions for a normal: below it the neighbours lie along one line (one LiDAR scan line at
// a neighbourhood smaller than the distance between lines), and any normal about that line
// would fit them. Two lines of an airborne scan 5 times farther apart than the spacing along
// a line give about 0.4 at 40 neighbours; one line with the scanner's range noise about 0.004.
constexpr double min_tangent_spread_ratio = 0.05;

// The least ratio of the second to the first standard deviation of a neighbourhood's positions
// weighted by the fit's kernel for the fit's frame to come from them. Below it the weights leave
// one line in effect (a scan line through the query, the next ones at the kernel's rim, where
// the weight vanishes), and under range noise the line's noisy band, not the surface, sets the
// frame: the normal then lies about the line, sideways (a mobile profiler with range noise of
// 0.3 spacings: 19% of the normals more than 60 degrees off, weighted ratios 0.06 to 0.12,
// unweighted 0.76 to 0.98; benchmark/README.md, section 8). There the frame comes from the
// unweighted covariance where that one does not spread along one line; and the automatic scale
// takes any rung whose weighted covariance is below the ratio for one line (it climbs).
constexpr double weighted_line_spread_ratio = 0.2;

// The eigen-decomposition of the covariance of a neighbourhood's positions (scaled frame) about
// their centroid, weighted by the fits' kernel (pss_weight). (Unweighted: Neighborhood_pca.)
struct Weighted_covariance
{
  double values[3], vectors[3][3];  // ascending eigenvalues and their unit vectors

  // False without weight or eigen-decomposition.
  bool compute(const Neighborhood& nb)
  {
    // (two lanes, lane_pair.h; the one point of a lane without its pair is padded with a
    // point outside the kernel)
    Lane_pair sums[10] = {};  // w, w q, w q qᵀ
    for(std::size_t i = 0; i < nb.size; i += 2)
    {
      const Lane_pair q[3] = {load_pair(nb.qx, i, nb.size, 2.0), load_pair(nb.qy, i, nb.size, 0.0),
                              load_pair(nb.qz, i, nb.size, 0.0)};
      const Lane_pair w = pss_weight(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      sums[0] += w;
      sums[1] += w * q[0];
      sums[2] += w * q[1];
      sums[3] += w * q[2];
      sums[4] += w * q[0] * q[0];
      sums[5] += w * q[0] * q[1];
      sums[6] += w * q[0] * q[2];
      sums[7] += w * q[1] * q[1];
      sums[8] += w * q[1] * q[2];
      sums[9] += w * q[2] * q[2];
    }
    const double sw = fold(sums[0]);
    double c[3], cov[6];
    for(int a = 0; a < 3; ++a)
      c[a] = fold(sums[1 + a]);
    for(int k = 0; k < 6; ++k)
      cov[k] = fold(sums[4 + k]);
    if(!(sw > 0))
      return false;
    // the raw second moments minus the centroid's (the coordinates are scaled to |q| < 1, so
    // the difference loses little)
    for(int a = 0; a < 3; ++a)
      c[a] /= sw;
    for(int a = 0, k = 0; a < 3; ++a)
      for(int b = a; b < 3; ++b, ++k)
        cov[k] = cov[k] / sw - c[a] * c[b];
    return symmetric_eigen_3(cov, values, vectors);
  }
};

// True if ascending eigenvalues `values` of a covariance spread along one line
// (weighted_line_spread_ratio).
inline bool spreads_along_one_line(const double values[3])
{
  return !(values[2] > 0) || !(values[1] >= weighted_line_spread_ratio * weighted_line_spread_ratio * values[2]);
}

// True if a covariance of positions whose eigenvalues are `values` (ascending) spreads in
// two directions: see min_tangent_spread_ratio.
inline bool spreads_in_two_directions(const double values[3])
{
  return values[2] > 0 && values[1] >= min_tangent_spread_ratio * min_tangent_spread_ratio * values[2];
}

struct Quadric_fit
{
  double t1[3], t2[3], n0[3];      // the frame of the fit, n0 oriented like the query's normal
  double axis[3];                  // n0 before it was oriented
  double a[6];                     // the height field's coefficients (scaled frame)
  Quadratic_height_fit equations;  // the weighted normal equations solved, penalty included

  // Neighbours i and i + 1 (lane_pair.h; one outside the kernel where i + 1 is past the end) in
  // the fit's frame: their kernel weights, tangent coordinates and heights, all 0 where the
  // weight is (the neighbourhood's border).
  void in_frame(const Neighborhood& nb, std::size_t i, Lane_pair& w, Lane_pair& u, Lane_pair& v, Lane_pair& h) const
  {
    const Lane_pair q[3] = {load_pair(nb.qx, i, nb.size, 2.0), load_pair(nb.qy, i, nb.size, 0.0),
                            load_pair(nb.qz, i, nb.size, 0.0)};
    w = pss_weight(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    u = where_positive(w, broadcast(t1[0]) * q[0] + broadcast(t1[1]) * q[1] + broadcast(t1[2]) * q[2]);
    v = where_positive(w, broadcast(t2[0]) * q[0] + broadcast(t2[1]) * q[1] + broadcast(t2[2]) * q[2]);
    h = where_positive(w, broadcast(n0[0]) * q[0] + broadcast(n0[1]) * q[1] + broadcast(n0[2]) * q[2]);
  }

  // The penalty's weight (see the header comment); 0: the plain least-squares quadric.
  double anisotropy_penalty = 5e-4;

  // Set by compute(): the weighted covariance spreads along one line (weighted_line_spread_ratio);
  // the frame then came from the unweighted one where that one does not.
  bool weighted_line = false;

  // Set by compute(): sum w (u² + v²)², which the penalty's weight scales (refit_with_penalty()).
  double fourth_moment = 0;

  // If set, compute() keeps each neighbour's weight, tangent coordinates and height there
  // (in_frame()) and variance_factors() on the same neighbourhood reads them instead of
  // computing them again: by pairs of neighbours (2 b, 2 b + 1), eight values from 8 b, the
  // two weights, the two u, the two v, the two heights (a weight of 0 past the last neighbour).
  std::vector<double>* frame_cache = nullptr;
  static std::size_t frame_cache_size(std::size_t neighbors) { return 8 * ((neighbors + 1) / 2); }

  // Set by compute() with a frame cache (`has_squared_moments`): the moments with weights w²
  // that variance_factors() reads, summed in compute()'s pass (the same values in the same order
  // as a pass over the cache would add: one pass fewer over the neighbours). Without them (a
  // cache this fit did not fill), variance_factors() sums them from the cache.
  Quadratic_moments squared_moments;
  bool has_squared_moments = false;

  // Fits the neighbourhood; false if its neighbours do not spread in two directions or the
  // fit has no solution. Where the neighbourhood carries the automatic scale's plain quadric of
  // its points (Neighborhood::plain_quadric) and no frame cache is asked for, that fit with
  // this one's penalty (refit_with_penalty(): the same result).
  bool compute(const Neighborhood& nb)
  {
    if(nb.plain_quadric && !frame_cache)
    {
      const double penalty = anisotropy_penalty;
      *this = *nb.plain_quadric;
      return refit_with_penalty(penalty);
    }
    weighted_line = false;
    has_squared_moments = false;
    if(nb.size < quadratic_height_coefficients)
      return false;
    // the frame: the eigenvectors of the weighted covariance, or of the unweighted one where
    // the weights leave one line and the neighbours do not (weighted_line_spread_ratio)
    Weighted_covariance covariance;
    if(!covariance.compute(nb))
      return false;
    const double* values = covariance.values;
    const double(*vectors)[3] = covariance.vectors;
    weighted_line = spreads_along_one_line(values);
    Neighborhood_pca unweighted;
    if(weighted_line && unweighted.compute(nb) && !spreads_along_one_line(unweighted.values))
    {
      values = unweighted.values;
      vectors = unweighted.vectors;
    }
    if(!spreads_in_two_directions(values))
      return false;
    orient_like(vectors[0], nb.query_normal, n0);
    for(int i = 0; i < 3; ++i)
    {
      axis[i] = vectors[0][i];
      t1[i] = vectors[2][i];
      t2[i] = vectors[1][i];
    }

    Quadratic_height_fit& fit = equations;
    fit = Quadratic_height_fit();
    Quadratic_sums<Lane_pair> sums, squared_sums;
    double* cache = nullptr;
    if(frame_cache)
    {
      frame_cache->resize(frame_cache_size(nb.size));
      cache = frame_cache->data();
    }
    for(std::size_t i = 0; i < nb.size; i += 2)
    {
      Lane_pair w, u, v, h;
      in_frame(nb, i, w, u, v, h);
      if(cache)
      {
        double* block = cache + 4 * i;
        store_lanes(block, w);
        store_lanes(block + 2, u);
        store_lanes(block + 4, v);
        store_lanes(block + 6, h);
        squared_sums.add(u, v, w * w);
      }
      sums.add(u, v, h, w);
    }
    if(cache)
    {
      squared_moments = Quadratic_moments(squared_sums);
      has_squared_moments = true;
    }
    const Quadratic_moments moments(sums);
    moments.fill(fit.ata, fit.atb);
    fourth_moment = moments.fourth();
    add_penalty(anisotropy_penalty);
    return fit.solve(a);
  }

  // After compute(): the fit that compute() gives on the same neighbourhood with a query normal
  // `reference`, bit for bit: the same frame and weights, the heights negated where n0 turns
  // over, so that n0, the coefficients and the normal equations' right-hand side are negated.
  // True if n0 turned over.
  bool orient_like_reference(const double reference[3])
  {
    double n[3];
    orient_like(axis, reference, n);
    if(n[0] == n0[0] && n[1] == n0[1] && n[2] == n0[2])
      return false;
    std::copy(n, n + 3, n0);
    for(double& c : a)
      c = -c;
    for(double& b : equations.atb)
      b = -b;
    return true;
  }

  // After compute() with anisotropy_penalty 0 (the automatic scale's rungs): the fit that
  // compute() with `penalty` gives on the same neighbourhood (the same frame and sums, bit for
  // bit), without a pass over its points. False where that fit has no solution.
  bool refit_with_penalty(double penalty)
  {
    CGAL_precondition(anisotropy_penalty == 0);
    anisotropy_penalty = penalty;
    add_penalty(penalty);
    return equations.solve(a);
  }

private:
  // the penalty lambda ((a3 - a5)² + a4²) / 2 in the normal equations (upper triangle)
  void add_penalty(double penalty)
  {
    const double lambda = penalty * fourth_moment;
    double(*ata)[6] = equations.ata;
    ata[3][3] += lambda;
    ata[3][5] -= lambda;
    ata[5][5] += lambda;
    ata[4][4] += lambda;
  }

public:
  // After compute() on the same neighbourhood: what the variances of linear combinations g[i] . a of the coefficients
  // are made of under independent position noise of variance sigma²: the sandwich covariance
  // of weighted least squares gives sigma² times factor[i] = g[i]ᵀ M⁻¹ (sum w² m mᵀ) M⁻¹ g[i],
  // M the normal equations; `sigma2` is the weighted mean squared residual with n_eff /
  // (n_eff - 6), n_eff = (sum w)² / sum w², for the six coefficients (scaled frame). False if
  // these have no value.
  bool variance_factors(const Neighborhood& nb, const double (*g)[6], int count, double* factor, double& sigma2) const
  {
    double b[6][6] = {};
    Lane_pair sums[2] = {};                  // sum w, sum w e²
    Quadratic_sums<Lane_pair> squared_sums;  // the moments with weights w², unless compute() summed them
    const double* cache =
      frame_cache && frame_cache->size() == frame_cache_size(nb.size) ? frame_cache->data() : nullptr;
    const bool summed = cache && has_squared_moments;
    Lane_pair A[6];
    for(int j = 0; j < 6; ++j)
      A[j] = broadcast(a[j]);
    for(std::size_t i = 0; i < nb.size; i += 2)
    {
      Lane_pair w, u, v, e;
      if(cache)
      {
        const double* block = cache + 4 * i;
        w = load_lanes(block);
        u = load_lanes(block + 2);
        v = load_lanes(block + 4);
        e = load_lanes(block + 6);
      }
      else
        in_frame(nb, i, w, u, v, e);
      e = e - (A[0] + A[1] * u + A[2] * v + A[3] * (u * u) + A[4] * (u * v) + A[5] * (v * v));
      sums[0] += w;
      sums[1] += w * e * e;
      if(!summed)
        squared_sums.add(u, v, w * w);
    }
    const double sw = fold(sums[0]), ssr = fold(sums[1]);
    const Quadratic_moments squared = summed ? squared_moments : Quadratic_moments(squared_sums);
    squared.fill(b);
    const double sw2 = squared.s[0];
    const double n_eff = sw2 > 0 ? sw * sw / sw2 : 0.0;
    if(!(n_eff > 6.5))
      return false;
    sigma2 = ssr / sw * n_eff / (n_eff - 6.0);
    for(int c = 0; c < count; ++c)
    {
      Quadratic_height_fit solve_for = equations;
      std::copy(g[c], g[c] + 6, solve_for.atb);
      double y[6];
      if(!solve_for.solve(y))
        return false;
      double var = 0;
      for(int j = 0; j < 6; ++j)
        for(int l = 0; l < 6; ++l)
          var += y[j] * (j <= l ? b[j][l] : b[l][j]) * y[l];
      factor[c] = std::max(0.0, var);
    }
    return std::isfinite(sigma2);
  }

  // The unit normal of the fitted surface at the query, oriented like the query's normal.
  bool normal(double n[3]) const
  {
    double h[6];
    height_field_gradient_hessian(a, t1, t2, n0, n, h);
    const double l2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if(!(l2 > 0) || !std::isfinite(l2))
      return false;
    const double inv = 1.0 / std::sqrt(l2);
    for(int i = 0; i < 3; ++i)
      n[i] *= inv;
    return true;
  }

  // The fitted surface's shape operator in the tangent basis (t1, t2) of a normal `nrm` close
  // to the fit's, W = [[W[0], W[1]], [W[1], W[2]]], in 1/length for `inverse_length_unit` =
  // 1/r, with the sign convention of `nrm` (positive where the surface bends away from it).
  bool shape_operator_in(const double nrm[3], const double b1[3], const double b2[3], double inverse_length_unit,
                         double W[3]) const
  {
    double g[3], h[6];
    height_field_gradient_hessian(a, t1, t2, n0, g, h);
    const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if(!(norm > 0) || !std::isfinite(norm))
      return false;
    const double side = g[0] * nrm[0] + g[1] * nrm[1] + g[2] * nrm[2] < 0 ? -1.0 : 1.0;
    shape_operator_in_basis(norm, h, side * inverse_length_unit, b1, b2, W);
    return std::isfinite(W[0]) && std::isfinite(W[1]) && std::isfinite(W[2]);
  }
};

// The weighted cubic height field over the points of a quadric's fit, in its frame and with its
// weights: the sums of Cubic_height_fit over its frame cache (Quadric_fit::frame_cache).
inline Cubic_height_fit cubic_over_frame_cache(const std::vector<double>& frame)
{
  Cubic_height_fit cubic;
  // (by pairs of neighbours; outside the kernel the weight and the values are 0: nothing added)
  for(std::size_t b = 0; b + 7 < frame.size(); b += 8)
    cubic.add(load_lanes(&frame[b + 2]), load_lanes(&frame[b + 4]), load_lanes(&frame[b + 6]), load_lanes(&frame[b]));
  return cubic;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
