// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A cloud without normals: read the positions only, estimate normals with the package
// (CGAL::estimate_oriented_normals: a weighted quadric fitted to the 40 nearest neighbours,
// oriented along a minimum spanning tree), then estimate the Algebraic Shape Operator with a
// fit of the positions blended in (position_fit_blend(0.5)): on simulated scans its error was
// within 1.35 times that with exact normals. The sign of the curvatures follows the orientation
// found: each connected part outward if it is closed, up if it is open. For an airborne scan,
// orient along +z instead: normal_orientation(CGAL::Normal_orientation::along_vector(0, 0, 1)),
// or Normal_orientation::automatic() (the spanning tree, with +z on the near-vertical normals
// of its open parts if the cloud is 2.5-D).
//
// usage: curvatures_without_normals INPUT [NEIGHBORS]
// (INPUT: any point file CGAL reads; normals in it, if any, are ignored here)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_oriented_normals.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Point_with_normal;
typedef CGAL::First_of_pair_property_map<Point_with_normal> Point_map;
typedef CGAL::Second_of_pair_property_map<Point_with_normal> Normal_map;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [NEIGHBORS]\n";
    return EXIT_FAILURE;
  }
  const std::size_t neighbors = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 40;

  // Positions only: without a normal_map parameter the reader does not read normals.
  std::vector<Point_with_normal> points;
  if(!CGAL::IO::read_points(argv[1], std::back_inserter(points), CGAL::parameters::point_map(Point_map())))
  {
    std::cerr << "error: cannot read " << argv[1] << "\n";
    return EXIT_FAILURE;
  }

  // 1. Oriented normals (the defaults: quadric, 40 nearest neighbours); points in input order.
  //    Points whose neighbours coincide or lie along one line get a zero normal
  //    (INVALID_NORMAL below).
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(points, np);

  // 2. Curvatures, neighbourhoods by count (each point's radius: distance to its K-th nearest),
  //    half of the tensor from a quadric fitted to the positions (the normals are estimated).
  namespace P = CGAL::Point_set_curvatures::parameters;
  const std::vector<CGAL::Curvature_estimate<Kernel> > estimates = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    points, P::neighbor_count(neighbors, P::position_fit_blend(0.5, np)));

  std::vector<double> mean;
  for(const CGAL::Curvature_estimate<Kernel>& e : estimates)
    if(e.is_valid())
      mean.push_back(e.mean_curvature);
  std::cout << points.size() << " points, " << without << " without a normal, " << mean.size() << " valid estimates\n";
  if(mean.empty())
    return EXIT_FAILURE;
  std::sort(mean.begin(), mean.end());
  std::cout << "mean curvature: 10th percentile " << mean[mean.size() / 10] << ", median " << mean[mean.size() / 2]
            << ", 90th percentile " << mean[9 * mean.size() / 10] << "\n";
  return mean.size() == points.size() ? EXIT_SUCCESS : EXIT_FAILURE;
}
