// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of the core package: estimate_aso_curvatures(), estimate_apss_curvatures() and the
// per-query classes Algebraic_shape_operator_fit and Algebraic_sphere_fit, through the
// public API only. Each TEST_CASE states one property (most are claims of Lejemble et al.
// 2021 or requirements of the package's issue); every tolerance says what was measured
// (Release build, x86-64, GCC) and why the bound is what it is. Run the tests with
// PSC_TEST_PRINT=1 in the environment to print the measured values again.

#include "scan_simulator.h"
#include "test_core_support.h"

#include <CGAL/Algebraic_shape_operator_fit.h>
#include <CGAL/Algebraic_sphere_fit.h>
#include <CGAL/Point_set_curvatures/average_spacing.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_oriented_normals.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>

#include <catch2/catch.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <array>
#include <atomic>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <list>
#include <random>
#include <set>
#include <thread>
#include <vector>

using namespace psc_test;
using namespace psc_core_test;
namespace PSC = CGAL::Point_set_curvatures;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
const double nan_value = std::numeric_limits<double>::quiet_NaN();
const double inf_value = std::numeric_limits<double>::infinity();

auto maps() { return CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); }
// The authors' estimator exactly: the paper's variant with their projection.
auto authors_maps()
{
  return PSC::parameters::aso_projection(CGAL::Aso_projection::AUTHORS_IMPLEMENTATION,
                                         PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, maps()));
}

template <class Tag = CGAL::Sequential_tag>
std::vector<Estimate> aso(const std::vector<Oriented_point>& pts, double r)
{
  return CGAL::estimate_aso_curvatures<Tag>(pts, r, maps());
}

template <class Tag = CGAL::Sequential_tag>
std::vector<Estimate> apss(const std::vector<Oriented_point>& pts, double r)
{
  return CGAL::estimate_apss_curvatures<Tag>(pts, r, maps());
}

// The paper's estimator (Aso_variant::PAPER) with the default projection.
template <class Tag = CGAL::Sequential_tag>
std::vector<Estimate> aso_paper(const std::vector<Oriented_point>& pts, double r)
{
  return CGAL::estimate_aso_curvatures<Tag>(pts, r, PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, maps()));
}

std::vector<Estimate> aso_authors(const std::vector<Oriented_point>& pts, double r)
{
  return CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, authors_maps());
}

// The shared clouds are read once per test program.
const std::vector<Oriented_point>& goursat_10k()
{
  static const std::vector<Oriented_point> c = read_xyz(repo_data("goursat_010000.xyz"));
  return c;
}
const std::vector<Oriented_point>& goursat_50k()
{
  static const std::vector<Oriented_point> c = read_xyz(repo_data("goursat_050000.xyz"));
  return c;
}
const std::vector<Oriented_point>& bunny()
{
  static const std::vector<Oriented_point> c = read_ascii_ply_xyz_normals(repo_data("bunny.ply"));
  return c;
}

std::size_t count_invalid(const std::vector<Estimate>& est)
{
  std::size_t n = 0;
  for(const Estimate& e : est)
    n += e.is_valid() ? 0 : 1;
  return n;
}

std::string printed(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Analytic surfaces
// ---------------------------------------------------------------------------------------

// Section 5 of the paper: the ASO is the shape operator of the APSS field. Points sampled
// on a sphere with exact normals are fitted exactly by the algebraic sphere whatever the
// weights, so the field does not depend on the evaluation point, its shape operator is
// exactly I/R, and only rounding is left.
TEST_CASE("ASO on a sphere with outward normals: k_min = k_max = H = 1/R and K = 1/R^2", "[aso][sphere]")
{
  struct Case
  {
    double R;
    Point c;
  };
  // small, unit and large radii; centres at the origin and far off it
  const Case cases[] = {{2, Point(0, 0, 0)},
                        {0.01, Point(0, 0, 0)},
                        {500, Point(0, 0, 0)},
                        {2, Point(3, -7, 11)},
                        {0.5, Point(-1000, 250, 40)}};
  for(const Case& c : cases)
  {
    const auto pts = sphere(20000, c.R, c.c);
    const double r = 0.1 * c.R;  // about 50 neighbours
    const auto est = aso(pts, r);
    REQUIRE(est.size() == pts.size());
    REQUIRE(count_invalid(est) == 0);
    Stat k_err, n_err, d_err;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      const Estimate& e = est[i];
      const double inv_R = 1 / c.R;
      k_err.add(std::abs(e.min_curvature - inv_R) / inv_R);
      k_err.add(std::abs(e.max_curvature - inv_R) / inv_R);
      k_err.add(std::abs(e.mean_curvature - inv_R) / inv_R);
      k_err.add(std::abs(e.gaussian_curvature - inv_R * inv_R) / (inv_R * inv_R));
      n_err.add(length(e.normal - pts[i].second));
      // principal directions: unit, orthogonal to each other and to the normal
      d_err.add(std::abs(length(e.min_direction) - 1));
      d_err.add(std::abs(length(e.max_direction) - 1));
      d_err.add(std::abs(e.min_direction * e.max_direction));
      d_err.add(std::abs(e.min_direction * e.normal));
      d_err.add(std::abs(e.max_direction * e.normal));
      REQUIRE(e.min_curvature <= e.max_curvature);
    }
    const std::string tag = "sphere R=" + printed(c.R) + " c=(" + printed(c.c.x()) + ")";
    measured("ASO " + tag + ": max relative curvature error", k_err.max);
    measured("ASO " + tag + ": max |normal - radial|", n_err.max);
    measured("ASO " + tag + ": max frame defect of directions", d_err.max);
    // Measured: 4.9e-11 for R = 0.5 centred at (-1000, 250, 40) (coordinates 2000 R away
    // from the origin: their rounding, relative to R, is 2000 times larger), at most 1.7e-13
    // elsewhere. The issue's bound, 1e-9, holds with a margin of 20.
    CHECK(k_err.max < 1e-9);
    // Measured 8.1e-13 for the far centre, at most 4e-15 elsewhere (same factor 2000).
    CHECK(n_err.max < 1e-10);
    // Measured at most 5.5e-16: the directions are an orthonormal tangent frame.
    CHECK(d_err.max < 1e-12);
  }
}

// The sign convention: curvature is positive where the surface bends away from the normal,
// so flipping every normal flips k_min, k_max, H (and the normal), and keeps K.
TEST_CASE("ASO on a sphere with inward normals gives -1/R, K = 1/R^2 and the inward normal", "[aso][sphere]")
{
  const double R = 2;
  const Point centre(3, -7, 11);
  const auto pts = sphere(20000, R, centre, /*inward=*/true);
  const auto est = aso(pts, 0.2);
  REQUIRE(count_invalid(est) == 0);
  Stat k_err, n_err;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    k_err.add(std::abs(est[i].min_curvature + 1 / R) * R);
    k_err.add(std::abs(est[i].max_curvature + 1 / R) * R);
    k_err.add(std::abs(est[i].mean_curvature + 1 / R) * R);
    k_err.add(std::abs(est[i].gaussian_curvature - 1 / (R * R)) * R * R);
    n_err.add(length(est[i].normal - pts[i].second));  // pts[i].second is inward
  }
  measured("ASO inward sphere: max relative curvature error", k_err.max);
  measured("ASO inward sphere: max |normal - inward radial|", n_err.max);
  // Same rounding as with outward normals (measured 1.7e-13 and 4e-15).
  CHECK(k_err.max < 1e-9);
  CHECK(n_err.max < 1e-12);
}

// Section 3, Equations 7-8: the APSS normal is the gradient of the fitted sphere and its
// mean curvature the Pratt-normalised 2 u_q, exactly 1/R on a sphere (signed by the
// normals); APSS cannot measure principal curvatures, so those fields stay NaN.
TEST_CASE("APSS on a sphere gives H = 1/R with radial normals, -1/R with inward normals", "[apss][sphere]")
{
  const double R = 2;
  const Point centre(3, -7, 11);
  for(bool inward : {false, true})
  {
    const auto pts = sphere(20000, R, centre, inward);
    const auto est = apss(pts, 0.2);
    REQUIRE(count_invalid(est) == 0);
    const double expected = inward ? -1 / R : 1 / R;
    Stat h_err, n_err;
    bool principal_nan = true;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      h_err.add(std::abs(est[i].mean_curvature - expected) * R);
      n_err.add(length(est[i].normal - pts[i].second));
      principal_nan = principal_nan && principal_fields_nan(est[i]);
    }
    measured(std::string("APSS sphere ") + (inward ? "inward" : "outward") + ": max relative H error", h_err.max);
    measured(std::string("APSS sphere ") + (inward ? "inward" : "outward") + ": max normal error", n_err.max);
    // Measured 3.3e-15 (H) and 1.0e-15 (normal): rounding only.
    CHECK(h_err.max < 1e-9);
    CHECK(n_err.max < 1e-12);
    CHECK(principal_nan);
  }
}

// A cylinder is not a sphere, yet the ASO (a derivative of sphere fits) must find k_min ~ 0
// along the axis and k_max ~ 1/R around it. The cylinder is sampled on a jittered grid
// (spacing 0.031): the error measured is the sampling's, not a bias of the estimator. Its
// mean over the cylinder (k_min R: -4e-5 at r = 0.15, -9e-6 at r = 0.3) is 20 to 100 times
// smaller than its maximum, and the maximum shrinks 13 times when r doubles (4 times more
// neighbours average out the jitter).
TEST_CASE("ASO on a cylinder: k_min ~ 0 along the axis, k_max ~ 1/R", "[aso][cylinder]")
{
  const double R = 1, height = 2;
  const auto pts = cylinder(200, 64, R, height);
  struct Bounds
  {
    double r, k_min, k_max, degrees, normal;
  };
  // Measured maxima, r = 0.15 (about 70 neighbours): |k_min| R 1.04e-2, |k_max - 1/R| R
  // 1.01e-2, angle(d_min, axis) 0.16 degrees, |n - n*| 1.0e-4; r = 0.3 (about 290
  // neighbours): 8.1e-4, 7.4e-4, 0.024 degrees, 1.0e-5. Bounds: 1.5 times those.
  const Bounds bounds[] = {{0.15, 1.5e-2, 1.5e-2, 0.25, 1.5e-4}, {0.3, 1.2e-3, 1.2e-3, 0.036, 1.5e-5}};
  for(const Bounds& b : bounds)
  {
    const auto est = aso(pts, b.r);
    REQUIRE(count_invalid(est) == 0);
    Stat k_min_err, k_max_err, angle, n_err;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      if(std::abs(pts[i].first.z()) > height / 2 - b.r)
        continue;  // the open ends bias the fit; only complete neighbourhoods are judged
      const Estimate& e = est[i];
      k_min_err.add(std::abs(e.min_curvature) * R);
      k_max_err.add(std::abs(e.max_curvature - 1 / R) * R);
      angle.add(line_angle_degrees(e.min_direction, Vector(0, 0, 1)));
      n_err.add(length(e.normal - pts[i].second));
    }
    REQUIRE(k_min_err.n > 7000);
    const std::string t = "ASO cylinder R=1 r=" + printed(b.r);
    measured(t + ": max |k_min| R", k_min_err.max);
    measured(t + ": max |k_max - 1/R| R", k_max_err.max);
    measured(t + ": max angle(d_min, axis) degrees", angle.max);
    measured(t + ": max normal error", n_err.max);
    CHECK(k_min_err.max < b.k_min);
    CHECK(k_max_err.max < b.k_max);
    CHECK(angle.max < b.degrees);
    CHECK(n_err.max < b.normal);
  }
}

// A planar neighbourhood is not degenerate: it is valid with zero curvatures. The tilted
// plane checks that rounding in a generic frame stays far below any real curvature.
TEST_CASE("ASO and APSS on a plane: valid, zero curvatures, the plane's normal", "[aso][apss][plane]")
{
  const double h = 0.01, r = 0.04;  // about 50 neighbours
  const auto flat = plane(60, h);
  const Rotation tilt(Vector(1, 2, 3), 0.7);
  const auto tilted = rotated(flat, tilt);
  for(int t = 0; t < 2; ++t)
  {
    const auto& pts = t == 0 ? flat : tilted;
    const Vector expected_normal = t == 0 ? Vector(0, 0, 1) : tilt(Vector(0, 0, 1));
    const auto est = aso(pts, r);
    const auto est_apss = apss(pts, r);
    REQUIRE(count_invalid(est) == 0);
    REQUIRE(count_invalid(est_apss) == 0);
    Stat k, n_err;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      // curvatures times r: the rounding error relative to the scale the fit can see
      k.add(std::abs(est[i].min_curvature) * r);
      k.add(std::abs(est[i].max_curvature) * r);
      k.add(std::abs(est[i].mean_curvature) * r);
      k.add(std::abs(est[i].gaussian_curvature) * r * r);
      k.add(std::abs(est_apss[i].mean_curvature) * r);
      n_err.add(length(est[i].normal - expected_normal));
      n_err.add(length(est_apss[i].normal - expected_normal));
    }
    const std::string name = t == 0 ? "plane z=0" : "tilted plane";
    measured(name + ": max |k| r (ASO, APSS)", k.max);
    measured(name + ": max normal error", n_err.max);
    // Measured: 0 exactly on z = 0 (every term of the fit is exactly planar), 2.2e-15 on
    // the tilted plane (5.4e-16 for the normal); 1e-12 leaves room for rounding only.
    CHECK(k.max < 1e-12);
    CHECK(n_err.max < 1e-12);
  }
}

// "Normals need not be unit; they are normalised": scaling every input normal by its own
// positive factor changes nothing but rounding, for APSS and the default ASO. (The
// authors' projection uses the normals as given, by design, and is not tested here.)
TEST_CASE("ASO and APSS do not depend on the length of the input normals", "[aso][apss]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> factor(0.01, 100.0);
  std::vector<Oriented_point> scaled = pts, unit = pts;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    unit[i].second = pts[i].second / length(pts[i].second);
    scaled[i].second = unit[i].second * factor(rng);
  }
  const auto a = aso(unit, r), b = aso(scaled, r), c = aso(pts, r);
  const auto a_apss = apss(unit, r), b_apss = apss(scaled, r);
  Stat k, n;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    REQUIRE(b[i].is_valid());
    const double scale = curvature_scale(a[i]);
    for(const Estimate* e : {&b[i], &c[i]})
    {
      k.add(scaled_difference(e->min_curvature, a[i].min_curvature, scale));
      k.add(scaled_difference(e->max_curvature, a[i].max_curvature, scale));
      n.add(length(e->normal - a[i].normal));
    }
    k.add(scaled_difference(b_apss[i].mean_curvature, a_apss[i].mean_curvature, scale));
    n.add(length(b_apss[i].normal - a_apss[i].normal));
  }
  measured("Goursat 10K normals scaled by [0.01, 100]: max scaled curvature change", k.max);
  measured("Goursat 10K normals scaled by [0.01, 100]: max normal change", n.max);
  // Measured 4.1e-15 and 3.5e-16: the normalisation's rounding (one ulp per component).
  CHECK(k.max < 1e-12);
  CHECK(n.max < 1e-12);
}

// The neighbourhood of a point is every input point at distance < r, itself included.
TEST_CASE("neighbor_count is the number of input points at distance < r, the query included", "[aso][apss][count]")
{
  const auto& pts = bunny();
  const double r = 0.005;
  const auto est = aso(pts, r);
  const auto est_apss = apss(pts, r);
  std::size_t checked = 0;
  for(std::size_t i = 0; i < pts.size(); i += 97)
  {
    const std::size_t n = brute_force_count(pts, pts[i].first, r);
    CHECK(est[i].neighbor_count == n);
    CHECK(est_apss[i].neighbor_count == n);
    ++checked;
  }
  CHECK(checked > 300);
}

// ---------------------------------------------------------------------------------------
// Reference values of the authors' implementation
// ---------------------------------------------------------------------------------------

namespace {

// Compares the estimates with data/reference/<file>. The reference was made with
// the authors' implementation (tangent plane orthogonal to u_l, raw input normals), hence
// Aso_projection::AUTHORS_IMPLEMENTATION. Curvatures: relative error with a floor at 1e-3
// of the row's max(|k_min|, |k_max|) (its square for K), since a near-zero curvature
// between two large ones carries the absolute rounding error of the large ones. (Measured:
// without the floor the worst relative difference is 5.6e-12, with it 4.9e-12: the CSV's
// own rounding to 12 significant digits, up to 5e-12.)
void check_reference(const std::vector<Oriented_point>& pts, double r, const std::string& file)
{
  const auto rows = read_reference(repo_data("reference/" + file));
  REQUIRE(rows.size() > 1000);
  const auto est = aso_authors(pts, r);
  REQUIRE(est.size() == pts.size());
  Stat k_err, n_err, d_err;
  std::size_t count_mismatch = 0, skipped_directions = 0;
  for(const Reference_row& row : rows)
  {
    REQUIRE(row.index < est.size());
    const Estimate& e = est[row.index];
    REQUIRE(e.is_valid());
    count_mismatch += (e.neighbor_count == row.neighbors) ? 0 : 1;
    const double scale = std::max(std::abs(row.k_min), std::abs(row.k_max));
    const double floor = 1e-3 * scale;
    k_err.add(scaled_difference(e.min_curvature, row.k_min, floor));
    k_err.add(scaled_difference(e.max_curvature, row.k_max, floor));
    k_err.add(scaled_difference(e.mean_curvature, row.mean, floor));
    k_err.add(scaled_difference(e.gaussian_curvature, row.gaussian, floor * scale));
    n_err.add(length(e.normal - Vector(row.n[0], row.n[1], row.n[2])));
    // A principal direction is defined up to sign, and only where k_min != k_max: its
    // rounding error is about (curvature rounding) / (k_max - k_min). Directions are
    // compared where the gap is at least 1e-3 of the curvature scale.
    if(row.k_max - row.k_min < 1e-3 * scale)
    {
      ++skipped_directions;
      continue;
    }
    d_err.add(line_distance(e.min_direction, Vector(row.d_min[0], row.d_min[1], row.d_min[2])));
    d_err.add(line_distance(e.max_direction, Vector(row.d_max[0], row.d_max[1], row.d_max[2])));
  }
  measured(file + ": max scaled curvature difference", k_err.max);
  measured(file + ": max normal difference", n_err.max);
  measured(file + ": max direction difference (up to sign)", d_err.max);
  measured(file + ": rows with near-umbilic directions skipped", double(skipped_directions));
  CHECK(count_mismatch == 0);
  // The issue's bound, 1e-9 (the CSV holds 12 significant digits). Measured: see the
  // TEST_CASEs below.
  CHECK(k_err.max < 1e-9);
  CHECK(n_err.max < 1e-9);
  CHECK(d_err.max < 1e-9);
  CHECK(skipped_directions < rows.size() / 100);
}

}  // namespace

TEST_CASE("ASO agrees with the authors' values on the bunny at r = 0.005", "[aso][reference]")
{
  // Measured: curvatures 4.9e-12 (relative, floored), normals 8.4e-13, directions 8.5e-13,
  // 0 of 3595 rows skipped for near-umbilic directions.
  check_reference(bunny(), 0.005, "bunny_aso_r0.005.csv");
}

TEST_CASE("ASO agrees with the authors' values on Goursat 10K at r = 1.5", "[aso][reference]")
{
  // Measured: curvatures 4.9e-12 (relative, floored), normals 8.3e-13, directions 8.6e-13,
  // 0 of 2000 rows skipped.
  check_reference(goursat_10k(), 1.5, "goursat_010000_aso_r1.5.csv");
}

// The default projects on the plane orthogonal to the returned (corrected) normal; the
// authors project on the plane orthogonal to u_l with raw normals. Both are the ASO of
// the same field: they must differ only slightly, and only the default gives directions
// that are exactly tangent to the normal it returns.
TEST_CASE("Default ASO projection differs slightly from the authors' and keeps directions tangent", "[aso][projection]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  const auto def = aso_paper(pts, r);  // the same variant as the authors', default projection
  const auto aut = aso_authors(pts, r);
  REQUIRE(count_invalid(def) == 0);
  REQUIRE(count_invalid(aut) == 0);
  Stat k_diff, n_diff, def_tangent, aut_tangent;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const double scale = curvature_scale(aut[i]);
    k_diff.add(scaled_difference(def[i].min_curvature, aut[i].min_curvature, scale));
    k_diff.add(scaled_difference(def[i].max_curvature, aut[i].max_curvature, scale));
    k_diff.add(scaled_difference(def[i].mean_curvature, aut[i].mean_curvature, scale));
    n_diff.add(length(def[i].normal - aut[i].normal));
    def_tangent.add(
      std::max(std::abs(def[i].min_direction * def[i].normal), std::abs(def[i].max_direction * def[i].normal)));
    aut_tangent.add(
      std::max(std::abs(aut[i].min_direction * aut[i].normal), std::abs(aut[i].max_direction * aut[i].normal)));
  }
  measured("Goursat 10K r=1.5 default vs authors: max scaled curvature difference", k_diff.max);
  measured("Goursat 10K r=1.5 default vs authors: mean scaled curvature difference", k_diff.mean());
  measured("Goursat 10K r=1.5 default vs authors: max normal difference", n_diff.max);
  measured("Goursat 10K r=1.5 default: max |d . n|", def_tangent.max);
  measured("Goursat 10K r=1.5 authors: max |d . n|", aut_tangent.max);
  measured("Goursat 10K r=1.5 authors: mean |d . n|", aut_tangent.mean());
  // Measured: curvatures differ by 1.1e-3 of the curvature scale at most, 4.6e-5 on
  // average, two orders of magnitude below the estimator's own error on this cloud (mean
  // |H - H*| = 3.1e-3 for curvatures up to 0.5, see the Goursat tests). Bounds: 1.5 times.
  CHECK(k_diff.max < 1.6e-3);
  CHECK(k_diff.mean() < 7e-5);
  // Both normals are grad f / |grad f|, but the authors' fit uses the input normals as
  // given, unit to 6 digits in the file (max ||n| - 1| = 7.4e-7): measured 2.2e-8.
  CHECK(n_diff.max < 1e-6);
  // Measured 5.1e-16 for the default; the authors' directions are off the normal's plane
  // by 1.1e-2 on average, 3.8e-2 at most (0.6 and 2.2 degrees).
  CHECK(def_tangent.max < 1e-12);
  CHECK(aut_tangent.mean() > 5e-3);
}

// ---------------------------------------------------------------------------------------
// Accuracy on the Goursat surface (Section 6.1 of the paper)
// ---------------------------------------------------------------------------------------

namespace {

struct Goursat_errors
{
  Stat H, k_min, k_max, normal_degrees, apss_H, apss_normal_degrees;
  Stat consistency;           // of H, K and the frame with k_min, k_max and the normal
  std::size_t unordered = 0;  // estimates with k_min > k_max
};

Goursat_errors goursat_errors(const std::vector<Oriented_point>& pts, double r, bool paper = false)
{
  const auto est = paper ? aso_paper(pts, r) : aso(pts, r);
  const auto est_apss = apss(pts, r);
  REQUIRE(count_invalid(est) == 0);
  REQUIRE(count_invalid(est_apss) == 0);
  Goursat_errors err;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const Truth t = goursat_truth(pts[i].first);
    err.H.add(std::abs(est[i].mean_curvature - t.mean));
    err.k_min.add(std::abs(est[i].min_curvature - t.k_min));
    err.k_max.add(std::abs(est[i].max_curvature - t.k_max));
    err.normal_degrees.add(line_angle_degrees(est[i].normal, t.normal));
    const Estimate& e = est[i];
    const double scale = curvature_scale(e);
    err.unordered += (e.min_curvature <= e.max_curvature) ? 0 : 1;
    err.consistency.add(std::abs(e.mean_curvature - 0.5 * (e.min_curvature + e.max_curvature)) / scale);
    err.consistency.add(std::abs(e.gaussian_curvature - e.min_curvature * e.max_curvature) / (scale * scale));
    err.consistency.add(std::abs(length(e.normal) - 1));
    err.consistency.add(std::abs(length(e.min_direction) - 1));
    err.consistency.add(std::abs(length(e.max_direction) - 1));
    err.consistency.add(std::abs(e.min_direction * e.max_direction));
    err.consistency.add(std::abs(e.min_direction * e.normal));
    err.consistency.add(std::abs(e.max_direction * e.normal));
    err.consistency.add(std::abs(length(est_apss[i].normal) - 1));
    // oriented like the input: a flipped normal would be a gross error, not an angle
    REQUIRE(est[i].normal * t.normal > 0);
    err.apss_H.add(std::abs(est_apss[i].mean_curvature - t.mean));
    err.apss_normal_degrees.add(line_angle_degrees(est_apss[i].normal, t.normal));
  }
  return err;
}

void print(const std::string& name, const Goursat_errors& e)
{
  measured(name + ": ASO mean |H - H*|", e.H.mean());
  measured(name + ": ASO mean |k_min - k_min*|", e.k_min.mean());
  measured(name + ": ASO mean |k_max - k_max*|", e.k_max.mean());
  measured(name + ": ASO mean normal angle (degrees)", e.normal_degrees.mean());
  measured(name + ": ASO max normal angle (degrees)", e.normal_degrees.max);
  measured(name + ": APSS mean |H - H*|", e.apss_H.mean());
  measured(name + ": APSS mean normal angle (degrees)", e.apss_normal_degrees.mean());
  measured(name + ": max defect of H = (k1+k2)/2, K = k1 k2, unit orthogonal frame", e.consistency.max);
}

}  // namespace

// Bounds on the mean absolute errors (curvatures of the Goursat surface range over about
// [-0.4, 0.5]); each is about 1.5 times the value measured, quoted beside it: they catch
// any real regression of the estimator while leaving room for rounding differences between
// compilers. The paper's claim (Section 6.1): ASO curvatures converge with the sampling,
// and its normal is more accurate than the APSS one.
namespace {

struct Goursat_bounds
{
  double H, k_min, k_max, normal_degrees, apss_H, apss_normal_degrees;
};

void check_goursat(const Goursat_errors& e, const Goursat_bounds& b)
{
  CHECK(e.H.mean() < b.H);
  CHECK(e.k_min.mean() < b.k_min);
  CHECK(e.k_max.mean() < b.k_max);
  CHECK(e.normal_degrees.mean() < b.normal_degrees);
  CHECK(e.apss_H.mean() < b.apss_H);
  CHECK(e.apss_normal_degrees.mean() < b.apss_normal_degrees);
  CHECK(e.normal_degrees.mean() < e.apss_normal_degrees.mean());
  // H = (k_min + k_max) / 2, K = k_min k_max, k_min <= k_max, unit normal and orthonormal
  // tangent directions: exact up to rounding (measured at most 5.1e-16).
  CHECK(e.unordered == 0);
  CHECK(e.consistency.max < 1e-12);
}

}  // namespace

TEST_CASE("ASO and APSS on Goursat 10K at r = 1.5: mean errors of H, k_min, k_max, normals", "[aso][apss][goursat]")
{
  const Goursat_errors e = goursat_errors(goursat_10k(), 1.5);
  print("Goursat 10K r=1.5", e);
  // The default (Aso_variant::ROBUST). Measured: H 9.76e-4, k_min 8.61e-4, k_max 1.52e-3,
  // normal 0.020 degrees; APSS H 3.52e-3, APSS normal 0.69 degrees.
  check_goursat(e, {1.5e-3, 1.3e-3, 2.3e-3, 0.030, 5.3e-3, 1.03});
  // The paper's estimator. Measured: H 3.08e-3, k_min 2.86e-3, k_max 4.64e-3, normal 0.052
  // degrees: the default's curvature errors are 3.2 times smaller.
  const Goursat_errors p = goursat_errors(goursat_10k(), 1.5, true);
  print("Goursat 10K r=1.5, paper's variant", p);
  check_goursat(p, {4.6e-3, 4.3e-3, 7.0e-3, 0.078, 5.3e-3, 1.03});
}

TEST_CASE("ASO and APSS on Goursat 50K at r = 1.0: mean errors of H, k_min, k_max, normals", "[aso][apss][goursat]")
{
  const Goursat_errors e = goursat_errors(goursat_50k(), 1.0);
  print("Goursat 50K r=1.0", e);
  // The default. Measured: H 2.74e-4, k_min 2.39e-4, k_max 4.23e-4, normal 0.0038 degrees;
  // APSS H 2.50e-3, APSS normal 0.32 degrees.
  check_goursat(e, {4.1e-4, 3.6e-4, 6.4e-4, 0.0057, 3.7e-3, 0.48});
  // The paper's estimator. Measured: H 1.28e-3, k_min 1.25e-3, k_max 1.90e-3, normal 0.018
  // degrees; 2.4 times smaller curvature errors than on 10K (the default: 3.6 times).
  const Goursat_errors p = goursat_errors(goursat_50k(), 1.0, true);
  print("Goursat 50K r=1.0, paper's variant", p);
  check_goursat(p, {1.9e-3, 1.9e-3, 2.85e-3, 0.027, 3.7e-3, 0.48});
}

// The 10K cloud read through the path the examples and the tool use.
TEST_CASE("ASO and APSS on the repository's Goursat 10K copy at r = 1.5: same mean errors", "[aso][apss][goursat]")
{
  const auto pts = read_xyz(repo_data("goursat_010000.xyz"));
  REQUIRE(pts.size() == 10000);
  const Goursat_errors e = goursat_errors(pts, 1.5);
  print("repository Goursat 10K r=1.5", e);
  // Measured: the same values as goursat_10k() (the same file).
  check_goursat(e, {1.5e-3, 1.3e-3, 2.3e-3, 0.030, 5.3e-3, 1.03});
}

// ---------------------------------------------------------------------------------------
// Invariances
// ---------------------------------------------------------------------------------------

TEST_CASE("Sequential and Parallel runs give bitwise identical results", "[aso][apss][parallel]")
{
  // Goursat 50K plus one point of each invalid kind, so that statuses are compared too.
  auto pts = goursat_50k();
  const double r = 1.0;
  pts.emplace_back(Point(nan_value, 0, 0), Vector(0, 0, 1));
  pts.emplace_back(pts[10].first, Vector(0, 0, 0));
  pts.emplace_back(Point(100, 0, 0), Vector(1, 0, 0));
  pts.insert(pts.begin() + 20000, 4, Oriented_point(Point(0, 100, 0), Vector(0, 1, 0)));
  const auto s = aso<CGAL::Sequential_tag>(pts, r);
  const auto p = aso<CGAL::Parallel_tag>(pts, r);
  const auto sa = apss<CGAL::Sequential_tag>(pts, r);
  const auto pa = apss<CGAL::Parallel_tag>(pts, r);
  const auto s_aut = aso_authors(pts, r);
  const auto p_aut = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, authors_maps());
  REQUIRE(s.size() == pts.size());
  REQUIRE(p.size() == pts.size());
  std::size_t differ = 0, differ_apss = 0, differ_authors = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    differ += same_estimate(s[i], p[i]) ? 0 : 1;
    differ_apss += same_estimate(sa[i], pa[i]) ? 0 : 1;
    differ_authors += same_estimate(s_aut[i], p_aut[i]) ? 0 : 1;
  }
  CHECK(differ == 0);
  CHECK(differ_apss == 0);
  CHECK(differ_authors == 0);
  CHECK(count_invalid(s) == 7);
  CHECK(count_invalid(pa) == 7);
}

#ifdef CGAL_LINKED_WITH_TBB
// The README's claims for Parallel_tag: the callback is called from the calling thread only,
// and the result does not depend on the number of threads, here 8 in a task arena (more than
// the cores of CI's machines; global_control lets TBB start that many workers anywhere).
// The default ASO (three passes: sample weights, fit, estimation) by count and APSS by radius.
TEST_CASE("Parallel_tag: the callback comes from the calling thread only, and 8 threads give the sequential bytes",
          "[aso][apss][parallel][callback]")
{
  const auto pts = sphere(20000, 1);
  const double r = 0.08;  // about 32 neighbours
  const auto by_count = PSC::parameters::neighbor_count(30, maps());
  const auto aso_sequential = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, by_count);
  const auto apss_sequential = apss<CGAL::Sequential_tag>(pts, r);
  REQUIRE(count_invalid(aso_sequential) == 0);
  REQUIRE(count_invalid(apss_sequential) == 0);

  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<std::size_t> calls(0), elsewhere(0);
  const std::function<bool(double)> cb = [&](double) {
    ++calls;
    elsewhere += std::this_thread::get_id() != caller ? 1 : 0;
    return true;
  };
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 8);
  tbb::task_arena arena(8);
  std::vector<Estimate> aso_parallel, apss_parallel;
  int concurrency = 0;
  arena.execute([&] {
    concurrency = tbb::this_task_arena::max_concurrency();
    aso_parallel = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, by_count.callback(cb));
    apss_parallel = CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, maps().callback(cb));
  });
  CHECK(concurrency == 8);
  CHECK(calls > 10);
  CHECK(elsewhere == 0);
  std::size_t differ = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    differ += (same_estimate(aso_parallel[i], aso_sequential[i]) ? 0 : 1) +
              (same_estimate(apss_parallel[i], apss_sequential[i]) ? 0 : 1);
  CHECK(differ == 0);
}
#endif

// Coordinates are centred at the query point before anything is summed, so a translation
// far from the origin costs only the rounding of the translated input itself.
TEST_CASE("A translation by (1e6, -2e6, 5e5) changes curvatures by less than 1e-6 relative", "[aso][apss][invariance]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  const auto far = translated(pts, Vector(1e6, -2e6, 5e5));
  const auto a = aso(pts, r), b = aso(far, r);
  const auto a_apss = apss(pts, r), b_apss = apss(far, r);
  Stat k, n, apss_h;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    REQUIRE(b[i].is_valid());
    REQUIRE(b_apss[i].is_valid());
    // relative to the curvature scale of the point (its largest |k|)
    const double scale = curvature_scale(a[i]);
    k.add(scaled_difference(b[i].min_curvature, a[i].min_curvature, scale));
    k.add(scaled_difference(b[i].max_curvature, a[i].max_curvature, scale));
    k.add(scaled_difference(b[i].mean_curvature, a[i].mean_curvature, scale));
    k.add(scaled_difference(b[i].gaussian_curvature, a[i].gaussian_curvature, scale * scale));
    n.add(length(b[i].normal - a[i].normal));
    apss_h.add(scaled_difference(b_apss[i].mean_curvature, a_apss[i].mean_curvature, scale));
  }
  measured("Goursat 10K translated: max scaled curvature change (ASO)", k.max);
  measured("Goursat 10K translated: max normal change (ASO)", n.max);
  measured("Goursat 10K translated: max scaled H change (APSS)", apss_h.max);
  // Measured: 5.8e-9 (ASO curvatures, scaled), 7.5e-11 (normals), 1.8e-10 (APSS H): the
  // translated coordinates (up to 2e6) are rounded to 4.7e-10, 3e-10 of r, and second
  // derivatives amplify that. The issue's bound, 1e-6, holds with a margin of 170.
  CHECK(k.max < 1e-6);
  CHECK(n.max < 1e-6);
  CHECK(apss_h.max < 1e-6);
}

// The estimators are geometric: a rotation of the cloud rotates normals and principal
// directions and leaves every curvature unchanged.
TEST_CASE("A rotation rotates normals and directions and leaves curvatures unchanged", "[aso][apss][invariance]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  const Rotation rot(Vector(1, -2, 0.5), 1.1);
  const auto turned = rotated(pts, rot);
  const auto a = aso(pts, r), b = aso(turned, r);
  const auto a_apss = apss(pts, r), b_apss = apss(turned, r);
  Stat k, n, d;
  std::size_t near_umbilic = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    REQUIRE(b[i].is_valid());
    const double scale = curvature_scale(a[i]);
    k.add(scaled_difference(b[i].min_curvature, a[i].min_curvature, scale));
    k.add(scaled_difference(b[i].max_curvature, a[i].max_curvature, scale));
    k.add(scaled_difference(b[i].mean_curvature, a[i].mean_curvature, scale));
    k.add(scaled_difference(b[i].gaussian_curvature, a[i].gaussian_curvature, scale * scale));
    k.add(scaled_difference(b_apss[i].mean_curvature, a_apss[i].mean_curvature, scale));
    n.add(length(b[i].normal - rot(a[i].normal)));
    n.add(length(b_apss[i].normal - rot(a_apss[i].normal)));
    // directions are defined up to sign and only away from umbilics (see the reference test)
    if(a[i].max_curvature - a[i].min_curvature < 1e-3 * scale)
    {
      ++near_umbilic;
      continue;
    }
    d.add(line_distance(b[i].min_direction, rot(a[i].min_direction)));
    d.add(line_distance(b[i].max_direction, rot(a[i].max_direction)));
  }
  measured("Goursat 10K rotated: max scaled curvature change", k.max);
  measured("Goursat 10K rotated: max normal error", n.max);
  measured("Goursat 10K rotated: max direction error (up to sign)", d.max);
  measured("Goursat 10K rotated: near-umbilic points skipped", double(near_umbilic));
  // Measured: curvatures 5.8e-14 (scaled), normals 1.2e-15, directions 1.7e-13, no point
  // skipped: the sums are the same up to rounding and summation order (the grid sorts
  // the rotated points differently). Bounds: 1e-10 (directions amplify curvature rounding
  // by up to k_scale / (k_max - k_min) <= 1e3) and 1e-12 for normals.
  CHECK(k.max < 1e-10);
  CHECK(n.max < 1e-12);
  CHECK(d.max < 1e-10);
  CHECK(near_umbilic < pts.size() / 100);
}

// ---------------------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------------------

TEST_CASE("A radius that is zero, negative, NaN or infinite throws std::invalid_argument naming it", "[bad_input]")
{
  using Catch::Matchers::Contains;
  const auto pts = sphere(100, 1);
  const std::vector<Oriented_point> none;
  for(double r : {0.0, -2.5, nan_value, inf_value, -inf_value})
  {
    INFO("radius " << r);
    const std::string value = printed(r);
    CHECK_THAT(invalid_argument_message([&] { aso(pts, r); }), Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message([&] { aso<CGAL::Parallel_tag>(pts, r); }),
               Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message([&] { aso_authors(pts, r); }), Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message([&] { apss(pts, r); }), Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message([&] { apss<CGAL::Parallel_tag>(pts, r); }),
               Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message(
                 [&] { CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, Point_map(), Normal_map(), r); }),
               Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message(
                 [&] { CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, Point_map(), Normal_map(), r); }),
               Contains("radius") && Contains(value));
    // the argument is checked whatever the data, an empty range included
    CHECK_THAT(invalid_argument_message([&] { aso(none, r); }), Contains("radius"));
    CHECK_THAT(invalid_argument_message([&] { apss(none, r); }), Contains("radius"));
  }
}

TEST_CASE("Without a radius neighbor_count is required, and a radius with neighbor_count throws", "[bad_input]")
{
  using Catch::Matchers::Contains;
  const auto pts = sphere(100, 1);
  typedef CGAL::Sequential_tag Seq;
  // the overloads without a radius need neighbor_count(k), k >= 1
  CHECK_THAT(invalid_argument_message([&] { CGAL::estimate_aso_curvatures<Seq>(pts, maps()); }),
             Contains("neighbor_count"));
  CHECK_THAT(invalid_argument_message([&] { CGAL::estimate_apss_curvatures<Seq>(pts, maps()); }),
             Contains("neighbor_count"));
  CHECK_THAT(invalid_argument_message(
               [&] { CGAL::estimate_aso_curvatures<Seq>(pts, PSC::parameters::neighbor_count(0, maps())); }),
             Contains("neighbor_count"));
  // the overloads with a radius refuse neighbor_count too (which scale would apply?)
  CHECK_THAT(invalid_argument_message(
               [&] { CGAL::estimate_aso_curvatures<Seq>(pts, 0.3, PSC::parameters::neighbor_count(10, maps())); }),
             Contains("neighbor_count") && Contains("radius"));
  CHECK_THAT(invalid_argument_message(
               [&] { CGAL::estimate_apss_curvatures<Seq>(pts, 0.3, PSC::parameters::neighbor_count(10, maps())); }),
             Contains("neighbor_count") && Contains("radius"));
}

TEST_CASE("An empty range gives an empty result", "[bad_input]")
{
  const std::vector<Oriented_point> none;
  CHECK(aso(none, 1.0).empty());
  CHECK(aso<CGAL::Parallel_tag>(none, 1.0).empty());
  CHECK(apss(none, 1.0).empty());
  CHECK(apss<CGAL::Parallel_tag>(none, 1.0).empty());
  CHECK(aso_authors(none, 1.0).empty());
}

namespace {

// Inserts `bad` points into a clean cloud at the given positions and checks that each bad
// point gets `expected` with NaN everywhere and count 0, and that every other point's
// estimate is bitwise the one it has in the clean cloud: the bad points are nobody's
// neighbour (same neighbour counts, same sums).
void check_unusable_points(const std::vector<Oriented_point>& clean, double r,
                           const std::vector<std::pair<std::size_t, Oriented_point>>& bad, Status expected)
{
  std::vector<Oriented_point> dirty;
  std::vector<int> origin;  // index in `clean`, or -1 for a bad point
  std::size_t next_bad = 0;
  for(std::size_t i = 0; i <= clean.size(); ++i)
  {
    while(next_bad < bad.size() && bad[next_bad].first == i)
    {
      dirty.push_back(bad[next_bad++].second);
      origin.push_back(-1);
    }
    if(i < clean.size())
    {
      dirty.push_back(clean[i]);
      origin.push_back(int(i));
    }
  }
  REQUIRE(dirty.size() == clean.size() + bad.size());
  typedef std::function<std::vector<Estimate>(const std::vector<Oriented_point>&)> Run;
  const std::vector<std::pair<std::string, Run>> runs = {
    {"ASO", [r](const std::vector<Oriented_point>& p) { return aso(p, r); }},
    {"ASO parallel", [r](const std::vector<Oriented_point>& p) { return aso<CGAL::Parallel_tag>(p, r); }},
    {"ASO authors", [r](const std::vector<Oriented_point>& p) { return aso_authors(p, r); }},
    {"APSS", [r](const std::vector<Oriented_point>& p) { return apss(p, r); }}};
  for(const auto& run : runs)
  {
    INFO(run.first);
    const auto ref = run.second(clean);
    const auto est = run.second(dirty);
    REQUIRE(est.size() == dirty.size());
    std::size_t wrong_bad = 0, changed = 0;
    for(std::size_t i = 0; i < dirty.size(); ++i)
    {
      if(origin[i] < 0)
        wrong_bad += (est[i].status == expected && est[i].neighbor_count == 0 && every_numeric_field_nan(est[i]) &&
                      !est[i].is_valid())
                       ? 0
                       : 1;
      else
        changed += same_estimate(est[i], ref[std::size_t(origin[i])]) ? 0 : 1;
    }
    CHECK(wrong_bad == 0);
    CHECK(changed == 0);
  }
}

}  // namespace

TEST_CASE("A point with a NaN or infinite coordinate is NON_FINITE_POINT and nobody's neighbour", "[bad_input]")
{
  const auto clean = sphere(3000, 1);
  const double r = 0.15;
  const Point p = clean[1000].first;
  const Vector n = clean[1000].second;
  check_unusable_points(clean, r,
                        {{0, {Point(nan_value, p.y(), p.z()), n}},
                         {500, {Point(p.x(), p.y(), inf_value), n}},
                         {1000, {Point(-inf_value, 0, 0), n}},
                         {2000, {Point(nan_value, nan_value, nan_value), n}},
                         {3000, {Point(p.x(), nan_value, p.z()), Vector(nan_value, 0, 0)}}},
                        Status::NON_FINITE_POINT);
}

TEST_CASE("A point with a zero, NaN or infinite normal is INVALID_NORMAL and nobody's neighbour", "[bad_input]")
{
  const auto clean = sphere(3000, 1);
  const double r = 0.15;
  // bad points placed exactly on good ones, so that they would be neighbours if used
  check_unusable_points(clean, r,
                        {{0, {clean[0].first, Vector(0, 0, 0)}},
                         {700, {clean[700].first, Vector(nan_value, 1, 0)}},
                         {1500, {clean[1500].first, Vector(0, inf_value, 0)}},
                         {1500, {clean[1499].first, Vector(nan_value, nan_value, nan_value)}},
                         {3000, {clean[2999].first, Vector(1e-300, 0, 0) * 1e-300}}},
                        Status::INVALID_NORMAL);
}

TEST_CASE("A cloud whose points are all unusable gives only invalid estimates", "[bad_input]")
{
  std::vector<Oriented_point> pts(5, Oriented_point(Point(0, 0, 0), Vector(0, 0, 0)));
  pts.emplace_back(Point(nan_value, 0, 0), Vector(0, 0, 1));
  for(const auto& est : {aso(pts, 1.0), apss(pts, 1.0), aso<CGAL::Parallel_tag>(pts, 1.0)})
  {
    REQUIRE(est.size() == 6);
    for(std::size_t i = 0; i < 5; ++i)
      CHECK(est[i].status == Status::INVALID_NORMAL);
    CHECK(est[5].status == Status::NON_FINITE_POINT);
    for(const Estimate& e : est)
      CHECK(every_numeric_field_nan(e));
  }
}

TEST_CASE("Fewer neighbours than the minimum is TOO_FEW_NEIGHBORS with the right neighbor_count", "[bad_input]")
{
  auto pts = sphere(3000, 1);
  const double r = 0.15;
  const std::size_t lonely = pts.size();
  pts.emplace_back(Point(10, 0, 0), Vector(1, 0, 0));  // alone: 1 neighbour
  pts.emplace_back(Point(0, 10, 0), Vector(0, 1, 0));  // a pair: 2 neighbours each
  pts.emplace_back(Point(0, 10 + 0.5 * r, 0), Vector(0, 1, 0));
  pts.emplace_back(Point(0, 0, 10), Vector(0, 0, 1));  // three: the fits' minimum
  pts.emplace_back(Point(0.05, 0, 10), Vector(0, 0, 1));
  pts.emplace_back(Point(0, 0.05, 10), Vector(0, 0, 1));
  const auto three = PSC::parameters::min_neighbors(3, maps());
  const auto three_authors = PSC::parameters::min_neighbors(3, authors_maps());
  // the default minimum (never below 6) and the fits' own minimum, 3 (min_neighbors(3))
  for(bool defaults : {true, false})
    for(const auto& est :
        {defaults ? aso(pts, r) : CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, three),
         defaults ? apss(pts, r) : CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, r, three),
         defaults ? aso_authors(pts, r) : CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, three_authors)})
    {
      REQUIRE(est.size() == pts.size());
      CHECK(est[lonely].status == Status::TOO_FEW_NEIGHBORS);
      CHECK(est[lonely].neighbor_count == 1);
      for(std::size_t i : {lonely + 1, lonely + 2})
      {
        CHECK(est[i].status == Status::TOO_FEW_NEIGHBORS);
        CHECK(est[i].neighbor_count == 2);
      }
      for(std::size_t i = lonely; i < lonely + 3; ++i)
        CHECK(every_numeric_field_nan(est[i]));
      for(std::size_t i = lonely + 3; i < lonely + 6; ++i)
      {
        // 3 neighbours is never a valid curvature tensor by default
        CHECK((est[i].status == Status::TOO_FEW_NEIGHBORS) == defaults);
        CHECK(est[i].neighbor_count == 3);
      }
      // the sphere's points keep their estimates (about 10 neighbours each)
      CHECK(est[0].is_valid());
    }
  // a smaller minimum than the fits need is raised to it: 2 neighbours stay too few
  const auto est =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, PSC::parameters::min_neighbors(1, maps()));
  CHECK(est[lonely + 1].status == Status::TOO_FEW_NEIGHBORS);
}

// Three flat neighbours with equal normals are a plane, the smallest neighbourhood the fits
// can solve (reached with min_neighbors(3); by default 3 neighbours are too few).
TEST_CASE("Three neighbours on a plane are enough for the fits, not for the default minimum", "[aso][apss][plane]")
{
  const std::vector<Oriented_point> pts = {
    {Point(0, 0, 1), Vector(0, 0, 2)}, {Point(0.3, 0, 1), Vector(0, 0, 2)}, {Point(0, 0.4, 1), Vector(0, 0, 2)}};
  const auto three = PSC::parameters::min_neighbors(3, maps());
  for(const auto& est : {CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 1.0, three),
                         CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, 1.0, three)})
    for(const Estimate& e : est)
    {
      REQUIRE(e.is_valid());
      CHECK(e.neighbor_count == 3);
      measured("three flat neighbours: |H|", std::abs(e.mean_curvature));
      CHECK(std::abs(e.mean_curvature) < 1e-12);  // measured 0
      CHECK(length(e.normal - Vector(0, 0, 1)) < 1e-12);
    }
  for(const auto& est : {aso(pts, 1.0), apss(pts, 1.0)})
    for(const Estimate& e : est)
    {
      CHECK(e.status == Status::TOO_FEW_NEIGHBORS);
      CHECK(e.neighbor_count == 3);
    }
}

TEST_CASE("Neighbours that all coincide are DEGENERATE_FIT with NaN fields", "[bad_input]")
{
  auto pts = sphere(3000, 1);
  const double r = 0.15;
  const std::size_t first = pts.size();
  for(int i = 0; i < 12; ++i)
    pts.emplace_back(Point(5, 5, 5), Vector(0, 0, 1));
  for(const auto& est : {aso(pts, r), apss(pts, r), aso_authors(pts, r), aso<CGAL::Parallel_tag>(pts, r)})
  {
    REQUIRE(est.size() == pts.size());
    for(std::size_t i = first; i < pts.size(); ++i)
    {
      CHECK(est[i].status == Status::DEGENERATE_FIT);
      CHECK(!est[i].is_valid());
      // the neighbours are counted (points at distance < r, the query included)
      CHECK(est[i].neighbor_count == 12);
      CHECK(every_numeric_field_nan(est[i]));
    }
    CHECK(count_invalid(est) == 12);
  }
}

TEST_CASE("Normals: neighbours that coincide up to rounding give no normal (DEGENERATE_FIT)", "[bad_input][normals]")
{
  // 60 samples within 5e-13 of a point of a sphere 1000 units from the origin (copies up to
  // rounding, as a rosette scan's passes over nadir leave): a normal fitted to their 40 nearest
  // is a fit of rounding errors (without the bound, every copy got one). The estimators' side:
  // test_baselines.
  std::vector<Oriented_point> pts = sphere(3000, 1, Point(1000, -2000, 500));
  const Point p = pts[0].first;
  for(const Point& q : near_copies(p, 60))
    pts.emplace_back(q, Vector(0, 0, 0));
  const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(
    pts, PSC::parameters::neighbor_count(
           40, PSC::parameters::normal_orientation(CGAL::Normal_orientation::towards_point(1000, -2000, 500), maps())));
  // the first point and its copies get a zero normal; away from them, the sphere's
  std::size_t zero = 0, far = 0, right = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(i == 0 || i >= 3000)
      zero += pts[i].second == CGAL::NULL_VECTOR ? 1 : 0;
    else if(std::sqrt(CGAL::squared_distance(pts[i].first, p)) > 0.5)
    {
      ++far;
      right += line_angle_degrees(pts[i].second, pts[i].first - Point(1000, -2000, 500)) < 1 ? 1 : 0;
    }
  CHECK(zero == 61);
  CHECK(without >= 61);
  CHECK(right == far);
}

// ---------------------------------------------------------------------------------------
// Containers, kernels and overloads
// ---------------------------------------------------------------------------------------

TEST_CASE("ASO and APSS: neighbours on a line or on a planar curve are DEGENERATE_FIT", "[bad_input][aso][apss]")
{
  // One scan line at a small radius: the curvature across the line is not measured, so no
  // tensor can be given (the sphere fit would silently supply its own curvature there).
  // Cases: a straight line with constant normals, a straight line with normals twisting
  // around it, a parabola z = x^2/2 in the plane y = 0 with its normals (a planar curve).
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  for(int variant = 0; variant < 3; ++variant)
  {
    std::vector<Oriented_point> pts;
    for(int i = -20; i <= 20; ++i)
    {
      const double x = 0.01 * i;
      const Vector n = variant == 0   ? Vector(0, 0, 1)
                       : variant == 1 ? Vector(0, std::sin(x), std::cos(x))
                                      : Vector(-x, 0, 1);
      pts.emplace_back(Point(x, 0, variant == 2 ? 0.5 * x * x : 0), n);
    }
    const auto e = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 0.1, np);
    const auto a = CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, 0.1, np);
    INFO("variant " << variant);
    CHECK(e[20].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
    CHECK(e[20].neighbor_count == 19);
    CHECK(std::isnan(e[20].min_curvature));
    // APSS too: its sphere would give the curvature along the line as a mean curvature.
    CHECK(a[20].status == CGAL::Curvature_estimate_status::DEGENERATE_FIT);
    CHECK(std::isnan(a[20].mean_curvature));
  }
  // A second scan line 0.02 away (within r) restores a tangent spread: valid again.
  std::vector<Oriented_point> two_lines;
  for(int i = -20; i <= 20; ++i)
    for(double y : {0.0, 0.02})
      two_lines.emplace_back(Point(0.01 * i, y, 0), Vector(0, 0, 1));
  const auto e = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(two_lines, 0.1, np);
  CHECK(e[40].is_valid());
  CHECK(std::abs(e[40].max_curvature) < 1e-12);
  const auto a = CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(two_lines, 0.1, np);
  CHECK(a[40].is_valid());
  CHECK(std::abs(a[40].mean_curvature) < 1e-12);
}

TEST_CASE("ASO refuses the constant kernel, which has no usable derivative", "[bad_input][aso]")
{
  const auto pts = sphere(2000, 1.0);
  namespace PSC = CGAL::Point_set_curvatures;
  const auto np = PSC::parameters::weight_kernel(CGAL::Apss_weight_kernel::CONSTANT,
                                                 CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  CHECK_THROWS_WITH(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 0.2, np),
                    Catch::Contains("weight_kernel"));
  CHECK_THROWS_AS(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(20, np)),
                  std::invalid_argument);
  // The smooth kernel, given explicitly, is the default.
  const auto smooth = PSC::parameters::weight_kernel(CGAL::Apss_weight_kernel::SMOOTH,
                                                     CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  CHECK(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 0.2, smooth)[0].is_valid());
}

TEST_CASE("Pairs, tuples, Point_set_3, Simple_cartesian and Epick give identical results", "[aso][apss][api]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  const auto ref = aso(pts, r);
  const auto ref_apss = apss(pts, r);
  auto all_identical = [](const auto& a, const auto& b) {
    if(a.size() != b.size())
      return false;
    for(std::size_t i = 0; i < a.size(); ++i)
      if(!same_estimate(a[i], b[i]))
        return false;
    return true;
  };

  SECTION("explicit maps overload")
  {
    CHECK(all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, Point_map(), Normal_map(), r)));
    CHECK(
      all_identical(ref_apss, CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, Point_map(), Normal_map(), r)));
  }
  SECTION("geom_traits named parameter")
  {
    CHECK(
      all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, maps().geom_traits(Kernel()))));
  }
  SECTION("std::tuple with Nth_of_tuple_property_map")
  {
    typedef std::tuple<Point, Vector, int> Tuple;
    std::vector<Tuple> tuples;
    for(const auto& p : pts)
      tuples.emplace_back(p.first, p.second, 7);
    const CGAL::Nth_of_tuple_property_map<0, Tuple> pm;
    const CGAL::Nth_of_tuple_property_map<1, Tuple> nm;
    CHECK(all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                               tuples, r, CGAL::parameters::point_map(pm).normal_map(nm))));
    CHECK(all_identical(ref_apss, CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(tuples, pm, nm, r)));
  }
  SECTION("CGAL::Point_set_3 with and without explicit maps")
  {
    CGAL::Point_set_3<Point, Vector> ps;
    ps.add_normal_map();
    for(const auto& p : pts)
      ps.insert(p.first, p.second);
    CHECK(all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(ps, r)));
    CHECK(all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ps, r, ps.parameters())));
    CHECK(all_identical(ref_apss, CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(ps, r)));
    CHECK(all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                               ps, r, CGAL::parameters::point_map(ps.point_map()).normal_map(ps.normal_map()))));
  }
  SECTION("Epick points in pairs and in a Point_set_3")
  {
    typedef std::pair<Epick::Point_3, Epick::Vector_3> Epick_point;
    std::vector<Epick_point> epts;
    CGAL::Point_set_3<Epick::Point_3, Epick::Vector_3> eps;
    eps.add_normal_map();
    for(const auto& p : pts)
    {
      const Epick::Point_3 q(p.first.x(), p.first.y(), p.first.z());
      const Epick::Vector_3 n(p.second.x(), p.second.y(), p.second.z());
      epts.emplace_back(q, n);
      eps.insert(q, n);
    }
    const std::vector<CGAL::Curvature_estimate<Epick>> e = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
      epts, r,
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Epick_point>())
        .normal_map(CGAL::Second_of_pair_property_map<Epick_point>()));
    CHECK(all_identical(ref, e));
    CHECK(all_identical(ref, CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(eps, r)));
    CHECK(all_identical(ref_apss, CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(eps, r)));
  }
}

// ---------------------------------------------------------------------------------------
// Progress and cancellation
// ---------------------------------------------------------------------------------------

// 200K points: progress is reported about every 1% of the points and at least every 16384,
// so the run has a dozen batches and can be cancelled in the middle.
TEST_CASE("A std::list (not random access) gives the same results as a std::vector", "[aso][apss][api]")
{
  // The driver reads non-random-access ranges through a table of iterators; the values and
  // the order of the results must not change, sequentially or in parallel.
  const std::vector<Oriented_point> pts = read_xyz(repo_data("goursat_010000.xyz"));
  const std::list<Oriented_point> listed(pts.begin(), pts.end());
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  const auto from_vector = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 1.5, np);
  const auto from_list = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(listed, 1.5, np);
  const auto from_list_parallel = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(listed, 1.5, np);
  REQUIRE(from_list.size() == pts.size());
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    REQUIRE(same_estimate(from_vector[i], from_list[i]));
    REQUIRE(same_estimate(from_vector[i], from_list_parallel[i]));
  }
}

TEST_CASE("callback reports non-decreasing progress in [0,1] ending at 1, and returning false cancels",
          "[aso][apss][callback]")
{
  const auto pts = sphere(200000, 1);
  const double r = 0.025;  // about 30 neighbours
  const auto full = aso(pts, r);
  REQUIRE(count_invalid(full) == 0);

  SECTION("full run")
  {
    std::vector<double> progress;
    const std::function<bool(double)> cb = [&progress](double x) {
      progress.push_back(x);
      return true;
    };
    const auto est = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, maps().callback(cb));
    REQUIRE(progress.size() >= 5);
    bool in_range = true, monotone = true;
    for(std::size_t i = 0; i < progress.size(); ++i)
    {
      in_range = in_range && progress[i] >= 0 && progress[i] <= 1;
      monotone = monotone && (i == 0 || progress[i] >= progress[i - 1]);
    }
    CHECK(in_range);
    CHECK(monotone);
    CHECK(progress.back() == 1.0);
    std::size_t differ = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      differ += same_estimate(est[i], full[i]) ? 0 : 1;
    CHECK(differ == 0);
  }

  // (the paper's variant: one pass, so the last value reported is the fraction of points
  // computed; the default runs a sample-weight pass first, see the next test)
  SECTION("cancelled runs, sequential and parallel, ASO and APSS")
  {
    const auto full_apss = apss(pts, r);
    const auto full_paper = aso_paper(pts, r);
    for(int run = 0; run < 4; ++run)
    {
      INFO("run " << run);
      int calls = 0;
      double last = -1;
      const std::function<bool(double)> cb = [&calls, &last](double x) {
        last = x;
        return ++calls < 3;  // cancel at the third report
      };
      const auto np = maps().callback(cb);
      const auto paper = PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, np);
      const std::vector<Estimate> est = run == 0   ? CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, paper)
                                        : run == 1 ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, paper)
                                        : run == 2 ? CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, r, np)
                                                   : CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, np);
      const auto& reference = run < 2 ? full_paper : full_apss;
      REQUIRE(est.size() == pts.size());
      CHECK(calls == 3);
      std::size_t computed = 0, not_computed = 0, bad = 0;
      for(std::size_t i = 0; i < pts.size(); ++i)
      {
        if(est[i].status == Status::NOT_COMPUTED)
        {
          ++not_computed;
          bad += (every_numeric_field_nan(est[i]) && est[i].neighbor_count == 0 && !est[i].is_valid()) ? 0 : 1;
        }
        else
        {
          ++computed;
          bad += same_estimate(est[i], reference[i]) ? 0 : 1;
        }
      }
      CHECK(bad == 0);
      CHECK(computed > 0);
      CHECK(not_computed > 0);
      // the last progress value reported is the fraction of points actually computed
      CHECK(std::abs(double(computed) - last * double(pts.size())) < 0.5);
    }
  }
}

// The default ASO with normal_refinement(1) runs three passes (sample weights, the refinement's
// sphere fit, the estimation), sharing [0, 1] as 0.25, 0.25, 0.5. Cancelled before the last
// pass, no point may carry a value: the earlier passes' values are not curvature estimates.
TEST_CASE("cancelled in the sample-weight or the refinement pass, every point is NOT_COMPUTED, in the estimation pass "
          "the points reached are the full run's",
          "[aso][callback][robust]")
{
  const auto pts = sphere(50000, 1);
  const double r = 0.05;  // about 30 neighbours
  const auto np = PSC::parameters::normal_refinement(1, maps());
  const auto full = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, np);
  REQUIRE(count_invalid(full) == 0);
  for(const double cancel_above : {0.0, 0.3, 0.7})
  {
    INFO("cancel at the first report above " << cancel_above);
    double cancelled_at = -1;
    const std::function<bool(double)> cb = [&](double x) {
      if(cancelled_at < 0 && x > cancel_above)
      {
        cancelled_at = x;
        return false;
      }
      return true;
    };
    const auto est = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      pts, r, PSC::parameters::normal_refinement(1, maps().callback(cb)));
    REQUIRE(cancelled_at > cancel_above);
    std::size_t computed = 0, not_computed = 0, bad = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      if(est[i].status == Status::NOT_COMPUTED)
      {
        ++not_computed;
        bad += every_numeric_field_nan(est[i]) ? 0 : 1;
      }
      else
      {
        ++computed;
        bad += same_estimate(est[i], full[i]) ? 0 : 1;
      }
    CHECK(bad == 0);
    if(cancelled_at < 0.5)
      CHECK(computed == 0);
    else
    {
      CHECK(computed > 0);
      CHECK(not_computed > 0);
    }
  }
}

// The documented rule: callback(fraction done) at least every 1% of the points, whatever
// the driver, the concurrency tag, and however many points share a grid cell.
TEST_CASE("callback comes at most 1% of the points apart on 100K points, by radius, by count and with one cell holding "
          "everything",
          "[aso][callback]")
{
  const auto pts = sphere(100000, 1);
  auto widest_step = [](const std::vector<double>& p) {
    double w = p.empty() ? 1.0 : p[0];
    for(std::size_t i = 1; i < p.size(); ++i)
      w = std::max(w, p[i] - p[i - 1]);
    return w;
  };
  for(int run = 0; run < 4; ++run)
  {
    INFO("run " << run << (run % 2 ? " parallel" : " sequential") << (run < 2 ? ", radius" : ", count"));
    std::vector<double> progress;
    const std::function<bool(double)> cb = [&progress](double x) {
      progress.push_back(x);
      return true;
    };
    const auto by_radius = maps().callback(cb);
    const auto by_count = PSC::parameters::neighbor_count(30, maps().callback(cb));
    const auto est = run == 0   ? CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 0.03, by_radius)
                     : run == 1 ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, 0.03, by_radius)
                     : run == 2 ? CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, by_count)
                                : CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, by_count);
    CHECK(count_invalid(est) == 0);
    REQUIRE(progress.size() >= 100);
    CHECK(widest_step(progress) <= 0.01 + 1e-12);  // 1000 points of 100000
    CHECK(progress.back() == 1.0);
  }

  // A radius covering the whole cloud: one grid cell holds every point, and is still split
  // into batches of at most 1% (and between threads); cancelling at the first report stops
  // the run there.
  const auto small = sphere(3000, 1);
  for(bool parallel : {false, true})
  {
    INFO((parallel ? "parallel" : "sequential") << ", radius 3 on a unit sphere");
    std::vector<double> progress;
    const std::function<bool(double)> cb = [&progress](double x) {
      progress.push_back(x);
      return true;
    };
    const auto est = parallel ? CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(small, 3.0, maps().callback(cb))
                              : CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(small, 3.0, maps().callback(cb));
    CHECK(count_invalid(est) == 0);
    REQUIRE(progress.size() >= 100);
    CHECK(widest_step(progress) <= 0.01 + 1e-12);  // 30 points of 3000
    std::size_t reports = 0;
    const std::function<bool(double)> cancel = [&reports](double) { return ++reports < 1; };
    const auto cut = parallel
                       ? CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(small, 3.0, maps().callback(cancel))
                       : CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(small, 3.0, maps().callback(cancel));
    CHECK(reports == 1);
    CHECK(count_invalid(cut) >= 3000 - 30);  // NOT_COMPUTED beyond the first batch
  }
}

// ---------------------------------------------------------------------------------------
// Per-query classes
// ---------------------------------------------------------------------------------------

namespace {

// A patch of an ellipsoid whose bounding box is smaller than r in every direction, moved
// inside one cell of the drivers' lattice (cells of side r anchored at the origin): the cloud
// functions then see every neighbourhood in input order, the order in which the per-query
// classes below receive them, so results must be bitwise equal.
std::vector<Oriented_point> small_patch(double half_side, double r)
{
  std::vector<Oriented_point> patch;
  for(const auto& p : ellipsoid(20000, 1, 0.8, 0.6))
    if(p.first.x() > 0 && std::abs(p.first.y()) < half_side && std::abs(p.first.z()) < half_side)
      patch.push_back(p);
  double lo[3] = {1e300, 1e300, 1e300};
  for(const auto& p : patch)
    for(int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p.first[a]);
  // the lowest corner goes to 1% of r above a lattice point (2r, 0, 0), by an exact shift
  const Vector shift(2 * r + 0.01 * r - lo[0], 0.01 * r - lo[1], 0.01 * r - lo[2]);
  for(auto& p : patch)
    p.first = p.first + shift;
  return patch;
}

}  // namespace

TEST_CASE("The per-query classes reproduce the cloud functions exactly at an input point", "[aso][apss][per_query]")
{
  const double r = 0.3;
  const auto patch = small_patch(0.14, r);  // extent 0.28 < r, in x too (x > 0.95 there)
  REQUIRE(patch.size() > 50);
  // the per-query classes compute the paper's estimator
  const auto est = aso_paper(patch, r);
  const auto est_authors = aso_authors(patch, r);
  const auto est_apss = apss(patch, r);
  std::size_t differ = 0, differ_authors = 0, differ_apss = 0, wrong_return = 0, valid = 0;
  for(std::size_t i = 0; i < patch.size(); ++i)
  {
    const Point& x = patch[i].first;
    CGAL::Algebraic_shape_operator_fit<Kernel> fit(x, r);
    CGAL::Algebraic_shape_operator_fit<Kernel> fit_authors(x, r, CGAL::Aso_projection::AUTHORS_IMPLEMENTATION);
    CGAL::Algebraic_sphere_fit<Kernel> sphere_fit(x, r);
    for(const auto& p : patch)
    {
      const bool inside = CGAL::squared_distance(p.first, x) < r * r;
      wrong_return += (fit.add_neighbor(p.first, p.second) == inside) ? 0 : 1;
      fit_authors.add_neighbor(p.first, p.second);
      wrong_return += (sphere_fit.add_neighbor(p.first, p.second) == inside) ? 0 : 1;
    }
    CHECK(fit.neighbor_count() == est[i].neighbor_count);
    CHECK(sphere_fit.neighbor_count() == est_apss[i].neighbor_count);
    differ += same_estimate(fit.estimate(), est[i]) ? 0 : 1;
    differ_authors += same_estimate(fit_authors.estimate(), est_authors[i]) ? 0 : 1;
    differ_apss += same_estimate(sphere_fit.estimate(), est_apss[i]) ? 0 : 1;
    valid += est[i].is_valid() ? 1 : 0;
  }
  // the same with Epick, whose FT is double too
  {
    const Point& x = patch[0].first;
    CGAL::Algebraic_shape_operator_fit<Epick> fit(Epick::Point_3(x.x(), x.y(), x.z()), r);
    for(const auto& p : patch)
      fit.add_neighbor(Epick::Point_3(p.first.x(), p.first.y(), p.first.z()),
                       Epick::Vector_3(p.second.x(), p.second.y(), p.second.z()));
    CHECK(same_estimate(fit.estimate(), est[0]));
  }
  CHECK(valid == patch.size());
  CHECK(wrong_return == 0);
  CHECK(differ == 0);
  CHECK(differ_authors == 0);
  CHECK(differ_apss == 0);
}

// On a real cloud the neighbours reach the classes in another order than in the cloud
// functions (which sort points in a grid): the same sums in another order.
TEST_CASE("The per-query classes agree with the cloud functions on Goursat 10K and ignore points beyond r",
          "[aso][apss][per_query]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  const auto est = aso_paper(pts, r);
  const auto est_apss = apss(pts, r);
  Stat k, n, h;
  std::size_t count_mismatch = 0;
  for(std::size_t i = 0; i < pts.size(); i += 50)
  {
    CGAL::Algebraic_shape_operator_fit<Kernel> fit(pts[i].first, r);
    CGAL::Algebraic_sphere_fit<Kernel> sphere_fit(pts[i].first, r);
    fit.add_neighbors(pts, Point_map(), Normal_map());  // the whole cloud: most are beyond r
    sphere_fit.add_neighbors(pts, Point_map(), Normal_map());
    count_mismatch +=
      (fit.neighbor_count() == est[i].neighbor_count && sphere_fit.neighbor_count() == est[i].neighbor_count) ? 0 : 1;
    const Estimate e = fit.estimate(), ea = sphere_fit.estimate();
    REQUIRE(e.is_valid());
    const double scale = curvature_scale(est[i]);
    k.add(scaled_difference(e.min_curvature, est[i].min_curvature, scale));
    k.add(scaled_difference(e.max_curvature, est[i].max_curvature, scale));
    k.add(scaled_difference(e.gaussian_curvature, est[i].gaussian_curvature, scale * scale));
    n.add(length(e.normal - est[i].normal));
    n.add(length(ea.normal - est_apss[i].normal));
    h.add(scaled_difference(ea.mean_curvature, est_apss[i].mean_curvature, scale));
  }
  measured("per-query vs cloud on Goursat 10K: max scaled curvature difference (ASO)", k.max);
  measured("per-query vs cloud on Goursat 10K: max normal difference", n.max);
  measured("per-query vs cloud on Goursat 10K: max scaled H difference (APSS)", h.max);
  CHECK(count_mismatch == 0);
  // Measured: 1.8e-15 (ASO curvatures, scaled), 3.2e-16 (normals), 2.5e-15 (APSS H):
  // summation order only.
  CHECK(k.max < 1e-12);
  CHECK(n.max < 1e-12);
  CHECK(h.max < 1e-12);
}

// Off the surface the ASO measures the level set of the fitted field through the
// evaluation point: for a sphere of radius R that is the concentric sphere through x, of
// curvature 1/|x - c|. APSS returns the curvature of the fitted sphere itself, 1/R.
TEST_CASE("The per-query classes evaluate off the cloud: ASO gives the level set's curvature, APSS the fitted sphere's",
          "[aso][apss][per_query]")
{
  const double R = 2, r = 0.4;
  const Point c(1, 2, 3);
  const auto pts = sphere(20000, R, c);
  Stat aso_err, apss_err, n_err;
  for(double offset : {-0.05, 0.02, 0.1})
    for(const Vector u : {Vector(0.6, 0, 0.8), Vector(-1, 0, 0), Vector(1, 1, 1) / std::sqrt(3.0)})
    {
      const Point x = c + (R + offset) * u;
      CGAL::Algebraic_shape_operator_fit<Kernel> fit(x, r);
      CGAL::Algebraic_sphere_fit<Kernel> sphere_fit(x, r);
      fit.add_neighbors(pts, Point_map(), Normal_map());
      sphere_fit.add_neighbors(pts, Point_map(), Normal_map());
      REQUIRE(fit.neighbor_count() > 50);
      REQUIRE(fit.neighbor_count() == brute_force_count(pts, x, r));
      const Estimate e = fit.estimate(), ea = sphere_fit.estimate();
      REQUIRE(e.is_valid());
      REQUIRE(ea.is_valid());
      const double level = 1 / (R + offset);
      aso_err.add(std::abs(e.min_curvature - level) / level);
      aso_err.add(std::abs(e.max_curvature - level) / level);
      aso_err.add(std::abs(e.gaussian_curvature - level * level) / (level * level));
      apss_err.add(std::abs(ea.mean_curvature - 1 / R) * R);
      n_err.add(length(e.normal - u));
      n_err.add(length(ea.normal - u));
    }
  measured("off-surface ASO: max relative error to 1/|x-c|", aso_err.max);
  measured("off-surface APSS: max relative error to 1/R", apss_err.max);
  measured("off-surface: max normal error", n_err.max);
  // Measured: 3.7e-15 (ASO), 8.0e-15 (APSS), 7.9e-16 (normals): the fit is exact, only
  // rounding is left.
  CHECK(aso_err.max < 1e-12);
  CHECK(apss_err.max < 1e-12);
  CHECK(n_err.max < 1e-12);
}

TEST_CASE("The per-query classes reject bad radii, non-finite positions and unusable neighbours",
          "[bad_input][per_query]")
{
  const Point x(0, 0, 1);
  using Catch::Matchers::Contains;
  for(double r : {0.0, -1.0, nan_value, inf_value})
  {
    INFO("radius " << r);
    const std::string value = printed(r);
    CHECK_THAT(invalid_argument_message([&] { CGAL::Algebraic_shape_operator_fit<Kernel> fit(x, r); }),
               Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message([&] {
                 CGAL::Algebraic_shape_operator_fit<Kernel> fit(x, r, CGAL::Aso_projection::AUTHORS_IMPLEMENTATION);
               }),
               Contains("radius") && Contains(value));
    CHECK_THAT(invalid_argument_message([&] { CGAL::Algebraic_sphere_fit<Kernel> fit(x, r); }),
               Contains("radius") && Contains(value));
  }
  CHECK_THROWS_AS(CGAL::Algebraic_shape_operator_fit<Kernel>(Point(nan_value, 0, 0), 1.0), std::invalid_argument);
  CHECK_THROWS_AS(CGAL::Algebraic_sphere_fit<Kernel>(Point(0, inf_value, 0), 1.0), std::invalid_argument);

  CGAL::Algebraic_shape_operator_fit<Kernel> fit(x, 0.5);
  CGAL::Algebraic_sphere_fit<Kernel> sphere_fit(x, 0.5);
  // an empty fit is TOO_FEW_NEIGHBORS with count 0 and NaN everywhere
  CHECK(fit.estimate().status == Status::TOO_FEW_NEIGHBORS);
  CHECK(every_numeric_field_nan(fit.estimate()));
  CHECK(sphere_fit.estimate().status == Status::TOO_FEW_NEIGHBORS);
  CHECK(fit.estimate().neighbor_count == 0);
  const std::vector<Oriented_point> unusable = {{Point(0, 0, 1.5), Vector(0, 0, 1)},  // at distance r
                                                {Point(0, 0, 1), Vector(0, 0, 0)},
                                                {Point(0, 0, 1), Vector(nan_value, 0, 1)},
                                                {Point(nan_value, 0, 1), Vector(0, 0, 1)},
                                                {Point(0, inf_value, 1), Vector(0, 0, 1)}};
  for(const auto& p : unusable)
  {
    CHECK_FALSE(fit.add_neighbor(p.first, p.second));
    CHECK_FALSE(sphere_fit.add_neighbor(p.first, p.second));
  }
  CHECK(fit.neighbor_count() == 0);
  CHECK(sphere_fit.neighbor_count() == 0);
  // two usable neighbours: still too few, counted
  CHECK(fit.add_neighbor(Point(0, 0, 1), Vector(0, 0, 1)));
  CHECK(fit.add_neighbor(Point(0.1, 0, 1), Vector(0, 0, 1)));
  CHECK(fit.estimate().status == Status::TOO_FEW_NEIGHBORS);
  CHECK(fit.estimate().neighbor_count == 2);
  // 2 < 12 (the default minimum); the fit's own minimum is 3
  CHECK(fit.estimate(1).status == Status::TOO_FEW_NEIGHBORS);
  // coincident neighbours (as many as the default minimum): degenerate
  CGAL::Algebraic_shape_operator_fit<Kernel> same(x, 0.5);
  CGAL::Algebraic_sphere_fit<Kernel> same_sphere(x, 0.5);
  for(int i = 0; i < 12; ++i)
  {
    same.add_neighbor(Point(0, 0.1, 1), Vector(0, 0, 1));
    same_sphere.add_neighbor(Point(0, 0.1, 1), Vector(0, 0, 1));
  }
  CHECK(same.estimate().status == Status::DEGENERATE_FIT);
  CHECK(same_sphere.estimate().status == Status::DEGENERATE_FIT);
  CHECK(every_numeric_field_nan(same.estimate()));
  CHECK(every_numeric_field_nan(same_sphere.estimate()));
}

// ---------------------------------------------------------------------------------------
// Tiles (Tile.h): a cloud estimated tile by tile gives the whole-cloud estimates bitwise
// ---------------------------------------------------------------------------------------

namespace {

// The range a tile needs: every point at distance <= halo from its core, in input order;
// `origin[j]` is the input index of the j-th point of the range.
std::vector<Oriented_point> tile_range(const std::vector<Oriented_point>& pts, const PSC::Tile& t,
                                       std::vector<std::size_t>& origin)
{
  std::vector<Oriented_point> range;
  origin.clear();
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(t.distance_to_core(pts[i].first.x(), pts[i].first.y(), pts[i].first.z()) <= t.halo)
    {
      range.push_back(pts[i]);
      origin.push_back(i);
    }
  return range;
}

// Of a tile's estimates `part` on `range` (`origin[j]`: the input index of its j-th point),
// how many belong to the tile's own points, and how many of those differ from the whole
// run's `whole` (bitwise).
struct Own_points
{
  std::size_t own = 0, differ = 0;
};
Own_points compare_own(const std::vector<Oriented_point>& range, const std::vector<std::size_t>& origin,
                       const PSC::Tile& t, const std::vector<Estimate>& part, const std::vector<Estimate>& whole)
{
  Own_points c;
  for(std::size_t j = 0; j < range.size(); ++j)
    if(t.owns(range[j].first.x(), range[j].first.y(), range[j].first.z()))
    {
      ++c.own;
      c.differ += !same_estimate(part[j], whole[origin[j]]);
    }
  return c;
}

}  // namespace

TEST_CASE("Tiles: every point estimated once, bitwise as in the whole-cloud run, by radius and by count",
          "[aso][apss][tile]")
{
  auto pts = ellipsoid(20000, 1, 0.8, 0.6, 7);
  pts[5].first = Point(nan_value, 0, 0);  // a non-finite point: nobody's own point
  const double r = 0.08;
  const std::size_t k = 25;
  const PSC::Tile_grid tiles(CGAL::Bbox_3(-1, -0.8, -0.6, 1, 0.8, 0.6), {{3, 2, 2}});
  REQUIRE(tiles.size() == 12);
  const auto whole_radius = aso(pts, r);  // the default variant: sample weights, reach 2 r
  // by count: the paper's variant, and the default (sample weights: the areas of the own
  // points' neighbours must be exact too)
  const auto paper = PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, maps());
  const auto whole_count =
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, PSC::parameters::neighbor_count(k, paper));
  const auto whole_count_weighted =
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, PSC::parameters::neighbor_count(k, maps()));
  // the tile of all space is no tile, whatever the options
  {
    const auto all = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      pts, PSC::parameters::neighbor_count(k, PSC::parameters::tile(PSC::Tile::whole_space(), maps())));
    std::size_t differ_all = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      differ_all += !same_estimate(all[i], whole_count_weighted[i]);
    CHECK(differ_all == 0);
  }
  const auto whole_apss = apss<CGAL::Parallel_tag>(pts, r);
  std::vector<int> owned(pts.size(), 0);
  std::size_t differ = 0, retried = 0, differ_count = 0, retried_weighted = 0, compared_weighted = 0;
  for(std::size_t i = 0; i < tiles.size(); ++i)
  {
    std::vector<std::size_t> origin;
    // by radius: a halo of two radii (the neighbours' sample weights depend on their own
    // neighbours)
    const PSC::Tile t = tiles.tile(i, 2 * r);
    const auto range = tile_range(pts, t, origin);
    const auto e = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(range, r, PSC::parameters::tile(t, maps()));
    const auto a = CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(range, r, PSC::parameters::tile(t, maps()));
    for(std::size_t j = 0; j < range.size(); ++j)
    {
      const Point& p = range[j].first;
      const bool own = t.owns(p.x(), p.y(), p.z());
      if(own)
      {
        ++owned[origin[j]];
        differ += !same_estimate(e[j], whole_radius[origin[j]]) + !same_estimate(a[j], whole_apss[origin[j]]);
      }
      else  // the unusable point keeps its status in every tile; the others are not computed
      {
        const Status expected = origin[j] == 5 ? Status::NON_FINITE_POINT : Status::NOT_COMPUTED;
        differ += (e[j].status != expected) + (a[j].status != expected);
      }
    }
    // by count: start from a small halo, grow it to what Halo_too_small asks
    double halo = 0.02;
    for(;;)
    {
      const PSC::Tile tk = tiles.tile(i, halo);
      const auto range_k = tile_range(pts, tk, origin);
      try
      {
        const auto ek = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
          range_k, PSC::parameters::neighbor_count(k, PSC::parameters::tile(tk, paper)));
        for(std::size_t j = 0; j < range_k.size(); ++j)
          if(tk.owns(range_k[j].first.x(), range_k[j].first.y(), range_k[j].first.z()))
            differ_count += !same_estimate(ek[j], whole_count[origin[j]]);
        break;
      }
      catch(const PSC::Halo_too_small& too_small)
      {
        REQUIRE(too_small.required_halo() > halo);
        halo = too_small.required_halo();
        ++retried;
      }
    }
    // by count with sample weights, from the halo the paper's variant needed: the areas
    // may ask for more
    for(;;)
    {
      const PSC::Tile tk = tiles.tile(i, halo);
      const auto range_k = tile_range(pts, tk, origin);
      try
      {
        const auto ek = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
          range_k, PSC::parameters::neighbor_count(k, PSC::parameters::tile(tk, maps())));
        for(std::size_t j = 0; j < range_k.size(); ++j)
          if(tk.owns(range_k[j].first.x(), range_k[j].first.y(), range_k[j].first.z()))
          {
            differ_count += !same_estimate(ek[j], whole_count_weighted[origin[j]]);
            ++compared_weighted;
          }
        break;
      }
      catch(const PSC::Halo_too_small& too_small)
      {
        REQUIRE(too_small.required_halo() > halo);
        halo = too_small.required_halo();
        ++retried_weighted;
      }
    }
  }
  CHECK(differ == 0);
  CHECK(differ_count == 0);
  CHECK(compared_weighted == pts.size() - 1);
  CHECK(retried_weighted > 0);  // the areas asked for a larger halo than the estimation alone
  std::size_t once = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    once += owned[i] == (i == 5 ? 0 : 1);
  CHECK(once == pts.size());
  CHECK(retried > 0);  // the small first halo was refused at least once (the retry path is tested)
  // a halo smaller than the reach is refused by radius: one radius for the paper's variant,
  // two with sample weights (the default); normal_refinement refuses tiles
  CHECK_THROWS_AS(
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, PSC::parameters::tile(tiles.tile(0, 0.5 * r), paper)),
    std::invalid_argument);
  CHECK_THROWS_AS(
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, PSC::parameters::tile(tiles.tile(0, 1.5 * r), maps())),
    std::invalid_argument);
  CHECK_NOTHROW(
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, PSC::parameters::tile(tiles.tile(0, 1.5 * r), paper)));
  CHECK_THROWS_AS(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                    pts, r, PSC::parameters::normal_refinement(1, PSC::parameters::tile(tiles.tile(0, 3 * r), maps()))),
                  std::invalid_argument);
}

// Issue 14: normals far from unit length are not trusted. With the authors' projection
// (normals used unnormalised) a normal of length 1e15 once gave a VALID H = 1.0036 on the unit
// sphere, 1e20 gave 535.
TEST_CASE("Normals of length outside [1e-3, 1e3] are INVALID_NORMAL unless accept_unnormalized_normals",
          "[aso][apss][bad_input]")
{
  auto pts = sphere(3000, 1);
  const double r = 0.15;
  const std::size_t big = 100, small = 200, fine = 300;
  pts[big].second = pts[big].second * 1e15;
  pts[small].second = pts[small].second * 1e-5;
  pts[fine].second = pts[fine].second * 900;  // inside the range: used (normalised by default)
  for(const auto& est : {aso(pts, r), apss(pts, r), aso_authors(pts, r)})
  {
    CHECK(est[big].status == Status::INVALID_NORMAL);
    CHECK(est[small].status == Status::INVALID_NORMAL);
    CHECK(every_numeric_field_nan(est[big]));
    CHECK(est[fine].is_valid());
    CHECK(est[0].is_valid());
  }
  // asked for: every finite non-zero normal is used; the default projection normalises them,
  // so the sphere stays exact
  const auto accepted = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, r, PSC::parameters::accept_unnormalized_normals(true, maps()));
  CHECK(accepted[big].is_valid());
  CHECK(accepted[small].is_valid());
  CHECK(std::abs(accepted[big].mean_curvature - 1) < 1e-9);
  CHECK(std::abs(accepted[small].mean_curvature - 1) < 1e-9);
}

// Review findings: a far outlier makes the whole cloud's grid use larger cells than the
// tile's (the grid must fit 62-bit keys); neighbourhoods are then put back in the order of
// cells of side r, so the tile still matches bitwise. By count, a range with fewer than k
// points asks for a larger halo instead of estimating from too few. Progress with a tile
// counts own points, at most 1% apart.
TEST_CASE("Tiles: bitwise with a far outlier, Halo_too_small below k points, progress in own points", "[aso][tile]")
{
  auto pts = sphere(20000, 1);
  pts.emplace_back(Point(1e15, 0, 0), Vector(1, 0, 0));
  const double r = 0.08;
  const auto whole = aso(pts, r);
  const PSC::Tile t(CGAL::Bbox_3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, 0, HUGE_VAL, HUGE_VAL), 2 * r);
  std::vector<std::size_t> origin;
  const auto range = tile_range(pts, t, origin);
  const auto part = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(range, r, PSC::parameters::tile(t, maps()));
  const Own_points compared = compare_own(range, origin, t, part, whole);
  CHECK(compared.own > 9000);
  CHECK(compared.differ == 0);  // 9949 of 9999 differed before the fix

  // five points alone at x = 5 with k = 25: their 25 nearest are not in the range
  std::vector<Oriented_point> few;
  for(int i = 0; i < 5; ++i)
    few.emplace_back(Point(5 + 0.01 * i, 0.02 * i * i, 0), Vector(0, 0, 1));
  const PSC::Tile around(CGAL::Bbox_3(4, -1, -1, 6, 1, 1), 0.5);
  CHECK_THROWS_AS(
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
      few, PSC::parameters::neighbor_count(
             25, PSC::parameters::tile(around, PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, maps())))),
    PSC::Halo_too_small);

  // own points 5% of the range: reports at most 1% of the own points apart
  const auto big = sphere(200000, 1);
  const PSC::Tile small_core(CGAL::Bbox_3(0.95, -HUGE_VAL, -HUGE_VAL, HUGE_VAL, HUGE_VAL, HUGE_VAL), HUGE_VAL);
  std::vector<double> progress;
  const std::function<bool(double)> cb = [&progress](double f) {
    progress.push_back(f);
    return true;
  };
  CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    big, 0.02,
    PSC::parameters::tile(small_core, PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, maps().callback(cb))));
  REQUIRE(progress.size() >= 90);  // measured 99 (batches of 1% rounded up)
  double widest = progress[0];
  for(std::size_t i = 1; i < progress.size(); ++i)
    widest = std::max(widest, progress[i] - progress[i - 1]);
  std::size_t own_points = 0;
  for(const auto& p : big)
    own_points += small_core.owns(p.first.x(), p.first.y(), p.first.z());
  // at most 1% of the own points, rounded up (0.20 before the fix)
  CHECK(widest <= double((own_points + 99) / 100) / double(own_points) + 1e-12);
  CHECK(progress.back() == 1.0);
}

TEST_CASE("Tiles: the drivers' rules: the tiles' box ignores outliers, the sample is every 2^j-th finite point, "
          "non-finite points are in no range, a range of every finite point is the whole cloud",
          "[tile]")
{
  // 1000 points on [0, 999] along x (y = -x, z = 7), and two outliers far away
  PSC::Tile_box_sample sample;
  sample.add(1e9, 0, 0);
  for(int i = 0; i < 1000; ++i)
  {
    sample.add(i, -i, 7);
    if(i == 500)
      sample.add(nan_value, 0, 0);  // skipped, not counted
  }
  sample.add(-1e9, 5, 5);
  REQUIRE(sample.size() == 1002);
  CHECK(sample.stride() == 1);
  const CGAL::Bbox_3 box = sample.box();
  // ranks floor(0.001 * 1001) = 1 and ceil(0.999 * 1001) = 1000 of the 1002 values on each axis
  CHECK(box.xmin() == 0);
  CHECK(box.xmax() == 999);
  CHECK(box.ymin() == -998);  // (the values -999 ... 0 and the outliers' 0 and 5)
  CHECK(box.ymax() == 0);
  CHECK(box.zmin() == 5);  // (the outliers' 0 and 5 below the 7s: rank 1 is 5)
  CHECK(box.zmax() == 7);
  CHECK(PSC::tile_grid_box({}) == CGAL::Bbox_3(0, 0, 0, 0, 0, 0));

  // at most 4 of 10 finite points: every 4th (0, 4, 8), the least power of two that keeps 4 or fewer
  PSC::Tile_box_sample small(4);
  for(int i = 0; i < 10; ++i)
  {
    small.add(i, 0, 0);
    small.add(HUGE_VAL, 0, 0);  // skipped, not counted
  }
  CHECK(small.stride() == 4);
  CHECK(small.coordinates() == std::vector<double>{0, 0, 0, 4, 0, 0, 8, 0, 0});

  // a point with a non-finite coordinate is at no distance from a core, nobody's own point, in
  // no range (an outer tile's infinite side included)
  const PSC::Tile unit(CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 1);
  CHECK(std::isnan(unit.distance_to_core(nan_value, 0.5, 0.5)));
  CHECK(unit.distance_to_core(-2, 0.5, 0.5) == 2);
  const PSC::Tile outer(CGAL::Bbox_3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, 0, 0, 0), 1);
  CHECK(std::isnan(outer.distance_to_core(-HUGE_VAL, -1, -1)));
  CHECK(std::isnan(outer.distance_to_core(HUGE_VAL, -1, -1)));
  CHECK_FALSE(outer.owns(-HUGE_VAL, -1, -1));
  CHECK(outer.owns(-1e308, -1, -1));
  CHECK(std::isinf(PSC::halo_of_range(0.5, 10, 10)));
  CHECK(PSC::halo_of_range(0.5, 9, 10) == 0.5);

  // a range: the finite points within the halo, the nearest left out, the halo to estimate with
  // and to retry with
  PSC::Tile_range range(outer);
  CHECK(range.take(-5, -5, -5));
  CHECK_FALSE(range.take(-HUGE_VAL, -1, -1));
  CHECK(range.take(0.5, -1, -1));
  CHECK_FALSE(range.take(nan_value, -1, -1));
  CHECK_FALSE(range.take(3, -1, -1));
  CHECK_FALSE(range.take(1.5, -1, -1));
  CHECK(range.finite_taken() == 2);
  CHECK(range.nearest_left_out() == 1.5);
  CHECK(range.halo(3) == 1);
  CHECK(std::isinf(range.halo(2)));
  CHECK(range.retry_halo(PSC::Halo_too_small(1.2, 1)) == 1.5);
  CHECK(range.retry_halo(PSC::Halo_too_small(4, 1)) == 4);
  range.skip_beyond(1.25);  // (points of a block not read)
  CHECK(range.retry_halo(PSC::Halo_too_small(1.2, 1)) == 1.25);
}

TEST_CASE("Tiles: the halo rule (halo_for_radius, halo_guess_for_count, next_halo) gives the whole run by count",
          "[aso][tile]")
{
  CHECK(PSC::halo_for_radius(0.25) == 0.5);
  // a unit grid of 60 x 60 points: k points fill a disk of radius sqrt(k / pi)
  std::vector<Oriented_point> grid;
  for(int i = 0; i < 60; ++i)
    for(int j = 0; j < 60; ++j)
      grid.emplace_back(Point(i, j, 0.01 * std::sin(0.3 * i) * std::cos(0.2 * j)), Vector(0, 0, 1));
  const CGAL::Bbox_3 box(0, 0, -0.01, 59, 59, 0.01);
  const double guess = PSC::halo_guess_for_count(box, grid.size(), 40);
  CHECK(guess == Approx(2 * std::sqrt(59.0 * 59.0 * 40.0 / (M_PI * 3600.0))).epsilon(1e-14));
  CHECK(guess == Approx(2 * std::sqrt(40.0 / M_PI)).epsilon(0.04));
  // an area beyond the largest double: computed from the halved extents, finite
  const double huge = PSC::halo_guess_for_count(CGAL::Bbox_3(-1e300, -1e300, 0, 1e300, 1e300, 0), 10, 40);
  CHECK(huge == Approx(2 * 2e300 * std::sqrt(40.0 / (M_PI * 10.0))).epsilon(1e-12));
  CHECK(PSC::next_halo(5, 2) == 5);
  CHECK(PSC::next_halo(1.5, 2) == 2);
  CHECK(PSC::next_halo(nan_value, 2) == 2);

  // a tile started with a quarter of the guess grows by next_halo until exact: the whole run's bits
  auto run = [](const std::vector<Oriented_point>& pts, const PSC::Tile& t) {
    return CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
      pts, PSC::parameters::neighbor_count(40, PSC::parameters::tile(t, maps())));
  };
  const auto whole = run(grid, PSC::Tile::whole_space());
  const CGAL::Bbox_3 core(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL, 20, 20, HUGE_VAL);
  double halo = guess / 4;
  int retries = 0;
  std::vector<Estimate> part;
  std::vector<std::size_t> origin;
  std::vector<Oriented_point> range;
  for(;;)
  {
    const PSC::Tile t(core, halo);
    range = tile_range(grid, t, origin);
    try
    {
      part = run(range, t);
      break;
    }
    catch(const PSC::Halo_too_small& e)
    {
      halo = PSC::next_halo(e.required_halo(), 2 * halo);
      ++retries;
      REQUIRE(retries < 10);
    }
  }
  CHECK(retries >= 1);
  const Own_points compared = compare_own(range, origin, PSC::Tile(core, halo), part, whole);
  CHECK(compared.own == 20 * 20);  // the core is half-open
  CHECK(compared.differ == 0);
}

TEST_CASE("aso_options: a variant's options as one value, overridden by the options given", "[aso][api]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  namespace P = PSC::parameters;
  auto run = [&](const auto& np) { return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, np); };
  auto same = [](const std::vector<Estimate>& a, const std::vector<Estimate>& b) {
    std::size_t differ = 0;
    for(std::size_t i = 0; i < a.size(); ++i)
      differ += !same_estimate(a[i], b[i]);
    return differ;
  };
  const auto robust = run(maps());
  const auto paper = run(P::aso_variant(CGAL::Aso_variant::PAPER, maps()));
  REQUIRE(same(robust, paper) > pts.size() / 2);  // the options matter on this cloud
  // the presets as values: the variants, bitwise, whatever aso_variant says
  CHECK(same(run(P::aso_options(PSC::aso_variant_options(CGAL::Aso_variant::ROBUST), maps())), robust) == 0);
  CHECK(same(run(P::aso_options(PSC::aso_variant_options(CGAL::Aso_variant::PAPER), maps())), paper) == 0);
  CHECK(same(run(P::aso_variant(CGAL::Aso_variant::PAPER,
                                P::aso_options(PSC::aso_variant_options(CGAL::Aso_variant::ROBUST), maps()))),
             robust) == 0);
  // one member changed: as the option given on its own
  PSC::Aso_variant_options uniform = PSC::aso_variant_options(CGAL::Aso_variant::ROBUST);
  uniform.sample_weights = CGAL::Sample_weights::UNIFORM;
  CHECK(same(run(P::aso_options(uniform, maps())), run(P::sample_weights(CGAL::Sample_weights::UNIFORM, maps()))) == 0);
  // an option given explicitly overrides the value's member
  CHECK(
    same(run(P::robust_orientation(true, P::aso_options(PSC::aso_variant_options(CGAL::Aso_variant::PAPER), maps()))),
         run(P::robust_orientation(true, P::aso_variant(CGAL::Aso_variant::PAPER, maps())))) == 0);
  PSC::Aso_variant_options constant = uniform;
  constant.weight_kernel = CGAL::Apss_weight_kernel::CONSTANT;
  CHECK_THROWS_AS(run(P::aso_options(constant, maps())), std::invalid_argument);
}

TEST_CASE("Algebraic_shape_operator_fit with named parameters: the cloud function's estimators at one point",
          "[aso][api][per_query]")
{
  const auto& pts = goursat_10k();
  const double r = 1.5;
  namespace P = PSC::parameters;
  const auto cloud_robust = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    pts, r, P::sample_weights(CGAL::Sample_weights::UNIFORM, maps()));  // the fit's weights: 1
  auto at = [&](auto&& fit) {
    for(const auto& p : pts)
      fit.add_neighbor(p.first, p.second);
    return fit.estimate();
  };
  std::size_t compared = 0;
  for(std::size_t i = 0; i < pts.size(); i += 500)
  {
    const Point& x = pts[i].first;
    typedef CGAL::Algebraic_shape_operator_fit<Kernel> Fit;
    const Estimate paper = at(Fit(x, r));
    CHECK(same_estimate(paper, at(Fit(x, r, P::aso_variant(CGAL::Aso_variant::PAPER)))));
    CHECK(
      same_estimate(at(Fit(x, r, CGAL::Aso_projection::AUTHORS_IMPLEMENTATION, CGAL::Apss_weight_kernel::SMOOTH_CUBIC)),
                    at(Fit(x, r,
                           P::aso_projection(CGAL::Aso_projection::AUTHORS_IMPLEMENTATION,
                                             P::weight_kernel(CGAL::Apss_weight_kernel::SMOOTH_CUBIC))))));
    const Estimate robust = at(Fit(x, r, P::aso_variant(CGAL::Aso_variant::ROBUST)));
    CHECK(same_estimate(robust, at(Fit(x, r, P::aso_options(PSC::aso_variant_options(CGAL::Aso_variant::ROBUST))))));
    CHECK_FALSE(same_estimate(robust, paper));
    // the cloud function's estimate at that point, to rounding (its sums run in another order)
    REQUIRE(robust.is_valid());
    CHECK(robust.mean_curvature == Approx(cloud_robust[i].mean_curvature).margin(1e-12));
    CHECK(robust.max_curvature == Approx(cloud_robust[i].max_curvature).margin(1e-12));
    ++compared;
  }
  CHECK(compared == 20);
  using Catch::Matchers::Contains;
  CHECK_THAT(invalid_argument_message([&] {
               CGAL::Algebraic_shape_operator_fit<Kernel> fit(pts[0].first, r, CGAL::Aso_projection::CORRECTED_NORMAL,
                                                              CGAL::Apss_weight_kernel::CONSTANT);
             }),
             Contains("Algebraic_shape_operator_fit") && Contains("weight_kernel"));
  CHECK_THROWS_AS(CGAL::Algebraic_shape_operator_fit<Kernel>(pts[0].first, r, P::position_fit_blend(2.0)),
                  std::invalid_argument);
}

// ---- The automatic scale (named parameter automatic_scale) ----

// A height field z = f(x, y) sampled on a grid of unit spacing, 2 half_side + 1 points a side,
// with Gaussian noise of deviation `sigma` on z and the exact normals of f.
std::vector<Oriented_point> noisy_height_field(int half_side, double sigma, double amplitude, double wavelength,
                                               unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<Oriented_point> pts;
  for(int i = -half_side; i <= half_side; ++i)
    for(int j = -half_side; j <= half_side; ++j)
    {
      const double x = i, y = j, w = 2 * M_PI / wavelength;
      const double z = amplitude * std::sin(w * x), dz = amplitude * w * std::cos(w * x);
      pts.emplace_back(Point(x, y, z + sigma * noise(rng)), Vector(-dz, 0, 1) / std::sqrt(1 + dz * dz));
    }
  return pts;
}

// H* at t of the wave z = A sin(2 pi t / L) (t = x or y): its graph's curvature across the
// crests, halved; positive where it bends away from the up normal.
double wave_mean_curvature(double t, double amplitude, double wavelength)
{
  const double w = 2 * M_PI / wavelength, d1 = amplitude * w * std::cos(w * t),
               d2 = -amplitude * w * w * std::sin(w * t);
  return -0.5 * d2 / std::pow(1 + d1 * d1, 1.5);
}

// The median chosen count and the mean |H - H*| over the points at least `margin` from the
// border, for a wave z = A sin(2 pi x / L).
std::pair<double, double> median_count_and_error(const std::vector<Oriented_point>& pts, const std::vector<Estimate>& e,
                                                 int half_side, double margin, double amplitude, double wavelength)
{
  std::vector<double> counts;
  double error = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const double x = std::round(pts[i].first.x()), y = pts[i].first.y();
    if(std::abs(x) > half_side - margin || std::abs(y) > half_side - margin || !e[i].is_valid())
      continue;
    counts.push_back(double(e[i].neighbor_count));
    error += std::abs(e[i].mean_curvature - wave_mean_curvature(x, amplitude, wavelength));
  }
  REQUIRE(counts.size() > 100);
  std::nth_element(counts.begin(), counts.begin() + counts.size() / 2, counts.end());
  return {counts[counts.size() / 2], error / double(counts.size())};
}

// The cloud with its normals estimated as the tool does without normals (a quadric of 40, or
// its automatic scale up to `largest`), oriented up.
std::vector<Oriented_point> with_estimated_normals(std::vector<Oriented_point> pts, std::size_t largest)
{
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    pts, PSC::parameters::neighbor_count(
           40, PSC::parameters::automatic_scale(largest, PSC::parameters::normal_orientation(
                                                           CGAL::Normal_orientation::along_vector(0, 0, 1), maps()))));
  return pts;
}

TEST_CASE("Automatic scale: the chosen count grows with the noise and shrinks with the curvature's variation",
          "[aso][automatic_scale]")
{
  const int half = 45;
  // as the tool runs a cloud without normals: normals and curvatures at the automatic scale,
  // against both at 40 neighbours
  auto run = [](const std::vector<Oriented_point>& pts, std::size_t largest) {
    const std::vector<Oriented_point> cloud = with_estimated_normals(pts, largest);
    return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      cloud, PSC::parameters::neighbor_count(
               40, PSC::parameters::automatic_scale(largest, PSC::parameters::position_fit_blend(0.5, maps()))));
  };
  // a gentle wave (wavelength 60 spacings, curvature up to 0.022): more noise, larger scales,
  // and a smaller error than at 40 neighbours
  double previous_count = 0;
  for(double sigma : {0.0, 0.1, 0.4})
  {
    const auto pts = noisy_height_field(half, sigma, 2.0, 60, 11);
    const auto chosen = median_count_and_error(pts, run(pts, 640), half, 16, 2.0, 60);
    const auto at_40 = median_count_and_error(pts, run(pts, 0), half, 16, 2.0, 60);
    measured("automatic scale, sigma " + std::to_string(sigma) + ": median count", chosen.first);
    measured("  mean |H - H*| automatic", chosen.second);
    measured("  mean |H - H*| at 40", at_40.second);
    CHECK(chosen.first >= previous_count);
    previous_count = chosen.first;
    if(sigma == 0)
    {
      CHECK(chosen.first < 60);                           // the smallest scale without noise
      CHECK(chosen.second <= 1.2 * at_40.second + 1e-6);  // and as accurate as k = 40
    }
    else
      CHECK(chosen.second < 0.2 * at_40.second);
  }
  CHECK(previous_count >= 320);
  // the same noise on a wave 4 times shorter and half as high (curvature 8 times larger,
  // varying 32 times faster): smaller scales, and more accurate than 40 neighbours (measured:
  // 6.24e-3 against 1.069e-2; 1.073e-2 while the estimate at a count kept for noise had the
  // position fit and the cubic kernel)
  const auto short_wave = noisy_height_field(half, 0.1, 1.0, 15, 11);
  const auto short_chosen = median_count_and_error(short_wave, run(short_wave, 640), half, 16, 1.0, 15);
  const auto short_40 = median_count_and_error(short_wave, run(short_wave, 0), half, 16, 1.0, 15);
  measured("automatic scale, short wave, sigma 0.1: median count", short_chosen.first);
  measured("  mean |H - H*| automatic", short_chosen.second);
  measured("  mean |H - H*| at 40", short_40.second);
  CHECK(short_chosen.first < 320);
  CHECK(short_chosen.second < 0.75 * short_40.second);
}

TEST_CASE(
  "Automatic scale: the noise told from two fits, unknown where the larger misses far more than the surface allows",
  "[aso][automatic_scale]")
{
  using PSC::internal::separated_noise;
  // radii 1 and 2: the surface's part of the residual variance grows 2^6 = 64 times
  CHECK(separated_noise(1.0, 1.0, 1.0, 2.0) == Approx(1.0));   // all noise
  CHECK(separated_noise(1.0, 1.0, 32.5, 2.0) == Approx(0.5));  // (64 - 32.5) / 63
  CHECK(separated_noise(1.0, 1.0, 500.0, 2.0) == 0);           // faster than r^6: no noise
  CHECK(std::isnan(separated_noise(1.0, 1.0, 520.0, 2.0)));    // beyond 8 x 64: unknown
  CHECK(std::isnan(separated_noise(1.0, 1.0, 1.0, 1.0001)));   // radii too close
}

TEST_CASE("Automatic scale: a rung of two noisy scan lines is passed over, not read as noise-free",
          "[aso][automatic_scale]")
{
  // 17 noisy lines of a wave across them (z = 4 sin(2 pi y / 120)), 10 units apart with points
  // 1 unit apart along them: at a line at the cloud's edge the first rung (40 points) holds that
  // line and the next; its quadric bends across them as their noise says, and the half of it
  // (one line and a few points) fits closer still, which read as no noise at all (before:
  // mean |H - H*| 0.040 on the edge lines, 7 times the largest curvature, 159 of 162 points
  // kept at 40 neighbours)
  const double across = 10, amplitude = 4, w = 2 * M_PI / 120;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<Oriented_point> pts;
  for(int j = -8; j <= 8; ++j)
    for(int i = -60; i <= 60; ++i)
    {
      const double y = across * j, dz = amplitude * w * std::cos(w * y);
      pts.emplace_back(Point(i, y, amplitude * std::sin(w * y) + 0.3 * noise(rng)),
                       Vector(0, -dz, 1) / std::sqrt(1 + dz * dz));
    }
  const std::vector<Oriented_point> cloud = with_estimated_normals(pts, 640);
  const auto e = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    cloud, PSC::parameters::neighbor_count(
             40, PSC::parameters::automatic_scale(640, PSC::parameters::position_fit_blend(0.5, maps()))));
  const double largest = 0.5 * amplitude * w * w;  // the largest |H*|, 0.0055
  double edge_error = 0, inside_error = 0;
  std::size_t edge = 0, inside = 0, edge_at_40 = 0;
  for(std::size_t k = 0; k < pts.size(); ++k)
  {
    const double x = pts[k].first.x(), y = pts[k].first.y();
    if(std::abs(x) > 40)
      continue;  // (away from the lines' ends)
    REQUIRE(e[k].is_valid());
    const double error = std::abs(e[k].mean_curvature - wave_mean_curvature(y, amplitude, 120));
    if(std::abs(y) == 8 * across)
    {
      ++edge;
      edge_error += error;
      edge_at_40 += e[k].neighbor_count == 40 ? 1 : 0;
    }
    else if(std::abs(y) < 7 * across)
    {
      ++inside;
      inside_error += error;
    }
  }
  REQUIRE(edge == 162);
  measured("two scan lines at the edge: mean |H - H*|", edge_error / double(edge));
  measured("  inside", inside_error / double(inside));
  CHECK(edge_at_40 == 0);
  // (measured: 0.0052; 0.0044 to 0.0058 over the noise's seeds 1 to 12, and 0.030 to 0.040
  // before)
  CHECK(edge_error / double(edge) < 2 * largest);
  CHECK(inside_error / double(inside) < 0.15 * largest);  // (measured: 0.00031; 0.00044 with the blend)
}

TEST_CASE("Automatic scale: where the rule climbed for noise, no position fit and the quartic kernel",
          "[aso][automatic_scale]")
{
  // With estimated normals, a count kept above the smallest because noise dominates has its
  // normals from large neighbourhoods, where the quadric of the positions is biased more than it
  // helps, and the narrower quartic kernel trades less bias for noise than the cubic: there the
  // estimate is the one without the position fit and with the quartic kernel (as if asked for),
  // elsewhere the blend and the kernel of the variant.
  const int half = 30;
  for(double sigma : {0.0, 0.4})
  {
    const std::vector<Oriented_point> cloud = with_estimated_normals(noisy_height_field(half, sigma, 2.0, 60, 7), 640);
    auto run = [&cloud](double blend) {
      return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
        cloud, PSC::parameters::neighbor_count(
                 40, PSC::parameters::automatic_scale(640, PSC::parameters::position_fit_blend(blend, maps()))));
    };
    const auto blended = run(0.5), alone = run(0.0);
    const auto quartic = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      cloud, PSC::parameters::neighbor_count(
               40, PSC::parameters::automatic_scale(
                     640, PSC::parameters::weight_kernel(CGAL::Apss_weight_kernel::SMOOTH_QUARTIC, maps()))));
    std::size_t climbed = 0, as_without_blend = 0, as_quartic = 0, smallest = 0, blend_shows = 0;
    for(std::size_t i = 0; i < cloud.size(); ++i)
    {
      REQUIRE(blended[i].is_valid());
      REQUIRE(alone[i].is_valid());
      REQUIRE(quartic[i].is_valid());
      REQUIRE(blended[i].neighbor_count == alone[i].neighbor_count);  // (the choice reads the rungs' quadrics)
      // (a count of 80 or more: a rung above the first; ties with the 40th can make the first
      // rung's count exceed 40 on a grid)
      if(blended[i].neighbor_count >= 80)
      {
        ++climbed;
        as_without_blend += same_estimate(blended[i], alone[i]) ? 1 : 0;
        as_quartic += same_estimate(blended[i], quartic[i]) ? 1 : 0;
      }
      else
      {
        ++smallest;
        blend_shows += same_estimate(blended[i], alone[i]) ? 0 : 1;
      }
    }
    measured("no blend, quartic kernel where climbed, sigma " + std::to_string(sigma) + ": points at 80 or more",
             double(climbed));
    measured("  points below 80 whose blend shows", double(blend_shows));
    if(sigma == 0)
    {
      // no noise: the smallest count, blended (all but one-sided neighbourhoods at the border)
      CHECK(smallest > 0.9 * double(cloud.size()));
      CHECK(blend_shows > 0.6 * double(smallest));
    }
    else
    {
      CHECK(climbed > 0.95 * double(cloud.size()));  // noise: larger counts, without the blend, quartic
      CHECK(as_without_blend == climbed);
      CHECK(as_quartic == climbed);
    }
  }
}

TEST_CASE("Automatic scale: over noisy airborne scan lines the sphere's H only where it agrees with the ASO",
          "[aso][automatic_scale]")
{
  // Airborne lines 5:1 over the wavy terrain (H* within +-0.166), range noise 0.3 times the
  // spacing, exact normals. Above the first rung the sphere's H replaces the ASO's where it lies
  // within 3 standard errors of the rung's quadric; over such lines it is the biased one (it
  // differs from the ASO's by 9 standard errors at the median), and it is now taken only where the
  // two also agree within 4 (automatic_scale_sphere_agreement). Mean |H - H*| (benchmark/
  // scan_experiments on 11,760 points of these lines: 0.0100 -> 0.0064).
  namespace scan = psc_test::scan;
  const scan::Height_field terrain = scan::wavy_terrain();
  const std::vector<scan::Sample> samples = scan::with_range_noise(
    0.3, [&](const scan::Noise& noise) { return scan::airborne_lines(terrain, 6, 0.1, 0.5, noise); });
  const std::vector<Oriented_point> cloud = scan::with_true_normals(samples);
  const auto e = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    cloud, PSC::parameters::neighbor_count(
             40, PSC::parameters::automatic_scale(640, PSC::parameters::position_fit_blend(0.5, maps()))));
  const auto sphere =
    CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(cloud, PSC::parameters::neighbor_count(640, maps()));
  double error = 0, sphere_error = 0;
  std::size_t n = 0, climbed = 0;
  for(std::size_t i = 0; i < samples.size(); ++i)
  {
    REQUIRE(e[i].is_valid());
    error += std::abs(e[i].mean_curvature - samples[i].truth.mean);
    if(sphere[i].is_valid())
      sphere_error += std::abs(sphere[i].mean_curvature - samples[i].truth.mean);
    climbed += e[i].neighbor_count >= 80 ? 1 : 0;
    ++n;
  }
  measured("noisy airborne lines, exact normals: points", double(n));
  measured("  at 80 neighbours or more", double(climbed));
  measured("  mean |H - H*|, the automatic scale", error / double(n));
  measured("  the APSS sphere at 640", sphere_error / double(n));
  CHECK(climbed > 0.9 * double(n));
  // (measured on these 3,000 points: 0.00946, against 0.01094 when the sphere was taken wherever
  // it agreed with the quadric; the sphere alone 0.0214)
  CHECK(error / double(n) < 0.0102);
  CHECK(error / double(n) < 0.5 * sphere_error / double(n));
}

TEST_CASE("Automatic scale: a first rung is trusted only where it can tell the curvature (noisy multi-beam rings)",
          "[aso][automatic_scale]")
{
  // A car-roof multi-beam scanner standing still over the wavy terrain (H* within +-0.166), range
  // noise 0.3 times the spacing, exact normals: first rungs of one or two rings were kept where
  // the first pass's tests read no noise, or where their interval missed the second rung's,
  // although their own standard error of H was beyond the bound (SE r > 0.1): H errors of 5 to 20
  // times the surface's curvature. Measured on these 43,859 points (benchmark/scan_experiments
  // `rings`, column auto-given): mean |H - H*| 0.0615 -> 0.0164, errors above 1: 891 -> 146.
  namespace scan = psc_test::scan;
  const scan::Height_field terrain = scan::wavy_terrain();
  const std::vector<scan::Sample> samples = scan::with_range_noise(0.3, [&](const scan::Noise& noise) {
    return scan::multibeam_rings(terrain, 12, 32, -0.535, -0.023, 0.0035, noise);
  });
  const std::vector<Oriented_point> cloud = scan::with_true_normals(samples);
  const auto e = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    cloud, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(640, maps())));
  double error = 0;
  std::size_t beyond = 0;
  for(std::size_t i = 0; i < samples.size(); ++i)
  {
    REQUIRE(e[i].is_valid());
    const double d = std::abs(e[i].mean_curvature - samples[i].truth.mean);
    error += d;
    beyond += d > 1 ? 1 : 0;
  }
  measured("noisy multi-beam rings, exact normals: mean |H - H*|", error / double(samples.size()));
  measured("  errors above 1", double(beyond));
  CHECK(error / double(samples.size()) < 0.025);
  CHECK(beyond < 300);
}

TEST_CASE("Automatic scale: the quadric's H where the ASO's disagrees with it by far (a mobile scan's edge)",
          "[aso][automatic_scale]")
{
  // A mobile profiler over the wavy terrain (H* within +-0.166), range noise 0.3 times the
  // spacing, normals estimated as the tool does without normals. At the first and last profiles
  // (one-sided neighbourhoods, where the estimated normals bend) the ASO reads H = -0.57 where
  // the truth is 0.003; the rung's quadric of positions does not. Where the ASO's H lies
  // more than automatic_scale_quadric_agreement (30) standard errors from the quadric's, the
  // curvatures are the quadric's (benchmark/scan_experiments `mobile`, 122,760 points: 8.64e-3 ->
  // 3.26e-3; the other eleven patterns within 1%).
  namespace scan = psc_test::scan;
  const scan::Height_field terrain = scan::wavy_terrain();
  const double half_width = 2;
  const std::vector<scan::Sample> samples = scan::with_range_noise(
    0.3, [&](const scan::Noise& noise) { return scan::mobile_profiles(terrain, half_width, 0.1, 0.0035, noise); });
  const std::vector<Oriented_point> cloud = with_estimated_normals(scan::with_true_normals(samples), 640);
  const auto e = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    cloud, PSC::parameters::neighbor_count(
             40, PSC::parameters::automatic_scale(640, PSC::parameters::position_fit_blend(0.5, maps()))));
  double error = 0, edge_error = 0, worst_edge = 0, max_error = 0;
  std::size_t n = 0, edge = 0;
  for(std::size_t i = 0; i < samples.size(); ++i)
  {
    REQUIRE(e[i].is_valid());
    const double d = std::abs(e[i].mean_curvature - samples[i].truth.mean);
    error += d;
    ++n;
    if(half_width - std::abs(samples[i].p.y()) < 0.3)
    {
      edge_error += d;
      worst_edge = std::max(worst_edge, d);
      max_error = std::max(max_error, e[i].mean_curvature_error);
      ++edge;
    }
  }
  measured("noisy mobile profiles, estimated normals: points", double(n));
  measured("  within 0.3 of the first or last profile", double(edge));
  measured("  mean |H - H*|", error / double(n));
  measured("  mean |H - H*| within 0.3 of the edge", edge_error / double(edge));
  measured("  largest |H - H*| there", worst_edge);
  measured("  largest standard error there", max_error);
  REQUIRE(edge > 100);
  // A point of the last-but-one profile whose 40 nearest are one line and whose 80 nearest
  // cannot be fitted (the line and a few points off it) climbs on to 640 (H 0.123, H* 0.104):
  // before, the line's rung was taken, valid with H 0.26 and a standard error of 83.
  CHECK(max_error < 1);
  // A point at the very edge whose 40 nearest are two lines that a quadric nearly interpolates
  // (residuals too small for the error's bound) and whose 80 nearest are a line rung: kept at
  // 40, it was off by 2.8 (H* 0.03) with a standard error of 0.73; with the line rung's
  // residuals for the noise, the 40 are passed over too and the point climbs (largest error
  // there 0.24).
  CHECK(worst_edge < 0.5);
  // (measured on these 19,500 points: 0.0203 within 0.3 of the edge and 0.0061 in all, against
  // 0.108 and 0.0194 without the quadric's H)
  CHECK(edge_error / double(edge) < 0.035);
  CHECK(error / double(n) < 0.0085);
}

TEST_CASE("Automatic scale: the quartic kernel where a count is kept without noise over evenly spread neighbours",
          "[aso][automatic_scale]")
{
  // Clean data keep the smallest count; where its neighbours spread evenly around the point the
  // ASO takes the narrower quartic kernel there too (less bias, and no noise for it to pass on),
  // where they lie along scan lines far apart the cubic (the narrower kernel sees fewer lines).
  // A wave z = 2 sin(2 pi x / 30) on a jittered unit grid, exact normals.
  const int half = 30;
  const double amplitude = 2, wavelength = 30, w = 2 * M_PI / wavelength;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Oriented_point> cloud;
  for(int i = -half; i <= half; ++i)
    for(int j = -half; j <= half; ++j)
    {
      const double x = i + jitter(rng), y = j + jitter(rng), dz = amplitude * w * std::cos(w * x);
      cloud.emplace_back(Point(x, y, amplitude * std::sin(w * x)), Vector(-dz, 0, 1) / std::sqrt(1 + dz * dz));
    }
  const auto automatic = [&cloud](const CGAL::Apss_weight_kernel* kernel) {
    const auto np = PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(640, maps()));
    return kernel
             ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, PSC::parameters::weight_kernel(*kernel, np))
             : CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, np);
  };
  const CGAL::Apss_weight_kernel quartic_kernel = CGAL::Apss_weight_kernel::SMOOTH_QUARTIC;
  const auto chosen = automatic(nullptr), quartic = automatic(&quartic_kernel);
  const auto fixed =
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, PSC::parameters::neighbor_count(40, maps()));
  std::size_t inside = 0, kept = 0, as_quartic = 0, as_fixed = 0;
  double error = 0, fixed_error = 0;
  for(std::size_t k = 0; k < cloud.size(); ++k)
  {
    const double x = cloud[k].first.x(), y = cloud[k].first.y();
    if(std::abs(x) > half - 6 || std::abs(y) > half - 6)
      continue;  // (one-sided neighbourhoods at the border)
    ++inside;
    REQUIRE(chosen[k].is_valid());
    REQUIRE(fixed[k].is_valid());
    if(chosen[k].neighbor_count >= 80)
      continue;
    ++kept;
    as_quartic += same_estimate(chosen[k], quartic[k]) ? 1 : 0;
    as_fixed += same_estimate(chosen[k], fixed[k]) ? 1 : 0;
    const double truth = wave_mean_curvature(x, amplitude, wavelength);
    error += std::abs(chosen[k].mean_curvature - truth);
    fixed_error += std::abs(fixed[k].mean_curvature - truth);
  }
  measured("evenly spread, clean: points kept at the smallest count", double(kept));
  measured("  mean |H - H*| there, automatic (quartic)", error / double(kept));
  measured("  the same, fixed count 40 (cubic)", fixed_error / double(kept));
  CHECK(kept > 0.95 * double(inside));
  CHECK(as_quartic > 0.98 * double(kept));  // (measured: all of them)
  CHECK(as_fixed < 0.01 * double(kept));
  CHECK(error < 0.9 * fixed_error);  // (measured: 2.53e-4 against 3.17e-4; the largest |H*| 0.044)

  // Rows 8 apart with points 1 apart along them (the same wave across the rows): the 40 nearest
  // hold the query's row and the next ones near the kernel's rim, the spread is uneven, and the
  // points kept at the smallest count keep the cubic (the fixed count's estimate; the quartic's
  // differs by up to 2.8e-3). (Most points pass over that rung as one line: measured 275 kept of
  // 990.)
  std::vector<Oriented_point> rows;
  for(int i = -60; i <= 60; ++i)
    for(int j = -8; j <= 8; ++j)
    {
      const double x = i + jitter(rng), y = 8.0 * j, dz = amplitude * w * std::cos(w * x);
      rows.emplace_back(Point(x, y, amplitude * std::sin(w * x)), Vector(-dz, 0, 1) / std::sqrt(1 + dz * dz));
    }
  const auto rows_chosen = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    rows, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(640, maps())));
  const auto rows_fixed =
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(rows, PSC::parameters::neighbor_count(40, maps()));
  std::size_t rows_inside = 0, rows_kept = 0, rows_as_fixed = 0;
  for(std::size_t k = 0; k < rows.size(); ++k)
  {
    if(std::abs(rows[k].first.x()) > 45 || std::abs(rows[k].first.y()) > 40)
      continue;
    ++rows_inside;
    if(!rows_chosen[k].is_valid() || rows_chosen[k].neighbor_count >= 80)
      continue;
    ++rows_kept;
    // (to rounding: the automatic scale evaluates a copy of the rung's neighbourhood)
    rows_as_fixed += std::abs(rows_chosen[k].mean_curvature - rows_fixed[k].mean_curvature) < 1e-12 ? 1 : 0;
  }
  measured("rows 8 apart: points kept at the smallest count", double(rows_kept));
  measured("  of them equal to the fixed count (cubic)", double(rows_as_fixed));
  CHECK(rows_kept > 0.2 * double(rows_inside));
  CHECK(rows_as_fixed > 0.98 * double(rows_kept));

  // The indicator: the axis ratio of the tangential spread, weighted as the quartic's gradient
  // moments, on a disc of a grid (even) and on three lines 0.85 r apart (uneven: one through the
  // query, two near the rim).
  std::vector<double> qx, qy, qz;
  const auto neighborhood = [&qx, &qy, &qz](double nz) {
    PSC::internal::Neighborhood nb;
    nb.size = qx.size();
    nb.qx = qx.data();
    nb.qy = qy.data();
    nb.qz = qz.data();
    nb.query_normal[2] = nz;
    return nb;
  };
  for(int i = -10; i <= 10; ++i)
    for(int j = -10; j <= 10; ++j)
      if(i * i + j * j < 100)
      {
        qx.push_back(0.1 * i);
        qy.push_back(0.1 * j);
        qz.push_back(0);
      }
  CHECK(PSC::internal::tangential_axis_ratio<4>(neighborhood(1)) == Approx(1).epsilon(1e-9));
  CHECK(PSC::internal::spreads_evenly(neighborhood(1)));
  CHECK(PSC::internal::tangential_axis_ratio<4>(neighborhood(0)) == 0);  // (no normal)
  qx.clear();
  qy.clear();
  qz.clear();
  for(int line = -1; line <= 1; ++line)
    for(int i = -19; i <= 19; ++i)
    {
      qx.push_back(0.05 * i);
      qy.push_back(0.85 * line);
      qz.push_back(0);
    }
  const double lines = PSC::internal::tangential_axis_ratio<4>(neighborhood(1));
  measured("three lines 0.85 r apart: axis ratio", lines);
  CHECK(lines < 0.5);
  CHECK_FALSE(PSC::internal::spreads_evenly(neighborhood(1)));
}

TEST_CASE("ASO: the position fit is blended in inside a patch, left out where the neighbourhood is one-sided", "[aso]")
{
  // a noisy wave on a grid (41 x 41 points) with its exact normals: the quadric of the positions
  // differs from the ASO everywhere, and at the grid's edge it extrapolates from one side
  const int half = 20;
  const auto pts = noisy_height_field(half, 0.1, 2.0, 20, 5);
  const auto with = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, PSC::parameters::neighbor_count(40, PSC::parameters::position_fit_blend(0.5, maps())));
  const auto without =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(40, maps()));
  std::size_t edge = 0, edge_same = 0, inside = 0, inside_same = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    REQUIRE(with[i].is_valid());
    REQUIRE(without[i].is_valid());
    const double x = std::abs(pts[i].first.x()), y = std::abs(pts[i].first.y());
    const bool same =
      with[i].mean_curvature == without[i].mean_curvature && with[i].max_curvature == without[i].max_curvature;
    if(x == half || y == half)
    {
      ++edge;
      edge_same += same ? 1 : 0;
    }
    else if(x <= half - 6 && y <= half - 6)
    {
      ++inside;
      inside_same += same ? 1 : 0;
    }
  }
  CHECK(edge == 160);
  CHECK(edge_same == edge);  // one-sided: the ASO alone
  CHECK(inside == 841);
  CHECK(inside_same == 0);  // blended
}

TEST_CASE("Automatic scale: exact on a plane and on a sphere, the count and error fields set", "[aso][automatic_scale]")
{
  const auto auto_np = PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(320, maps()));
  const auto plane = noisy_height_field(20, 0.0, 0.0, 60, 1);
  for(const Estimate& e : CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(plane, auto_np))
  {
    REQUIRE(e.is_valid());
    CHECK(std::abs(e.mean_curvature) < 1e-9);
    CHECK(std::abs(e.gaussian_curvature) < 1e-9);
    CHECK(e.neighbor_count >= 40);
    CHECK(e.mean_curvature_error >= 0);
  }
  const double R = 2;
  const auto ball = sphere(20000, R);
  std::size_t larger = 0;
  for(const Estimate& e : CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ball, auto_np))
  {
    REQUIRE(e.is_valid());
    CHECK(e.mean_curvature == Approx(1 / R).epsilon(1e-6));
    CHECK(e.min_curvature == Approx(1 / R).epsilon(1e-4));
    CHECK(e.max_curvature == Approx(1 / R).epsilon(1e-4));
    CHECK(e.neighbor_count >= 40);
    CHECK(e.neighbor_count <= 330);
    larger += e.neighbor_count > 60 ? 1 : 0;
  }
  measured("sphere: points at a count above 60", double(larger));
  // without automatic_scale the field is NaN
  CHECK(
    std::isnan(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ball, PSC::parameters::neighbor_count(40, maps()))[0]
                 .mean_curvature_error));
}

TEST_CASE("Automatic scale: the passes' progress in proportion to their time", "[automatic_scale][callback]")
{
  typedef PSC::internal::Automatic_scale_progress Progress;
  double now = 0;
  std::vector<double> seen;
  const auto record = [&seen](double f) {
    seen.push_back(f);
    return true;
  };
  const auto clock = [&now]() { return now; };
  const double c = Progress::climber_cost;
  // q: the share of the points visited that the pass sent on, from a prior of a few points
  const auto q = [](double sent, double visited) {
    return (sent + Progress::prior_sent_on * Progress::prior_points) / (visited + Progress::prior_points);
  };
  Progress progress(record, clock);
  // the first pass (1000 points, another pass after it): its fraction over 1 + q c (its time is
  // not known yet)
  const auto first = progress.start_pass(1000, false);
  REQUIRE(first.points);
  for(int i = 0; i < 100; ++i)
    ++progress.sent_on();
  now = 4;
  first.points(0.4);
  CHECK(seen.back() == Approx(0.4 / (1 + q(100, 400) * c)));
  for(int i = 0; i < 150; ++i)
    ++progress.sent_on();
  now = 10;
  first.points(1.0);
  const double first_share = 1 / (1 + q(250, 1000) * c);
  CHECK(seen.back() == Approx(first_share));
  // the last pass over the 250 points sent on: at its start, its prior (c points of the first
  // pass each: 250 c 10 / 1000 s)
  const auto second = progress.start_pass(250, true);
  second.points(0.0);
  CHECK(seen.back() == Approx(std::max(first_share, 10 / (10 + 250 * c * 10 / 1000.0))));
  // from 5% of it on, its own rate: half of it in 20 s, the whole in 40 s
  now = 30;
  second.points(0.5);
  CHECK(seen.back() == Approx(30.0 / 50));
  // never less than reported: slower than its rate said (half of it in 50 s)
  now = 60;
  CHECK(progress.fraction(0.5) == Approx(60.0 / 110));
  second.points(0.5);
  CHECK(seen.back() == Approx(30.0 / 50));
  now = 70;
  second.points(1.0);
  CHECK(seen.back() == 1.0);
  CHECK(std::is_sorted(seen.begin(), seen.end()));

  // an area pass first (2 s): the points' prior is 1 / area_cost of it
  seen.clear();
  now = 0;
  Progress with_areas(record, clock);
  const auto pass = with_areas.start_pass(1000, false);
  now = 1;
  pass.areas(0.5);
  CHECK(seen.back() == Approx(1.0 / (2 * (1 + (1 + q(0, 0) * c) / Progress::area_cost))));
  now = 2;
  pass.areas(1.0);
  now = 3;  // its first report after 1 s of set-up (no point sent on yet: the prior share)
  pass.points(0.0);
  const double points_prior = 2 / Progress::area_cost;
  CHECK(seen.back() == Approx(3 / (2 + (1 + points_prior) * (1 + q(0, 0) * c))));
  now = 12;  // a fifth of the points in 9 s more, none sent on: 45 s a whole pass from there
  pass.points(0.2);
  CHECK(seen.back() == Approx(12 / (2 + (10 + 0.8 * 45) * (1 + q(0, 200) * c))));

  // a first pass that sends nothing on is the whole; without a callback, nothing to report
  Progress alone(record);
  alone.start_pass(10, false).points(0.5);
  CHECK(seen.back() == Approx(0.5 / (1 + q(0, 5) * c)));
  CHECK(alone.finish());
  CHECK(seen.back() == 1.0);
  Progress silent{std::function<bool(double)>()};
  const auto none = silent.start_pass(10, false);
  CHECK_FALSE(none.points);
  CHECK_FALSE(none.areas);
  CHECK(silent.finish());
}

TEST_CASE("Automatic scale: sequential == parallel, tiles == whole, normals too", "[aso][automatic_scale][tile]")
{
  const auto pts = noisy_height_field(40, 0.3, 2.0, 60, 5);
  const auto np = PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(320, maps()));
  const auto par = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, np);
  const auto seq = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, np);
  std::size_t differ = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    differ += !same_estimate(par[i], seq[i]) || bits(par[i].mean_curvature_error) != bits(seq[i].mean_curvature_error);
  CHECK(differ == 0);
  // passes of growing neighbourhoods (each only where the previous one's top rung was kept):
  // progress non-decreasing, ending at 1; cancelled in any pass, the points without their
  // final estimate are NOT_COMPUTED, the others those of the whole run
  std::vector<double> progress;
  const std::function<bool(double)> record = [&progress](double f) {
    progress.push_back(f);
    return true;
  };
  CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    pts, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(320, maps().callback(record))));
  REQUIRE(progress.size() > 10);
  CHECK(std::is_sorted(progress.begin(), progress.end()));
  CHECK(progress.back() == 1.0);
  for(double at : {0.3, 0.6, 0.8})
  {
    INFO("cancelled at " << at);
    const std::function<bool(double)> stop = [at](double f) { return f < at; };
    const auto cancelled = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      pts, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(320, maps().callback(stop))));
    std::size_t not_computed = 0, differ_cancelled = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      if(cancelled[i].status == Status::NOT_COMPUTED)
        ++not_computed;
      else
        differ_cancelled += same_estimate(cancelled[i], par[i]) ? 0 : 1;
    CHECK(differ_cancelled == 0);
    CHECK(not_computed > 0);
  }
  // tiles with the halo the largest scale needs (retried while too small)
  const PSC::Tile_grid tiles(CGAL::Bbox_3(-40, -40, -10, 40, 40, 10), {{2, 2, 1}});
  std::size_t owned = 0;
  differ = 0;
  for(std::size_t t = 0; t < tiles.size(); ++t)
    for(double halo = 4;; halo *= 2)
    {
      const PSC::Tile tile = tiles.tile(t, halo);
      std::vector<std::size_t> origin;
      const auto range = tile_range(pts, tile, origin);
      try
      {
        const auto e = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
          range, PSC::parameters::neighbor_count(
                   40, PSC::parameters::automatic_scale(320, PSC::parameters::tile(tile, maps()))));
        const Own_points compared = compare_own(range, origin, tile, e, par);
        owned += compared.own;
        differ += compared.differ;
        break;
      }
      catch(const PSC::Halo_too_small&)
      {
        REQUIRE(halo < 100);
      }
    }
  CHECK(owned == pts.size());
  CHECK(differ == 0);
  // normals: the chosen quadric's, the same in both modes
  std::vector<Oriented_point> a = pts, b = pts;
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    a, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(320, maps())));
  CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(
    b, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(320, maps())));
  std::size_t up = 0;
  differ = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    differ += bits(a[i].second.x()) != bits(b[i].second.x()) || bits(a[i].second.z()) != bits(b[i].second.z());
    up += line_angle_degrees(a[i].second, pts[i].second) < 5 ? 1 : 0;
  }
  CHECK(differ == 0);
  CHECK(up >= 0.99 * double(a.size()));
}

// An estimator of the automatic scale's branch test: the same estimate at every neighbourhood.
struct Fixed_estimator : PSC::internal::Estimator_base
{
  PSC::internal::Local_estimate e;
  PSC::internal::Local_estimate operator()(const PSC::internal::Neighborhood&) const { return e; }
};

TEST_CASE("Automatic scale: the mean curvature at a rung above the first, branch by branch", "[automatic_scale]")
{
  // Automatic_scale_estimator::at_choice() with fixed estimates, on the cap z = -(x^2 + 2 y^2) / 2
  // (radius 1, normal +z: principal curvatures 1 along x and 2 along y, H = 1.5). The rung's
  // quadric says H = 1.5 with a standard error of 0.01 (radius 1).
  namespace I = PSC::internal;
  std::vector<double> qx, qy, qz, up, one;
  for(int i = -6; i <= 6; ++i)
    for(int j = -6; j <= 6; ++j)
    {
      const double x = i / 7.0, y = j / 7.0;
      if(x * x + y * y >= 1)
        continue;
      qx.push_back(x);
      qy.push_back(y);
      qz.push_back(-0.5 * (x * x + 2 * y * y));
      up.push_back(0);
      one.push_back(1);
    }
  I::Neighborhood nb;
  nb.size = qx.size();
  nb.qx = qx.data();
  nb.qy = qy.data();
  nb.qz = qz.data();
  nb.nx = nb.ny = up.data();
  nb.nz = one.data();
  nb.query_normal[2] = 1;
  I::Scale_choice c;
  c.found = c.noise_climb = true;
  c.rung = 2;
  c.count = c.k = 160;
  c.radius = 1;
  c.mean = 1.5;
  c.mean_error = 0.01;
  // the ASO's estimate (k_max - k_min 0.4) with its normal along +z (`normal_z` 1) or -z, the sphere's H
  const auto estimate = [&](double aso, double sphere, double coherence, const I::Scale_choice& choice,
                            double normal_z = 1) {
    I::Scale_estimators<Fixed_estimator> estimators;
    Fixed_estimator& a = estimators.at_noise_scale;
    a.e.status = CGAL::Curvature_estimate_status::VALID;
    a.e.normal[0] = a.e.normal[1] = 0;
    a.e.normal[2] = normal_z;
    a.e.mean = aso;
    a.e.k_min = aso - 0.2;
    a.e.k_max = aso + 0.2;
    a.e.normal_coherence = coherence;
    estimators.estimator = estimators.where_even = a;
    Fixed_estimator s;
    s.e = a.e;
    s.e.mean = sphere;
    I::Scale_ladder ladder;
    const I::Automatic_scale_estimator<Fixed_estimator, Fixed_estimator> automatic(estimators, s, ladder);
    return automatic.at_choice(choice, nb);
  };
  // the sphere where it agrees with the quadric (3 standard errors) and the ASO (4)
  I::Local_estimate e = estimate(1.51, 1.48, 0.99, c);
  CHECK(e.mean == 1.48);
  CHECK(e.k_max - e.k_min == Approx(0.4));
  CHECK(e.mean_error == 0.01);
  CHECK(e.neighbor_count == 160);
  // the ASO where the sphere disagrees with it by more than 4 and the ASO is well told
  CHECK(estimate(1.53, 1.48, 0.99, c).mean == 1.53);
  // the sphere again where the ASO's normals disagree (coherence below 0.95, or not computed)...
  CHECK(estimate(1.53, 1.48, 0.9, c).mean == 1.48);
  CHECK(estimate(1.53, 1.48, std::numeric_limits<double>::quiet_NaN(), c).mean == 1.48);
  // ...or its standard error times the radius exceeds 0.05
  I::Scale_choice noisy = c;
  noisy.mean_error = 0.06;
  CHECK(estimate(1.75, 1.4, 0.99, noisy).mean == 1.4);
  CHECK(estimate(1.75, 1.4, 0.99, c).mean == 1.75);  // (0.01: the ASO)
  // the ASO where the sphere is more than 3 from the quadric and the ASO within 30
  e = estimate(1.7, 1.0, 0.99, c);
  CHECK(e.mean == 1.7);
  CHECK(e.k_max - e.k_min == Approx(0.4));
  // the quadric where the ASO lies more than 30 from it: its H, its principal curvatures and
  // directions, the ASO's normal
  e = estimate(2.0, 1.0, 0.99, c);
  REQUIRE(e.status == CGAL::Curvature_estimate_status::VALID);
  CHECK(e.mean == 1.5);
  CHECK(e.k_min == Approx(1.0).margin(1e-9));
  CHECK(e.k_max == Approx(2.0).margin(1e-9));
  CHECK(e.gaussian == Approx(2.0).margin(1e-9));
  CHECK(std::abs(e.d_max[1]) == Approx(1.0).margin(1e-9));
  CHECK(std::abs(e.d_min[0]) == Approx(1.0).margin(1e-9));
  CHECK(e.normal[2] == 1);
  CHECK(e.mean_error == 0.01);
  // the ASO's normal against the point's (its neighbours' side): the quadric compared on that side
  CHECK(estimate(-1.55, 0.0, 0.99, c, -1).mean == -1.55);
  e = estimate(-1.0, 0.0, 0.99, c, -1);
  CHECK(e.mean == -1.5);
  CHECK(e.k_min == Approx(-2.0).margin(1e-9));
  CHECK(e.k_max == Approx(-1.0).margin(1e-9));
  // the sphere, close to the quadric, before the quadric where the ASO is poorly told
  CHECK(estimate(2.0, 1.49, 0.9, c).mean == 1.49);
  // not where the rung was reached past line rungs without noise: the ASO's
  I::Scale_choice lines = c;
  lines.noise_climb = false;
  CHECK(estimate(2.0, 1.0, 0.99, lines).mean == 2.0);
  // on the first rung the wrapped estimator's, whatever the others say
  I::Scale_choice first = c;
  first.rung = 0;
  first.noise_climb = false;
  CHECK(estimate(2.0, 1.0, 0.99, first).mean == 2.0);
}

// The first pass's tests (Scale_ladder::gate) on the 40 nearest of points of a terrain at random
// positions, one a unit of area: the share of the points they send on to larger neighbourhoods.
double first_pass_climbs(double noise, PSC::internal::Scale_ladder::Statistic statistic)
{
  namespace I = PSC::internal;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> side(0, 60);
  std::normal_distribution<double> gauss(0, 1);
  std::vector<std::array<double, 3>> p(3600);
  for(auto& q : p)
  {
    q[0] = side(random);
    q[1] = side(random);
    q[2] = 2 * std::sin(q[0] / 9) * std::cos(q[1] / 13) + 0.5 * std::sin(q[0] / 3 + q[1] / 5) + noise * gauss(random);
  }
  I::Scale_ladder ladder;
  ladder.smallest = ladder.largest = 40;
  ladder.gate = true;
  ladder.statistic = statistic;  // (the normals' test: one frame; the mean curvature's: separate fits)
  I::Ladder_scratch scratch;
  std::size_t queries = 0, climbs = 0;
  for(const auto& x : p)
  {
    if(std::abs(x[0] - 30) > 20 || std::abs(x[1] - 30) > 20)
      continue;
    // the driver's neighbourhood: the 40 nearest, scaled by knn_radius_factor times the 40th's distance
    std::vector<std::pair<double, std::size_t>> d;
    for(std::size_t j = 0; j < p.size(); ++j)
      d.emplace_back(std::pow(p[j][0] - x[0], 2) + std::pow(p[j][1] - x[1], 2) + std::pow(p[j][2] - x[2], 2), j);
    std::nth_element(d.begin(), d.begin() + 39, d.end());
    const double r = I::knn_radius_factor * std::sqrt(d[39].first);
    std::vector<double> qx, qy, qz, up(40, 0.0), one(40, 1.0);
    for(std::size_t i = 0; i < 40; ++i)
    {
      qx.push_back((p[d[i].second][0] - x[0]) / r);
      qy.push_back((p[d[i].second][1] - x[1]) / r);
      qz.push_back((p[d[i].second][2] - x[2]) / r);
    }
    I::Neighborhood nb;
    nb.size = 40;
    nb.qx = qx.data();
    nb.qy = qy.data();
    nb.qz = qz.data();
    nb.nx = nb.ny = up.data();
    nb.nz = one.data();
    nb.radius = r;
    nb.query_normal[2] = 1;
    const I::Scale_choice c = ladder.choose(nb, scratch);
    REQUIRE(c.found);
    ++queries;
    climbs += c.climb ? 1 : 0;
    CHECK(c.count == (c.climb ? 80u : 40u));
  }
  REQUIRE(queries > 1500);
  return double(climbs) / double(queries);
}

TEST_CASE("Automatic scale: the first tests keep most points of a clean random cloud, send noisy ones on",
          "[automatic_scale]")
{
  typedef PSC::internal::Scale_ladder::Statistic Statistic;
  // measured: 0.026 in a shared frame (the normals'), 0.060 with the separate fits (the
  // curvatures'), both with the cubic's test (without it 0.104 and 0.376)
  const double shared = first_pass_climbs(0, Statistic::NORMAL),
               separate = first_pass_climbs(0, Statistic::MEAN_CURVATURE);
  measured("first pass climbs, clean terrain: shared frame", shared);
  measured("  separate fits and the cubic", separate);
  CHECK(shared < 0.05);  // (0.104 without the cubic)
  CHECK(separate < 0.12);
  // noise of 0.3 times the spacing: every point goes on, with either test; the curvatures' at
  // 0.03 too (a noise whose standard error of H at 40 exceeds the bias there)
  for(Statistic fit : {Statistic::NORMAL, Statistic::MEAN_CURVATURE})
    CHECK(first_pass_climbs(0.3, fit) > 0.99);
  const double low_noise = first_pass_climbs(0.03, Statistic::MEAN_CURVATURE);
  measured("first pass climbs, noise 0.03 spacings: separate fits and the cubic", low_noise);
  CHECK(low_noise > 0.95);
}

TEST_CASE("Automatic scale: the first test's cubic: its residual variance, and none over scan lines",
          "[automatic_scale]")
{
  namespace I = PSC::internal;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> disc(-1, 1);
  std::normal_distribution<double> gauss(0, 1);
  const auto cubic = [](double u, double v) { return 0.1 + 0.2 * u - 0.3 * u * v + 0.4 * u * u * u - 0.2 * u * v * v; };
  for(double sigma : {0.0, 0.01})  // (many samples: the variance itself)
  {
    I::Cubic_height_fit fit;
    for(int i = 0; i < 4000; ++i)
    {
      const double u = disc(random), v = disc(random);
      fit.add(u, v, cubic(u, v) + sigma * gauss(random), 1 - 0.25 * (u * u + v * v));
    }
    double s2 = -1;
    REQUIRE(fit.residual_variance(I::gate_cubic_least_pivot, s2));
    measured("cubic residual variance over sigma^2 (sigma " + std::to_string(sigma) + ")",
             sigma > 0 ? s2 / (sigma * sigma) : s2);
    if(sigma == 0)
      CHECK(s2 < 1e-12);  // (an exact cubic: the rounding of sum w h² less the fitted part, 2e-16)
    else
      CHECK(s2 == Approx(sigma * sigma).epsilon(0.1));
    // its coefficients (cubic_normal()'s slope is a1, a2) and the share of the quadratic's
    // residual variance it leaves: 0 for an exact cubic, about 1 where the quadratic's
    // residuals are noise (here the noise's 1e-4 against the quadratic's 4.6e-3: measured 0.022)
    const double coefficients[10] = {0.1, 0.2, 0, 0, -0.3, 0, 0.4, 0, -0.2, 0};
    double a[10], share = -1;
    REQUIRE(fit.solve(I::cubic_normal_least_pivot, a, share));
    for(int c = 0; c < 10; ++c)
      CHECK(a[c] == Approx(coefficients[c]).margin(sigma > 0 ? 0.003 : 1e-12));
    measured("cubic's share of the quadratic's residual variance (sigma " + std::to_string(sigma) + ")", share);
    CHECK(share < (sigma > 0 ? 0.08 : 1e-9));
  }
  {
    // a plane under noise: the cubic's terms explain nothing of the quadratic's residuals
    I::Cubic_height_fit plane;
    for(int i = 0; i < 4000; ++i)
    {
      const double u = disc(random), v = disc(random);
      plane.add(u, v, 0.5 * u + 0.01 * gauss(random), 1 - 0.25 * (u * u + v * v));
    }
    double a[10], share = -1;
    REQUIRE(plane.solve(I::cubic_normal_least_pivot, a, share));
    CHECK(share == Approx(1).epsilon(0.01));
    CHECK(a[1] == Approx(0.5).margin(0.002));
  }
  // few samples of equal weight, pure noise: the mean of the cubic's residual variance is the
  // noise's (the factor n_eff / (n_eff - 10); 0.75 without it, 0.88 with the quadric's 6);
  // measured 1.00. (With unequal weights the factor only approximates: at the kernel's weights
  // over a disc, +14% for the cubic and +6% for the quadric, the cubic's test leaning to noise.)
  double mean_ratio = 0;
  const int trials = 2000;
  for(int t = 0; t < trials; ++t)
  {
    I::Cubic_height_fit small;
    for(int i = 0; i < 40; ++i)
    {
      const double u = disc(random), v = disc(random), h = 0.01 * gauss(random);  // (in this order)
      small.add(u, v, h, 1.0);
    }
    double s2 = 0;
    // (a loose pivot: 40 points at random can leave a cubic monomial's below gate_cubic_least_pivot)
    REQUIRE(small.residual_variance(1e-10, s2));
    mean_ratio += s2 / (0.01 * 0.01) / trials;
  }
  measured("cubic residual variance over sigma^2, 40 samples, mean of 2000", mean_ratio);
  CHECK(mean_ratio == Approx(1).epsilon(0.03));
  // three noisy scan lines across the disc: the cubic's v³ is nearly a combination of 1, v, v²
  // there (v takes three values), so the test tells nothing
  I::Cubic_height_fit lines;
  for(int i = 0; i < 60; ++i)
  {
    const double u = disc(random), v = 0.6 * (i % 3 - 1) + 0.01 * gauss(random);
    lines.add(u, v, cubic(u, v) + 0.01 * gauss(random), 1.0);
  }
  double s2 = -1;
  CHECK_FALSE(lines.residual_variance(I::gate_cubic_least_pivot, s2));
  CHECK(lines.residual_variance(1e-10, s2));  // (the same samples pass a loose pivot)
  // 10.5 effective samples or fewer: no variance (11 samples, one weighing 0.2: 10.36; all
  // weighing 1: 11)
  I::Cubic_height_fit few, eleven;
  for(int i = 0; i < 11; ++i)
  {
    const double u = disc(random), v = disc(random), h = 0.1 * gauss(random);
    few.add(u, v, h, i == 0 ? 0.2 : 1.0);
    eleven.add(u, v, h, 1.0);
  }
  CHECK_FALSE(few.residual_variance(1e-10, s2));
  CHECK(eleven.residual_variance(1e-10, s2));
}

TEST_CASE("Automatic scale: refused with a radius, below neighbor_count, with refinement, and for plane normals",
          "[bad_input][automatic_scale]")
{
  const auto pts = noisy_height_field(10, 0.0, 0.0, 60, 1);
  CHECK_THROWS_AS(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                    pts, PSC::parameters::neighbor_count(
                           40, PSC::parameters::automatic_scale(320, PSC::parameters::normal_refinement(1, maps())))),
                  std::invalid_argument);
  CHECK_THROWS_AS(
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 3.0, PSC::parameters::automatic_scale(320, maps())),
    std::invalid_argument);
  CHECK_THROWS_AS(CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                    pts, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(20, maps()))),
                  std::invalid_argument);
  std::vector<Oriented_point> copy = pts;
  CHECK_THROWS_AS(
    CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(
      copy, PSC::parameters::neighbor_count(
              18, PSC::parameters::automatic_scale(320, PSC::parameters::normal_fit(CGAL::Normal_fit::PLANE, maps())))),
    std::invalid_argument);
}

// =======================================================================================
// The average spacing (what --radius Nx is measured in)

TEST_CASE("average_spacing: the mean distance to the k + 1 nearest, itself included, over the finite points",
          "[average_spacing]")
{
  std::vector<Oriented_point> pts = sphere(600, 2.0);
  // a point far away, and a non-finite one that must be left out
  pts.emplace_back(Point(30, 0, 0), Vector(0, 0, 1));
  pts.emplace_back(Point(std::numeric_limits<double>::quiet_NaN(), 0, 0), Vector(0, 0, 1));
  const CGAL::First_of_pair_property_map<Oriented_point> point_map;
  const std::size_t k = 6;
  // brute force: every finite point's distances to every finite point (its own 0 included)
  double expected = 0;
  std::size_t finite = 0;
  for(const Oriented_point& p : pts)
  {
    if(!std::isfinite(p.first.x()))
      continue;
    std::vector<double> d;
    for(const Oriented_point& q : pts)
      if(std::isfinite(q.first.x()))
        d.push_back(std::sqrt(CGAL::squared_distance(p.first, q.first)));
    std::sort(d.begin(), d.end());
    double sum = 0;
    for(std::size_t j = 0; j <= k; ++j)
      sum += d[j];
    expected += sum / double(k + 1);
    ++finite;
  }
  expected /= double(finite);
  const double sequential = PSC::average_spacing<CGAL::Sequential_tag>(pts, k, CGAL::parameters::point_map(point_map));
  CHECK(std::abs(sequential - expected) <= 1e-12 * expected);
#ifdef CGAL_LINKED_WITH_TBB
  const double parallel = PSC::average_spacing<CGAL::Parallel_tag>(pts, k, CGAL::parameters::point_map(point_map));
  CHECK(bits(parallel) == bits(sequential));
#endif
  // a Point_set_3, its own point map
  CGAL::Point_set_3<Point> ps;
  for(const Oriented_point& p : pts)
    ps.insert(p.first);
  CHECK(bits(PSC::average_spacing<CGAL::Sequential_tag>(ps, k)) == bits(sequential));
  // cancelled: 0; k = 0 refused; no finite point: 0
  const std::function<bool(double)> stop = [](double) { return false; };
  CHECK(PSC::average_spacing<CGAL::Sequential_tag>(pts, k, CGAL::parameters::point_map(point_map).callback(stop)) == 0);
  CHECK_THROWS_AS(PSC::average_spacing<CGAL::Sequential_tag>(pts, 0, CGAL::parameters::point_map(point_map)),
                  std::invalid_argument);
  const std::vector<Oriented_point> none = {{Point(std::numeric_limits<double>::infinity(), 0, 0), Vector(0, 0, 1)}};
  CHECK(PSC::average_spacing<CGAL::Sequential_tag>(none, k, CGAL::parameters::point_map(point_map)) == 0);
}

TEST_CASE("Automatic scale, its sums and orders: moments, radix sort, distance ranks", "[automatic_scale][internal]")
{
  namespace I = CGAL::Point_set_curvatures::internal;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  // the normal equations from the 15 distinct monomials equal the outer products (to rounding)
  I::Quadratic_height_fit products;
  I::Quadratic_moments moments;
  double fourth = 0;
  for(int i = 0; i < 500; ++i)
  {
    const double u = uniform(rng), v = uniform(rng), h = uniform(rng), w = 0.5 + 0.5 * uniform(rng);
    products.add(u, v, h, w);
    moments.add(u, v, h, w);
    fourth += w * (u * u + v * v) * (u * u + v * v);
  }
  double ata[6][6] = {}, atb[6] = {};
  moments.fill(ata, atb);
  for(int i = 0; i < 6; ++i)
  {
    CHECK(atb[i] == Approx(products.atb[i]).epsilon(1e-12).margin(1e-12));
    for(int j = i; j < 6; ++j)
      CHECK(ata[i][j] == Approx(products.ata[i][j]).epsilon(1e-12).margin(1e-12));
  }
  CHECK(moments.fourth() == Approx(fourth).epsilon(1e-12));
  // the neighbourhoods' order by input position: the radix sort's, from 96 points on, is std::sort's,
  // with distinct input positions of 1 to 4 bytes
  for(int bytes = 1; bytes <= 4; ++bytes)
  {
    const std::uint64_t range = std::uint64_t(1) << (8 * bytes);
    const std::uint32_t cloud_size = 200;  // grid positions
    I::Sorted_cloud cloud;
    std::uniform_int_distribution<std::uint64_t> any(0, range - 1);
    std::set<std::uint32_t> taken;
    while(taken.size() < cloud_size)
      taken.insert(static_cast<std::uint32_t>(any(rng)));
    cloud.input_index.assign(taken.begin(), taken.end());
    std::shuffle(cloud.input_index.begin(), cloud.input_index.end(), rng);
    std::vector<std::uint64_t> scratch;
    for(std::size_t size : {10u, 95u, 96u, 150u, 200u})
    {
      std::vector<std::uint32_t> index(cloud_size);
      for(std::uint32_t i = 0; i < cloud_size; ++i)
        index[i] = i;
      std::shuffle(index.begin(), index.end(), rng);
      index.resize(size);
      std::vector<std::uint32_t> expected = index;
      std::sort(expected.begin(), expected.end(),
                [&](std::uint32_t a, std::uint32_t b) { return cloud.input_index[a] < cloud.input_index[b]; });
      I::sort_by_input_index(cloud, index.data(), index.size(), scratch);
      CHECK(index == expected);
    }
  }
  // the rungs' k-th distances: those of nth_element, ties and the neighbourhood's rim included
  std::vector<double> d2(700);
  for(std::size_t i = 0; i < d2.size(); ++i)
    d2[i] = i % 7 == 0 ? 0.25 : 0.5 * (1 + uniform(rng));
  d2[3] = 0;
  d2[5] = 1.0;
  d2[6] = 1.0 + 1e-12;  // (rounding at the rim)
  I::Distance_ranks ranks;
  ranks.assign(d2);
  std::vector<double> sorted = d2;
  std::sort(sorted.begin(), sorted.end());
  // (100 and 101 in one bucket: the second selection within a bucket the first one reordered)
  for(std::size_t k : {1u, 20u, 40u, 80u, 100u, 101u, 160u, 320u, 640u, 699u, 700u})
    CHECK(ranks.kth(k) == sorted[k - 1]);
}

TEST_CASE("Automatic scale in three passes (20, then 320, then 640): more accurate than the smallest count, "
          "the same sequentially and in parallel",
          "[aso][automatic_scale]")
{
  // exact normals, range noise 0.4 spacings on a gentle wave: most points climb past 320, which
  // only the third pass (the neighbourhood of 640) can tell
  const int half = 30;
  const auto pts = noisy_height_field(half, 0.4, 2.0, 60, 5);
  auto run = [&pts](auto tag, std::size_t largest) {
    namespace P = PSC::parameters;
    if(largest == 0)
      return CGAL::estimate_aso_curvatures<decltype(tag)>(pts, P::neighbor_count(20, maps()));
    return CGAL::estimate_aso_curvatures<decltype(tag)>(pts,
                                                        P::neighbor_count(20, P::automatic_scale(largest, maps())));
  };
  const auto parallel = run(CGAL::Parallel_tag(), 640);
  const auto sequential = run(CGAL::Sequential_tag(), 640);
  std::size_t differ = 0, at_640 = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    differ += same_estimate(parallel[i], sequential[i]) ? 0 : 1;
    at_640 += parallel[i].is_valid() && parallel[i].neighbor_count >= 640 ? 1 : 0;
  }
  CHECK(differ == 0);
  measured("three passes: points at 640", double(at_640));
  CHECK(at_640 > pts.size() / 4);
  const auto chosen = median_count_and_error(pts, parallel, half, 10, 2.0, 60);
  const auto at_20 = median_count_and_error(pts, run(CGAL::Parallel_tag(), 0), half, 10, 2.0, 60);
  measured("  mean |H - H*| automatic", chosen.second);
  measured("  mean |H - H*| at 20", at_20.second);
  CHECK(chosen.first >= 640);
  CHECK(chosen.second < 0.1 * at_20.second);
}
