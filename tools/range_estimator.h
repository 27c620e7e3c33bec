// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's one estimation step, the same for every run: the estimates of a range of points,
// which is the whole cloud in memory (one tile covering all of space,
// CGAL::Point_set_curvatures::Tile::whole_space()) or one tile of a file larger than the
// memory limit with its halo (tiled_run.h). When the cloud in memory has no normals, they are
// estimated first (estimated_normals.h; turned towards the scanner for --orient scanner); a
// tile always has its normals: the file's, or those estimated in a first pass over the tiles
// (tiled_normals.h). Then the curvatures with the chosen method (methods.h).

#ifndef POINT_SET_CURVATURES_TOOL_RANGE_ESTIMATOR_H
#define POINT_SET_CURVATURES_TOOL_RANGE_ESTIMATOR_H

#include "command_line.h"
#include "estimated_normals.h"
#include "methods.h"
#include "run_summary.h"
#include "psc_io/support.h"

#include <CGAL/Point_set_curvatures/Tile.h>

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace psc_tool {

// The pulse directions x(t) y(t) z(t) of a range's points (--orient scanner), one value per
// point each; null unless the file has no normals and they are turned towards the scanner.
typedef std::array<const std::vector<double>*, 3> Pulse_values;

class Range_estimator
{
public:
  // `with_normals`: the points have normals (none are estimated; a tile must have them).
  Range_estimator(const Options& o, const Estimation_settings& scale, Orientation_choice& orientation,
                  bool with_normals);

  // The estimates of the points of `ps` (all of them, the tile's own points otherwise; the
  // normals of `ps` are set when estimated). `phase(name)` starts the progress phase of
  // "normals" or "curvatures" and returns its callback. Throws
  // CGAL::Point_set_curvatures::Halo_too_small when the range must be read with a larger
  // halo (the halo to ask for), Cancelled when interrupted, Error when the normals' options
  // are refused.
  Estimates estimate(Point_set& ps, const CGAL::Point_set_curvatures::Tile& tile, const Pulse_values& pulses,
                     const std::function<Progress(const char*)>& phase);

  // Points that got a normal but whose pulse has no direction (their normal keeps the +z
  // orientation); seconds spent on the normals.
  std::size_t undirected() const { return m_undirected; }
  double normals_seconds() const { return m_normals_seconds; }

private:
  const Options& m_o;
  Estimation_settings m_scale;
  // the curvatures' choices that the normals' automatic scale makes over the whole cloud
  CGAL::Point_set_curvatures::Scale_choices m_choices;
  Orientation_choice& m_orientation;
  const bool m_with_normals;
  std::size_t m_undirected = 0;
  double m_normals_seconds = 0;
};

// The warnings on the estimated normals, once every point is estimated (`summary`): that they
// were estimated and how they are oriented, the points that got none, the points whose pulse
// has no direction. Nothing when the file has normals.
void add_normal_warnings(std::vector<std::string>& warnings, const Options& o, bool with_normals,
                         const Orientation_choice& orientation, const Row_summary& summary, std::size_t undirected);

}  // namespace psc_tool

#endif
