// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Minimal use: oriented points in a std::vector of (position, normal) pairs, the Algebraic
// Shape Operator at every point, a few values printed. The points sample a sphere of radius
// 2 with outward normals, so every curvature should be 1/2 (Gaussian curvature 1/4).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/estimate_aso_curvatures.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Oriented_point;

int main()
{
  // 5000 points spread evenly on the sphere (Fibonacci lattice), unit outward normals.
  const double sphere_radius = 2;
  const std::size_t n = 5000;
  const double golden_angle = M_PI * (3 - std::sqrt(5.0));
  std::vector<Oriented_point> points;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1 - (2 * double(i) + 1) / double(n);
    const double r = std::sqrt(1 - z * z);
    const Vector u(r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z);
    points.emplace_back(CGAL::ORIGIN + sphere_radius * u, u);
  }

  // Neighbourhoods of radius 0.4 (about 50 points each, in the unit of the coordinates).
  const std::vector<CGAL::Curvature_estimate<Kernel> > estimates = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    points, 0.4,
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented_point>())
      .normal_map(CGAL::Second_of_pair_property_map<Oriented_point>()));

  std::cout << "expected on a sphere of radius 2: k_min = k_max = mean = 0.5, gaussian = 0.25\n";
  for(std::size_t i = 0; i < 3; ++i)
  {
    const CGAL::Curvature_estimate<Kernel>& e = estimates[i];
    if(e.is_valid())
      std::cout << "point " << i << ": k_min " << e.min_curvature << ", k_max " << e.max_curvature << ", mean "
                << e.mean_curvature << ", gaussian " << e.gaussian_curvature << ", " << e.neighbor_count
                << " neighbours\n";
    else
      std::cout << "point " << i << ": no estimate (" << e.status << ")\n";
  }

  // The estimate is exact up to rounding on a sphere: any visible error is a bug.
  double worst = 0;
  for(const CGAL::Curvature_estimate<Kernel>& e : estimates)
    worst = std::max(worst, e.is_valid() ? std::abs(e.mean_curvature - 0.5) : 1.0);
  std::cout << "largest |mean - 0.5| over the " << n << " points: " << worst << "\n";
  return worst < 1e-6 ? EXIT_SUCCESS : EXIT_FAILURE;
}
