// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Experiment 5: pictures of the bunny and of the Goursat LiDAR cloud coloured by the estimated
// curvatures (curvatures_*.png), errors on the LiDAR cloud (lidar.csv).

#ifndef PSC_BENCHMARK_PAPER_EXPERIMENTS_PICTURES_H
#define PSC_BENCHMARK_PAPER_EXPERIMENTS_PICTURES_H

#include "support.h"

namespace psc_paper {
namespace {  // one translation unit: paper_experiments.cpp

// --- experiment 5 -----------------------------------------------------------------------

double quantile_abs(std::vector<double> v, double q)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if(v.empty())
    return 1;
  for(double& x : v)
    x = std::abs(x);
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

double mean_nearest_distance(const Cloud& c)
{
  std::vector<double> xyz;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const Oriented_point& p : c)
    for(int i = 0; i < 3; ++i)
    {
      xyz.push_back(p.first[i]);
      lo[i] = std::min(lo[i], p.first[i]);
      hi[i] = std::max(hi[i], p.first[i]);
    }
  // cells of about 4 points on a surface filling the box
  double area =
    (hi[0] - lo[0]) * (hi[1] - lo[1]) + (hi[1] - lo[1]) * (hi[2] - lo[2]) + (hi[0] - lo[0]) * (hi[2] - lo[2]);
  const double cell = 2 * std::sqrt(2 * area / double(c.size()));
  const goursat::Hash_grid grid(xyz, cell);
  double sum = 0;
  std::size_t count = 0;
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    double best = cell * cell;
    grid.for_each_in_ball(&xyz[3 * i], cell, [&](std::uint32_t j, double d2) {
      if(j != i)
        best = std::min(best, d2);
    });
    if(best < cell * cell)
    {
      sum += std::sqrt(best);
      ++count;
    }
  }
  return count ? sum / double(count) : cell;
}

// Splat radius of every point: 0.8 x the distance to its 6th nearest neighbour, which
// closes the gaps between the scan lines of anisotropic clouds (bunny, LiDAR) that a
// radius from the nearest neighbour leaves open.
std::vector<double> splat_radii(const Cloud& c)
{
  const double cell = 4 * mean_nearest_distance(c);
  std::vector<double> xyz;
  for(const Oriented_point& p : c)
    for(int i = 0; i < 3; ++i)
      xyz.push_back(p.first[i]);
  const goursat::Hash_grid grid(xyz, cell);
  std::vector<double> radii(c.size());
  std::vector<double> d2s;
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    d2s.clear();
    grid.for_each_in_ball(&xyz[3 * i], cell, [&](std::uint32_t j, double d2) {
      if(j != i)
        d2s.push_back(d2);
    });
    const std::size_t k = 6;
    double d = cell;
    if(d2s.size() >= k)
    {
      std::nth_element(d2s.begin(), d2s.begin() + (k - 1), d2s.end());
      d = std::sqrt(d2s[k - 1]);
    }
    radii[i] = 0.8 * d;
  }
  return radii;
}

// Renders panels (one per quantity) and writes a gnuplot script assembling them.
struct Panel
{
  std::string title;
  std::vector<double> values;
};

void render_figure(Context& ctx, const std::string& name, const std::string& title, const Cloud& cloud,
                   const std::vector<std::vector<Panel> >& rows, const render::View& view, double range)
{
  const int size = 400;
  const std::vector<double> radii = splat_radii(cloud);
  std::vector<std::vector<std::string> > files(rows.size());
  for(std::size_t row = 0; row < rows.size(); ++row)
    for(std::size_t col = 0; col < rows[row].size(); ++col)
    {
      std::vector<render::Splat> splats(cloud.size());
      for(std::size_t i = 0; i < cloud.size(); ++i)
      {
        const Oriented_point& p = cloud[i];
        splats[i].position = {{p.first.x(), p.first.y(), p.first.z()}};
        splats[i].normal = {{p.second.x(), p.second.y(), p.second.z()}};
        splats[i].color = render::diverging_color(rows[row][col].values[i], range);
        splats[i].radius = radii[i];
      }
      const std::string file = "panel_" + name + "_" + std::to_string(row) + std::to_string(col) + ".png";
      render::render_splats(splats, view, size, size).write_png(ctx.path(file));
      files[row].push_back(file);
    }
  const std::size_t columns = rows.front().size();
  std::ofstream gp(ctx.path(name + ".gp"));
  const int w = int(columns) * 330 + 100, h = int(rows.size()) * 350 + 40;
  gp << "set terminal pngcairo size " << w << "," << h << " font ',11'\nset output '" << name << ".png'\n";
  gp << render::diverging_palette_gnuplot() << "\nset cbrange [" << -range << ":" << range << "]\n";
  gp << "unset key\nunset border\nunset xtics\nunset ytics\nset size ratio -1\n";
  gp << "set multiplot title " << gp_quote(title) << " font ',13'\n";
  const double cw = 330.0 / w, ch = 350.0 / h, top = 1 - 40.0 / h;
  for(std::size_t row = 0; row < rows.size(); ++row)
    for(std::size_t col = 0; col < columns; ++col)
    {
      gp << "set origin " << col * cw << "," << top - (row + 1) * ch << "\nset size " << cw << "," << ch << "\n";
      gp << "set title " << gp_quote(rows[row][col].title) << "\n";
      gp << "unset colorbox\n";
      gp << "plot '" << files[row][col] << "' binary filetype=png with rgbimage\n";
    }
  // colour bar: a palette plot of nothing, only its colorbox
  gp << "set origin " << columns * cw << "," << top - rows.size() * ch << "\nset size " << 100.0 / w << ","
     << rows.size() * ch << "\n";
  gp << "unset title\nset colorbox user origin " << (columns * cw + 0.01) << "," << (top - rows.size() * ch + 0.1 * ch)
     << " size 0.015," << (rows.size() * ch - 0.2 * ch)
     << "\nset cbtics font ',10'\nset cblabel 'curvature (1/length)'\n";
  gp << "unset size\nset size " << 100.0 / w << "," << rows.size() * ch << "\n";
  gp << "plot [0:1][0:1] '+' using (NaN):(NaN):(0) with points palette\n";
  gp << "unset multiplot\n";
}

void experiment_pictures(Context& ctx)
{
  ctx.report.section("Experiment 5: real data (Figures 1 and 7)");
  const Estimator& aso = find_estimator(ctx.estimators, "ASO");

  // Bunny
  {
    const Cloud bunny = psc_test::read_ascii_ply_xyz_normals(ctx.options.data + "/bunny.ply");
    const double r = 0.005;
    const std::vector<Estimate> est = aso.run(bunny, r, true);
    std::vector<Panel> panels(3);
    panels[0].title = "ASO mean curvature H";
    panels[1].title = "ASO k_{min}";
    panels[2].title = "ASO k_{max}";
    std::size_t invalid = 0;
    for(const Estimate& e : est)
    {
      panels[0].values.push_back(e.mean_curvature);
      panels[1].values.push_back(e.min_curvature);
      panels[2].values.push_back(e.max_curvature);
      invalid += e.is_valid() ? 0 : 1;
    }
    std::vector<double> pooled = panels[1].values;
    pooled.insert(pooled.end(), panels[2].values.begin(), panels[2].values.end());
    const double range = quantile_abs(pooled, 0.95);
    render_figure(ctx, "curvatures_bunny",
                  "Stanford bunny (" + format_count(bunny.size()) + " points), ASO, r = " + format(r), bunny, {panels},
                  render::View::looking_from({{0, 0, 1}}, {{0, 1, 0}}), range);
    ctx.report.text("- `curvatures_bunny.png`: bunny, ASO at r = " + format(r) + ", " + std::to_string(invalid) +
                    " invalid estimates (dark green); colour range ±" + format(range) +
                    " (95% quantile of |k|), blue negative, red positive.");
  }

  // Goursat LiDAR: estimates next to the analytic truth, and errors of every estimator.
  {
    const Cloud lidar = psc_test::read_xyz(ctx.options.data + "/goursat-lidar.xyz");
    const double r = 1.0;
    std::vector<Panel> est_panels(3), truth_panels(3);
    est_panels[0].title = "ASO H";
    est_panels[1].title = "ASO k_{min}";
    est_panels[2].title = "ASO k_{max}";
    truth_panels[0].title = "exact H";
    truth_panels[1].title = "exact k_{min}";
    truth_panels[2].title = "exact k_{max}";
    Test_cloud t;
    t.points = lidar;
    t.sample_size = lidar.size();
    for(std::size_t i = 0; i < lidar.size(); ++i)
    {
      // truth at the radial projection of the (noisy) point onto the surface
      const double v[3] = {lidar[i].first.x(), lidar[i].first.y(), lidar[i].first.z()};
      double p[3];
      goursat::project_radially(v, p);
      t.scored.push_back(std::uint32_t(i));
      t.truth.push_back(psc_test::goursat_truth(Point(p[0], p[1], p[2])));
      truth_panels[0].values.push_back(t.truth.back().mean);
      truth_panels[1].values.push_back(t.truth.back().k_min);
      truth_panels[2].values.push_back(t.truth.back().k_max);
    }
    const std::vector<Estimate> est = aso.run(lidar, r, true);
    for(const Estimate& e : est)
    {
      est_panels[0].values.push_back(e.mean_curvature);
      est_panels[1].values.push_back(e.min_curvature);
      est_panels[2].values.push_back(e.max_curvature);
    }
    std::vector<double> pooled = truth_panels[1].values;
    pooled.insert(pooled.end(), truth_panels[2].values.begin(), truth_panels[2].values.end());
    const double range = quantile_abs(pooled, 0.95);
    render_figure(ctx, "curvatures_goursat_lidar",
                  "Goursat surface, simulated LiDAR (" + std::to_string(lidar.size()) +
                    " points), ASO r = " + format(r) + " (top) and exact values (bottom)",
                  lidar, {est_panels, truth_panels}, render::View::looking_from({{0, 0, 1}}, {{0, 1, 0}}), range);
    ctx.report.text(
      "- `curvatures_goursat_lidar.png`: simulated LiDAR scan of the Goursat surface (top face, anisotropic, "
      "depth noise), ASO at r = " +
      format(r) + " above the exact values; colour range ±" + format(range) + ".\n");

    std::vector<Error_row> rows;
    for(const Estimator& e : ctx.estimators)
    {
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Estimate> x = e.run(lidar, r, true);
      rows.push_back(Error_row{e.name, lidar.size(), r, "lidar", score(t, x, e.unsigned_curvatures), seconds_since(t0),
                               lidar.size()});
    }
    write_error_csv(ctx.path("lidar.csv"), rows);
    ctx.report.text("Errors on the LiDAR cloud against the analytic values at the radial projection of each point "
                    "(points near the scan border have one-sided neighbourhoods):\n");
    ctx.report.table(error_table(rows, false, false));
  }
}

}  // namespace
}  // namespace psc_paper

#endif
