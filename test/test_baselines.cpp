// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The baselines of Lejemble et al. 2021 (Table 1): distance to the barycenter, distance to
// the PCA plane, Point Set Surfaces, osculating jets (CGAL), order-2 Wavejets, Voronoi
// Covariance Measure (CGAL), against analytic curvatures, against each other and against
// ASO; API, statuses and bad input of every function.
//
// Every cloud and every algorithm is deterministic (fixed seeds), so the measured errors
// below are reproducible; tolerances are the measured values with a margin for other
// compilers and libraries (x1.5 unless said otherwise). The measured errors are printed
// (std::cout) by every accuracy test.

#include "test_support.h"
#include "goursat_sampler.h"  // area-uniform i.i.d. samples of the Goursat surface

#include <CGAL/Algebraic_shape_operator_fit.h>
#include <CGAL/estimate_algebraic_sphere_features.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_barycenter_curvatures.h>
#include <CGAL/estimate_jet_curvatures.h>
#include <CGAL/estimate_pca_plane_curvatures.h>
#include <CGAL/estimate_pss_curvatures.h>
#include <CGAL/estimate_tangent_voronoi_areas.h>
#include <CGAL/estimate_vcm_curvatures.h>
#include <CGAL/estimate_wavejet_curvatures.h>

#include <CGAL/Point_set_curvatures/estimators.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/vcm_estimate_normals.h>
#include <CGAL/Point_set_3.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace psc_test;
namespace PSC = CGAL::Point_set_curvatures;
typedef CGAL::Epick Epick;
typedef std::vector<CGAL::Curvature_estimate<Kernel> > Estimates;

namespace {

// ---------------------------------------------------------------------------------------
// Running the estimators
// ---------------------------------------------------------------------------------------

enum class Method { ASO, BARYCENTER, PCA_PLANE, PSS, JET, WAVEJET, VCM };
const Method all_methods[] = {Method::ASO, Method::BARYCENTER, Method::PCA_PLANE, Method::PSS,
                              Method::JET, Method::WAVEJET,    Method::VCM};
const Method baselines[] = {Method::BARYCENTER, Method::PCA_PLANE, Method::PSS,
                            Method::JET,        Method::WAVEJET,   Method::VCM};

const char* name(Method m)
{
  switch(m)
  {
    case Method::ASO: return "ASO";
    case Method::BARYCENTER: return "barycenter";
    case Method::PCA_PLANE: return "PCA plane";
    case Method::PSS: return "PSS";
    case Method::JET: return "jet (CGAL)";
    case Method::WAVEJET: return "wavejet";
    case Method::VCM: return "VCM (CGAL)";
  }
  return "?";
}

enum class Kind { SIGNED_TENSOR, UNSIGNED_MEAN, MAGNITUDES };
Kind kind(Method m)
{
  if(m == Method::BARYCENTER || m == Method::PCA_PLANE)
    return Kind::UNSIGNED_MEAN;
  return m == Method::VCM ? Kind::MAGNITUDES : Kind::SIGNED_TENSOR;
}

// Least number of neighbours (query included) of a valid estimate of each function with
// default parameters: the measured minima of the user manual ("Neighbourhoods and scale").
std::size_t minimum_neighbors(Method m)
{
  switch(m)
  {
    case Method::ASO:
    case Method::JET:
    case Method::WAVEJET: return 12;
    case Method::PCA_PLANE: return 10;
    case Method::PSS: return 15;
    default: return 20;  // barycenter, VCM
  }
}

// ... and the least the fit itself can solve, reached with min_neighbors(1).
std::size_t fit_minimum_neighbors(Method m)
{
  switch(m)
  {
    case Method::ASO:
    case Method::BARYCENTER:
    case Method::PCA_PLANE:
    case Method::VCM: return 3;
    default: return 6;
  }
}

auto maps() { return CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); }

// Every function through its (points, radius, np) overload.
template <class Tag, class Range, class NP>
auto run(Method m, const Range& pts, double r, const NP& np)
{
  switch(m)
  {
    case Method::ASO: return CGAL::estimate_aso_curvatures<Tag>(pts, r, np);
    case Method::BARYCENTER: return CGAL::estimate_barycenter_curvatures<Tag>(pts, r, np);
    case Method::PCA_PLANE: return CGAL::estimate_pca_plane_curvatures<Tag>(pts, r, np);
    case Method::PSS: return CGAL::estimate_pss_curvatures<Tag>(pts, r, np);
    case Method::JET: return CGAL::estimate_jet_curvatures<Tag>(pts, r, np);
    case Method::WAVEJET: return CGAL::estimate_wavejet_curvatures<Tag>(pts, r, np);
    case Method::VCM: break;
  }
  return CGAL::estimate_vcm_curvatures<Tag>(pts, r, np);
}

template <class Tag = CGAL::Parallel_tag>
Estimates run(Method m, const std::vector<Oriented_point>& pts, double r)
{
  return run<Tag>(m, pts, r, maps());
}

// Every function through its (points, np) overload (neighbourhoods by count).
template <class Tag, class NP>
Estimates run_without_radius(Method m, const std::vector<Oriented_point>& pts, const NP& np)
{
  switch(m)
  {
    case Method::ASO: return CGAL::estimate_aso_curvatures<Tag>(pts, np);
    case Method::BARYCENTER: return CGAL::estimate_barycenter_curvatures<Tag>(pts, np);
    case Method::PCA_PLANE: return CGAL::estimate_pca_plane_curvatures<Tag>(pts, np);
    case Method::PSS: return CGAL::estimate_pss_curvatures<Tag>(pts, np);
    case Method::JET: return CGAL::estimate_jet_curvatures<Tag>(pts, np);
    case Method::WAVEJET: return CGAL::estimate_wavejet_curvatures<Tag>(pts, np);
    case Method::VCM: break;
  }
  return CGAL::estimate_vcm_curvatures<Tag>(pts, np);
}

template <class Tag>
Estimates run_by_count(Method m, const std::vector<Oriented_point>& pts, std::size_t k)
{
  return run_without_radius<Tag>(m, pts, PSC::parameters::neighbor_count(k, maps()));
}

// Every function through its (points, point_map, normal_map, radius) overload.
Estimates run_explicit_maps(Method m, const std::vector<Oriented_point>& pts, double r)
{
  typedef CGAL::Sequential_tag S;
  switch(m)
  {
    case Method::ASO: return CGAL::estimate_aso_curvatures<S>(pts, Point_map(), Normal_map(), r);
    case Method::BARYCENTER: return CGAL::estimate_barycenter_curvatures<S>(pts, Point_map(), Normal_map(), r);
    case Method::PCA_PLANE: return CGAL::estimate_pca_plane_curvatures<S>(pts, Point_map(), Normal_map(), r);
    case Method::PSS: return CGAL::estimate_pss_curvatures<S>(pts, Point_map(), Normal_map(), r);
    case Method::JET: return CGAL::estimate_jet_curvatures<S>(pts, Point_map(), Normal_map(), r);
    case Method::WAVEJET: return CGAL::estimate_wavejet_curvatures<S>(pts, Point_map(), Normal_map(), r);
    case Method::VCM: break;
  }
  return CGAL::estimate_vcm_curvatures<S>(pts, Point_map(), Normal_map(), r);
}

// ---------------------------------------------------------------------------------------
// Errors against the truth
// ---------------------------------------------------------------------------------------

struct Stat
{
  double sum = 0, max = 0;
  std::size_t n = 0;
  void add(double e)
  {
    sum += std::abs(e);
    max = std::max(max, std::abs(e));
    ++n;
  }
  double mean() const { return n ? sum / double(n) : std::numeric_limits<double>::quiet_NaN(); }
};

struct Errors
{
  std::size_t considered = 0, valid = 0;
  Stat H;             // signed: |H - H_t|; unsigned: ||H| - |H_t||
  Stat k_min, k_max;  // signed, or magnitudes sorted for VCM
  Stat normal;        // degrees
  Stat direction;     // degrees, direction of the larger (|)k(|), away from umbilics
  // the errors of a constant zero at the same points: an error bound at or above them would
  // pass an estimator that returns 0 everywhere (issue 45)
  Stat H_of_zero, k_min_of_zero, k_max_of_zero;
};

double angle_degrees(const Vector& a, const Vector& b)
{
  const double c = (a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / M_PI;
}

Errors errors(
  Kind k, const Estimates& est, const std::vector<Oriented_point>& pts, const std::function<Truth(const Point&)>& truth,
  const std::function<bool(const Point&)>& keep = [](const Point&) { return true; })
{
  Errors e;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    if(!keep(pts[i].first))
      continue;
    ++e.considered;
    const auto& x = est[i];
    if(!x.is_valid())
      continue;
    ++e.valid;
    const Truth t = truth(pts[i].first);
    const double spread = std::max(std::abs(t.k_min), std::abs(t.k_max));
    if(std::isfinite(x.normal.x()))
      e.normal.add(angle_degrees(x.normal, t.normal));
    e.H_of_zero.add(t.mean);
    if(k == Kind::UNSIGNED_MEAN)
      e.H.add(x.mean_curvature - std::abs(t.mean));
    else if(k == Kind::SIGNED_TENSOR)
    {
      e.H.add(x.mean_curvature - t.mean);
      e.k_min.add(x.min_curvature - t.k_min);
      e.k_max.add(x.max_curvature - t.k_max);
      e.k_min_of_zero.add(t.k_min);
      e.k_max_of_zero.add(t.k_max);
      if(t.k_max - t.k_min > 0.2 * spread)
        e.direction.add(line_angle_degrees(x.max_direction, t.d_max));
    }
    else
    {
      double a = std::abs(t.k_min), b = std::abs(t.k_max);
      const Vector larger = a > b ? t.d_min : t.d_max;
      if(a > b)
        std::swap(a, b);
      e.k_min.add(x.min_curvature - a);
      e.k_max.add(x.max_curvature - b);
      e.k_min_of_zero.add(a);
      e.k_max_of_zero.add(b);
      if(b - a > 0.2 * spread)
        e.direction.add(line_angle_degrees(x.max_direction, larger));
    }
  }
  return e;
}

void print_header(const std::string& title)
{
  std::cout << "\n"
            << title << "\n"
            << "| estimator | valid | mean/max err H | mean/max err k_min | mean/max err k_max "
               "| normal deg mean/max | direction deg mean |\n|---|---|---|---|---|---|---|\n";
}

void print_row(const std::string& label, const Errors& e)
{
  auto pair = [](const Stat& s) {
    std::ostringstream o;
    if(s.n == 0)
      o << "-";
    else
      o << std::setprecision(3) << s.mean() << " / " << s.max;
    return o.str();
  };
  std::ostringstream mean_direction;
  if(e.direction.n)
    mean_direction << std::setprecision(3) << e.direction.mean();
  else
    mean_direction << "-";
  std::cout << "| " << label << " | " << e.valid << "/" << e.considered << " | " << pair(e.H) << " | " << pair(e.k_min)
            << " | " << pair(e.k_max) << " | " << pair(e.normal) << " | " << mean_direction.str() << " |" << std::endl;
}

// An error bound of the tables below, for an error measured as `error` where a constant zero
// would err by `of_zero`: the bound must be below `of_zero` (else it proves nothing: issue 45),
// and the error below the bound. Where an estimator's error exceeds the quantity itself (said
// at each table) no bound can prove accuracy: `regression_only(b)` then only keeps its error
// below its measured value b (x1.5), which a constant zero would also meet, to catch garbage.
struct Bound
{
  double value;
  bool accuracy = true;  // false: regression_only
  Bound(double v) : value(v) {}
};
Bound regression_only(double b)
{
  Bound r(b);
  r.accuracy = false;
  return r;
}
void check_bound(const char* what, double error, const Bound& bound, double of_zero)
{
  INFO(what << ": error " << error << ", bound " << bound.value << (bound.accuracy ? "" : " (regression only)")
            << ", a constant zero's error " << of_zero);
  if(bound.accuracy)
    CHECK(bound.value < of_zero);
  CHECK(error < bound.value);
}

// The curvature bounds of a row: mean and largest error of H, then of k_min and k_max (the
// worse of the two against the worse of a constant zero's).
void check_bounds(Kind kind, const Errors& e, const Bound& mean_H, const Bound& max_H, const Bound& mean_k,
                  const Bound& max_k)
{
  if(kind != Kind::MAGNITUDES)
  {
    check_bound("mean H error", e.H.mean(), mean_H, e.H_of_zero.mean());
    check_bound("largest H error", e.H.max, max_H, e.H_of_zero.max);
  }
  if(kind != Kind::UNSIGNED_MEAN)
  {
    check_bound("mean k error", std::max(e.k_min.mean(), e.k_max.mean()), mean_k,
                std::max(e.k_min_of_zero.mean(), e.k_max_of_zero.mean()));
    check_bound("largest k error", std::max(e.k_min.max, e.k_max.max), max_k,
                std::max(e.k_min_of_zero.max, e.k_max_of_zero.max));
  }
}

// ---------------------------------------------------------------------------------------
// Clouds
// ---------------------------------------------------------------------------------------

Truth sphere_truth(const Point& p, const Point& c, double R, bool inward = false)
{
  Truth t;
  Vector n = p - c;
  n = n / std::sqrt(n.squared_length());
  t.normal = inward ? -n : n;
  t.k_min = t.k_max = t.mean = (inward ? -1.0 : 1.0) / R;
  t.gaussian = 1.0 / (R * R);
  return t;
}

Truth cylinder_truth(const Point& p, double R)
{
  Truth t;
  Vector n(p.x(), p.y(), 0);
  n = n / std::sqrt(n.squared_length());
  t.normal = n;
  t.k_min = 0;
  t.k_max = 1.0 / R;
  t.mean = 0.5 / R;
  t.gaussian = 0;
  t.d_max = Vector(-n.y(), n.x(), 0);
  t.d_min = Vector(0, 0, 1);
  return t;
}

// The Fibonacci sphere mapped onto the ellipsoid: a density that varies smoothly, with the
// local regularity of a blue-noise sampling (psc_test::ellipsoid is i.i.d. random).
std::vector<Oriented_point> regular_ellipsoid(std::size_t n, double a, double b, double c)
{
  std::vector<Oriented_point> out;
  for(const auto& p : sphere(n, 1.0))
  {
    const Point q(a * p.first.x(), b * p.first.y(), c * p.first.z());
    const Vector g(q.x() / (a * a), q.y() / (b * b), q.z() / (c * c));
    out.emplace_back(q, g / std::sqrt(g.squared_length()));
  }
  return out;
}

const std::vector<Oriented_point>& goursat_10k()
{
  static const std::vector<Oriented_point> pts = read_xyz(repo_data("goursat_010000.xyz"));
  return pts;
}

bool same_number(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }
template <class V>
bool same_vector(const V& a, const V& b)
{
  return same_number(a.x(), b.x()) && same_number(a.y(), b.y()) && same_number(a.z(), b.z());
}
template <class E1, class E2>
bool same_estimate(const E1& a, const E2& b)
{
  return a.status == b.status && a.neighbor_count == b.neighbor_count &&
         same_number(a.mean_curvature, b.mean_curvature) && same_number(a.gaussian_curvature, b.gaussian_curvature) &&
         same_number(a.min_curvature, b.min_curvature) && same_number(a.max_curvature, b.max_curvature) &&
         same_number(a.normal.x(), b.normal.x()) && same_number(a.normal.y(), b.normal.y()) &&
         same_number(a.normal.z(), b.normal.z()) && same_number(a.min_direction.x(), b.min_direction.x()) &&
         same_number(a.min_direction.y(), b.min_direction.y()) &&
         same_number(a.min_direction.z(), b.min_direction.z()) &&
         same_number(a.max_direction.x(), b.max_direction.x()) &&
         same_number(a.max_direction.y(), b.max_direction.y()) && same_number(a.max_direction.z(), b.max_direction.z());
}

template <class E>
bool all_nan(const E& e)
{
  return std::isnan(e.mean_curvature) && std::isnan(e.gaussian_curvature) && std::isnan(e.min_curvature) &&
         std::isnan(e.max_curvature) && std::isnan(e.normal.x()) && std::isnan(e.min_direction.x()) &&
         std::isnan(e.max_direction.x());
}

// Identical estimates (bitwise, NaN equal to NaN). VCM included: its cells are computed so
// that they do not depend on memory addresses (vcm_cells.h; CGAL's compute_vcm() did).
template <class E1, class E2>
bool reproduced(Method, const E1& a, const E2& b, double)
{
  return same_estimate(a, b);
}

// Which fields a valid estimate of each method fills (the others must be NaN).
void check_fields(Method m, const CGAL::Curvature_estimate<Kernel>& e)
{
  INFO(name(m));
  REQUIRE(e.is_valid());
  const bool tensor = kind(m) == Kind::SIGNED_TENSOR;
  CHECK(std::isfinite(e.mean_curvature) == (kind(m) != Kind::MAGNITUDES));
  CHECK(std::isfinite(e.gaussian_curvature) == tensor);
  CHECK(std::isfinite(e.min_curvature) == (kind(m) != Kind::UNSIGNED_MEAN));
  CHECK(std::isfinite(e.max_curvature) == (kind(m) != Kind::UNSIGNED_MEAN));
  CHECK(std::isfinite(e.min_direction.x()) == (kind(m) != Kind::UNSIGNED_MEAN));
  CHECK(std::isfinite(e.max_direction.x()) == (kind(m) != Kind::UNSIGNED_MEAN));
  CHECK(std::isfinite(e.normal.x()) == (m != Method::BARYCENTER));
  if(kind(m) == Kind::UNSIGNED_MEAN)
    CHECK(e.mean_curvature >= 0);
  if(kind(m) == Kind::MAGNITUDES)
    CHECK(e.min_curvature >= 0);
  if(kind(m) != Kind::UNSIGNED_MEAN)
  {
    CHECK(e.min_curvature <= e.max_curvature);
    CHECK(e.min_direction.squared_length() == Approx(1).epsilon(1e-12));
    CHECK(e.max_direction.squared_length() == Approx(1).epsilon(1e-12));
    CHECK(std::abs(e.min_direction * e.max_direction) < 1e-12);
    CHECK(std::abs(e.min_direction * e.normal) < 1e-9);
    CHECK(std::abs(e.max_direction * e.normal) < 1e-9);
  }
  if(m != Method::BARYCENTER)
    CHECK(e.normal.squared_length() == Approx(1).epsilon(1e-12));
  if(tensor)
  {
    CHECK(e.mean_curvature == Approx(0.5 * (e.min_curvature + e.max_curvature)).margin(1e-12));
    CHECK(e.gaussian_curvature == Approx(e.min_curvature * e.max_curvature).margin(1e-12));
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Building blocks
// ---------------------------------------------------------------------------------------

TEST_CASE("Jacobi eigen-decomposition of symmetric 3x3 matrices", "[baselines][eigen]")
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for(int trial = 0; trial < 2000; ++trial)
  {
    // random rotation times a spectrum with a wide range (as a flat covariance: 1, 1, 1e-8)
    double m[6];
    const double scale[3] = {1.0, trial % 2 ? 1.0 : 0.3, trial % 3 ? 1e-8 : 0.5};
    double a[3][3] = {};
    Vector q[3];
    Vector v0(u(rng), u(rng), u(rng)), v1(u(rng), u(rng), u(rng));
    q[0] = v0 / std::sqrt(v0.squared_length());
    v1 = v1 - (v1 * q[0]) * q[0];
    q[1] = v1 / std::sqrt(v1.squared_length());
    q[2] = CGAL::cross_product(q[0], q[1]);
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        for(int k = 0; k < 3; ++k)
          a[i][j] += scale[k] * q[k][i] * q[k][j];
    m[0] = a[0][0];
    m[1] = a[0][1];
    m[2] = a[0][2];
    m[3] = a[1][1];
    m[4] = a[1][2];
    m[5] = a[2][2];
    double values[3], vectors[3][3];
    REQUIRE(PSC::internal::symmetric_eigen_3(m, values, vectors));
    CHECK(values[0] <= values[1]);
    CHECK(values[1] <= values[2]);
    for(int k = 0; k < 3; ++k)
    {
      const double* v = vectors[k];
      CHECK(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] == Approx(1).epsilon(1e-14));
      // residual |A v - λ v| at the rounding level of the largest eigenvalue
      for(int i = 0; i < 3; ++i)
        CHECK(std::abs(a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2] - values[k] * v[i]) < 1e-14);
    }
    // the small eigenvalue is recovered to its own relative accuracy, not the large ones'
    if(trial % 3 != 0)
      CHECK(values[0] == Approx(1e-8).epsilon(1e-6));
  }
}

// ---------------------------------------------------------------------------------------
// Analytic surfaces: each estimator within its measured bounds
// ---------------------------------------------------------------------------------------

// Sphere of radius 2 centred away from the origin, Fibonacci sampling, r = 0.25 (about 39
// neighbours); truth k = H = 0.5. Measured mean / max errors (tolerances x1.5):
//   ASO: 3e-15 / 3e-14 (it fits spheres exactly);
//   PSS 0.0013 / 0.0014, jets and wavejets 0.0019 / 0.0021 on k_min, k_max and H: the height
//     ρ²/(2R) + ρ⁴/(8R³) + ... of a sphere is not quadratic, and the quartic term biases a
//     quadratic fit by a fraction of (r/R)² = 1.6% (0.3 to 0.4% here);
//   |H| from the barycenter 0.13 / 0.72: the tangential drift of the barycenter of ~39
//     discrete points dominates the r²/(4R) = 0.008 offset it measures;
//   |H| from the PCA plane 0.014 / 0.035 (the drift removed);
//   VCM (R = r) 0.65 to 0.74 / 0.84: each Voronoi cell's spread over the spacing adds about
//     0.02 to λ_i/λ_n against r²k²/4 = 0.004, so the magnitudes come out 2.3 times too large;
//     with R = 2 (the feature size, as CGAL recommends) 0.020 to 0.056 / 0.082.
// Normals (max, degrees): fits 0.0018 (jets), PCA plane 0.50, VCM 1.1.
TEST_CASE("Sphere: each estimator within its measured bounds, every bound below a constant zero's error",
          "[baselines][sphere]")
{
  const Point c(1, -2, 3);
  const double R = 2, r = 0.25;
  const auto pts = sphere(10000, R, c);
  auto truth = [&](const Point& p) { return sphere_truth(p, c, R); };
  print_header("Sphere R = 2, 10000 points, r = 0.25");
  // H = k = 0.5. Regression bounds only where an error exceeds that: the barycenter's largest
  // (0.72) and VCM at its default offset radius r (0.65-0.74 mean: the cells' spread over r, a
  // bias that shrinks as 1/R^2 with the offset radius R, checked at R = 2 below). Measured x1.5.
  struct Tolerance
  {
    Method m;
    Bound mean_H, max_H, mean_k, max_k;
  };
  const Tolerance tolerances[] = {{Method::ASO, 1e-12, 1e-11, 1e-12, 1e-11},
                                  {Method::BARYCENTER, 0.2, regression_only(1.1), 0, 0},
                                  {Method::PCA_PLANE, 0.021, 0.053, 0, 0},
                                  {Method::PSS, 0.002, 0.0021, 0.002, 0.0021},
                                  {Method::JET, 0.003, 0.0032, 0.003, 0.0032},
                                  {Method::WAVEJET, 0.003, 0.0032, 0.003, 0.0032},
                                  {Method::VCM, 0, 0, regression_only(1.1), regression_only(1.26)}};
  for(const Tolerance& t : tolerances)
  {
    const Estimates est = run(t.m, pts, r);
    const Errors e = errors(kind(t.m), est, pts, truth);
    print_row(name(t.m), e);
    INFO(name(t.m));
    CHECK(e.valid == pts.size());
    check_fields(t.m, est[123]);
    check_bounds(kind(t.m), e, t.mean_H, t.max_H, t.mean_k, t.max_k);
    // normals: exact for ASO (acos resolves 1e-6 degree); the others x1.5
    if(t.m == Method::ASO)
      CHECK(e.normal.max < 1e-5);
    else if(t.m == Method::PCA_PLANE)
      CHECK(e.normal.max < 0.75);
    else if(t.m == Method::VCM)
      CHECK(e.normal.max < 1.6);
    else if(t.m != Method::BARYCENTER)
      CHECK(e.normal.max < 0.0027);
  }
  // VCM with the offset radius at the feature size: the cell-spread bias shrinks as 1/R²
  const Estimates vcm =
    CGAL::estimate_vcm_curvatures<CGAL::Parallel_tag>(pts, r, PSC::parameters::vcm_offset_radius(R, maps()));
  const Errors e = errors(Kind::MAGNITUDES, vcm, pts, truth);
  print_row("VCM (CGAL), R = 2 (feature size)", e);
  CHECK(e.k_min.mean() < 0.03);
  check_bounds(Kind::MAGNITUDES, e, 0, 0, 0.084, 0.123);
}

TEST_CASE("Inward normals flip the signed curvatures and the normals, not the magnitudes", "[baselines][sphere]")
{
  const Point c(0, 0, 0);
  const double R = 1, r = 0.2;
  const auto out = sphere(3000, R, c);
  const auto in = sphere(3000, R, c, true);
  for(Method m : all_methods)
  {
    INFO(name(m));
    const Estimates a = run(m, out, r), b = run(m, in, r);
    for(std::size_t i = 0; i < out.size(); i += 7)
    {
      REQUIRE(a[i].is_valid());
      REQUIRE(b[i].is_valid());
      if(kind(m) == Kind::SIGNED_TENSOR)
      {
        CHECK(a[i].mean_curvature > 0.9);
        CHECK(b[i].mean_curvature == Approx(-a[i].mean_curvature).epsilon(1e-9));
        CHECK(b[i].min_curvature == Approx(-a[i].max_curvature).epsilon(1e-9));
        CHECK(b[i].max_curvature == Approx(-a[i].min_curvature).epsilon(1e-9));
        CHECK(b[i].gaussian_curvature == Approx(a[i].gaussian_curvature).epsilon(1e-9));
      }
      else if(m == Method::VCM)  // magnitudes: the same cells, the same bits
      {
        CHECK(b[i].min_curvature == a[i].min_curvature);
        CHECK(b[i].max_curvature == a[i].max_curvature);
      }
      else
        CHECK(b[i].mean_curvature == a[i].mean_curvature);
      if(m != Method::BARYCENTER)
      {
        CHECK(a[i].normal * (out[i].second) > 0.999);
        CHECK(b[i].normal * (in[i].second) > 0.999);
      }
    }
  }
}

// Cylinder of radius 1 and height 3 (jittered grid, 6000 points), r = 0.2 (about 39
// neighbours); points closer than r to the rims are excluded (one-sided neighbourhoods bias
// every estimator, ASO up to 0.3 in H). Truth: k_min = 0 along the axis, k_max = 1, H = 0.5.
// Measured mean / max errors (tolerances x1.5):
//   H: ASO 0.0020 / 0.017, PSS 0.0024 / 0.0028, jets and wavejets 0.0039 / 0.0049,
//      PCA plane 0.033 / 0.14, barycenter 0.52 / 2.0 (the grid's anisotropic spacing,
//      0.063 x 0.05, drifts the barycenter);
//   k_min, k_max (worse of the two): ASO 0.0028 / 0.022, PSS 0.0049 / 0.0056, jets and
//      wavejets 0.0078 / 0.0094;
//   direction of k_max (mean, degrees): ASO 0.071, PSS 0.004, jets 0.008, wavejets 0.007;
//   VCM: at R = r no curvature is resolved (magnitude errors 1.28 in mean, 3.5 at most: the
//      cell spread adds (2/r) sqrt(0.019) = 1.4 to the magnitudes), but its direction of the
//      larger magnitude is the circumference within 2.7 degrees (mean).
TEST_CASE("Cylinder: each estimator within its measured bounds, every bound below a constant zero's error",
          "[baselines][cylinder]")
{
  const double R = 1, height = 3, r = 0.2;
  const auto pts = cylinder(100, 60, R, height);
  auto truth = [&](const Point& p) { return cylinder_truth(p, R); };
  auto interior = [&](const Point& p) { return std::abs(p.z()) < 0.5 * height - r; };
  print_header("Cylinder R = 1, 6000 points, r = 0.2, points farther than r from the rims");
  // H = 0.5, k = 0 and 1. Regression bounds only for the barycenter (mean H error 0.52) and
  // VCM (1.28 on k_min): their errors exceed the curvatures; VCM's direction is bounded.
  struct Tolerance
  {
    Method m;
    Bound mean_H, max_H, mean_k, max_k;
    double direction;
  };
  const Tolerance tolerances[] = {{Method::ASO, 0.003, 0.026, 0.0043, 0.034, 0.11},
                                  {Method::BARYCENTER, regression_only(0.78), regression_only(3.0), 0, 0, 0},
                                  {Method::PCA_PLANE, 0.05, 0.21, 0, 0, 0},
                                  {Method::PSS, 0.0036, 0.0043, 0.0073, 0.0084, 0.006},
                                  {Method::JET, 0.0058, 0.0073, 0.012, 0.014, 0.012},
                                  {Method::WAVEJET, 0.0058, 0.0073, 0.012, 0.014, 0.011},
                                  {Method::VCM, 0, 0, regression_only(1.9), regression_only(5.2), 4.0}};
  for(const Tolerance& t : tolerances)
  {
    const Estimates est = run(t.m, pts, r);
    const Errors e = errors(kind(t.m), est, pts, truth, interior);
    print_row(name(t.m), e);
    INFO(name(t.m));
    CHECK(e.valid == e.considered);
    check_fields(t.m, est[2000]);
    check_bounds(kind(t.m), e, t.mean_H, t.max_H, t.mean_k, t.max_k);
    if(kind(t.m) != Kind::UNSIGNED_MEAN)
      CHECK(e.direction.mean() < t.direction);
  }
}

// Ellipsoid with semi-axes 1, 0.7, 0.5 (curvatures 0.5 to 4), 10000 i.i.d. points
// (psc_test::ellipsoid: normalised Gaussian directions), r = 0.09 (about 39 neighbours).
// Random sampling is irregular at the scale of the neighbourhoods, which hurts the
// estimators that differentiate the weights (ASO) or use the barycenter. Measured mean / max
// errors (tolerances x1.5), ASO the default variant (the paper's: H 0.038 / 0.73, k 0.049 /
// 0.93; the default's sample weights and kernel cut them 2.7 times, PSS stays ahead here):
//   H: ASO 0.0141 / 0.258, PSS 0.0093 / 0.066, jets 0.013 / 0.10, wavejets 0.014 / 0.11,
//      PCA plane 0.14 / 0.92, barycenter 3.3 / 17.5 (useless here: above H itself, a
//      regression bound only);
//   k_min, k_max (worse of the two): ASO 0.0194 / 0.579, PSS 0.015 / 0.11, jets 0.021 / 0.17,
//      wavejets 0.021 / 0.18; VCM magnitudes 3.3 / 5.6 (above the curvatures, regression only).
TEST_CASE(
  "Ellipsoid (random sampling): each estimator within its measured bounds, every bound below a constant zero's error",
  "[baselines][ellipsoid]")
{
  const double a = 1, b = 0.7, c = 0.5, r = 0.09;
  const auto pts = ellipsoid(10000, a, b, c);
  auto truth = [&](const Point& p) { return ellipsoid_truth(p, a, b, c); };
  print_header("Ellipsoid 1 x 0.7 x 0.5, 10000 random points, r = 0.09");
  struct Tolerance
  {
    Method m;
    Bound mean_H, max_H, mean_k, max_k;
  };
  const Tolerance tolerances[] = {{Method::ASO, 0.021, 0.39, 0.029, 0.87},
                                  {Method::BARYCENTER, regression_only(5.0), regression_only(26), 0, 0},
                                  {Method::PCA_PLANE, 0.22, 1.4, 0, 0},
                                  {Method::PSS, 0.014, 0.099, 0.023, 0.165},
                                  {Method::JET, 0.02, 0.153, 0.032, 0.25},
                                  {Method::WAVEJET, 0.02, 0.168, 0.032, 0.276},
                                  {Method::VCM, 0, 0, regression_only(4.9), regression_only(8.3)}};
  for(const Tolerance& t : tolerances)
  {
    const Estimates est = run(t.m, pts, r);
    const Errors e = errors(kind(t.m), est, pts, truth);
    print_row(name(t.m), e);
    INFO(name(t.m));
    // every point is valid but those below the estimator's measured minimum (20 for the
    // barycenter and VCM: 27 of the 10000 points of this irregular sample)
    std::size_t too_few = 0;
    for(const auto& x : est)
      too_few += x.status == CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS && x.neighbor_count < 20;
    CHECK(e.valid + too_few == pts.size());
    CHECK(too_few <= 30);
    check_bounds(kind(t.m), e, t.mean_H, t.max_H, t.mean_k, t.max_k);
  }
}

// ---------------------------------------------------------------------------------------
// Comparisons with CGAL and between full-tensor estimators
// ---------------------------------------------------------------------------------------

// estimate_jet_curvatures() is CGAL's Monge_via_jet_fitting on the package's neighbourhoods:
// a direct call of CGAL's class, in absolute coordinates, with the neighbours found by brute
// force and the query point first, gives the same curvatures to rounding (measured: 5e-14
// relative at most; the fit is invariant to the scaled frame up to rounding; bound 1e-8).
// With the query point NOT first, CGAL evaluates the jet at another neighbour: curvatures
// then differ by up to 31% of their magnitude over these 271 points (bound: more than 10%),
// the mistake this test would catch.
TEST_CASE("estimate_jet_curvatures agrees with a direct call of CGAL::Monge_via_jet_fitting", "[baselines][jet][cgal]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  const Estimates jets = run(Method::JET, pts, r);
  typedef CGAL::Monge_via_jet_fitting<Kernel> Fitter;
  double worst = 0, worst_not_first = 0;
  for(std::size_t i = 0; i < pts.size(); i += 37)
  {
    const Point& x = pts[i].first;
    std::vector<Point> first, last;
    first.push_back(x);
    for(const auto& p : pts)
      if(CGAL::squared_distance(p.first, x) < r * r && p.first != x)
      {
        first.push_back(p.first);
        last.push_back(p.first);
      }
    last.push_back(x);
    Fitter fitter;
    Fitter::Monge_form monge = fitter(first.begin(), first.end(), 2, 2);
    monge.comply_wrt_given_normal(pts[i].second);
    Fitter::Monge_form other = fitter(last.begin(), last.end(), 2, 2);
    other.comply_wrt_given_normal(pts[i].second);
    const auto& e = jets[i];
    REQUIRE(e.is_valid());
    CHECK(e.neighbor_count == first.size());
    const double scale = std::max(std::abs(e.min_curvature), std::abs(e.max_curvature));
    worst = std::max({worst, std::abs(e.min_curvature + monge.principal_curvatures(0)) / scale,
                      std::abs(e.max_curvature + monge.principal_curvatures(1)) / scale});
    worst_not_first = std::max({worst_not_first, std::abs(e.min_curvature + other.principal_curvatures(0)) / scale,
                                std::abs(e.max_curvature + other.principal_curvatures(1)) / scale});
    CHECK(angle_degrees(e.normal, monge.normal_direction()) < 1e-5);  // acos resolves 1e-6 degree
    if(e.max_curvature - e.min_curvature > 1e-3 * scale)              // directions defined away from umbilics
      CHECK(line_angle_degrees(e.min_direction, monge.maximal_principal_direction()) < 1e-5);
  }
  std::cout << "\nJets vs direct CGAL call on Goursat 10K, r = 1.5: max relative difference " << worst
            << " with the query first, " << worst_not_first << " with the query last" << std::endl;
  CHECK(worst < 1e-8);
  CHECK(worst_not_first > 0.1);
}

namespace {

// Mean over the points valid for both of |k_min - k_min'| + |k_max - k_max'| / 2.
double mean_disagreement(const Estimates& a, const Estimates& b)
{
  double s = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].is_valid() && b[i].is_valid())
    {
      s +=
        0.5 * (std::abs(a[i].min_curvature - b[i].min_curvature) + std::abs(a[i].max_curvature - b[i].max_curvature));
      ++n;
    }
  return n ? s / double(n) : std::numeric_limits<double>::infinity();
}

// Mean over the points of |k_min - k_min_t| + |k_max - k_max_t| / 2 (magnitudes for VCM).
double mean_tensor_error(Kind k, const Estimates& est, const std::vector<Oriented_point>& pts,
                         const std::function<Truth(const Point&)>& truth)
{
  const Errors e = errors(k, est, pts, truth);
  REQUIRE(e.valid == pts.size());
  return 0.5 * (e.k_min.mean() + e.k_max.mean());
}

}  // namespace

// The full-tensor estimators agree with each other and with CGAL's jet fitting: mean of
// (|Δk_min| + |Δk_max|)/2 between every pair, on Goursat 10K at r = 1.5 (39 neighbours;
// curvatures up to 0.42) and on the random ellipsoid (curvatures 0.5 to 4). Measured
// (bounds x1.5): Goursat: PSS-jets and PSS-wavejets 0.0030, ASO to the others 0.0043 to
// 0.0066, jets-wavejets 9e-5 (the same quadratic over nearly the same plane); ellipsoid:
// PSS-jets 0.0092, ASO to the others 0.050 to 0.054 (ASO is the outlier on random sampling,
// see the ellipsoid test), jets-wavejets 0.0005.
TEST_CASE("Full-tensor estimators agree with each other and with CGAL jet fitting", "[baselines][cgal][agreement]")
{
  const Method tensors[] = {Method::ASO, Method::PSS, Method::JET, Method::WAVEJET};
  struct Cloud
  {
    const char* title;
    std::vector<Oriented_point> pts;
    double r;
    double bound, aso_bound;
  };
  const Cloud clouds[] = {{"Goursat 10K, r = 1.5", goursat_10k(), 1.5, 0.0045, 0.01},
                          {"ellipsoid 10K random, r = 0.09", ellipsoid(10000, 1, 0.7, 0.5), 0.09, 0.014, 0.081}};
  for(const Cloud& cloud : clouds)
  {
    std::vector<Estimates> est;
    for(Method m : tensors)
      est.push_back(run(m, cloud.pts, cloud.r));
    std::cout << "\nMean disagreement (|dk_min| + |dk_max|)/2, " << cloud.title
              << "\n|   | ASO | PSS | jet | wavejet |\n|---|---|---|---|---|\n";
    for(std::size_t i = 0; i < 4; ++i)
    {
      std::cout << "| " << name(tensors[i]) << " |";
      for(std::size_t j = 0; j < 4; ++j)
        std::cout << " " << std::setprecision(3) << mean_disagreement(est[i], est[j]) << " |";
      std::cout << "\n";
    }
    for(std::size_t i = 0; i < 4; ++i)
      for(std::size_t j = i + 1; j < 4; ++j)
      {
        INFO(cloud.title << ": " << name(tensors[i]) << " vs " << name(tensors[j]));
        CHECK(mean_disagreement(est[i], est[j]) < (i == 0 ? cloud.aso_bound : cloud.bound));
      }
    // jets and wavejets fit the same quadratic over nearly the same plane
    CHECK(mean_disagreement(est[2], est[3]) < 0.06 * cloud.bound);
  }
}

// The paper's claim (Section 6.1): ASO is at least as accurate as osculating jets and VCM
// against the analytic values, on the same neighbourhoods, on the Goursat surface sampled
// by Lloyd relaxation with r = 5% of the bounding box diagonal (1.67 here, 48 neighbours).
// Measured mean (|Δk_min| + |Δk_max|)/2: ASO 0.0036, jets 0.0049 (PSS 0.0032); on the
// magnitudes, VCM 0.099 (R = r) and 0.24 (R = 0.5 r, the paper's setting); mean |ΔH|:
// ASO 0.0030, jets 0.0045 (PSS 0.0030). The assertions are the paper's inequalities.
// Also printed, not asserted: ASO against jets at about 40 neighbours on Goursat 10K and on
// the two ellipsoids (measured: Goursat 10K, r = 1.5: ASO 0.0038, jets 0.0043; regular
// ellipsoid: ASO 0.0085, jets 0.013; random ellipsoid: ASO 0.048, jets 0.014). The claim
// fails on random sampling, and also on Goursat 50K at r = 0.67, 39 neighbours (ASO 0.0019,
// jets 0.0013, PSS 0.0007; not run here, 5 s): ASO needs a locally regular sampling, and at
// a fixed neighbour count its error decreases more slowly than the jets' as r shrinks.
TEST_CASE("ASO is at least as accurate as CGAL jets and VCM on Goursat (paper setting)", "[baselines][cgal][accuracy]")
{
  const auto& pts = goursat_10k();
  const double r = 0.05 * 2 * std::sqrt(3.0) * 9.6608;  // 5% of the bounding box diagonal
  auto truth = [](const Point& p) { return goursat_truth(p); };
  const Estimates aso = run(Method::ASO, pts, r), jet = run(Method::JET, pts, r);
  const Estimates vcm = run(Method::VCM, pts, r);
  const Estimates vcm_half =
    CGAL::estimate_vcm_curvatures<CGAL::Parallel_tag>(pts, r, PSC::parameters::vcm_offset_radius(0.5 * r, maps()));
  print_header("Goursat 10K, r = 1.673 (5% of the diagonal, the paper's setting)");
  const Errors e_aso = errors(Kind::SIGNED_TENSOR, aso, pts, truth);
  const Errors e_jet = errors(Kind::SIGNED_TENSOR, jet, pts, truth);
  print_row("ASO", e_aso);
  print_row("jet (CGAL)", e_jet);
  print_row("PSS", errors(Kind::SIGNED_TENSOR, run(Method::PSS, pts, r), pts, truth));
  print_row("wavejet", errors(Kind::SIGNED_TENSOR, run(Method::WAVEJET, pts, r), pts, truth));
  print_row("VCM (CGAL), R = r", errors(Kind::MAGNITUDES, vcm, pts, truth));
  print_row("VCM (CGAL), R = 0.5 r", errors(Kind::MAGNITUDES, vcm_half, pts, truth));

  const double aso_k = mean_tensor_error(Kind::SIGNED_TENSOR, aso, pts, truth);
  const double jet_k = mean_tensor_error(Kind::SIGNED_TENSOR, jet, pts, truth);
  // VCM only has magnitudes: compare ASO's magnitudes with VCM's, on the same terms
  const double aso_abs = mean_tensor_error(Kind::MAGNITUDES, aso, pts, truth);
  const double vcm_abs = mean_tensor_error(Kind::MAGNITUDES, vcm, pts, truth);
  const double vcm_half_abs = mean_tensor_error(Kind::MAGNITUDES, vcm_half, pts, truth);
  CHECK(aso_k <= jet_k);
  CHECK(e_aso.H.mean() <= e_jet.H.mean());
  CHECK(aso_abs <= vcm_abs);
  CHECK(aso_abs <= vcm_half_abs);

  // Where the claim does not hold: ASO needs a locally regular sampling.
  std::cout << "\nASO vs CGAL jets, mean (|dk_min| + |dk_max|)/2 against the truth, about 40 neighbours:\n"
            << "| cloud | r | ASO | jet | PSS |\n|---|---|---|---|---|\n";
  struct Case
  {
    std::string title;
    std::vector<Oriented_point> pts;
    double r;
    std::function<Truth(const Point&)> truth;
  };
  const double a = 1, b = 0.7, c = 0.5;
  auto ell = [=](const Point& p) { return ellipsoid_truth(p, a, b, c); };
  const Case cases[] = {{"Goursat 10K (Lloyd)", goursat_10k(), 1.5, truth},
                        {"ellipsoid 10K regular (Fibonacci)", regular_ellipsoid(10000, a, b, c), 0.09, ell},
                        {"ellipsoid 10K random", ellipsoid(10000, a, b, c), 0.09, ell}};
  for(const Case& k : cases)
  {
    const double e_a = mean_tensor_error(Kind::SIGNED_TENSOR, run(Method::ASO, k.pts, k.r), k.pts, k.truth);
    const double e_j = mean_tensor_error(Kind::SIGNED_TENSOR, run(Method::JET, k.pts, k.r), k.pts, k.truth);
    const double e_p = mean_tensor_error(Kind::SIGNED_TENSOR, run(Method::PSS, k.pts, k.r), k.pts, k.truth);
    std::cout << "| " << k.title << " | " << k.r << " | " << e_a << " | " << e_j << " | " << e_p << " |\n";
    if(e_a > e_j)
      WARN(k.title << ": ASO less accurate than CGAL jets (" << e_a << " > " << e_j << ")");
  }
  std::cout << std::flush;
}

// ---------------------------------------------------------------------------------------
// API: overloads, containers, kernels, concurrency
// ---------------------------------------------------------------------------------------

// Sequential and parallel runs are identical, bit for bit, on the simulated LiDAR scan
// (anisotropic sampling and depth noise: a few points have too few neighbours); VCM up to
// the rounding of CGAL's Voronoi cells, which differs between any two calls.
TEST_CASE("Sequential and parallel runs give identical results", "[baselines][parallel]")
{
  const auto pts = read_xyz(repo_data("goursat-lidar.xyz"));
  const double r = 2.0;
  for(Method m : baselines)
  {
    INFO(name(m));
    const Estimates s = run<CGAL::Sequential_tag>(m, pts, r);
    const Estimates p = run<CGAL::Parallel_tag>(m, pts, r);
    REQUIRE(s.size() == p.size());
    std::size_t different = 0, valid = 0;
    for(std::size_t i = 0; i < s.size(); ++i)
    {
      different += reproduced(m, s[i], p[i], r) ? 0 : 1;
      valid += s[i].is_valid() ? 1 : 0;
    }
    CHECK(different == 0);
    CHECK(valid > pts.size() * 9 / 10);
  }
}

TEST_CASE("The three overloads, Point_set_3 and Epick give identical results", "[baselines][api]")
{
  const auto pts = sphere(2000, 1.0, Point(0.5, 0, 0));
  const double r = 0.3;
  CGAL::Point_set_3<Epick::Point_3, Epick::Vector_3> eps;
  eps.add_normal_map();
  for(const auto& p : pts)
    eps.insert(Epick::Point_3(p.first.x(), p.first.y(), p.first.z()),
               Epick::Vector_3(p.second.x(), p.second.y(), p.second.z()));
  for(Method m : baselines)
  {
    INFO(name(m));
    const Estimates ref = run<CGAL::Sequential_tag>(m, pts, r);
    const Estimates explicit_maps = run_explicit_maps(m, pts, r);
    const std::vector<CGAL::Curvature_estimate<Epick> > e = run<CGAL::Sequential_tag>(m, eps, r, eps.parameters());
    std::size_t different = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      different += (reproduced(m, ref[i], explicit_maps[i], r) && reproduced(m, ref[i], e[i], r)) ? 0 : 1;
    CHECK(different == 0);
  }
}

// Neighbourhoods by count: the (points, np) overloads with neighbor_count(k). On the
// Fibonacci sphere the k-th neighbour distance is nearly uniform, so the accuracy is that
// of the radius runs (measured mean errors by count, radius in parentheses: PSS 0.0013
// (0.0013), jets and wavejets 0.0020 (0.0020), PCA plane 0.015 (0.014), barycenter 0.18
// (0.13), VCM 0.75 (0.74)); tolerances x1.5. Sequential and parallel runs agree (on a
// smaller sphere).
TEST_CASE("Neighbourhoods by count: every function, same accuracy as by radius", "[baselines][count]")
{
  const double R = 2;
  const auto pts = sphere(10000, R);
  const std::size_t k = 40;
  print_header("Sphere R = 2, 10000 points, 40 nearest neighbours");
  for(Method m : baselines)
  {
    INFO(name(m));
    const Estimates est = run_by_count<CGAL::Parallel_tag>(m, pts, k);
    const Errors e = errors(kind(m), est, pts, [&](const Point& p) { return sphere_truth(p, Point(0, 0, 0), R); });
    CHECK(e.valid == pts.size());
    std::size_t fewer = 0;
    for(const auto& x : est)
      fewer += x.neighbor_count < k ? 1 : 0;
    CHECK(fewer == 0);
    print_row(name(m), e);
    switch(m)
    {
      case Method::BARYCENTER: CHECK(e.H.mean() < 0.27); break;
      case Method::PCA_PLANE: CHECK(e.H.mean() < 0.023); break;
      case Method::VCM: CHECK(std::max(e.k_min.mean(), e.k_max.mean()) < 1.13); break;
      case Method::PSS: CHECK(std::max(e.k_min.mean(), e.k_max.mean()) < 0.002); break;
      default: CHECK(std::max(e.k_min.mean(), e.k_max.mean()) < 0.0031); break;
    }
    const auto small = sphere(2000, 1.0);
    const Estimates s = run_by_count<CGAL::Sequential_tag>(m, small, 20);
    const Estimates p = run_by_count<CGAL::Parallel_tag>(m, small, 20);
    std::size_t different = 0;
    for(std::size_t i = 0; i < small.size(); ++i)
      different += reproduced(m, s[i], p[i], 0.1) ? 0 : 1;
    CHECK(different == 0);
  }
}

// Far from the origin (LiDAR coordinates near 1e6): the estimators see the scaled centred
// frame, VCM goes through CGAL in absolute coordinates. The curvatures of the sphere move
// by less than 1e-6 relative (measured 1e-9 for the fits, 4e-8 for VCM).
TEST_CASE("Coordinates far from the origin change nothing", "[baselines][numerics]")
{
  const double R = 1, r = 0.2;
  const auto near = sphere(3000, R);
  const auto far = sphere(3000, R, Point(1e6, -2e6, 5e5));
  for(Method m : baselines)
  {
    INFO(name(m));
    const Estimates a = run(m, near, r), b = run(m, far, r);
    double worst = 0;
    for(std::size_t i = 0; i < near.size(); ++i)
    {
      REQUIRE(b[i].is_valid());
      CHECK(a[i].neighbor_count == b[i].neighbor_count);
      if(kind(m) != Kind::MAGNITUDES)
        worst = std::max(worst, std::abs(a[i].mean_curvature - b[i].mean_curvature));
      if(kind(m) != Kind::UNSIGNED_MEAN)
        worst = std::max({worst, std::abs(a[i].min_curvature - b[i].min_curvature),
                          std::abs(a[i].max_curvature - b[i].max_curvature)});
    }
    CHECK(worst < 1e-6);
  }
}

// ---------------------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------------------

TEST_CASE("Invalid radius, scale or options throw std::invalid_argument naming the parameter", "[baselines][errors]")
{
  const auto pts = sphere(500, 1.0);
  const double bad[] = {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()};
  for(Method m : baselines)
  {
    INFO(name(m));
    for(double r : bad)
      CHECK_THROWS_WITH(run(m, pts, r), Catch::Contains("'radius'") && Catch::Contains("estimate_"));
    // by count without neighbor_count, or with both a radius and neighbor_count
    const auto np = maps();
    const auto both = PSC::parameters::neighbor_count(10, maps());
    CHECK_THROWS_AS(run_without_radius<CGAL::Sequential_tag>(m, pts, np), std::invalid_argument);
    CHECK_THROWS_AS(run<CGAL::Sequential_tag>(m, pts, 0.2, both), std::invalid_argument);
  }
  SECTION("jet degrees")
  {
    auto jets = [&](int fitting, int monge) {
      return CGAL::estimate_jet_curvatures<CGAL::Sequential_tag>(
        pts, 0.2,
        CGAL::parameters::degree_fitting(fitting).degree_monge(monge).point_map(Point_map()).normal_map(Normal_map()));
    };
    CHECK_THROWS_WITH(jets(2, 1), Catch::Contains("'degree_monge'"));
    CHECK_THROWS_WITH(jets(4, 5), Catch::Contains("'degree_monge'"));
    CHECK_THROWS_WITH(jets(1, 2), Catch::Contains("'degree_fitting'"));
    CHECK_THROWS_WITH(jets(2, 3), Catch::Contains("'degree_fitting'"));
    CHECK_THROWS_WITH(jets(13, 2), Catch::Contains("'degree_fitting'"));
    CHECK_THROWS_WITH(jets(-3, 2), Catch::Contains("'degree_fitting'"));
    CHECK_NOTHROW(jets(4, 4));
  }
  SECTION("VCM offset radius")
  {
    for(double R : bad)
      CHECK_THROWS_WITH(
        CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(pts, 0.2, PSC::parameters::vcm_offset_radius(R, maps())),
        Catch::Contains("'vcm_offset_radius'"));
  }
}

// Isolated clusters of m points on small spherical caps (irregular positions, so that no
// fit is degenerate by symmetry), 100 r apart: every point has exactly m neighbours.
// m = minimum - 1 gives TOO_FEW_NEIGHBORS with the count and NaN elsewhere, m = minimum
// gives valid estimates.
TEST_CASE("Too few neighbours: status, count and NaN at the threshold of each estimator", "[baselines][status]")
{
  const double r = 1.0;
  auto clusters = [&](std::size_t m) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    std::vector<Oriented_point> pts;
    for(int c = 0; c < 5; ++c)
    {
      const Point centre(100.0 * c, 0, 0);
      for(std::size_t i = 0; i < m; ++i)
      {
        const double x = i == 0 ? 0 : u(rng), y = i == 0 ? 0 : u(rng);
        const double z = -0.2 * (x * x + y * y) + 0.05 * x * y;  // curved, not a quadric of revolution
        pts.emplace_back(centre + Vector(x, y, z), Vector(0, 0, 1));
      }
    }
    return pts;
  };
  struct Threshold
  {
    Method m;
    std::size_t minimum;
    std::function<Estimates(const std::vector<Oriented_point>&)> run;
  };
  std::vector<Threshold> thresholds;
  for(Method m : all_methods)
  {
    thresholds.push_back(
      {m, minimum_neighbors(m), [m, r](const std::vector<Oriented_point>& p) { return run(m, p, r); }});
    // a threshold below the fit's own minimum is raised to it
    thresholds.push_back({m, fit_minimum_neighbors(m), [m, r](const std::vector<Oriented_point>& p) {
                            return run<CGAL::Parallel_tag>(m, p, r, PSC::parameters::min_neighbors(1, maps()));
                          }});
  }
  thresholds.push_back({Method::JET, 10, [r](const std::vector<Oriented_point>& p) {
                          return CGAL::estimate_jet_curvatures<CGAL::Parallel_tag>(
                            p, r,
                            PSC::parameters::min_neighbors(
                              1, CGAL::parameters::degree_fitting(3).point_map(Point_map()).normal_map(Normal_map())));
                        }});
  for(const Threshold& t : thresholds)
  {
    INFO(name(t.m) << ", minimum " << t.minimum);
    const auto few = clusters(t.minimum - 1);
    const Estimates a = t.run(few);
    for(const auto& e : a)
    {
      CHECK(e.status == CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS);
      CHECK(e.neighbor_count == t.minimum - 1);
      CHECK(all_nan(e));
    }
    const auto enough = clusters(t.minimum);
    const Estimates b = t.run(enough);
    for(const auto& e : b)
    {
      CHECK(e.status == CGAL::Curvature_estimate_status::VALID);
      CHECK(e.neighbor_count == t.minimum);
    }
  }
}

TEST_CASE("Non-finite points and invalid normals get their status and NaN, and are nobody's neighbour",
          "[baselines][status]")
{
  auto pts = sphere(2000, 1.0);
  const double r = 0.3;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Estimates clean_vcm = run(Method::VCM, pts, r);
  pts[10].first = Point(nan, 0, 0);
  pts[20].second = Vector(0, 0, 0);
  pts[30].first = Point(std::numeric_limits<double>::infinity(), 1, 2);
  pts[40].second = Vector(nan, 1, 0);
  for(Method m : baselines)
  {
    INFO(name(m));
    const Estimates e = run(m, pts, r);
    CHECK(e[10].status == CGAL::Curvature_estimate_status::NON_FINITE_POINT);
    CHECK(e[30].status == CGAL::Curvature_estimate_status::NON_FINITE_POINT);
    CHECK(e[20].status == CGAL::Curvature_estimate_status::INVALID_NORMAL);
    CHECK(e[40].status == CGAL::Curvature_estimate_status::INVALID_NORMAL);
    for(std::size_t i : {10, 20, 30, 40})
    {
      CHECK(all_nan(e[i]));
      CHECK(e[i].neighbor_count == 0);
    }
    std::size_t valid = 0;
    for(const auto& x : e)
      valid += x.is_valid() ? 1 : 0;
    CHECK(valid == pts.size() - 4);
    // the neighbours of point 20 (its normal is zero) do not count it
    std::size_t expected = 0;
    for(std::size_t j = 0; j < pts.size(); ++j)
      if(j != 10 && j != 20 && j != 30 && j != 40 && CGAL::squared_distance(pts[j].first, pts[21].first) < r * r)
        ++expected;
    CHECK(e[21].neighbor_count == expected);
  }
}

// VCM's cells are cut and integrated by the package (vcm_cells.h) from CGAL's Delaunay
// triangulation, because CGAL's compute_vcm() depends on memory addresses: they are CGAL's
// cells all the same. Measured on a sphere and a cylinder: the magnitudes from CGAL's
// covariances and the package's agree within 3.9e-15 and 3.5e-15 relative (k_max).
TEST_CASE("VCM: the package's cells give CGAL's compute_vcm() magnitudes to rounding", "[baselines][vcm][cgal]")
{
  for(int shape = 0; shape < 2; ++shape)
  {
    const auto pts = shape == 0 ? sphere(3000, 2.0) : cylinder(60, 50, 1.0, 4.0);
    const double r = shape == 0 ? 0.4 : 0.5, R = 0.3;
    INFO((shape == 0 ? "sphere" : "cylinder"));
    const Estimates e =
      CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(pts, r, PSC::parameters::vcm_offset_radius(R, maps()));
    std::vector<Epick::Point_3> positions;
    for(const auto& p : pts)
      positions.emplace_back(p.first.x(), p.first.y(), p.first.z());
    std::vector<std::array<double, 6> > cov;
    CGAL::compute_vcm(positions, cov, R, r);
    double worst = 0;
    std::size_t compared = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      if(!e[i].is_valid())
        continue;
      const double n[3] = {pts[i].second.x(), pts[i].second.y(), pts[i].second.z()};
      const PSC::internal::Local_estimate c = PSC::internal::vcm_curvature_estimate(cov[i], r, n);
      REQUIRE(c.status == CGAL::Curvature_estimate_status::VALID);
      worst = std::max(worst, std::abs(c.k_max - e[i].max_curvature) / std::abs(c.k_max));
      ++compared;
    }
    if(std::getenv("PSC_TEST_PRINT"))
      std::printf("[measured] VCM k_max, package against compute_vcm, relative: %.3g\n", worst);
    CHECK(compared > pts.size() * 9 / 10);
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("VCM: a collinear cloud is degenerate, the callback can cancel", "[baselines][vcm]")
{
  std::vector<Oriented_point> line;
  for(int i = 0; i < 50; ++i)
    line.emplace_back(Point(0.01 * i, 0, 0), Vector(0, 0, 1));
  // (19 neighbours at most: below VCM's default minimum of 20, so the fit's own minimum)
  for(const auto& e : run<CGAL::Parallel_tag>(Method::VCM, line, 0.1, PSC::parameters::min_neighbors(3, maps())))
  {
    CHECK(e.status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
    CHECK(all_nan(e));
  }
  const auto pts = sphere(2000, 1.0);
  const double r = 0.3;
  std::vector<double> progress;
  const Estimates all = CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(pts, r,
                                                                            CGAL::parameters::callback([&](double f) {
                                                                              progress.push_back(f);
                                                                              return true;
                                                                            })
                                                                              .point_map(Point_map())
                                                                              .normal_map(Normal_map()));
  REQUIRE(!progress.empty());
  CHECK(progress.front() == 0.0);
  CHECK(progress.back() == 1.0);
  CHECK(std::is_sorted(progress.begin(), progress.end()));
  // reports every 1% of the cells, then of the diagonalisations (half the fraction each)
  double gap = 0;
  for(std::size_t i = 1; i < progress.size(); ++i)
    gap = std::max(gap, progress[i] - progress[i - 1]);
  CHECK(gap <= 0.0051);
  const Estimates ref = run<CGAL::Sequential_tag>(Method::VCM, pts, r);
  std::size_t different = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    different += same_estimate(all[i], ref[i]) ? 0 : 1;
  CHECK(different == 0);
  const Estimates cancelled = CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(
    pts, r, CGAL::parameters::callback([](double) { return false; }).point_map(Point_map()).normal_map(Normal_map()));
  for(const auto& e : cancelled)
  {
    CHECK(e.status == CGAL::Curvature_estimate_status::NOT_COMPUTED);
    CHECK(all_nan(e));
  }
}

// ---------------------------------------------------------------------------------------
// Degenerate neighbourhoods that once produced garbage marked valid, or crashed.

TEST_CASE("Baselines: one scan line is DEGENERATE_FIT, not a valid zero curvature", "[baselines][bad_input]")
{
  // The curve y = x^3 + x^2/2 in the plane z = 0 with in-plane normals: every neighbourhood
  // is a planar curve, so the curvature across it is not measured. Before the tangent-spread
  // check, PSS, jets, wavejets and the PCA plane returned VALID zero curvature with a normal
  // orthogonal to the input normal, and VCM a VALID k_max on a circle.
  std::vector<Oriented_point> curve;
  for(int i = -100; i <= 100; ++i)
  {
    const double x = 0.005 * i, y = x * x * x + 0.5 * x * x;
    const Vector tangent(1, 3 * x * x + x, 0);
    curve.emplace_back(Point(x, y, 0), Vector(-tangent.y(), tangent.x(), 0) / std::sqrt(tangent.squared_length()));
  }
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  const double r = 0.1;
  auto all_degenerate = [](const std::vector<CGAL::Curvature_estimate<Kernel> >& e) {
    for(const auto& x : e)
      if(x.is_valid())
        return false;
    return true;
  };
  CHECK(all_degenerate(CGAL::estimate_barycenter_curvatures<CGAL::Sequential_tag>(curve, r, np)));
  CHECK(all_degenerate(CGAL::estimate_pca_plane_curvatures<CGAL::Sequential_tag>(curve, r, np)));
  CHECK(all_degenerate(CGAL::estimate_pss_curvatures<CGAL::Sequential_tag>(curve, r, np)));
  CHECK(all_degenerate(CGAL::estimate_jet_curvatures<CGAL::Sequential_tag>(curve, r, np)));
  CHECK(all_degenerate(CGAL::estimate_wavejet_curvatures<CGAL::Sequential_tag>(curve, r, np)));
  CHECK(all_degenerate(CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(curve, r, np)));
  const auto e = CGAL::estimate_pss_curvatures<CGAL::Sequential_tag>(curve, r, np);
  CHECK(e[100].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
  CHECK(e[100].neighbor_count > 30);
}

TEST_CASE("Jets by count on coincident points are DEGENERATE_FIT (CGAL's fitting is not called)",
          "[baselines][bad_input]")
{
  // CGAL's Monge_via_jet_fitting indexed Eigen blocks with negative sizes on coincident points
  // (an assertion failure; undefined behaviour in Release).
  // 12 points: the jets' default minimum
  std::vector<Oriented_point> same(12, Oriented_point(Point(1, 2, 3), Vector(0, 0, 1)));
  const auto np = CGAL::Point_set_curvatures::parameters::neighbor_count(
    1000, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  const auto e = CGAL::estimate_jet_curvatures<CGAL::Sequential_tag>(same, np);
  for(const auto& x : e)
  {
    CHECK(x.status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
    CHECK(x.neighbor_count == 12);
  }
}

// A sphere of radius 1 far from the origin with `copies` more samples at its first point,
// copies up to rounding (near_copies()).
std::vector<Oriented_point> sphere_with_near_copies(std::size_t copies)
{
  std::vector<Oriented_point> pts = sphere(3000, 1, Point(1000, -2000, 500));
  const Oriented_point p = pts[0];
  for(const Point& q : near_copies(p.first, copies))
    pts.emplace_back(q, p.second);
  return pts;
}

TEST_CASE("Neighbours that coincide up to rounding are DEGENERATE_FIT, not curvatures of 1/rounding",
          "[baselines][bad_input]")
{
  // A drone's rosette scan (benchmark/scan_experiments `rosette`) passes over nadir 400 times, its
  // samples there within 1e-15 of one another: at 40 neighbours every estimator gave mean
  // curvatures of 1e8 to 1e11 there, reported valid (neighbourhoods of radius 1e-16, offsets that
  // are rounding errors). Here 60 samples within 5e-13 of the sphere's first point, 1000 units
  // from the origin (without the bound: valid, ASO H -7e10, PSS -1e12, jets -1e12): that point and its copies
  // are DEGENERATE_FIT, the points away from them valid and right.
  const std::size_t copies = 60;
  const auto pts = sphere_with_near_copies(copies);
  const std::size_t first = pts.size() - copies;
  auto check = [&](const Estimates& e, const char* what) {
    INFO(what);
    REQUIRE(e.size() == pts.size());
    std::size_t degenerate = e[0].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT ? 1 : 0;
    for(std::size_t i = first; i < pts.size(); ++i)
      degenerate += e[i].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT && std::isnan(e[i].mean_curvature);
    CHECK(degenerate == copies + 1);
    // (the points whose 40 nearest hold some of the copies may be degenerate too, or valid and
    // pulled by 61 samples at one place; farther away every estimate is valid)
    std::size_t far = 0, valid = 0;
    double worst = 0;
    for(std::size_t i = 1; i < first; ++i)
      if(std::sqrt(CGAL::squared_distance(pts[i].first, pts[0].first)) > 0.5)
      {
        ++far;
        valid += e[i].is_valid() ? 1 : 0;
        const double error = std::abs(e[i].mean_curvature - 1.0);
        worst = error <= worst ? worst : error;  // (NaN kept)
      }
    CHECK(valid == far);
    return worst;
  };
  for(Method m : all_methods)
  {
    const double worst = check(run_by_count<CGAL::Sequential_tag>(m, pts, 40), name(m));
    // the sphere's H is 1 (the PCA plane and the barycenter do not measure it, VCM gives k_max
    // only)
    if(m != Method::PCA_PLANE && m != Method::BARYCENTER && m != Method::VCM)
    {
      measured(std::string(name(m)) + ": largest |H - 1| away from the copies", worst);
      CHECK(worst < 0.05);
    }
  }
  const double worst = check(
    CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(40, maps())), "apss");
  measured("apss: largest |H - 1| away from the copies", worst);
  CHECK(worst < 0.05);
  const auto f =
    CGAL::estimate_algebraic_sphere_features<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(40, maps()));
  std::size_t degenerate = f[0].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT ? 1 : 0;
  for(std::size_t i = first; i < pts.size(); ++i)
    degenerate += f[i].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT ? 1 : 0;
  CHECK(degenerate == copies + 1);
}

TEST_CASE("VCM refuses coordinates beyond 1e150 instead of crashing in CGAL", "[baselines][vcm][bad_input]")
{
  // CGAL's Voronoi constructions square coordinates; at 1.5e308 its exact fallback raised
  // SIGFPE. The other estimators handle such clouds (far points are nobody's neighbour).
  std::vector<Oriented_point> pts = sphere(500, 1.0);
  pts.emplace_back(Point(-1.5e308, 0, 0), Vector(0, 0, 1));
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  CHECK_THROWS_AS(CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(pts, 0.3, np), std::invalid_argument);
  // ... and below 1e-100, where CGAL's exact fallback divided by zero (SIGFPE)
  std::vector<Oriented_point> tiny;
  for(const Oriented_point& p : sphere(500, 1.0))
    tiny.emplace_back(CGAL::ORIGIN + (p.first - CGAL::ORIGIN) * 1e-250, p.second);
  CHECK_THROWS_AS(CGAL::estimate_vcm_curvatures<CGAL::Sequential_tag>(tiny, 0.3e-250, np), std::invalid_argument);
  const auto aso = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 0.3, np);
  CHECK(aso[0].is_valid());
  CHECK(aso[500].status == CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS);
}

TEST_CASE("The 3x3 eigen-solver is scale invariant (VCM covariances scale as length^5)", "[baselines][internal]")
{
  // Eigenvalues 1, 3, 5 with a rotated basis, at scales where squares under- or overflow:
  // the Jacobi convergence test used to stop before any rotation there.
  for(double scale : {1.0, 1e-170, 1e-300, 1e160, 1e300})
  {
    const double m[6] = {2 * scale, -1 * scale, 0, 2 * scale, 0, 5 * scale};  // [[2,-1,0],[-1,2,0],[0,0,5]]
    double values[3], vectors[3][3];
    REQUIRE(CGAL::Point_set_curvatures::internal::symmetric_eigen_3(m, values, vectors));
    INFO("scale " << scale);
    CHECK(values[0] / scale == Approx(1).epsilon(1e-12));
    CHECK(values[1] / scale == Approx(3).epsilon(1e-12));
    CHECK(values[2] / scale == Approx(5).epsilon(1e-12));
    CHECK(std::abs(std::abs(vectors[0][0]) - std::sqrt(0.5)) < 1e-12);
  }
}

// =======================================================================================
// Beyond the paper: the default ASO (Aso_variant::ROBUST) against the paper's and PSS
// =======================================================================================

namespace {

typedef CGAL::Curvature_estimate_status Status;

double mean_H_error(const Estimates& est, const std::vector<Oriented_point>& truth_points)
{
  double sum = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < est.size(); ++i)
    if(est[i].is_valid())
    {
      sum += std::abs(est[i].mean_curvature - goursat_truth(truth_points[i].first).mean);
      ++n;
    }
  REQUIRE(n > 0.99 * double(est.size()));
  return sum / double(n);
}

auto paper_maps() { return PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, maps()); }

// Mean |H - H*| of the default ASO, the paper's ASO and PSS on a Goursat cloud, printed.
struct Three_errors
{
  double robust, paper, pss;
};
Three_errors default_paper_pss(const std::vector<Oriented_point>& pts, double r, const std::string& name)
{
  Three_errors e;
  e.robust = mean_H_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, maps()), pts);
  e.paper = mean_H_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, paper_maps()), pts);
  e.pss = mean_H_error(run(Method::PSS, pts, r), pts);
  measured(name + " mean |H - H*|: default ASO", e.robust);
  measured(name + " mean |H - H*|: paper's ASO", e.paper);
  measured(name + " mean |H - H*|: PSS", e.pss);
  return e;
}

}  // namespace

// The targets of the issue "an ASO that stays accurate on real sampling and imperfect
// normals", measured on the same clouds as benchmark/paper_experiments (experiment 7).
TEST_CASE("Default ASO: at least 4.6x the paper's accuracy on Goursat 50K, within 2% of it with 30% flipped normals, "
          "noisy normals refined",
          "[aso][robust]")
{
  const auto pts = read_xyz(repo_data("goursat_050000.xyz"));
  const double r = 1.5;
  const Three_errors e = default_paper_pss(pts, r, "Goursat 50K r=1.5");
  // Measured 0.255e-3, 1.20e-3, 2.40e-3 (the README's "4.7 times"). The issue's target for the
  // default: 0.30e-3. (Deterministic: the same bytes in every run.)
  CHECK(e.robust < 0.30e-3);
  CHECK(e.paper > 4.6 * e.robust);
  CHECK(e.robust < e.pss);

  // 30% of the normals flipped: the robust orientation uses them flipped back.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  auto flipped = pts;
  for(auto& p : flipped)
    if(u(rng) < 0.3)
      p.second = -p.second;
  const double robust_flipped =
    mean_H_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(flipped, r, maps()), pts);
  const double paper_flipped =
    mean_H_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(flipped, r, paper_maps()), pts);
  measured("Goursat 50K, 30% flipped: default ASO", robust_flipped);
  measured("Goursat 50K, 30% flipped: paper's ASO", paper_flipped);
  // Measured 0.257e-3 (0.8% above the clean value: nearly every flip is undone) and 21.0e-3.
  CHECK(robust_flipped < 1.02 * e.robust);
  CHECK(paper_flipped > 15e-3);

  // Every normal tilted by 30 degrees in a random tangent direction: two refinements.
  auto tilted = pts;
  for(auto& p : tilted)
  {
    const Vector n = p.second;
    const Vector a = std::abs(n.x()) < 0.9 ? Vector(1, 0, 0) : Vector(0, 1, 0);
    Vector t1 = CGAL::cross_product(n, a);
    t1 = t1 / std::sqrt(t1.squared_length());
    const Vector t2 = CGAL::cross_product(n, t1);
    const double phi = 2 * M_PI * u(rng), tilt = 30 * M_PI / 180;
    p.second = std::cos(tilt) * n + std::sin(tilt) * (std::cos(phi) * t1 + std::sin(phi) * t2);
  }
  const double tilted_default = mean_H_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(tilted, r, maps()), pts);
  const double tilted_refined = mean_H_error(
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(tilted, r, PSC::parameters::normal_refinement(1, maps())), pts);
  const double tilted_refined_twice = mean_H_error(
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(tilted, r, PSC::parameters::normal_refinement(2, maps())), pts);
  measured("Goursat 50K, normals tilted 30 deg: default ASO", tilted_default);
  measured("Goursat 50K, normals tilted 30 deg: default ASO, normal_refinement(1)", tilted_refined);
  measured("Goursat 50K, normals tilted 30 deg: default ASO, normal_refinement(2)", tilted_refined_twice);
  // Measured (another draw of the tilts) 50.7e-3, 8.9e-3 and 4.0e-3 (the refinement passes use
  // the APSS sphere's normals; refining with the ASO's own gave 16.3e-3 and 5.95e-3); the
  // issue's target with one refinement: 15e-3.
  CHECK(tilted_refined < 15e-3);
  CHECK(tilted_refined_twice < 0.7 * tilted_refined);
  CHECK(tilted_default > 3 * tilted_refined);
}

TEST_CASE(
  "Default ASO on i.i.d. random Goursat samples: at least as accurate as PSS (the paper's ASO: 2.3 times worse)",
  "[aso][robust]")
{
  std::vector<Oriented_point> pts;  // the draw of paper_experiments' experiment 7
  for(const auto& p : goursat::iid_sample(10000, 2021 * 37 + 1))
    pts.emplace_back(Point(p.first.x(), p.first.y(), p.first.z()), Vector(p.second.x(), p.second.y(), p.second.z()));
  const Three_errors e = default_paper_pss(pts, 1.5, "Goursat 10K i.i.d. r=1.5");
  // Measured 2.28e-3 (2.79e-3 without the normal-field blend), 6.62e-3, 2.95e-3.
  CHECK(e.robust <= e.pss);
  CHECK(e.paper > 2 * e.robust);
}

// Every variant is exact on a sphere, however irregular the sampling: the sample weights,
// the kernel and the orientation change the weights of an exact fit, not the fit.
TEST_CASE("Every ASO variant gives k = 1 on a unit sphere sampled i.i.d. with a 1:10 density ramp", "[aso][robust]")
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : ellipsoid(20000, 1, 1, 1, 9))
    if(u(rng) * 10 < 1 + 9 * (p.first.x() + 1) / 2)
      pts.push_back(p);
  for(auto kernel : {CGAL::Apss_weight_kernel::SMOOTH, CGAL::Apss_weight_kernel::SMOOTH_CUBIC,
                     CGAL::Apss_weight_kernel::SMOOTH_QUARTIC})
    for(auto weights : {CGAL::Sample_weights::UNIFORM, CGAL::Sample_weights::TANGENT_VORONOI_AREA})
      for(bool robust : {false, true})
        for(bool blend : {false, true})
        {
          INFO("kernel " << int(kernel) << ", weights " << int(weights) << ", orientation " << robust << ", blend "
                         << blend);
          const auto est = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
            pts, 0.3,
            PSC::parameters::weight_kernel(
              kernel,
              PSC::parameters::sample_weights(weights, PSC::parameters::robust_orientation(
                                                         robust, PSC::parameters::normal_field_blend(blend, maps())))));
          double worst = 0;
          std::size_t valid = 0;
          for(const auto& e : est)
            if(e.is_valid())
            {
              ++valid;
              worst = std::max({worst, std::abs(e.min_curvature - 1), std::abs(e.max_curvature - 1)});
            }
          CHECK(valid == pts.size());
          CHECK(worst < 1e-9);  // measured below 1e-12
        }
  // the blend is active on that cloud: some neighbourhoods are one-sided enough (uniform
  // weights, i.i.d. samples with a density ramp)
  const auto blended = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, 0.3, PSC::parameters::sample_weights(CGAL::Sample_weights::UNIFORM, maps()));
  const auto unblended = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, 0.3,
    PSC::parameters::sample_weights(CGAL::Sample_weights::UNIFORM, PSC::parameters::normal_field_blend(false, maps())));
  std::size_t changed = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    changed += blended[i].max_curvature != unblended[i].max_curvature;
  measured("sphere with a density ramp, uniform weights: estimates changed by the blend", double(changed));
  CHECK(changed > pts.size() / 20);
}

// The blend is active on that cloud (so the test above checks the normal-field fit's
// exactness too), and a half sphere, where every border point has a one-sided neighbourhood,
// is exact as well.
TEST_CASE("The normal-field blend is exact on a sphere cut in half", "[aso][robust][blend]")
{
  std::vector<Oriented_point> half;
  for(const Oriented_point& p : ellipsoid(20000, 1, 1, 1, 9))
    if(p.first.z() > 0)
      half.push_back(p);
  const double r = 0.3;
  const auto est = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(half, r, maps());
  const auto unblended =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(half, r, PSC::parameters::normal_field_blend(false, maps()));
  double worst = 0;
  std::size_t at_cut = 0, changed_at_cut = 0;
  for(std::size_t i = 0; i < half.size(); ++i)
  {
    REQUIRE(est[i].is_valid());
    worst = std::max({worst, std::abs(est[i].min_curvature - 1), std::abs(est[i].max_curvature - 1)});
    if(half[i].first.z() < 0.1 * r)  // a half-disk neighbourhood: the fit's weight is 1
    {
      ++at_cut;
      // both are exact here, up to rounding: a different rounding shows the fit was used
      changed_at_cut +=
        est[i].min_curvature != unblended[i].min_curvature || est[i].max_curvature != unblended[i].max_curvature;
    }
  }
  measured("half sphere: points at the cut", double(at_cut));
  measured("half sphere: changed by the blend at the cut", double(changed_at_cut));
  CHECK(worst < 1e-9);  // measured below 1e-12
  CHECK(at_cut > 100);
  CHECK(changed_at_cut > 0.9 * double(at_cut));
}

// The ASO's bias on one-sided neighbourhoods, in the continuum (a fine grid with exact
// normals): the curvature across a border through the evaluation point comes out about 25%
// low; the normal-field blend removes it.
TEST_CASE("One-sided neighbourhoods: the normal-field blend removes the ASO's bias across a border",
          "[aso][robust][blend]")
{
  const double k1 = 0.2, k2 = 0.1, h = 0.04, r = 1.4;
  std::vector<Oriented_point> patch;  // z = -(k1 x² + k2 y²) / 2 for x >= 0: a border along x = 0
  for(int i = 0; i * h <= 3.0; ++i)
    for(int j = -75; j <= 75; ++j)
    {
      const double x = i * h, y = j * h;
      const Vector n(k1 * x, k2 * y, 1);
      patch.emplace_back(Point(x, y, -(k1 * x * x + k2 * y * y) / 2), n / std::sqrt(n.squared_length()));
    }
  const auto blended = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(patch, r, maps());
  const auto unblended =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(patch, r, PSC::parameters::normal_field_blend(false, maps()));
  double worst_blended = 0, best_unblended = 1;
  std::size_t border = 0;
  for(std::size_t i = 0; i < patch.size(); ++i)
  {
    const Point& p = patch[i].first;
    if(p.x() != 0 || std::abs(p.y()) > 0.2)
      continue;
    ++border;
    REQUIRE(blended[i].is_valid());
    REQUIRE(unblended[i].is_valid());
    // at (0, y) the principal curvatures are k1 (across the border) and k2 to 2e-4
    worst_blended = std::max(
      {worst_blended, std::abs(blended[i].max_curvature - k1) / k1, std::abs(blended[i].min_curvature - k2) / k2});
    best_unblended = std::min(best_unblended, std::abs(unblended[i].max_curvature - k1) / k1);
  }
  measured("paraboloid cut along x = 0: worst relative error with the blend", worst_blended);
  measured("paraboloid cut along x = 0: least relative error of k1 without", best_unblended);
  // Measured 0.012 (the normal field's own curvature: n is linear in (x, y) only to first
  // order) and 0.235.
  CHECK(border == 11);
  CHECK(best_unblended > 0.2);
  CHECK(worst_blended < 0.03);
}

// The issue's target on the simulated LiDAR scan (scan lines, a border all around the part
// the scanner saw), and the invariance of the blended estimator under a rotation.
TEST_CASE("Default ASO on the simulated LiDAR scan: below 3.3e-3 and below PSS, rotation invariant",
          "[aso][robust][blend]")
{
  const auto pts = read_xyz(repo_data("goursat-lidar.xyz"));
  const double r = 1.4;
  std::vector<Oriented_point> truth_points;  // the truth at the radial projection
  for(const auto& p : pts)
  {
    const double v[3] = {p.first.x(), p.first.y(), p.first.z()};
    double q[3];
    goursat::project_radially(v, q);
    truth_points.emplace_back(Point(q[0], q[1], q[2]), p.second);
  }
  const auto est = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, maps());
  const double robust = mean_H_error(est, truth_points);
  const double unblended = mean_H_error(
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, PSC::parameters::normal_field_blend(false, maps())),
    truth_points);
  const double pss = mean_H_error(run(Method::PSS, pts, r), truth_points);
  measured("Goursat LiDAR r=1.4 mean |H - H*|: default ASO", robust);
  measured("Goursat LiDAR r=1.4 mean |H - H*|: without the blend", unblended);
  measured("Goursat LiDAR r=1.4 mean |H - H*|: PSS", pss);
  // Measured 1.30e-3, 3.35e-3 and 2.27e-3 (the paper's ASO: 4.83e-3).
  CHECK(robust < 3.3e-3);
  CHECK(robust < pss);
  CHECK(unblended > 2 * robust);

  // The per-query class with the same options gives the same estimates (uniform weights: the
  // class takes the sample weights from the caller), at the points where the blend applies.
  const auto uniform = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, r, PSC::parameters::sample_weights(CGAL::Sample_weights::UNIFORM, maps()));
  const auto uniform_unblended = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, r,
    PSC::parameters::sample_weights(CGAL::Sample_weights::UNIFORM, PSC::parameters::normal_field_blend(false, maps())));
  std::size_t compared = 0;
  double class_difference = 0;
  for(std::size_t i = 0; i < pts.size() && compared < 40; ++i)
  {
    if(!uniform[i].is_valid() || uniform[i].max_curvature == uniform_unblended[i].max_curvature)
      continue;
    // the robust variant's options (its sample weights are those of the neighbours, all 1 here)
    CGAL::Algebraic_shape_operator_fit<Kernel> fit(pts[i].first, r,
                                                   PSC::parameters::aso_variant(CGAL::Aso_variant::ROBUST));
    for(const auto& p : pts)
      fit.add_neighbor(p.first, p.second);
    const auto e = fit.estimate();
    REQUIRE(e.is_valid());
    class_difference = std::max({class_difference, std::abs(e.min_curvature - uniform[i].min_curvature),
                                 std::abs(e.max_curvature - uniform[i].max_curvature)});
    ++compared;
  }
  measured("Goursat LiDAR: Algebraic_shape_operator_fit with the blend vs the cloud function", class_difference);
  CHECK(compared == 40);
  CHECK(class_difference < 1e-10);  // the same sums in another order

  const CGAL::Aff_transformation_3<Kernel> rot(0.36, -0.48, 0.8, 0.8, 0.6, 0, -0.48, 0.64, 0.6);
  std::vector<Oriented_point> turned;
  for(const auto& p : pts)
    turned.emplace_back(rot(p.first), rot(p.second));
  const auto est_turned = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(turned, r, maps());
  double worst = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    REQUIRE(est[i].status == est_turned[i].status);
    if(est[i].is_valid())
      worst = std::max(worst, std::abs(est[i].mean_curvature - est_turned[i].mean_curvature));
  }
  measured("Goursat LiDAR rotated: max change of H", worst);
  CHECK(worst < 1e-9);
}

// Two parallel sheets closer than r with opposite normals (both sides of a thin plate): the
// robust orientation would flip one sheet's normals and fit one surface to both. It reports
// TWO_SHEETS instead; away from the other sheet the estimates are the plane's.
TEST_CASE(
  "Thin plate: the robust orientation reports TWO_SHEETS where both sides are within r, a cube's edges are left alone",
  "[aso][robust]")
{
  const double r = 0.2, gap = 0.05;  // sheets 0.25 r apart
  std::vector<Oriented_point> plate;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for(int i = 0; i < 8000; ++i)
  {
    const double x = u(rng), y = u(rng);
    plate.emplace_back(Point(x, y, 0), Vector(0, 0, -1));  // bottom side, outward down
    const double x2 = u(rng), y2 = u(rng);
    if(x2 < 0)  // the top side covers half of it: points at x > r see one sheet only
      plate.emplace_back(Point(x2, y2, gap), Vector(0, 0, 1));
  }
  const auto est = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(plate, r, maps());
  std::size_t two_sheets_under = 0, under = 0, flat_alone = 0, alone = 0;
  for(std::size_t i = 0; i < plate.size(); ++i)
  {
    const Point& p = plate[i].first;
    if(std::abs(p.x()) > 0.95 - r || std::abs(p.y()) > 0.95 - r)
      continue;  // away from the plate's border
    if(p.x() < -r)
    {
      ++under;
      two_sheets_under += est[i].status == Status::TWO_SHEETS;
    }
    else if(p.x() > r)
    {
      ++alone;
      flat_alone += est[i].is_valid() && std::abs(est[i].mean_curvature) < 1e-6;
    }
  }
  CHECK(under > 1000);
  CHECK(two_sheets_under == under);
  CHECK(flat_alone == alone);

  // A cube's faces meet at 90 degrees: no normal is more than 90 degrees from the weighted
  // majority, so nothing is flipped and the estimates are those without the orientation.
  std::vector<Oriented_point> cube;
  for(int f = 0; f < 6; ++f)
    for(int i = 0; i < 2000; ++i)
    {
      double c[3] = {u(rng), u(rng), u(rng)};
      const int axis = f / 2;
      c[axis] = f % 2 ? 1 : -1;
      Vector n(axis == 0 ? c[0] : 0, axis == 1 ? c[1] : 0, axis == 2 ? c[2] : 0);
      cube.emplace_back(Point(c[0], c[1], c[2]), n);
    }
  const auto with = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(cube, 0.3, maps());
  const auto without =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(cube, 0.3, PSC::parameters::robust_orientation(false, maps()));
  std::size_t same = 0;
  for(std::size_t i = 0; i < cube.size(); ++i)
    same += with[i].status == without[i].status &&
            (!with[i].is_valid() || with[i].mean_curvature == without[i].mean_curvature);
  CHECK(same == cube.size());
}

// Foliage: points filling a volume with normals pointing anywhere (what the normal estimation
// gives in a tree crown, oriented to +z as the tool does for airborne scans) are one noisy
// surface, not two sheets: the estimate is given, with a low normal_coherence. A plane's
// coherence is 1, a sphere's close to 1.
TEST_CASE(
  "Foliage is estimated with a low normal_coherence, not TWO_SHEETS, and smooth surfaces have a coherence near 1",
  "[aso][robust]")
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Oriented_point> crown;
  while(crown.size() < 6000)
  {
    const Point p(u(rng), u(rng), u(rng));
    Vector n(u(rng), u(rng), u(rng));
    if(p.x() * p.x() + p.y() * p.y() + p.z() * p.z() > 1 || n.squared_length() > 1 || n.squared_length() < 1e-2)
      continue;
    crown.emplace_back(p, n.z() < 0 ? -n : n);
  }
  // the same crown with normals of either sign (a spanning tree's orientation in a crown):
  // half of the weight disagrees with the reference, at offsets anywhere. The previous rule
  // (mean offsets more than 0.05 r apart) called most of these TWO_SHEETS.
  std::vector<Oriented_point> either = crown;
  for(std::size_t i = 0; i < either.size(); i += 2)
    either[i].second = -either[i].second;
  const auto k40 = PSC::parameters::neighbor_count(40, maps());
  for(const auto& est :
      {CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(crown, k40),
       CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(crown, PSC::parameters::robust_orientation(true, k40)),
       CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(either, k40)})
  {
    std::size_t valid = 0;
    std::vector<double> coherence;
    for(const auto& e : est)
      if(e.is_valid())
      {
        ++valid;
        coherence.push_back(e.normal_coherence);
      }
    std::sort(coherence.begin(), coherence.end());
    measured("foliage: valid (of 6000)", double(valid));
    measured("foliage: median normal_coherence", coherence[coherence.size() / 2]);
    CHECK(valid > 0.95 * double(crown.size()));    // measured 6000 of 6000 (each case)
    CHECK(coherence[coherence.size() / 2] < 0.8);  // measured 0.61 (ASO), 0.57 (APSS), 0.61 (either sign)
  }
  // a bent thin shell stays two sheets: both sides of a tube wall of radius 1, 0.05 thick
  // (0.25 r), normals outward on the outer side and inward on the inner side
  std::vector<Oriented_point> shell;
  for(int i = 0; i < 12000; ++i)
  {
    const double phi = M_PI * u(rng), z = u(rng);
    const Vector out(std::cos(phi), std::sin(phi), 0);
    shell.emplace_back(Point(out.x(), out.y(), z), out);
    shell.emplace_back(Point(1.05 * out.x(), 1.05 * out.y(), u(rng)), -out);
  }
  const auto shell_est = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(shell, 0.2, maps());
  std::size_t inner = 0, inner_two_sheets = 0;
  for(std::size_t i = 0; i < shell.size(); ++i)
  {
    const Point& p = shell[i].first;
    if(std::abs(p.z()) > 0.75)
      continue;  // away from the tube's ends
    ++inner;
    inner_two_sheets += shell_est[i].status == CGAL::Curvature_estimate_status::TWO_SHEETS;
  }
  CHECK(inner > 15000);
  CHECK(inner_two_sheets == inner);

  // a plane: exactly 1; a unit sphere at r = 0.2: measured 0.996 and more
  std::vector<Oriented_point> flat;
  for(int i = 0; i < 2000; ++i)
    flat.emplace_back(Point(u(rng), u(rng), 0), Vector(0, 0, 1));
  std::size_t flat_valid = 0;
  for(const auto& e : CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(flat, k40))
    if(e.is_valid())
    {
      ++flat_valid;
      CHECK(e.normal_coherence == Approx(1.0).epsilon(1e-12));
    }
  CHECK(flat_valid == flat.size());
  double least = 1;
  std::size_t sphere_valid = 0;
  for(const auto& e : CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(sphere(20000, 1.0), 0.2, maps()))
    if(e.is_valid())
    {
      ++sphere_valid;
      least = std::min(least, double(e.normal_coherence));
    }
  CHECK(sphere_valid == 20000);
  measured("sphere R = 1, r = 0.2: least normal_coherence", least);
  CHECK(least > 0.99);
  CHECK(least < 1.0);
  // estimators without normal sums leave it NaN
  CHECK(std::isnan(CGAL::estimate_pss_curvatures<CGAL::Sequential_tag>(flat, k40)[0].normal_coherence));
}

namespace {

// How many estimates differ (same_estimate() above: bitwise, NaN equal to NaN).
template <class Range>
std::size_t count_different(const Range& a, const Range& b)
{
  REQUIRE(a.size() == b.size());
  std::size_t d = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    d += same_estimate(a[i], b[i]) ? 0 : 1;
  return d;
}

}  // namespace

// The area pass shared by several estimators of one run (issue 11's speed target: "the areas
// pass can be shared by every estimator of one run").
TEST_CASE("estimate_tangent_voronoi_areas + sample_weight_map: one area pass gives every estimator's area-weighted "
          "result bitwise",
          "[aso][robust][weights]")
{
  // a unit sphere sampled i.i.d. with a 1:10 density ramp, a point with a zero normal
  typedef std::tuple<Point, Vector, double> Item;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Item> items;
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : ellipsoid(12000, 1, 1, 1, 4))
    if(u(rng) * 10 < 1 + 9 * (p.first.x() + 1) / 2)
    {
      items.emplace_back(p.first, p.second, -1.0);
      pts.push_back(p);
    }
  std::get<1>(items[7]) = Vector(0, 0, 0);
  pts[7].second = Vector(0, 0, 0);
  const double r = 0.3;
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Item>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Item>());
  const auto wnp = PSC::parameters::sample_weight_map(CGAL::Nth_of_tuple_property_map<2, Item>(), np);
  REQUIRE(CGAL::estimate_tangent_voronoi_areas<CGAL::Parallel_tag>(items, r, wnp));

  // Real values: the unusable point weighs 0; the areas are a quadrature of the sphere: on the
  // dense half (x > 0, spacing about 0.04) they sum to its area 2 pi; on the whole sphere to
  // less than 4 pi, as the sparsest cells (spacing 0.1 at x = -1) are cut by the disk of
  // radius r/4 = 0.075.
  double total = 0, dense = 0;
  for(const Item& it : items)
  {
    total += std::get<2>(it);
    dense += std::get<0>(it).x() > 0 ? std::get<2>(it) : 0.0;
  }
  measured("sum of the tangent Voronoi areas on the half sphere x > 0 / 2 pi - 1", dense / (2 * M_PI) - 1);
  measured("sum of the tangent Voronoi areas on the unit sphere / 4 pi - 1", total / (4 * M_PI) - 1);
  CHECK(std::get<2>(items[7]) == 0);
  CHECK(std::abs(dense / (2 * M_PI) - 1) < 0.005);
  CHECK(total < 4 * M_PI);
  CHECK(total > 0.95 * 4 * M_PI);
  // the sequential pass gives the same areas
  std::vector<Item> sequential = items;
  for(Item& it : sequential)
    std::get<2>(it) = -1;
  REQUIRE(CGAL::estimate_tangent_voronoi_areas<CGAL::Sequential_tag>(sequential, r, wnp));
  std::size_t area_differences = 0;
  for(std::size_t i = 0; i < items.size(); ++i)
    area_differences += std::get<2>(items[i]) != std::get<2>(sequential[i]);
  CHECK(area_differences == 0);

  // the ASO (default, and the paper's variant with area weights), APSS and the sphere
  // features, each with its own area pass and with the shared areas
  const auto area = CGAL::Sample_weights::TANGENT_VORONOI_AREA;
  CHECK(count_different(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, maps()),
                        CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(items, r, wnp)) == 0);
  CHECK(count_different(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                          pts, r, PSC::parameters::sample_weights(area, paper_maps())),
                        CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                          items, r, PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, wnp))) == 0);
  CHECK(count_different(
          CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, PSC::parameters::sample_weights(area, maps())),
          CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(items, r, wnp)) == 0);
  {
    const auto own = CGAL::estimate_algebraic_sphere_features<CGAL::Parallel_tag>(
      pts, r, PSC::parameters::sample_weights(area, maps()));
    const auto shared = CGAL::estimate_algebraic_sphere_features<CGAL::Parallel_tag>(items, r, wnp);
    std::size_t different = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      different += (own[i].status != shared[i].status || !same_number(own[i].mean_curvature, shared[i].mean_curvature));
    CHECK(different == 0);
  }
  // normals of length 2.5 and the authors' projection, which uses them unnormalised: the areas
  // still match (they always take the query's unit normal)
  {
    auto long_pts = pts;
    auto long_items = items;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      long_pts[i].second = 2.5 * pts[i].second;
      std::get<1>(long_items[i]) = 2.5 * std::get<1>(items[i]);
    }
    REQUIRE(CGAL::estimate_tangent_voronoi_areas<CGAL::Sequential_tag>(long_items, r, wnp));
    const auto authors = CGAL::Aso_projection::AUTHORS_IMPLEMENTATION;
    CHECK(count_different(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                            long_pts, r, PSC::parameters::aso_projection(authors, maps())),
                          CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                            long_items, r, PSC::parameters::aso_projection(authors, wnp))) == 0);
  }
  // the weights change the estimates (the test would pass trivially otherwise)
  CHECK(count_different(CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, maps()),
                        CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(items, r, wnp)) > pts.size() / 2);

  // by count: the areas of the estimators' k/4 nearest
  const std::size_t k = 40;
  std::vector<Item> by_count = items;
  REQUIRE(CGAL::estimate_tangent_voronoi_areas<CGAL::Parallel_tag>(by_count, PSC::parameters::neighbor_count(k, wnp)));
  CHECK(count_different(
          CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, PSC::parameters::neighbor_count(k, maps())),
          CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(by_count, PSC::parameters::neighbor_count(k, wnp))) == 0);

  // CGAL::Point_set_3 with a property of its own
  CGAL::Point_set_3<Point, Vector> ps;
  ps.add_normal_map();
  for(const auto& p : pts)
    ps.insert(p.first, p.second);
  auto ps_area = ps.add_property_map<double>("area", -1.0).first;
  REQUIRE(CGAL::estimate_tangent_voronoi_areas<CGAL::Sequential_tag>(
    ps, r, PSC::parameters::sample_weight_map(ps_area, ps.parameters())));
  CHECK(count_different(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(ps, r, ps.parameters()),
                        CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                          ps, r, PSC::parameters::sample_weight_map(ps_area, ps.parameters()))) == 0);

  // The map is read, not recomputed: weights of 1 give the unweighted estimator bitwise (w
  // times 1.0 is exact), by radius, by count and through a refinement pass; sequential and
  // parallel runs reading the map agree.
  {
    auto ones = items;
    for(Item& it : ones)
      std::get<2>(it) = 1.0;
    const auto uniform = PSC::parameters::sample_weights(CGAL::Sample_weights::UNIFORM, maps());
    CHECK(count_different(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, uniform),
                          CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ones, r, wnp)) == 0);
    CHECK(count_different(
            CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, PSC::parameters::neighbor_count(k, uniform)),
            CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ones, PSC::parameters::neighbor_count(k, wnp))) == 0);
    CHECK(count_different(
            CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, PSC::parameters::normal_refinement(1, uniform)),
            CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ones, r, PSC::parameters::normal_refinement(1, wnp))) ==
          0);
    CHECK(count_different(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(items, r, wnp),
                          CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(items, r, wnp)) == 0);
  }

  // A tile reads the whole cloud's weights from the map: its own points get the whole-cloud
  // estimates, by radius (halo r) and by count.
  {
    const PSC::Tile tile(CGAL::Bbox_3(0.2, -2, 0, 0.5, 2, 2), 0.5);
    std::vector<Item> range;
    std::vector<std::size_t> from;
    for(std::size_t i = 0; i < items.size(); ++i)
    {
      const Point& p = std::get<0>(items[i]);
      if(tile.distance_to_core(p.x(), p.y(), p.z()) <= tile.halo)
      {
        range.push_back(items[i]);
        from.push_back(i);
      }
    }
    REQUIRE(range.size() < items.size());
    for(bool by_radius : {true, false})
    {
      INFO("by radius " << by_radius);
      const auto whole =
        by_radius
          ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(items, r, wnp)
          : CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(by_count, PSC::parameters::neighbor_count(k, wnp));
      std::vector<Item> tile_range = range;
      if(!by_radius)
        for(std::size_t j = 0; j < range.size(); ++j)
          std::get<2>(tile_range[j]) = std::get<2>(by_count[from[j]]);
      const auto part =
        by_radius ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(tile_range, r, PSC::parameters::tile(tile, wnp))
                  : CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                      tile_range, PSC::parameters::neighbor_count(k, PSC::parameters::tile(tile, wnp)));
      std::size_t own = 0, different = 0;
      for(std::size_t j = 0; j < range.size(); ++j)
      {
        const Point& p = std::get<0>(range[j]);
        if(!tile.owns(p.x(), p.y(), p.z()))
          continue;
        ++own;
        different += same_estimate(part[j], whole[from[j]]) ? 0 : 1;
      }
      CHECK(own > 500);  // 682 own points of 6610
      CHECK(different == 0);
    }
  }

  // Cancelled: false, and the map is left as it was.
  {
    auto untouched = items;
    for(Item& it : untouched)
      std::get<2>(it) = -7;
    const std::function<bool(double)> stop = [](double) { return false; };
    CHECK_FALSE(CGAL::estimate_tangent_voronoi_areas<CGAL::Sequential_tag>(untouched, r, wnp.callback(stop)));
    std::size_t written = 0;
    for(const Item& it : untouched)
      written += std::get<2>(it) != -7;
    CHECK(written == 0);
  }

  // Bad weights: a clear exception, never NaN sums; weights that are all 0 are no fit.
  auto bad = items;
  std::get<2>(bad[3]) = -1;
  CHECK_THROWS_AS(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(bad, r, wnp), std::invalid_argument);
  std::get<2>(bad[3]) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(bad, r, wnp), std::invalid_argument);
  // an estimator without sample weights ignores the map
  CHECK_NOTHROW(CGAL::estimate_pss_curvatures<CGAL::Sequential_tag>(bad, r, wnp));
  for(Item& it : bad)
    std::get<2>(it) = 0;
  const auto zero = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(bad, r, wnp);
  std::size_t degenerate = 0;
  for(const auto& e : zero)
    degenerate += e.status == Status::DEGENERATE_FIT && std::isnan(e.mean_curvature);
  CHECK(degenerate + 1 == zero.size());  // the point with a zero normal is INVALID_NORMAL
  degenerate = 0;
  for(const auto& e : CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(bad, r, wnp))
    degenerate += e.status == Status::DEGENERATE_FIT && std::isnan(e.mean_curvature);
  CHECK(degenerate + 1 == zero.size());
  // not supported: the multi-scale features, a tile
  const std::vector<double> radii{0.2, 0.3};
  CHECK_THROWS_AS(CGAL::estimate_multiscale_algebraic_sphere_features<CGAL::Sequential_tag>(items, radii, wnp),
                  std::invalid_argument);
  CHECK_THROWS_AS(CGAL::estimate_tangent_voronoi_areas<CGAL::Sequential_tag>(
                    items, r, PSC::parameters::tile(PSC::Tile(CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 0.6), wnp)),
                  std::invalid_argument);
}

TEST_CASE("Every estimator fills the fields its description declares (estimators.h), and only those",
          "[baselines][api]")
{
  namespace F = PSC::estimate_fields;
  const double R = 2, r = 0.5;
  const auto pts = sphere(2000, R);
  // the test's Method of each described estimator but the APSS (not a baseline)
  const std::pair<const char*, Method> named[] = {{"aso", Method::ASO},
                                                  {"barycenter", Method::BARYCENTER},
                                                  {"pca_plane", Method::PCA_PLANE},
                                                  {"pss", Method::PSS},
                                                  {"jet", Method::JET},
                                                  {"wavejet", Method::WAVEJET},
                                                  {"vcm", Method::VCM}};
  // the estimator `name`: `apss()` for the APSS, `f(method)` for the others
  auto by_name = [&](const std::string& name, const auto& f, const auto& apss) -> Estimates {
    if(name == "apss")
      return apss();
    for(const auto& n : named)
      if(name == n.first)
        return f(n.second);
    FAIL("no estimator named " << name);
    return {};
  };
  // the three runs of each: whole, on a tile (all but VCM, which refuses one; an infinite halo:
  // the range is the whole cloud), with the automatic scale (the ASO; ignored by the others)
  const PSC::Tile half(CGAL::Bbox_3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, 0, HUGE_VAL, HUGE_VAL), HUGE_VAL);
  const auto tiled = PSC::parameters::tile(half, maps());
  const auto automatic = PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(640, maps()));
  auto run_whole = [&](const std::string& name) {
    return by_name(
      name, [&](Method m) { return run(m, pts, r); },
      [&] { return CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, maps()); });
  };
  auto run_tiled = [&](const std::string& name) {
    return by_name(
      name, [&](Method m) { return run<CGAL::Parallel_tag>(m, pts, r, tiled); },
      [&] { return CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, tiled); });
  };
  auto run_automatic = [&](const std::string& name) {
    return by_name(
      name, [&](Method m) { return run_without_radius<CGAL::Parallel_tag>(m, pts, automatic); },
      [&] { return CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, automatic); });
  };
  auto finite = [](const Vector& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); };
  std::size_t described = 0;
  for(const PSC::Estimator_description& d : PSC::estimators)
  {
    INFO(d.name);
    CHECK(PSC::find_estimator(d.name) == &d);
    const Estimates estimates = run_whole(d.name);
    std::size_t valid = 0;
    for(const auto& e : estimates)
    {
      if(!e.is_valid())
        continue;
      ++valid;
      CHECK(finite(e.normal) == bool(d.fields & F::normal));
      CHECK(std::isfinite(e.mean_curvature) == bool(d.fields & F::mean_curvature));
      CHECK(std::isfinite(e.gaussian_curvature) == bool(d.fields & F::gaussian_curvature));
      CHECK(std::isfinite(e.min_curvature) == bool(d.fields & F::principal_curvatures));
      CHECK(std::isfinite(e.max_curvature) == bool(d.fields & F::principal_curvatures));
      CHECK(finite(e.min_direction) == bool(d.fields & F::principal_directions));
      CHECK(finite(e.max_direction) == bool(d.fields & F::principal_directions));
      CHECK(std::isfinite(e.normal_coherence) == bool(d.fields & F::normal_coherence));
      CHECK(std::isnan(e.mean_curvature_error));  // only with the automatic scale
    }
    CHECK(valid == pts.size());
    ++described;

    if(d.supports_tiles)
    {
      // the tile's own points (x < 0) as in the whole run, bitwise; the others not computed
      const Estimates part = run_tiled(d.name);
      REQUIRE(part.size() == pts.size());
      std::size_t own = 0, differ = 0, others = 0;
      for(std::size_t i = 0; i < pts.size(); ++i)
        if(pts[i].first.x() < 0)
        {
          ++own;
          differ += !same_estimate(part[i], estimates[i]);
        }
        else
          others += part[i].status == CGAL::Curvature_estimate_status::NOT_COMPUTED;
      CHECK(own > pts.size() / 3);
      CHECK(differ == 0);
      CHECK(others == pts.size() - own);
    }
    else
      CHECK_THROWS_AS(run_tiled(d.name), std::invalid_argument);
    // the automatic scale: a standard error of the mean curvature where supported, ignored elsewhere
    std::size_t with_error = 0;
    for(const auto& e : run_automatic(d.name))
      with_error += std::isfinite(e.mean_curvature_error);
    CHECK((with_error > pts.size() / 2) == d.supports_automatic_scale);
    CHECK((with_error == 0) == !d.supports_automatic_scale);
  }
  CHECK(described == 8);
  // the declared least counts are the test's own (measured, the manual's section 3.1); the
  // good counts those the manual's table gives
  for(const auto& n : named)
    CHECK(PSC::find_estimator(n.first)->min_neighbors == minimum_neighbors(n.second));
  CHECK(PSC::find_estimator("apss")->min_neighbors == 12);
  CHECK(PSC::find_estimator("aso")->good_neighbors_of(CGAL::Aso_variant::ROBUST) == 12);
  CHECK(PSC::find_estimator("aso")->good_neighbors_of(CGAL::Aso_variant::PAPER) == 20);
  CHECK(PSC::find_estimator("vcm")->good_neighbors_of(CGAL::Aso_variant::PAPER) == 25);
  CHECK(PSC::find_estimator("nonexistent") == nullptr);
}
