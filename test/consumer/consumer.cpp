// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The consumer project's program: ASO curvatures of a unit sphere, sequential and parallel
// (the package target must bring TBB). Exit status 0 if k_min = k_max = 1 everywhere.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/estimate_aso_curvatures.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#ifndef CGAL_LINKED_WITH_TBB
#error "Point_set_curvatures::Point_set_curvatures did not bring TBB (CGAL::TBB_support)"
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Oriented_point;

int main()
{
  std::vector<Oriented_point> points;
  const int n = 4000;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for(int i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), t = golden * i;
    const K::Vector_3 v(r * std::cos(t), r * std::sin(t), z);
    points.emplace_back(CGAL::ORIGIN + v, v);
  }
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented_point>())
                    .normal_map(CGAL::Second_of_pair_property_map<Oriented_point>());
  const auto seq = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(points, 0.15, np);
  const auto par = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(points, 0.15, np);
  double worst = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(!seq[i].is_valid() || seq[i].mean_curvature != par[i].mean_curvature)
      return 1;
    worst = std::max({worst, std::abs(seq[i].min_curvature - 1), std::abs(seq[i].max_curvature - 1)});
  }
  std::printf("consumer: %zu points, largest |k - 1| = %.3g\n", points.size(), worst);
  return worst < 1e-9 ? 0 : 1;
}
