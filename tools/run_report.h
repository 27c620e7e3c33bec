// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's report of a run, the same for runs in memory and in tiles: the summary on
// standard output (method, scale, points, valid share, neighbours, times, H and K), the
// warnings on standard error once the output is written, and the messages that explain small
// neighbourhoods and runs without a valid estimate, with the scale to try.

#ifndef POINT_SET_CURVATURES_TOOL_RUN_REPORT_H
#define POINT_SET_CURVATURES_TOOL_RUN_REPORT_H

#include "command_line.h"
#include "methods.h"
#include "progress_bar.h"
#include "run_summary.h"
#include "psc_io/support.h"

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace psc_tool {

// What the writing and the report share between in-memory and tiled runs.
struct Run_context
{
  const Options& o;
  Progress_bar& progress;
  std::vector<std::string>& warnings;
  std::chrono::steady_clock::time_point start;
};

// "1.234": seconds in the report.
std::string s3(double seconds);

// "automatic scale: 40 to 640 nearest neighbours, ...": the scale, for the summary and the
// output's header.
std::string scale_description(const Estimation_settings& s);

// "aso (robust variant)": the method and its options, for the summary and the output's header.
std::string method_label(const Options& o, const Estimation_settings& scale);

// The report on standard output, and the warnings (after the output is written, so that a
// failure prints one line only). Throws No_valid_estimate, after them, when no point got a
// valid estimate (exit status 3). `estimated_normals`: how the normals were estimated (empty
// when the file has them); `times`: the phases' seconds; `tiles`: the tiles' line (empty in
// memory).
void print_report(const Run_context& c, const Estimation_settings& scale, std::size_t n,
                  const std::string& estimated_normals, const Row_summary& summary, const std::string& times,
                  const std::string& tiles);

}  // namespace psc_tool

#endif
