// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's writers: binary or ASCII PLY, or CSV with a header line, one row per input
// point in input order. The rows come from a callback, so this file knows nothing of the
// estimators.

#ifndef POINT_SET_CURVATURES_TOOL_WRITE_POINT_CLOUD_H
#define POINT_SET_CURVATURES_TOOL_WRITE_POINT_CLOUD_H

#include "tool_support.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace psc_tool {

// The 16 doubles of a row, in order: x y z nx ny nz k_min k_max mean gaussian dmin_x dmin_y
// dmin_z dmax_x dmax_y dmax_z; then neighbors (int), valid (uchar) and, with colours, red green
// blue (uchar).
extern const char* const output_field_names[16];

struct Output_row
{
  double value[16];
  std::int32_t neighbors = 0;
  unsigned char valid = 0;
  unsigned char color[3] = {0, 0, 0};
};

struct Output_layout
{
  enum Format { BINARY_PLY, ASCII_PLY, CSV } format = BINARY_PLY;
  bool color = false;                 // write red green blue
  std::vector<std::string> comments;  // PLY header comments
};

// Writes `n` rows, row(i, r) filling row i. Progress: the fraction of rows written, about
// every 1%; false cancels (Cancelled). Write errors are left to the caller (ferror).
void write_point_cloud(std::FILE* f, const Output_layout& layout, std::size_t n,
                       const std::function<void(std::size_t, Output_row&)>& row, const Progress& progress);

} // namespace psc_tool

#endif
