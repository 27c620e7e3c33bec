// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The normals of a cloud without them in the point_set_curvatures tool: the orientation that
// --orient (and what "auto" picks for the input) asks for, their estimation by the package,
// and their turning towards the scanner (--orient scanner).

#ifndef POINT_SET_CURVATURES_TOOL_ESTIMATED_NORMALS_H
#define POINT_SET_CURVATURES_TOOL_ESTIMATED_NORMALS_H

#include "command_line.h"
#include "methods.h"
#include "psc_io/read_point_cloud.h"
#include "psc_io/support.h"

#include <CGAL/Point_set_curvatures/Tile.h>
#include <CGAL/estimate_oriented_normals.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace psc_tool {

// The attributes holding the pulse directions x(t) y(t) z(t) of LAS wave packets (read_las.cpp).
std::array<int, 3> pulse_attributes(const std::vector<Attribute>& attributes);

// Turns each normal towards the origin of its point's pulse: against the pulse's direction
// (x(t), y(t), z(t): from the scanner to the point). Points without a direction (zero or not
// finite) keep the +z orientation; returns the number of those for which `counted(i)` holds.
template <class Normal_of, class Pulse_of, class Counted>
std::size_t orient_towards_scanner(std::size_t n, const Normal_of& normal, const Pulse_of& pulse,
                                   const Counted& counted)
{
  std::size_t without = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3> d = pulse(i);
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if(!(dd > 0) || !std::isfinite(dd))
    {
      without += counted(i) ? 1 : 0;
      continue;
    }
    Vector& v = normal(i);
    if(v.x() * d[0] + v.y() * d[1] + v.z() * d[2] > 0)
      v = -v;
  }
  return without;
}

// How the estimated normals are oriented: --orient, or for "auto" (the default) what suits
// the input (LAS files are airborne or mobile scans, seen from above, unless they hold pulse
// directions), and why, for the summary.
struct Orientation_choice
{
  CGAL::Normal_orientation orientation;
  bool scanner = false;  // then each normal is turned towards its pulse's origin afterwards
  std::string text;      // what the summary says
};

// The orientation for a LAS input (`las`) with or without pulse directions, or another input.
Orientation_choice choose_orientation(const Options& o, bool las, bool has_pulses);

// What a cloud's oriented normals hold, for the summary of --orient auto: the normals (not
// zero), those within 60 degrees of the vertical, those of them pointing up, all pointing up.
struct Vertical_count
{
  std::size_t usable = 0, vertical = 0, vertical_up = 0, up = 0;
  void add(double x, double y, double z);  // (a zero normal is not counted)
};

// What the summary says of an automatic orientation whose normals hold `count`.
std::string automatic_orientation_text(const Vertical_count& count);

// Estimates the normals of the point set as the options say, oriented as `choice` says (its
// text completed for the automatic orientation): of every point, or of the tile's own points
// (the others get a zero normal; the tile needs an orientation along a vector). Returns the
// number of points left without a normal. Throws Cancelled when interrupted,
// CGAL::Point_set_curvatures::Halo_too_small when the tile's halo is too small. With `choices`,
// the automatic scale's passes record there the curvatures' choices (parameters::scale_choices).
std::size_t estimate_normals(Point_set& ps, const Options& o, Orientation_choice& choice, const Progress& progress,
                             const CGAL::Point_set_curvatures::Tile& tile,
                             CGAL::Point_set_curvatures::Scale_choices* choices = nullptr);

// The first step of estimate_normals() alone, for an orientation over the whole cloud gathered
// from tiles (tiled_normals.h): the unoriented normals and nearest neighbours (indices of `ps`)
// of the tile's own points (the others NOT_COMPUTED). Throws Cancelled when interrupted,
// CGAL::Point_set_curvatures::Halo_too_small when the tile's halo is too small.
std::vector<CGAL::Point_set_curvatures::internal::Normal_record>
estimate_normal_records(Point_set& ps, const Options& o, const Progress& progress,
                        const CGAL::Point_set_curvatures::Tile& tile);

}  // namespace psc_tool

#endif
