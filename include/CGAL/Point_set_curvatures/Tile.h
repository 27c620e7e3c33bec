// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Spatial tiles: estimating a cloud piece by piece (bounded memory, several processes or
// machines) with results bitwise identical to the whole-cloud run.

#ifndef CGAL_POINT_SET_CURVATURES_TILE_H
#define CGAL_POINT_SET_CURVATURES_TILE_H

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {

/// \ingroup PkgPointSetCurvaturesRef
///
/// One tile of a cloud: the points it estimates (its *own* points, those inside `core`) and the
/// distance `halo` up to which the points around the core are present as neighbours.
///
/// Given to an estimation function with the named parameter
/// `CGAL::Point_set_curvatures::parameters::tile()`, the range passed to the function must hold
/// every point of the whole cloud at distance `<= halo` from `core` (points farther away are
/// allowed and ignored as queries), **in the same relative order as in the whole cloud**. Then
/// the estimate of every own point is bitwise identical to the one of the whole-cloud run
/// with the same parameters and concurrency tag, whatever the other tiles; the other points get
/// the status `NOT_COMPUTED`, or `NON_FINITE_POINT` / `INVALID_NORMAL` if they are unusable.
///
/// The core is half-open: a point `p` is own if `core.min(a) <= p[a] < core.max(a)` on each
/// axis `a`; bounds may be infinite, so that the tiles of a `Tile_grid` cover all of space and
/// every finite point is own in exactly one tile.
///
/// An infinite `halo` says that the range holds the whole cloud (every finite point): the
/// estimation then never throws `Halo_too_small`, even when the cloud has fewer points than a
/// neighbourhood by count asks for (it gets them all, as in the whole-cloud run).
struct Tile
{
  /// the region of the tile's own points (half-open, see above)
  Bbox_3 core;
  /// every point of the cloud at distance `<= halo` from `core` is in the range
  double halo = 0;

  Tile() = default;
  Tile(const Bbox_3& core_box, double halo_distance) : core(core_box), halo(halo_distance) {}

  /// The tile whose core is all of space: every point is own, the same as passing no tile
  /// (a driver can then always pass a tile, for example the whole cloud when it fits in
  /// memory, and pieces of it when it does not).
  static Tile whole_space()
  {
    const double inf = std::numeric_limits<double>::infinity();
    return Tile(Bbox_3(-inf, -inf, -inf, inf, inf, inf), inf);
  }

  /// `true` for a tile whose core is all of space (see `whole_space()`)
  bool is_whole_space() const
  {
    const double inf = std::numeric_limits<double>::infinity();
    return core.xmin() == -inf && core.ymin() == -inf && core.zmin() == -inf && core.xmax() == inf &&
           core.ymax() == inf && core.zmax() == inf;
  }

  /// `true` if the point `(x, y, z)` is one of the tile's own points (never for a point with
  /// a non-finite coordinate: such points are nobody's own, as for `Tile_grid::tile_of()`)
  bool owns(double x, double y, double z) const
  {
    return x >= core.xmin() && x < core.xmax() && y >= core.ymin() && y < core.ymax() && z >= core.zmin() &&
           z < core.zmax() && std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
  }

  /// Euclidean distance from `(x, y, z)` to the core (0 inside; infinite only when the
  /// distance itself exceeds the largest double: no overflow of the squares; NaN for a point
  /// with a non-finite coordinate, so that such a point is never within a halo)
  double distance_to_core(double x, double y, double z) const
  {
    if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
      return std::numeric_limits<double>::quiet_NaN();
    const double d[3] = {std::max({0.0, core.xmin() - x, x - core.xmax()}),
                         std::max({0.0, core.ymin() - y, y - core.ymax()}),
                         std::max({0.0, core.zmin() - z, z - core.zmax()})};
    const double s = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if(s <= (std::numeric_limits<double>::max)())
      return std::sqrt(s);
    // the squares overflow (a distance beyond 1e154): the same distance scaled by its largest
    // component
    const double m = std::max({d[0], d[1], d[2]});
    if(!(m <= (std::numeric_limits<double>::max)()))
      return m;  // infinite
    const double u = d[0] / m, v = d[1] / m, w = d[2] / m;
    return m * std::sqrt(u * u + v * v + w * w);
  }

  /// Distance from an own point to the core's boundary (infinite along unbounded sides): a
  /// ball around it of radius `distance_inside_core() + halo` holds only points of the range.
  double distance_inside_core(double x, double y, double z) const
  {
    return std::min(
      {x - core.xmin(), core.xmax() - x, y - core.ymin(), core.ymax() - y, z - core.zmin(), core.zmax() - z});
  }
};

/// \ingroup PkgPointSetCurvaturesRef
///
/// Thrown by an estimation function run on a `Tile` when the tile's halo is too small for
/// the result to be exact: with neighbourhoods by count, a point's radius reaches its `k`-th
/// nearest neighbour, which is only known once it is found. `required_halo()` is a larger
/// halo to run the tile again with: one that suffices for every point whose `k` nearest were
/// found in the range (more points in the range only shrink the radii), or, when the range
/// holds fewer than `k` points, twice the halo (at least the range's extent). Growing the
/// halo by it terminates: at worst the range becomes the whole cloud, which a driver says
/// with an infinite halo (never too small). `required_halo()` may be infinite (a point
/// whose neighbours are farther than the largest double).
class Halo_too_small : public std::runtime_error
{
public:
  Halo_too_small(double required, double given) : std::runtime_error(message(required, given)), m_required(required) {}
  /// a halo with which the same tile gives exact results
  double required_halo() const { return m_required; }

private:
  static std::string message(double required, double given)
  {
    std::ostringstream s;
    s.precision(17);
    s << "Point_set_curvatures: the tile's halo " << given << " is too small for exact results; a halo of " << required
      << " suffices";
    return s.str();
  }
  double m_required;
};

// ---- The halo a tile needs: the rule that every driver of tiles (the tool's --memory-limit,
// Dask) follows ----

/// \ingroup PkgPointSetCurvaturesRef
/// The halo of a tile for neighbourhoods of radius `r` (in the unit of the coordinates):
/// `2 r`. An estimate reads the points within `r`, and the default ASO's sample weights
/// (tangent Voronoi areas) of each of them read their own neighbours within `r`; no retry is
/// ever needed. An infinite `r` gives an infinite halo (the whole cloud).
/// \pre `r` is positive (the estimation functions refuse other radii).
inline double halo_for_radius(double r) { return 2 * r; }

/// \ingroup PkgPointSetCurvaturesRef
/// A first guess of the halo of a tile for neighbourhoods of `k` points (by count), for
/// `n` finite points spread over `box` (in the unit of the coordinates): twice the radius of
/// a disk holding `k` of them when they cover, evenly, a surface spanning the two largest
/// extents of the box. A guess: where the density is lower, the estimation throws
/// `Halo_too_small` and the tile is run again with `next_halo()`. `n = 0` counts as 1; a box
/// flat in two directions (points on a line) gives a tiny halo, grown by the retries. Where
/// the box's area overflows a double, it is computed from the halved extents (the guess is
/// then infinite only if the halo itself overflows); an infinite bound gives an infinite
/// halo (the whole cloud).
/// \pre `box` is not empty and its bounds are not NaN.
inline double halo_guess_for_count(const Bbox_3& box, std::size_t n, std::size_t k)
{
  double e[3] = {box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()};
  std::sort(e, e + 3);
  const double area = (std::max)(e[1] * e[2], 1e-300);
  // (pi to 15 digits: the tool's guess since its first version; with more digits one tile of a
  // shipped LAS run would be read once more, and the tool's summary would change)
  const double per_point = double(k) / (3.14159265358979 * double((std::max)(std::size_t(1), n)));
  const double halo = 2 * std::sqrt(area * per_point);
  if(std::isfinite(halo))
    return halo;
  double h[3] = {box.xmax() / 2 - box.xmin() / 2, box.ymax() / 2 - box.ymin() / 2, box.zmax() / 2 - box.zmin() / 2};
  std::sort(h, h + 3);
  return 4 * (std::sqrt(h[1]) * std::sqrt(h[2]) * std::sqrt(per_point));
}

/// \ingroup PkgPointSetCurvaturesRef
/// The halo to run a tile again with after its estimation threw `Halo_too_small`:
/// `required_halo` (its `required_halo()`), at least `at_least`, so that the tile's range
/// grows at every retry when `at_least` exceeds the last halo. The drivers (the tool's
/// `--memory-limit`, Dask) pass the distance to the core of the nearest finite point the
/// range left out (the least growth that adds a point; a range that left none out is the
/// whole cloud, see `halo_of_range()`, and is never retried), or a lower bound of it above the
/// halo where they skipped points unread (`Tile_range`). A NaN `required_halo` gives `at_least`.
inline double next_halo(double required_halo, double at_least)
{
  return required_halo > at_least ? required_halo : at_least;
}

/// \ingroup PkgPointSetCurvaturesRef
/// The halo to estimate a tile's range with, given the halo `halo` it was gathered with: an
/// infinite halo when the range holds every finite point of the cloud (`finite_in_range ==
/// finite_in_cloud`, whatever `halo`'s value): the estimation then never throws
/// `Halo_too_small`, even for neighbourhoods by count larger than the cloud, which get every
/// point as in the whole-cloud run; otherwise `halo`. Every driver of tiles applies this rule,
/// so that a tile that already holds the whole cloud is never retried.
inline double halo_of_range(double halo, std::size_t finite_in_range, std::size_t finite_in_cloud)
{
  return finite_in_range == finite_in_cloud ? std::numeric_limits<double>::infinity() : halo;
}

/// \ingroup PkgPointSetCurvaturesRef
///
/// A tile's range as a driver gathers it, reading the cloud in input order: `take()` says
/// whether a point belongs to the range (a finite point at distance `<= halo` from the core),
/// and the range's rules follow from what was read: `halo()` the halo to estimate it with
/// (`halo_of_range()`: infinite once it holds every finite point of the cloud) and, after
/// `Halo_too_small`, `retry_halo()` the halo to gather it again with (`next_halo()` at the
/// nearest finite point left out, or nearer where the driver did not read every point: the
/// distance given to `skip_beyond()`, below which lie none of the points it skipped).
class Tile_range
{
public:
  /// The range of `tile` (its core and halo).
  explicit Tile_range(const Tile& tile) : m_tile(tile) {}

  /// Whether the next point of the cloud belongs to the range.
  bool take(double x, double y, double z)
  {
    const double d = m_tile.distance_to_core(x, y, z);  // (NaN for a non-finite point)
    if(d <= m_tile.halo)
    {
      ++m_finite;
      return true;
    }
    if(d < m_nearest_left_out)
      m_nearest_left_out = d;
    return false;
  }

  /// Notes that the driver skipped points at distance at least `distance` from the core
  /// (`distance` above the halo: a block of a file it did not read).
  void skip_beyond(double distance)
  {
    if(distance < m_nearest_left_out)
      m_nearest_left_out = distance;
  }

  /// the number of points taken (all finite)
  std::size_t finite_taken() const { return m_finite; }
  /// the distance to the core of the nearest finite point left out (infinite if none)
  double nearest_left_out() const { return m_nearest_left_out; }
  /// `halo_of_range()` of the range, the cloud holding `finite_in_cloud` finite points
  double halo(std::size_t finite_in_cloud) const { return halo_of_range(m_tile.halo, m_finite, finite_in_cloud); }
  /// `next_halo()` at the nearest point left out (or skipped), after the range's estimation
  /// threw `error`.
  double retry_halo(const Halo_too_small& error) const { return next_halo(error.required_halo(), m_nearest_left_out); }

private:
  Tile m_tile;
  std::size_t m_finite = 0;
  double m_nearest_left_out = std::numeric_limits<double>::infinity();
};

/// \ingroup PkgPointSetCurvaturesRef
/// The box of a `Tile_grid` over the points `xyz` (x y z of each point in turn, every
/// coordinate finite): on each axis the 0.1% and 99.9% quantiles of the values (the values of
/// ranks `floor(0.001 (m - 1))` and `ceil(0.999 (m - 1))` of the `m` points), so that a few
/// outliers (a bird over an airborne scan, a stray return) do not stretch the tiles; the outer
/// tiles reach to infinity and own them. No point gives the box reduced to the origin. The
/// drivers take it on a `Tile_box_sample` of the cloud.
inline Bbox_3 tile_grid_box(const std::vector<double>& xyz)
{
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  const std::size_t m = xyz.size() / 3;
  if(m > 0)
  {
    std::vector<double> v(m);
    const std::size_t low_rank = std::size_t(0.001 * double(m - 1));
    const std::size_t high_rank = std::size_t(std::ceil(0.999 * double(m - 1)));
    for(int a = 0; a < 3; ++a)
    {
      for(std::size_t i = 0; i < m; ++i)
        v[i] = xyz[3 * i + a];
      // (two selections: the values a sort would put at those ranks, in linear time)
      std::nth_element(v.begin(), v.begin() + low_rank, v.end());
      lo[a] = v[low_rank];
      std::nth_element(v.begin() + low_rank, v.begin() + high_rank, v.end());
      hi[a] = v[high_rank];
    }
  }
  return Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

/// \ingroup PkgPointSetCurvaturesRef
///
/// An evenly spaced sample of a cloud's finite points, read once in input order without
/// knowing their number, for the box of its tiles (`box()`, `tile_grid_box()`): every
/// `stride()`-th finite point, the stride the least power of two that keeps at most
/// `max_points` of them (when the sample grows past it, the stride doubles and every other
/// sampled point is dropped).
class Tile_box_sample
{
public:
  /// the sample's size by default: 2^20 points (24 MiB)
  static constexpr std::size_t default_max_points = std::size_t(1) << 20;

  /// \pre `max_points >= 1`
  explicit Tile_box_sample(std::size_t max_points = default_max_points) : m_max((std::max)(max_points, std::size_t(1)))
  {}

  /// Takes the next point of the cloud in input order (points with a non-finite coordinate
  /// are skipped: they are not counted).
  void add(double x, double y, double z)
  {
    if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
      return;
    if(m_seen++ % m_stride != 0)
      return;
    m_xyz.insert(m_xyz.end(), {x, y, z});
    if(m_xyz.size() > 3 * m_max)
    {
      std::size_t m = 0;
      for(std::size_t i = 0; 3 * i < m_xyz.size(); i += 2, ++m)
        std::copy(&m_xyz[3 * i], &m_xyz[3 * i] + 3, &m_xyz[3 * m]);
      m_xyz.resize(3 * m);
      m_stride *= 2;
    }
  }

  /// the sampled points' coordinates, x y z of each in turn
  const std::vector<double>& coordinates() const { return m_xyz; }
  /// the number of sampled points
  std::size_t size() const { return m_xyz.size() / 3; }
  /// every `stride()`-th finite point is sampled
  std::size_t stride() const { return m_stride; }
  /// `tile_grid_box(coordinates())`
  Bbox_3 box() const { return tile_grid_box(m_xyz); }

private:
  std::size_t m_max;
  std::size_t m_stride = 1, m_seen = 0;
  std::vector<double> m_xyz;
};

/// \ingroup PkgPointSetCurvaturesRef
///
/// A partition of space into a grid of tiles covering a cloud's bounding box: every finite
/// point is own in exactly one tile (the outer tiles extend to infinity), and
/// `for_each_tile_near()` lists the tiles whose halo contains a point, so that one pass over a
/// cloud distributes it (own points and halos) in input order.
class Tile_grid
{
public:
  Tile_grid() = default;

  /// Tiles of side about `tile_side` over `box` (at least one per axis; the interior
  /// boundaries split each axis of the box evenly).
  /// \throws std::invalid_argument if `tile_side` is not positive and finite.
  Tile_grid(const Bbox_3& box, double tile_side)
  {
    if(!(tile_side > 0) || !std::isfinite(tile_side))
      throw std::invalid_argument("Tile_grid: the tile side must be positive and finite");
    std::array<std::size_t, 3> counts;
    for(int a = 0; a < 3; ++a)
    {
      // the extent of finite bounds may overflow (from -1e308 to 1e308): halved, it cannot
      const double half =
        std::isfinite(box.min(a)) && std::isfinite(box.max(a)) ? box.max(a) / 2 - box.min(a) / 2 : 0.0;
      const double c = half > 0 ? std::ceil(2 * (half / tile_side)) : 1.0;
      counts[a] = static_cast<std::size_t>(std::min(c, 1e6));
    }
    set(box, counts);
  }

  /// `counts[a]` tiles along axis `a` over `box` (each at least 1).
  Tile_grid(const Bbox_3& box, const std::array<std::size_t, 3>& counts) { set(box, counts); }

  /// number of tiles
  std::size_t size() const { return m_boundaries[0].empty() ? 0 : count(0) * count(1) * count(2); }
  /// number of tiles along axis `a`
  std::size_t count(int a) const { return m_boundaries[a].size() - 1; }

  /// Tile `i` (`i < size()`) with the given halo. Its core's outer sides are infinite.
  Tile tile(std::size_t i, double halo) const
  {
    const std::size_t c[3] = {i % count(0), (i / count(0)) % count(1), i / (count(0) * count(1))};
    return Tile(Bbox_3(m_boundaries[0][c[0]], m_boundaries[1][c[1]], m_boundaries[2][c[2]], m_boundaries[0][c[0] + 1],
                       m_boundaries[1][c[1] + 1], m_boundaries[2][c[2] + 1]),
                halo);
  }

  /// The tile owning `(x, y, z)`, or `size()` for a point with a NaN or infinite coordinate
  /// (such points are nobody's own point: their estimate is `NON_FINITE_POINT` anyway).
  std::size_t tile_of(double x, double y, double z) const
  {
    const double p[3] = {x, y, z};
    std::size_t c[3];
    for(int a = 0; a < 3; ++a)
    {
      if(!std::isfinite(p[a]))
        return size();
      c[a] = slab(a, p[a]);
    }
    return c[0] + count(0) * (c[1] + count(1) * c[2]);
  }

  /// Calls `f(i)` for every tile `i` whose core is at distance `<= halo` from `(x, y, z)`
  /// (the owning tile included), in increasing `i`. Nothing for non-finite points.
  template <class Function>
  void for_each_tile_near(double x, double y, double z, double halo, Function&& f) const
  {
    const double p[3] = {x, y, z};
    std::size_t first[3], last[3];
    for(int a = 0; a < 3; ++a)
    {
      if(!std::isfinite(p[a]))
        return;
      first[a] = slab(a, p[a] - halo);
      last[a] = slab(a, p[a] + halo);
    }
    for(std::size_t k = first[2]; k <= last[2]; ++k)
      for(std::size_t j = first[1]; j <= last[1]; ++j)
        for(std::size_t i = first[0]; i <= last[0]; ++i)
        {
          const std::size_t t = i + count(0) * (j + count(1) * k);
          if(tile(t, halo).distance_to_core(x, y, z) <= halo)
            f(t);
        }
  }

private:
  void set(const Bbox_3& box, const std::array<std::size_t, 3>& counts)
  {
    const double inf = std::numeric_limits<double>::infinity();
    for(int a = 0; a < 3; ++a)
    {
      const std::size_t n = std::max<std::size_t>(1, counts[a]);
      std::vector<double>& b = m_boundaries[a];
      b.assign(1, -inf);
      const double lo = box.min(a), extent = box.max(a) - box.min(a);
      // an extent that overflows (finite bounds from -1e308 to 1e308) is split in halves:
      // lo/2 + (hi/2 - lo/2) t stays between lo/2 and hi/2, and doubling it is exact
      const double half = box.max(a) / 2 - box.min(a) / 2;
      const bool overflows = !std::isfinite(extent) && std::isfinite(half);
      for(std::size_t i = 1; i < n; ++i)
      {
        const double t = double(i) / double(n);
        const double v = overflows ? 2 * (lo / 2 + half * t) : lo + extent * t;
        if(std::isfinite(v) && v > b.back())
          b.push_back(v);
      }
      b.push_back(inf);
    }
  }

  // index of the slab [b_i, b_{i+1}) holding v along axis a (clamped for infinite v)
  std::size_t slab(int a, double v) const
  {
    const std::vector<double>& b = m_boundaries[a];
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), v) - b.begin());
    return std::min(std::max<std::size_t>(i, 1), b.size() - 1) - 1;
  }

  std::vector<double> m_boundaries[3];  // per axis: -inf, interior boundaries, +inf
};

}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif  // CGAL_POINT_SET_CURVATURES_TILE_H
