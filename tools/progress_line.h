// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The text of the tool's progress bar (progress_bar.h draws it on a terminal):
// "curvatures   [##########....................]  34%     6.6 s  ETA 12 s". Header-only and
// free of the rest of the tool, so that test_tool checks the text without a terminal.

#ifndef POINT_SET_CURVATURES_TOOL_PROGRESS_LINE_H
#define POINT_SET_CURVATURES_TOOL_PROGRESS_LINE_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace psc_tool {

// "12 s", "2 min 05 s", "3 h 07 min": a duration for the ETA.
inline std::string eta_text(double seconds)
{
  char text[64];
  const double s = std::max(0.0, std::round(seconds));
  if(s < 60)
    std::snprintf(text, sizeof text, "%.0f s", s);
  else if(s < 3600)
    std::snprintf(text, sizeof text, "%d min %02d s", int(s / 60), int(std::fmod(s, 60.0)));
  else if(s < 1e7)
    std::snprintf(text, sizeof text, "%d h %02d min", int(s / 3600), int(std::fmod(s, 3600.0) / 60));
  else
    std::snprintf(text, sizeof text, "days");
  return text;
}

// The line of a phase `name` that has done `fraction` of its work in `seconds`: a bar, the
// percentage, the elapsed time and, once a fraction of at least 1% is known and a second has
// passed, the estimated time left (the time so far scaled by what remains). The lines of a
// phase have the same width, so that a line drawn over an earlier one (after "\r") leaves
// nothing of it: a step's `label` (the tile a pass over the tiles is at) follows, padded to
// `label_width`, the longest of the phase's so far (the bar then shorter, 20 characters, so
// that "tile 3/9 curvatures" keeps the line within 88 columns).
// `eta`, if not negative, is the time left to show in place of that estimate (once a fraction of
// at least 1% is known and a second has passed).
inline std::string progress_line(const std::string& name, double fraction, double seconds,
                                 const std::string& label = std::string(), std::size_t label_width = 0, double eta = -1)
{
  const double f = std::isfinite(fraction) ? std::max(0.0, std::min(1.0, fraction)) : 0.0;
  const int percent = static_cast<int>(100 * f);
  const int width = label.empty() && label_width == 0 ? 30 : 20;  // (a step: room for it)
  const int filled = percent * width / 100;
  std::string eta_shown;
  if(f >= 0.01 && f < 1 && seconds >= 1)
    eta_shown = "ETA " + eta_text(eta >= 0 ? eta : seconds * (1 - f) / f);
  char text[256];
  std::snprintf(text, sizeof text, "%-12s [%s%s] %3d%% %7.1f s  %-16s", name.c_str(), std::string(filled, '#').c_str(),
                std::string(width - filled, '.').c_str(), percent, std::max(0.0, seconds), eta_shown.c_str());
  std::string line = text;
  if(label_width > 0 || !label.empty())
    line += " " + label + std::string(label_width > label.size() ? label_width - label.size() : 0, ' ');
  return line;
}

}  // namespace psc_tool

#endif
