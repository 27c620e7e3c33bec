// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Helpers of test_core.cpp only: bitwise comparison of estimates, NaN checks, error
// statistics, rigid motions of oriented clouds, and an opt-in printout of the measured
// values behind the tolerances (run the tests with PSC_TEST_PRINT=1 to re-measure them).

#ifndef PSC_TEST_CORE_SUPPORT_H
#define PSC_TEST_CORE_SUPPORT_H

#include "test_support.h"

#include <CGAL/Curvature_estimate.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace psc_core_test {

using psc_test::Kernel;
using psc_test::measured;
using psc_test::Oriented_point;
using psc_test::Point;
using psc_test::Vector;

typedef CGAL::Curvature_estimate<Kernel> Estimate;
typedef CGAL::Curvature_estimate_status Status;

inline std::uint64_t bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

template <class FT>
bool same_bits(const FT& a, const FT& b)
{
  return bits(CGAL::to_double(a)) == bits(CGAL::to_double(b));
}

template <class V>
bool same_bits_vector(const V& a, const V& b)
{
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

// Every field equal, doubles compared bit for bit (so NaN == NaN, and 0.0 != -0.0).
template <class K1, class K2>
bool same_estimate(const CGAL::Curvature_estimate<K1>& a, const CGAL::Curvature_estimate<K2>& b)
{
  auto v = [](const auto& w) {
    return std::vector<double>{CGAL::to_double(w.x()), CGAL::to_double(w.y()), CGAL::to_double(w.z())};
  };
  const std::vector<double> va = v(a.normal), vb = v(b.normal);
  const std::vector<double> ma = v(a.min_direction), mb = v(b.min_direction);
  const std::vector<double> xa = v(a.max_direction), xb = v(b.max_direction);
  for(int i = 0; i < 3; ++i)
    if(bits(va[i]) != bits(vb[i]) || bits(ma[i]) != bits(mb[i]) || bits(xa[i]) != bits(xb[i]))
      return false;
  return a.status == b.status && a.neighbor_count == b.neighbor_count &&
         same_bits(a.mean_curvature, b.mean_curvature) && same_bits(a.gaussian_curvature, b.gaussian_curvature) &&
         same_bits(a.min_curvature, b.min_curvature) && same_bits(a.max_curvature, b.max_curvature);
}

template <class V>
bool is_nan_vector(const V& v)
{
  return std::isnan(CGAL::to_double(v.x())) && std::isnan(CGAL::to_double(v.y())) && std::isnan(CGAL::to_double(v.z()));
}

// The fields APSS does not provide (and no invalid estimate may hold).
template <class K>
bool principal_fields_nan(const CGAL::Curvature_estimate<K>& e)
{
  return std::isnan(CGAL::to_double(e.min_curvature)) && std::isnan(CGAL::to_double(e.max_curvature)) &&
         std::isnan(CGAL::to_double(e.gaussian_curvature)) && is_nan_vector(e.min_direction) &&
         is_nan_vector(e.max_direction);
}

template <class K>
bool every_numeric_field_nan(const CGAL::Curvature_estimate<K>& e)
{
  return principal_fields_nan(e) && std::isnan(CGAL::to_double(e.mean_curvature)) && is_nan_vector(e.normal);
}

inline double length(const Vector& v) { return std::sqrt(v.squared_length()); }

// Distance between two unit vectors taken as lines (a direction's sign is arbitrary).
inline double line_distance(const Vector& a, const Vector& b) { return std::min(length(a - b), length(a + b)); }

// |a - b| relative to max(|b|, floor): the floor keeps near-zero values from being judged
// on their (meaningless) relative error.
inline double scaled_difference(double a, double b, double floor)
{
  return std::abs(a - b) / std::max(std::abs(b), floor);
}

// Largest principal curvature magnitude of an estimate: the scale of its curvatures.
template <class K>
double curvature_scale(const CGAL::Curvature_estimate<K>& e)
{
  return std::max(std::abs(CGAL::to_double(e.min_curvature)), std::abs(CGAL::to_double(e.max_curvature)));
}

// Running maximum and mean.
struct Stat
{
  double max = 0, sum = 0;
  std::size_t n = 0;
  void add(double x)
  {
    max = std::max(max, x);
    sum += x;
    ++n;
  }
  double mean() const { return n ? sum / double(n) : 0; }
};

// A rotation matrix (Rodrigues' formula) about `axis` by `angle` radians.
struct Rotation
{
  double m[3][3];
  Rotation(Vector axis, double angle)
  {
    axis = axis / length(axis);
    const double c = std::cos(angle), s = std::sin(angle), k[3] = {axis.x(), axis.y(), axis.z()};
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        m[i][j] = (1 - c) * k[i] * k[j] + (i == j ? c : 0.0);
    m[0][1] -= s * k[2];
    m[0][2] += s * k[1];
    m[1][0] += s * k[2];
    m[1][2] -= s * k[0];
    m[2][0] -= s * k[1];
    m[2][1] += s * k[0];
  }
  Vector operator()(const Vector& v) const
  {
    return Vector(m[0][0] * v.x() + m[0][1] * v.y() + m[0][2] * v.z(),
                  m[1][0] * v.x() + m[1][1] * v.y() + m[1][2] * v.z(),
                  m[2][0] * v.x() + m[2][1] * v.y() + m[2][2] * v.z());
  }
  Point operator()(const Point& p) const { return CGAL::ORIGIN + (*this)(p - CGAL::ORIGIN); }
};

inline std::vector<Oriented_point> rotated(const std::vector<Oriented_point>& pts, const Rotation& rot)
{
  std::vector<Oriented_point> out;
  out.reserve(pts.size());
  for(const Oriented_point& p : pts)
    out.emplace_back(rot(p.first), rot(p.second));
  return out;
}

inline std::vector<Oriented_point> translated(const std::vector<Oriented_point>& pts, const Vector& t)
{
  std::vector<Oriented_point> out;
  out.reserve(pts.size());
  for(const Oriented_point& p : pts)
    out.emplace_back(p.first + t, p.second);
  return out;
}

// Number of points of `pts` at distance < r from `x` (brute force).
inline std::size_t brute_force_count(const std::vector<Oriented_point>& pts, const Point& x, double r)
{
  std::size_t n = 0;
  for(const Oriented_point& p : pts)
    if(CGAL::squared_distance(p.first, x) < r * r)
      ++n;
  return n;
}

}  // namespace psc_core_test

#endif
