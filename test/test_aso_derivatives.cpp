// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The ASO is the shape operator of the APSS field phi(x) = u_c(x) + u_l(x).x + u_q(x) x.x,
// whose coefficients are refitted with weights centred at x (Equations 1-5, 27-29). This
// test checks the package's closed-form gradient and Hessian (two passes, jets and adjoints)
// against central finite differences of phi computed by an independent, naive
// implementation of Equations 2-4 written here.

#include "test_support.h"

#include <CGAL/Algebraic_shape_operator_fit.h>

#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <cmath>
#include <random>
#include <vector>

using namespace psc_test;

namespace {

struct Sample
{
  double p[3], n[3];
  double a = 1;  // sample weight
};

// The variant of the field: kernel (1 - |p - x|^2/r^2)^P, the samples' weights, and the
// robust orientation (each normal flipped against the weighted sum of the normals at x).
struct Field_variant
{
  int P = 2;
  bool orient = false;
};

// phi(x) for samples with fixed positions, weights a (1 - |p - x|^2/r^2)^P centred at x.
double apss_field(const std::vector<Sample>& samples, double r, const double x[3], Field_variant v = {})
{
  auto weight = [&](const Sample& s) {
    double d2 = 0;
    for(int i = 0; i < 3; ++i)
      d2 += (s.p[i] - x[i]) * (s.p[i] - x[i]);
    return d2 >= r * r ? 0.0 : s.a * std::pow(1 - d2 / (r * r), v.P);
  };
  double m[3] = {0, 0, 0};
  for(const Sample& s : samples)
    for(int i = 0; i < 3; ++i)
      m[i] += weight(s) * s.n[i];
  double A = 0, B[3] = {0, 0, 0}, C[3] = {0, 0, 0}, D = 0, E = 0;
  for(const Sample& s : samples)
  {
    const double w = weight(s);
    if(w == 0)
      continue;
    const double side = v.orient && s.n[0] * m[0] + s.n[1] * m[1] + s.n[2] * m[2] < 0 ? -1.0 : 1.0;
    A += w;
    for(int i = 0; i < 3; ++i)
    {
      B[i] += w * s.p[i];
      C[i] += w * side * s.n[i];
      D += w * s.p[i] * side * s.n[i];
      E += w * s.p[i] * s.p[i];
    }
  }
  const double BB = B[0] * B[0] + B[1] * B[1] + B[2] * B[2];
  const double BC = B[0] * C[0] + B[1] * C[1] + B[2] * C[2];
  const double uq = 0.5 * (A * D - BC) / (A * E - BB);
  double ul[3];
  for(int i = 0; i < 3; ++i)
    ul[i] = (C[i] - 2 * uq * B[i]) / A;
  const double uc = -(ul[0] * B[0] + ul[1] * B[1] + ul[2] * B[2] + uq * E) / A;
  return uc + ul[0] * x[0] + ul[1] * x[1] + ul[2] * x[2] + uq * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

// Oriented samples of the patch z = a x^2 + b x y + c y^2 + d x^3 + e y^3 around the origin.
std::vector<Sample> patch(unsigned seed, double r, std::size_t n)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-r, r);
  const double a = 0.8, b = 0.5, c = -0.6, d = 0.7, e = -0.4;  // curvatures of order 1 (r = 0.3)
  std::vector<Sample> s;
  while(s.size() < n)
  {
    double x = u(rng), y = u(rng);
    if(s.empty())
      x = y = 0;  // the evaluation point itself
    const double z = a * x * x + b * x * y + c * y * y + d * x * x * x + e * y * y * y;
    double nv[3] = {-(2 * a * x + b * y + 3 * d * x * x), -(b * x + 2 * c * y + 3 * e * y * y), 1};
    const double l = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
    if(x * x + y * y + z * z < 0.98 * r * r)
      s.push_back({{x, y, z}, {nv[0] / l, nv[1] / l, nv[2] / l}});
  }
  return s;
}

}  // namespace

TEST_CASE("ASO gradient and Hessian equal finite differences of the APSS field")
{
  const double r = 0.3;
  // The paper's field, then the variants of estimate_aso_curvatures(): kernels ^3 and ^4,
  // sample weights, and 30% of the normals flipped with the robust orientation.
  struct Case
  {
    Field_variant v;
    CGAL::Apss_weight_kernel kernel;
    bool weighted;
  };
  const Case cases[] = {{{2, false}, CGAL::Apss_weight_kernel::SMOOTH, false},
                        {{3, false}, CGAL::Apss_weight_kernel::SMOOTH_CUBIC, false},
                        {{4, false}, CGAL::Apss_weight_kernel::SMOOTH_QUARTIC, true},
                        {{3, true}, CGAL::Apss_weight_kernel::SMOOTH_CUBIC, true}};
  for(const Case& c : cases)
    for(unsigned seed : {1u, 2u, 3u})
    {
      INFO("kernel exponent " << c.v.P << ", weights " << c.weighted << ", orientation " << c.v.orient);
      std::vector<Sample> samples = patch(seed, r, 80);
      std::mt19937 rng(seed + 100);
      std::uniform_real_distribution<double> u(0, 1);
      for(std::size_t i = 1; i < samples.size(); ++i)
      {
        if(c.weighted)
          samples[i].a = 0.5 + u(rng);
        if(c.v.orient && u(rng) < 0.3)
          for(double& x : samples[i].n)
            x = -x;
      }

      // Central differences, step h = 1e-4 r: truncation O(h^2) ~ 1e-8 relative, rounding
      // ~ 1e-16 / h^2 ~ 1e-8 for the Hessian.
      const double h = 1e-4 * r;
      double grad[3], hess[3][3];
      for(int i = 0; i < 3; ++i)
      {
        double xp[3] = {0, 0, 0}, xm[3] = {0, 0, 0};
        xp[i] = h;
        xm[i] = -h;
        grad[i] = (apss_field(samples, r, xp, c.v) - apss_field(samples, r, xm, c.v)) / (2 * h);
        for(int j = 0; j < 3; ++j)
        {
          double pp[3] = {0, 0, 0}, pm[3] = {0, 0, 0}, mp[3] = {0, 0, 0}, mm[3] = {0, 0, 0};
          pp[i] += h;
          pp[j] += h;
          pm[i] += h;
          pm[j] -= h;
          mp[i] -= h;
          mp[j] += h;
          mm[i] -= h;
          mm[j] -= h;
          hess[i][j] = (apss_field(samples, r, pp, c.v) - apss_field(samples, r, pm, c.v) -
                        apss_field(samples, r, mp, c.v) + apss_field(samples, r, mm, c.v)) /
                       (4 * h * h);
        }
      }
      // Truth from the finite differences: shape operator of phi on the plane orthogonal to
      // its gradient (the package's default projection).
      const double h9[9] = {hess[0][0], hess[0][1], hess[0][2], hess[1][0], hess[1][1],
                            hess[1][2], hess[2][0], hess[2][1], hess[2][2]};
      const Truth fd = truth_from_implicit(grad, h9);

      namespace P = CGAL::Point_set_curvatures::parameters;
      CGAL::Algebraic_shape_operator_fit<Kernel> fit(Point(0, 0, 0), r,
                                                     P::weight_kernel(c.kernel, P::robust_orientation(c.v.orient)));
      for(const Sample& s : samples)
        fit.add_neighbor(Point(s.p[0], s.p[1], s.p[2]), Vector(s.n[0], s.n[1], s.n[2]), s.a);
      const auto e = fit.estimate();
      REQUIRE(e.is_valid());
      std::printf("P=%d weights %d orientation %d seed %u: |1 - n.n_fd| %.1e, |dk_min| %.1e, |dk_max| %.1e, "
                  "direction %.1e deg\n",
                  c.v.P, int(c.weighted), int(c.v.orient), seed, std::abs(e.normal * fd.normal - 1),
                  std::abs(e.min_curvature - fd.k_min), std::abs(e.max_curvature - fd.k_max),
                  line_angle_degrees(e.max_direction, fd.d_max));
      INFO("seed " << seed << ": ASO k_min " << e.min_curvature << " k_max " << e.max_curvature
                   << ", finite differences " << fd.k_min << " " << fd.k_max);
      // Measured over the seeds and variants: 1 - n.n_fd <= 2.2e-16, curvature differences
      // <= 8e-8 (curvatures of order 1: the finite-difference error). Bounds: 5e-7; a wrong
      // term of Equation 29, a wrong kernel derivative or a weight missing from one pass
      // changes the curvatures by O(1e-2) at least.
      CHECK(std::abs(e.normal * fd.normal - 1) < 1e-12);
      CHECK(std::abs(e.min_curvature - fd.k_min) < 5e-7);
      CHECK(std::abs(e.max_curvature - fd.k_max) < 5e-7);
      CHECK(line_angle_degrees(e.max_direction, fd.d_max) < 1e-4);
    }
}

// The robust orientation takes its reference from the first pass's sum C and runs the
// orientation test and an oriented first pass only where some normal disagrees with it. That
// must be the estimator that flips from the start: majority_orientation(), then both passes on
// the flipped normals (the code before the shortcut), bitwise, with and without flips.
TEST_CASE("Robust orientation: the shortcut through the first pass equals orienting first, bitwise")
{
  namespace PSCi = CGAL::Point_set_curvatures::internal;
  typedef PSCi::Power_kernel<3> K3;
  const double r = 0.3;
  for(double flipped : {0.0, 0.3})
    for(unsigned seed : {1u, 2u, 3u})
    {
      INFO("flipped fraction " << flipped << ", seed " << seed);
      std::vector<Sample> samples = patch(seed, r, 80);
      std::mt19937 rng(seed + 200);
      std::uniform_real_distribution<double> u(0, 1);
      std::vector<double> col[7];
      for(std::size_t i = 0; i < samples.size(); ++i)
      {
        if(i > 0 && u(rng) < flipped)
          for(double& x : samples[i].n)
            x = -x;
        for(int a = 0; a < 3; ++a)
        {
          col[a].push_back(samples[i].p[a] / r);
          col[3 + a].push_back(samples[i].n[a]);
        }
        col[6].push_back(0.5 + u(rng));
      }
      PSCi::Neighborhood nb;
      nb.size = samples.size();
      nb.qx = col[0].data();
      nb.qy = col[1].data();
      nb.qz = col[2].data();
      nb.nx = col[3].data();
      nb.ny = col[4].data();
      nb.nz = col[5].data();
      nb.sample_weight = col[6].data();
      nb.radius = r;
      for(int a = 0; a < 3; ++a)
        nb.query_normal[a] = samples[0].n[a];
      PSCi::Aso_settings settings;
      settings.kernel_exponent = 3;
      settings.orient_neighbors = true;
      for(bool blend : {false, true})
      {
        settings.normal_field_blend = blend;
        const PSCi::Local_estimate shortcut = PSCi::algebraic_shape_operator(nb, settings);
        double ref[3];
        REQUIRE(PSCi::majority_orientation<K3>(nb, ref));
        const PSCi::Local_estimate first =
          PSCi::aso_from_first_pass<K3, true, true>(nb, PSCi::aso_first_pass<K3, true, true>(nb, ref), ref, settings);
        REQUIRE(shortcut.status == CGAL::Curvature_estimate_status::VALID);
        CHECK(shortcut.k_min == first.k_min);
        CHECK(shortcut.k_max == first.k_max);
        for(int a = 0; a < 3; ++a)
          CHECK(shortcut.normal[a] == first.normal[a]);
      }
    }
}

// The normal-field fit of the blend (normal_field_fit.h): S = I / R on a sphere from one side
// only (a cap cut through its centre), in a tilted frame too; refused without spread across.
TEST_CASE("Normal-field fit: exact on a one-sided sphere cap, refused on a line")
{
  namespace PSCi = CGAL::Point_set_curvatures::internal;
  const double R = 2.0;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for(double tilt : {0.0, 0.3})
  {
    // frame: t1 = (cos, 0, sin) tilted about y, t2 = (0, 1, 0); the sphere's centre (0, 0, -R)
    const double t1[3] = {std::cos(tilt), 0, std::sin(tilt)}, t2[3] = {0, 1, 0};
    PSCi::Normal_field_sums f;
    for(int i = 0; i < 200; ++i)
    {
      const double x = std::abs(u(rng)), y = u(rng);  // one side: x >= 0
      const double p[3] = {x, y, std::sqrt(R * R - x * x - y * y) - R};
      const double n[3] = {p[0] / R, p[1] / R, (p[2] + R) / R};
      auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
      const double w = 0.5 + std::abs(u(rng));
      f.w += w;
      f.u += w * dot(p, t1);
      f.v += w * dot(p, t2);
      f.uu += w * dot(p, t1) * dot(p, t1);
      f.uv += w * dot(p, t1) * dot(p, t2);
      f.vv += w * dot(p, t2) * dot(p, t2);
      f.a += w * dot(n, t1);
      f.b += w * dot(n, t2);
      f.au += w * dot(n, t1) * dot(p, t1);
      f.av += w * dot(n, t1) * dot(p, t2);
      f.bu += w * dot(n, t2) * dot(p, t1);
      f.bv += w * dot(n, t2) * dot(p, t2);
    }
    double S[3] = {0, 0, 0};
    REQUIRE(f.solve(S));
    INFO("tilt " << tilt);
    CHECK(std::abs(S[0] - 1 / R) < 1e-12);
    CHECK(std::abs(S[1]) < 1e-12);
    CHECK(std::abs(S[2] - 1 / R) < 1e-12);
  }
  // points along a line (v = 0), then with a spread across of 1e-4 and 1e-2 of the length
  for(double across : {0.0, 1e-4, 1e-2})
  {
    PSCi::Normal_field_sums f;
    for(int i = 0; i < 50; ++i)
    {
      const double pu = 0.02 * i, pv = across * (i % 2 ? 1 : -1);
      f.w += 1;
      f.u += pu;
      f.v += pv;
      f.uu += pu * pu;
      f.uv += pu * pv;
      f.vv += pv * pv;
      f.a += pu;
      f.au += pu * pu;
      f.av += pu * pv;
    }
    double S[3] = {0, 0, 0};
    CHECK(f.solve(S) == (across > 1e-3));
  }
}
