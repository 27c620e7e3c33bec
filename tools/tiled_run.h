// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool on files larger than its memory limit (--memory-limit). The input is read once
// in chunks (read_or_scan): if its points fit, they are kept and the run is the usual
// in-memory one; otherwise the read only counts them and bounds them. Then (run_tiled) a
// second read counts the points per cell of a fine grid, from which a
// CGAL::Point_set_curvatures::Tile_grid is chosen whose tiles, with their halos, fit the
// limit; each tile reads the file again, keeping the points within its halo in input order,
// is estimated with the library's `tile` parameter (bitwise as in one piece), and writes the
// rows of its own points to a temporary file, sorted by input index. A final merge of these
// files gives the rows in input order to the writer. Neighbourhoods by count start from a
// halo guessed from the density and grow it when the library says it is too small
// (Halo_too_small: before estimating, or after it when the sample weights' areas need more).
// A file without normals first has its normals estimated in a pass over tiles of their own
// (visit_tiles(), tiled_normals.h), then given to the curvature tiles (Tiling::normals).

#ifndef POINT_SET_CURVATURES_TOOL_TILED_RUN_H
#define POINT_SET_CURVATURES_TOOL_TILED_RUN_H

#include "psc_io/read_point_cloud.h"
#include "psc_io/support.h"
#include "psc_io/write_point_cloud.h"

#include <CGAL/Point_set_curvatures/Tile.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace psc_tool {

// The input's points within a tile's halo, in input order.
struct Tile_points
{
  std::vector<double> xyz, normals;             // 3 per point; normals empty without
  std::vector<std::uint64_t> index;             // each point's index in the input
  std::vector<std::vector<double>> attributes;  // per attribute of the input, a value per point
  std::size_t size() const { return index.size(); }
};

// What read_or_scan() found.
struct Scanned_input
{
  bool fits = false;         // the whole cloud is in `cloud`
  Point_cloud cloud;         // all the points if `fits`; otherwise only the description
  std::uint64_t points = 0;  // every point of the file
  std::uint64_t finite = 0;  // those with finite coordinates
  double lo[3], hi[3];       // the bounds of the finite points
  // a sample of the finite points (at most 2^20 of them, evenly spaced in input order), for
  // the tiles' box, which ignores outliers
  CGAL::Point_set_curvatures::Tile_box_sample sample;
};

// The memory an in-memory run takes per point with `attributes` input attributes, with the
// automatic scale or not, with normals estimated and oriented along a spanning tree or not
// (the peak RSS of 1M points of a terrain without attributes, 2026-11-30: at --neighbors 40, 366
// bytes a point with normals in the file, 364 with normals estimated along +z, 479 along a
// spanning tree; with the automatic scale 500, with or without normals; the user manual).
double bytes_per_point(std::size_t attributes, bool automatic_scale = false, bool spanning_tree = false);

// The halo of neighbourhoods of `k` nearest at the cloud's mean density: the library's guess
// (PSC::halo_guess_for_count) on the box of the 0.1% to 99.9% quantiles of the sample (the
// box of the tiles). The tiles' grid is chosen with it; each tile by count then starts with
// the halo of the density around its core (tile_first_halo() in tiled_run.cpp).
double density_halo(const Scanned_input& input, std::size_t k);

// Reads `path` in chunks; keeps the points as long as their estimated memory
// (bytes_per_point(), the spanning tree counted if the file has no normals) stays within
// `memory_limit` bytes.
Scanned_input read_or_scan(const std::string& path, const Read_options& options, double memory_limit,
                           bool automatic_scale, bool spanning_tree);

// Row i of the output (i in increasing order).
typedef std::function<void(std::size_t, Output_row&)> Row_source;

struct Tiling
{
  double memory_limit = 0;    // bytes
  double halo = 0;            // the halo of the tiles by radius
  std::size_t neighbors = 0;  // by count (halo unused): the first halos from the density
  // (a tile's halo grows when the estimator throws Halo_too_small)
  std::string temporary_prefix;  // the rows' temporary file is named prefix + "tiles-XXXXXX"
  // starts a progress phase (the density pass; the pass over the tiles, named estimate_phase)
  // and returns its callback
  std::function<Progress(const std::string&)> phase;
  // names a step of the pass over the tiles ("tile 3/8 read", "tile 3/8 curvatures")
  std::function<void(const std::string&)> step;
  // called after every tile; true to cancel (Cancelled is thrown)
  std::function<bool()> interrupted;
  // The bytes per point of a tile with its halo (0: bytes_per_point() of the attributes read,
  // without the automatic scale).
  double point_bytes = 0;
  // Normals by input index (3 per point), given to the tiles of a file without normals: those
  // estimated in a first pass (tiled_normals.h).
  const std::vector<double>* normals = nullptr;
  // the name of the pass over the tiles in the progress line, and of a tile's estimation step
  // ("tile 3/8 curvatures")
  std::string estimate_phase = "curvatures";
  // called once the tile grid is chosen, before the tiles: its size, and the finest grid of
  // at most Tiled_report::few_tiles tiles (its size, the most points a tile of it reads)
  std::function<void(std::size_t tiles, std::size_t few_tiles_grid, double few_tiles_points)> grid_chosen;
};

// Estimates the points of a tile, reporting to `progress`, and returns the source of their
// rows (k: the point's rank in `points`). May free the points' coordinates and normals.
// Throws CGAL::Point_set_curvatures::Halo_too_small when the halo must grow.
typedef std::function<Row_source(Tile_points& points, const CGAL::Point_set_curvatures::Tile& tile,
                                 const Progress& progress)>
  Tile_estimator;

struct Tiled_report
{
  std::size_t tiles = 0;                          // tiles with own points
  std::size_t halo_growths = 0;                   // tiles read again with a larger halo
  double halo = 0;                                // the largest halo of a tile
  std::size_t largest_range = 0;                  // the most points of one tile with its halo
  double density_seconds = 0;                     // the pass that chooses the tiles
  double read_seconds = 0, estimate_seconds = 0;  // of all tiles
  double rows_seconds = 0;                        // the tiles' rows to their temporary files
  // The grid of at most `few_tiles` tiles closest to the one chosen: its number of tiles and
  // the most points of one of them with its first halo (the memory limit that would choose
  // it, divided by Tiling::point_bytes).
  static constexpr std::size_t few_tiles = 100;
  std::size_t few_tiles_grid = 0;
  double few_tiles_points = 0;
};

// Visits a tile's points (`own[k]`: point k is the tile's own). Throws
// CGAL::Point_set_curvatures::Halo_too_small when the halo must grow.
typedef std::function<void(Tile_points& points, const std::vector<char>& own,
                           const CGAL::Point_set_curvatures::Tile& tile, const Progress& progress)>
  Tile_visitor;

// Chooses the tiles (the density pass) and reads each with its halo, in turn, for `visit`
// (read again with a larger halo when it asks). The report's times: the reads and the visits.
// With `options.keep_attributes` false the tiles hold no attribute values.
Tiled_report visit_tiles(const std::string& path, const Read_options& options, const Scanned_input& input,
                         const Tiling& tiling, const Tile_visitor& visit);

// Runs the tiles and then `write(rows)`, where rows(i, r) gives row i in input order; every
// row also goes to `own_row(i, r)` once, as soon as its tile is estimated (for a summary).
Tiled_report run_tiled(const std::string& path, const Read_options& options, const Scanned_input& input,
                       const Tiling& tiling, const Tile_estimator& estimate,
                       const std::function<void(std::size_t, const Output_row&)>& own_row,
                       const std::function<void(const Row_source&)>& write);

}  // namespace psc_tool

#endif
