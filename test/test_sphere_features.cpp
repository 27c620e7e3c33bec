// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Algebraic sphere features, APSS projection and bilaplacian flow (Lejemble et al. 2021,
// Sections 3-4; issue 6). The asymptotic laws are measured on analytic surfaces:
//   constant kernel (the paper's constants)  1 - p = (k1-k2)² r²/16,  v = |∇H|² r⁴/4,
//                                            u_c = (9H³ - 5KH - ΔH) r⁴/96
//   smooth kernel (derived, see internal/algebraic_sphere_features.h)
//                                            1 - p = (k1-k2)² r²/32,  v = |∇H|² r⁴/16,
//                                            u_c = (19H³ - 11KH - 2ΔH) r⁴/640
// Every tolerance is justified by the value measured with the fixed seeds of this file; run
// with PSC_TEST_PRINT=1 to print them again.

#include "test_support.h"

#include <CGAL/Algebraic_point_set_surface.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/apss_smooth_point_set.h>
#include <CGAL/estimate_algebraic_sphere_features.h>
#include <CGAL/estimate_apss_curvatures.h>

#include <boost/property_map/function_property_map.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <list>
#include <random>
#include <string>
#include <vector>

using namespace psc_test;
namespace PSC = CGAL::Point_set_curvatures;

namespace {

typedef CGAL::Algebraic_sphere_features<Kernel> Features;
typedef CGAL::Algebraic_point_set_surface<Kernel> Surface;
typedef CGAL::Curvature_estimate_status Status;
typedef CGAL::Apss_weight_kernel Weight;
typedef CGAL::Sequential_tag Seq;
typedef CGAL::Parallel_tag Par;

const Weight both_kernels[] = {Weight::SMOOTH, Weight::CONSTANT};  // the paper's two kernels
// with the kernels (1 - d²/r²)^3 and ^4 (issue 11): every test that does not check a
// kernel-specific asymptotic constant runs with all four
const Weight all_kernels[] = {Weight::SMOOTH, Weight::CONSTANT, Weight::SMOOTH_CUBIC, Weight::SMOOTH_QUARTIC};
const char* name(Weight w)
{
  switch(w)
  {
    case Weight::SMOOTH: return "smooth";
    case Weight::CONSTANT: return "constant";
    case Weight::SMOOTH_CUBIC: return "smooth cubic";
    default: return "smooth quartic";
  }
}

auto maps() { return CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); }
auto maps(Weight w) { return PSC::parameters::weight_kernel(w, maps()); }

double length(const Vector& v) { return std::sqrt(v.squared_length()); }
double distance(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

bool all_nan(const Features& f)
{
  return std::isnan(f.u_c) && std::isnan(f.u_l.x()) && std::isnan(f.u_q) && std::isnan(f.pratt_norm) &&
         std::isnan(f.anisotropy) && std::isnan(f.normal.x()) && std::isnan(f.mean_curvature) &&
         std::isnan(f.geometric_variation) && std::isnan(f.d_u_c_dr) && std::isnan(f.d_normal_dr.x()) &&
         std::isnan(f.d_mean_curvature_dr) && std::isnan(f.center.x()) && std::isnan(f.sphere_radius) &&
         std::isnan(f.projection.x()) && std::isnan(f.kernel_radius);
}

// Every numeric field bitwise equal (NaN equal to NaN).
bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }
bool same(const Features& a, const Features& b)
{
  return same(a.u_c, b.u_c) && same(a.u_l.x(), b.u_l.x()) && same(a.u_l.y(), b.u_l.y()) && same(a.u_l.z(), b.u_l.z()) &&
         same(a.u_q, b.u_q) && same(a.pratt_norm, b.pratt_norm) && same(a.geometric_variation, b.geometric_variation) &&
         same(a.d_u_c_dr, b.d_u_c_dr) && same(a.d_normal_dr.x(), b.d_normal_dr.x()) &&
         same(a.d_mean_curvature_dr, b.d_mean_curvature_dr) && same(a.center.x(), b.center.x()) &&
         same(a.sphere_radius, b.sphere_radius) && same(a.projection.z(), b.projection.z()) &&
         a.neighbor_count == b.neighbor_count && a.status == b.status && a.is_plane == b.is_plane;
}

// A height field over the tangent plane at the origin (principal frame, normal +z):
// h = (a20 x² + a02 y²)/2 + cubic + quartic terms (Equation 10 of the paper). Curvatures with the
// package's sign: k1 = -a20, k2 = -a02; ∇H = ((a30 + a12)/2, (a03 + a21)/2) up to sign;
// ΔH = -(a40 + 2 a22 + a04)/2 (half the bilaplacian of h).
struct Height_field
{
  double a20, a02, a30, a21, a12, a03, a40, a31, a22, a13, a04;

  double h(double x, double y) const
  {
    return 0.5 * (a20 * x * x + a02 * y * y) +
           (a30 * x * x * x + 3 * a21 * x * x * y + 3 * a12 * x * y * y + a03 * y * y * y) / 6 +
           (a40 * x * x * x * x + 4 * a31 * x * x * x * y + 6 * a22 * x * x * y * y + 4 * a13 * x * y * y * y +
            a04 * y * y * y * y) /
             24;
  }
  double hx(double x, double y) const
  {
    return a20 * x + (a30 * x * x + 2 * a21 * x * y + a12 * y * y) / 2 +
           (a40 * x * x * x + 3 * a31 * x * x * y + 3 * a22 * x * y * y + a13 * y * y * y) / 6;
  }
  double hy(double x, double y) const
  {
    return a02 * y + (a21 * x * x + 2 * a12 * x * y + a03 * y * y) / 2 +
           (a31 * x * x * x + 3 * a22 * x * x * y + 3 * a13 * x * y * y + a04 * y * y * y) / 6;
  }
  double k1() const { return -a20; }
  double k2() const { return -a02; }
  double H() const { return 0.5 * (k1() + k2()); }
  double K() const { return k1() * k2(); }
  double grad_H_squared() const { return 0.25 * ((a30 + a12) * (a30 + a12) + (a03 + a21) * (a03 + a21)); }
  double laplacian_H() const { return -0.5 * (a40 + 2 * a22 + a04); }
};

// The paraboloid of the tests, z = (x² + 0.4 y²)/2, whose curvature varies through cubic and
// quartic terms (so that ∇H and ΔH are not zero at the origin).
const Height_field varying_paraboloid = {1.0, 0.4, 0.8, -0.3, 0.5, 0.6, 3.0, 0.7, -1.2, 0.4, 2.0};

// Samples the height field over the disc of radius `extent` on a lattice of the given spacing,
// rotated by 0.3 rad and offset, with exact unit normals. A lattice in the tangent plane is
// uniform to second order in area (the area element is 1 + O(r²), which the derivation shows
// leaves the leading terms of every law unchanged), and much less noisy than random samples,
// which matters for 4th-order quantities like u_c.
std::vector<Oriented_point> lattice_patch(const Height_field& s, double extent, double spacing)
{
  std::vector<Oriented_point> pts;
  const int n = int(std::ceil(extent / spacing)) + 1;
  const double c = std::cos(0.3), sn = std::sin(0.3);
  for(int i = -n; i <= n; ++i)
    for(int j = -n; j <= n; ++j)
    {
      const double a = (i + 0.37) * spacing, b = (j + 0.61) * spacing;
      const double x = c * a - sn * b, y = sn * a + c * b;
      if(x * x + y * y > extent * extent)
        continue;
      const double gx = s.hx(x, y), gy = s.hy(x, y);
      pts.emplace_back(Point(x, y, s.h(x, y)), Vector(-gx, -gy, 1) / std::sqrt(1 + gx * gx + gy * gy));
    }
  return pts;
}

// Features at the origin of a patch of the height field sampled with about 31000 points in the
// ball of radius r (spacing r / 100).
Features patch_features(const Height_field& s, double r, Weight w, double radius_factor = 1.0)
{
  const auto pts = lattice_patch(s, 1.3 * r, r / 100);
  return Surface(pts, r * radius_factor, maps(w)).features(Point(0, 0, 0));
}

// The ellipsoid x²/a² + y²/b² + z²/c² = 1 sampled by mapping a Fibonacci sphere (quasi-uniform,
// far less noisy than random directions), exact outward normals.
std::vector<Oriented_point> fibonacci_ellipsoid(std::size_t n, double a, double b, double c)
{
  std::vector<Oriented_point> pts;
  for(const Oriented_point& u : sphere(n, 1.0))
  {
    const Point p(a * u.first.x(), b * u.first.y(), c * u.first.z());
    const Vector g(p.x() / (a * a), p.y() / (b * b), p.z() / (c * c));
    pts.emplace_back(p, g / length(g));
  }
  return pts;
}

// Goursat surface (data/goursat_010000.xyz): F = -8 - 2|x|² + 0.03 Σ x_i⁴, first-order distance.
double goursat_distance(const Point& p)
{
  const double x[3] = {p.x(), p.y(), p.z()};
  double F = -8, g2 = 0;
  for(int i = 0; i < 3; ++i)
  {
    F += -2 * x[i] * x[i] + 0.03 * x[i] * x[i] * x[i] * x[i];
    const double g = -4 * x[i] + 0.12 * x[i] * x[i] * x[i];
    g2 += g * g;
  }
  return F / std::sqrt(g2);
}

}  // namespace

using Catch::Matchers::Contains;

// ---------------------------------------------------------------------------------------
// Sphere, plane: exact values
// ---------------------------------------------------------------------------------------

TEST_CASE("Sphere: u_q = 1/(2R), u_c = 0, 1 - p = 0, v = 0, the sphere's centre and radius", "[features][sphere]")
{
  const double R = 2.0, r = 0.3;
  const Point c(1, -2, 3);
  for(bool inward : {false, true})
    for(Weight w : all_kernels)
    {
      INFO(name(w) << (inward ? ", inward normals" : ", outward normals"));
      const auto pts = sphere(20000, R, c, inward);
      const auto f = CGAL::estimate_algebraic_sphere_features<Par>(pts, r, maps(w));
      const auto apss = CGAL::estimate_apss_curvatures<Par>(pts, r, maps(w));
      REQUIRE(f.size() == pts.size());
      const double sign = inward ? -1 : 1;
      double e_uq = 0, e_uc = 0, e_p = 0, e_v = 0, e_centre = 0, e_proj = 0, e_n = 0;
      for(std::size_t i = 0; i < pts.size(); ++i)
      {
        REQUIRE(f[i].is_valid());
        e_uq = std::max(e_uq, std::abs(f[i].u_q - sign / (2 * R)) * R);
        e_uc = std::max(e_uc, std::abs(f[i].u_c) / R);
        e_p = std::max(e_p, std::abs(f[i].anisotropy));
        e_centre = std::max(e_centre, (distance(f[i].center, c) + std::abs(f[i].sphere_radius - R)) / R);
        e_proj = std::max(e_proj, distance(f[i].projection, pts[i].first) / R);
        e_n = std::max(e_n, length(f[i].normal - pts[i].second));
        // the APSS function's normal and mean curvature, bit for bit (same sums)
        CHECK(f[i].mean_curvature == apss[i].mean_curvature);
        CHECK(f[i].normal == apss[i].normal);
        CHECK(f[i].neighbor_count == apss[i].neighbor_count);
        CHECK(f[i].kernel_radius == r);
        CHECK(std::abs(length(f[i].u_l) - 1) < 1e-12);  // the point is on its sphere
        CHECK_FALSE(f[i].is_plane);
        e_v = std::max({e_v, f[i].geometric_variation, std::abs(f[i].d_u_c_dr), length(f[i].d_normal_dr) * r,
                        std::abs(f[i].d_mean_curvature_dr) * r * r});
      }
      // Measured (both kernels and orientations): |u_q - 1/2R| R 1.6e-15, |u_c|/R 3.3e-16,
      // 1 - p 1.6e-15, centre and radius 6e-15, v and scale derivatives 2.3e-15: the fit of a
      // sphere sampled exactly is exact, so rounding alone is left.
      const std::string what = std::string("sphere ") + name(w) + (inward ? " inward" : " outward");
      measured(what + " |u_q - 1/2R| R", e_uq);
      measured(what + " |u_c|/R", e_uc);
      measured(what + " |1 - p|", e_p);
      measured(what + " centre + radius error / R", e_centre);
      measured(what + " projection and normal errors", std::max(e_proj, e_n));
      measured(what + " v and scale derivatives", e_v);
      CHECK(e_uq < 1e-12);
      CHECK(e_uc < 1e-12);
      CHECK(e_p < 1e-12);
      CHECK(e_centre < 1e-11);
      CHECK(e_proj < 1e-12);
      CHECK(e_n < 1e-12);
      CHECK(e_v < 1e-12);
    }
}

TEST_CASE("Plane: u_q = 0, a plane (no centre, infinite radius), 1 - p = 0, v = 0", "[features][plane]")
{
  const auto pts = plane(60, 0.1);
  for(Weight w : all_kernels)
  {
    INFO(name(w));
    const auto f = CGAL::estimate_algebraic_sphere_features<Seq>(pts, 0.35, maps(w));
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      REQUIRE(f[i].is_valid());
      CHECK(f[i].u_q == 0);  // exact: every q.n and every tangential normal component is 0
      CHECK(f[i].is_plane);
      CHECK(std::isinf(f[i].sphere_radius));
      CHECK(std::isnan(f[i].center.x()));
      CHECK(f[i].u_c == 0);
      CHECK(f[i].anisotropy == 0);
      CHECK(f[i].normal == Vector(0, 0, 1));
      CHECK(f[i].projection == pts[i].first);
      CHECK(f[i].geometric_variation == 0);
    }
  }
}

TEST_CASE("Sequential and Parallel give bitwise identical features, multi-scale features and flows",
          "[features][parallel]")
{
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  const std::vector<double> radii = {1.0, 1.5, 2.0};
  for(Weight w : all_kernels)
  {
    INFO(name(w));
    const auto a = CGAL::estimate_algebraic_sphere_features<Seq>(pts, 1.5, maps(w));
    const auto b = CGAL::estimate_algebraic_sphere_features<Par>(pts, 1.5, maps(w));
    const auto ma = CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(pts, radii, maps(w));
    const auto mb = CGAL::estimate_multiscale_algebraic_sphere_features<Par>(pts, radii, maps(w));
    std::size_t differ = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      differ += same(a[i], b[i]) ? 0 : 1;
      for(std::size_t k = 0; k < radii.size(); ++k)
        differ += same(ma[k][i], mb[k][i]) ? 0 : 1;
    }
    CHECK(differ == 0);
    auto fa = pts, fb = pts;
    CGAL::apss_smooth_point_set<Seq>(fa, 1.5, PSC::parameters::update_normals(true, maps(w)).number_of_iterations(3));
    CGAL::apss_smooth_point_set<Par>(fb, 1.5, PSC::parameters::update_normals(true, maps(w)).number_of_iterations(3));
    CHECK(fa == fb);
  }
}

// ---------------------------------------------------------------------------------------
// Scale derivatives and multi-scale form
// ---------------------------------------------------------------------------------------

TEST_CASE("The analytic scale derivatives agree with central differences in r", "[features][derivatives]")
{
  // The smooth kernel makes every sum C^1 in r (a neighbour enters the ball with weight 0 and
  // zero slope), so central differences of step 1e-4 r converge to the analytic derivative.
  const double r = 0.2, h = 1e-4;
  const auto pts = lattice_patch(varying_paraboloid, 1.3 * r, r / 60);
  const Point o(0.01, -0.02, varying_paraboloid.h(0.01, -0.02));
  for(Weight w : {Weight::SMOOTH, Weight::SMOOTH_CUBIC, Weight::SMOOTH_QUARTIC})
  {
    INFO(name(w));
    const Features f = Surface(pts, r, maps(w)).features(o);
    const Features fp = Surface(pts, r * (1 + h), maps(w)).features(o);
    const Features fm = Surface(pts, r * (1 - h), maps(w)).features(o);
    REQUIRE((f.is_valid() && fp.is_valid() && fm.is_valid()));
    const double d_uc = (fp.u_c - fm.u_c) / (2 * h * r);
    const Vector d_n = (fp.normal - fm.normal) / (2 * h * r);
    const double d_H = (fp.mean_curvature - fm.mean_curvature) / (2 * h * r);
    const double e_uc = std::abs(f.d_u_c_dr - d_uc) / std::abs(d_uc);
    const double e_n = length(f.d_normal_dr - d_n) / length(d_n);
    const double e_H = std::abs(f.d_mean_curvature_dr - d_H) / std::abs(d_H);
    // Measured relative differences (smooth kernel): 7.3e-7 (u_c), 2.4e-7 (normal), 3.7e-7 (H),
    // the size of the O(h²) error and of the jumps of the second derivative as neighbours cross
    // the boundary; a kernel derivative off by 25% (3 s t instead of 4 s t) fails all three.
    // The kernels ^3 and ^4 are smoother at the boundary (measured below 1e-7).
    measured(std::string("d u_c/dr analytic vs central difference, relative, ") + name(w), e_uc);
    measured(std::string("d n/dr analytic vs central difference, relative, ") + name(w), e_n);
    measured(std::string("d H/dr analytic vs central difference, relative, ") + name(w), e_H);
    CHECK(e_uc < 1e-4);
    CHECK(e_n < 1e-4);
    CHECK(e_H < 1e-4);
    CHECK(std::abs(f.d_normal_dr * f.normal) < 1e-12 * length(f.d_normal_dr));  // tangent
    // v is Equation 18 of these derivatives
    const double v =
      f.d_u_c_dr * f.d_u_c_dr + r * r * f.d_normal_dr.squared_length() + std::pow(r * r * f.d_mean_curvature_dr, 2);
    CHECK(f.geometric_variation == Approx(v).epsilon(1e-12));
  }
}

namespace {

// Integrates f(p, n, dA) over the part of the height field's graph inside the ball of radius
// R around the origin, with the area of the tangent plane (the continuum of the lattice
// samples): polar coordinates, the boundary rho(theta) of the 3-D ball found by Newton,
// Gauss-Legendre in rho, the midpoint rule in theta (spectral for periodic integrands).
template <class F>
void integrate_over_ball(const Height_field& s, double R, F f)
{
  static std::vector<double> node, weight;
  if(node.empty())
  {
    const int m = 64;
    for(int i = 0; i < m; ++i)
    {
      double x = std::cos(CGAL_PI * (i + 0.75) / (m + 0.5)), dp = 0;
      for(int it = 0; it < 100; ++it)
      {
        double p0 = 1, p1 = x;
        for(int k = 2; k <= m; ++k)
        {
          const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = m * (x * p1 - p0) / (x * x - 1);
        x -= p1 / dp;
      }
      node.push_back(x);
      weight.push_back(2 / ((1 - x * x) * dp * dp));
    }
  }
  const int angles = 256;
  for(int a = 0; a < angles; ++a)
  {
    const double th = 2 * CGAL_PI * (a + 0.5) / angles, c = std::cos(th), sn = std::sin(th);
    double rho = R;
    for(int it = 0; it < 50; ++it)
    {
      const double z = s.h(rho * c, rho * sn);
      const double dz = s.hx(rho * c, rho * sn) * c + s.hy(rho * c, rho * sn) * sn;
      rho -= (rho * rho + z * z - R * R) / (2 * rho + 2 * z * dz);
    }
    for(std::size_t i = 0; i < node.size(); ++i)
    {
      const double d = 0.5 * rho * (node[i] + 1), x = d * c, y = d * sn;
      const double hx = s.hx(x, y), hy = s.hy(x, y), l = std::sqrt(1 + hx * hx + hy * hy);
      const double p[3] = {x, y, s.h(x, y)}, n[3] = {-hx / l, -hy / l, 1 / l};
      f(p, n, 0.5 * rho * weight[i] * d * 2 * CGAL_PI / angles);
    }
  }
}

// The sums of Equations 2-4 of the continuum over the ball of radius r, in the frame
// q = p / frame (frame = r: the scaled frame; frame = 1: input units), each g_j weighted by
// omega(s) (s = |q|²): omega = 1 gives the constant-kernel sums, omega = r dw/dr their scale
// derivative as the package estimates it.
template <class Sums, class Omega>
void continuum_sums(const Height_field& s, double r, double frame, Omega omega, Sums& out)
{
  integrate_over_ball(s, r, [&](const double* p, const double* n, double dA) {
    const double q[3] = {p[0] / frame, p[1] / frame, p[2] / frame};
    const double ss = q[0] * q[0] + q[1] * q[1] + q[2] * q[2], w = omega(ss) * dA;
    out.A += w;
    for(int k = 0; k < 3; ++k)
    {
      out.B[k] += w * q[k];
      out.C[k] += w * n[k];
    }
    out.D += w * (q[0] * n[0] + q[1] * n[1] + q[2] * n[2]);
    out.E += w * ss;
  });
}

}  // namespace

TEST_CASE("Constant kernel: the scale derivatives are those of the continuum sums", "[features][derivatives]")
{
  // In the continuum, r d/dr of a constant-kernel sum is a boundary integral. The true value:
  // the sums in input units (g = 1, p, n, p.n, |p|²) by quadrature at r (1 ± 1e-4), central
  // difference, converted to the scaled frame (divided by r^k, k = 0, 1, 0, 1, 2). The
  // package's estimate: the same sums with the weight r dw/dr = 2 phi(s) of
  // Kernel_polynomial<Constant_kernel>. Both go through the package's sphere_features.
  namespace PSCI = PSC::internal;
  const Height_field& s = varying_paraboloid;
  for(double r : {0.1, 0.05})
  {
    PSCI::Algebraic_sphere_sums<PSCI::Constant_kernel> sums;
    const auto one = [](double) { return 1.0; };
    continuum_sums(s, r, r, one, sums);
    sums.count = 1000;  // any count above the minimum
    std::fill(sums.qq, sums.qq + 6, 0.0);
    sums.qq[0] = sums.qq[3] = 1;  // spread in two tangent directions (tested elsewhere)
    PSCI::Sphere_sums estimated, truth;
    continuum_sums(
      s, r, r, [](double ss) { return PSCI::r_dw_dr<PSCI::Constant_kernel>(ss); }, estimated);
    const double h = 1e-4;
    PSCI::Sphere_sums plus, minus;  // input units
    continuum_sums(s, r * (1 + h), 1.0, one, plus);
    continuum_sums(s, r * (1 - h), 1.0, one, minus);
    truth.A = (plus.A - minus.A) / (2 * h);
    for(int k = 0; k < 3; ++k)
    {
      truth.B[k] = (plus.B[k] - minus.B[k]) / (2 * h * r);
      truth.C[k] = (plus.C[k] - minus.C[k]) / (2 * h);
    }
    truth.D = (plus.D - minus.D) / (2 * h * r);
    truth.E = (plus.E - minus.E) / (2 * h * r * r);
    const PSCI::Local_sphere_features f = PSCI::sphere_features(sums, estimated, r);
    const PSCI::Local_sphere_features g = PSCI::sphere_features(sums, truth, r);
    REQUIRE((f.is_valid() && g.is_valid()));
    const Vector dn(f.d_normal[0], f.d_normal[1], f.d_normal[2]);
    const Vector dn_true(g.d_normal[0], g.d_normal[1], g.d_normal[2]);
    const double e_n = length(dn - dn_true) / length(dn_true);
    const double e_uc = std::abs(f.d_u_c / g.d_u_c - 1), e_H = std::abs(f.d_mean / g.d_mean - 1);
    // Measured relative errors: normal 3.9e-5 / 2.4e-6, u_c 9.6e-3 / 2.7e-3, H 9.7e-3 / 2.6e-3
    // (r = 0.1 / 0.05), O(r^4) and O(r²) as derived. With a weight exact for degree 1 only,
    // 2 (6 s - 2), the normal's error is 5e-3 / 1.3e-3 and u_c's and H's 0.37 and 0.57 at
    // both radii; with half the weight (phi instead of 2 phi) all three are 0.5.
    measured("constant kernel r dn/dr vs continuum, relative, r = " + std::to_string(r), e_n);
    measured("constant kernel du_c/dr vs continuum, relative, r = " + std::to_string(r), e_uc);
    measured("constant kernel r^2 dH/dr vs continuum, relative, r = " + std::to_string(r), e_H);
    CHECK(e_n < 2e-4);
    CHECK(e_uc < 0.02);
    CHECK(e_H < 0.02);
    // and the continuum itself follows Proposition 2: measured v / law 0.969 and 0.992
    const double ratio = g.geometric_variation / (s.grad_H_squared() * std::pow(r, 4) / 4);
    measured("continuum constant-kernel v / law, r = " + std::to_string(r), ratio);
    CHECK(std::abs(ratio - 1) < 0.05);
  }
}

TEST_CASE("Multi-scale features equal the single-scale ones at every radius", "[features][multiscale]")
{
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  const std::vector<double> radii = {1.5, 0.8, 2.5, 1.5, 1.1};  // any order, duplicates allowed
  for(Weight w : all_kernels)
  {
    INFO(name(w));
    const auto ms = CGAL::estimate_multiscale_algebraic_sphere_features<Par>(pts, radii, maps(w));
    REQUIRE(ms.size() == radii.size());
    for(std::size_t k = 0; k < radii.size(); ++k)
    {
      const double r = radii[k];
      const auto ss = CGAL::estimate_algebraic_sphere_features<Par>(pts, r, maps(w));
      REQUIRE(ms[k].size() == pts.size());
      double e = 0, e_v = 0;
      std::size_t counts = 0, too_few = 0;
      for(std::size_t i = 0; i < pts.size(); ++i)
      {
        const Features &a = ms[k][i], &b = ss[i];
        REQUIRE(a.status == b.status);
        if(!a.is_valid())
        {
          // below the default minimum of 12 neighbours (a few points at r = 0.8)
          REQUIRE(a.status == Status::TOO_FEW_NEIGHBORS);
          ++too_few;
          continue;
        }
        counts += a.neighbor_count == b.neighbor_count ? 0 : 1;
        CHECK(a.kernel_radius == r);
        // coefficients in units of r: u_c / r, u_q r, u_l, p, normal
        e = std::max({e, std::abs(a.u_c - b.u_c) / r, std::abs(a.u_q - b.u_q) * r, length(a.u_l - b.u_l),
                      std::abs(a.pratt_norm - b.pratt_norm), length(a.normal - b.normal)});
        e_v = std::max(e_v, std::abs(a.geometric_variation - b.geometric_variation) / b.geometric_variation);
      }
      // Measured: coefficients 5e-15, v 3e-12 relative (the moments lose about a digit to the
      // direct sums; v is a sum of squares of small derivatives).
      measured("multi-scale vs single-scale coefficients, r = " + std::to_string(r), e);
      measured("multi-scale vs single-scale v relative, r = " + std::to_string(r), e_v);
      CHECK(counts == 0);
      CHECK(e < 1e-12);
      CHECK(e_v < 1e-9);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Asymptotic laws
// ---------------------------------------------------------------------------------------

TEST_CASE("Cylinder: 1 - p = r^2/(16 R^2) (constant kernel), r^2/(32 R^2) (smooth kernel)", "[features][laws]")
{
  const double R = 1.0;
  const auto pts = cylinder(628, 100, R, 1.0, 3);  // spacing 0.01, jittered grid
  for(Weight w : both_kernels)
    for(double r : {0.1, 0.2})
    {
      const double law = r * r / ((w == Weight::CONSTANT ? 16 : 32) * R * R);
      const auto f = CGAL::estimate_algebraic_sphere_features<Par>(pts, r, maps(w));
      double lo = 1e9, hi = -1e9;
      for(std::size_t i = 0; i < pts.size(); ++i)
        if(std::abs(pts[i].first.z()) < 0.49 - r)  // whole neighbourhoods only
        {
          REQUIRE(f[i].is_valid());
          lo = std::min(lo, f[i].anisotropy / law);
          hi = std::max(hi, f[i].anisotropy / law);
        }
      // Measured ratios (about 300 and 1250 neighbours): constant [0.961, 1.030] (r = 0.1),
      // [0.989, 1.011] (r = 0.2); smooth [0.985, 1.017], [0.997, 1.004]: within the 10% asked.
      measured(std::string("cylinder ") + name(w) + " (1-p)/law min, r = " + std::to_string(r), lo);
      measured(std::string("cylinder ") + name(w) + " (1-p)/law max, r = " + std::to_string(r), hi);
      CHECK(lo > 0.9);
      CHECK(hi < 1.1);
    }
}

TEST_CASE("Ellipsoid: 1 - p = (k1-k2)^2 r^2/16 (constant), /32 (smooth) where it is not tiny", "[features][laws]")
{
  const double a = 1, b = 0.8, c = 0.6, r = 0.1;
  const auto pts = fibonacci_ellipsoid(100000, a, b, c);
  for(Weight w : both_kernels)
  {
    const double factor = r * r / (w == Weight::CONSTANT ? 16 : 32);
    const auto f = CGAL::estimate_algebraic_sphere_features<Par>(pts, r, maps(w));
    double lo = 1e9, hi = -1e9;
    std::size_t used = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      const Truth t = ellipsoid_truth(pts[i].first, a, b, c);
      const double dk = t.k_max - t.k_min;  // from 0 at the umbilics to 1.42
      // Not tiny: |k1 - k2| >= 0.8. Near the umbilics the next term of the expansion (order r⁴,
      // with derivatives of the curvatures that do not vanish there) is no longer small against
      // (k1 - k2)² r²: at |k1 - k2| = 0.3 the measured ratios reach 1.18.
      if(dk < 0.8)
        continue;
      REQUIRE(f[i].is_valid());
      ++used;
      lo = std::min(lo, f[i].anisotropy / (dk * dk * factor));
      hi = std::max(hi, f[i].anisotropy / (dk * dk * factor));
    }
    // Measured over the ~47000 points used (about 430 neighbours): constant [0.952, 1.052],
    // smooth [0.971, 1.032].
    measured(std::string("ellipsoid ") + name(w) + " (1-p)/law min", lo);
    measured(std::string("ellipsoid ") + name(w) + " (1-p)/law max", hi);
    CHECK(used > 40000);
    CHECK(lo > 0.9);
    CHECK(hi < 1.1);
  }
}

TEST_CASE("Paraboloid with varying curvature: v = |grad H|^2 r^4/16 (smooth), /4 (constant)", "[features][laws]")
{
  const Height_field& s = varying_paraboloid;  // |∇H|² = 0.445
  for(double r : {0.1, 0.05})
  {
    // Smooth kernel: v is computed analytically. Measured v / law: 0.982 (r = 0.1), 0.996
    // (r = 0.05); at r = 0.2 it is 0.93 and at 0.4 0.78 (higher-order terms).
    const Features f = patch_features(s, r, Weight::SMOOTH);
    REQUIRE(f.is_valid());
    const double ratio = f.geometric_variation / (s.grad_H_squared() * std::pow(r, 4) / 16);
    measured("paraboloid smooth v/law, r = " + std::to_string(r), ratio);
    CHECK(std::abs(ratio - 1) < 0.2);

    // Constant kernel: v with the boundary-term derivative (the paper's constant), at 20
    // evaluation points between the lattice samples (the estimate moves with the points near
    // the boundary of the ball). Measured v / law: mean 0.969 / 0.992, farthest from 1 0.960 /
    // 0.975 (r = 0.1 / 0.05); the continuum value is 0.969 / 0.992 (test above). With the
    // weight 2 psi_2 of least i.i.d. variance, which jumps at the boundary, the farthest of 40
    // points is 0.83 at r = 0.05 and 1.39 at r = 0.025. This law only sees the normal's term
    // of v; the test above checks all three.
    const auto lattice = lattice_patch(s, 1.3 * r, r / 100);
    const Surface surface(lattice, r, maps(Weight::CONSTANT));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> offset(-r / 100, r / 100);
    double mean = 0, farthest = 1;
    for(int i = 0; i < 20; ++i)
    {
      const double x = offset(rng), y = offset(rng);
      const Features c = surface.features(Point(x, y, s.h(x, y)));
      REQUIRE(c.is_valid());
      const double c_ratio = c.geometric_variation / (s.grad_H_squared() * std::pow(r, 4) / 4);
      mean += c_ratio / 20;
      if(std::abs(c_ratio - 1) > std::abs(farthest - 1))
        farthest = c_ratio;
    }
    measured("paraboloid constant v/law, mean of 20 points, r = " + std::to_string(r), mean);
    measured("paraboloid constant v/law, farthest from 1, r = " + std::to_string(r), farthest);
    CHECK(std::abs(mean - 1) < 0.05);
    CHECK(std::abs(farthest - 1) < 0.1);
    const Features cp = patch_features(s, r, Weight::CONSTANT, 1.2);
    const Features cm = patch_features(s, r, Weight::CONSTANT, 0.8);
    const double v = ((cp.normal - cm.normal) / 0.4).squared_length();
    const double fd_ratio = v / (s.grad_H_squared() * std::pow(r, 4) / 4);
    measured("paraboloid constant (r dn/dr)^2 by differences / law, r = " + std::to_string(r), fd_ratio);
    CHECK(std::abs(fd_ratio - 1) < 0.2);
  }
}

TEST_CASE("Paraboloid: u_c = (9H^3-5KH-lap H) r^4/96 (constant), (19H^3-11KH-2 lap H) r^4/640 (smooth)",
          "[features][laws]")
{
  // Theorem 1 (the paper's sign of H is the opposite of ours, hence its leading minus sign).
  const Height_field& s = varying_paraboloid;
  const double r = 0.05;
  const double H = s.H(), K = s.K(), L = s.laplacian_H();
  const double law_constant = (9 * H * H * H - 5 * K * H - L) / 96 * std::pow(r, 4);
  const double law_smooth = (19 * H * H * H - 11 * K * H - 2 * L) / 640 * std::pow(r, 4);
  const double ratio_c = patch_features(s, r, Weight::CONSTANT).u_c / law_constant;
  const double ratio_s = patch_features(s, r, Weight::SMOOTH).u_c / law_smooth;
  // Measured: 0.996 (constant), 1.009 (smooth); at r = 0.1 1.087 and 1.036. A 4th-order
  // quantity: with ~8000 jittered random samples instead of the lattice the error reaches 60%.
  measured("paraboloid constant u_c/law", ratio_c);
  measured("paraboloid smooth u_c/law", ratio_s);
  CHECK(std::abs(ratio_c - 1) < 0.1);
  CHECK(std::abs(ratio_s - 1) < 0.1);
  // Both laws vanish on a sphere, where u_c = 0 exactly: its height field z = R - sqrt(R² - ρ²)
  // = ρ²/(2R) + ρ⁴/(8R³) + ... has a20 = a02 = 1/R, a40 = a04 = 3/R³, a22 = 1/R³ (ΔH = 4H³).
  const double R = 3;
  const Height_field ball = {1 / R, 1 / R, 0, 0, 0, 0, 3 / (R * R * R), 0, 1 / (R * R * R), 0, 3 / (R * R * R)};
  const double Hs = ball.H(), Ks = ball.K(), Ls = ball.laplacian_H();
  CHECK(std::abs(9 * Hs * Hs * Hs - 5 * Ks * Hs - Ls) < 1e-15);
  CHECK(std::abs(19 * Hs * Hs * Hs - 11 * Ks * Hs - 2 * Ls) < 1e-15);
}

// ---------------------------------------------------------------------------------------
// Projection onto the APSS surface
// ---------------------------------------------------------------------------------------

TEST_CASE("Projection onto a sampled sphere lands on it to 1e-12 with the radial normal", "[projection][sphere]")
{
  const double R = 2.0, r = 0.4;
  const Point c(1, -2, 3);
  const auto pts = sphere(20000, R, c);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for(Weight w : all_kernels)
  {
    const Surface surface(pts, r, maps(w));
    CHECK(surface.number_of_points() == pts.size());
    double e = 0, e_n = 0;
    std::size_t iterations = 0;
    for(int i = 0; i < 200; ++i)
    {
      // positions up to 0.25 r off the sphere
      Vector d(u(rng), u(rng), u(rng));
      d = d / length(d);
      const Point x = c + (R + 0.25 * r * u(rng)) * d;
      const auto p = surface.project(x);
      REQUIRE(p.is_valid());
      e = std::max(e, std::abs(distance(p.point, c) - R));
      e_n = std::max(e_n, length(p.normal - (p.point - c) / R));
      iterations = std::max(iterations, p.iterations);
    }
    // Measured: 4e-16 from the sphere, normals 1e-15; 2 steps (the second one confirms).
    measured(std::string("sphere projection distance ") + name(w), e);
    CHECK(e < 1e-12);
    CHECK(e_n < 1e-12);
    CHECK(iterations <= 3);
  }
}

TEST_CASE("Projection handles the plane case u_q = 0 and projects orthogonally", "[projection][plane]")
{
  // a tilted plane through (1, 2, 3) with unit normal m, exact normals
  const Vector m = Vector(1, -2, 2) / 3;
  const Vector t1 = Vector(2, 1, 0) / std::sqrt(5.0);
  const Vector t2 = CGAL::cross_product(m, t1);
  std::vector<Oriented_point> pts;
  for(int i = -30; i <= 30; ++i)
    for(int j = -30; j <= 30; ++j)
      pts.emplace_back(Point(1, 2, 3) + 0.05 * i * t1 + 0.05 * j * t2 + 0.013 * ((i * 7 + j * 3) % 5) * t1, m);
  const Surface surface(pts, 0.3, maps());
  const Point x = Point(1, 2, 3) + 0.2 * t1 - 0.4 * t2 + 0.1 * m;
  const auto p = surface.project(x);
  REQUIRE(p.is_valid());
  CHECK(distance(p.point, x - 0.1 * m) < 1e-12);
  CHECK(length(p.normal - m) < 1e-12);
  const Features f = surface.features(x);
  CHECK(f.is_plane);
  CHECK(std::abs(f.u_c - 0.1) < 1e-12);  // the algebraic distance of a plane is the distance
}

TEST_CASE("Projection onto Goursat's APSS surface converges near the surface and is idempotent",
          "[projection][goursat]")
{
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  const Surface surface(pts, 1.5, maps());
  std::mt19937 rng(1);
  std::normal_distribution<double> g(0, 0.3);
  double far = 0, again = 0;
  std::size_t iterations = 0;
  for(int i = 0; i < 500; ++i)
  {
    const Point x = pts[(i * 37) % pts.size()].first + Vector(g(rng), g(rng), g(rng));
    const auto p = surface.project(x);
    REQUIRE(p.is_valid());
    iterations = std::max(iterations, p.iterations);
    far = std::max(far, std::abs(goursat_distance(p.point)));
    again = std::max(again, distance(surface.project(p.point).point, p.point));
    CHECK(std::abs(length(p.normal) - 1) < 1e-12);
  }
  // Measured: at most 5 steps; 1.7e-3 from the true surface (the APSS surface at r = 1.5 on
  // 10K points, spacing about 0.3); a second projection moves by 1.5e-13 (tolerance 1.5e-10).
  measured("goursat projection max steps", double(iterations));
  measured("goursat projection max distance to the surface", far);
  measured("goursat projection idempotence", again);
  CHECK(iterations <= 10);
  CHECK(far < 0.01);
  CHECK(again < 1e-9);
}

TEST_CASE("Features at arbitrary positions agree with the cloud function at cloud points", "[projection][features]")
{
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  for(Weight w : all_kernels)
  {
    const Surface surface(pts, 1.5, maps(w));
    const auto f = CGAL::estimate_algebraic_sphere_features<Seq>(pts, 1.5, maps(w));
    double e = 0;
    for(std::size_t i = 0; i < pts.size(); i += 97)
    {
      const Features g = surface.features(pts[i].first);
      REQUIRE(g.neighbor_count == f[i].neighbor_count);
      e = std::max({e, std::abs(g.u_q - f[i].u_q) * 1.5, length(g.u_l - f[i].u_l), std::abs(g.u_c - f[i].u_c) / 1.5,
                    distance(g.projection, f[i].projection) / 1.5});
      e = std::max(e, std::abs(g.geometric_variation - f[i].geometric_variation) / f[i].geometric_variation);
    }
    // Measured 7.6e-14 (smooth), 5.8e-14 (constant), driven by the relative v: another
    // summation order.
    measured(std::string("features(x) vs cloud function ") + name(w), e);
    CHECK(e < 1e-10);
  }
}

// ---------------------------------------------------------------------------------------
// Bilaplacian flow
// ---------------------------------------------------------------------------------------

TEST_CASE("The flow leaves a sampled sphere fixed", "[flow][sphere]")
{
  const auto pts = sphere(5000, 2.0, Point(1, -2, 3));
  for(Weight w : all_kernels)
    for(bool update : {false, true})
    {
      auto moved = pts;
      const auto status = CGAL::apss_smooth_point_set<Par>(
        moved, 0.5, PSC::parameters::update_normals(update, maps(w)).number_of_iterations(5));
      double e = 0, e_n = 0;
      for(std::size_t i = 0; i < pts.size(); ++i)
      {
        CHECK(status[i] == Status::VALID);
        e = std::max(e, distance(moved[i].first, pts[i].first));
        e_n = std::max(e_n, length(moved[i].second - pts[i].second));
      }
      measured(std::string("sphere flow displacement after 5 iterations, ") + name(w), e);
      CHECK(e < 1e-12);  // measured 1e-15
      CHECK(e_n < 1e-12);
    }
}

TEST_CASE("The flow decreases the RMS distance to a noisy sphere at each iteration", "[flow][sphere]")
{
  const double R = 1.0, sigma = 0.01;
  auto noisy = sphere(20000, R);
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, sigma);
  for(auto& p : noisy)
    p.first = p.first + Vector(g(rng), g(rng), g(rng));  // normals: those of the exact samples
  auto rms = [&](const std::vector<Oriented_point>& pts) {
    double s = 0;
    for(const auto& p : pts)
      s += std::pow(length(p.first - CGAL::ORIGIN) - R, 2);
    return std::sqrt(s / pts.size());
  };
  for(Weight w : all_kernels)
    for(bool update : {false, true})
    {
      INFO(name(w) << (update ? ", normals updated" : ", input normals"));
      auto pts = noisy;
      double previous = rms(pts);
      // Measured (smooth kernel, both normal modes): 0.0100, 0.00131, 0.00092, 0.00076, ...,
      // 0.00041 after 10 iterations; the mean distance to the centre stays 1.0001.
      for(int it = 1; it <= 10; ++it)
      {
        CGAL::apss_smooth_point_set<Par>(pts, 0.15, PSC::parameters::update_normals(update, maps(w)));
        const double now = rms(pts);
        measured(std::string("noisy sphere RMS, ") + name(w) + (update ? " updated" : " input") + ", iteration " +
                   std::to_string(it),
                 now);
        CHECK(now < previous);
        previous = now;
      }
      CHECK(previous < 0.1 * sigma);
    }
}

TEST_CASE("30 iterations of the flow on noisy Goursat 10K (paper's Figure 3 setting) do not collapse it",
          "[flow][goursat]")
{
  // Figure 3: 30 projections on algebraic spheres of a noisy cloud, positions and normals
  // evolving (update_normals). Noise sigma = 0.05, about 1/6 of the spacing; r = 1.5.
  auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  std::mt19937 rng(4);
  std::normal_distribution<double> g(0, 0.05);
  for(auto& p : pts)
    p.first = p.first + Vector(g(rng), g(rng), g(rng));
  auto mean_norm = [](const std::vector<Oriented_point>& q) {
    double s = 0;
    for(const auto& p : q)
      s += length(p.first - CGAL::ORIGIN);
    return s / q.size();
  };
  auto rms_distance = [](const std::vector<Oriented_point>& q) {
    double s = 0;
    for(const auto& p : q)
      s += std::pow(goursat_distance(p.first), 2);
    return std::sqrt(s / q.size());
  };
  const double size0 = mean_norm(pts), rms0 = rms_distance(pts);
  const auto status =
    CGAL::apss_smooth_point_set<Par>(pts, 1.5, PSC::parameters::update_normals(true, maps()).number_of_iterations(30));
  for(const Status s : status)
    CHECK(s == Status::VALID);
  const double size = mean_norm(pts), rms = rms_distance(pts);
  double unit = 0;
  for(const auto& p : pts)
    unit = std::max(unit, std::abs(length(p.second) - 1));
  // Measured: mean distance to the centre 11.4218 -> 11.4213 (-0.004%; the PCA-plane flow of
  // the same figure, run outside the tests, shrinks it to 10.6455, -6.8%); RMS distance to the
  // Goursat surface 0.0505 -> 0.0083 after 2 iterations, then 0.157 after 30: the flow rounds
  // the shape (its fixed points are spheres), without shrinking it.
  measured("goursat flow mean |p| before", size0);
  measured("goursat flow mean |p| after 30", size);
  measured("goursat flow RMS distance before", rms0);
  measured("goursat flow RMS distance after 30", rms);
  CHECK(std::abs(size / size0 - 1) < 0.005);
  CHECK(rms < 0.3);
  CHECK(unit < 1e-12);  // the written normals are unit
}

TEST_CASE("The flow with input normals keeps them and moves points along them", "[flow]")
{
  auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0, 0.05);
  for(auto& p : pts)
    p.first = p.first + Vector(g(rng), g(rng), g(rng));
  const auto before = pts;
  CGAL::apss_smooth_point_set<Seq>(pts, 1.5, maps().number_of_iterations(30));
  double rms = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    CHECK(pts[i].second == before[i].second);
    rms += std::pow(goursat_distance(pts[i].first), 2);
  }
  rms = std::sqrt(rms / pts.size());
  // Measured 0.0058 (from 0.0505): the exact input normals anchor the surface.
  measured("goursat flow with input normals, RMS distance after 30", rms);
  CHECK(rms < 0.02);
}

// ---------------------------------------------------------------------------------------
// Kernel option, API, bad input
// ---------------------------------------------------------------------------------------

TEST_CASE("weight_kernel selects the kernel of estimate_apss_curvatures", "[kernel][apss]")
{
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  const auto smooth = CGAL::estimate_apss_curvatures<Seq>(pts, 1.5, maps());
  const auto smooth2 = CGAL::estimate_apss_curvatures<Seq>(pts, 1.5, maps(Weight::SMOOTH));
  const auto constant = CGAL::estimate_apss_curvatures<Seq>(pts, 1.5, maps(Weight::CONSTANT));
  const auto f = CGAL::estimate_algebraic_sphere_features<Seq>(pts, 1.5, maps(Weight::CONSTANT));
  std::size_t differ = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    CHECK(smooth[i].mean_curvature == smooth2[i].mean_curvature);
    CHECK(constant[i].mean_curvature == f[i].mean_curvature);
    differ += constant[i].mean_curvature != smooth[i].mean_curvature ? 1 : 0;
  }
  CHECK(differ > pts.size() / 2);
}

TEST_CASE("Point_set_3, Epick and the explicit-maps overload give the same features", "[features][api]")
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  const auto ref = CGAL::estimate_algebraic_sphere_features<Seq>(pts, Point_map(), Normal_map(), 1.5);
  CGAL::Point_set_3<Epick::Point_3, Epick::Vector_3> set;
  set.add_normal_map();
  for(const auto& p : pts)
    set.insert(Epick::Point_3(p.first.x(), p.first.y(), p.first.z()),
               Epick::Vector_3(p.second.x(), p.second.y(), p.second.z()));
  const auto f = CGAL::estimate_algebraic_sphere_features<Seq>(set, 1.5);
  REQUIRE(f.size() == pts.size());
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    CHECK(f[i].u_q == ref[i].u_q);
    CHECK(f[i].geometric_variation == ref[i].geometric_variation);
  }
  // the flow on a Point_set_3, normals written through its normal map
  auto set_copy = set;
  CGAL::apss_smooth_point_set<Seq>(set_copy, 1.5, PSC::parameters::update_normals(true));
  std::size_t moved = 0;
  for(auto it = set.begin(); it != set.end(); ++it)
    moved += set_copy.point(*it) != set.point(*it) ? 1 : 0;
  CHECK(moved > pts.size() / 2);
  // a std::list (not random access)
  const std::list<Oriented_point> list(pts.begin(), pts.end());
  const auto g = CGAL::estimate_algebraic_sphere_features<Seq>(list, 1.5, maps());
  for(std::size_t i = 0; i < pts.size(); ++i)
    CHECK(same(g[i], ref[i]));
}

TEST_CASE("Bad radii, radii lists and parameters throw std::invalid_argument naming them", "[bad_input]")
{
  const auto pts = sphere(500, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  for(double r : {0.0, -1.0, std::nan(""), inf})
  {
    INFO("radius " << r);
    CHECK_THAT(invalid_argument_message([&] { CGAL::estimate_algebraic_sphere_features<Seq>(pts, r, maps()); }),
               Contains("radius"));
    CHECK_THAT(invalid_argument_message([&] { CGAL::estimate_algebraic_sphere_features<Par>(pts, r, maps()); }),
               Contains("radius"));
    CHECK_THAT(invalid_argument_message([&] {
                 CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(pts, {0.5, r}, maps());
               }),
               Contains("radii"));
    CHECK_THAT(invalid_argument_message([&] {
                 auto copy = pts;
                 CGAL::apss_smooth_point_set<Seq>(copy, r, maps());
               }),
               Contains("radius"));
    CHECK_THAT(invalid_argument_message([&] { Surface(pts, r, maps()); }), Contains("radius"));
  }
  CHECK_THAT(invalid_argument_message(
               [&] { CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(pts, std::vector<double>(), maps()); }),
             Contains("radii"));
  CHECK_THAT(invalid_argument_message([&] {
               CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(pts, {0.5},
                                                                        PSC::parameters::neighbor_count(10, maps()));
             }),
             Contains("neighbor_count"));
  CHECK_THAT(invalid_argument_message([&] {
               CGAL::estimate_algebraic_sphere_features<Seq>(pts, 0.5, PSC::parameters::neighbor_count(10, maps()));
             }),
             Contains("neighbor_count"));
  CHECK_THAT(invalid_argument_message([&] {
               auto copy = pts;
               CGAL::apss_smooth_point_set<Seq>(copy, 0.5, maps().number_of_iterations(-1));
             }),
             Contains("number_of_iterations"));
  // update_normals with a read-only normal map
  CHECK_THAT(invalid_argument_message([&] {
               auto copy = pts;
               auto normal_of = [](const Oriented_point& p) { return p.second; };
               CGAL::apss_smooth_point_set<Seq>(
                 copy, 0.5,
                 PSC::parameters::update_normals(
                   true, CGAL::parameters::point_map(Point_map())
                           .normal_map(boost::make_function_property_map<Oriented_point>(normal_of))));
             }),
             Contains("update_normals"));
  Surface surface(pts, 0.5, maps());
  CHECK_THAT(invalid_argument_message([&] { surface.set_tolerance(-1); }), Contains("tolerance"));
  CHECK_THAT(invalid_argument_message([&] { surface.set_maximum_number_of_iterations(0); }),
             Contains("maximum_number_of_iterations"));
}

TEST_CASE("Empty ranges, unusable points, too few neighbours and degenerate fits", "[bad_input]")
{
  const std::vector<Oriented_point> none;
  CHECK(CGAL::estimate_algebraic_sphere_features<Seq>(none, 1.0, maps()).empty());
  const auto ms = CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(none, {1.0, 2.0}, maps());
  CHECK((ms.size() == 2 && ms[0].empty() && ms[1].empty()));
  auto empty = none;
  CHECK(CGAL::apss_smooth_point_set<Seq>(empty, 1.0, maps()).empty());
  CHECK(Surface(none, 1.0, maps()).project(Point(0, 0, 0)).status == CGAL::Apss_projection_status::TOO_FEW_NEIGHBORS);

  auto pts = sphere(2000, 1.0);
  const double nan = std::nan("");
  pts[10].first = Point(nan, 0, 0);
  pts[20].second = Vector(0, 0, 0);
  pts[30].second = Vector(nan, 1, 0);
  pts.emplace_back(Point(10, 10, 10), Vector(0, 0, 1));  // isolated: only itself
  for(int i = 0; i < 12; ++i)                            // 12 coincident points (the default minimum)
    pts.emplace_back(Point(-10, 0, 0), Vector(0, 0, 1));
  const std::size_t n = pts.size();
  const auto f = CGAL::estimate_algebraic_sphere_features<Seq>(pts, 0.3, maps());
  const auto m = CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(pts, {0.2, 0.3}, maps());
  for(const auto* r : {&f, &m[0], &m[1]})
  {
    const auto& v = *r;
    CHECK(v[10].status == Status::NON_FINITE_POINT);
    CHECK(v[20].status == Status::INVALID_NORMAL);
    CHECK(v[30].status == Status::INVALID_NORMAL);
    CHECK(v[n - 13].status == Status::TOO_FEW_NEIGHBORS);
    CHECK(v[n - 13].neighbor_count == 1);
    CHECK(v[n - 1].status == Status::DEGENERATE_FIT);
    for(std::size_t i : {std::size_t(10), std::size_t(20), std::size_t(30), n - 13, n - 1})
      CHECK(all_nan(v[i]));
  }
  // unusable points are nobody's neighbour: the others' results equal those of the cloud
  // without them
  std::vector<Oriented_point> clean;
  std::vector<std::size_t> kept;
  for(std::size_t i = 0; i < n; ++i)
    if(i != 10 && i != 20 && i != 30)
    {
      clean.push_back(pts[i]);
      kept.push_back(i);
    }
  const auto g = CGAL::estimate_algebraic_sphere_features<Seq>(clean, 0.3, maps());
  std::size_t differ = 0;
  for(std::size_t j = 0; j < clean.size(); ++j)
  {
    const Features& a = g[j];
    const Features& b = f[kept[j]];
    differ +=
      a.status == b.status && a.neighbor_count == b.neighbor_count && (!a.is_valid() || std::abs(a.u_q - b.u_q) < 1e-12)
        ? 0
        : 1;
  }
  CHECK(differ == 0);

  // the flow leaves unusable, isolated and degenerate points in place
  auto flowed = pts;
  const auto status = CGAL::apss_smooth_point_set<Seq>(flowed, 0.3, maps().number_of_iterations(2));
  CHECK(status[10] == Status::NON_FINITE_POINT);
  CHECK(status[20] == Status::INVALID_NORMAL);
  CHECK(status[n - 13] == Status::TOO_FEW_NEIGHBORS);
  CHECK(status[n - 1] == Status::DEGENERATE_FIT);
  CHECK(std::isnan(flowed[10].first.x()));
  CHECK(flowed[20].second == Vector(0, 0, 0));
  CHECK(flowed[n - 13].first == pts[n - 13].first);
  CHECK(flowed[n - 1].first == pts[n - 1].first);

  // projection: non-finite position, far from the cloud, at the centre of the fitted sphere
  const Surface surface(pts, 0.3, maps());
  CHECK(surface.number_of_points() == n - 3);
  auto p = surface.project(Point(nan, 0, 0));
  CHECK(p.status == CGAL::Apss_projection_status::NON_FINITE_POINT);
  CHECK(std::isnan(p.point.x()));
  p = surface.project(Point(5, 5, 5));
  CHECK(p.status == CGAL::Apss_projection_status::TOO_FEW_NEIGHBORS);
  CHECK((std::isnan(p.point.x()) && std::isnan(p.normal.x()) && p.neighbor_count == 0));
  p = surface.project(Point(-10, 0, 0.1));
  CHECK(p.status == CGAL::Apss_projection_status::DEGENERATE_FIT);
  CHECK(std::isnan(p.point.x()));
  CHECK(surface.features(Point(nan, 0, 0)).status == Status::NON_FINITE_POINT);
  CHECK(surface.features(Point(5, 5, 5)).status == Status::TOO_FEW_NEIGHBORS);
}

TEST_CASE("callback: progress in [0,1], and returning false cancels features and flow", "[callback]")
{
  const auto pts = read_xyz(repo_data("goursat_050000.xyz"));
  std::vector<double> seen;
  auto record = [&](double x) {
    seen.push_back(x);
    return true;
  };
  CGAL::estimate_algebraic_sphere_features<Seq>(pts, 1.0, maps().callback(record));
  REQUIRE(!seen.empty());
  CHECK(seen.back() == 1.0);
  for(std::size_t i = 1; i < seen.size(); ++i)
    CHECK(seen[i] >= seen[i - 1]);

  auto stop = [](double) { return false; };
  const auto f = CGAL::estimate_algebraic_sphere_features<Seq>(pts, 1.0, maps().callback(stop));
  const auto m = CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(pts, {0.5, 1.0}, maps().callback(stop));
  std::size_t not_computed = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    not_computed += f[i].status == Status::NOT_COMPUTED ? 1 : 0;
    if(f[i].status == Status::NOT_COMPUTED)
      CHECK((all_nan(f[i]) && m[1][i].status == Status::NOT_COMPUTED));
  }
  CHECK(not_computed > pts.size() / 2);

  // flow: 3 iterations, cancelled during the second one
  seen.clear();
  auto flowed = pts;
  auto half = [&](double x) {
    seen.push_back(x);
    return x < 0.5;
  };
  const auto status = CGAL::apss_smooth_point_set<Seq>(flowed, 1.0, maps().number_of_iterations(3).callback(half));
  REQUIRE(!seen.empty());
  CHECK(seen.back() >= 0.5);
  CHECK(seen.back() < 2.0 / 3.0 + 1e-12);  // the third iteration never started
  std::size_t stopped = 0, moved_in_place = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(status[i] == Status::NOT_COMPUTED)
    {
      ++stopped;
      // moved once (first iteration), not twice
      moved_in_place += flowed[i].first != pts[i].first ? 1 : 0;
    }
  CHECK(stopped > 0);
  CHECK(moved_in_place == stopped);
}

// ---------------------------------------------------------------------------------------
// Degenerate inputs found in review.

TEST_CASE("Features, multi-scale features and the APSS surface are DEGENERATE_FIT on a circle, like APSS",
          "[features][bad_input]")
{
  // A circle of radius 2 in z = 0 with in-plane normals: the sphere fitted to one curve takes
  // the curvature along it for a mean curvature. The curvature function said so; the
  // features (which reproduce its normal and mean curvature) now agree.
  std::vector<Oriented_point> circle;
  for(int i = 0; i < 400; ++i)
  {
    const double a = 2 * M_PI * i / 400.0;
    circle.emplace_back(Point(2 * std::cos(a), 2 * std::sin(a), 0), Vector(std::cos(a), std::sin(a), 0));
  }
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  const auto apss = CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(circle, 0.5, np);
  const auto features = CGAL::estimate_algebraic_sphere_features<CGAL::Sequential_tag>(circle, 0.5, np);
  const std::vector<double> radii = {0.3, 0.5};
  const auto multi = CGAL::estimate_multiscale_algebraic_sphere_features<CGAL::Sequential_tag>(circle, radii, np);
  for(std::size_t i = 0; i < circle.size(); i += 37)
  {
    CHECK(apss[i].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
    CHECK(features[i].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
    CHECK(std::isnan(features[i].mean_curvature));
    for(const auto& scale : multi)
      CHECK(scale[i].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
  }
}

TEST_CASE("Algebraic_point_set_surface builds on a cloud spanning +-1e308", "[projection][bad_input]")
{
  // The grid's cell size used to double to infinity and loop forever when the extent
  // overflowed; the far points are now in one cell and nobody's neighbour.
  std::vector<Oriented_point> pts = sphere(300, 1.0);
  pts.emplace_back(Point(1e308, 0, 0), Vector(1, 0, 0));
  pts.emplace_back(Point(-1e308, 0, 0), Vector(-1, 0, 0));
  CGAL::Algebraic_point_set_surface<Kernel> surface(pts, 0.5,
                                                    CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  const auto projected = surface.project(Point(0, 0, 1.1));
  REQUIRE(projected.is_valid());
  CHECK(std::abs(std::sqrt(CGAL::squared_distance(projected.point, Point(0, 0, 0))) - 1) < 1e-6);
}

// Sample weights (issue 11): the same quadrature argument as for the ASO. A sphere stays
// exact; on i.i.d. samples with a density ramp the APSS mean curvature of the features gets
// closer to the truth; the multi-scale function refuses them.
TEST_CASE("Sphere features with tangent Voronoi area weights: exact on a sphere, refused by the multi-scale function",
          "[features][robust]")
{
  const auto pts = sphere(5000, 1.0);
  const auto weighted = CGAL::estimate_algebraic_sphere_features<Seq>(
    pts, 0.3, PSC::parameters::sample_weights(CGAL::Sample_weights::TANGENT_VORONOI_AREA, maps()));
  double worst = 0;
  for(const auto& f : weighted)
  {
    REQUIRE(f.is_valid());
    worst = std::max(worst, std::abs(f.mean_curvature - 1));
  }
  CHECK(worst < 1e-9);  // measured below 1e-13
  CHECK_THROWS_AS(
    CGAL::estimate_multiscale_algebraic_sphere_features<Seq>(
      pts, {0.2, 0.3}, PSC::parameters::sample_weights(CGAL::Sample_weights::TANGENT_VORONOI_AREA, maps())),
    std::invalid_argument);
}
