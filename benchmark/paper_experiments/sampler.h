// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The sampler report: spacing statistics of the Goursat sampler against the shared samples
// (sampler.csv, spacing.png).

#ifndef PSC_BENCHMARK_PAPER_EXPERIMENTS_SAMPLER_H
#define PSC_BENCHMARK_PAPER_EXPERIMENTS_SAMPLER_H

#include "support.h"

namespace psc_paper {
namespace {  // one translation unit: paper_experiments.cpp

// --- sampler report ---------------------------------------------------------------------

struct Spacing_stats
{
  std::string name;
  std::size_t n = 0;
  double mean = 0, cv = 0, min = 0, p01 = 0, p99 = 0;
  std::vector<double> histogram;  // fraction per bin of nn/h in [0, 1.6), 40 bins
};

Spacing_stats spacing_stats(const std::string& name, const Cloud& points)
{
  std::vector<double> d = goursat::nearest_neighbor_spacing(points);
  Spacing_stats s;
  s.name = name;
  s.n = d.size();
  for(double x : d)
    s.mean += x;
  s.mean /= double(d.size());
  double var = 0;
  for(double x : d)
    var += (x - s.mean) * (x - s.mean);
  s.cv = std::sqrt(var / double(d.size())) / s.mean;
  std::sort(d.begin(), d.end());
  s.min = d.front();
  s.p01 = d[d.size() / 100];
  s.p99 = d[d.size() * 99 / 100];
  s.histogram.assign(40, 0);
  for(double x : d)
    s.histogram[std::min<std::size_t>(39, std::size_t(x / 0.04))] += 1.0 / double(d.size());
  return s;
}

void experiment_sampler(Context& ctx)
{
  ctx.report.section("Sampler: blue noise on the Goursat surface");
  const auto& c = goursat::surface_constants();
  ctx.report.text("Surface `-8 - 2(x²+y²+z²) + 0.03(x⁴+y⁴+z⁴) = 0`: area " + format(c.area, 7) + ", bounding box [-" +
                  format(c.half_extent, 7) + ", " + format(c.half_extent, 7) + "]³, diagonal " + format(c.diagonal, 7) +
                  ". Spacing below is the nearest-neighbour "
                  "distance divided by h = sqrt(area/N) (a hexagonal lattice has 1.075 h, uniform random "
                  "points 0.5 h on average with a coefficient of variation of 0.52).\n");
  std::vector<Spacing_stats> stats;
  std::vector<std::size_t> sizes = {10000, 50000};
  std::vector<Error_row> compared;  // estimators on the shared samples and on ours
  const double r5 = 0.05 * ctx.diagonal();
  auto compare = [&](const std::string& label, const Cloud& cloud) {
    Test_cloud t;
    t.points = cloud;
    t.sample_size = cloud.size();
    for(std::size_t i = 0; i < cloud.size(); ++i)
    {
      t.scored.push_back(std::uint32_t(i));
      t.truth.push_back(psc_test::goursat_truth(cloud[i].first));
    }
    for(const char* name : {"APSS", "ASO", "ASO-paper"})
    {
      const Estimator& e = find_estimator(ctx.estimators, name);
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Estimate> est = e.run(cloud, r5, true);
      compared.push_back(Error_row{e.name, cloud.size(), r5, label, score(t, est, e.unsigned_curvatures),
                                   seconds_since(t0), cloud.size()});
    }
  };
  for(std::size_t n : sizes)
  {
    goursat::Random random(ctx.options.seed + n);
    const std::vector<double> xyz = goursat::uniform_random_points(n, random);
    Cloud pts;
    for(std::size_t i = 0; i < n; ++i)
      pts.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), Vector(0, 0, 1));
    stats.push_back(spacing_stats("uniform random, N=" + format_count(n), pts));
    stats.push_back(spacing_stats("this sampler (" + std::to_string(goursat::Sampling_options().lloyd_iterations) +
                                    " Lloyd iterations), N=" + format_count(n),
                                  ctx.samples.get(n).points));
    compare("this sampler", ctx.samples.get(n).points);
    const std::string file = ctx.options.data + (n == 10000 ? "/goursat_010000.xyz" : "/goursat_050000.xyz");
    std::ifstream probe(file);
    if(probe)
    {
      const Cloud shared = psc_test::read_xyz(file);
      stats.push_back(spacing_stats("shared sample " + file.substr(file.find_last_of('/') + 1), shared));
      compare("shared " + file.substr(file.find_last_of('/') + 1), shared);
    }
  }
  Table t;
  t.header = {"point set",       "N", "mean spacing / h", "coefficient of variation", "min / h", "1% quantile / h",
              "99% quantile / h"};
  for(const Spacing_stats& s : stats)
    t.rows.push_back(
      {s.name, std::to_string(s.n), format(s.mean), format(s.cv), format(s.min), format(s.p01), format(s.p99)});
  ctx.report.table(t);
  ctx.report.text("The same estimators on the shared samples and on this sampler's (r = 5% of the diagonal, exact "
                  "normals, every point scored; the shared points lie within 1e-5 of the surface):\n");
  ctx.report.table(error_table(compared, true, true));

  // Spacing statistics of the samples compared above.
  std::ofstream csv(ctx.path("sampler.csv"));
  csv << "point_set,N,mean_spacing_over_h,cv,min_over_h,p01_over_h,p99_over_h\n";
  for(const Spacing_stats& s : stats)
    csv << s.name << "," << s.n << "," << s.mean << "," << s.cv << "," << s.min << "," << s.p01 << "," << s.p99 << "\n";

  std::ofstream gp(ctx.path("spacing.gp"));
  gp << "set terminal pngcairo size 900,520 font ',11'\nset output 'spacing.png'\n";
  gp << "$H << EOD\n";
  for(std::size_t b = 0; b < 40; ++b)
  {
    gp << (b + 0.5) * 0.04;
    for(const Spacing_stats& s : stats)
      gp << " " << s.histogram[b];
    gp << "\n";
  }
  gp << "EOD\n";
  gp << "set title 'Nearest-neighbour spacing on the Goursat surface (h = sqrt(area/N))'\n"
        "set xlabel 'nearest-neighbour distance / h'\nset ylabel 'fraction of points'\n"
        "set key top left noenhanced\nset grid\n";
  gp << "plot ";
  for(std::size_t i = 0; i < stats.size(); ++i)
    gp << (i ? ", \\\n     " : "") << "$H using 1:" << i + 2 << " with linespoints lw 2 pt " << (i % 7) + 1
       << " ps 0.6 lc rgb '" << gnuplot_colors[i % 10] << "' title " << gp_quote(stats[i].name);
  gp << "\n";
}

}  // namespace
}  // namespace psc_paper

#endif
