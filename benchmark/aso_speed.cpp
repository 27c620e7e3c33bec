// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Speed and memory of the core estimators (issue: core package).
//
// 1M points of an ellipsoid (random order), radius chosen for about 40 neighbours. In one
// run, each timed several times (best kept):
//   - bare traversal: build the sorted uniform grid (keys, sort, sorted copy of the
//     positions) and visit every pair within r, adding one coordinate: the floor of any
//     fixed-radius estimator; and the same with std::sort instead of the estimators' radix
//     sort (what the grid's sort saves),
//   - CGAL Kd_tree + Fuzzy_sphere visiting the same pairs (why the package uses a grid),
//   - APSS and ASO, sequential and parallel,
//   - the default's sample weights alone (estimate_tangent_voronoi_areas) and the default ASO
//     reading them (sample_weight_map): the cost of an area pass shared by several estimators,
//   - ASO with neighbourhoods by count (neighbor_count = the mean number of neighbours of
//     the radius runs, rounded), sequential and parallel: the cost of a per-point radius.
// Prints a Markdown table with seconds, ns per (point, neighbour) pair and ratios to the
// bare traversal, the parallel speed-up, and the peak heap used by ASO beyond its input
// and its result vector.
//
// usage: aso_speed [number_of_points=1000000] [repetitions=3] [--no-kdtree]

#include "bench_support.h"
#include "memory_counter.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_tangent_voronoi_areas.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

using namespace psc_test;
using psc_bench::ellipsoid_area;
using psc_bench::seconds_since;

namespace PSCi = CGAL::Point_set_curvatures::internal;

// Bare traversal: sorted grid built as the estimators build it (radix sort of the cell keys;
// with `std_sort`, std::sort as before it, for comparison), then every pair within r.
// Returns the sum of the x coordinates of all neighbours (so nothing is optimised away)
// and the number of pairs.
std::pair<double, std::size_t> bare_traversal(const std::vector<Oriented_point>& pts, double r, bool std_sort = false)
{
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const auto& p : pts)
    for(int i = 0; i < 3; ++i)
    {
      lo[i] = std::min(lo[i], p.first[i]);
      hi[i] = std::max(hi[i], p.first[i]);
    }
  PSCi::Neighbor_grid grid;
  grid.set_geometry(lo, hi, r);
  std::vector<PSCi::Neighbor_grid::Keyed_index> keyed(pts.size());
  for(std::size_t i = 0; i < pts.size(); ++i)
    keyed[i] = {grid.key(pts[i].first.x(), pts[i].first.y(), pts[i].first.z()), static_cast<std::uint32_t>(i)};
  if(std_sort)
    std::sort(keyed.begin(), keyed.end());
  else
  {
    std::vector<PSCi::Neighbor_grid::Keyed_index> scratch;
    PSCi::sort_by_key_then_index(keyed, scratch);
  }
  grid.set_cells(keyed);
  std::vector<double> xyz(3 * pts.size());
  for(std::size_t k = 0; k < pts.size(); ++k)
    for(int i = 0; i < 3; ++i)
      xyz[3 * k + i] = pts[keyed[k].second].first[i];
  std::vector<PSCi::Neighbor_grid::Keyed_index>().swap(keyed);

  // Four partial sums so that the loop is not bound by the latency of one floating-point
  // addition chain (a single accumulator makes this floor 40% slower).
  const double r2 = r * r;
  double sum[4] = {0, 0, 0, 0};
  std::size_t pairs = 0;
  grid.for_each_cell(0, grid.number_of_cells(), [&](PSCi::Index_range cell, const PSCi::Index_range* rows) {
    for(std::uint32_t q = cell.begin; q < cell.end; ++q)
    {
      const double x0 = xyz[3 * q], x1 = xyz[3 * q + 1], x2 = xyz[3 * q + 2];
      std::size_t count = 0;
      for(int row = 0; row < 9; ++row)
      {
        std::uint32_t j = rows[row].begin;
        for(; j + 4 <= rows[row].end; j += 4)
          for(int l = 0; l < 4; ++l)
          {
            const double* p = &xyz[3 * (j + l)];
            const double dx = p[0] - x0, dy = p[1] - x1, dz = p[2] - x2;
            const bool inside = dx * dx + dy * dy + dz * dz < r2;
            sum[l] += inside ? p[0] : 0.0;
            count += inside;
          }
        for(; j < rows[row].end; ++j)
        {
          const double* p = &xyz[3 * j];
          const double dx = p[0] - x0, dy = p[1] - x1, dz = p[2] - x2;
          const bool inside = dx * dx + dy * dy + dz * dz < r2;
          sum[0] += inside ? p[0] : 0.0;
          count += inside;
        }
      }
      pairs += count;
    }
  });
  return {sum[0] + sum[1] + sum[2] + sum[3], pairs};
}

// The same pairs with CGAL's Kd_tree and Fuzzy_sphere, points spatially sorted first.
std::pair<double, std::size_t> kdtree_traversal(const std::vector<Oriented_point>& pts, double r)
{
  typedef CGAL::Search_traits_3<Kernel> Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;
  std::vector<Point> sorted;
  sorted.reserve(pts.size());
  for(const auto& p : pts)
    sorted.push_back(p.first);
  CGAL::spatial_sort(sorted.begin(), sorted.end());
  Tree tree(sorted.begin(), sorted.end());
  tree.build();
  double sum = 0;
  std::size_t pairs = 0;
  std::vector<Point> found;
  for(const Point& p : sorted)
  {
    found.clear();
    tree.search(std::back_inserter(found), Sphere(p, r, 0.));
    for(const Point& q : found)
      if(CGAL::squared_distance(p, q) < r * r)
      {
        sum += q.x();
        ++pairs;
      }
  }
  return {sum, pairs};
}

int main(int argc, char** argv)
{
  std::size_t n = 1000000;
  int repetitions = 3;
  bool kdtree = true;
  int positional = 0;
  for(int i = 1; i < argc; ++i)
  {
    if(std::strcmp(argv[i], "--no-kdtree") == 0)
      kdtree = false;
    else if(positional++ == 0)
      n = std::stoul(argv[i]);
    else
      repetitions = std::stoi(argv[i]);
  }

  const double a = 1.0, b = 0.7, c = 0.5;
  const std::vector<Oriented_point> pts = ellipsoid(n, a, b, c, 42);
  const double r = std::sqrt(40.0 * ellipsoid_area(a, b, c) / (M_PI * double(n)));
  const auto params = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());

  double t_bare = 1e300, t_bare_std = 1e300, t_kd = 1e300, t_apss_s = 1e300, t_apss_p = 1e300, t_aso_s = 1e300,
         t_aso_p = 1e300, t_knn_s = 1e300, t_knn_p = 1e300, t_paper_s = 1e300, t_paper_p = 1e300, t_uniform_s = 1e300,
         t_areas_s = 1e300, t_given_s = 1e300;
  namespace P = CGAL::Point_set_curvatures::parameters;
  const auto paper = P::aso_variant(CGAL::Aso_variant::PAPER, params);
  const auto uniform = P::sample_weights(CGAL::Sample_weights::UNIFORM, params);
  // the same cloud with a column for the shared sample weights
  typedef std::tuple<Point, Vector, double> Weighted_point;
  std::vector<Weighted_point> weighted;
  weighted.reserve(n);
  for(const auto& p : pts)
    weighted.emplace_back(p.first, p.second, 0.0);
  const auto weighted_params =
    P::sample_weight_map(CGAL::Nth_of_tuple_property_map<2, Weighted_point>(),
                         CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Weighted_point>())
                           .normal_map(CGAL::Nth_of_tuple_property_map<1, Weighted_point>()));
  std::size_t pairs = 0;
  long long aso_peak_extra = 0;
  double checksum = 0;
  for(int rep = 0; rep < repetitions; ++rep)
  {
    auto t0 = std::chrono::steady_clock::now();
    const auto bare = bare_traversal(pts, r);
    t_bare = std::min(t_bare, seconds_since(t0));
    pairs = bare.second;
    checksum += bare.first;
    t0 = std::chrono::steady_clock::now();
    checksum += bare_traversal(pts, r, true).first;
    t_bare_std = std::min(t_bare_std, seconds_since(t0));

    if(kdtree && rep == 0)  // slow; once is enough to make the point
    {
      t0 = std::chrono::steady_clock::now();
      const auto kd = kdtree_traversal(pts, r);
      t_kd = seconds_since(t0);
      if(kd.second != pairs)
        std::fprintf(stderr, "warning: kd-tree found %zu pairs, grid %zu\n", kd.second, pairs);
    }

    t0 = std::chrono::steady_clock::now();
    auto apss = CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, r, params);
    t_apss_s = std::min(t_apss_s, seconds_since(t0));
    checksum += apss[n / 2].mean_curvature;
    decltype(apss)().swap(apss);

    t0 = std::chrono::steady_clock::now();
    apss = CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, r, params);
    t_apss_p = std::min(t_apss_p, seconds_since(t0));
    decltype(apss)().swap(apss);

    psc_bench::reset_peak();
    const long long before = psc_bench::current_bytes();
    t0 = std::chrono::steady_clock::now();
    auto aso = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, params);
    t_aso_s = std::min(t_aso_s, seconds_since(t0));
    const long long result_bytes = static_cast<long long>(aso.capacity() * sizeof(aso[0]));
    aso_peak_extra = psc_bench::peak_bytes() - before - result_bytes;
    checksum += aso[n / 3].max_curvature;
    decltype(aso)().swap(aso);

    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, params);
    t_aso_p = std::min(t_aso_p, seconds_since(t0));
    decltype(aso)().swap(aso);

    // the paper's variant, and the default without its sample-weight pass
    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, paper);
    t_paper_s = std::min(t_paper_s, seconds_since(t0));
    checksum += aso[n / 7].max_curvature;
    decltype(aso)().swap(aso);
    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, r, paper);
    t_paper_p = std::min(t_paper_p, seconds_since(t0));
    decltype(aso)().swap(aso);
    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, r, uniform);
    t_uniform_s = std::min(t_uniform_s, seconds_since(t0));
    decltype(aso)().swap(aso);

    // one area pass shared: the areas alone, then the ASO reading them
    t0 = std::chrono::steady_clock::now();
    CGAL::estimate_tangent_voronoi_areas<CGAL::Sequential_tag>(weighted, r, weighted_params);
    t_areas_s = std::min(t_areas_s, seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(weighted, r, weighted_params);
    t_given_s = std::min(t_given_s, seconds_since(t0));
    checksum += aso[n / 9].max_curvature;
    decltype(aso)().swap(aso);

    const std::size_t k = static_cast<std::size_t>(std::lround(double(pairs) / double(n)));
    const auto by_count = CGAL::Point_set_curvatures::parameters::neighbor_count(k, params);
    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, by_count);
    t_knn_s = std::min(t_knn_s, seconds_since(t0));
    checksum += aso[n / 5].min_curvature;
    decltype(aso)().swap(aso);

    t0 = std::chrono::steady_clock::now();
    aso = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, by_count);
    t_knn_p = std::min(t_knn_p, seconds_since(t0));
  }

  const double ns_pair = 1e9 / double(pairs);
  std::printf("points: %zu, radius: %.6g, mean neighbours (query included): %.2f, repetitions: %d (best kept)\n\n", n,
              r, double(pairs) / double(n), repetitions);
  std::printf("| run | seconds | ns per pair | ratio to bare traversal |\n|---|---|---|---|\n");
  auto row = [&](const char* name, double t) {
    std::printf("| %s | %.3f | %.1f | %.2f |\n", name, t, t * ns_pair, t / t_bare);
  };
  row("bare grid traversal (build + visit pairs)", t_bare);
  row("bare grid traversal, grid sorted by std::sort instead of the radix sort", t_bare_std);
  if(kdtree)
    row("CGAL Kd_tree + Fuzzy_sphere (spatially sorted)", t_kd);
  row("APSS, Sequential_tag", t_apss_s);
  row("APSS, Parallel_tag", t_apss_p);
  row("ASO (default: Aso_variant::ROBUST), Sequential_tag", t_aso_s);
  row("ASO (default: Aso_variant::ROBUST), Parallel_tag", t_aso_p);
  row("ASO, default without sample weights (kernel ^3, orientation), Sequential_tag", t_uniform_s);
  row("sample weights alone (estimate_tangent_voronoi_areas), Sequential_tag", t_areas_s);
  row("ASO (default) reading the weights (sample_weight_map), Sequential_tag", t_given_s);
  row("ASO, Aso_variant::PAPER, Sequential_tag", t_paper_s);
  row("ASO, Aso_variant::PAPER, Parallel_tag", t_paper_p);
  row("ASO by count (neighbor_count), Sequential_tag", t_knn_s);
  row("ASO by count (neighbor_count), Parallel_tag", t_knn_p);
  std::printf("\nASO parallel speed-up: %.2fx; APSS parallel speed-up: %.2fx\n", t_aso_s / t_aso_p,
              t_apss_s / t_apss_p);
  std::printf("ASO by count / ASO by radius: %.2f sequential, %.2f parallel\n", t_knn_s / t_aso_s, t_knn_p / t_aso_p);
  std::printf("default / paper: %.2f sequential, %.2f parallel; sample-weight pass: %.3f s, %.2f of the "
              "default's ASO pass\n",
              t_aso_s / t_paper_s, t_aso_p / t_paper_p, t_aso_s - t_uniform_s, (t_aso_s - t_uniform_s) / t_uniform_s);
  std::printf("ASO (default) peak heap beyond input and result: %.1f bytes per point\n",
              double(aso_peak_extra) / double(n));
  std::printf("(checksum %.6g)\n", checksum);
  return 0;
}
