// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Experiment 1: convergence with N, fixed and shrinking radius (convergence.csv, .png).

#ifndef PSC_BENCHMARK_PAPER_EXPERIMENTS_CONVERGENCE_H
#define PSC_BENCHMARK_PAPER_EXPERIMENTS_CONVERGENCE_H

#include "support.h"

namespace psc_paper {
namespace {  // one translation unit: paper_experiments.cpp

// --- experiment 1 -----------------------------------------------------------------------

// Shrinking radius: r(N) = r5 (N / 10K)^(-1/4), i.e. proportional to sqrt(h): the radius
// tends to 0 while the number of neighbours grows like sqrt(N) (48 at 10K, 480 at 1M), the
// regime where the discrete sums converge to the integrals of Section 4.1.
double shrinking_radius(double r5, std::size_t n) { return r5 * std::pow(double(n) / 10000.0, -0.25); }

void experiment_convergence(Context& ctx)
{
  ctx.report.section("Experiment 1: convergence (Figure 4)");
  const std::vector<std::size_t> sizes =
    ctx.options.quick ? std::vector<std::size_t>{10000, 25000, 50000}
                      : std::vector<std::size_t>{10000, 25000, 50000, 100000, 250000, 500000, 1000000};
  const double r5 = 0.05 * ctx.diagonal();
  ctx.report.text("Exact positions and normals. Fixed radius r = 5% of the bounding-box diagonal = " + format(r5, 4) +
                  "; shrinking radius r(N) = r5 (N/10K)^(-1/4) (proportional to the square root of the spacing, "
                  "so that r -> 0 while the neighbour count grows like sqrt(N)). Errors are means over the valid "
                  "estimates of the scored points: every point for N < 100K, the points of the fundamental domain "
                  "x >= y >= z >= 0 (1/48 of the surface, the estimators running on it plus an r-margin) from "
                  "100K on. Directions: angle between estimated and true k_max directions where k_max - k_min >= " +
                  format(direction_gap) + ". Empty cell: quantity not given by the estimator.\n");
  Budget budget("convergence", ctx.budget(100, 5));
  std::vector<Error_row> fixed_rows, shrinking_rows;
  struct Domain_check
  {
    std::string estimator;
    std::size_t n;
    Errors whole, domain;
    std::size_t domain_points;
  };
  std::vector<Domain_check> domain_check;
  for(std::size_t n : sizes)
  {
    const Goursat_sample& sample = ctx.samples.get(n);
    for(int rule = 0; rule < 2; ++rule)
    {
      const double r = rule == 0 ? r5 : shrinking_radius(r5, n);
      const Test_cloud t = make_test_cloud(sample.points, sample.points, r);
      for(const Estimator& e : ctx.estimators)
      {
        // Check of the fundamental-domain scoring: at the largest N scored on the whole
        // surface, the same estimates scored on the domain only.
        std::function<void(const std::vector<Estimate>&)> check;
        if(rule == 0 && !t.domain && n * 2 >= domain_threshold)
          check = [&](const std::vector<Estimate>& est) {
            Test_cloud sub;
            sub.sample_size = t.sample_size;
            for(std::size_t s = 0; s < t.scored.size(); ++s)
              if(in_fundamental_cone(t.points[t.scored[s]].first))
              {
                sub.scored.push_back(t.scored[s]);
                sub.truth.push_back(t.truth[s]);
              }
            domain_check.push_back({e.name, n, score(t, est, e.unsigned_curvatures),
                                    score(sub, est, e.unsigned_curvatures), sub.scored.size()});
          };
        run_and_score(ctx, budget, e, t, r, rule == 0 ? "fixed_radius" : "shrinking_radius",
                      rule == 0 ? fixed_rows : shrinking_rows, check);
      }
    }
  }
  std::vector<Error_row> all = fixed_rows;
  all.insert(all.end(), shrinking_rows.begin(), shrinking_rows.end());
  std::stable_sort(all.begin(), all.end(), [](const Error_row& a, const Error_row& b) {
    return std::make_tuple(a.condition, a.N) < std::make_tuple(b.condition, b.N);
  });
  write_error_csv(ctx.path("convergence.csv"), all);
  ctx.report.text("Fixed radius:\n");
  ctx.report.table(error_table(fixed_rows, true, false));
  ctx.report.text("Shrinking radius:\n");
  ctx.report.table(error_table(shrinking_rows, true, false));
  ctx.report.text(skipped_text(ctx, "convergence"));
  if(!domain_check.empty())
  {
    Table c;
    // clang-format off
    c.header = {"estimator", "N",
                "H error, whole surface", "H error, domain",
                "normal error, whole surface", "normal error, domain",
                "k_max error, whole surface", "k_max error, domain"};
    // clang-format on
    for(const Domain_check& d : domain_check)
      c.rows.push_back({d.estimator, format_count(d.n), format(d.whole.H), format(d.domain.H), format(d.whole.normal),
                        format(d.domain.normal), format(d.whole.kmax), format(d.domain.kmax)});
    ctx.report.text("Check of the domain scoring (fixed radius, same estimates scored on the whole surface and on "
                    "the fundamental domain only, " +
                    std::to_string(domain_check.front().domain_points) + " points):\n");
    ctx.report.table(c);
  }
  plot_errors_vs_x(
    ctx, "convergence", "Convergence on the Goursat surface (exact normals)",
    {{"r = 5% diag", fixed_rows}, {"r = r_5 (N/10K)^{-1/4}", shrinking_rows}}, "N (points)",
    [](const Error_row& r) { return double(r.N); }, true);
}

}  // namespace
}  // namespace psc_paper

#endif
