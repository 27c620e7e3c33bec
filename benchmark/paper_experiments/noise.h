// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Experiments 2 and 3: Gaussian noise on the positions (noise_position.csv, .png); noisy,
// flipped and PCA normals (noise_normals.csv, .png).

#ifndef PSC_BENCHMARK_PAPER_EXPERIMENTS_NOISE_H
#define PSC_BENCHMARK_PAPER_EXPERIMENTS_NOISE_H

#include "support.h"

namespace psc_paper {
namespace {  // one translation unit: paper_experiments.cpp

// --- experiments 2 and 3 ------------------------------------------------------------------

std::size_t noise_sample_size(const Context& ctx) { return ctx.options.quick ? 25000 : 100000; }

void experiment_noise_position(Context& ctx)
{
  ctx.report.section("Experiment 2: Gaussian noise on the positions (Figure 5, Theorem 2)");
  const std::size_t n = noise_sample_size(ctx);
  const double r = 0.05 * ctx.diagonal();
  const Goursat_sample& sample = ctx.samples.get(n);
  ctx.report.text("N = " + format_count(n) + ", r = 5% of the diagonal = " + format(r, 4) +
                  ". Every position moved by an isotropic Gaussian vector of standard deviation sigma per "
                  "coordinate (the paper's 0.005, 0.01, 0.02 at r = 0.1); the input normals stay the exact "
                  "normals of the clean points, and the truth is taken at the clean points.\n");
  Budget budget("noise_position", ctx.budget(25, 3));
  std::vector<Error_row> rows;
  for(double fraction : {0.0, 0.05, 0.1, 0.2})
  {
    const double sigma = fraction * r;
    goursat::Random random(ctx.options.seed * 7 + 11);
    Cloud noisy = sample.points;
    for(Oriented_point& p : noisy)
    {
      const double g0 = random.gaussian(), g1 = random.gaussian(), g2 = random.gaussian();
      p.first = Point(p.first.x() + sigma * g0, p.first.y() + sigma * g1, p.first.z() + sigma * g2);
    }
    const Test_cloud t = make_test_cloud(sample.points, noisy, r);
    const std::string condition = "sigma=" + format(fraction) + "r";
    for(const Estimator& e : ctx.estimators)
      run_and_score(ctx, budget, e, t, r, condition, rows);
  }
  write_error_csv(ctx.path("noise_position.csv"), rows);
  ctx.report.table(error_table(rows, false, true));
  ctx.report.text(skipped_text(ctx, "noise_position"));
  plot_errors_vs_x(ctx, "noise_position", "Gaussian noise on the positions, N = " + format_count(n) + ", r = 5% diag",
                   {{"noise", rows}}, "sigma / r",
                   [](const Error_row& row) { return std::stod(row.condition.substr(6)); }, false,
                   {"set xrange [-0.01:0.21]"});
}

// PCA normals (k nearest neighbours), oriented by a minimum spanning tree, in input order;
// returns the number of points the MST could not orient.
std::size_t pca_oriented_normals(Cloud& points, unsigned k)
{
  typedef std::tuple<Point, Vector, std::size_t> Indexed;
  std::vector<Indexed> work;
  work.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    work.emplace_back(points[i].first, Vector(0, 0, 0), i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Indexed>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Indexed>());
  CGAL::pca_estimate_normals<CGAL::Parallel_tag>(work, k, np);
  const auto unoriented = CGAL::mst_orient_normals(work, k, np);
  const std::size_t failed = std::size_t(std::distance(unoriented, work.end()));
  for(const Indexed& w : work)
    points[std::get<2>(w)].second = std::get<1>(w);
  return failed;
}

void experiment_noise_normals(Context& ctx)
{
  ctx.report.section("Experiment 3: perturbed normals (Figure 6, and PCA normals of Figure 5)");
  const std::size_t n = noise_sample_size(ctx);
  const double r = 0.05 * ctx.diagonal();
  const Goursat_sample& sample = ctx.samples.get(n);
  const unsigned k = 18;
  Budget budget("noise_normals", ctx.budget(30, 6));
  std::vector<Error_row> rows;
  std::vector<std::string> notes;
  struct Condition
  {
    std::string name;
    std::function<void(Cloud&)> apply;
  };
  std::vector<Condition> conditions;
  conditions.push_back({"exact", [](Cloud&) {}});
  for(double degrees : {10.0, 20.0, 30.0})
    conditions.push_back({"angle_sigma=" + format(degrees) + "deg", [&, degrees](Cloud& c) {
                            // Tilt by a Gaussian angle vector of standard deviation `degrees`
                            // per tangent axis (mean tilt 1.25 sigma).
                            goursat::Random random(ctx.options.seed * 13 + std::uint64_t(degrees));
                            double mean_tilt = 0;
                            for(Oriented_point& p : c)
                            {
                              const double nn[3] = {p.second.x(), p.second.y(), p.second.z()};
                              double t1[3], t2[3];
                              goursat::tangent_frame(nn, t1, t2);
                              const double a = random.gaussian() * degrees * M_PI / 180;
                              const double b = random.gaussian() * degrees * M_PI / 180;
                              const double tilt = std::sqrt(a * a + b * b);
                              mean_tilt += tilt;
                              if(tilt == 0)
                                continue;
                              const double cs = std::cos(tilt), sn = std::sin(tilt) / tilt;
                              p.second = Vector(cs * nn[0] + sn * (a * t1[0] + b * t2[0]),
                                                cs * nn[1] + sn * (a * t1[1] + b * t2[1]),
                                                cs * nn[2] + sn * (a * t1[2] + b * t2[2]));
                            }
                            notes.push_back("angle_sigma=" + format(degrees) + "deg: mean tilt " +
                                            format(mean_tilt / double(c.size()) * 180 / M_PI) + " degrees");
                          }});
  for(double p : {0.1, 0.3})
    conditions.push_back({"flip_p=" + format(p), [&, p](Cloud& c) {
                            goursat::Random random(ctx.options.seed * 17 + std::uint64_t(p * 10));
                            for(Oriented_point& q : c)
                              if(random.uniform() < p)
                                q.second = -q.second;
                          }});
  conditions.push_back(
    {"pca_normals_k" + std::to_string(k), [&](Cloud& c) {
       const auto t0 = std::chrono::steady_clock::now();
       const std::size_t failed = pca_oriented_normals(c, k);
       double angle = 0;
       std::size_t wrong = 0;
       for(std::size_t i = 0; i < c.size(); ++i)
       {
         const Vector& truth = sample.points[i].second;
         const double d = c[i].second * truth / std::sqrt(c[i].second.squared_length());
         angle += std::acos(std::min(1.0, std::abs(d))) * 180 / M_PI;
         if(d < 0)
           ++wrong;
       }
       notes.push_back("pca_normals_k" + std::to_string(k) + ": CGAL::pca_estimate_normals (k = " + std::to_string(k) +
                       ") + CGAL::mst_orient_normals (k = " + std::to_string(k) + ") in " + format(seconds_since(t0)) +
                       " s; mean angle to the true normal " + format(angle / double(c.size())) + " degrees; " +
                       std::to_string(wrong) + " normals point inwards, " + std::to_string(failed) +
                       " left unoriented by the MST");
     }});
  for(const Condition& c : conditions)
  {
    Cloud input = sample.points;
    c.apply(input);
    const Test_cloud t = make_test_cloud(sample.points, input, r);
    for(const char* name : {"APSS", "ASO", "ASO-paper"})
      run_and_score(ctx, budget, find_estimator(ctx.estimators, name), t, r, c.name, rows);
  }
  ctx.report.text("N = " + format_count(n) + ", r = " + format(r, 4) +
                  ", exact positions. Angular noise: each normal tilted by a random tangent angle vector "
                  "with a Gaussian distribution of the given standard deviation per axis. Flips: each normal "
                  "reversed with probability p. The normal error 1 - |n.n*| ignores orientation.\n");
  for(const std::string& s : notes)
    ctx.report.text("- " + s);
  ctx.report.text("");
  write_error_csv(ctx.path("noise_normals.csv"), rows);
  ctx.report.table(error_table(rows, false, true));
  ctx.report.text(skipped_text(ctx, "noise_normals"));

  // Grouped plot: x = condition index.
  std::vector<std::string> names;
  for(const Condition& c : conditions)
    names.push_back(c.name);
  std::string tics = "set xtics (";
  for(std::size_t i = 0; i < names.size(); ++i)
    tics += (i ? ", " : "") + gp_quote(names[i]) + " " + std::to_string(i);
  tics += ") rotate by -30 font ',8' noenhanced";
  plot_errors_vs_x(ctx, "noise_normals", "Perturbed input normals, N = " + format_count(n) + ", r = 5% diag",
                   {{"normals", rows}}, "",
                   [names](const Error_row& row) {
                     return double(std::find(names.begin(), names.end(), row.condition) - names.begin());
                   },
                   false, {tics, "set xrange [-0.5:" + std::to_string(names.size() - 0.5) + "]"});
}

}  // namespace
}  // namespace psc_paper

#endif
