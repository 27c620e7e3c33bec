// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The normals of a file larger than the memory limit and without normals, estimated once in
// a first pass over the tiles (visit_tiles()), before the curvature tiles, which are then given
// them as a file's normals (Tiling::normals): each point's normal is estimated once, where a
// curvature tile estimating the normals of its own halo estimated most of them several times
// (lone-star.las, 519K points, --memory-limit 210M --orient +z: 229 s in 6 tiles before, 82 s in
// 16 tiles after, 35 s in memory). The outputs are bitwise those of the in-memory run.
//
// With an orientation along a vector or towards a point (and --orient scanner), each tile
// orients the normals of its own points. A spanning tree (--orient mst, and --orient auto on
// files other than LAS files with pulse directions) spans the whole cloud: each tile gives its
// own points their unoriented normal and nearest neighbours
// (estimate_normal_records(), bitwise as over the whole cloud), gathered by input index with
// their coordinates, and these are oriented at once as the library orients a whole cloud
// (CGAL::Point_set_curvatures::internal::orient_normal_records()). The gathered arrays of
// every point stay in memory: 24 bytes a point (the normals) with a local orientation; with a
// spanning tree about 120 bytes a point during the tiles and 330 at the orientation's peak.

#ifndef POINT_SET_CURVATURES_TOOL_TILED_NORMALS_H
#define POINT_SET_CURVATURES_TOOL_TILED_NORMALS_H

#include "command_line.h"
#include "estimated_normals.h"
#include "tiled_run.h"

#include <cstddef>
#include <string>
#include <vector>

namespace psc_tool {

// The bytes a point of the file that the estimated normals take once gathered (3 doubles),
// beside the curvature tiles.
constexpr double gathered_normal_bytes = 24;

// The least memory limit for the normals of `points` points oriented over the whole cloud
// (`global`: a spanning tree): the gathered arrays at the orientation's peak, with a quarter
// more as headroom (the tiles, before, have all but the records and coordinates); 0 otherwise
// (the normals' 24 bytes a point are taken from the tiles' share, down to the smallest tiles).
double least_memory_for_tiled_normals(double points, bool global);

struct Tiled_normals
{
  std::vector<double> normals;     // 3 per point of the file, in input order (zero: none)
  Tiled_report report;             // of the first pass
  double orientation_seconds = 0;  // the spanning tree's
  std::size_t undirected = 0;      // --orient scanner: own points whose pulse has no direction
};

// The normals of every point of `input` (not in memory: Scanned_input::fits false), estimated
// as the options say and oriented as `choice` says (its text completed for --orient auto).
// `tiling` gives the memory limit (the gathered arrays' share is taken from it), the progress
// phases and the interruption. Throws Cancelled when interrupted; `tiling.memory_limit` must be
// at least least_memory_for_tiled_normals().
Tiled_normals estimate_tiled_normals(const std::string& path, const Read_options& read_options,
                                     const Scanned_input& input, const Options& o, Orientation_choice& choice,
                                     Tiling tiling);

}  // namespace psc_tool

#endif
