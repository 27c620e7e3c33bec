// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reads an oriented point cloud (.xyz/.pwn "x y z nx ny nz", .ply with nx ny nz, .off),
// estimates the Algebraic Shape Operator at every point and writes a binary PLY with, per
// input point and in input order: x y z, the corrected normal nx ny nz, k_min k_max mean
// gaussian, the principal directions dmin_x.. and dmax_x.., neighbor count and a valid flag.
// Invalid estimates are written with NaN values and valid = 0.
//
// usage: aso_curvatures_from_file INPUT OUTPUT.ply RADIUS

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/estimate_aso_curvatures.h>

#include <CGAL/IO/read_points.h>
#include <CGAL/IO/write_ply_points.h>
#include <CGAL/property_map.h>

#include <boost/property_map/function_property_map.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef std::pair<Point, Vector> Oriented_point;
typedef CGAL::First_of_pair_property_map<Oriented_point> Point_map;
typedef CGAL::Second_of_pair_property_map<Oriented_point> Normal_map;
typedef CGAL::Curvature_estimate<Kernel> Estimate;

int main(int argc, char** argv)
{
  if(argc != 4)
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT.ply RADIUS\n";
    return 2;
  }
  const double radius = std::strtod(argv[3], nullptr);

  std::vector<Oriented_point> points;
  if(!CGAL::IO::read_points(argv[1], std::back_inserter(points),
                            CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())))
  {
    std::cerr << "error: cannot read " << argv[1] << "\n";
    return 2;
  }

  std::vector<Estimate> estimates;
  const auto start = std::chrono::steady_clock::now();
  try
  {
    estimates = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      points, radius, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
  }
  catch(const std::invalid_argument& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The PLY writer reads every property through a map keyed by the point's index.
  std::vector<std::size_t> indices(points.size());
  for(std::size_t i = 0; i < indices.size(); ++i)
    indices[i] = i;
  auto point_of = boost::make_function_property_map<std::size_t, Point>(
    [&](std::size_t i) { return points[i].first; });
  auto field = [&](double Estimate::*member) {
    return boost::make_function_property_map<std::size_t, double>(
      [&estimates, member](std::size_t i) { return estimates[i].*member; });
  };
  // one coordinate of a vector field (CGAL's PLY writer takes one map per scalar property)
  auto coordinate = [&](Vector Estimate::*member, int c) {
    return boost::make_function_property_map<std::size_t, double>(
      [&estimates, member, c](std::size_t i) { return CGAL::to_double((estimates[i].*member)[c]); });
  };
  auto neighbors = boost::make_function_property_map<std::size_t, int>(
    [&](std::size_t i) { return static_cast<int>(estimates[i].neighbor_count); });
  auto valid = boost::make_function_property_map<std::size_t, unsigned char>(
    [&](std::size_t i) { return static_cast<unsigned char>(estimates[i].is_valid()); });
  typedef CGAL::IO::PLY_property<double> D;

  std::ofstream out(argv[2], std::ios::binary);
  CGAL::IO::set_binary_mode(out);
  const bool ok = CGAL::IO::write_PLY_with_properties(
    out, indices,
    CGAL::IO::make_ply_point_writer(point_of),
    std::make_pair(coordinate(&Estimate::normal, 0), D("nx")),
    std::make_pair(coordinate(&Estimate::normal, 1), D("ny")),
    std::make_pair(coordinate(&Estimate::normal, 2), D("nz")),
    std::make_pair(field(&Estimate::min_curvature), D("k_min")),
    std::make_pair(field(&Estimate::max_curvature), D("k_max")),
    std::make_pair(field(&Estimate::mean_curvature), D("mean")),
    std::make_pair(field(&Estimate::gaussian_curvature), D("gaussian")),
    std::make_pair(coordinate(&Estimate::min_direction, 0), D("dmin_x")),
    std::make_pair(coordinate(&Estimate::min_direction, 1), D("dmin_y")),
    std::make_pair(coordinate(&Estimate::min_direction, 2), D("dmin_z")),
    std::make_pair(coordinate(&Estimate::max_direction, 0), D("dmax_x")),
    std::make_pair(coordinate(&Estimate::max_direction, 1), D("dmax_y")),
    std::make_pair(coordinate(&Estimate::max_direction, 2), D("dmax_z")),
    std::make_pair(neighbors, CGAL::IO::PLY_property<int>("neighbors")),
    std::make_pair(valid, CGAL::IO::PLY_property<unsigned char>("valid")));
  if(!ok || !out)
  {
    std::cerr << "error: cannot write " << argv[2] << "\n";
    return 2;
  }

  std::size_t n_valid = 0, n_neighbors = 0;
  for(const Estimate& e : estimates)
    if(e.is_valid())
    {
      ++n_valid;
      n_neighbors += e.neighbor_count;
    }
  std::cout << points.size() << " points, " << n_valid << " valid estimates, "
            << (n_valid ? double(n_neighbors) / double(n_valid) : 0.0)
            << " neighbours on average, ASO in " << seconds << " s; wrote " << argv[2] << "\n";
  return 0;
}
