// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scanned clouds with analytic truth, as real scanners produce them: rays cast at a fixed
// angular step from a scanner position, the first hit with the surface kept, optional range
// noise along the ray and coordinates quantised to a grid (LAS stores integers). Three
// surfaces: a torus, a wavy terrain (a height field) and a plane. The truth (normal, principal
// curvatures, directions) is that of the surface point nearest to each sample.
//
// Used by benchmark/scan_experiments.cpp and by the tests of normals estimated from positions.

#ifndef PSC_TEST_SCAN_SIMULATOR_H
#define PSC_TEST_SCAN_SIMULATOR_H

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace psc_test {
namespace scan {

// A surface the simulator can scan: a signed implicit function F (F > 0 outside, its
// gradient along the outward or upward normal), its gradient and Hessian, the first hit of
// a ray, and the nearest surface point.
struct Surface
{
  virtual ~Surface() = default;
  virtual double value(const double x[3]) const = 0;
  virtual void gradient_hessian(const double x[3], double g[3], double h[9]) const = 0;
  // first t > 0 with o + t d on the surface (d unit), or a negative value if none
  virtual double first_hit(const double o[3], const double d[3]) const = 0;
  virtual void nearest(const double x[3], double y[3]) const = 0;

  Truth truth_at(const double x[3]) const
  {
    double y[3], g[3], h[9];
    nearest(x, y);
    gradient_hessian(y, g, h);
    return truth_from_implicit(g, h);
  }
};

// Refines a bracket [a, b] of the ray o + t d where F changes sign, by bisection to rounding.
template <class F>
inline double bisect(const F& f, double a, double b)
{
  double fa = f(a);
  for(int i = 0; i < 200 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++i)
  {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if((fm > 0) == (fa > 0))
    {
      a = m;
      fa = fm;
    }
    else
      b = m;
  }
  return 0.5 * (a + b);
}

// The torus of radii R (centre to tube centre) and r (tube) around the z axis; outward normals.
// Its mean curvature goes from (1/r - 1/(R - r)) / 2 inside the hole to (1/r + 1/(R + r)) / 2
// outside.
struct Torus : Surface
{
  double R = 1, r = 0.4;
  Torus(double R_, double r_) : R(R_), r(r_) {}

  // the exact distance, signed
  double distance(const double x[3]) const
  {
    const double q = std::hypot(x[0], x[1]) - R;
    return std::hypot(q, x[2]) - r;
  }
  double value(const double x[3]) const override { return distance(x); }
  void gradient_hessian(const double x[3], double g[3], double h[9]) const override
  {
    // F = (rho - R)^2 + z^2 - r^2 with rho = |(x, y)|: same zero set and outside, smooth
    const double rho = std::hypot(x[0], x[1]);
    const double c = (rho - R) / rho;
    g[0] = 2 * c * x[0];
    g[1] = 2 * c * x[1];
    g[2] = 2 * x[2];
    // d/dx_j (2 c x_i) = 2 c delta_ij + 2 x_i R x_j / rho^3
    const double s = 2 * R / (rho * rho * rho);
    h[0] = 2 * c + s * x[0] * x[0];
    h[1] = s * x[0] * x[1];
    h[2] = 0;
    h[3] = h[1];
    h[4] = 2 * c + s * x[1] * x[1];
    h[5] = 0;
    h[6] = 0;
    h[7] = 0;
    h[8] = 2;
  }
  double first_hit(const double o[3], const double d[3]) const override
  {
    // sphere tracing with the exact distance, then bisection on the last step
    double t = 0;
    for(int i = 0; i < 100000 && t < 1e3; ++i)
    {
      const double x[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
      const double s = distance(x);
      if(s < 1e-9)
      {
        auto f = [&](double u) {
          const double y[3] = {o[0] + u * d[0], o[1] + u * d[1], o[2] + u * d[2]};
          return distance(y);
        };
        const double a = std::max(0.0, t - 1e-6);
        return f(a) > 0 && f(t + 1e-6) < 0 ? bisect(f, a, t + 1e-6) : t;
      }
      t += s;
    }
    return -1;
  }
  void nearest(const double x[3], double y[3]) const override
  {
    const double rho = std::hypot(x[0], x[1]);
    const double cx = R * x[0] / rho, cy = R * x[1] / rho;  // the tube's centre circle
    const double v[3] = {x[0] - cx, x[1] - cy, x[2]};
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    y[0] = cx + r * v[0] / l;
    y[1] = cy + r * v[1] / l;
    y[2] = r * v[2] / l;
  }
};

// A height field z = f(x, y) with f, its gradient and Hessian; normals upward (F = z - f).
struct Height_field : Surface
{
  std::function<double(double, double)> f;
  std::function<void(double, double, double[2], double[3])> derivatives;  // (fx, fy), (fxx, fxy, fyy)
  double max_height = 1e300;  // an upper bound of f: a ray above it going up hits nothing
  double slope_bound = 4;     // an upper bound of |grad f|

  double value(const double x[3]) const override { return x[2] - f(x[0], x[1]); }
  void gradient_hessian(const double x[3], double g[3], double h[9]) const override
  {
    double d1[2], d2[3];
    derivatives(x[0], x[1], d1, d2);
    g[0] = -d1[0];
    g[1] = -d1[1];
    g[2] = 1;
    h[0] = -d2[0];
    h[1] = -d2[1];
    h[2] = 0;
    h[3] = -d2[1];
    h[4] = -d2[2];
    h[5] = 0;
    h[6] = 0;
    h[7] = 0;
    h[8] = 0;
  }
  double first_hit(const double o[3], const double d[3]) const override
  {
    // march in steps small against the surface's features, then bisection
    auto F = [&](double t) {
      const double y[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
      return value(y);
    };
    if(!(F(0) > 0))
      return -1;
    // along the ray, z - f falls by at most (|d_z| + slope_bound |d_xy|) per unit of length:
    // a step of F / that cannot cross the surface; below a minimum step, bisection
    const double fall = std::abs(d[2]) + slope_bound * std::hypot(d[0], d[1]);
    double t = 0;
    for(int i = 0; i < 1000000; ++i)
    {
      const double next = t + std::max(1e-3, F(t) / fall);
      if(F(next) <= 0)
        return bisect(F, t, next);
      t = next;
      if(t > 1e4 || (d[2] >= 0 && o[2] + t * d[2] > max_height))
        break;
    }
    return -1;
  }
  void nearest(const double x[3], double y[3]) const override
  {
    // Newton on the distance from x to (u, v, f(u, v)), from the vertical projection
    double u = x[0], v = x[1];
    for(int it = 0; it < 50; ++it)
    {
      double d1[2], d2[3];
      derivatives(u, v, d1, d2);
      const double e = f(u, v) - x[2];
      // gradient of 0.5 |(u - x, v - y, f - z)|^2 and its Hessian
      const double gu = (u - x[0]) + e * d1[0], gv = (v - x[1]) + e * d1[1];
      const double huu = 1 + d1[0] * d1[0] + e * d2[0], huv = d1[0] * d1[1] + e * d2[1],
                   hvv = 1 + d1[1] * d1[1] + e * d2[2];
      const double det = huu * hvv - huv * huv;
      const double du = (hvv * gu - huv * gv) / det, dv = (huu * gv - huv * gu) / det;
      u -= du;
      v -= dv;
      if(std::abs(du) + std::abs(dv) < 1e-15 * (1 + std::abs(u) + std::abs(v)))
        break;
    }
    y[0] = u;
    y[1] = v;
    y[2] = f(u, v);
  }
};

// The wavy terrain of the scan experiments: two crossing waves and a shorter oblique one,
// slopes up to about 0.9, mean curvature between about -0.2 and 0.2 (unit: metres).
inline Height_field wavy_terrain()
{
  Height_field t;
  const double a = 1.5, wx = 1 / 4.0, wy = 1 / 5.0, b = 0.4, ux = 1 / 1.7, uy = 1 / 2.3;
  t.f = [=](double x, double y) { return a * std::sin(wx * x) * std::cos(wy * y) + b * std::sin(ux * x + uy * y); };
  t.max_height = a + b;
  t.slope_bound = 2;  // |grad f| <= a (wx + wy) + b (ux + uy) = 1.08
  t.derivatives = [=](double x, double y, double d1[2], double d2[3]) {
    const double sx = std::sin(wx * x), cx = std::cos(wx * x), sy = std::sin(wy * y), cy = std::cos(wy * y);
    const double s = std::sin(ux * x + uy * y), c = std::cos(ux * x + uy * y);
    d1[0] = a * wx * cx * cy + b * ux * c;
    d1[1] = -a * wy * sx * sy + b * uy * c;
    d2[0] = -a * wx * wx * sx * cy - b * ux * ux * s;
    d2[1] = -a * wx * wy * cx * sy - b * ux * uy * s;
    d2[2] = -a * wy * wy * sx * cy - b * uy * uy * s;
  };
  return t;
}

// A tilted plane z = 0.3 x - 0.2 y (zero curvature).
inline Height_field tilted_plane()
{
  Height_field t;
  t.f = [](double x, double y) { return 0.3 * x - 0.2 * y; };
  t.derivatives = [](double, double, double d1[2], double d2[3]) {
    d1[0] = 0.3;
    d1[1] = -0.2;
    d2[0] = d2[1] = d2[2] = 0;
  };
  return t;
}

// One scanned sample: its position, the scanner position it was seen from, and the truth.
struct Sample
{
  Point p;
  Point scanner;
  Truth truth;
};

struct Noise
{
  double range_sigma = 0;  // standard deviation of the range noise, along the ray
  double quantum = 0;      // coordinates rounded to multiples of it (0: none)
  unsigned seed = 2021;
};

// Casts one ray and appends its sample, if it hits within `keep`.
inline void cast(const Surface& s, const double o[3], const double d[3], const Noise& noise, std::mt19937_64& rng,
                 const std::function<bool(const double*)>& keep, std::vector<Sample>& out)
{
  const double t = s.first_hit(o, d);
  if(!(t > 0))
    return;
  double e = 0;
  if(noise.range_sigma > 0)
    e = std::normal_distribution<double>(0, noise.range_sigma)(rng);
  double x[3] = {o[0] + (t + e) * d[0], o[1] + (t + e) * d[1], o[2] + (t + e) * d[2]};
  double on[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
  if(!keep(on))
    return;
  if(noise.quantum > 0)
    for(double& c : x)
      c = noise.quantum * std::round(c / noise.quantum);
  Sample sample;
  sample.p = Point(x[0], x[1], x[2]);
  sample.scanner = Point(o[0], o[1], o[2]);
  sample.truth = noise.range_sigma > 0 || noise.quantum > 0 ? s.truth_at(x) : s.truth_at(on);
  out.push_back(sample);
}

// A terrestrial scanner at `o`: azimuth phi over [0, 2 pi) and elevation over
// [elevation_min, elevation_max] (radians), both at the fixed step `step`; rays in the order a
// scanner emits them (one vertical profile after the other).
inline void terrestrial_scan(const Surface& s, const double o[3], double step, double elevation_min,
                             double elevation_max, const Noise& noise, std::mt19937_64& rng,
                             const std::function<bool(const double*)>& keep, std::vector<Sample>& out)
{
  const int n_phi = int(std::floor(2 * M_PI / step));
  const int n_theta = int(std::floor((elevation_max - elevation_min) / step)) + 1;
  for(int i = 0; i < n_phi; ++i)
  {
    const double phi = i * step;
    for(int j = 0; j < n_theta; ++j)
    {
      const double theta = elevation_min + j * step;
      const double d[3] = {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
      cast(s, o, d, noise, rng, keep, out);
    }
  }
}

// The torus (R = 1, r = 0.4) seen from one terrestrial scanner at (0, -3, 1.6): about 20K
// points at the default step, the near side of the tube and part of the hole, with grazing
// angles at the silhouette.
inline std::vector<Sample> terrestrial_torus(const Noise& noise = Noise(), double step = 0.0042)
{
  const Torus torus(1.0, 0.4);
  std::mt19937_64 rng(noise.seed);
  std::vector<Sample> out;
  const double o[3] = {0, -3, 1.6};
  // only the rays towards the torus's bounding sphere matter: azimuths around -y... cast all
  // directions within the cone of the bounding sphere (radius 1.4 around the origin)
  const double dist = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
  const double half = std::asin(std::min(1.0, 1.45 / dist));
  const double to[3] = {-o[0] / dist, -o[1] / dist, -o[2] / dist};
  const double phi0 = std::atan2(to[1], to[0]), theta0 = std::asin(to[2]);
  const int n = int(std::ceil(half / step));
  for(int i = -n; i <= n; ++i)
    for(int j = -n; j <= n; ++j)
    {
      const double phi = phi0 + i * step, theta = theta0 + j * step;
      const double d[3] = {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
      cast(
        torus, o, d, noise, rng, [](const double*) { return true; }, out);
    }
  return out;
}

// How the mirror of an airborne scanner sweeps while the aircraft flies on (along +y).
enum class Sweep {
  PARALLEL,  // idealised: every line straight across the track, points aligned from line to line
  POLYGON,   // rotating polygon: every sweep in the same direction, so lines oblique and parallel
  ZIGZAG     // oscillating mirror: sweeps alternate, lines zigzag (0 and 2 line spacings apart
             // at the swath's edges, one at nadir)
};

// Airborne sweeps over a surface, from an aircraft at `altitude` above z = 0 flying along +y,
// the mirror sweeping the scan angle over [-max_angle, max_angle] so that points on a line are
// `point_spacing` apart at nadir, one line every `line_spacing`; points with x, y inside
// [-half_width, half_width] are kept. Except PARALLEL, the aircraft moves on during each
// sweep: the sweep starting at y0 ends at y0 + line_spacing. `offset` shifts the aircraft's track along x (in
// point spacings). With `wobble` > 0, each line starts at a random phase along x (the points
// of neighbouring lines no longer aligned) and each pulse leaves from a y moved by a normal
// deviate of standard deviation `wobble` (the aircraft's attitude): lines that are not
// straight.
inline std::vector<Sample> airborne_sweeps(const Surface& s, double half_width, double point_spacing,
                                           double line_spacing, Sweep sweep, const Noise& noise = Noise(),
                                           double wobble = 0, double altitude = 300, double max_angle = 0.35,
                                           double offset = 0.37)
{
  std::mt19937_64 rng(noise.seed);
  std::mt19937_64 attitude(noise.seed + 1);  // apart, so that the range noise is the same draw
  std::uniform_real_distribution<double> phase(0, 1);
  std::normal_distribution<double> deviate(0, 1);
  std::vector<Sample> out;
  const double angle_step = point_spacing / altitude;
  const int n_angles = int(std::floor(max_angle / angle_step));
  auto keep = [half_width](const double* x) { return std::abs(x[0]) <= half_width && std::abs(x[1]) <= half_width; };
  bool forward = true;
  // (moving sweeps start a line earlier: they end one line spacing farther on)
  const double first = -half_width - (sweep == Sweep::PARALLEL ? 1 : 2) * line_spacing;
  for(double y = first; y <= half_width + line_spacing; y += line_spacing)
  {
    const double start = wobble > 0 ? phase(attitude) : 0.0;
    for(int i = -n_angles; i <= n_angles; ++i)
    {
      const double f = sweep == Sweep::PARALLEL ? 0.0 : double(i + n_angles) / double(2 * n_angles);
      const double o[3] = {offset * point_spacing,
                           y + f * line_spacing + (wobble > 0 ? wobble * deviate(attitude) : 0.0), altitude};
      const double a = ((forward ? i : -i) + start) * angle_step;
      const double d[3] = {std::sin(a), 0, -std::cos(a)};
      cast(s, o, d, noise, rng, keep, out);
    }
    if(sweep != Sweep::POLYGON)  // (a parallel scan's rays alternate their order too)
      forward = !forward;
  }
  return out;
}

// Airborne scan lines over a surface: PARALLEL sweeps, every line straight across the track
// (along x), points aligned from line to line.
inline std::vector<Sample> airborne_lines(const Surface& s, double half_width, double point_spacing,
                                          double line_spacing, const Noise& noise = Noise(), double altitude = 300,
                                          double max_angle = 0.35)
{
  return airborne_sweeps(s, half_width, point_spacing, line_spacing, Sweep::PARALLEL, noise, 0, altitude, max_angle);
}

// A mobile mapping system: a vehicle driving along +y on the height field, its profiler
// `height` above the ground at x = 0 turning in the plane across the road (the x-z plane),
// one profile every `profile_spacing` along y and one ray every `angle_step` radians in it:
// points dense along a profile near the vehicle and sparser away from it, profiles far apart
// (at 5 m from the track, 0.1 m between profiles and 0.0175 m along one at the default step).
// Points with |x| <= half_width, |y| <= half_width are kept.
inline std::vector<Sample> mobile_profiles(const Height_field& s, double half_width = 8, double profile_spacing = 0.1,
                                           double angle_step = 0.0035, const Noise& noise = Noise(),
                                           double height = 2.0)
{
  std::mt19937_64 rng(noise.seed);
  std::vector<Sample> out;
  auto keep = [half_width](const double* x) { return std::abs(x[0]) <= half_width && std::abs(x[1]) <= half_width; };
  const int n = int(std::floor(2 * M_PI / angle_step));
  for(double y = -half_width - profile_spacing; y <= half_width + profile_spacing; y += profile_spacing)
  {
    const double o[3] = {0, y, s.f(0, y) + height};
    for(int i = 0; i < n; ++i)
    {
      const double a = i * angle_step;
      const double d[3] = {std::cos(a), 0, std::sin(a)};
      if(d[2] < -0.05)  // the rays that reach the ground not far from the vehicle
        cast(s, o, d, noise, rng, keep, out);
    }
  }
  return out;
}

// A spinning multi-beam scanner (a car-roof LiDAR) standing still `height` above the height
// field at (x0, y0): `beams` lasers at elevations evenly spread over [elevation_min,
// elevation_max] (radians, below the horizon), each turning through a full circle at the
// azimuth step `azimuth_step`. Each beam draws a ring on the ground: points 1-4 cm apart along it,
// rings 0.2 m apart near the car and more than 1 m apart at 10 m (the pattern whose
// neighbourhoods lie along one ring). Points with |x|, |y| <= half_width are kept.
inline std::vector<Sample> multibeam_rings(const Height_field& s, double half_width = 12, int beams = 32,
                                           double elevation_min = -0.535, double elevation_max = -0.023,
                                           double azimuth_step = 0.0035, const Noise& noise = Noise(),
                                           double height = 2.0, double x0 = 0.3, double y0 = -0.7)
{
  std::mt19937_64 rng(noise.seed);
  std::vector<Sample> out;
  auto keep = [half_width](const double* x) { return std::abs(x[0]) <= half_width && std::abs(x[1]) <= half_width; };
  const double o[3] = {x0, y0, s.f(x0, y0) + height};
  const int n = int(std::floor(2 * M_PI / azimuth_step));
  for(int b = 0; b < beams; ++b)
  {
    const double e = elevation_min + (elevation_max - elevation_min) * b / std::max(1, beams - 1);
    for(int i = 0; i < n; ++i)
    {
      const double a = i * azimuth_step;
      const double d[3] = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
      cast(s, o, d, noise, rng, keep, out);
    }
  }
  return out;
}

// A Risley-prism scanner (the rosette of solid-state LiDARs) looking down from a drone
// `altitude` above z = 0 at (x0, y0): the ray's tilt is the sum of two vectors of length
// half_angle / 2 turning in opposite directions at slightly different rates, so that the
// rosette's petals precess and cross one another at every angle; `points` rays at a fixed time
// step over `petals` petals. Dense at the centre and at the petals' tips, sparser between
// them. Points with |x|, |y| <= half_width are kept.
inline std::vector<Sample> rosette(const Surface& s, double half_width = 12, std::size_t points = 160000,
                                   double petals = 400, const Noise& noise = Noise(), double altitude = 40,
                                   double half_angle = 0.33, double x0 = 0.2, double y0 = -0.4)
{
  std::mt19937_64 rng(noise.seed);
  std::vector<Sample> out;
  auto keep = [half_width](const double* x) { return std::abs(x[0]) <= half_width && std::abs(x[1]) <= half_width; };
  const double o[3] = {x0, y0, altitude};
  // a petal every pi / ((w1 - w2) / 2) of time; the pattern turns at (w1 + w2) / 2
  const double w1 = 1.0, w2 = -1.0937;
  const double duration = petals * M_PI / ((w1 - w2) / 2), dt = duration / double(points);
  for(std::size_t i = 0; i < points; ++i)
  {
    const double t = i * dt;
    const double tx = 0.5 * half_angle * (std::cos(w1 * t) + std::cos(w2 * t));
    const double ty = 0.5 * half_angle * (std::sin(w1 * t) + std::sin(w2 * t));
    const double norm = std::sqrt(1 + tx * tx + ty * ty);
    const double d[3] = {tx / norm, ty / norm, -1 / norm};
    cast(s, o, d, noise, rng, keep, out);
  }
  return out;
}

// Two terrestrial scans of a height field from tripods `height` above the ground at
// (-6, -2) and (5, 4), merged: each keeps the points between 2 and `reach` (horizontally)
// from it inside the square [-half_width, half_width]^2. Grazing rays: the spacing along a
// scanner's radial direction grows like the distance squared. `station_count` 1 keeps the first scan only.
inline std::vector<Sample> merged_terrestrial(const Height_field& s, double half_width = 12, double step = 0.006,
                                              double reach = 12, const Noise& noise = Noise(), double height = 1.8,
                                              int station_count = 2)
{
  std::mt19937_64 rng(noise.seed);
  std::vector<Sample> out;
  const double stations[2][2] = {{-6, -2}, {5, 4}};
  for(int k = 0; k < station_count && k < 2; ++k)
  {
    const auto& st = stations[k];
    const double o[3] = {st[0], st[1], s.f(st[0], st[1]) + height};
    auto keep = [&](const double* x) {
      const double h = std::hypot(x[0] - st[0], x[1] - st[1]);
      return h >= 2 && h <= reach && std::abs(x[0]) <= half_width && std::abs(x[1]) <= half_width;
    };
    // elevations from -pi/2 + a little to slightly below the horizon suffice for terrain
    terrestrial_scan(s, o, step, -1.3, 0.15, noise, rng, keep, out);
  }
  return out;
}

// The points of samples as oriented points (the true normals).
inline std::vector<Oriented_point> with_true_normals(const std::vector<Sample>& samples)
{
  std::vector<Oriented_point> pts;
  pts.reserve(samples.size());
  for(const Sample& s : samples)
    pts.emplace_back(s.p, s.truth.normal);
  return pts;
}

// The median distance from a sample to its nearest other sample (brute force on a grid).
inline double median_spacing(const std::vector<Sample>& samples)
{
  if(samples.size() < 2)
    return 0;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const Sample& s : samples)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], s.p[a]);
      hi[a] = std::max(hi[a], s.p[a]);
    }
  const double diag = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double cell = std::max(diag / std::cbrt(double(samples.size())), 1e-12);
  auto key = [&](const Point& p, int a) { return static_cast<long long>(std::floor((p[a] - lo[a]) / cell)); };
  std::vector<std::pair<std::uint64_t, std::uint32_t> > keyed;
  const long long m = static_cast<long long>(std::floor(diag / cell)) + 3;
  auto pack = [m](long long x, long long y, long long z) { return std::uint64_t((x * m + y) * m + z); };
  for(std::uint32_t i = 0; i < samples.size(); ++i)
    keyed.emplace_back(pack(key(samples[i].p, 0), key(samples[i].p, 1), key(samples[i].p, 2)), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<double> nearest(samples.size(), 1e300);
  for(std::uint32_t i = 0; i < samples.size(); ++i)
  {
    const Point& p = samples[i].p;
    const long long c[3] = {key(p, 0), key(p, 1), key(p, 2)};
    for(long long dx = -1; dx <= 1; ++dx)
      for(long long dy = -1; dy <= 1; ++dy)
        for(long long dz = -1; dz <= 1; ++dz)
        {
          if(c[0] + dx < 0 || c[1] + dy < 0 || c[2] + dz < 0)
            continue;
          const std::uint64_t k = pack(c[0] + dx, c[1] + dy, c[2] + dz);
          auto it = std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(k, std::uint32_t(0)));
          for(; it != keyed.end() && it->first == k; ++it)
            if(it->second != i)
              nearest[i] = std::min(nearest[i], std::sqrt(CGAL::squared_distance(p, samples[it->second].p)));
        }
  }
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

// The samples `scan(noise)` gives with a range noise of `share` times the median spacing of the same
// scan without noise (the unit of benchmark/scan_experiments' --noise); `scan` takes a Noise.
template <class Scan>
std::vector<Sample> with_range_noise(double share, const Scan& scan)
{
  Noise noise;
  noise.range_sigma = share * median_spacing(scan(Noise()));
  return scan(noise);
}

}  // namespace scan
}  // namespace psc_test

#endif
