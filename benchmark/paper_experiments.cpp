// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Section 6 of Lejemble et al. 2021, measured here (issue 5). One program, run by
// benchmark/paper_experiments.sh, which writes into the output folder:
//
//   sampler:        spacing statistics of the Goursat sampler against the shared samples
//                   (sampler.csv, spacing.png)
//   experiment 1:   convergence with N, fixed and shrinking radius (convergence.csv, .png)
//   experiment 2:   Gaussian noise on the positions (noise_position.csv, .png)
//   experiment 3:   noisy, flipped and PCA normals (noise_normals.csv, .png)
//   experiment 4:   timings, sequential and parallel (timings.csv, .png)
//   experiment 5:   pictures of the bunny and of the Goursat LiDAR cloud coloured by the
//                   estimated curvatures (curvatures_*.png), errors on the LiDAR cloud
//                   (lidar.csv)
//   experiment 6:   error against the neighbour count, which sets each estimator's least
//                   neighbour count of a valid estimate (neighbors.csv, .png)
//   experiment 7:   the ASO's variants beyond the paper against PSS and jets (variants.csv)
//   summary.md:     every table, in Markdown.
//
// Plots are gnuplot scripts (*.gp, data inline) that the shell script runs.
//
// Estimators: ASO and APSS, and every baseline whose header exists (same interface:
// CGAL::estimate_<name>_curvatures<ConcurrencyTag>(points, radius, np)).
//
// Costs are bounded: errors are computed on a region of the surface (below) and every
// estimator has a time budget per experiment; a run whose predicted time (from its
// previous run, scaled by points x neighbours) does not fit is skipped and listed in the
// summary, never silently dropped.
//
// usage: paper_experiments [--quick] [--out DIR] [--data DIR] [--seed S]
//                          [--only LIST] [--budget-scale X]
//   LIST: comma-separated among sampler,convergence,noise_position,noise_normals,timings,pictures,
//         neighbors,variants
//
// One header per experiment in benchmark/paper_experiments/, what they share in support.h.

#include "paper_experiments/sampler.h"
#include "paper_experiments/convergence.h"
#include "paper_experiments/noise.h"
#include "paper_experiments/timings.h"
#include "paper_experiments/neighbors.h"
#include "paper_experiments/variants.h"
#include "paper_experiments/pictures.h"

#include <chrono>
#include <exception>
#include <iostream>
#include <string>
#include <thread>

using namespace psc_paper;

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse_options(argc, argv);
    Context ctx(options);
    Budget::start() = std::chrono::steady_clock::now();
    Budget::deadline() = options.quick ? 100 : 960;
    const auto t0 = std::chrono::steady_clock::now();
    std::string names;
    for(const Estimator& e : ctx.estimators)
      names += (names.empty() ? "" : ", ") + e.name;
    ctx.report.add("# Paper experiments (Lejemble et al. 2021, Section 6), measured here\n\n");
    ctx.report.text(std::string("Mode: ") + (options.quick ? "--quick" : "full") + ", seed " +
                    std::to_string(options.seed) + ", " + std::to_string(std::thread::hardware_concurrency()) +
                    " hardware threads. Estimators found: " + names + ".");
    if(options.run("sampler"))
      experiment_sampler(ctx);
    if(options.run("convergence"))
      experiment_convergence(ctx);
    if(options.run("noise_position"))
      experiment_noise_position(ctx);
    if(options.run("noise_normals"))
      experiment_noise_normals(ctx);
    if(options.run("neighbors"))
      experiment_neighbors(ctx);
    if(options.run("variants"))
      experiment_variants(ctx);
    if(options.run("timings"))
      experiment_timings(ctx);
    if(options.run("pictures"))
      experiment_pictures(ctx);

    ctx.report.section("Goursat samples used");
    Table t;
    t.header = {"N", "Lloyd iterations", "sampling seconds", "max residual abs(F)/norm(grad F), over the diagonal"};
    for(const auto& s : ctx.samples.all())
      t.rows.push_back({format_count(s.first), std::to_string(goursat::Sampling_options().lloyd_iterations),
                        format(s.second.seconds), format(s.second.max_residual)});
    ctx.report.table(t);
    ctx.report.text("Total time of the program: " + format(seconds_since(t0)) + " s.");
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "paper_experiments: " << e.what() << "\n";
    return 1;
  }
}
