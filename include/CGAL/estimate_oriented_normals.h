// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Oriented normals for clouds that have none (most LiDAR scans): the normals of a weighted
// quadric or of the PCA plane of each neighbourhood, on the package's neighbourhood driver,
// then an orientation along a vector, towards a point (the scanner), or propagated along a
// minimum spanning tree of the neighbourhood graph.

#ifndef CGAL_ESTIMATE_ORIENTED_NORMALS_H
#define CGAL_ESTIMATE_ORIENTED_NORMALS_H

#include <CGAL/Point_set_curvatures/internal/automatic_scale_estimation.h>
#include <CGAL/Point_set_curvatures/internal/crossing_parity.h>
#include <CGAL/Point_set_curvatures/internal/evaluate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/pca_plane.h>
#include <CGAL/Point_set_curvatures/internal/quadric_fit.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/Point_set_curvatures/scale_choices.h>
#include <CGAL/Point_set_curvatures/vertical_normals.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
/// How `CGAL::estimate_oriented_normals()` orients the normals it estimates.
struct Normal_orientation
{
  enum Kind {
    /// Propagation along a minimum spanning tree of the neighbourhood graph weighted by
    /// `1 - |n_i . n_j|` (Hoppe et al. 1992), in each connected part from its highest point;
    /// then each part's sign is chosen as a whole: outward where the part looks closed (the
    /// mean of its unit normals shorter than 0.5, and `|sum (p - c) . n|` at least 0.3
    /// `sum |p - c|`, `c` the part's centroid), which makes `sum (p - c) . n` positive (three
    /// times the enclosed volume for a closed surface with outward normals, by the divergence
    /// theorem); otherwise (an open surface: a terrain, a street, one side of an object) the
    /// side where the mean normal points up (+z). In a closed part, the pieces that the tree
    /// entered across a thin part or between nearly perpendicular normals (where the side it
    /// passes on is a guess) are each turned to the side that the generalized winding number
    /// of the rest of the part says is outside, and the small ones (at most 100 points) then to
    /// the side of their neighbours along the surface where 90% of their agreement says so. Then
    /// each part seen from all sides (closed or not; not those of a 2.5-D cloud under
    /// `AUTOMATIC`) has each point's side checked by the parity of the surface crossings along
    /// its normal's line (even outward, odd inward, counted on a grid of the part's points),
    /// where a sample finds normals inward: the far face of a thin plate, which the tree reaches
    /// round a knife-edge rim with the near face's side, and plates whose small flux left their
    /// side to the mean normal. Plates thinner than about 3 nearest-neighbour distances stay
    /// undecided (their faces share the grid's cells). For closed or unknown shapes. Default.
    MINIMUM_SPANNING_TREE,
    /// Every normal makes a non-negative dot product with `vector` (airborne scans: +z).
    ALONG_VECTOR,
    /// Every normal points towards `point` (a scanner or camera position).
    TOWARDS_POINT,
    /// Along a minimum spanning tree as `MINIMUM_SPANNING_TREE`; then, if the cloud is 2.5-D
    /// (airborne and mobile scans, seen from above: at least 60% of the estimated normals
    /// within 60 degrees of the vertical, see `CGAL::Point_set_curvatures::is_two_and_a_half_d()`),
    /// every near-vertical normal of the open parts along +z on its own, so that a tree crown or
    /// a roof edge cannot turn a region (steeper normals keep the tree's side). On a 2.5-D cloud
    /// a part is closed (and kept outward) only if it is also seen from all sides: a bottom of
    /// normals pointing down under a top of normals pointing up, sharing a footprint whose rim
    /// is steep (a torus lying flat); ground that the tree turned against the roofs, which
    /// also makes normals that cancel and a large outward flux, is open, hence up.
    AUTOMATIC
  };
  Kind kind = MINIMUM_SPANNING_TREE;
  double target[3] = {0, 0, 1};  ///< the vector or the point

  /// the default: propagation along a minimum spanning tree
  static Normal_orientation minimum_spanning_tree() { return Normal_orientation(); }
  /// normals on the side of the vector `(x, y, z)`
  static Normal_orientation along_vector(double x, double y, double z)
  {
    Normal_orientation o;
    o.kind = ALONG_VECTOR;
    o.target[0] = x;
    o.target[1] = y;
    o.target[2] = z;
    return o;
  }
  /// normals towards the point `(x, y, z)`
  static Normal_orientation towards_point(double x, double y, double z)
  {
    Normal_orientation o = along_vector(x, y, z);
    o.kind = TOWARDS_POINT;
    return o;
  }
  /// the spanning tree, with the open parts of 2.5-D clouds along +z
  static Normal_orientation automatic()
  {
    Normal_orientation o;
    o.kind = AUTOMATIC;
    return o;
  }
};

/// \ingroup PkgPointSetCurvaturesRef
/// What `CGAL::estimate_oriented_normals()` fits to each neighbourhood.
enum class Normal_fit {
  /// the least-squares plane of the neighbours (principal component analysis, unweighted):
  /// biased by the curvature to first order, and rough from point to point
  PLANE,
  /// a quadric height field over the weighted PCA plane, fitted by weighted least squares
  /// with the weights `(1 - d²/r²)²` (smooth from point to point), its anisotropic part
  /// slightly penalised so that neighbourhoods on two or three scan lines stay determined
  QUADRIC
};

namespace Point_set_curvatures {
namespace internal_np {
enum normal_orientation_t { normal_orientation };
enum normal_fit_t { normal_fit };
}  // namespace internal_np

namespace parameters {
/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `CGAL::estimate_oriented_normals()`: how the normals are oriented.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Normal_orientation, internal_np::normal_orientation_t, NamedParameters>
normal_orientation(const Normal_orientation& o, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Normal_orientation, internal_np::normal_orientation_t, NamedParameters>(o, np);
}
/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter of `CGAL::estimate_oriented_normals()`: what is fitted to each
/// neighbourhood (`CGAL::Normal_fit`).
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Normal_fit, internal_np::normal_fit_t, NamedParameters>
normal_fit(Normal_fit fit, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Normal_fit, internal_np::normal_fit_t, NamedParameters>(fit, np);
}
}  // namespace parameters

/// \ingroup PkgPointSetCurvaturesRef
/// The default neighbour count of `CGAL::estimate_oriented_normals()` for a fit: 40 for the
/// quadric (its best count for the ASO at 40 neighbours on simulated scans, benchmark/README.md
/// "Scans without normals"), 18 for the plane.
inline std::size_t default_normal_neighbors(Normal_fit fit) { return fit == Normal_fit::QUADRIC ? 40 : 18; }

namespace internal {

// Degree of the neighbourhood graph of the spanning tree: each point's nearest neighbours.
constexpr std::size_t normal_graph_degree = 12;

// Per point: the unoriented normal and its nearest neighbours (input indices).
struct Normal_record
{
  double normal[3] = {0, 0, 0};
  std::uint32_t neighbor[normal_graph_degree];
  std::uint8_t degree = 0;
  std::size_t count = 0;  // with the automatic scale: the chosen neighbourhood's size
  Curvature_estimate_status status = Curvature_estimate_status::NOT_COMPUTED;
};

// The evaluation of the driver: the fit's normal (neighbourhoods spread along one line only,
// such as one LiDAR scan line, or whose points coincide up to rounding,
// neighborhood_below_precision(), have none: DEGENERATE_FIT) and the nearest neighbours.
struct Normal_at_point
{
  Normal_fit fit;
  Scale_ladder ladder;  // ladder.largest 0: the driver's neighbourhood; else the automatic scale
  // With the automatic scale, in the pass after the first: the curvatures' choices to record
  // (curvature_scale_record(), by input position), or null.
  Curvature_scale_records* curvatures = nullptr;
  Normal_record operator()(const Neighborhood& nb) const;
};

// The least relative pivot of the cubic of cubic_normal(): at 0.03 (the first test's) the cubic's
// normals are taken on half the points of clean lines 5:1 with a wobble, and the ASO, which
// differentiates the normal field, sees the step between them and the quadric's normals (mean
// |H - H*| 0.81e-3 -> 0.86e-3); at 0.01 0.64e-3; at 0.003 scan lines 5:1 in a zigzag lose
// (1.52e-3 -> 1.84e-3). benchmark/scan_experiments, clean, the default without normals.
constexpr double cubic_normal_least_pivot = 0.01;
// The ratio of the cubic's residual variance to the quadratic's (Cubic_height_fit::solve()) below
// which cubic_normal() takes the cubic's normal: where the rung is kept as clean but noise is what
// the quadratic leaves (ratio near 1), the cubic's slope only adds variance (without this bound:
// lines 8:1 with a wobble under range noise of 0.1 and 0.3 spacings, normals' mean angle +6% and
// +9%).
constexpr double cubic_normal_share = 0.2;

// Where the first rung is kept without noise (Scale_choice::clean), the normal of the weighted
// cubic over the quadric's frame and weights (its frame cache): the quadric's slope carries the
// surface's third-order terms, the cubic's does not. Left as it is where the cubic's monomials
// are not well told apart (cubic_normal_least_pivot: scan lines) or where it fits no better
// than the quadratic (cubic_normal_share).
inline void cubic_normal(const Quadric_fit& quadric, double n[3])
{
  double a[10], share;
  if(!cubic_over_frame_cache(*quadric.frame_cache).solve(cubic_normal_least_pivot, a, share) ||
     !(share < cubic_normal_share))
    return;
  double g[3];
  for(int i = 0; i < 3; ++i)
    g[i] = quadric.n0[i] - a[1] * quadric.t1[i] - a[2] * quadric.t2[i];
  const double l2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  if(!(l2 > 0) || !std::isfinite(l2))
    return;
  const double inv = 1.0 / std::sqrt(l2);
  for(int i = 0; i < 3; ++i)
    n[i] = g[i] * inv;
}

inline Normal_record Normal_at_point::operator()(const Neighborhood& nb) const
{
  Normal_record r;
  const std::size_t least = fit == Normal_fit::QUADRIC ? quadratic_height_coefficients : pca_plane_min_neighbors;
  if(nb.size < least)
  {
    r.status = Curvature_estimate_status::TOO_FEW_NEIGHBORS;
    return r;
  }
  if(neighborhood_below_precision(nb))
  {
    r.status = Curvature_estimate_status::DEGENERATE_FIT;
    return r;
  }
  bool found = false;
  if(ladder.largest > 0)
  {
    thread_local Ladder_scratch scratch;
    thread_local Rung_cache cache;  // (the rungs' fits, for the curvatures' rule)
    cache.clear();
    scratch.cache = curvatures ? &cache : nullptr;
    Quadric_fit quadric;  // with the penalty that scan lines need
    const Scale_choice c = ladder.choose(nb, scratch);
    r.count = c.count;
    const bool climbs = ladder.climbs(c);
    // (as_first_rung: the ladder's plain quadric failed there, the penalised one may not, as
    // with a fixed count)
    thread_local std::vector<double> frame;  // (for cubic_normal())
    if(c.clean)
      quadric.frame_cache = &frame;
    found = !climbs && (c.found || c.as_first_rung) && quadric.compute(scratch.chosen.nb) && quadric.normal(r.normal);
    if(found && c.clean)
      cubic_normal(quadric, r.normal);
    if(curvatures)
    {
      // (the same scratch: its offsets and ranks are the neighbourhood's; its rungs not needed any more)
      scratch.same_neighborhood = true;
      *curvatures->of(nb.query_index) = curvature_scale_record(ladder, nb, scratch);
      scratch.same_neighborhood = false;
    }
    if(climbs)
    {
      ladder.count_sent_on();
      // a provisional record (no normal, no neighbours), replaced by the next pass's
      r.status = Curvature_estimate_status::VALID;
      return r;
    }
  }
  else if(fit == Normal_fit::QUADRIC)
  {
    Quadric_fit quadric;
    found = quadric.compute(nb) && quadric.normal(r.normal);
  }
  else
  {
    Neighborhood_pca pca;
    found = pca.compute(nb) && spreads_in_two_directions(pca.values);
    if(found)
      std::copy(pca.vectors[0], pca.vectors[0] + 3, r.normal);
  }
  if(!found)
  {
    r.status = Curvature_estimate_status::DEGENERATE_FIT;
    return r;
  }
  r.status = Curvature_estimate_status::VALID;
  // the nearest neighbours other than the point itself, ties by input index: the smallest
  // (d², index) pairs, kept sorted while the neighbourhood is read (most candidates are farther
  // than the last kept and cost one comparison)
  std::pair<double, std::uint32_t> nearest[normal_graph_degree];
  std::size_t degree = 0;
  for(std::size_t i = 0; i < nb.size; ++i)
  {
    const double d2 = nb.qx[i] * nb.qx[i] + nb.qy[i] * nb.qy[i] + nb.qz[i] * nb.qz[i];
    if(d2 == 0)
      continue;  // the point itself, or a copy of it: no orientation to learn from it
    // (the distance first: the index, two reads away, only where it may decide)
    if(degree == normal_graph_degree && d2 > nearest[degree - 1].first)
      continue;
    const std::pair<double, std::uint32_t> candidate(d2, nb.input_index[nb.index[i]]);
    if(degree == normal_graph_degree && !(candidate < nearest[degree - 1]))
      continue;
    std::size_t j = degree < normal_graph_degree ? degree++ : degree - 1;
    for(; j > 0 && candidate < nearest[j - 1]; --j)
      nearest[j] = nearest[j - 1];
    nearest[j] = candidate;
  }
  for(std::size_t i = 0; i < degree; ++i)
    r.neighbor[i] = nearest[i].second;
  r.degree = static_cast<std::uint8_t>(degree);
  return r;
}

// Whether a part that looks closed is an object seen from all sides, for a 2.5-D cloud (seen
// from above, where ground joined to roofs and walls can pass the closed test when the tree
// turned some of it: roofs up and ground down make a large outward flux). With the part's
// normals turned by `sign`, on a grid of the horizontal plane (about 8 points a cell): the
// near-vertical normals pointing down (a bottom) are at least 20% of the near-vertical ones,
// at least 80% of them lie below one pointing up in their cell and at least 80% of those
// pointing up lie above one pointing down (top and bottom share a footprint: the ground beside
// a building lies under nothing), and at least 80% of the cells on the footprint's rim hold a
// steep normal (an object's side; a tile's cut edge holds ground).
inline bool seen_from_all_sides(const std::vector<std::uint32_t>& part, const std::vector<double>& xyz,
                                const std::vector<double>& n, double sign)
{
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for(std::uint32_t i : part)
    for(int a = 0; a < 2; ++a)
    {
      lo[a] = std::min(lo[a], xyz[3 * std::size_t(i) + a]);
      hi[a] = std::max(hi[a], xyz[3 * std::size_t(i) + a]);
    }
  const double cell = std::sqrt((hi[0] - lo[0]) * (hi[1] - lo[1]) * 8 / double(part.size()));
  // (a part without horizontal extent, a wall, has no footprint; nor has one a billion cells long)
  if(!(cell > 0) || !std::isfinite(cell) || (hi[0] - lo[0]) / cell > 1e8 || (hi[1] - lo[1]) / cell > 1e8)
    return false;
  const double columns = std::floor((hi[1] - lo[1]) / cell) + 3;
  auto key = [&](double x, double y) {
    return std::int64_t(std::floor((x - lo[0]) / cell) + 1) * std::int64_t(columns) +
           std::int64_t(std::floor((y - lo[1]) / cell) + 1);
  };
  struct Cell
  {
    double top = -HUGE_VAL;    // highest point whose normal points up
    double bottom = HUGE_VAL;  // lowest point whose normal points down
    std::size_t points = 0, steep = 0;
  };
  std::vector<std::pair<std::int64_t, std::uint32_t> > keyed;  // (cell, point), sorted by cell
  keyed.reserve(part.size());
  for(std::uint32_t i : part)
    keyed.emplace_back(key(xyz[3 * std::size_t(i)], xyz[3 * std::size_t(i) + 1]), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::int64_t> keys;
  std::vector<Cell> cells;
  for(const auto& ki : keyed)
  {
    if(keys.empty() || keys.back() != ki.first)
    {
      keys.push_back(ki.first);
      cells.emplace_back();
    }
    Cell& c = cells.back();
    const double* v = &n[3 * std::size_t(ki.second)];
    const double z = xyz[3 * std::size_t(ki.second) + 2];
    ++c.points;
    if(!is_near_vertical(v[0], v[1], v[2]))
      ++c.steep;
    else if(sign * v[2] > 0)
      c.top = std::max(c.top, z);
    else
      c.bottom = std::min(c.bottom, z);
  }
  auto cell_of = [&](std::int64_t k) -> const Cell* {
    const auto it = std::lower_bound(keys.begin(), keys.end(), k);
    return it != keys.end() && *it == k ? &cells[std::size_t(it - keys.begin())] : nullptr;
  };
  std::size_t up = 0, down = 0, up_covered = 0, down_covered = 0;
  for(const auto& ki : keyed)
  {
    const double* v = &n[3 * std::size_t(ki.second)];
    if(!is_near_vertical(v[0], v[1], v[2]))
      continue;
    const double z = xyz[3 * std::size_t(ki.second) + 2];
    const Cell& c = *cell_of(ki.first);
    if(sign * v[2] > 0)
    {
      ++up;
      up_covered += c.bottom < z ? 1 : 0;
    }
    else
    {
      ++down;
      down_covered += c.top > z ? 1 : 0;
    }
  }
  if(double(down) < 0.2 * double(up + down) || double(down_covered) < 0.8 * double(down) ||
     double(up_covered) < 0.8 * double(up))
    return false;
  const std::int64_t column_step = std::int64_t(columns);
  std::size_t rim = 0, rim_steep = 0;
  for(std::size_t c = 0; c < keys.size(); ++c)
  {
    const std::int64_t k = keys[c];
    if(cell_of(k - 1) && cell_of(k + 1) && cell_of(k - column_step) && cell_of(k + column_step))
      continue;
    ++rim;
    rim_steep += cells[c].steep > 0 ? 1 : 0;
  }
  return double(rim_steep) >= 0.8 * double(rim);
}

// Turns the normals of one connected part (`part`, input indices) as a whole: outward if the
// part looks closed, else up (Normal_orientation::MINIMUM_SPANNING_TREE); then with `upward`
// (Normal_orientation::AUTOMATIC on a 2.5-D cloud) each near-vertical normal of an open part
// to +z on its own (steep ones, whose side up is noise, keep the tree's). `xyz` and `n` hold 3
// values per point. Closed: the mean of the unit normals is shorter than 0.5 (it vanishes on a
// closed surface sampled evenly; it is 0.5 on a hemisphere) and the flux sum (p - c) . n is at
// least 0.3 sum |p - c| in magnitude (1 on a sphere, 0.57 on a torus of radii 1 and 0.4;
// 0.1 on a terrestrial street scan, whose normals also nearly cancel); with `upward`, also
// seen_from_all_sides(). Returns whether the part was taken for closed.
inline bool choose_part_sign(const std::vector<std::uint32_t>& part, const std::vector<double>& xyz,
                             std::vector<double>& n, bool upward)
{
  if(part.empty())
    return false;
  double m[3] = {0, 0, 0}, c[3] = {0, 0, 0};
  for(std::uint32_t i : part)
    for(int a = 0; a < 3; ++a)
    {
      m[a] += n[3 * std::size_t(i) + a];
      c[a] += xyz[3 * std::size_t(i) + a];
    }
  const double count = double(part.size());
  for(double& x : c)
    x /= count;
  double flux = 0, spread = 0;
  for(std::uint32_t i : part)
  {
    const double d[3] = {xyz[3 * std::size_t(i)] - c[0], xyz[3 * std::size_t(i) + 1] - c[1],
                         xyz[3 * std::size_t(i) + 2] - c[2]};
    flux += d[0] * n[3 * std::size_t(i)] + d[1] * n[3 * std::size_t(i) + 1] + d[2] * n[3 * std::size_t(i) + 2];
    spread += std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
  bool closed = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] < 0.25 * count * count && std::abs(flux) >= 0.3 * spread;
  if(closed && upward)
    closed = seen_from_all_sides(part, xyz, n, flux < 0 ? -1.0 : 1.0);
  auto turn = [&n](std::uint32_t i) {
    for(int a = 0; a < 3; ++a)
      n[3 * std::size_t(i) + a] = -n[3 * std::size_t(i) + a];
  };
  if((closed ? flux : m[2]) < 0)
    for(std::uint32_t i : part)
      turn(i);
  if(upward && !closed)
    for(std::uint32_t i : part)
    {
      const double* v = &n[3 * std::size_t(i)];
      if(v[2] < 0 && is_near_vertical(v[0], v[1], v[2]))
        turn(i);
    }
  return closed;
}

// The symmetric graph of the records' neighbours over the VALID records, as CSR: the neighbours of
// point i are adjacency[offset[i], offset[i + 1]) (up to 24: each record's and the records naming it).
inline void normal_graph(const std::vector<Normal_record>& records, std::vector<std::size_t>& offset,
                         std::vector<std::uint32_t>& adjacency)
{
  const std::size_t count = records.size();
  auto usable = [&](std::size_t i) { return records[i].status == Curvature_estimate_status::VALID; };
  offset.assign(count + 1, 0);  // up to 24 entries per point: 64 bits
  for(std::size_t i = 0; i < count; ++i)
    if(usable(i))
      for(std::size_t e = 0; e < records[i].degree; ++e)
        if(usable(records[i].neighbor[e]))
        {
          ++offset[i + 1];
          ++offset[records[i].neighbor[e] + 1];
        }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  adjacency.assign(offset.back(), 0);
  std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
  for(std::size_t i = 0; i < count; ++i)
    if(usable(i))
      for(std::size_t e = 0; e < records[i].degree; ++e)
      {
        const std::uint32_t j = records[i].neighbor[e];
        if(!usable(j))
          continue;
        adjacency[fill[i]++] = j;
        adjacency[fill[j]++] = static_cast<std::uint32_t>(i);
      }
}

// True if the edge between points i and j lies within 30 degrees of both tangent planes (of the
// unit normals `n`): not across a thin part, whose two sheets are close.
inline bool along_surface(const std::vector<double>& xyz, const std::vector<double>& n, std::uint32_t i,
                          std::uint32_t j)
{
  const double* p = &xyz[3 * std::size_t(i)];
  const double* q = &xyz[3 * std::size_t(j)];
  const double e[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const double l2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  const double* ni = &n[3 * std::size_t(i)];
  const double* nj = &n[3 * std::size_t(j)];
  const double a = e[0] * ni[0] + e[1] * ni[1] + e[2] * ni[2], b = e[0] * nj[0] + e[1] * nj[1] + e[2] * nj[2];
  return a * a <= 0.25 * l2 && b * b <= 0.25 * l2;
}

// The pieces of a closed part whose side the tree may have got wrong. A piece is a subtree joined
// by edges the tree can trust: normals within about 45 degrees (weight at most 0.3) and the edge
// within 30 degrees of both tangent planes; the tree enters a new piece where it crossed between
// nearly perpendicular normals or across a thin part (a fin, an ear, a tail, where a fit over both
// sheets gives them one side). Each piece but the largest (kept as the part's sign made it) is
// turned if the rest of the part says it points inward: the generalized winding number of the rest
// (sum (p_j - x) . n_j / |p_j - x|^3 over a regular subsample, equal weights) is larger inside a
// closed surface with outward normals than outside, also across the hole that the piece leaves, so
// at probes p - d n and p + d n of 16 of the piece's points (d twice the spacing of the subsample)
// the sum of the differences gives its side. The 2048 largest pieces, in decreasing size, with
// about 2e8 evaluations in all (Stanford dragon of 23K points without normals: 96.4% of the output
// normals outward before, 98.99% with it, 98.87% after later changes of the normals' scale;
// benchmark/README.md, section 8). The small pieces (at most local_vote_piece_size points; on the
// thinnest parts, where the probes, a few spacings away, cross to the other sheet) are then
// decided again, largest first, by their neighbours in the graph (`offset`, `adjacency`) that lie
// in a piece before them, through the edges along the surface: turned where the normals' dot
// products say so clearly (their sum below -0.8 times the sum of their magnitudes: 90% of the
// weight against). Stanford dragon without normals, estimated normals inward (benchmark/README.md,
// section 8): 5K points 316 -> 312, 23K 336 -> 207, 100K 513 -> 475 (with any majority, 423, 178
// and 423: the coarsest sample's thin parts mislead their neighbours). Deterministic. `part` is a
// connected part of the graph and its pieces are numbered consecutively (as
// orient_along_spanning_tree() makes them); a neighbour outside is not read.
constexpr std::size_t local_vote_piece_size = 100;
constexpr double local_vote_margin = 0.8;
inline void repair_closed_part(const std::vector<std::uint32_t>& part, const std::vector<std::uint32_t>& piece,
                               const std::vector<Normal_record>& records, const std::vector<std::size_t>& offset,
                               const std::vector<std::uint32_t>& adjacency, const std::vector<double>& xyz,
                               std::vector<double>& n)
{
  // the part's pieces, largest first (ties by piece number)
  std::vector<std::pair<std::uint32_t, std::uint32_t> > by_piece;  // (piece, point)
  by_piece.reserve(part.size());
  for(std::uint32_t i : part)
    by_piece.emplace_back(piece[i], i);
  std::sort(by_piece.begin(), by_piece.end());
  struct Range
  {
    std::size_t begin, end;
  };
  std::vector<Range> ranges;
  for(std::size_t a = 0; a < by_piece.size();)
  {
    std::size_t b = a;
    while(b < by_piece.size() && by_piece[b].first == by_piece[a].first)
      ++b;
    ranges.push_back({a, b});
    a = b;
  }
  if(ranges.size() < 2)
    return;
  std::stable_sort(ranges.begin(), ranges.end(),
                   [](const Range& x, const Range& y) { return x.end - x.begin > y.end - y.begin; });
  constexpr std::size_t most_pieces = 2048, probes = 16;
  const std::size_t tested = std::min(ranges.size() - 1, most_pieces);
  // the subsample: about 2e8 evaluations in all
  const std::size_t budget = 200000000 / (2 * probes * tested);
  const std::size_t stride = std::max<std::size_t>(1, (part.size() + budget - 1) / std::max<std::size_t>(1, budget));
  // the spacing: median distance to the nearest neighbour
  std::vector<double> nearest;
  for(std::size_t a = 0; a < part.size(); a += std::max<std::size_t>(1, part.size() / 4096))
  {
    const Normal_record& rec = records[part[a]];
    if(rec.degree == 0)
      continue;
    const double* p = &xyz[3 * std::size_t(part[a])];
    const double* q = &xyz[3 * std::size_t(rec.neighbor[0])];
    nearest.push_back(
      std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2])));
  }
  double d = 0;  // (0 without a spacing, as on copies of one point: no winding number)
  if(!nearest.empty())
  {
    std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
    d = 2 * nearest[nearest.size() / 2] * std::sqrt(double(stride));
  }
  std::vector<std::uint32_t> field;
  for(std::size_t a = 0; a < part.size(); a += stride)
    field.push_back(part[a]);
  const auto turn_piece = [&](std::size_t r) {
    for(std::size_t a = ranges[r].begin; a < ranges[r].end; ++a)
      for(int k = 0; k < 3; ++k)
        n[3 * std::size_t(by_piece[a].second) + k] = -n[3 * std::size_t(by_piece[a].second) + k];
  };
  auto winding = [&](const double x[3], std::uint32_t skip) {
    double w = 0;
    for(std::uint32_t j : field)
    {
      if(piece[j] == skip)
        continue;
      const double* p = &xyz[3 * std::size_t(j)];
      const double* v = &n[3 * std::size_t(j)];
      const double e[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
      const double l2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
      if(l2 > 0)
        w += (e[0] * v[0] + e[1] * v[1] + e[2] * v[2]) / (l2 * std::sqrt(l2));
    }
    return w;
  };
  for(std::size_t r = 1; d > 0 && r <= tested; ++r)
  {
    const std::size_t size = ranges[r].end - ranges[r].begin, probed = std::min(size, probes);
    const std::uint32_t id = by_piece[ranges[r].begin].first;
    double vote = 0;
    for(std::size_t s = 0; s < probed; ++s)
    {
      const std::uint32_t i = by_piece[ranges[r].begin + s * size / probed].second;
      const double* p = &xyz[3 * std::size_t(i)];
      const double* v = &n[3 * std::size_t(i)];
      const double inside[3] = {p[0] - d * v[0], p[1] - d * v[1], p[2] - d * v[2]};
      const double outside[3] = {p[0] + d * v[0], p[1] + d * v[1], p[2] + d * v[2]};
      vote += winding(inside, id) - winding(outside, id);
    }
    if(vote < 0)
      turn_piece(r);
  }
  // the small pieces by their neighbours in the pieces before them (larger, or decided; the
  // largest, which set the part's side, stays). The part's pieces are numbered consecutively
  // and a point's neighbours in the graph are in its part: a piece's rank by number.
  const std::uint32_t first = by_piece.front().first;
  std::vector<std::uint32_t> rank(by_piece.back().first - first + 1, 0);
  for(std::size_t r = 0; r < ranges.size(); ++r)
    rank[by_piece[ranges[r].begin].first - first] = static_cast<std::uint32_t>(r);
  for(std::size_t r = 1; r < ranges.size(); ++r)
  {
    if(ranges[r].end - ranges[r].begin > local_vote_piece_size)
      continue;
    double vote = 0, weight = 0;
    for(std::size_t a = ranges[r].begin; a < ranges[r].end; ++a)
    {
      const std::uint32_t i = by_piece[a].second;
      const double* ni = &n[3 * std::size_t(i)];
      for(std::size_t e = offset[i]; e < offset[i + 1]; ++e)
      {
        const std::uint32_t j = adjacency[e];
        const std::size_t q = piece[j] - first;  // (wraps to a large value below `first`)
        if(q >= rank.size() || rank[q] >= r || !along_surface(xyz, n, i, j))
          continue;
        const double* nj = &n[3 * std::size_t(j)];
        const double agreement = ni[0] * nj[0] + ni[1] * nj[1] + ni[2] * nj[2];
        vote += agreement;
        weight += std::abs(agreement);
      }
    }
    if(vote < -local_vote_margin * weight)
      turn_piece(r);
  }
}

// Orients the unit normals `n` (3 per point; records that are not VALID have none) by Prim's
// algorithm on the symmetric graph of the records' neighbours, weights 1 - |n_i . n_j|
// (quantized), from the highest unvisited usable point of each connected part; then turns
// each part as a whole (choose_part_sign(), with `upward`), repairs closed parts piece by
// piece (repair_closed_part()) and, unless `upward`, checks each point of a part seen from all
// sides by the parity of the crossings along its normal (repair_by_crossing_parity()).
// Deterministic. `progress` gets the fraction of the points visited; returns false if
// cancelled.
inline bool orient_along_spanning_tree(const std::vector<Normal_record>& records, const std::vector<double>& xyz,
                                       std::vector<double>& n, bool upward, const std::function<bool(double)>& progress)
{
  const std::size_t count = records.size();
  auto usable = [&](std::size_t i) { return records[i].status == Curvature_estimate_status::VALID; };
  std::vector<std::size_t> offset;
  std::vector<std::uint32_t> adjacency;
  normal_graph(records, offset, adjacency);
  // seeds: usable points by decreasing height
  std::vector<std::uint32_t> by_height;
  for(std::size_t i = 0; i < count; ++i)
    if(usable(i))
      by_height.push_back(static_cast<std::uint32_t>(i));
  auto z = [&xyz](std::uint32_t i) { return xyz[3 * std::size_t(i) + 2]; };
  std::sort(by_height.begin(), by_height.end(),
            [&](std::uint32_t a, std::uint32_t b) { return z(a) > z(b) || (z(a) == z(b) && a < b); });

  // The candidate edges, by weight quantized to 1/4096 (a bucket queue: O(1) per edge, where
  // a binary heap of the ~24 edges per point costs 5 times more on 2M points); within a
  // bucket, last in first out. Lazy: an edge to a visited point is dropped when popped.
  constexpr std::size_t buckets = 4096;
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t> > > queue(buckets);
  std::size_t lowest = buckets, queued = 0;
  std::vector<char> visited(count, 0);
  std::vector<std::uint32_t> part;  // the points of the current connected part
  // the piece of each point (repair_closed_part()): its parent's if the tree edge weighs at most
  // 0.3, else a new one
  constexpr std::size_t reliable_bucket = std::size_t(0.3 * double(buckets));
  std::vector<std::uint32_t> piece(count, 0);
  std::uint32_t pieces = 0;
  const std::size_t step = std::max<std::size_t>(1, by_height.size() / 100);
  std::size_t done = 0;
  // for repair_by_crossing_parity(): the graph's neighbours, the farthest of a point's nearest
  std::vector<signed char> vote(upward ? 0 : count, 0);
  const auto neighbors = [&](std::uint32_t i, const auto& f) {
    for(std::size_t a = offset[i]; a < offset[i + 1]; ++a)
      f(adjacency[a]);
  };
  const auto reach = [&](std::uint32_t i) {
    double farthest = 0;
    const double* p = &xyz[3 * std::size_t(i)];
    for(std::size_t e = 0; e < records[i].degree; ++e)
    {
      const double* q = &xyz[3 * std::size_t(records[i].neighbor[e])];
      farthest = std::max(farthest, std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                              (p[2] - q[2]) * (p[2] - q[2])));
    }
    return farthest;
  };
  auto visit = [&](std::uint32_t i) {
    visited[i] = 1;
    part.push_back(i);
    const double* ni = &n[3 * std::size_t(i)];
    for(std::size_t a = offset[i]; a < offset[i + 1]; ++a)
    {
      const std::uint32_t j = adjacency[a];
      if(visited[j])
        continue;
      const double* nj = &n[3 * std::size_t(j)];
      const double w = 1 - std::abs(ni[0] * nj[0] + ni[1] * nj[1] + ni[2] * nj[2]);
      const std::size_t b = std::min(buckets - 1, static_cast<std::size_t>(std::max(0.0, w) * double(buckets)));
      queue[b].emplace_back(j, i);
      lowest = std::min(lowest, b);
      ++queued;
    }
    ++done;
    return !(progress && done % step == 0 && !progress(double(done) / double(by_height.size())));
  };
  for(std::uint32_t seed : by_height)
  {
    if(visited[seed])
      continue;
    part.clear();
    piece[seed] = pieces++;
    if(!visit(seed))
      return false;
    while(queued > 0)
    {
      while(queue[lowest].empty())
        ++lowest;
      const std::pair<std::uint32_t, std::uint32_t> e = queue[lowest].back();
      queue[lowest].pop_back();
      --queued;
      if(visited[e.first])
        continue;
      double* nj = &n[3 * std::size_t(e.first)];
      const double* ni = &n[3 * std::size_t(e.second)];
      if(ni[0] * nj[0] + ni[1] * nj[1] + ni[2] * nj[2] < 0)
        for(int a = 0; a < 3; ++a)
          nj[a] = -nj[a];
      piece[e.first] =
        lowest <= reliable_bucket && along_surface(xyz, n, e.second, e.first) ? piece[e.second] : pieces++;
      if(!visit(e.first))
        return false;
    }
    lowest = buckets;
    if(choose_part_sign(part, xyz, n, upward))
      repair_closed_part(part, piece, records, offset, adjacency, xyz, n);
    if(!upward)  // (a 2.5-D cloud's open parts are turned up, point by point)
      repair_by_crossing_parity(part, xyz, n, neighbors, reach, vote);
  }
  return true;
}

// The orientation that the named parameters ask for (checked: a finite target).
template <class NamedParameters>
Normal_orientation chosen_normal_orientation(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Normal_orientation orientation =
    choose_parameter(get_parameter(np, internal_np::normal_orientation), Normal_orientation());
  for(double t : orientation.target)
    if(!std::isfinite(t))
      throw std::invalid_argument("estimate_oriented_normals: parameter 'normal_orientation' needs a finite target");
  return orientation;
}

// The normals' scale, checked (std::invalid_argument): the radius or the count k of the fit
// (ladder.smallest; 0 by radius), and the automatic scale's ladder (largest 0 without it).
template <class NamedParameters>
Scale_ladder normal_scale_ladder(const NamedParameters& np, bool radius_given, double radius)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const char* name = "estimate_oriented_normals";
  const Normal_fit fit = choose_parameter(get_parameter(np, internal_np::normal_fit), Normal_fit::QUADRIC);
  const std::size_t k = choose_parameter(get_parameter(np, internal_np::neighbor_count),
                                         radius_given ? std::size_t(0) : default_normal_neighbors(fit));
  check_scale(radius, k, !radius_given, name);
  Scale_ladder ladder;
  ladder.largest = automatic_scale_parameter(np, radius_given, name);
  ladder.smallest = k;
  ladder.statistic = Scale_ladder::Statistic::NORMAL;
  if(ladder.largest > 0 && fit != Normal_fit::QUADRIC)
    throw std::invalid_argument("estimate_oriented_normals: parameter 'automatic_scale' needs Normal_fit::QUADRIC");
  return ladder;
}

// Whether the orientation spans the whole cloud: the spanning tree, which AUTOMATIC may choose.
inline bool is_global(const Normal_orientation& orientation)
{
  return orientation.kind == Normal_orientation::MINIMUM_SPANNING_TREE ||
         orientation.kind == Normal_orientation::AUTOMATIC;
}

// Step 1 of estimate_oriented_normals(): the unoriented normal and the nearest neighbours of
// every point (indices of `points`), on the driver; with a tile, of the tile's own points only
// (the others NOT_COMPUTED), whatever the orientation: a global orientation is then the
// caller's, over the records of every tile gathered (as the tool does for files larger than
// its memory limit), bitwise as over the whole cloud. `callback` gets the fraction done and
// returns false to cancel, which sets `cancelled`. The input normals are not read.
template <class ConcurrencyTag, class PointRange, class NamedParameters>
std::vector<Normal_record> estimate_normal_records(PointRange& points, bool radius_given, double radius,
                                                   const NamedParameters& np,
                                                   const std::function<bool(double)>& callback, bool& cancelled)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  typedef typename Geom_traits::Vector_3 Vector_3;
  const char* name = "estimate_oriented_normals";
  const Normal_fit fit = choose_parameter(get_parameter(np, internal_np::normal_fit), Normal_fit::QUADRIC);
  const Scale_ladder ladder = normal_scale_ladder(np, radius_given, radius);
  const std::size_t k = ladder.smallest;
  Neighborhood_options options;
  options.function_name = name;
  options.tile = choose_parameter(get_parameter(np, internal_np::tile), Tile::whole_space());
  options.has_tile = !options.tile.is_whole_space();
  if(callback)
    options.callback = [&callback, &cancelled](double f) {
      const bool go_on = callback(f);
      cancelled = cancelled || !go_on;
      return go_on;
    };
  const auto point_map = NP_helper::get_const_point_map(points, np);
  typedef typename boost::property_traits<decltype(point_map)>::key_type Key;
  const CGAL::Constant_property_map<Key, Vector_3> no_normal(Vector_3(0, 0, 1));
  std::vector<Normal_record> records;
  if(ladder.largest == 0)
    records = evaluate_with_maps<Normal_record, ConcurrencyTag>(points, radius_given, radius, k, point_map, no_normal,
                                                                options, Normal_at_point{fit, ladder});
  else
  {
    const std::function<bool(double)> one_pass_callback = options.callback;  // (sets `cancelled`)
    Knn_search_cache knn;  // (the search's tree: the same in every pass)
    // the curvatures' choices, in the pass after the first (the pass that climbs from the
    // smallest rung, as the curvatures' second pass does), over the whole range
    Scale_choices* choices =
      choose_parameter(get_parameter(np, internal_np::scale_choices), static_cast<Scale_choices*>(nullptr));
    Curvature_scale_records* curvature_records = nullptr;
    if(choices && !options.has_tile && ladder.rungs() > 1)
    {
      curvature_records = &choices->records();
      curvature_records->smallest = ladder.smallest;
      curvature_records->largest = ladder.largest;
      curvature_records->slot.clear();  // (until the second pass: none)
      curvature_records->records.clear();
    }
    const std::size_t second_largest = next_pass_largest(ladder, ladder.smallest);
    const auto run = [&](const Scale_ladder& l, const std::vector<char>* visit,
                         const Automatic_scale_progress::Callbacks& progress, bool& pass_cancelled) {
      Neighborhood_options o = options;
      o.visit = visit;
      o.knn_cache = &knn;
      // (the passes' progress, mapped by automatic_scale_passes(), on to one_pass_callback)
      o.callback = progress.points;
      Normal_at_point at_point{fit, l};
      if(curvature_records && visit && !l.gate && l.largest == second_largest)
      {
        curvature_records->assign_slots(*visit);
        at_point.curvatures = curvature_records;
      }
      std::vector<Normal_record> r = evaluate_with_maps<Normal_record, ConcurrencyTag>(
        points, radius_given, radius, l.largest, point_map, no_normal, o, at_point);
      pass_cancelled = cancelled;
      return r;
    };
    records = automatic_scale_passes<Normal_record>(
      one_pass_callback ? points_to_estimate(points, point_map, options.tile) : 0, ladder, run,
      [](const Normal_record& r) { return r.status == Curvature_estimate_status::VALID ? r.count : std::size_t(0); },
      one_pass_callback);
  }
  if(!options.has_tile)  // (with a tile, the other points are not computed)
    for(const Normal_record& r : records)
      cancelled = cancelled || r.status == Curvature_estimate_status::NOT_COMPUTED;
  return records;
}

// Step 2 of estimate_oriented_normals(): the unit normals `n` (3 per record, zero where a
// record is not VALID) of `records` oriented as `orientation` says, `xyz` holding the points'
// coordinates (3 per record). For AUTOMATIC, the cloud is 2.5-D by the records' normals. The
// spanning tree's `tree_progress` gets the fraction of the points visited; returns false if
// it cancelled.
inline bool orient_normal_records(const std::vector<Normal_record>& records, const std::vector<double>& xyz,
                                  const Normal_orientation& orientation, std::vector<double>& n,
                                  const std::function<bool(double)>& tree_progress)
{
  const std::size_t count = records.size();
  const bool global = is_global(orientation);
  bool upward = false;  // AUTOMATIC on a 2.5-D cloud
  if(orientation.kind == Normal_orientation::AUTOMATIC)
  {
    std::size_t usable = 0, vertical = 0;
    for(const Normal_record& r : records)
      if(r.status == Curvature_estimate_status::VALID)
      {
        ++usable;
        vertical += is_near_vertical(r.normal[0], r.normal[1], r.normal[2]) ? 1 : 0;
      }
    upward = is_two_and_a_half_d(vertical, usable);
  }
  n.assign(3 * count, 0.0);
  for(std::size_t i = 0; i < count; ++i)
  {
    if(records[i].status != Curvature_estimate_status::VALID)
      continue;
    std::copy(records[i].normal, records[i].normal + 3, &n[3 * i]);
    if(global)
      continue;
    double t[3] = {orientation.target[0], orientation.target[1], orientation.target[2]};
    if(orientation.kind == Normal_orientation::TOWARDS_POINT)
      for(int a = 0; a < 3; ++a)
        t[a] -= xyz[3 * i + a];
    if(n[3 * i] * t[0] + n[3 * i + 1] * t[1] + n[3 * i + 2] * t[2] < 0)
      for(int a = 0; a < 3; ++a)
        n[3 * i + a] = -n[3 * i + a];
  }
  return !global || orient_along_spanning_tree(records, xyz, n, upward, tree_progress);
}

// The common body of the two overloads.
template <class ConcurrencyTag, class PointRange, class NamedParameters>
std::size_t estimate_oriented_normals(PointRange& points, bool radius_given, double radius, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  typedef typename Geom_traits::Vector_3 Vector_3;
  static_assert(NP_helper::has_normal_map(),
                "Error: no normal map. Pass CGAL::parameters::normal_map(...): the normals are written there.");
  // (its exceptions first, as before the split)
  const bool automatic = normal_scale_ladder(np, radius_given, radius).largest > 0;
  const Normal_orientation orientation = chosen_normal_orientation(np);
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  const bool global = is_global(orientation);
  if(!choose_parameter(get_parameter(np, internal_np::tile), Tile::whole_space()).is_whole_space() && global)
    throw std::invalid_argument("estimate_oriented_normals: parameter 'tile' needs an orientation along a vector "
                                "or towards a point: a spanning tree, and the automatic choice, need the whole cloud");

  // 1. Unoriented normals and nearest neighbours (with the spanning tree, the fit is the first
  // 70% of the progress, 90% with the automatic scale: with it, the tree took 15% of the time on
  // a clean 1M terrain, 2.5% on lone-star.las).
  bool cancelled = false;
  const double fit_share = global ? (automatic ? 0.9 : 0.7) : 1.0;
  std::function<bool(double)> fit_progress;
  if(callback)
    fit_progress = [&callback, fit_share](double f) { return callback(fit_share * f); };
  const std::vector<Normal_record> records =
    estimate_normal_records<ConcurrencyTag>(points, radius_given, radius, np, fit_progress, cancelled);

  // 2. Orientation.
  const auto point_map = NP_helper::get_const_point_map(points, np);
  std::vector<double> n, xyz(3 * records.size(), 0.0);
  std::size_t i = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++i)
  {
    const auto& p = get(point_map, *it);
    xyz[3 * i] = CGAL::to_double(p.x());
    xyz[3 * i + 1] = CGAL::to_double(p.y());
    xyz[3 * i + 2] = CGAL::to_double(p.z());
  }
  if(!cancelled)
  {
    std::function<bool(double)> tree_progress;
    if(callback)
      tree_progress = [&callback, fit_share](double f) { return callback(fit_share + (1 - fit_share) * f); };
    cancelled = !orient_normal_records(records, xyz, orientation, n, tree_progress);
  }

  // 3. Output: the normals, zero where there is none (those points are then INVALID_NORMAL
  // for the estimators), if the run was cancelled, or outside the tile's core.
  const auto normal_map = NP_helper::get_normal_map(points, np);
  std::size_t without = 0;
  i = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++i)
  {
    const bool has = !cancelled && records[i].status == Curvature_estimate_status::VALID;
    without += has ? 0 : 1;
    put(normal_map, *it, has ? Vector_3(n[3 * i], n[3 * i + 1], n[3 * i + 2]) : Vector_3(0, 0, 0));
  }
  if(callback && !cancelled)
    callback(1.0);
  return without;
}

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Estimates an oriented unit normal at every point of a point cloud without normals (most
/// LiDAR scans) and writes it through `normal_map`: the normal of a fit of the point's `k`
/// nearest neighbours (itself included), on the package's neighbourhood driver (in parallel
/// with `CGAL::Parallel_tag`), then oriented as
/// `Point_set_curvatures::parameters::normal_orientation` says: along a minimum spanning
/// tree of the graph of each point's 12 nearest neighbours with each connected part's sign
/// chosen outward if it is closed, up if it is open (default), along a vector, towards a
/// point, or the spanning tree with every normal of its open parts along +z if the cloud is
/// 2.5-D (`CGAL::Normal_orientation`). The result is the input the curvature estimators of this
/// package need.
///
/// The fit (`Point_set_curvatures::parameters::normal_fit`) is by default a weighted quadric
/// (`CGAL::Normal_fit::QUADRIC`, 40 neighbours): its normals are nearly free of the
/// curvature's bias and vary smoothly from point to point, which the ASO needs since it
/// differentiates the normal field: on simulated scans the ASO on quadric normals comes close
/// to its error with exact normals, and far below its error on PCA-plane normals (measured:
/// benchmark/README.md, section 8). `CGAL::Normal_fit::PLANE` is the PCA plane (18
/// neighbours by default).
///
/// Points whose normal cannot be estimated get a zero normal, which the estimators report as
/// `INVALID_NORMAL`: non-finite coordinates, too few neighbours (3 for the plane, 6 for the
/// quadric), coincident neighbours, and neighbourhoods spread along one line only (the ratio
/// of the second to the first standard deviation of the positions below 0.05: one LiDAR scan
/// line at a neighbourhood smaller than the distance between lines, where any normal about the
/// line would fit; give a larger `k`). So do all points if the run is cancelled through
/// `callback`.
/// Sequential and parallel runs give identical normals.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PointRange a model of `Range` whose value type is the key type of the maps
///
/// \param points the point cloud
/// \param np named parameters among the ones below
///
/// \returns the number of points that got a zero normal.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a property map in which the normals are written. Required.}
///     \cgalParamType{a model of `WritablePropertyMap` whose value type is `geom_traits::Vector_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::normal_fit}
///     \cgalParamDescription{what is fitted to each neighbourhood}
///     \cgalParamType{`CGAL::Normal_fit`}
///     \cgalParamDefault{`CGAL::Normal_fit::QUADRIC`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::neighbor_count}
///     \cgalParamDescription{the number `k` of nearest neighbours of the fit, the point included}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{40 for `Normal_fit::QUADRIC`, 18 for `Normal_fit::PLANE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::normal_orientation}
///     \cgalParamDescription{how the normals are oriented (`CGAL::Normal_orientation`)}
///     \cgalParamType{`CGAL::Normal_orientation`}
///     \cgalParamDefault{`CGAL::Normal_orientation::minimum_spanning_tree()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::tile}
///     \cgalParamDescription{normals of the tile's own points only, bitwise as for the whole
///       cloud (`CGAL::Point_set_curvatures::Tile`; the other points get a zero normal); with
///       an orientation along a vector or towards a point only (the spanning tree and the
///       automatic choice need the whole cloud: `std::invalid_argument`). By count, a halo too small for a point's `k` nearest
///       throws `CGAL::Point_set_curvatures::Halo_too_small`.}
///     \cgalParamType{`CGAL::Point_set_curvatures::Tile`}
///     \cgalParamDefault{no tile: every point}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called from the calling thread with the fraction done, at least
///       every 1% of the points (the fit is the first 70% with the spanning tree and the
///       automatic orientation, 90% with the automatic scale, whose passes report the fraction
///       of the time expected: user manual, "Progress and cancellation"); returning
///       `false` cancels}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel` with a floating-point `FT`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument for a `neighbor_count` of 0, a non-finite orientation target,
/// or a tile with the spanning tree or the automatic orientation.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::size_t estimate_oriented_normals(PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_oriented_normals<ConcurrencyTag>(points, false, 0.0, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Same as above with the neighbours at distance `< radius` instead of the `k` nearest.
/// \throws std::invalid_argument if `radius` is not positive and finite.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::size_t estimate_oriented_normals(PointRange& points, double radius,
                                      const NamedParameters& np = parameters::default_values())
{
  return Point_set_curvatures::internal::estimate_oriented_normals<ConcurrencyTag>(points, true, radius, np);
}

}  // namespace CGAL

#endif
