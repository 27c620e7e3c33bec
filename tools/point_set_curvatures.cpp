// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// point_set_curvatures INPUT OUTPUT [options]
//
// Command-line front end of the package: reads a point cloud (.xyz/.pwn/.txt/.csv/.asc, .ply, .off, .las),
// estimates normals if the file has none, estimates curvatures at every point and writes them
// (.ply, .csv or .las), every input point in input order. The options are parsed in
// command_line.cpp, the estimators run from methods.cpp, the files are read and written in
// read_*.cpp and write_point_cloud.cpp (the output file's safety in output_file.cpp), normals
// are estimated in estimated_normals.cpp, interruption and progress are in interruption.cpp and
// progress_bar.h. Every run estimates through range_estimator.h (an input that fits in memory
// as one tile covering all of space, a larger one tile by tile: tiled_run.cpp), writes through
// run_output.h and reports through run_report.h; this file holds the two runs and main().
// Run with --help for the options. Exit status: 0 on success, 2 on invalid arguments or
// unreadable/malformed/unwritable files (one line on stderr, no output file left behind), 3
// when no point got a valid estimate (the output written, the reason on stderr), 130 when
// interrupted by Ctrl-C (SIGINT), 143 by SIGTERM, 1 on unexpected failures.

#include <CGAL/Point_set_curvatures/Tile.h>
#include <CGAL/Point_set_curvatures/average_spacing.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_oriented_normals.h>

#include <tbb/global_control.h>

#include "command_line.h"
#include "estimated_normals.h"
#include "interruption.h"
#include "methods.h"
#include "output_file.h"
#include "progress_bar.h"
#include "range_estimator.h"
#include "run_output.h"
#include "run_report.h"
#include "psc_io/read_point_cloud.h"
#include "run_summary.h"
#include "tiled_normals.h"
#include "tiled_run.h"
#include "psc_io/support.h"
#include "psc_io/write_las.h"
#include "psc_io/write_point_cloud.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace psc_tool;
namespace PSC = CGAL::Point_set_curvatures;

// ---------------------------------------------------------------------------------------
// Finite points (--radius Nx needs 7)

std::size_t finite_point_count(const Point_set& ps)
{
  return std::size_t(std::count_if(ps.begin(), ps.end(), [&ps](Point_set::Index i) {
    const Point& p = ps.point(i);
    return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
  }));
}

// --require-normals on a file without normals: an Error.
void refuse_without_normals(const Options& o, bool with_normals)
{
  if(!with_normals && o.require_normals)
    throw Error(cat(in_quotes(o.input), " has no normals (nx ny nz) and --require-normals was given"));
}

// The scale and estimator options of the run: the command line's, with the position fit
// blended into the robust ASO by default when the normals are estimated (--position-blend;
// --variant paper stays the paper's estimator unless asked).
Estimation_settings estimation_scale(const Options& o, bool normals_estimated)
{
  Estimation_settings s = o.scale;
  s.position_fit_blend =
    o.position_blend >= 0
      ? o.position_blend
      : CGAL::Point_set_curvatures::front_end_defaults::position_fit_blend(s.variant, normals_estimated);
  return s;
}

// The physical memory of the machine, in bytes (0 if unknown).
double physical_memory()
{
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

// More tiles than this: the memory limit is said to be too small (--memory-limit 1K on 1000
// points: 570 tiles, 14 times as long as 8 tiles at 200K).
const std::size_t many_tiles = 500;

// "190K": a --memory-limit of at least `bytes`, two significant digits.
std::string memory_argument(double bytes)
{
  const char* units = "KMGT";
  double v = bytes / 1024;
  int u = 0;
  while(v >= 1000 && u < 3)
  {
    v /= 1024;
    ++u;
  }
  const double step = v >= 100 ? 10 : v >= 10 ? 1 : 0.1;
  v = std::ceil(v / step - 1e-9) * step;
  char text[64];
  std::snprintf(text, sizeof text, step < 1 ? "%.1f%c" : "%.0f%c", std::max(v, 0.1), units[u]);
  return text;
}

// The run on an input that does not fit in the memory limit: estimated in tiles
// (tiled_run.h), bitwise as in memory.
int run_tiled_input(const Run_context& c, Temporary_output& output, const Read_options& read_options,
                    const Scanned_input& input, double memory_limit, const Orientation_choice& orientation,
                    const Las_output_options* las)
{
  const double count_seconds = seconds_since(c.start);
  const Options& o = c.o;
  const std::size_t n = std::size_t(input.points);
  const std::string too_large = cat(in_quotes(o.input), " holds ", n, " points, more than fit in the memory limit (",
                                    memory_limit / (1 << 20), " MB, --memory-limit)");
  // Without normals, they are estimated first, tile by tile, and given to the curvature tiles
  // (tiled_normals.h); with a spanning tree they are oriented over the whole cloud in memory.
  const bool with_normals = input.cloud.has_normals();
  refuse_without_normals(o, with_normals);
  const bool global = !with_normals && CGAL::Point_set_curvatures::internal::is_global(orientation.orientation);
  if(memory_limit < least_memory_for_tiled_normals(double(n), global))
    throw Error(cat(too_large, " and has no normals: ", "orienting them along a spanning tree over the whole cloud (",
                    o.orientation_text == "auto" ? "--orient auto here" : "--orient mst", ") needs --memory-limit ",
                    memory_argument(least_memory_for_tiled_normals(double(n), global)),
                    " or more; or orient them "
                    "locally, tile by tile: --orient +z (airborne scans), another axis, or viewpoint:X,Y,Z"));
  if(!o.scale.by_count && o.scale.spacing_multiple > 0)
    throw Error(cat(too_large, ": --radius ", o.scale.spacing_multiple,
                    "x needs the whole cloud for the average "
                    "spacing; give the radius as a length, or raise --memory-limit"));
  if(!o.method->supports_tiles)
    throw Error(cat(too_large, ": --method ", o.method->name, " needs the whole cloud (", o.method->whole_cloud_reason,
                    "); raise --memory-limit"));
  const Estimation_settings scale = estimation_scale(o, !with_normals);
  reserve_output(o, output, o.drop_attributes && !las ? std::vector<Attribute>() : input.cloud.attributes, n, las);
  Tiling tiling;
  tiling.memory_limit = memory_limit;
  tiling.point_bytes = bytes_per_point(input.cloud.attributes.size(), scale.automatic_largest > 0);
  if(scale.by_count)
    tiling.neighbors = scale.largest_count();
  else
    tiling.halo = PSC::halo_for_radius(scale.radius);
  tiling.temporary_prefix = temporary_prefix(o.output);
  tiling.phase = [&c](const std::string& name) { return c.progress.phase(name); };
  tiling.step = [&c](const std::string& name) { c.progress.step(name); };
  tiling.interrupted = []() { return interrupted != 0; };
  // a limit making many tiles is said at once on a terminal (the run may be long), else with
  // the other warnings at the end
  const auto slow_tiling = [&](const char* makes, std::size_t tiles, std::size_t few_grid, double few_points) {
    return cat(
      "--memory-limit ", size_text(memory_limit), makes, tiles,
      " tiles, each read again from the input with its halo: slow; --memory-limit ",
      memory_argument(few_points * tiling.point_bytes + (with_normals ? 0.0 : gathered_normal_bytes * double(n))),
      " gives at most ", plural(few_grid, "tile"));
  };
  bool slow_tiling_said = false;
  tiling.grid_chosen = [&](std::size_t tiles, std::size_t few_grid, double few_points) {
    if(tiles > many_tiles)
      slow_tiling_said = c.progress.note(
        cat(program, ": warning: ", slow_tiling(" makes up to ", tiles, few_grid, few_points), " (Ctrl-C to stop)"));
  };
  Orientation_choice tile_orientation = orientation;  // (completed when estimated)
  Tiled_normals normals;
  if(!with_normals)
  {
    normals = estimate_tiled_normals(o.input, read_options, input, o, tile_orientation, tiling);
    tiling.normals = &normals.normals;
    tiling.memory_limit = std::max(0.0, tiling.memory_limit - gathered_normal_bytes * double(n));
  }
  Range_estimator estimator(o, scale, tile_orientation, true);
  const Tile_estimator estimate = [&](Tile_points& points, const PSC::Tile& tile,
                                      const Progress& progress) -> Row_source {
    auto ps = std::make_shared<Point_set>();
    fill_point_set(*ps, points.xyz, points.normals);
    std::vector<double>().swap(points.xyz);
    std::vector<double>().swap(points.normals);
    const Pulse_values pulses = {{nullptr, nullptr, nullptr}};
    std::shared_ptr<Estimates> estimates;
    try
    {
      estimates = std::make_shared<Estimates>(
        estimator.estimate(*ps, tile, pulses, [&progress](const char*) { return progress; }));
    }
    catch(const std::invalid_argument& e)
    {
      throw Error(
        cat(e.what(), " (", too_large, ", so it is estimated in tiles: give --radius, or raise --memory-limit)"));
    }
    if(interrupted)
      throw Cancelled();
    return [ps, estimates](std::size_t k, Output_row& r) { estimate_row(*ps, *estimates, k, r); };
  };
  Row_summary summary(n, static_cast<int>(CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS));
  double write_seconds = 0;
  const Tiled_report report = run_tiled(
    o.input, read_options, input, tiling, estimate,
    [&summary](std::size_t i, const Output_row& r) { summary.add(i, r); },
    [&](const Row_source& rows) {
      add_normal_warnings(c.warnings, o, with_normals, tile_orientation, summary, normals.undirected);
      const auto write_start = std::chrono::steady_clock::now();
      write_output(c, output, scale, o.drop_attributes && !las ? std::vector<Attribute>() : input.cloud.attributes, n,
                   summary, rows, las);
      write_seconds = seconds_since(write_start);
    });
  if(report.tiles > many_tiles && !slow_tiling_said)
    c.warnings.push_back(slow_tiling(" makes ", report.tiles, report.few_tiles_grid, report.few_tiles_points));
  print_report(
    c, scale, n, with_normals ? std::string() : cat(normal_fit_description(o), ", oriented ", tile_orientation.text),
    summary,
    cat("count ", s3(count_seconds),
        !with_normals ? cat(", normals: density ", s3(normals.report.density_seconds), ", tile reads ",
                            s3(normals.report.read_seconds), ", tiles ", s3(normals.report.estimate_seconds),
                            ", orientation ", s3(normals.orientation_seconds))
                      : std::string(),
        ", density ", s3(report.density_seconds), ", tile reads ", s3(report.read_seconds), ", curvatures ",
        s3(report.estimate_seconds), ", tile rows ", s3(report.rows_seconds), ", merge and write ", s3(write_seconds)),
    cat(report.tiles, " (memory limit ", memory_limit / (1 << 20), " MB; at most ", report.largest_range,
        " points with a halo of ", report.halo,
        report.halo_growths ? cat("; ", report.halo_growths, " tiles read again with a larger halo") : std::string(),
        !with_normals ? cat("; the normals first in ", plural(normals.report.tiles, "tile"),
                            global ? ", oriented over the whole cloud in memory" : "")
                      : std::string(),
        ")"));
  return 0;
}

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string out_ext = lower_extension(o.output);
  if(out_ext != ".ply" && out_ext != ".csv" && out_ext != ".las")
    throw Error(cat("unsupported output format ", in_quotes(out_ext.empty() ? o.output : out_ext), " for ",
                    in_quotes(o.output), " (expected .ply, .csv or .las)"));
  const bool las_output = out_ext == ".las";
  if(las_output && !o.color.empty())
    throw Error(cat("--color ", o.color,
                    ": a .las output holds no colours of the estimates (LAS viewers colour by a field: choose ",
                    o.color, "); drop --color, or write .ply"));
  if(las_output && o.ascii)
    throw Error("--ascii: a .las output is binary; drop --ascii, or write .ply or .csv");
  {
    struct stat in, out;
    if(::stat(o.input.c_str(), &in) == 0 && ::stat(o.output.c_str(), &out) == 0 && in.st_dev == out.st_dev &&
       in.st_ino == out.st_ino)
      throw Error(cat("the output ", in_quotes(o.output), " is the input file: choose another output"));
  }

  std::unique_ptr<tbb::global_control> threads;
  if(o.threads > 0)
    threads.reset(
      new tbb::global_control(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(o.threads)));

  // An unwritable OUTPUT fails before any long computation; its size is reserved once the
  // input is read, and its file created when writing starts.
  check_output_path(o.output);
  Temporary_output output(o.output);
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  // beyond a file size limit (ulimit -f), a write or a reservation fails with EFBIG, which
  // is reported, instead of killing the process
  std::signal(SIGXFSZ, SIG_IGN);
  if(const std::size_t stale = remove_stale_temporaries(o.output))
    if(!o.quiet)
      std::fprintf(stderr, "%s: note: removed %s of earlier runs writing %s that were killed (%s*)\n", program,
                   plural(stale, "temporary file").c_str(), in_quotes(o.output).c_str(),
                   hidden_sibling(o.output, ".tmp-").c_str());
  Progress_bar progress(!o.quiet && ::isatty(STDERR_FILENO));
  auto check_interrupted = [&]() {
    if(interrupted)
      throw Cancelled();
  };
  // Warnings are printed once the output is written, so that a failure prints one line only.
  std::vector<std::string> warnings;
  auto warn = [&](const std::string& message) { warnings.push_back(message); };
  const Run_context context{o, progress, warnings, start};

  // 1. Read, or count the points of a file too large for the memory limit.
  const double memory_limit = o.memory_limit > 0 ? o.memory_limit : 0.25 * physical_memory();
  if(o.memory_limit > physical_memory() && physical_memory() > 0)
    warn(cat("--memory-limit ", size_text(o.memory_limit), " exceeds this machine's memory (",
             size_text(physical_memory()),
             " of RAM): inputs up to that size are read whole and may be swapped out; give at most the RAM, or "
             "omit --memory-limit for a quarter of it"));
  Read_options read_options;
  read_options.columns = o.columns;
  const bool las = lower_extension(o.input) == ".las";
  // the pulses of --orient scanner, or of --orient auto on a LAS file
  read_options.keep_attributes =
    !o.drop_attributes || o.orient_scanner || (las && o.orientation_text == "auto") || las_output;
  read_options.allow_truncated = o.allow_truncated;
  read_options.progress = progress.phase("reading");
  // (the automatic scale of the curvatures takes more memory, and so does a spanning tree over
  // the estimated normals: --orient mst, or auto but on a LAS file with pulse directions)
  const bool automatic_scale = estimation_scale(o, false).automatic_largest > 0;
  const bool spanning_tree =
    CGAL::Point_set_curvatures::internal::is_global(o.orientation) || o.orientation_text == "auto";
  Scanned_input input =
    read_or_scan(o.input, read_options, memory_limit > 0 ? memory_limit : HUGE_VAL, automatic_scale, spanning_tree);
  for(const std::string& w : input.cloud.warnings)
    warn(w);
  const std::array<int, 3> pulse = pulse_attributes(input.cloud.attributes);
  if(o.orient_scanner && !input.cloud.has_normals() && *std::min_element(pulse.begin(), pulse.end()) < 0)
    throw Error(cat("--orient scanner: ", in_quotes(o.input),
                    " holds no pulse directions (the wave packets of LAS point "
                    "formats 4, 5, 9 and 10); use --orient +z (airborne scans) or viewpoint:X,Y,Z"));
  const bool has_pulses = *std::min_element(pulse.begin(), pulse.end()) >= 0;
  Orientation_choice orientation = choose_orientation(o, las, has_pulses);
  // a LAS output: the input's LAS header and records, the bounds of its points (the same in
  // tiles as in memory)
  Las_output_options las_options;
  las_options.source = input.cloud.las;
  las_options.input_path = o.input;
  las_options.drop_attributes = o.drop_attributes;
  for(int a = 0; a < 3; ++a)
  {
    las_options.lo[a] = input.lo[a];
    las_options.hi[a] = input.hi[a];
  }
  const Las_output_options* las_out = las_output ? &las_options : nullptr;
  if(!input.fits)
  {
    read_options.progress = Progress();
    return run_tiled_input(context, output, read_options, input, memory_limit, orientation, las_out);
  }
  // 2. The whole cloud in memory: the estimation of one tile covering all of space
  // (range_estimator.h), as each tile of a larger file.
  Point_set ps;
  const std::vector<Attribute> attributes = std::move(input.cloud.attributes);  // written after the estimates
  const std::vector<Attribute> no_attributes;
  const bool with_normals = input.cloud.has_normals();
  fill_point_set(ps, input.cloud.xyz, input.cloud.normals);
  input.cloud = Point_cloud();
  reserve_output(o, output, o.drop_attributes && !las_output ? no_attributes : attributes, ps.size(), las_out);
  const double read_seconds = seconds_since(start);
  check_interrupted();
  refuse_without_normals(o, with_normals);

  // 3. Average spacing, for --radius Nx.
  Estimation_settings scale = estimation_scale(o, !with_normals);
  const auto spacing_start = std::chrono::steady_clock::now();
  if(!scale.by_count && scale.spacing_multiple > 0)
  {
    if(finite_point_count(ps) < 7)
      throw Error(cat("--radius ", scale.spacing_multiple, "x: ", in_quotes(o.input),
                      " has fewer than 7 points, too few for an average spacing"));
    // (6 neighbours, as CGAL::compute_average_spacing() is usually called)
    scale.spacing =
      PSC::average_spacing<CGAL::Parallel_tag>(ps, 6, CGAL::parameters::callback(progress.phase("spacing")));
    check_interrupted();
    scale.radius = scale.spacing_multiple * scale.spacing;
    if(!(scale.radius > 0) || !std::isfinite(scale.radius))
      throw Error(cat("--radius ", scale.spacing_multiple, "x: the average spacing of ", in_quotes(o.input), " is ",
                      scale.spacing, " (coincident points?)"));
  }
  const double spacing_seconds = seconds_since(spacing_start);

  // 4. Normals if the file has none, then curvatures.
  const auto estimation_start = std::chrono::steady_clock::now();
  Range_estimator estimator(o, scale, orientation, with_normals);
  Pulse_values pulses = {{nullptr, nullptr, nullptr}};
  if(!with_normals && orientation.scanner)  // (a file with normals may have no pulses)
    for(int a = 0; a < 3; ++a)
      pulses[a] = &attributes[pulse[a]].values;
  const Estimates estimates = estimator.estimate(ps, PSC::Tile::whole_space(), pulses,
                                                 [&progress](const char* name) { return progress.phase(name); });
  const double estimation_seconds = seconds_since(estimation_start) - estimator.normals_seconds();
  check_interrupted();

  // 5. Write.
  const auto write_start = std::chrono::steady_clock::now();
  Row_summary summary(ps.size(), static_cast<int>(CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS));
  {
    Output_row r;
    for(std::size_t i = 0; i < ps.size(); ++i)
    {
      estimate_row(ps, estimates, i, r);
      summary.add(i, r);
    }
  }
  add_normal_warnings(warnings, o, with_normals, orientation, summary, estimator.undirected());
  write_output(
    context, output, scale, o.drop_attributes && !las_output ? no_attributes : attributes, ps.size(), summary,
    [&](std::size_t i, Output_row& r) { estimate_row(ps, estimates, i, r); }, las_out);
  const double write_seconds = seconds_since(write_start);
  print_report(context, scale, ps.size(),
               with_normals ? std::string() : cat(normal_fit_description(o), ", oriented ", orientation.text), summary,
               cat("read ", s3(read_seconds), ", normals ", s3(estimator.normals_seconds()), ", spacing ",
                   s3(spacing_seconds), ", curvatures ", s3(estimation_seconds), ", write ", s3(write_seconds)),
               "");
  return 0;
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse_command_line(argc, argv);
    if(options.help)
    {
      print_usage(std::cout);
      return 0;
    }
    return run(options);
  }
  catch(const Cancelled&)
  {
    // the temporary output was removed when the stack unwound
    std::fprintf(stderr, "\n%s: interrupted (%s), nothing written\n", program, current_phase.c_str());
    return 128 + interrupt_signal;  // 130 for SIGINT, 143 for SIGTERM
  }
  catch(const Error& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  }
  catch(const No_valid_estimate& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 3;
  }
  catch(const std::invalid_argument& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "%s: internal error: %s\n", program, e.what());
    return 1;
  }
}
