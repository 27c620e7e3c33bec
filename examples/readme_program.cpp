// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
// The C++ program of the README, verbatim below these lines (test/readme_program.cmake checks it).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Oriented_point;
namespace P = CGAL::Point_set_curvatures::parameters;

int main(int argc, char** argv)  // ./build/examples/readme_program data/goursat_010000.xyz
{
  std::vector<Oriented_point> points;  // positions with oriented normals, x y z nx ny nz per line
  std::ifstream in(argc > 1 ? argv[1] : "data/goursat_010000.xyz");
  for(std::string line; std::getline(in, line);)  // (a line that does not read as 6 numbers is skipped)
    if(double x, y, z, nx, ny, nz; std::istringstream(line) >> x >> y >> z >> nx >> ny >> nz)
      points.emplace_back(K::Point_3(x, y, z), K::Vector_3(nx, ny, nz));
  auto estimates = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(points,  // the 40 nearest of each point
      P::neighbor_count(40, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented_point>())
                                             .normal_map(CGAL::Second_of_pair_property_map<Oriented_point>())));
  for(std::size_t i = 0; i < estimates.size() && i < 5; ++i)  // one estimate per point, in input order
    if(estimates[i].is_valid())
      std::cout << "k_min " << estimates[i].min_curvature << "  k_max " << estimates[i].max_curvature
                << "  mean " << estimates[i].mean_curvature << "\n";
    else
      std::cout << "no estimate: " << estimates[i].status << "\n";  // e.g. too_few_neighbors; fields NaN
}
