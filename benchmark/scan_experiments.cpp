// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Curvatures of scanned clouds without normals, against analytic truth (test/scan_simulator.h):
// a terrestrial scan of a torus, airborne scan lines over a wavy terrain, two terrestrial scans
// of that terrain merged, and more patterns over that terrain (airborne lines of other ratios,
// oblique and zigzag sweeps, lines that are not straight, a mobile profiler, one terrestrial
// station, a car-roof multi-beam scanner standing still, a drone's Risley-prism rosette); clean, with
// range noise, with quantised coordinates. For each cloud,
// the normals a user can get (exact, the package's estimates of each fit order, CGAL's jets)
// and the curvature estimators on them, by count.
//
//   scan_experiments [--neighbors K] [--normal-neighbors K1,K2...] [--only torus,airborne,merged,
//                    airborne2,airborne10,polygon5,zigzag5,zigzag3,wobbly5,wobbly8,mobile,terrestrial,
//                    rings,rosette]
//                    [--noise SIGMA_IN_SPACINGS] [--quantum Q] [--line-spacing S] [--dump PREFIX]
//                    [--auto LARGEST]  (the automatic scale: normals and ASO, ladder 40 .. LARGEST;
//                                       columns auto, with the position fit blended at 0.5 as for
//                                       estimated normals, and auto-given, without, as the tool on
//                                       a cloud with normals)
//                    [--rows exact,default,auto640,...]  (the normal sources to run)

#include "bench_support.h"
#include "scan_simulator.h"

#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_jet_curvatures.h>
#include <CGAL/estimate_oriented_normals.h>
#include <CGAL/estimate_pss_curvatures.h>
#include <CGAL/jet_estimate_normals.h>
#include <cstdlib>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace psc_test;
namespace P = CGAL::Point_set_curvatures::parameters;
typedef std::vector<Oriented_point> Cloud;
typedef CGAL::Curvature_estimate<Kernel> Estimate;

struct Options
{
  std::size_t k = 40;
  std::set<std::string> only;
  std::set<std::string> rows;  // normal sources to run (empty: all)
  double noise = 0;            // range noise, in median spacings
  double quantum = 0;          // coordinate grid
  std::vector<std::size_t> normal_neighbors = {40};
  std::string dump;           // prefix of per-point CSV files (x, y, z, true H, estimated H, neighbours,
                              // standard error of H of the automatic scale)
  double line_spacing = 0.5;  // of the airborne lines (points 0.1 apart along a line)
  std::size_t automatic = 0;  // the automatic scale's largest count (0: not run)
};
std::size_t automatic_largest = 0;

struct Named_cloud
{
  std::string name;
  std::vector<scan::Sample> samples;
};

std::vector<Named_cloud> clouds(const Options& o)
{
  std::vector<Named_cloud> list;
  auto wanted = [&](const std::string& n) { return o.only.empty() || o.only.count(n) > 0; };
  const scan::Height_field terrain = scan::wavy_terrain();
  auto make = [&](const std::string& name, const std::function<std::vector<scan::Sample>(const scan::Noise&)>& f) {
    if(!wanted(name))
      return;
    scan::Noise noise;
    noise.quantum = o.quantum;
    if(o.noise > 0)
    {
      const double spacing = scan::median_spacing(f(scan::Noise()));
      noise.range_sigma = o.noise * spacing;
    }
    list.push_back({name, f(noise)});
  };
  make("torus", [](const scan::Noise& n) { return scan::terrestrial_torus(n); });
  make("airborne", [&](const scan::Noise& n) { return scan::airborne_lines(terrain, 12, 0.1, o.line_spacing, n); });
  make("merged", [&](const scan::Noise& n) { return scan::merged_terrestrial(terrain, 12, 0.009, 12, n); });
  // more patterns, measured on no tuning (issue 44): airborne lines of other along/across
  // ratios and sweeps, a mobile profiler, one terrestrial station
  using scan::Sweep;
  make("airborne2", [&](const scan::Noise& n) { return scan::airborne_lines(terrain, 12, 0.1, 0.2, n); });
  make("airborne10", [&](const scan::Noise& n) { return scan::airborne_lines(terrain, 12, 0.1, 1.0, n); });
  make("polygon5",
       [&](const scan::Noise& n) { return scan::airborne_sweeps(terrain, 12, 0.1, 0.5, Sweep::POLYGON, n); });
  make("zigzag5", [&](const scan::Noise& n) { return scan::airborne_sweeps(terrain, 12, 0.1, 0.5, Sweep::ZIGZAG, n); });
  make("zigzag3",
       [&](const scan::Noise& n) { return scan::airborne_sweeps(terrain, 12, 0.15, 0.45, Sweep::ZIGZAG, n); });
  // lines that are not straight (3 cm of attitude wobble) and whose points do not align
  make("wobbly5",
       [&](const scan::Noise& n) { return scan::airborne_sweeps(terrain, 12, 0.1, 0.5, Sweep::PARALLEL, n, 0.03); });
  make("wobbly8",
       [&](const scan::Noise& n) { return scan::airborne_sweeps(terrain, 12, 0.1, 0.8, Sweep::PARALLEL, n, 0.03); });
  make("mobile", [&](const scan::Noise& n) { return scan::mobile_profiles(terrain, 8, 0.1, 0.0035, n); });
  make("terrestrial",
       [&](const scan::Noise& n) { return scan::merged_terrestrial(terrain, 10, 0.006, 10, n, 1.8, 1); });
  // more patterns (issue 44, measured on no tuning): a car-roof multi-beam scanner standing
  // still (rings), a drone's Risley-prism rosette
  make("rings",
       [&](const scan::Noise& n) { return scan::multibeam_rings(terrain, 12, 32, -0.535, -0.023, 0.0035, n); });
  make("rosette", [&](const scan::Noise& n) { return scan::rosette(terrain, 12, 160000, 400, n); });
  return list;
}

// Normals: a name and how to get them from the cloud (written into the cloud's normals).
struct Normal_source
{
  std::string name;
  std::function<void(Cloud&)> estimate;
  bool oriented_by_truth = true;  // else as the library orients them (the orientation measured too)
};

// Orients each estimated normal like the true one (the orientation is measured apart).
void orient_by_truth(Cloud& c, const std::vector<scan::Sample>& s)
{
  for(std::size_t i = 0; i < c.size(); ++i)
    if(c[i].second * s[i].truth.normal < 0)
      c[i].second = -c[i].second;
}

std::vector<Normal_source> normal_sources(const Options& o)
{
  std::vector<Normal_source> list;
  list.push_back({"exact", [](Cloud&) {}});
  auto library = [](CGAL::Normal_fit fit, std::size_t k) {
    return [fit, k](Cloud& c) {
      CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
        c, P::neighbor_count(k, P::normal_fit(fit, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))));
    };
  };
  list.push_back({"plane18", library(CGAL::Normal_fit::PLANE, 18)});
  list.push_back({"cgal-jet30", [](Cloud& c) {
                    CGAL::jet_estimate_normals<CGAL::Parallel_tag>(
                      c, 30, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()).degree_fitting(2));
                  }});
  for(std::size_t k : o.normal_neighbors)
    list.push_back({"quadric" + std::to_string(k), library(CGAL::Normal_fit::QUADRIC, k)});
  if(o.automatic > 0)
    list.push_back(
      {"auto" + std::to_string(o.automatic), [&o](Cloud& c) {
         CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
           c, P::automatic_scale(
                o.automatic, P::neighbor_count(40, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))));
       }});
  // what a user gets: the library's defaults, orientation included
  list.push_back({"default",
                  [](Cloud& c) {
                    CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
                      c, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
                  },
                  false});
  return list;
}

struct Curvature_method
{
  std::string name;
  std::function<std::vector<Estimate>(const Cloud&, std::size_t)> run;
};

std::vector<Curvature_method> curvature_methods()
{
  std::vector<Curvature_method> list;
#define PSC_METHOD(NAME, FUNCTION, ...)                                                                                \
  list.push_back(                                                                                                      \
    {NAME, [](const Cloud& c, std::size_t k) {                                                                         \
       return CGAL::FUNCTION<CGAL::Parallel_tag>(                                                                      \
         c, P::neighbor_count(k, __VA_ARGS__ CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())));      \
     }})
  PSC_METHOD("aso", estimate_aso_curvatures, );
  list.push_back(
    {"aso+position", [](const Cloud& c, std::size_t k) {
       return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
         c, P::neighbor_count(
              k, P::position_fit_blend(0.5, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))));
     }});
  list.push_back(
    {"aso-paper", [](const Cloud& c, std::size_t k) {
       return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
         c, P::neighbor_count(k, P::aso_variant(CGAL::Aso_variant::PAPER,
                                                CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))));
     }});
  if(automatic_largest > 0)
    list.push_back(
      {"auto", [](const Cloud& c, std::size_t k) {
         return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
           c, P::automatic_scale(
                std::max(k, automatic_largest),
                P::neighbor_count(
                  k, P::position_fit_blend(0.5, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())))));
       }});
  if(automatic_largest > 0)  // the tool's default on a cloud with normals: no position fit
    list.push_back({"auto-given", [](const Cloud& c, std::size_t k) {
                      return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                        c, P::automatic_scale(
                             std::max(k, automatic_largest),
                             P::neighbor_count(k, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))));
                    }});
  PSC_METHOD("apss", estimate_apss_curvatures, );
  PSC_METHOD("pss", estimate_pss_curvatures, );
  PSC_METHOD("jet", estimate_jet_curvatures, );
#undef PSC_METHOD
  return list;
}

struct Score
{
  double mean_abs_H = 0;
  double valid = 0;
};

Score score(const std::vector<Estimate>& est, const std::vector<scan::Sample>& s)
{
  Score r;
  std::size_t n = 0;
  for(std::size_t i = 0; i < est.size(); ++i)
  {
    if(!est[i].is_valid() || !std::isfinite(est[i].mean_curvature))
      continue;
    r.mean_abs_H += std::abs(est[i].mean_curvature - s[i].truth.mean);
    ++n;
  }
  r.mean_abs_H = n ? r.mean_abs_H / double(n) : std::nan("");
  r.valid = double(n) / double(est.size());
  return r;
}

// Angle errors of the normals (degrees, as lines): median and mean.
std::pair<double, double> normal_errors(const Cloud& c, const std::vector<scan::Sample>& s)
{
  std::vector<double> a;
  for(std::size_t i = 0; i < c.size(); ++i)
    if(c[i].second.squared_length() > 0)
      a.push_back(line_angle_degrees(c[i].second, s[i].truth.normal));
  if(a.empty())
    return {std::nan(""), std::nan("")};
  double sum = 0;
  for(double x : a)
    sum += x;
  std::nth_element(a.begin(), a.begin() + a.size() / 2, a.end());
  return {a[a.size() / 2], sum / double(a.size())};
}

std::string g3(double x)
{
  std::ostringstream s;
  s << std::setprecision(3) << x;
  return s.str();
}

}  // namespace

int main(int argc, char** argv)
{
  Options o;
  psc_bench::Arguments args(argc, argv);
  for(std::string a; args.next(a);)
  {
    if(a == "--neighbors")
      o.k = std::stoul(args.value());
    else if(a == "--noise")
      o.noise = std::stod(args.value());
    else if(a == "--normal-neighbors")
    {
      o.normal_neighbors.clear();
      for(const std::string& part : args.list())
        o.normal_neighbors.push_back(std::stoul(part));
    }
    else if(a == "--auto")
      automatic_largest = o.automatic = std::stoul(args.value());
    else if(a == "--line-spacing")
      o.line_spacing = std::stod(args.value());
    else if(a == "--dump")
      o.dump = args.value();
    else if(a == "--quantum")
      o.quantum = std::stod(args.value());
    else if(a == "--rows")
    {
      const std::vector<std::string> parts = args.list();
      o.rows.insert(parts.begin(), parts.end());
    }
    else if(a == "--only")
    {
      const std::vector<std::string> parts = args.list();
      o.only.insert(parts.begin(), parts.end());
    }
    else
    {
      std::cerr << "usage: scan_experiments [--neighbors K] [--noise SIGMA] [--quantum Q] [--only PATTERN,...]\n";
      return 2;
    }
  }
  const std::vector<Curvature_method> methods = curvature_methods();
  for(const Named_cloud& nc : clouds(o))
  {
    double lo = 1e300, hi = -1e300;
    for(const scan::Sample& s : nc.samples)
    {
      lo = std::min(lo, s.truth.mean);
      hi = std::max(hi, s.truth.mean);
    }
    std::cout << "\n## " << nc.name << ": " << nc.samples.size() << " points, median spacing "
              << g3(scan::median_spacing(nc.samples)) << ", H* in [" << g3(lo) << ", " << g3(hi) << "], k = " << o.k
              << "\n\n| normals | angle median / mean (deg) |";
    for(const Curvature_method& m : methods)
      std::cout << " " << m.name << " |";
    std::cout << "\n|---|---|";
    for(std::size_t j = 0; j < methods.size(); ++j)
      std::cout << "---|";
    std::cout << "\n";
    for(const Normal_source& ns : normal_sources(o))
    {
      if(!o.rows.empty() && o.rows.count(ns.name) == 0)
        continue;
      Cloud c = scan::with_true_normals(nc.samples);
      const auto t0 = std::chrono::steady_clock::now();
      ns.estimate(c);
      const double normal_seconds = psc_bench::seconds_since(t0);
      std::size_t flipped = 0;
      for(std::size_t i = 0; i < c.size(); ++i)
        flipped += c[i].second * nc.samples[i].truth.normal < 0 ? 1 : 0;
      if(ns.oriented_by_truth)
        orient_by_truth(c, nc.samples);
      const std::pair<double, double> ne = normal_errors(c, nc.samples);
      std::cout << "| " << ns.name << " (" << g3(normal_seconds) << " s"
                << (ns.oriented_by_truth ? std::string() : ", " + std::to_string(flipped) + " inward") << ") | "
                << g3(ne.first) << " / " << g3(ne.second) << " |";
      for(const Curvature_method& m : methods)
      {
        const std::vector<Estimate> est = m.run(c, o.k);
        if(!o.dump.empty())
        {
          std::ofstream f(o.dump + "_" + nc.name + "_" + ns.name + "_" + m.name + ".csv");
          f << std::setprecision(10);
          for(std::size_t i = 0; i < est.size(); ++i)
            f << nc.samples[i].p.x() << "," << nc.samples[i].p.y() << "," << nc.samples[i].p.z() << ","
              << nc.samples[i].truth.mean << "," << est[i].mean_curvature << "," << est[i].neighbor_count << ","
              << est[i].mean_curvature_error << "\n";
        }
        const Score s = score(est, nc.samples);
        std::cout << " " << g3(s.mean_abs_H) << (s.valid < 0.995 ? " (" + g3(100 * s.valid) + "% valid)" : "") << " |";
      }
      std::cout << "\n" << std::flush;
    }
  }
  return 0;
}
