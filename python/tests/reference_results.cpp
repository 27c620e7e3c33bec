// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Test helper of the Python bindings: runs the C++ API on a cloud and writes its results as
// raw doubles, for python/tests/test_curvatures.py to compare with the module bit for bit.
//
//   psc_python_reference INPUT.xyz OUTPUT_DIR
//
// writes OUTPUT_DIR/points.bin (N x 6 doubles: the positions and normals as read) and, per
// configuration, OUTPUT_DIR/<name>.bin: N records of 15 doubles (normal, k_min, k_max, mean,
// gaussian, min_direction, max_direction, neighbor count, status), or for the sphere features
// 6 doubles (u_c, u_q, anisotropy, geometric_variation, neighbor count, status), or for the
// normals 3 doubles.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/estimate_algebraic_sphere_features.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_jet_curvatures.h>
#include <CGAL/estimate_oriented_normals.h>
#include <CGAL/estimate_pss_curvatures.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Oriented;
typedef CGAL::Curvature_estimate<K> Estimate;

static std::string g_dir;

static void write(const std::string& name, const std::vector<double>& v)
{
  std::ofstream out(g_dir + "/" + name + ".bin", std::ios::binary);
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(double)));
  if(!out)
  {
    std::cerr << "cannot write " << name << "\n";
    std::exit(1);
  }
}

static void write_estimates(const std::string& name, const std::vector<Estimate>& e)
{
  std::vector<double> v;
  for(const Estimate& x : e)
  {
    const double r[16] = {
      x.normal.x(),         x.normal.y(),         x.normal.z(),        x.min_curvature,     x.max_curvature,
      x.mean_curvature,     x.gaussian_curvature, x.min_direction.x(), x.min_direction.y(), x.min_direction.z(),
      x.max_direction.x(),  x.max_direction.y(),  x.max_direction.z(), x.normal_coherence,  double(x.neighbor_count),
      double(int(x.status))};
    v.insert(v.end(), r, r + 16);
  }
  write(name, v);
}

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::cerr << "usage: psc_python_reference INPUT.xyz OUTPUT_DIR\n";
    return 2;
  }
  g_dir = argv[2];
  std::ifstream in(argv[1]);
  std::vector<Oriented> cloud;
  std::vector<double> raw;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    double x[6];
    if(!(s >> x[0] >> x[1] >> x[2] >> x[3] >> x[4] >> x[5]))
      continue;
    cloud.emplace_back(K::Point_3(x[0], x[1], x[2]), K::Vector_3(x[3], x[4], x[5]));
    raw.insert(raw.end(), x, x + 6);
  }
  if(cloud.empty())
  {
    std::cerr << "no point read from " << argv[1] << "\n";
    return 1;
  }
  write("points", raw);

  namespace P = CGAL::Point_set_curvatures::parameters;
  const auto np = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())
                    .normal_map(CGAL::Second_of_pair_property_map<Oriented>());
  // Default calls, as a user of the C++ API writes them.
  write_estimates("aso_r1.5", CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, 1.5, np));
  write_estimates("aso_r1.5_callback",
                  CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                    cloud, 1.5, np.callback(std::function<bool(double)>([](double) { return true; }))));
  write_estimates("aso_paper_r1.5", CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
                                      cloud, 1.5, P::aso_variant(CGAL::Aso_variant::PAPER, np)));
  write_estimates("aso_paper_blend_r1.5",
                  CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                    cloud, 1.5, P::aso_variant(CGAL::Aso_variant::PAPER, P::normal_field_blend(true, np))));
  write_estimates("aso_k30", CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, P::neighbor_count(30, np)));
  write_estimates("aso_k40_position_blend", CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                                              cloud, P::neighbor_count(40, P::position_fit_blend(0.5, np))));
  write_estimates(
    "aso_quartic_authors_r1.5",
    CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
      cloud, 1.5,
      P::weight_kernel(CGAL::Apss_weight_kernel::SMOOTH_QUARTIC,
                       P::aso_projection(CGAL::Aso_projection::AUTHORS_IMPLEMENTATION, P::min_neighbors(20, np)))));
  write_estimates("apss_r1.5", CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(cloud, 1.5, np));
  write_estimates("pss_r1.5", CGAL::estimate_pss_curvatures<CGAL::Parallel_tag>(cloud, 1.5, np));
  write_estimates("jet_r1.5_d3",
                  CGAL::estimate_jet_curvatures<CGAL::Parallel_tag>(cloud, 1.5, np.degree_fitting(3).degree_monge(2)));

  std::vector<double> f;
  for(const auto& x : CGAL::estimate_algebraic_sphere_features<CGAL::Parallel_tag>(cloud, 1.5, np))
  {
    const double r[6] = {
      x.u_c, x.u_q, x.anisotropy, x.geometric_variation, double(x.neighbor_count), double(int(x.status))};
    f.insert(f.end(), r, r + 6);
  }
  write("features_r1.5", f);

  // the normals of estimate_oriented_normals(): the defaults (a quadric of 40, the spanning
  // tree), the PCA plane of 18, the automatic orientation
  auto normals = [&](const std::string& name, const auto& parameters) {
    std::vector<Oriented> unoriented = cloud;
    CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(unoriented, parameters);
    std::vector<double> n;
    for(const Oriented& o : unoriented)
    {
      const double r[3] = {o.second.x(), o.second.y(), o.second.z()};
      n.insert(n.end(), r, r + 3);
    }
    write(name, n);
  };
  normals("normals_default", np);
  normals("normals_plane", P::normal_fit(CGAL::Normal_fit::PLANE, np));
  normals("normals_auto", P::normal_orientation(CGAL::Normal_orientation::automatic(), np));
  std::cout << cloud.size() << " points\n";
  return 0;
}
