// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A static k-d tree over 3-D points for the neighbourhoods by count (knn_neighborhoods.h):
// k nearest points and open balls, with results that depend only on the point set, never on
// the order in which the tree is traversed.
//
// Layout. The build permutes the points so that every node covers a contiguous range of
// them (median split along the axis of largest extent, leaves of at most leaf_size points)
// and stores, per node, that range and the bounding box of its points; the coordinates are
// copied in that order, so a leaf is scanned linearly. Searches go down the child whose box
// is nearer first and skip a box farther than the current bound of the k-th distance.
//
// Determinism. Candidates are ordered by (squared distance, id), lexicographically; a box is
// skipped only if it is strictly farther than the worst kept candidate, so the k nearest
// found are the first k of that order whatever the traversal. The build breaks coordinate
// ties by id; its shape depends on the number of points only, so it can be built in
// parallel and still be the same tree.
//
// Use. It serves the neighbourhoods by count that the grid cannot (knn_neighborhoods.h) and
// the sampling of d_k that sets the grid's side. Per query on 1M ellipsoid points in tree
// order (one run): the 43 nearest 4.3 us, a ball of 48 points 2.6 us, several times a grid
// query, which scans contiguous memory and sorts nothing; hence the grid first. Against the
// CGAL Kd_tree it replaces, its own code keeps the order of ties explicit and builds in
// parallel with a fixed shape.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_POINT_KD_TREE_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_POINT_KD_TREE_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

class Point_kd_tree
{
public:
  // (squared distance, id): ids are the positions of the points given to build()
  typedef std::pair<double, std::uint32_t> Candidate;

  static constexpr std::uint32_t leaf_size = 8;

  // Builds the tree on the points xyz[3 i .. 3 i + 2], i < n (copied), with ids i; with
  // Parallel_tag, the subtrees are built concurrently. The shape depends on n only (the
  // median is always taken, even along an axis without extent), so every node has its
  // place in advance and either tag gives the same tree.
  template <class ConcurrencyTag>
  void build(const double* xyz, std::size_t n)
  {
    std::vector<Item> items(n);
    for(std::size_t i = 0; i < n; ++i)
      items[i] = Item{{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}, static_cast<std::uint32_t>(i)};
    m_nodes.assign(n > 0 ? node_count(n) : 0, Node());
    if(n > 0)
      build_node<ConcurrencyTag>(0, 0, static_cast<std::uint32_t>(n), items, 0);
    m_xyz.resize(3 * n);
    m_id.resize(n);
    for(std::size_t t = 0; t < n; ++t)
    {
      for(int a = 0; a < 3; ++a)
        m_xyz[3 * t + a] = items[t].x[a];
      m_id[t] = items[t].id;
    }
  }

  // Renames every id i to new_id[i] (a permutation or any injective map).
  void relabel(const std::vector<std::uint32_t>& new_id)
  {
    for(std::uint32_t& id : m_id)
      id = new_id[id];
  }

  std::size_t size() const { return m_id.size(); }

  // The `count` nearest points of p (count >= 1), by increasing (d2, id), in `out`.
  void nearest(const double p[3], std::size_t count, std::vector<Candidate>& out) const
  {
    nearest_unordered(p, count, out);
    std::sort(out.begin(), out.end());
  }

  // The same points in no particular order (the neighbourhoods by count order them by input
  // position afterwards, and sorting them by distance was 12% of a run of the automatic scale).
  void nearest_unordered(const double p[3], std::size_t count, std::vector<Candidate>& out) const
  {
    out.clear();
    if(m_id.empty() || count == 0)
      return;
    double bound = std::numeric_limits<double>::infinity();
    nearest_in(0, p, count, bound, out);
    keep_best(count, out);
  }

  // The points at squared distance < r2 from p, by increasing (d2, id), in `out`.
  void ball(const double p[3], double r2, std::vector<Candidate>& out) const
  {
    out.clear();
    if(!m_id.empty())
      ball_in(0, p, r2, out);
    std::sort(out.begin(), out.end());
  }

private:
  struct Node
  {
    double lo[3], hi[3];
    std::uint32_t begin, end;
    std::uint32_t left = 0, right = 0;  // children; 0 for a leaf (0 is the root)
  };

  struct Item
  {
    double x[3];
    std::uint32_t id;
  };

  // Nodes of a subtree of `size` points: leaves hold at most leaf_size, inner nodes split at
  // the median (sizes floor and ceil of the half).
  static std::uint32_t node_count(std::size_t size)
  {
    return size <= leaf_size ? 1 : 1 + node_count(size / 2) + node_count(size - size / 2);
  }

  template <class ConcurrencyTag>
  void build_node(std::uint32_t node, std::uint32_t begin, std::uint32_t end, std::vector<Item>& items, int depth)
  {
    Node& nd = m_nodes[node];
    nd.begin = begin;
    nd.end = end;
    for(int a = 0; a < 3; ++a)
      nd.lo[a] = nd.hi[a] = items[begin].x[a];
    for(std::uint32_t t = begin + 1; t < end; ++t)
      for(int a = 0; a < 3; ++a)
      {
        nd.lo[a] = std::min(nd.lo[a], items[t].x[a]);
        nd.hi[a] = std::max(nd.hi[a], items[t].x[a]);
      }
    if(end - begin <= leaf_size)
      return;
    int axis = 0;
    for(int a = 1; a < 3; ++a)
      if(nd.hi[a] - nd.lo[a] > nd.hi[axis] - nd.lo[axis])
        axis = a;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [axis](const Item& i, const Item& j) {
                       return i.x[axis] < j.x[axis] || (i.x[axis] == j.x[axis] && i.id < j.id);
                     });
    nd.left = node + 1;
    nd.right = node + 1 + node_count(mid - begin);
    const std::uint32_t left = nd.left, right = nd.right;
#ifdef CGAL_LINKED_WITH_TBB
    // about 2^10 tasks: enough to balance 2 to 64 threads, few enough to cost nothing
    if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && depth < 10)
    {
      tbb::parallel_invoke([&] { build_node<ConcurrencyTag>(left, begin, mid, items, depth + 1); },
                           [&] { build_node<ConcurrencyTag>(right, mid, end, items, depth + 1); });
      return;
    }
#endif
    build_node<ConcurrencyTag>(left, begin, mid, items, depth + 1);
    build_node<ConcurrencyTag>(right, mid, end, items, depth + 1);
  }

  double box_squared_distance(const Node& nd, const double p[3]) const
  {
    double d2 = 0;
    for(int a = 0; a < 3; ++a)
    {
      const double below = nd.lo[a] - p[a], above = p[a] - nd.hi[a];
      const double d = below > 0 ? below : (above > 0 ? above : 0.0);
      d2 += d * d;
    }
    return d2;
  }

  // The same expression as the grid's scan (visit_cells_knn in knn_neighborhoods.h): both
  // paths see the same distances, to the bit.
  double squared_distance(std::uint32_t t, const double p[3]) const
  {
    const double dx = m_xyz[3 * std::size_t(t)] - p[0];
    const double dy = m_xyz[3 * std::size_t(t) + 1] - p[1];
    const double dz = m_xyz[3 * std::size_t(t) + 2] - p[2];
    return dx * dx + dy * dy + dz * dz;
  }

  // Keeps the `count` best candidates of `out` (unordered).
  static void keep_best(std::size_t count, std::vector<Candidate>& out)
  {
    if(out.size() <= count)
      return;
    std::nth_element(out.begin(), out.begin() + (count - 1), out.end());
    out.resize(count);
  }

  // Depth first, nearer child first. `out` collects every candidate not farther than `bound`
  // (no heap: sifting pairs costs more than the rare compactions); when it holds twice
  // `count`, it is cut to the `count` best and `bound` becomes the farthest of them, an upper
  // bound of the final k-th distance, which skips the boxes strictly beyond it.
  void nearest_in(std::uint32_t node, const double p[3], std::size_t count, double& bound,
                  std::vector<Candidate>& out) const
  {
    const Node& nd = m_nodes[node];
    if(nd.left == 0)
    {
      for(std::uint32_t t = nd.begin; t < nd.end; ++t)
      {
        const double d2 = squared_distance(t, p);
        if(d2 <= bound)
          out.emplace_back(d2, m_id[t]);
      }
      if(out.size() >= 2 * count)
      {
        keep_best(count, out);
        bound = std::max_element(out.begin(), out.end())->first;
      }
      return;
    }
    const double d0 = box_squared_distance(m_nodes[nd.left], p);
    const double d1 = box_squared_distance(m_nodes[nd.right], p);
    const bool left_first = d0 <= d1;
    if(!((left_first ? d0 : d1) > bound))
      nearest_in(left_first ? nd.left : nd.right, p, count, bound, out);
    if(!((left_first ? d1 : d0) > bound))
      nearest_in(left_first ? nd.right : nd.left, p, count, bound, out);
  }

  void ball_in(std::uint32_t node, const double p[3], double r2, std::vector<Candidate>& out) const
  {
    const Node& nd = m_nodes[node];
    if(!(box_squared_distance(nd, p) < r2))
      return;
    if(nd.left == 0)
    {
      for(std::uint32_t t = nd.begin; t < nd.end; ++t)
      {
        const double d2 = squared_distance(t, p);
        if(d2 < r2)
          out.emplace_back(d2, m_id[t]);
      }
      return;
    }
    ball_in(nd.left, p, r2, out);
    ball_in(nd.right, p, r2, out);
  }

  std::vector<double> m_xyz;        // coordinates in tree order
  std::vector<std::uint32_t> m_id;  // tree order -> id
  std::vector<Node> m_nodes;
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
