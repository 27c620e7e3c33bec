// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// CGAL::Point_set_3: read a cloud with normals (.xyz, .ply, .off), estimate the Algebraic
// Shape Operator with the point set's own point and normal maps, store the results as
// property maps of the point set and write everything as a binary PLY: x y z, the corrected
// normal nx ny nz (the input normal where the estimate is invalid), k_min k_max mean gaussian,
// the principal directions dmin_x dmin_y dmin_z dmax_x dmax_y dmax_z, valid; and the sample
// weights (area), computed once and shared by the ASO and the APSS sphere fit (apss_mean).
//
// usage: point_set_3_curvatures INPUT OUTPUT.ply RADIUS

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_tangent_voronoi_areas.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;

int main(int argc, char** argv)
{
  if(argc != 4)
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT.ply RADIUS\n";
    return EXIT_FAILURE;
  }
  Point_set points;
  if(!CGAL::IO::read_point_set(argv[1], points) || !points.has_normal_map())
  {
    std::cerr << "error: cannot read " << argv[1] << " as a point set with normals\n";
    return EXIT_FAILURE;
  }

  // The point set's point and normal maps are the defaults (points.parameters()). The default
  // ASO weights every neighbour by the area of its tangent Voronoi cell: computed once here,
  // into a property of the point set, and read by both estimators below instead of computing
  // it twice (the estimates are bitwise those of each function with
  // sample_weights(TANGENT_VORONOI_AREA), the ASO's default; APSS's default is UNIFORM).
  const double radius = std::atof(argv[3]);
  Point_set::Property_map<double> area = points.add_property_map<double>("area", 0.0).first;
  const auto with_areas = CGAL::Point_set_curvatures::parameters::sample_weight_map(area, points.parameters());
  CGAL::estimate_tangent_voronoi_areas<CGAL::Parallel_tag>(points, radius, with_areas);
  const std::vector<CGAL::Curvature_estimate<Kernel> > estimates =
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(points, radius, with_areas);
  const std::vector<CGAL::Curvature_estimate<Kernel> > sphere =
    CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(points, radius, with_areas);

  // One property map per quantity; the PLY writer saves every scalar property map.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Point_set::Property_map<double> apss_mean = points.add_property_map<double>("apss_mean", nan).first;
  Point_set::Property_map<double> k_min = points.add_property_map<double>("k_min", nan).first;
  Point_set::Property_map<double> k_max = points.add_property_map<double>("k_max", nan).first;
  Point_set::Property_map<double> mean = points.add_property_map<double>("mean", nan).first;
  Point_set::Property_map<double> gaussian = points.add_property_map<double>("gaussian", nan).first;
  Point_set::Property_map<std::uint8_t> valid = points.add_property_map<std::uint8_t>("valid", 0).first;
  // principal directions, three doubles each (the PLY writer takes scalar properties)
  const char* direction_names[6] = {"dmin_x", "dmin_y", "dmin_z", "dmax_x", "dmax_y", "dmax_z"};
  Point_set::Property_map<double> direction[6];
  for(int c = 0; c < 6; ++c)
    direction[c] = points.add_property_map<double>(direction_names[c], nan).first;
  std::size_t i = 0, n_valid = 0;
  for(Point_set::Index p : points)
  {
    apss_mean[p] = sphere[i].mean_curvature;
    const CGAL::Curvature_estimate<Kernel>& e = estimates[i++];  // same order as the point set
    k_min[p] = e.min_curvature;
    k_max[p] = e.max_curvature;
    mean[p] = e.mean_curvature;
    gaussian[p] = e.gaussian_curvature;
    valid[p] = e.is_valid() ? 1 : 0;
    for(int c = 0; c < 3; ++c)
    {
      direction[c][p] = e.min_direction[c];
      direction[3 + c][p] = e.max_direction[c];
    }
    // the corrected normal replaces the input one where the estimate is valid
    if(e.is_valid())
    {
      points.normal(p) = e.normal;
      ++n_valid;
    }
  }

  if(!CGAL::IO::write_PLY(argv[2], points, CGAL::parameters::use_binary_mode(true)))
  {
    std::cerr << "error: cannot write " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points, " << n_valid << " valid estimates; wrote " << argv[2]
            << " with the properties:";
  for(const std::string& name : points.properties())
    std::cout << " " << name;
  std::cout << "\n";
  return n_valid > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
