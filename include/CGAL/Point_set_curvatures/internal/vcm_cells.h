// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Voronoi cells of the VCM (vcm.h), cut by the offset ball, and their covariance
// matrices: the same quantities as CGAL::compute_vcm() (CGAL 5.5), computed so that they
// are reproducible bit for bit.
//
// CGAL's compute_vcm() intersects, for each point p, the half-spaces of the bisector planes
// of p and its Delaunay neighbours with the 20 half-spaces of a polytope approximating the
// ball of radius R around p (the planes tangent to the sphere at the 20 vertices of a
// regular dodecahedron: an icosahedron), through halfspace_intersection_with_constructions_3
// and convex_hull_3. That convex hull keeps the boundary edges of its visible sets in a
// std::map keyed by vertex handles (addresses): the order in which it builds faces, hence
// the rounding of the cell's vertices, depends on where the allocator put them. Measured on
// an 80-point sphere: two runs of the same program give different covariances (one of
// three results at random); with address-space randomisation off (setarch -R), always the
// same.
//
// Here the cell is the icosahedron clipped by each bisector half-space in turn (Sutherland-
// Hodgman on every face, the section closing it as a new face), the neighbours taken in the
// order of their input index, each computation from data alone: the same input gives the
// same bits, on any thread, in any process. A crossing point is computed from the edge's
// inside end towards its outside end, so that the two faces sharing an edge get the same
// point. The covariance (about p) is the sum over the faces, fanned into triangles (a, b,
// c), of the second moment of the tetrahedron (p, a, b, c):
//
//   integral of x xᵀ = |det(a, b, c)| / 120 (a aᵀ + b bᵀ + c cᵀ + s sᵀ),  s = a + b + c,
//
// p being inside its convex cell, every such tetrahedron lies in the cell.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_VCM_CELLS_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_VCM_CELLS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// A convex polytope as a list of faces, each a convex polygon (its vertices in order, either
// orientation), in coordinates centred at the cell's point.
struct Vcm_polytope
{
  std::vector<double> xyz;              // the faces' vertices, one after the other
  std::vector<std::uint32_t> begin{0};  // face f holds vertices begin[f] to begin[f + 1] - 1

  std::size_t faces() const { return begin.size() - 1; }
  void clear()
  {
    xyz.clear();
    begin.assign(1, 0);
  }
  void add_vertex(const double* v) { xyz.insert(xyz.end(), v, v + 3); }
  // closes the face made of the vertices added since the last one (dropped if fewer than 3)
  void end_face()
  {
    const std::uint32_t n = static_cast<std::uint32_t>(xyz.size() / 3);
    if(n - begin.back() >= 3)
      begin.push_back(n);
    else
      xyz.resize(3 * std::size_t(begin.back()));
  }
};

// Scratch of one thread.
struct Vcm_cell_scratch
{
  Vcm_polytope cell, next;
  std::vector<double> side;                                          // per vertex of `cell`: n.x - c
  std::vector<std::array<double, 3> > section;                       // the points of the cut
  std::vector<std::tuple<double, double, double, double> > ordered;  // (angle, x, y, z)
};

// Clips `s.cell` by the half-space n.x <= c (c > 0: the origin is inside). Returns false if
// no vertex is outside (the cell is left as it is, bit for bit).
inline bool clip_vcm_cell(const double n[3], double c, Vcm_cell_scratch& s)
{
  const Vcm_polytope& P = s.cell;
  const std::size_t vertices = P.xyz.size() / 3;
  s.side.resize(vertices);
  bool outside = false;
  for(std::size_t v = 0; v < vertices; ++v)
  {
    const double* x = &P.xyz[3 * v];
    s.side[v] = n[0] * x[0] + n[1] * x[1] + n[2] * x[2] - c;
    outside = outside || s.side[v] > 0;
  }
  if(!outside)
    return false;
  Vcm_polytope& Q = s.next;
  Q.clear();
  s.section.clear();
  for(std::size_t f = 0; f < P.faces(); ++f)
  {
    const std::uint32_t b = P.begin[f], e = P.begin[f + 1];
    for(std::uint32_t i = b; i < e; ++i)
    {
      const std::uint32_t j = i + 1 < e ? i + 1 : b;
      const double si = s.side[i], sj = s.side[j];
      const double* xi = &P.xyz[3 * std::size_t(i)];
      if(si <= 0)
      {
        Q.add_vertex(xi);
        if(si == 0)
          s.section.push_back({{xi[0], xi[1], xi[2]}});
      }
      if((si < 0 && sj > 0) || (si > 0 && sj < 0))
      {
        // from the inside end to the outside end, whichever face asks
        const std::uint32_t in = si < 0 ? i : j, out = si < 0 ? j : i;
        const double s_in = s.side[in], s_out = s.side[out];
        const double t = s_in / (s_in - s_out);
        const double* a = &P.xyz[3 * std::size_t(in)];
        const double* o = &P.xyz[3 * std::size_t(out)];
        const double x[3] = {a[0] + t * (o[0] - a[0]), a[1] + t * (o[1] - a[1]), a[2] + t * (o[2] - a[2])};
        Q.add_vertex(x);
        s.section.push_back({{x[0], x[1], x[2]}});
      }
    }
    Q.end_face();
  }
  // The section: its distinct points in angular order around their centroid.
  std::sort(s.section.begin(), s.section.end());
  s.section.erase(std::unique(s.section.begin(), s.section.end()), s.section.end());
  if(s.section.size() >= 3)
  {
    double centre[3] = {0, 0, 0};
    for(const auto& p : s.section)
      for(int a = 0; a < 3; ++a)
        centre[a] += p[a];
    for(int a = 0; a < 3; ++a)
      centre[a] /= double(s.section.size());
    // an orthonormal basis (u, w) of the plane
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double m[3] = {n[0] / nn, n[1] / nn, n[2] / nn};
    const int k = std::abs(m[0]) <= std::abs(m[1]) && std::abs(m[0]) <= std::abs(m[2]) ? 0
                  : std::abs(m[1]) <= std::abs(m[2])                                   ? 1
                                                                                       : 2;
    double u[3] = {0, 0, 0};
    u[k] = 1;
    const double d = u[0] * m[0] + u[1] * m[1] + u[2] * m[2];
    for(int a = 0; a < 3; ++a)
      u[a] -= d * m[a];
    const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for(int a = 0; a < 3; ++a)
      u[a] /= lu;
    const double w[3] = {m[1] * u[2] - m[2] * u[1], m[2] * u[0] - m[0] * u[2], m[0] * u[1] - m[1] * u[0]};
    s.ordered.clear();
    for(const auto& p : s.section)
    {
      const double r[3] = {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
      s.ordered.emplace_back(
        std::atan2(r[0] * w[0] + r[1] * w[1] + r[2] * w[2], r[0] * u[0] + r[1] * u[1] + r[2] * u[2]), p[0], p[1], p[2]);
    }
    std::sort(s.ordered.begin(), s.ordered.end());
    for(const auto& o : s.ordered)
    {
      const double x[3] = {std::get<1>(o), std::get<2>(o), std::get<3>(o)};
      Q.add_vertex(x);
    }
    Q.end_face();
  }
  std::swap(s.cell, s.next);
  return true;
}

// The polytope of CGAL's Sphere_discretization (N = 20) for the ball of radius R centred at
// the origin: the half-spaces n.x <= R for the 20 unit vectors (+-1, +-1, +-1)/sqrt(3),
// (0, +-1/phi, +-phi)/sqrt(3), (+-1/phi, +-phi, 0)/sqrt(3), (+-phi, 0, +-1/phi)/sqrt(3),
// cut from a cube of half-side 2R (its corners are 2 sqrt(3) R away, beyond the
// icosahedron's vertices at 1.26 R).
inline void vcm_ball_polytope(double R, Vcm_cell_scratch& s)
{
  Vcm_polytope& P = s.cell;
  P.clear();
  const double h = 2 * R;
  // the cube's six faces, counter-clockwise seen from outside
  static const int corners[6][4][3] = {
    {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}, {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
    {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}, {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
    {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}}, {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
  for(const auto& face : corners)
  {
    for(const auto& c : face)
    {
      const double v[3] = {h * c[0], h * c[1], h * c[2]};
      P.add_vertex(v);
    }
    P.end_face();
  }
  const double phi = (1 + std::sqrt(5.0)) / 2, a = 1 / std::sqrt(3.0), b = a / phi, g = a * phi;
  std::vector<std::array<double, 3> > normals;
  for(double x : {a, -a})
    for(double y : {a, -a})
      for(double z : {a, -a})
        normals.push_back({{x, y, z}});
  for(double p : {b, -b})
    for(double q : {g, -g})
    {
      normals.push_back({{0, p, q}});
      normals.push_back({{p, q, 0}});
      normals.push_back({{q, 0, p}});
    }
  for(const auto& n : normals)
    clip_vcm_cell(n.data(), R, s);
}

// The covariance matrix (xx xy xz yy yz zz) of `s.cell` about the origin.
inline std::array<double, 6> vcm_cell_covariance(const Vcm_cell_scratch& s)
{
  std::array<double, 6> m = {{0, 0, 0, 0, 0, 0}};
  const Vcm_polytope& P = s.cell;
  for(std::size_t f = 0; f < P.faces(); ++f)
  {
    const double* a = &P.xyz[3 * std::size_t(P.begin[f])];
    for(std::uint32_t i = P.begin[f] + 1; i + 1 < P.begin[f + 1]; ++i)
    {
      const double* b = &P.xyz[3 * std::size_t(i)];
      const double* c = &P.xyz[3 * std::size_t(i) + 3];
      const double det = std::abs(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                                  a[2] * (b[0] * c[1] - b[1] * c[0])) /
                         120.0;
      const double t[3] = {a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]};
      int k = 0;
      for(int r = 0; r < 3; ++r)
        for(int q = r; q < 3; ++q)
          m[k++] += det * (a[r] * a[q] + b[r] * b[q] + c[r] * c[q] + t[r] * t[q]);
    }
  }
  return m;
}

// The VCM covariance of one point: the ball polytope `ball` (vcm_ball_polytope) cut by the
// bisector half-spaces of the neighbours `d` (count of them, each the neighbour minus the
// point, x y z), in that order.
inline std::array<double, 6> vcm_covariance(const Vcm_polytope& ball, const double* d, std::size_t count,
                                            Vcm_cell_scratch& s)
{
  s.cell = ball;
  for(std::size_t j = 0; j < count; ++j)
  {
    const double* n = d + 3 * j;
    const double c = 0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(c > 0)
      clip_vcm_cell(n, c, s);
  }
  return vcm_cell_covariance(s);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif  // CGAL_POINT_SET_CURVATURES_INTERNAL_VCM_CELLS_H
