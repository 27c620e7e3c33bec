// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's readers: one validating pass over the file, no third-party reader. A file is
// either read completely and exactly as its header or columns say, or refused with an Error
// whose message names the file, the line or element, and what is wrong; nothing is read
// from a count in a header before it is checked against the bytes the file holds.
//
//   .xyz .pwn .txt .csv   one point per line, values separated by white space or by commas;
//                         '#' comments; an optional point count alone on the first line; an
//                         optional header line of column names (x y z nx ny nz, normal_x...).
//                         Without names or --columns: 3 values (x y z) or 6 (x y z nx ny nz),
//                         the latter refused when its last three columns are not unit vectors
//                         (colours, say), with a message naming --columns.
//   .ply                  ASCII and binary (both endiannesses), any property order and scalar
//                         type, other elements and properties skipped; normals named nx ny nz
//                         or normal_x normal_y normal_z.
//   .off                  OFF or NOFF (normals), faces checked and ignored.

#ifndef POINT_SET_CURVATURES_TOOL_READ_POINT_CLOUD_H
#define POINT_SET_CURVATURES_TOOL_READ_POINT_CLOUD_H

#include "tool_support.h"

#include <cstddef>
#include <string>
#include <vector>

namespace psc_tool {

struct Point_cloud
{
  std::vector<double> xyz;      // 3 per point, in file order
  std::vector<double> normals;  // 3 per point, or empty when the file has none
  std::string normals_source;   // where the normals came from, for messages

  std::size_t size() const { return xyz.size() / 3; }
  bool has_normals() const { return !normals.empty(); }
};

struct Read_options
{
  // --columns: one name per value of a text line: x, y, z, nx, ny, nz (or normal_x, ...),
  // anything else (for example _ or r) for a value that is skipped. Empty: automatic.
  std::vector<std::string> columns;
  // Called with the fraction of the file read, about every 1%; false cancels (Cancelled).
  Progress progress;
};

// The formats read_point_cloud() understands, for messages: ".xyz, .pwn, .txt, .csv, .ply or .off".
const char* readable_formats();

// Parses a --columns value ("x,y,z,_,_,_,nx,ny,nz"); throws Error if it lacks x, y or z,
// names a coordinate twice, or names only some of nx, ny, nz.
std::vector<std::string> parse_columns(const std::string& text);

// Reads `path` (a regular file) by its extension. Throws Error for anything malformed,
// Cancelled if the progress callback returned false.
Point_cloud read_point_cloud(const std::string& path, const Read_options& options);

} // namespace psc_tool

#endif
