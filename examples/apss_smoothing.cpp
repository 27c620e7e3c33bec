// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Bilaplacian flow of the APSS algebraic spheres (Lejemble et al. 2021, Section 4.5, Figure 3):
// reads a cloud with normals, optionally adds Gaussian noise to the positions (to see the flow
// remove it), moves every point onto the algebraic sphere fitted around it for a number of
// iterations, and writes the smoothed cloud (x y z nx ny nz; the format follows the output
// file's extension: .ply, .xyz, .off).
//
// usage: apss_smoothing INPUT OUTPUT RADIUS [ITERATIONS=10] [NOISE=0] [--update-normals]
//   NOISE: standard deviation of the noise added first, in the unit of the coordinates
//   --update-normals: positions and normals evolve together (the geometric flow of Figure 3);
//                     without it the input normals are kept and used by every iteration

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_points.h>
#include <CGAL/apss_smooth_point_set.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Oriented_point;
typedef CGAL::First_of_pair_property_map<Oriented_point> Point_map;
typedef CGAL::Second_of_pair_property_map<Oriented_point> Normal_map;
namespace PSC = CGAL::Point_set_curvatures;

int main(int argc, char** argv)
{
  std::vector<std::string> args(argv + 1, argv + argc);
  bool update_normals = false;
  for(auto it = args.begin(); it != args.end();)
    if(*it == "--update-normals")
    {
      update_normals = true;
      it = args.erase(it);
    }
    else
      ++it;
  if(args.size() < 3 || args.size() > 5)
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT RADIUS [ITERATIONS=10] [NOISE=0] [--update-normals]\n";
    return EXIT_FAILURE;
  }
  const double radius = std::atof(args[2].c_str());
  const int iterations = args.size() > 3 ? std::atoi(args[3].c_str()) : 10;
  const double noise = args.size() > 4 ? std::atof(args[4].c_str()) : 0.0;

  std::vector<Oriented_point> points;
  const auto maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  if(!CGAL::IO::read_points(args[0], std::back_inserter(points), maps))
  {
    std::cerr << "error: cannot read " << args[0] << "\n";
    return EXIT_FAILURE;
  }
  if(noise > 0)
  {
    std::mt19937 rng(1);
    std::normal_distribution<double> g(0, noise);
    for(Oriented_point& p : points)
      p.first = p.first + Vector(g(rng), g(rng), g(rng));
  }
  const std::vector<Oriented_point> before = points;

  std::vector<CGAL::Curvature_estimate_status> status;
  try
  {
    status = CGAL::apss_smooth_point_set<CGAL::Parallel_tag>(
      points, radius, PSC::parameters::update_normals(update_normals, maps).number_of_iterations(iterations));
  }
  catch(const std::invalid_argument& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  double moved = 0;
  std::size_t n_moved = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(status[i] == CGAL::Curvature_estimate_status::VALID)
    {
      ++n_moved;
      moved += std::sqrt(CGAL::squared_distance(points[i].first, before[i].first));
    }
  if(!CGAL::IO::write_points(args[1], points, maps.stream_precision(17)))
  {
    std::cerr << "error: cannot write " << args[1] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points, " << iterations << " iterations at radius " << radius
            << (update_normals ? " (normals updated)" : " (input normals)") << ": " << n_moved
            << " moved at the last one, mean displacement " << (n_moved ? moved / n_moved : 0.0) << "; wrote "
            << args[1] << "\n";
  return n_moved > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
