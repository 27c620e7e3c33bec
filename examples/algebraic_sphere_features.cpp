// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The geometric features of the APSS algebraic sphere (Lejemble et al. 2021, Figure 2): reads a
// cloud with normals, computes at every point the Pratt-normalised coefficients u_c, u_q, the
// anisotropy 1 - p and the GLS geometric variation v, stores them as properties of the point
// set and writes a binary PLY coloured by one of them (red green blue), for a viewer such as
// MeshLab or CloudCompare.
//
// usage: algebraic_sphere_features INPUT OUTPUT.ply RADIUS [anisotropy|u_c|u_q|variation]
//        (default: variation)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/estimate_algebraic_sphere_features.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;
typedef CGAL::Algebraic_sphere_features<Kernel> Features;

// Colour of t in [-1, 1]: blue (-1), white (0), red (1) for signed features; for non-negative
// ones t is in [0, 1] and goes from white to red.
void colour(double t, std::uint8_t rgb[3])
{
  t = std::max(-1.0, std::min(1.0, t));
  const double a = 1 - std::abs(t);  // fades the other two channels
  const double strong = 255, weak = 255 * a;
  rgb[0] = std::uint8_t(t >= 0 ? strong : weak);
  rgb[1] = std::uint8_t(weak);
  rgb[2] = std::uint8_t(t <= 0 ? strong : weak);
}

int main(int argc, char** argv)
{
  if(argc != 4 && argc != 5)
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT.ply RADIUS [anisotropy|u_c|u_q|variation]\n";
    return EXIT_FAILURE;
  }
  const std::string shown = argc == 5 ? argv[4] : "variation";
  if(shown != "anisotropy" && shown != "u_c" && shown != "u_q" && shown != "variation")
  {
    std::cerr << "error: unknown feature '" << shown << "'\n";
    return EXIT_FAILURE;
  }
  Point_set points;
  if(!CGAL::IO::read_point_set(argv[1], points) || !points.has_normal_map())
  {
    std::cerr << "error: cannot read " << argv[1] << " as a point set with normals\n";
    return EXIT_FAILURE;
  }

  std::vector<Features> features;
  try
  {
    features = CGAL::estimate_algebraic_sphere_features<CGAL::Parallel_tag>(points, std::atof(argv[3]));
  }
  catch(const std::invalid_argument& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }

  auto value = [&](const Features& f) -> double {
    if(shown == "anisotropy")
      return f.anisotropy;
    if(shown == "u_c")
      return f.u_c;
    if(shown == "u_q")
      return f.u_q;
    return f.geometric_variation;
  };
  const bool is_signed = shown == "u_c" || shown == "u_q";
  // Colour scale: the 95th percentile of |value|, robust to a few extreme points.
  std::vector<double> magnitudes;
  for(const Features& f : features)
    if(f.is_valid())
      magnitudes.push_back(std::abs(value(f)));
  if(magnitudes.empty())
  {
    std::cerr << "error: no valid estimate (radius too small?)\n";
    return EXIT_FAILURE;
  }
  std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() * 95 / 100, magnitudes.end());
  const double scale = std::max(magnitudes[magnitudes.size() * 95 / 100], std::numeric_limits<double>::min());

  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto add = [&](const char* name) { return points.add_property_map<double>(name, nan).first; };
  Point_set::Property_map<double> u_c = add("u_c"), u_q = add("u_q"), p = add("pratt_norm"),
                                  anisotropy = add("anisotropy"), v = add("geometric_variation"),
                                  mean = add("mean_curvature");
  Point_set::Property_map<std::uint8_t> red = points.add_property_map<std::uint8_t>("red", 0).first;
  Point_set::Property_map<std::uint8_t> green = points.add_property_map<std::uint8_t>("green", 0).first;
  Point_set::Property_map<std::uint8_t> blue = points.add_property_map<std::uint8_t>("blue", 0).first;
  std::size_t i = 0, n_valid = 0;
  for(Point_set::Index index : points)
  {
    const Features& f = features[i++];  // same order as the point set
    if(!f.is_valid())
      continue;  // NaN properties, black
    ++n_valid;
    u_c[index] = f.u_c;
    u_q[index] = f.u_q;
    p[index] = f.pratt_norm;
    anisotropy[index] = f.anisotropy;
    v[index] = f.geometric_variation;
    mean[index] = f.mean_curvature;
    std::uint8_t rgb[3];
    colour(value(f) / scale, rgb);
    red[index] = rgb[0];
    green[index] = rgb[1];
    blue[index] = rgb[2];
  }

  if(!CGAL::IO::write_PLY(argv[2], points, CGAL::parameters::use_binary_mode(true)))
  {
    std::cerr << "error: cannot write " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << points.size() << " points, " << n_valid << " valid; coloured by " << shown
            << (is_signed ? " (blue < 0 < red)" : " (white 0 to red)") << ", full colour at |" << shown
            << "| = " << scale << "; wrote " << argv[2] << "\n";
  return EXIT_SUCCESS;
}
