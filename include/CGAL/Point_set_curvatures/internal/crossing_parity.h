// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The side of each normal of a part of a cloud checked by the parity of the surface crossings
// along its line, point by point: on a closed surface with outward normals, the ray from a
// point along its normal crosses the surface an even number of times, the ray against it an
// odd number. Unlike the spanning tree's propagation and the winding number over pieces, the
// test does not follow the tree: it turns the points of a thin part's far sheet that the tree
// reached round a knife-edge rim with the near sheet's side (estimate_oriented_normals.h).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_CROSSING_PARITY_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_CROSSING_PARITY_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// One bit per cubic cell of side h over a box.
class Occupancy_grid
{
public:
  // False (and no grid) if the box needs more than `most_per_axis` cells along an axis or
  // `most` in all.
  bool init(const double lo[3], const double hi[3], double h, std::size_t most_per_axis, std::size_t most)
  {
    std::size_t total = 1;
    for(int a = 0; a < 3; ++a)
    {
      const double cells = std::floor((hi[a] - lo[a]) / h) + 1;
      if(!(cells >= 1) || cells > double(most_per_axis))
        return false;
      m_lo[a] = lo[a];
      m_dims[a] = std::size_t(cells);
      total *= m_dims[a];
    }
    if(total > most)
      return false;
    m_h = h;
    m_bits.assign((total + 63) / 64, 0);
    return true;
  }
  void mark(const double p[3])
  {
    std::size_t c;
    if(cell(p, c))
      m_bits[c / 64] |= std::uint64_t(1) << (c % 64);
  }
  // The most samples a ray from within the box takes to leave it in steps of half a cell (its
  // diagonal in half-cells, and a margin).
  std::size_t most_steps() const { return 2 * (m_dims[0] + m_dims[1] + m_dims[2]) + 8; }
  // -1 outside the box, else whether the cell of p is occupied.
  int occupied(const double p[3]) const
  {
    std::size_t c;
    if(!cell(p, c))
      return -1;
    return int((m_bits[c / 64] >> (c % 64)) & 1);
  }

private:
  bool cell(const double p[3], std::size_t& c) const
  {
    c = 0;
    for(int a = 0; a < 3; ++a)
    {
      const double x = std::floor((p[a] - m_lo[a]) / m_h);
      if(!(x >= 0 && x < double(m_dims[a])))
        return false;
      c = c * m_dims[a] + std::size_t(x);
    }
    return true;
  }
  double m_lo[3] = {0, 0, 0}, m_h = 1;
  std::size_t m_dims[3] = {0, 0, 0};
  std::vector<std::uint64_t> m_bits;
};

// The runs of occupied cells that the ray p + t d (d unit) enters, sampled from t = `start` in
// steps of `step` (half a cell), until it leaves the grid; at most grid.most_steps() samples (a
// step below the coordinates' precision, as on near-duplicate points far from the origin, would
// not move the ray).
inline std::size_t crossings(const Occupancy_grid& grid, const double p[3], const double d[3], double start,
                             double step)
{
  std::size_t runs = 0;
  bool in_run = false;
  const std::size_t most = grid.most_steps();
  for(std::size_t s = 0; s < most; ++s)
  {
    const double t = start + double(s) * step;
    const double q[3] = {p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2]};
    const int o = grid.occupied(q);
    if(o < 0)
      break;
    runs += (o == 1 && !in_run) ? 1 : 0;
    in_run = o == 1;
  }
  return runs;
}

// The parity test's constants: cells of 0.75 times the median distance from a point to its
// farthest graph neighbour, each point marking its tangent disc of half that distance (so that
// a sheet sampled at random has no holes a ray slips through, and stays a cell or two thick);
// rays from 1.5 cells out in steps of half a cell. A part is checked only if it has at least
// `least_points` points, fits `most_cells_per_axis`, `most_cells` and `cells_per_point` times its
// points (the grid at most 8 bytes a point: its memory is counted with the orientation's, in
// tools/tiled_normals.cpp, with the 29 bytes a point this check takes in all), and the test is decisive
// (the two rays of opposite parities) at `least_decisive` of a sample of its points (every
// part.size() / 1024-th, 1024 to 2047 of them): parts
// seen from all sides, not open scenes (a terrestrial scan's: 38% decisive, flips there would be
// noise); and only if the sample finds normals inward (at least `least_inward` of them and
// `least_inward_share` of the sample: a part oriented right costs the sample's rays only, where
// every point's would double the normals' time of a closed sphere of 500K points). A point is turned where its rays say so and its graph neighbours' votes agree (their
// sum, its own included, below -0.5 times their count); then up to `relaxation_rounds` times
// each point whose rays did not confirm it turns if most of its graph neighbours' normals face
// the other way.
constexpr std::size_t parity_least_points = 64, parity_most_cells_per_axis = 1024,
                      parity_most_cells = std::size_t(1) << 27, parity_cells_per_point = 64, parity_sample = 1024,
                      relaxation_rounds = 10;
constexpr std::size_t least_inward = 3;
constexpr double parity_cell = 0.75, parity_splat = 0.5, parity_start = 1.5, least_decisive = 0.8,
                 least_inward_share = 0.005;

// Checks the normals `n` (3 per point, unit, of the points `part`, input indices into `xyz`)
// by the parity of crossings (above) and turns those it finds inward. `neighbors(i, f)` calls
// f(j) for each graph neighbour j of point i (in the part); `reach(i)` is the distance from i to
// its farthest nearest neighbour; `vote` is scratch of one entry per point, zero, left zero.
// Deterministic. Returns the number of normals turned.
template <class Neighbors, class Reach>
std::size_t repair_by_crossing_parity(const std::vector<std::uint32_t>& part, const std::vector<double>& xyz,
                                      std::vector<double>& n, const Neighbors& neighbors, const Reach& reach,
                                      std::vector<signed char>& vote)
{
  if(part.size() < parity_least_points)
    return 0;
  std::vector<double> scale(part.size());
  for(std::size_t k = 0; k < part.size(); ++k)
    scale[k] = reach(part[k]);
  std::vector<double> sorted(scale);
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double h = parity_cell * sorted[sorted.size() / 2];
  if(!(h > 0) || !std::isfinite(h))
    return 0;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(std::uint32_t i : part)
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::min)(lo[a], xyz[3 * std::size_t(i) + a] - 2 * h);
      hi[a] = (std::max)(hi[a], xyz[3 * std::size_t(i) + a] + 2 * h);
    }
  Occupancy_grid grid;
  if(!grid.init(lo, hi, h, parity_most_cells_per_axis,
                (std::min)(parity_most_cells, parity_cells_per_point * part.size())))
    return 0;
  for(std::size_t k = 0; k < part.size(); ++k)
  {
    const double* p = &xyz[3 * std::size_t(part[k])];
    const double* v = &n[3 * std::size_t(part[k])];
    // a tangent frame (t1, t2) of the normal
    const double a[3] = {std::abs(v[0]) < 0.9 ? 1.0 : 0.0, std::abs(v[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    double t1[3] = {v[1] * a[2] - v[2] * a[1], v[2] * a[0] - v[0] * a[2], v[0] * a[1] - v[1] * a[0]};
    const double l = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    if(!(l > 0))
      continue;
    for(double& x : t1)
      x /= l;
    const double t2[3] = {v[1] * t1[2] - v[2] * t1[1], v[2] * t1[0] - v[0] * t1[2], v[0] * t1[1] - v[1] * t1[0]};
    const double r = parity_splat * scale[k];
    static const double disc[9][2] = {{0, 0},     {1, 0},      {-1, 0},     {0, 1},      {0, -1},
                                      {0.7, 0.7}, {-0.7, 0.7}, {0.7, -0.7}, {-0.7, -0.7}};
    for(const auto& uv : disc)
    {
      const double q[3] = {p[0] + r * (uv[0] * t1[0] + uv[1] * t2[0]), p[1] + r * (uv[0] * t1[1] + uv[1] * t2[1]),
                           p[2] + r * (uv[0] * t1[2] + uv[1] * t2[2])};
      grid.mark(q);
    }
  }
  // -1: the rays say the normal points inward, +1 outward, 0 undecided
  auto parity_vote = [&](std::uint32_t i) -> signed char {
    const double* p = &xyz[3 * std::size_t(i)];
    const double* v = &n[3 * std::size_t(i)];
    const double back[3] = {-v[0], -v[1], -v[2]};
    const std::size_t out = crossings(grid, p, v, parity_start * h, 0.5 * h) % 2,
                      in = crossings(grid, p, back, parity_start * h, 0.5 * h) % 2;
    return out == in ? 0 : out == 0 ? 1 : -1;
  };
  {
    const std::size_t stride = (std::max)(std::size_t(1), part.size() / parity_sample);
    std::size_t sampled = 0, decisive = 0, inward = 0;
    for(std::size_t k = 0; k < part.size(); k += stride)
    {
      const signed char v = parity_vote(part[k]);
      ++sampled;
      decisive += v != 0 ? 1 : 0;
      inward += v < 0 ? 1 : 0;
    }
    if(double(decisive) < least_decisive * double(sampled) || inward < least_inward ||
       double(inward) < least_inward_share * double(sampled))
      return 0;
  }
  for(std::uint32_t i : part)
    vote[i] = parity_vote(i);
  std::vector<std::uint32_t> turned;
  for(std::uint32_t i : part)
  {
    if(vote[i] != -1)
      continue;
    double sum = vote[i], count = 1;
    neighbors(i, [&](std::uint32_t j) {
      sum += vote[j];
      count += 1;
    });
    if(sum < -0.5 * count)
      turned.push_back(i);
  }
  auto turn = [&n](std::uint32_t i) {
    for(int a = 0; a < 3; ++a)
      n[3 * std::size_t(i) + a] = -n[3 * std::size_t(i) + a];
  };
  for(std::uint32_t i : turned)
    turn(i);
  std::size_t total = turned.size();
  for(std::size_t round = 0; round < relaxation_rounds; ++round)
  {
    turned.clear();
    for(std::uint32_t i : part)
    {
      if(vote[i] == 1)
        continue;
      const double* v = &n[3 * std::size_t(i)];
      double against = 0, count = 0;
      neighbors(i, [&](std::uint32_t j) {
        const double* w = &n[3 * std::size_t(j)];
        against += (v[0] * w[0] + v[1] * w[1] + v[2] * w[2] < 0) ? 1 : 0;
        count += 1;
      });
      if(against > 0.75 * count)
        turned.push_back(i);
    }
    if(turned.empty())
      break;
    for(std::uint32_t i : turned)
      turn(i);
    total += turned.size();
  }
  for(std::uint32_t i : part)
    vote[i] = 0;
  return total;
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
