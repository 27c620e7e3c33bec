// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A parallel run (CGAL::Parallel_tag, TBB) with a progress callback, then a run cancelled by
// the callback: the points not reached keep the status NOT_COMPUTED and NaN values.
// The cloud, 100 000 points on a torus with exact outward normals, is generated here.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/estimate_aso_curvatures.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Oriented_point;
typedef CGAL::Curvature_estimate<Kernel> Estimate;

int main()
{
  // Torus of radii 3 (centre circle) and 1 (tube) on a 500 x 200 grid of angles.
  std::vector<Oriented_point> points;
  for(int i = 0; i < 500; ++i)
    for(int j = 0; j < 200; ++j)
    {
      const double u = 2 * M_PI * i / 500, v = 2 * M_PI * j / 200;
      const Vector n(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
      const Point c(3 * std::cos(u), 3 * std::sin(u), 0);
      points.emplace_back(c + n, n);
    }
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented_point>())
                    .normal_map(CGAL::Second_of_pair_property_map<Oriented_point>());
  const double radius = 0.15;

  // 1. Progress: the callback runs on the calling thread between batches of at most 1% of
  //    the points (about 0.25 s each on long runs), with the fraction done; returning true
  //    continues.
  const std::vector<Estimate> all = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    points, radius, np.callback(std::function<bool(double)>([](double done) {
      std::cout << "progress " << int(100 * done) << "%\n";
      return true;
    })));

  // 2. Cancellation: returning false stops the run after the current batch. The default
  //    estimator first computes the samples' weights (the first third of the progress), then
  //    the estimates: cancelled at 60%, part of the points have an estimate.
  const std::vector<Estimate> part = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    points, radius, np.callback(std::function<bool(double)>([](double done) {
      std::cout << "progress " << int(100 * done) << "%" << (done >= 0.6 ? ", cancelling\n" : "\n");
      return done < 0.6;
    })));

  std::size_t valid = 0, computed = 0, not_computed = 0, same = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    valid += all[i].is_valid();
    if(part[i].status == CGAL::Curvature_estimate_status::NOT_COMPUTED)
      ++not_computed;
    else
    {
      ++computed;
      // what was computed before the cancellation is what the full run computed
      same += (part[i].mean_curvature == all[i].mean_curvature);
    }
  }
  std::cout << "full run: " << valid << " valid estimates of " << points.size() << "\n"
            << "cancelled run: " << computed << " computed, " << not_computed << " not computed (status "
            << CGAL::Curvature_estimate_status::NOT_COMPUTED << ")\n";
  const bool ok = valid == points.size() && not_computed > 0 && computed > 0 && same == computed;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
