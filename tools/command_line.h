// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The command line of the point_set_curvatures tool: its options, their checks (an Error,
// exit status 2, for anything invalid) and the --help text.

#ifndef POINT_SET_CURVATURES_TOOL_COMMAND_LINE_H
#define POINT_SET_CURVATURES_TOOL_COMMAND_LINE_H

#include "methods.h"

#include <CGAL/estimate_oriented_normals.h>

#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace psc_tool {

inline constexpr const char* program = "point_set_curvatures";

// Quantities that --color can show: their index q in Row_summary (summary_quantities).
const std::map<std::string, int>& color_quantities();

// The settings of one run, from the command line (see print_usage()).
struct Options
{
  std::string input, output;
  const Method* method = nullptr;
  Estimation_settings scale;
  bool radius_given = false, neighbors_given = false;
  int threads = 0;  // 0: every core
  bool quiet = false, ascii = false, require_normals = false, help = false;
  bool float32 = false, drop_attributes = false;  // --float, --drop-attributes
  bool ply_scalar_names = false;                  // --ply-names scalar (CloudCompare's scalar_NAME)
  bool allow_truncated = false;                   // --allow-truncated
  std::vector<std::string> fields;                // --fields, empty: all
  std::string color;                              // quantity to colour by, empty for none
  std::vector<std::string> columns;               // --columns, empty: automatic
  // --orient; "auto" is resolved once the input is known (resolve_orientation())
  CGAL::Normal_orientation orientation = CGAL::Normal_orientation::automatic();
  std::string orientation_text = "auto";
  bool orient_scanner = false;                              // --orient scanner
  CGAL::Normal_fit normal_fit = CGAL::Normal_fit::QUADRIC;  // --normal-fit
  std::size_t normal_neighbors = 0;                         // --normal-neighbors; 0: the fit's default (40, plane 18)
  double position_blend = -1;  // --position-blend; < 0: 0.5 if the normals are estimated, else 0
  double memory_limit = 0;     // --memory-limit in bytes; 0: a quarter of the RAM
};

// --neighbors auto: the library's ladder of counts of the automatic scale (curvatures and,
// with the quadric fit, normals).
inline constexpr std::size_t automatic_smallest = CGAL::Point_set_curvatures::automatic_scale_ladder::smallest;
inline constexpr std::size_t automatic_largest = CGAL::Point_set_curvatures::automatic_scale_ladder::largest;

// The neighbour count of the normal estimation: --normal-neighbors, else the fit's default.
std::size_t normal_neighbor_count(const Options& o);

// The largest count of the normals' automatic scale (--neighbors auto with the quadric fit),
// else 0; and the largest neighbourhood a normal reads.
std::size_t normal_automatic_largest(const Options& o);
std::size_t normal_largest_count(const Options& o);

// "quadric fit of the 40 nearest neighbours": how the normals are estimated.
std::string normal_fit_description(const Options& o);

// The --help text.
void print_usage(std::ostream& os);

// The options of the command line; throws Error for anything invalid.
Options parse_command_line(int argc, char** argv);

}  // namespace psc_tool

#endif
