// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Responsiveness on a huge radius (issue 14): N points on a unit sphere and a radius of 3,
// which covers the whole cloud, so every point has N neighbours, every point lies in one grid
// cell and the cost is quadratic. For each estimator, Parallel_tag then Sequential_tag:
//   - the callback asks to cancel once `cancel_after` seconds have passed; the benchmark
//     measures the time from that request (the callback returning false) to the function's
//     return: the cancellation latency,
//   - the widest gap between two consecutive progress reports,
//   - the cores used: process CPU time over wall time during the run (2 on this machine if
//     the single cell is shared by both threads),
//   - the cost of the full run extrapolated from the fraction done: the worst case of a
//     radius that covers the cloud, in ns per (point, neighbour) pair.
//
// usage: responsiveness [number_of_points=50000] [cancel_after_seconds=3]

#include "bench_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_oriented_normals.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

typedef std::chrono::steady_clock Clock;

double cpu_seconds()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Measure
{
  double latency = 0;     // cancel request -> return (s)
  double widest_gap = 0;  // between consecutive reports (s)
  double cores = 0;       // CPU time / wall time
  double fraction = 0;    // done when cancelled
  double wall = 0;
};

template <class Run>
Measure measure(Run run, double cancel_after)
{
  Measure m;
  const Clock::time_point start = Clock::now();
  Clock::time_point last_report = start, cancel_time = start;
  bool cancelled = false;
  const std::function<bool(double)> cb = [&](double fraction) {
    const Clock::time_point now = Clock::now();
    m.widest_gap = std::max(m.widest_gap, std::chrono::duration<double>(now - last_report).count());
    last_report = now;
    m.fraction = fraction;
    if(!cancelled && std::chrono::duration<double>(now - start).count() >= cancel_after)
    {
      cancelled = true;
      cancel_time = Clock::now();
      return false;
    }
    return !cancelled;
  };
  const double cpu0 = cpu_seconds();
  run(cb);
  const Clock::time_point end = Clock::now();
  m.wall = std::chrono::duration<double>(end - start).count();
  m.cores = (cpu_seconds() - cpu0) / m.wall;
  m.latency = cancelled ? std::chrono::duration<double>(end - cancel_time).count() : -1;
  return m;
}

}  // namespace

int main(int argc, char** argv)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::pair<K::Point_3, K::Vector_3> Oriented_point;
  typedef CGAL::First_of_pair_property_map<Oriented_point> Point_map;
  typedef CGAL::Second_of_pair_property_map<Oriented_point> Normal_map;

  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 50000;
  const double cancel_after = argc > 2 ? std::atof(argv[2]) : 3.0;
  const double radius = 3.0;

  std::vector<Oriented_point> cloud;
  for(const auto& p : psc_test::sphere(n, 1.0))
    cloud.emplace_back(K::Point_3(p.first.x(), p.first.y(), p.first.z()),
                       K::Vector_3(p.second.x(), p.second.y(), p.second.z()));
  const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());

  std::printf("%zu points on a unit sphere, radius %.1f (every point has %zu neighbours), cancel requested "
              "after %.1f s\n\n",
              n, radius, n, cancel_after);
  std::printf("| estimator | tag | cancel latency (s) | widest report gap (s) | cores used | done when "
              "cancelled | full run, extrapolated (s) | ns per pair |\n|---|---|---|---|---|---|---|---|\n");

  auto row = [&](const char* name, const char* tag, const Measure& m) {
    const double full = m.fraction > 0 ? m.wall / m.fraction : 0;
    std::printf("| %s | %s | %.3f | %.3f | %.2f | %.1f%% | %.0f | %.1f |\n", name, tag, m.latency, m.widest_gap,
                m.cores, 100 * m.fraction, full, 1e9 * full / (double(n) * double(n)));
    std::fflush(stdout);
  };

  for(int parallel = 1; parallel >= 0; --parallel)
  {
    const char* tag = parallel ? "Parallel_tag" : "Sequential_tag";
    row("ASO (default)", tag,
        measure(
          [&](const std::function<bool(double)>& cb) {
            if(parallel)
              CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, radius, np.callback(cb));
            else
              CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(cloud, radius, np.callback(cb));
          },
          cancel_after));
    row("ASO (paper)", tag,
        measure(
          [&](const std::function<bool(double)>& cb) {
            const auto p =
              CGAL::Point_set_curvatures::parameters::aso_variant(CGAL::Aso_variant::PAPER, np.callback(cb));
            if(parallel)
              CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(cloud, radius, p);
            else
              CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(cloud, radius, p);
          },
          cancel_after));
    row("APSS", tag,
        measure(
          [&](const std::function<bool(double)>& cb) {
            if(parallel)
              CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(cloud, radius, np.callback(cb));
            else
              CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(cloud, radius, np.callback(cb));
          },
          cancel_after));
  }
  return 0;
}
