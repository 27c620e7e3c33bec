// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tangent Voronoi areas as sample weights: the area each sample stands for, so that the sums
// of the fits are a quadrature of surface integrals with area weights instead of equal
// weights.
//
// The fits' sums (algebraic_sphere.h, algebraic_shape_operator.h) estimate surface integrals
// of the kernel times polynomials, with the samples as nodes. With equal weights the
// estimate is good only if the samples are evenly spread (blue noise); on i.i.d. samples, scan
// lines or a density ramp its error dominates the ASO's (the weights' Hessian makes it
// sensitive to where samples happen to be). The area a_j of the cell of sample p_j in a
// Voronoi diagram of its neighbours, taken in its own tangent plane, is the natural quadrature
// weight: sum_j a_j f(p_j) is then a first-order Riemann sum of the integral of f. a_j does
// not depend on the evaluation point, so multiplying the kernel weights by it keeps the ASO's
// derivatives exact.
//
// The cell: the neighbours of p_j are projected on the plane through p_j orthogonal to its
// (input) normal; the disk of radius `bound` around p_j is clipped by the bisector half-plane
// of each projected neighbour, nearest first, until the next neighbour is farther than twice
// the cell's farthest vertex (it cannot cut the cell any more). The disk bounds the weight of
// isolated samples. Copies of p_j (at distance 0) share its cell.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_TANGENT_VORONOI_AREA_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_TANGENT_VORONOI_AREA_H

#include <CGAL/Point_set_curvatures/internal/local_estimate.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// A convex polygon of at most `capacity` vertices, clipped by half-planes; it keeps the
// squared distance of its farthest vertex from the origin. Two vertex buffers take turns:
// a clip reads one and writes the other (no copy back).
class Convex_cell
{
public:
  static constexpr int capacity = 64;

  void set_square(double h)
  {
    m_size = 4;
    const double x[4] = {-h, h, h, -h}, y[4] = {-h, -h, h, h};
    m_front = 0;
    for(int i = 0; i < 4; ++i)
    {
      m_xy[0][0][i] = x[i];
      m_xy[0][1][i] = y[i];
    }
    m_farthest = 2 * h * h;
  }

  // Keeps the part where ux X + uy Y <= c (the side of the origin of the bisector of the
  // origin and a point u, with c = |u|^2 / 2).
  void clip(double ux, double uy, double c)
  {
    const double* x = m_xy[m_front][0];
    const double* y = m_xy[m_front][1];
    double* nx = m_xy[1 - m_front][0];
    double* ny = m_xy[1 - m_front][1];
    int n = 0;
    double farthest = 0;
    auto keep = [&](double px, double py) {
      if(n < capacity)
      {
        nx[n] = px;
        ny[n] = py;
        ++n;
        farthest = std::max(farthest, px * px + py * py);
      }
    };
    double di = ux * x[0] + uy * y[0] - c;
    for(int i = 0; i < m_size; ++i)
    {
      const int j = i + 1 == m_size ? 0 : i + 1;
      const double dj = ux * x[j] + uy * y[j] - c;
      if(di <= 0)
        keep(x[i], y[i]);
      if((di < 0 && dj > 0) || (di > 0 && dj < 0))
      {
        const double t = di / (di - dj);
        keep(x[i] + t * (x[j] - x[i]), y[i] + t * (y[j] - y[i]));
      }
      di = dj;
    }
    m_size = n;
    m_front = 1 - m_front;
    m_farthest = farthest;
  }

  // Area of the part of the cell inside the disk of radius R centred at the origin: the sum
  // over the edges (p, q) of the signed area of the triangle (0, p, q) cut by the disk, where
  // the parts of an edge outside the disk are replaced by arcs (circular sectors).
  double area_in_disk(double R) const
  {
    const double* x = m_xy[m_front][0];
    const double* y = m_xy[m_front][1];
    const double R2 = R * R;
    auto cross = [](double ax, double ay, double bx, double by) { return ax * by - ay * bx; };
    auto sector = [&](double ax, double ay, double bx, double by) {
      return 0.5 * R2 * std::atan2(cross(ax, ay, bx, by), ax * bx + ay * by);
    };
    double total = 0;
    if(m_farthest <= R2)
    {
      // the whole cell is in the disk (the usual case): its area, without arcs
      for(int i = 0; i < m_size; ++i)
      {
        const int j = i + 1 == m_size ? 0 : i + 1;
        total += cross(x[i], y[i], x[j], y[j]);
      }
      return 0.5 * std::abs(total);
    }
    for(int i = 0; i < m_size; ++i)
    {
      const int j = i + 1 == m_size ? 0 : i + 1;
      const double px = x[i], py = y[i], dx = x[j] - px, dy = y[j] - py;
      const double A = dx * dx + dy * dy, B = px * dx + py * dy, C = px * px + py * py - R2;
      const double disc = B * B - A * C;
      if(!(A > 0))
        continue;
      if(disc <= 0)
      {
        total += sector(px, py, x[j], y[j]);
        continue;
      }
      const double root = std::sqrt(disc);
      const double t1 = std::max(0.0, (-B - root) / A), t2 = std::min(1.0, (-B + root) / A);
      if(t1 >= t2)
      {
        total += sector(px, py, x[j], y[j]);
        continue;
      }
      // the chord inside the disk, and arcs for the parts of the edge outside it (none at an
      // end inside the disk)
      const double ax = t1 > 0 ? px + t1 * dx : px, ay = t1 > 0 ? py + t1 * dy : py;
      const double bx = t2 < 1 ? px + t2 * dx : x[j], by = t2 < 1 ? py + t2 * dy : y[j];
      total += 0.5 * cross(ax, ay, bx, by);
      if(t1 > 0)
        total += sector(px, py, ax, ay);
      if(t2 < 1)
        total += sector(bx, by, x[j], y[j]);
    }
    return std::abs(total);
  }

  double farthest_squared() const { return m_farthest; }

private:
  int m_size = 0;
  int m_front = 0;  // m_xy[m_front] holds the cell, the other buffer receives the next clip
  double m_farthest = 0;
  double m_xy[2][2][capacity];
};

// Reusable scratch of tangent_voronoi_area(): the projected neighbours.
struct Tangent_cell_scratch
{
  struct Projected
  {
    double d2, u, v;
    bool operator<(const Projected& o) const { return d2 < o.d2 || (d2 == o.d2 && (u < o.u || (u == o.u && v < o.v))); }
  };
  std::vector<Projected> projected;
};

// Area, in the input's squared length unit, of the tangent Voronoi cell of the query of
// `nb` (see the header comment) within the disk of radius `bound` (in units of nb.radius):
// a disk rather than a square, so that the area does not depend on the orientation of the
// tangent basis (rotation invariance). 0 if the query has no usable normal.
inline double tangent_voronoi_area(const Neighborhood& nb, double bound, Tangent_cell_scratch& scratch)
{
  const double* n = nb.query_normal;
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if(!(nn > 0) || !std::isfinite(nn))
    return 0;
  const double inv = 1.0 / std::sqrt(nn);
  const double unit[3] = {n[0] * inv, n[1] * inv, n[2] * inv};
  double t1[3], t2[3];
  tangent_basis(unit, t1, t2);
  // Only neighbours projected within 2 * bound can ever cut the part that counts (the test
  // in the loop below); they are put in distance order lazily, a prefix at a time
  // (nth_element then sort, growing the prefix 4-fold), since the loop usually stops after a
  // dozen: linear cost in the neighbourhood's size, not k log k, when the radius is large.
  const double bound2 = bound * bound;
  std::vector<Tangent_cell_scratch::Projected>& p = scratch.projected;
  p.clear();
  std::size_t copies = 0;  // copies: other samples at the query's position
  bool self = false;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double qx = nb.qx[i], qy = nb.qy[i], qz = nb.qz[i];
    if(qx == 0 && qy == 0 && qz == 0)
    {
      copies += self ? 1 : 0;
      self = true;
      continue;
    }
    const double u = qx * t1[0] + qy * t1[1] + qz * t1[2];
    const double v = qx * t2[0] + qy * t2[1] + qz * t2[2];
    const double d2 = u * u + v * v;
    if(d2 <= 4 * bound2)
      p.push_back(Tangent_cell_scratch::Projected{d2, u, v});
  }
  // a square that holds the disk, clipped by the bisectors until the next neighbour is farther
  // than twice the part of the cell that counts (its farthest vertex, at most `bound`)
  Convex_cell cell;
  cell.set_square(bound);
  std::size_t sorted = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    if(i == sorted)
    {
      const std::size_t next = std::min(p.size(), std::max<std::size_t>(16, 4 * sorted));
      if(next < p.size())
        std::nth_element(p.begin() + sorted, p.begin() + next, p.end());
      std::sort(p.begin() + sorted, p.begin() + next);
      sorted = next;
    }
    const Tangent_cell_scratch::Projected& x = p[i];
    if(x.d2 > 4 * std::min(bound2, cell.farthest_squared()))
      break;  // this and the farther neighbours cannot cut the part that counts
    if(!(x.d2 > 1e-24))
      continue;  // on the normal line through the query: no tangential separation
    cell.clip(x.u, x.v, 0.5 * x.d2);
  }
  return cell.area_in_disk(bound) * nb.radius * nb.radius / double(1 + copies);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
