// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See run_report.h.

#include "run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace psc_tool {

namespace {

std::string min_median_max(const Row_summary& s, int q)
{
  if(s.count(q) == 0)
    return s.valid() ? "n/a (not estimated by this method)" : "n/a (no valid estimate)";
  return cat("min ", s.min(q), "  median ", percentile(s.sample(q), 0.5), "  max ", s.max(q));
}

// The points that can be anyone's neighbour: finite, with a usable normal.
std::size_t usable_points(const Row_summary& summary)
{
  std::size_t n = summary.valid();
  for(const auto& s : summary.invalid())
    if(s.first != int(CGAL::Curvature_estimate_status::NON_FINITE_POINT) &&
       s.first != int(CGAL::Curvature_estimate_status::INVALID_NORMAL))
      n += s.second;
  return n;
}

// "fewer than 12 neighbours": the least count of a valid estimate, when the tool knows it
// (--min-neighbors below a fit's own least count, 3 or 6 points, is raised to it).
std::string fewer_than_least(const Method& m, const Estimation_settings& scale)
{
  const std::size_t least = scale.min_neighbors ? scale.min_neighbors : m.min_neighbors;
  return least >= 6 ? cat("fewer than ", least, " neighbours") : std::string("too few neighbours for a fit");
}

// When the input holds fewer usable points than the method's `good_neighbors`, no scale
// helps: what to say instead of a suggested scale ("" otherwise).
std::string too_small_input(const Method& m, const Estimation_settings& scale, const std::string& input,
                            const Row_summary& summary)
{
  const std::size_t usable = usable_points(summary);
  const std::size_t good = m.good_neighbors_of(scale.variant);
  if(usable >= good)
    return "";
  return cat(in_quotes(input), " is too small for ", m.name, ": it holds ", plural(usable, "usable point"),
             " (finite, with a normal), fewer than the ", good, " neighbours from which ", m.name,
             "'s errors stay within twice those at 40 (measured, see the manual), whatever --radius or --neighbors");
}

// The scale to try for about 40 neighbours, from the median count (counts grow like the
// radius squared on a surface).
std::string suggested_scale(const Method& m, const Estimation_settings& scale, double median)
{
  if(scale.by_count)
    return cat("--neighbors ", std::max<std::size_t>(40, m.good_neighbors_of(scale.variant)));
  const double factor = std::sqrt(40.0 / std::max(median, 1.0));
  return scale.spacing_multiple > 0 ? cat("--radius ", scale.spacing_multiple * factor, "x")
                                    : cat("--radius ", scale.radius * factor);
}

// The warning when neighbourhoods are small: empty if the median count of the estimated
// points reaches the method's measured `good_neighbors`.
std::string small_neighborhood_warning(const Method& m, const Estimation_settings& scale, const Row_summary& summary,
                                       const std::string& input)
{
  if(summary.neighbor_sample().empty())
    return "";
  const double median = percentile(summary.neighbor_sample(), 0.5);
  const std::size_t good = m.good_neighbors_of(scale.variant);
  if(median >= double(good))
    return "";
  const std::string invalid =
    summary.too_few() == 0
      ? std::string()
      : cat("; ", plural(summary.too_few(), "point"), summary.too_few() == 1 ? " has " : " have ",
            fewer_than_least(m, scale), " and ", summary.too_few() == 1 ? "is" : "are", " invalid (too_few_neighbors)");
  const std::string too_small = too_small_input(m, scale, input, summary);
  if(!too_small.empty())
    return too_small + invalid;
  return cat("the median neighbourhood holds ", plural(std::size_t(median), "point"), ", fewer than the ", good,
             " from which ", m.name, "'s errors stay within twice those at 40 neighbours (measured, see the manual)",
             invalid, ". For about 40 neighbours, try ", suggested_scale(m, scale, median));
}

// Why no point got a valid estimate (exit status 3): the most frequent status, what causes
// it, and what to try.
std::string no_valid_estimate_reason(const Method& m, const Estimation_settings& scale, const Row_summary& summary,
                                     const std::string& input, bool normals_estimated)
{
  typedef CGAL::Curvature_estimate_status Status;
  int status = -1;
  std::size_t count = 0, n = 0;
  for(const auto& s : summary.invalid())
  {
    n += s.second;
    if(s.second > count)
    {
      status = s.first;
      count = s.second;
    }
  }
  const std::string what =
    cat(count == n ? (n == 1 ? std::string("the only point is ") : cat("all ", n, " points are "))
                   : cat(count, " of the ", n, count == 1 ? " points is " : " points are "),
        CGAL::to_string(static_cast<Status>(status)));
  std::string why;
  switch(static_cast<Status>(status))
  {
    case Status::TOO_FEW_NEIGHBORS: {
      const std::string too_small = too_small_input(m, scale, input, summary);
      if(!too_small.empty())
        why = too_small + " (--min-neighbors lowers the least count of a valid estimate, at a cost in accuracy)";
      else if(!summary.neighbor_sample().empty())
      {
        const double median = percentile(summary.neighbor_sample(), 0.5);
        why = cat("the median neighbourhood holds ", plural(std::size_t(median), "point"), ": ",
                  fewer_than_least(m, scale), ", the least count of a valid ", m.name,
                  " estimate; for about 40 neighbours, try ", suggested_scale(m, scale, median));
      }
      break;
    }
    case Status::DEGENERATE_FIT:
      why = "coincident neighbours, neighbours along one line (a single scan line), or a radius far larger than "
            "the cloud; --radius 3.5x gives about 40 neighbours";
      break;
    case Status::NON_FINITE_POINT: why = "NaN or infinite coordinates"; break;
    case Status::INVALID_NORMAL:
      why = normals_estimated ? "no normal could be estimated (too few points, coincident points, or points along "
                                "one line: try a larger --normal-neighbors)"
                              : "the normals are zero, not finite or far from unit length (are the columns right? "
                                "see --columns)";
      break;
    case Status::TWO_SHEETS:
      why = "two layers with opposite normals in every neighbourhood (a thin plate, or neighbourhoods reaching "
            "across the object): try a smaller --radius or --neighbors";
      break;
    default: break;
  }
  return cat("no valid estimate: ", what, why.empty() ? std::string() : ": " + why);
}

// The warnings and the summary (not with --quiet).
void print_summary(const Run_context& c, const Estimation_settings& scale, std::size_t n,
                   const std::string& estimated_normals, const Row_summary& summary, const std::string& times,
                   const std::string& tiles)
{
  const Options& o = c.o;
  if(o.quiet)
    return;
  for(const std::string& w : c.warnings)
    std::fprintf(stderr, "%s: warning: %s\n", program, w.c_str());
  std::string why;
  for(const auto& s : summary.invalid())
    why += cat(why.empty() ? "; " : ", ", s.second, " ",
               CGAL::to_string(static_cast<CGAL::Curvature_estimate_status>(s.first)));
  const std::size_t valid = summary.valid();
  std::printf("%s: %s -> %s\n", program, o.input.c_str(), o.output.c_str());
  std::printf("  method      %s: %s\n", method_label(o, scale).c_str(), o.method->summary);
  std::printf("  scale       %s\n", scale_description(scale).c_str());
  std::printf("  points      %zu%s\n", n, estimated_normals.empty() ? "" : " (normals estimated)");
  if(!estimated_normals.empty())
  {
    std::printf("  normals     %s\n", estimated_normals.c_str());
    // what the output holds: the estimators' corrected normals, which can differ in side from
    // the estimated ones (the ASO's takes the side of the neighbours' majority)
    const std::size_t vertical = summary.near_vertical(), up = summary.near_vertical_up();
    if(valid > 0)
      std::printf("  output      %s%% of the valid rows' normals within 60 degrees of the vertical, %s%% of those "
                  "point up (%zu down)\n",
                  percent_text(vertical, valid).c_str(), percent_text(up, vertical).c_str(), vertical - up);
  }
  if(!tiles.empty())
    std::printf("  tiles       %s\n", tiles.c_str());
  std::printf("  valid       %zu (%.2f %%)%s\n", valid, 100.0 * double(valid) / double(n), why.c_str());
  std::printf("  neighbours  %.2f on average (valid estimates)\n",
              valid ? double(summary.neighbors()) / double(valid) : 0.0);
  std::printf("  time        %s s: %s\n", s3(seconds_since(c.start)).c_str(), times.c_str());
  std::printf("  H (mean)    %s\n", min_median_max(summary, summary_quantities::of("mean")).c_str());
  std::printf("  K (Gauss)   %s\n", min_median_max(summary, summary_quantities::of("gaussian")).c_str());
}

}  // namespace

std::string s3(double seconds)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

std::string scale_description(const Estimation_settings& s)
{
  if(s.by_count && s.automatic_largest > 0)
    return cat("automatic scale: ", s.neighbors, " to ", s.automatic_largest,
               " nearest neighbours, the count chosen per point (field neighbors)");
  if(s.by_count)
    return cat(s.neighbors, " nearest neighbours per point (itself included)");
  if(s.spacing_multiple > 0)
    return cat("radius ", s.radius, " (", s.spacing_multiple, " x average spacing ", s.spacing, ")");
  return cat("radius ", s.radius);
}

std::string method_label(const Options& o, const Estimation_settings& scale)
{
  if(std::string(o.method->name) != "aso")
    return o.method->name;
  return cat("aso (", scale.variant == CGAL::Aso_variant::PAPER ? "paper's variant" : "robust variant",
             scale.position_fit_blend > 0 ? cat(", blended with a position fit, weight ", scale.position_fit_blend)
                                          : std::string(),
             ")");
}

void print_report(const Run_context& c, const Estimation_settings& scale, std::size_t n,
                  const std::string& estimated_normals, const Row_summary& summary, const std::string& times,
                  const std::string& tiles)
{
  const Options& o = c.o;
  const bool none_valid = n > 0 && summary.valid() == 0;
  const std::string small = none_valid ? std::string() : small_neighborhood_warning(*o.method, scale, summary, o.input);
  if(!small.empty())
    c.warnings.push_back(small);
  print_summary(c, scale, n, estimated_normals, summary, times, tiles);
  if(none_valid)
    throw No_valid_estimate(
      cat(no_valid_estimate_reason(*o.method, scale, summary, o.input, !estimated_normals.empty()), "; ",
          in_quotes(o.output), " was written, every row invalid"));
}

}  // namespace psc_tool
