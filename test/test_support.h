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
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace psc_test {

// Prints a measured quantity when PSC_TEST_PRINT is set in the environment, so that the
// numbers quoted in the tests' comments can be measured again.
inline void measured(const std::string& what, double value)
{
  if(std::getenv("PSC_TEST_PRINT"))
    std::printf("[measured] %-70s %.3e\n", what.c_str(), value);
}

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
    s >> r.index >> r.neighbors >> r.k_min >> r.k_max >> r.mean >> r.gaussian >> r.n[0] >> r.n[1] >> r.n[2] >>
      r.d_min[0] >> r.d_min[1] >> r.d_min[2] >> r.d_max[0] >> r.d_max[1] >> r.d_max[2];
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
  if(std::abs(n[0]) > 0.9)
  {
    a[0] = 0;
    a[1] = 1;
  }
  const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
  double t1[3] = {a[0] - an * n[0], a[1] - an * n[1], a[2] - an * n[2]};
  const double l1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for(double& x : t1)
    x /= l1;
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

// `n` copies of `p` up to rounding: each coordinate moved by up to 4 rounding units (the same
// point computed along different paths; a rosette scan's passes over nadir).
inline std::vector<Point> near_copies(const Point& p, std::size_t n, unsigned seed = 7)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> steps(-4, 4);
  auto moved = [&](double v) {
    const int s = steps(rng);
    for(int i = 0; i < std::abs(s); ++i)
      v = std::nextafter(v, s > 0 ? 1e300 : -1e300);
    return v;
  };
  std::vector<Point> out;
  for(std::size_t j = 0; j < n; ++j)
  {
    const double x = moved(p.x()), y = moved(p.y()), z = moved(p.z());
    out.emplace_back(x, y, z);
  }
  return out;
}

// Angle in degrees between two lines (directions up to sign).
inline double line_angle_degrees(const Vector& a, const Vector& b)
{
  const double c = std::abs(a * b) / std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

// Fibonacci sphere of radius R centred at c, outward normals (or inward if `inward`).
inline std::vector<Oriented_point> sphere(std::size_t n, double R, const Point& c = Point(0, 0, 0), bool inward = false)
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
inline std::vector<Oriented_point> cylinder(std::size_t n_around, std::size_t n_along, double R, double height,
                                            unsigned seed = 1)
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

// The bytes of a LAS file, written from the ASPRS specification for the tests of the tool's
// reader and for the benchmarks: the positions of `pts` quantised with `scale` and `offset`
// (the values read back in `quantised`), point data record format `format` in LAS 1.`minor`,
// `extra` extra bytes per record; the fields of point i are the functions of i below.
inline std::uint16_t las_intensity(std::size_t i) { return std::uint16_t(i * 37 % 65536); }
inline int las_classification(std::size_t i) { return int(2 + i % 4); }
inline double las_gps_time(std::size_t i) { return 3.5e8 + 0.25 * double(i); }
inline std::uint16_t las_red(std::size_t i) { return std::uint16_t(i * 256 % 65536); }

template <class T>
inline void put_le(std::string& s, std::size_t at, T v)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));  // the test machines are little-endian, as LAS is
  for(std::size_t k = 0; k < sizeof(T); ++k)
    s[at + k] = char(b[k]);
}

// With `beam_from` (formats 4, 5, 9, 10), the wave packets' pulse directions x(t) y(t) z(t)
// point from that position (the scanner) to each point, 1e-3 times their difference.
inline std::string las_file(const std::vector<Oriented_point>& pts, int format, int minor, double scale,
                            const double offset[3], std::size_t extra = 0,
                            std::vector<std::array<double, 3> >* quantised = nullptr, const double* beam_from = nullptr)
{
  static const std::size_t sizes[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  const std::size_t header = minor >= 4 ? 375 : minor == 3 ? 235 : 227;
  const std::size_t record = sizes[format] + extra, n = pts.size();
  std::string h(header, '\0');
  h.replace(0, 4, "LASF");
  put_le<std::uint8_t>(h, 24, 1);
  put_le<std::uint8_t>(h, 25, std::uint8_t(minor));
  put_le<std::uint16_t>(h, 94, std::uint16_t(header));
  put_le<std::uint32_t>(h, 96, std::uint32_t(header));
  put_le<std::uint8_t>(h, 104, std::uint8_t(format));
  put_le<std::uint16_t>(h, 105, std::uint16_t(record));
  put_le<std::uint32_t>(h, 107, std::uint32_t(format < 6 ? n : 0));
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  std::string body(n * record, '\0');
  for(std::size_t i = 0; i < n; ++i)
  {
    std::array<double, 3> x;
    const std::size_t o = i * record;
    for(int a = 0; a < 3; ++a)
    {
      const std::int32_t X = std::int32_t(std::lround((pts[i].first[a] - offset[a]) / scale));
      put_le<std::int32_t>(body, o + 4 * a, X);
      x[a] = double(X) * scale + offset[a];
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
    if(quantised)
      quantised->push_back(x);
    put_le<std::uint16_t>(body, o + 12, las_intensity(i));
    if(format < 6)
    {
      put_le<std::uint8_t>(body, o + 14, std::uint8_t(1 | (2 << 3)));  // return 1 of 2
      put_le<std::uint8_t>(body, o + 15, std::uint8_t(las_classification(i)));
      put_le<std::int8_t>(body, o + 16, std::int8_t(-12));
      put_le<std::uint16_t>(body, o + 18, 7);
      if(format != 0 && format != 2)
        put_le<double>(body, o + 20, las_gps_time(i));
      if(format == 2 || format == 3 || format == 5)
        put_le<std::uint16_t>(body, o + (format == 2 ? 20 : 28), las_red(i));
    }
    else
    {
      put_le<std::uint8_t>(body, o + 14, std::uint8_t(1 | (2 << 4)));
      put_le<std::uint8_t>(body, o + 15, std::uint8_t(1 << 3));  // overlap
      put_le<std::uint8_t>(body, o + 16, std::uint8_t(las_classification(i)));
      put_le<std::int16_t>(body, o + 18, std::int16_t(-2000));  // -12 degrees
      put_le<std::uint16_t>(body, o + 20, 7);
      put_le<double>(body, o + 22, las_gps_time(i));
      if(format == 7 || format == 8 || format == 10)
        put_le<std::uint16_t>(body, o + 30, las_red(i));
      if(format == 8 || format == 10)
        put_le<std::uint16_t>(body, o + 36, 4242);
    }
    if(beam_from && (format == 4 || format == 5 || format == 9 || format == 10))
    {
      const std::size_t w = o + (format == 4 ? 28 : format == 5 ? 34 : format == 9 ? 30 : 38);
      put_le<std::uint8_t>(body, w, 1);
      put_le<std::uint32_t>(body, w + 9, 256);
      put_le<float>(body, w + 13, 1000.0f);
      for(int a = 0; a < 3; ++a)
        put_le<float>(body, w + 17 + 4 * a, float(1e-3 * (pts[i].first[a] - beam_from[a])));
    }
  }
  for(int a = 0; a < 3; ++a)
  {
    put_le<double>(h, 131 + 8 * a, scale);
    put_le<double>(h, 155 + 8 * a, offset[a]);
    put_le<double>(h, 179 + 16 * a, hi[a]);
    put_le<double>(h, 187 + 16 * a, lo[a]);
  }
  if(minor >= 4)
    put_le<std::uint64_t>(h, 247, n);
  return h + body;
}

}  // namespace psc_test

#endif
