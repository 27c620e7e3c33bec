// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the test programs: readers for the data files, analytic surfaces with exact
// normals and curvatures, and small helpers. Header-only; each test program includes it.

#ifndef PSC_TEST_SUPPORT_H
#define PSC_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace psc_test {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Oriented_point;
typedef CGAL::First_of_pair_property_map<Oriented_point> Point_map;
typedef CGAL::Second_of_pair_property_map<Oriented_point> Normal_map;

inline std::string repo_data(const std::string& name) { return std::string(PSC_DATA_DIR) + "/" + name; }

// "x y z nx ny nz" per line; lines starting with '#' are comments.
inline std::vector<Oriented_point> read_xyz(const std::string& file)
{
  std::ifstream in(file);
  if(!in)
    throw std::runtime_error("cannot open " + file);
  std::vector<Oriented_point> pts;
  std::string line;
  while(std::getline(in, line))
  {
    if(line.empty() || line[0] == '#')
      continue;
    std::istringstream s(line);
    double v[6];
    if(s >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5])
      pts.emplace_back(Point(v[0], v[1], v[2]), Vector(v[3], v[4], v[5]));
  }
  return pts;
}

// ASCII PLY with vertices "x y z nx ny nz" (data/bunny.ply).
inline std::vector<Oriented_point> read_ascii_ply_xyz_normals(const std::string& file)
{
  std::ifstream in(file);
  if(!in)
    throw std::runtime_error("cannot open " + file);
  std::string line;
  while(std::getline(in, line))
    if(line.rfind("end_header", 0) == 0)
      break;
  std::vector<Oriented_point> pts;
  double v[6];
  while(in >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5])
    pts.emplace_back(Point(v[0], v[1], v[2]), Vector(v[3], v[4], v[5]));
  return pts;
}

// One row of data/reference/*.csv
struct Reference_row
{
  std::size_t index, neighbors;
  double k_min, k_max, mean, gaussian;
  double n[3], d_min[3], d_max[3];
};

inline std::vector<Reference_row> read_reference(const std::string& file)
{
  std::ifstream in(file);
  if(!in)
    throw std::runtime_error("cannot open " + file);
  std::string line;
  std::getline(in, line);  // header
  std::vector<Reference_row> rows;
  while(std::getline(in, line))
  {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    Reference_row r;
    s >> r.index >> r.neighbors >> r.k_min >> r.k_max >> r.mean >> r.gaussian >> r.n[0] >> r.n[1] >>
      r.n[2] >> r.d_min[0] >> r.d_min[1] >> r.d_min[2] >> r.d_max[0] >> r.d_max[1] >> r.d_max[2];
    if(s)
      rows.push_back(r);
  }
  return rows;
}

// Exact differential quantities of a surface at a point.
struct Truth
{
  Vector normal;
  double k_min, k_max, mean, gaussian;
  Vector d_min, d_max;
};

// Truth from the gradient g and Hessian h (row-major 3x3) of an implicit function F whose
// gradient points along the chosen normal: shape operator P h P / |g|.
inline Truth truth_from_implicit(const double g[3], const double h[9])
{
  const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  const double n[3] = {g[0] / gn, g[1] / gn, g[2] / gn};
  // tangent basis
  double a[3] = {1, 0, 0};
  if(std::abs(n[0]) > 0.9) { a[0] = 0; a[1] = 1; }
  const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
  double t1[3] = {a[0] - an * n[0], a[1] - an * n[1], a[2] - an * n[2]};
  const double l1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for(double& x : t1) x /= l1;
  const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
  auto form = [&](const double* u, const double* v) {
    double s = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        s += u[i] * h[3 * i + j] * v[j];
    return s / gn;
  };
  const double A = form(t1, t1), B = form(t1, t2), C = form(t2, t2);
  const double m = 0.5 * (A + C), rad = std::hypot(0.5 * (A - C), B);
  const double theta = 0.5 * std::atan2(2 * B, A - C);
  const double c = std::cos(theta), s = std::sin(theta);
  Truth t;
  t.normal = Vector(n[0], n[1], n[2]);
  t.k_min = m - rad;
  t.k_max = m + rad;
  t.mean = m;
  t.gaussian = t.k_min * t.k_max;
  t.d_max = Vector(c * t1[0] + s * t2[0], c * t1[1] + s * t2[1], c * t1[2] + s * t2[2]);
  t.d_min = Vector(-s * t1[0] + c * t2[0], -s * t1[1] + c * t2[1], -s * t1[2] + c * t2[2]);
  return t;
}

// Goursat surface of the paper (Section 6.1): F = -8 - 2|x|^2 + 0.03 sum x_i^4, outward
// normal grad F / |grad F| (F < 0 inside).
inline Truth goursat_truth(const Point& p)
{
  const double x[3] = {p.x(), p.y(), p.z()};
  double g[3], h[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  for(int i = 0; i < 3; ++i)
  {
    g[i] = -4 * x[i] + 0.12 * x[i] * x[i] * x[i];
    h[4 * i] = -4 + 0.36 * x[i] * x[i];
  }
  return truth_from_implicit(g, h);
}

// Angle in degrees between two lines (directions up to sign).
inline double line_angle_degrees(const Vector& a, const Vector& b)
{
  const double c = std::abs(a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

// Fibonacci sphere of radius R centred at c, outward normals (or inward if `inward`).
inline std::vector<Oriented_point> sphere(std::size_t n, double R, const Point& c = Point(0, 0, 0),
                                          bool inward = false)
{
  std::vector<Oriented_point> pts;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (i + 0.5) / double(n);
    const double rho = std::sqrt(1 - z * z);
    const double phi = golden * double(i);
    const Vector u(rho * std::cos(phi), rho * std::sin(phi), z);
    pts.emplace_back(c + R * u, inward ? -u : u);
  }
  return pts;
}

// Cylinder of radius R around the z axis, z in [-h/2, h/2], on a jittered grid; outward normals.
inline std::vector<Oriented_point> cylinder(std::size_t n_around, std::size_t n_along, double R,
                                            double height, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  std::vector<Oriented_point> pts;
  for(std::size_t i = 0; i < n_along; ++i)
    for(std::size_t j = 0; j < n_around; ++j)
    {
      const double phi = 2 * M_PI * (j + jitter(rng)) / double(n_around);
      const double z = height * ((i + 0.5 + jitter(rng)) / double(n_along) - 0.5);
      const Vector u(std::cos(phi), std::sin(phi), 0);
      pts.emplace_back(Point(R * u.x(), R * u.y(), z), u);
    }
  return pts;
}

// Plane z = 0 on a jittered grid of spacing h, normals +z.
inline std::vector<Oriented_point> plane(std::size_t n_side, double h, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Oriented_point> pts;
  for(std::size_t i = 0; i < n_side; ++i)
    for(std::size_t j = 0; j < n_side; ++j)
      pts.emplace_back(Point(h * (i + jitter(rng)), h * (j + jitter(rng)), 0), Vector(0, 0, 1));
  return pts;
}

// Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 (normalised Gaussian directions), outward normals.
inline std::vector<Oriented_point> ellipsoid(std::size_t n, double a, double b, double c, unsigned seed = 1)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<Oriented_point> pts;
  while(pts.size() < n)
  {
    const double u[3] = {g(rng), g(rng), g(rng)};
    const double l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if(l < 1e-12)
      continue;
    const Point p(a * u[0] / l, b * u[1] / l, c * u[2] / l);
    Vector nrm(p.x() / (a * a), p.y() / (b * b), p.z() / (c * c));
    pts.emplace_back(p, nrm / std::sqrt(nrm.squared_length()));
  }
  return pts;
}

// Exact quantities of the ellipsoid above at a point of it.
inline Truth ellipsoid_truth(const Point& p, double a, double b, double c)
{
  const double g[3] = {2 * p.x() / (a * a), 2 * p.y() / (b * b), 2 * p.z() / (c * c)};
  const double h[9] = {2 / (a * a), 0, 0, 0, 2 / (b * b), 0, 0, 0, 2 / (c * c)};
  return truth_from_implicit(g, h);
}

// what() of the std::invalid_argument that f() throws, or a note saying it threw none.
template <class F>
inline std::string invalid_argument_message(F f)
{
  try
  {
    f();
  }
  catch(const std::invalid_argument& e)
  {
    return e.what();
  }
  catch(...)
  {
    return "<an exception other than std::invalid_argument>";
  }
  return "<no exception>";
}

} // namespace psc_test

#endif
