// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A cloud without normals: read the positions only, estimate normals with CGAL (jet fitting),
// orient them consistently along a minimum spanning tree, then estimate the Algebraic Shape
// Operator. The sign of the curvatures follows the orientation found: CGAL starts from the
// highest point with an upward normal, which is outward on a closed surface.
//
// usage: curvatures_without_normals INPUT [NEIGHBORS]
// (INPUT: any point file CGAL reads; normals in it, if any, are ignored here)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
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
  if(!CGAL::IO::read_points(argv[1], std::back_inserter(points),
                            CGAL::parameters::point_map(Point_map())))
  {
    std::cerr << "error: cannot read " << argv[1] << "\n";
    return EXIT_FAILURE;
  }

  // 1. Unoriented normals from a jet fitted to the 18 nearest neighbours of each point.
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  CGAL::jet_estimate_normals<CGAL::Parallel_tag>(points, 18, np);
  // 2. Consistent orientation. The points are reordered: the oriented ones come first.
  const auto unoriented = CGAL::mst_orient_normals(points, 18, np);
  const std::size_t n_unoriented = static_cast<std::size_t>(std::distance(unoriented, points.end()));

  // 3. Curvatures, neighbourhoods by count (each point's radius: distance to its K-th nearest).
  const std::vector<CGAL::Curvature_estimate<Kernel> > estimates =
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      points, CGAL::Point_set_curvatures::parameters::neighbor_count(neighbors, np));

  std::vector<double> mean;
  for(const CGAL::Curvature_estimate<Kernel>& e : estimates)
    if(e.is_valid())
      mean.push_back(e.mean_curvature);
  std::cout << points.size() << " points, " << n_unoriented << " normals left unoriented, "
            << mean.size() << " valid estimates\n";
  if(mean.empty())
    return EXIT_FAILURE;
  std::sort(mean.begin(), mean.end());
  std::cout << "mean curvature: 10th percentile " << mean[mean.size() / 10] << ", median "
            << mean[mean.size() / 2] << ", 90th percentile " << mean[9 * mean.size() / 10] << "\n";
  return mean.size() == points.size() ? EXIT_SUCCESS : EXIT_FAILURE;
}
