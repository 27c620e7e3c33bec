// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Osculating jets (Cazals and Pouget, "Estimating differential quantities using polynomial
// fitting of osculating jets", CAGD 22(2), 2005) through CGAL::Monge_via_jet_fitting: a
// least-squares polynomial of degree `degree_fitting` over the PCA plane of the
// neighbourhood, converted to its Monge form up to degree `degree_monge`.
//
// Points that matter when driving CGAL's class:
//   - the Monge form is computed at the projection of the FIRST point of the range on the
//     fitted jet (the fit's origin), so the query point goes first; the driver's
//     neighbourhood contains the query point at q = 0 somewhere in grid order, which is
//     skipped once so that it is not counted twice;
//   - the Monge normal has an arbitrary orientation: comply_wrt_given_normal() flips it
//     (and swaps and negates the coefficients) to agree with the input normal;
//   - CGAL's Monge coefficients k1 >= k2 are positive where the surface bends towards
//     the normal (z = (k1 x² + k2 y²)/2 in the frame (d1, d2, n)), the opposite of the
//     package's convention: k_min = -k1 along d1, k_max = -k2 along d2;
//   - the neighbourhood is in the scaled frame q = (p - x)/r: curvatures are divided by r.
//     (CGAL preconditions the fit by the mean coordinate, so the scale changes nothing else.)

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_OSCULATING_JET_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_OSCULATING_JET_H

#ifndef CGAL_EIGEN3_ENABLED
#error                                                                                                                 \
  "CGAL::estimate_jet_curvatures() needs Eigen 3 (CGAL::Monge_via_jet_fitting solves with CGAL::Eigen_svd): in CMake, find_package(Eigen3 3.3 REQUIRED), include(CGAL_Eigen3_support) and link CGAL::Eigen3_support."
#endif

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

struct Jet_degrees
{
  std::size_t fitting = 2;  // degree of the fitted polynomial, >= degree_monge
  std::size_t monge = 2;    // degree of the Monge form, 2 to 4 (curvatures need 2)
};

// Number of coefficients of a bivariate polynomial of degree d: (d+1)(d+2)/2, the minimal
// number of points (query included) of the least-squares fit.
inline std::size_t jet_min_neighbors(std::size_t degree_fitting)
{
  return (degree_fitting + 1) * (degree_fitting + 2) / 2;
}

// Above this condition number of the (preconditioned) Vandermonde matrix the fit is
// treated as singular (e.g. collinear neighbourhoods). Measured with degree 2 at about 40
// neighbours: at most 4.9 on the Goursat 10K cloud, 9.1 on a random ellipsoid, 22 on the
// noisy, anisotropic simulated LiDAR scan (median about 4).
constexpr double jet_max_condition_number = 1e12;

inline Local_estimate osculating_jet_estimate(const Neighborhood& nb, const Jet_degrees& degrees)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Monge_via_jet_fitting<K> Fitter;

  if(nb.size < jet_min_neighbors(degrees.fitting))
    return Local_estimate::invalid(Curvature_estimate_status::TOO_FEW_NEIGHBORS);
  // CGAL's fitting builds its frame from the neighbours' PCA first: coincident or collinear
  // neighbours make it index Eigen blocks with negative sizes (an assertion failure, undefined
  // behaviour without assertions). Reject them before calling it.
  if(neighborhood_lacks_tangent_spread(nb))
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);

  std::vector<K::Point_3> points;
  points.reserve(nb.size + 1);
  points.emplace_back(0.0, 0.0, 0.0);  // the query point first: the jet is evaluated there
  bool query_skipped = false;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    if(!query_skipped && nb.qx[i] == 0 && nb.qy[i] == 0 && nb.qz[i] == 0)
    {
      query_skipped = true;
      continue;
    }
    points.emplace_back(nb.qx[i], nb.qy[i], nb.qz[i]);
  }

  Fitter fitter;
  typename Fitter::Monge_form monge = fitter(points.begin(), points.end(), degrees.fitting, degrees.monge);
  const double condition = fitter.condition_number();
  if(!(condition < jet_max_condition_number))  // also NaN
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  monge.comply_wrt_given_normal(K::Vector_3(nb.query_normal[0], nb.query_normal[1], nb.query_normal[2]));

  const double inv_r = 1.0 / nb.radius;
  const K::Vector_3 n = monge.normal_direction();
  const K::Vector_3 d1 = monge.maximal_principal_direction();
  const K::Vector_3 d2 = monge.minimal_principal_direction();
  Local_estimate e;
  e.k_min = -monge.principal_curvatures(0) * inv_r;
  e.k_max = -monge.principal_curvatures(1) * inv_r;
  e.mean = 0.5 * (e.k_min + e.k_max);
  e.gaussian = e.k_min * e.k_max;
  for(int i = 0; i < 3; ++i)
  {
    e.normal[i] = n[i];
    e.d_min[i] = d1[i];
    e.d_max[i] = d2[i];
  }
  bool finite = std::isfinite(e.k_min) && std::isfinite(e.k_max);
  for(int i = 0; i < 3; ++i)
    finite = finite && std::isfinite(e.normal[i]) && std::isfinite(e.d_min[i]) && std::isfinite(e.d_max[i]);
  if(!finite)
    return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
  e.status = Curvature_estimate_status::VALID;
  return e;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
