// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's output, the same for runs in memory and in tiles: each point's row from its
// estimate, the output's layout (format, columns, header comments, colours of --color), its
// size reserved before the estimation, and its writing (write_point_cloud.h, write_las.h)
// under a temporary name renamed once complete (output_file.h).

#ifndef POINT_SET_CURVATURES_TOOL_RUN_OUTPUT_H
#define POINT_SET_CURVATURES_TOOL_RUN_OUTPUT_H

#include "command_line.h"
#include "methods.h"
#include "output_file.h"
#include "psc_io/read_point_cloud.h"
#include "run_report.h"
#include "run_summary.h"
#include "tiled_run.h"
#include "psc_io/write_las.h"
#include "psc_io/write_point_cloud.h"

#include <cstddef>
#include <vector>

namespace psc_tool {

// Row i of the output from the point set and its estimates (without colour).
void estimate_row(const Point_set& ps, const Estimates& estimates, std::size_t i, Output_row& r);

// Reserves the output's size before the estimation (Temporary_output::reserve): the layout of
// write_output() with the scale and colour range still unknown (a margin for the header
// comments that hold them). A LAS output (`las` not null) has its size from write_las.h.
void reserve_output(const Options& o, Temporary_output& output, const std::vector<Attribute>& attributes, std::size_t n,
                    const Las_output_options* las);

// Writes the n rows of `rows` (asked for in input order), coloured from the summary; a LAS
// output when `las` is not null.
void write_output(const Run_context& c, Temporary_output& output, const Estimation_settings& scale,
                  const std::vector<Attribute>& attributes, std::size_t n, const Row_summary& summary,
                  const Row_source& rows, const Las_output_options* las);

}  // namespace psc_tool

#endif
