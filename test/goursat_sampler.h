// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Blue-noise samples of the Goursat surface of Lejemble et al. 2021, Section 6.1:
//
//   F(x) = -8 - 2 (x² + y² + z²) + 0.03 (x⁴ + y⁴ + z⁴) = 0,   outward normal ∇F/|∇F|.
//
// The surface is star-shaped around the origin: along a unit direction u, with
// s(u) = u_x⁴ + u_y⁴ + u_z⁴, F(t u) = -8 - 2 t² + 0.03 s t⁴ has exactly one positive root
// t(u)² = (2 + sqrt(4 + 0.96 s)) / (0.06 s). Every point handed out is t(u) u computed from
// that closed form, so it lies on the surface to rounding error (measured below 1e-14 of the
// bounding-box diagonal), and its normal is the exact normalised gradient.
//
// Sampling (deterministic for a seed, same result sequential or parallel):
//   1. area-uniform random points: directions uniform on the sphere, mapped to t(u) u and
//      kept with probability proportional to the area element t²/(n·u) (rejection);
//   2. Lloyd relaxation on the surface: every point moves to the centroid of its Voronoi
//      cell restricted to its tangent plane (the 3-D bisector planes of its neighbours cut
//      the tangent plane), then back onto the surface along its direction from the origin.
//      All points move at once from the previous positions (Jacobi), hence determinism.
// The spacing histogram of the result is measured against the shared samples of the
// same surface in benchmark/README.md.

#ifndef PSC_BENCHMARK_GOURSAT_SAMPLER_H
#define PSC_BENCHMARK_GOURSAT_SAMPLER_H

#include <CGAL/Simple_cartesian.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace goursat {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Oriented_point;

inline double implicit(const double p[3])
{
  const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  const double r4 = p[0] * p[0] * p[0] * p[0] + p[1] * p[1] * p[1] * p[1] + p[2] * p[2] * p[2] * p[2];
  return -8 - 2 * r2 + 0.03 * r4;
}

inline void gradient(const double p[3], double g[3])
{
  for(int i = 0; i < 3; ++i)
    g[i] = -4 * p[i] + 0.12 * p[i] * p[i] * p[i];
}

// Distance estimate |F|/|∇F| (first order, exact to O(d²)): the projection residual.
inline double residual(const double p[3])
{
  double g[3];
  gradient(p, g);
  return std::abs(implicit(p)) / std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

// Distance from the origin to the surface along the unit direction u (closed form above).
inline double radial_distance(const double u[3])
{
  const double s = u[0] * u[0] * u[0] * u[0] + u[1] * u[1] * u[1] * u[1] + u[2] * u[2] * u[2] * u[2];
  return std::sqrt((2 + std::sqrt(4 + 0.96 * s)) / (0.06 * s));
}

// Surface point in the direction of any non-zero v, written into p.
inline void project_radially(const double v[3], double p[3])
{
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const double u[3] = {v[0] / l, v[1] / l, v[2] / l};
  const double t = radial_distance(u);
  for(int i = 0; i < 3; ++i)
    p[i] = t * u[i];
}

inline void unit_normal(const double p[3], double n[3])
{
  gradient(p, n);
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for(int i = 0; i < 3; ++i)
    n[i] /= l;
}

// Area element of the radial parametrisation: dA = t² / (n·u) dω.
inline double area_density(const double u[3])
{
  const double t = radial_distance(u);
  const double p[3] = {t * u[0], t * u[1], t * u[2]};
  double n[3];
  unit_normal(p, n);
  return t * t / (n[0] * u[0] + n[1] * u[1] + n[2] * u[2]);
}

// Fibonacci directions: a deterministic, nearly uniform quadrature of the sphere.
template <class F>
void for_each_fibonacci_direction(std::size_t m, F f)
{
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for(std::size_t i = 0; i < m; ++i)
  {
    const double z = 1 - 2 * (double(i) + 0.5) / double(m);
    const double rho = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = golden * double(i);
    const double u[3] = {rho * std::cos(phi), rho * std::sin(phi), z};
    f(u);
  }
}

struct Surface_constants
{
  double area = 0;         // surface area
  double half_extent = 0;  // the bounding box is [-half_extent, half_extent]^3
  double diagonal = 0;     // bounding-box diagonal, 2 sqrt(3) half_extent
  double max_area_density = 0;
};

// Area by quadrature of the area element over 2M Fibonacci directions (relative error
// below 1e-6: doubling the count changes it by less); extent by maximising |x| over the same
// directions, then refining along the best direction's neighbourhood.
inline const Surface_constants& surface_constants()
{
  static const Surface_constants c = [] {
    Surface_constants k;
    const std::size_t m = 2000000;
    double sum = 0, best = 0;
    double best_u[3] = {1, 0, 0};
    for_each_fibonacci_direction(m, [&](const double* u) {
      const double a = area_density(u);
      sum += a;
      k.max_area_density = std::max(k.max_area_density, a);
      const double t = radial_distance(u);
      if(t * u[0] > best)
      {
        best = t * u[0];
        std::copy(u, u + 3, best_u);
      }
    });
    // Local refinement of max x over directions (pattern search, step halving).
    double step = 0.01;
    while(step > 1e-12)
    {
      bool moved = false;
      for(int axis = 0; axis < 3 && !moved; ++axis)
        for(double sign : {-1.0, 1.0})
        {
          double v[3] = {best_u[0], best_u[1], best_u[2]};
          v[axis] += sign * step;
          double p[3];
          project_radially(v, p);
          if(p[0] > best)
          {
            best = p[0];
            const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            for(int i = 0; i < 3; ++i)
              best_u[i] = p[i] / l;
            moved = true;
            break;
          }
        }
      if(!moved)
        step *= 0.5;
    }
    k.area = sum * 4 * M_PI / double(m);
    k.half_extent = best;
    k.diagonal = 2 * std::sqrt(3.0) * best;
    return k;
  }();
  return c;
}

// Portable randomness: std::mt19937_64's output is fixed by the standard; the
// distributions of <random> are not, so the conversions are done here.
class Random
{
public:
  explicit Random(std::uint64_t seed) : m_engine(seed) {}
  double uniform() { return double(m_engine() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
  double gaussian()
  {
    if(m_has_spare)
    {
      m_has_spare = false;
      return m_spare;
    }
    double u1;
    do
      u1 = uniform();
    while(u1 <= 0);
    const double u2 = uniform();
    const double r = std::sqrt(-2 * std::log(u1));
    m_spare = r * std::sin(2 * M_PI * u2);
    m_has_spare = true;
    return r * std::cos(2 * M_PI * u2);
  }
  void unit_vector(double u[3])
  {
    double l;
    do
    {
      for(int i = 0; i < 3; ++i)
        u[i] = gaussian();
      l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    } while(l < 1e-12);
    for(int i = 0; i < 3; ++i)
      u[i] /= l;
  }

private:
  std::mt19937_64 m_engine;
  bool m_has_spare = false;
  double m_spare = 0;
};

// Uniform hash grid for ball queries of radius <= cell on a point set stored as xyz triples.
class Hash_grid
{
public:
  Hash_grid(const std::vector<double>& xyz, double cell) : m_xyz(xyz), m_cell(cell)
  {
    const std::size_t n = xyz.size() / 3;
    std::vector<std::pair<std::uint64_t, std::uint32_t> > keyed(n);
    for(std::size_t i = 0; i < n; ++i)
      keyed[i] = {key_of(&xyz[3 * i]), std::uint32_t(i)};
    std::sort(keyed.begin(), keyed.end());
    m_order.resize(n);
    std::size_t cells = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      m_order[i] = keyed[i].second;
      if(i == 0 || keyed[i].first != keyed[i - 1].first)
        ++cells;
    }
    std::size_t size = 16;
    while(size < 2 * cells)
      size *= 2;
    m_mask = size - 1;
    m_slots.assign(size, Slot());
    for(std::size_t i = 0; i < n;)
    {
      std::size_t j = i;
      while(j < n && keyed[j].first == keyed[i].first)
        ++j;
      std::size_t s = hash(keyed[i].first) & m_mask;
      while(m_slots[s].end != 0)
        s = (s + 1) & m_mask;
      m_slots[s] = Slot{keyed[i].first, std::uint32_t(i), std::uint32_t(j)};
      i = j;
    }
  }

  // Calls f(index, squared distance) for every point at distance < radius (radius <= cell).
  template <class F>
  void for_each_in_ball(const double q[3], double radius, F f) const
  {
    const double r2 = radius * radius;
    long c[3];
    for(int i = 0; i < 3; ++i)
      c[i] = cell_coordinate(q[i]);
    for(long dx = -1; dx <= 1; ++dx)
      for(long dy = -1; dy <= 1; ++dy)
        for(long dz = -1; dz <= 1; ++dz)
        {
          const Slot* s = find(pack(c[0] + dx, c[1] + dy, c[2] + dz));
          if(s == nullptr)
            continue;
          for(std::uint32_t k = s->begin; k < s->end; ++k)
          {
            const std::uint32_t j = m_order[k];
            const double* p = &m_xyz[3 * j];
            const double d2 =
              (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
            if(d2 < r2)
              f(j, d2);
          }
        }
  }

  // Point indices in cell order (spatially coherent).
  const std::vector<std::uint32_t>& order() const { return m_order; }

private:
  struct Slot
  {
    std::uint64_t key = 0;
    std::uint32_t begin = 0, end = 0;  // end == 0: empty slot
  };

  long cell_coordinate(double x) const { return long(std::floor(x / m_cell)) + (1L << 20); }
  static std::uint64_t pack(long x, long y, long z)
  {
    return (std::uint64_t(x) << 42) | (std::uint64_t(y) << 21) | std::uint64_t(z);
  }
  std::uint64_t key_of(const double* p) const
  {
    return pack(cell_coordinate(p[0]), cell_coordinate(p[1]), cell_coordinate(p[2]));
  }
  static std::uint64_t hash(std::uint64_t k)
  {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return k;
  }
  const Slot* find(std::uint64_t key) const
  {
    std::size_t s = hash(key) & m_mask;
    while(m_slots[s].end != 0)
    {
      if(m_slots[s].key == key)
        return &m_slots[s];
      s = (s + 1) & m_mask;
    }
    return nullptr;
  }

  const std::vector<double>& m_xyz;
  double m_cell;
  std::vector<std::uint32_t> m_order;
  std::vector<Slot> m_slots;
  std::size_t m_mask = 0;
};

template <class F>
void parallel_for_each_index(std::size_t n, bool parallel, F f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
      for(std::size_t i = r.begin(); i != r.end(); ++i)
        f(i);
    });
    return;
  }
#endif
  (void)parallel;
  for(std::size_t i = 0; i < n; ++i)
    f(i);
}

inline void tangent_frame(const double n[3], double t1[3], double t2[3])
{
  double a[3] = {1, 0, 0};
  if(std::abs(n[0]) > 0.6)
  {
    a[0] = 0;
    a[1] = 1;
  }
  const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
  for(int i = 0; i < 3; ++i)
    t1[i] = a[i] - an * n[i];
  const double l = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for(int i = 0; i < 3; ++i)
    t1[i] /= l;
  t2[0] = n[1] * t1[2] - n[2] * t1[1];
  t2[1] = n[2] * t1[0] - n[0] * t1[2];
  t2[2] = n[0] * t1[1] - n[1] * t1[0];
}

// Convex polygon in the tangent plane, clipped by half-planes {x : a·x <= b}.
struct Polygon2
{
  static const int capacity = 64;
  double x[capacity], y[capacity];
  int size = 0;

  void clip(double ax, double ay, double b)
  {
    double nx[capacity], ny[capacity];
    int m = 0;
    for(int i = 0; i < size; ++i)
    {
      const int j = (i + 1) % size;
      const double si = ax * x[i] + ay * y[i] - b, sj = ax * x[j] + ay * y[j] - b;
      if(si <= 0 && m < capacity)
      {
        nx[m] = x[i];
        ny[m++] = y[i];
      }
      if(((si < 0 && sj > 0) || (si > 0 && sj < 0)) && m < capacity)
      {
        const double t = si / (si - sj);
        nx[m] = x[i] + t * (x[j] - x[i]);
        ny[m++] = y[i] + t * (y[j] - y[i]);
      }
    }
    size = m;
    std::copy(nx, nx + m, x);
    std::copy(ny, ny + m, y);
  }

  double max_squared_radius() const
  {
    double r = 0;
    for(int i = 0; i < size; ++i)
      r = std::max(r, x[i] * x[i] + y[i] * y[i]);
    return r;
  }

  // Area centroid; false if degenerate.
  bool centroid(double& cx, double& cy) const
  {
    double a = 0, sx = 0, sy = 0;
    for(int i = 0; i < size; ++i)
    {
      const int j = (i + 1) % size;
      const double c = x[i] * y[j] - x[j] * y[i];
      a += c;
      sx += (x[i] + x[j]) * c;
      sy += (y[i] + y[j]) * c;
    }
    if(!(std::abs(a) > 0))
      return false;
    cx = sx / (3 * a);
    cy = sy / (3 * a);
    return true;
  }
};

struct Sampling_options
{
  std::size_t size = 10000;
  std::uint64_t seed = 1;
  // Lloyd iterations. The coefficient of variation of the nearest-neighbour distance
  // (10K points) goes from 0.52 (uniform random) to 0.13 after 6 iterations, 0.105 after
  // 10 and 0.08 after 20; the shared reference samples have 0.36-0.38. 10 iterations cost
  // about 1.6 µs per point each (one core).
  int lloyd_iterations = 10;
  bool parallel = true;
};

// Area-uniform random points of the surface (stage 1), as xyz triples.
inline std::vector<double> uniform_random_points(std::size_t n, Random& random)
{
  const double bound = surface_constants().max_area_density * 1.05;
  std::vector<double> xyz;
  xyz.reserve(3 * n);
  while(xyz.size() < 3 * n)
  {
    double u[3];
    random.unit_vector(u);
    const double a = area_density(u);
    if(a > bound)
      throw std::logic_error("goursat: area density bound too small");
    if(random.uniform() * bound < a)
    {
      const double t = radial_distance(u);
      for(int i = 0; i < 3; ++i)
        xyz.push_back(t * u[i]);
    }
  }
  return xyz;
}

// One Lloyd step on the surface; returns the mean displacement divided by the mean spacing h.
// `search` is the neighbour search radius in units of h (see lloyd_search_radius).
inline double lloyd_step(std::vector<double>& xyz, bool parallel, double search_in_h = 2.5,
                         std::size_t* incomplete_cells = nullptr)
{
  const std::size_t n = xyz.size() / 3;
  const double h = std::sqrt(surface_constants().area / double(n));
  const double search = search_in_h * h;
  const Hash_grid grid(xyz, search);
  std::vector<double> next(xyz.size());
  std::vector<double> moved(n);
  std::vector<unsigned char> incomplete(incomplete_cells != nullptr ? n : 0, 0);
  const std::vector<std::uint32_t>& order = grid.order();
  parallel_for_each_index(n, parallel, [&](std::size_t k) {
    const std::uint32_t i = order[k];
    const double* p = &xyz[3 * i];
    double nrm[3], t1[3], t2[3];
    unit_normal(p, nrm);
    tangent_frame(nrm, t1, t2);
    // neighbours sorted by distance
    std::array<std::pair<double, std::uint32_t>, 96> nb;
    std::size_t count = 0;
    grid.for_each_in_ball(p, search, [&](std::uint32_t j, double d2) {
      if(j != i && count < nb.size())
        nb[count++] = {d2, j};
    });
    std::sort(nb.begin(), nb.begin() + count);
    Polygon2 cell;
    const double half = 0.5 * search;
    const double sx[4] = {-half, half, half, -half}, sy[4] = {-half, -half, half, half};
    for(int c = 0; c < 4; ++c)
    {
      cell.x[c] = sx[c];
      cell.y[c] = sy[c];
    }
    cell.size = 4;
    double cell_radius2 = 2 * half * half;
    for(std::size_t c = 0; c < count; ++c)
    {
      // A neighbour farther than twice the cell's radius cannot cut it (nor can the
      // following ones, sorted by distance).
      if(nb[c].first > 4 * cell_radius2)
        break;
      const double* q = &xyz[3 * nb[c].second];
      const double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
      // 3-D bisector plane 2 x·d <= |d|² restricted to the tangent plane x = a t1 + b t2.
      const double a = d[0] * t1[0] + d[1] * t1[1] + d[2] * t1[2];
      const double b = d[0] * t2[0] + d[1] * t2[1] + d[2] * t2[2];
      cell.clip(2 * a, 2 * b, nb[c].first);
      cell_radius2 = cell.max_squared_radius();
    }
    if(incomplete_cells != nullptr && 4 * cell.max_squared_radius() > search * search)
      incomplete[i] = 1;
    double cx = 0, cy = 0;
    if(!cell.centroid(cx, cy))
      cx = cy = 0;
    const double v[3] = {p[0] + cx * t1[0] + cy * t2[0], p[1] + cx * t1[1] + cy * t2[1],
                         p[2] + cx * t1[2] + cy * t2[2]};
    project_radially(v, &next[3 * i]);
    const double* q = &next[3 * i];
    moved[i] = std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
  });
  xyz.swap(next);
  if(incomplete_cells != nullptr)
    *incomplete_cells = std::size_t(std::count(incomplete.begin(), incomplete.end(), 1));
  double sum = 0;
  for(double m : moved)
    sum += m;
  return sum / double(n) / h;
}

// Neighbour search radius of Lloyd iteration `it`, in units of h = sqrt(area / n). A
// neighbour at distance d can cut a cell only if d < 2 x (the cell's largest vertex
// distance). Cells of uniform random points need a wide search; after two iterations 2 h
// is enough for almost every cell. Cells that may miss a cutting neighbour (counted by
// lloyd_step(..., incomplete_cells), 200K points): 13% at iteration 0 (2.5 h), 3% at
// iteration 2 (2 h), 0.04% at iteration 6, none from iteration 9 on. Such a cell is only
// too large, which slows the early iterations down without biasing the final ones.
inline double lloyd_search_radius(int it) { return it < 2 ? 2.5 : 2.0; }

// `n` area-uniform i.i.d. points of the surface (stage 1 only, no relaxation) with their
// exact outward unit normals.
inline std::vector<Oriented_point> iid_sample(std::size_t n, std::uint64_t seed)
{
  Random random(seed);
  const std::vector<double> xyz = uniform_random_points(n, random);
  std::vector<Oriented_point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    double nv[3];
    unit_normal(&xyz[3 * i], nv);
    points.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), Vector(nv[0], nv[1], nv[2]));
  }
  return points;
}

// The sample: positions on the surface with exact outward unit normals.
inline std::vector<Oriented_point> sample(const Sampling_options& options)
{
  if(options.size < 4)
    throw std::invalid_argument("goursat::sample: size must be at least 4");
  Random random(options.seed);
  std::vector<double> xyz = uniform_random_points(options.size, random);
  for(int it = 0; it < options.lloyd_iterations; ++it)
    lloyd_step(xyz, options.parallel, lloyd_search_radius(it));
  std::vector<Oriented_point> points;
  points.reserve(options.size);
  for(std::size_t i = 0; i < options.size; ++i)
  {
    double n[3];
    unit_normal(&xyz[3 * i], n);
    points.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), Vector(n[0], n[1], n[2]));
  }
  return points;
}

// Largest projection residual |F|/|∇F| of a set of points, divided by the diagonal.
inline double max_relative_residual(const std::vector<Oriented_point>& points)
{
  double worst = 0;
  for(const Oriented_point& op : points)
  {
    const double p[3] = {op.first.x(), op.first.y(), op.first.z()};
    worst = std::max(worst, residual(p));
  }
  return worst / surface_constants().diagonal;
}

// Nearest-neighbour distance of every point divided by h = sqrt(area / n) (h is the
// spacing of a square grid of the same density; a hexagonal one has 1.075 h).
inline std::vector<double> nearest_neighbor_spacing(const std::vector<Oriented_point>& points, bool parallel = true)
{
  const std::size_t n = points.size();
  std::vector<double> xyz(3 * n);
  for(std::size_t i = 0; i < n; ++i)
  {
    xyz[3 * i] = points[i].first.x();
    xyz[3 * i + 1] = points[i].first.y();
    xyz[3 * i + 2] = points[i].first.z();
  }
  const double h = std::sqrt(surface_constants().area / double(n));
  const double search = 3 * h;
  const Hash_grid grid(xyz, search);
  std::vector<double> out(n);
  parallel_for_each_index(n, parallel, [&](std::size_t i) {
    double best = search * search;
    grid.for_each_in_ball(&xyz[3 * i], search, [&](std::uint32_t j, double d2) {
      if(j != i)
        best = std::min(best, d2);
    });
    out[i] = std::sqrt(best) / h;
  });
  return out;
}

}  // namespace goursat

#endif
