// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See estimated_normals.h.

#include "estimated_normals.h"

#include "interruption.h"

#include <CGAL/Point_set_curvatures/parameters.h>

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;

std::array<int, 3> pulse_attributes(const std::vector<Attribute>& attributes)
{
  std::array<int, 3> found = {{-1, -1, -1}};
  for(std::size_t j = 0; j < attributes.size(); ++j)
    for(int a = 0; a < 3; ++a)
      if(attributes[j].name == std::string("wave_") + "xyz"[a] + "_t")
        found[a] = int(j);
  return found;
}

Orientation_choice choose_orientation(const Options& o, bool las, bool has_pulses)
{
  Orientation_choice c;
  c.orientation = o.orientation;
  c.scanner = o.orient_scanner;
  if(o.orientation_text != "auto")
  {
    c.text = cat(o.orientation_text, " (--orient)");
    return c;
  }
  if(las && has_pulses)
  {
    c.orientation = CGAL::Normal_orientation::along_vector(0, 0, 1);
    c.scanner = true;
    c.text = "towards the scanner (LAS pulse directions; --orient auto)";
  }
  else if(las)
    c.orientation = CGAL::Normal_orientation::automatic();  // text once the normals are known
  else
  {
    c.orientation = CGAL::Normal_orientation::minimum_spanning_tree();
    c.text = "mst: along a minimum spanning tree, closed parts outward, open parts up (--orient auto)";
  }
  return c;
}

std::size_t estimate_normals(Point_set& ps, const Options& o, Orientation_choice& choice, const Progress& progress,
                             const PSC::Tile& tile)
{
  if(!ps.has_normal_map())
    ps.add_normal_map();
  const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    ps, PSC::parameters::neighbor_count(
          normal_neighbor_count(o),
          PSC::parameters::automatic_scale(
            normal_automatic_largest(o),
            PSC::parameters::normal_fit(
              o.normal_fit, PSC::parameters::normal_orientation(
                              choice.orientation,
                              PSC::parameters::tile(tile, CGAL::parameters::callback(progress)))))));
  if(interrupted)
    throw Cancelled();
  if(choice.orientation.kind == CGAL::Normal_orientation::AUTOMATIC)
  {
    // what the estimated normals hold (measured, not what the rule meant to do; the output holds
    // the estimators' corrected normals, which may turn a few: the report states those apart)
    std::size_t usable = 0, vertical = 0, vertical_up = 0, up = 0;
    for(Point_set::Index i : ps)
    {
      const Vector& n = ps.normal(i);
      if(n == CGAL::NULL_VECTOR)
        continue;
      ++usable;
      up += n.z() > 0 ? 1 : 0;
      if(PSC::is_near_vertical(n.x(), n.y(), n.z()))
      {
        ++vertical;
        vertical_up += n.z() > 0 ? 1 : 0;
      }
    }
    const std::string within =
      cat(percent_text(vertical, usable), "% of the estimated normals within 60 degrees of the vertical");
    if(usable == 0)
      choice.text = "none: no normal could be estimated (--orient auto)";
    else if(PSC::is_two_and_a_half_d(vertical, usable))
      choice.text = cat("+z (LAS file, 2.5-D: ", within, "; ", percent_text(vertical_up, vertical), "% of those point up",
                        vertical_up < vertical ? ", the others are the undersides of closed objects, turned outward"
                                               : "",
                        "; the steeper ones along a minimum spanning tree; --orient auto)");
    else
      choice.text = cat("mst (LAS file, not 2.5-D: ", within, "): along a minimum spanning tree, closed parts "
                        "outward, open parts up; ", percent_text(up, usable), "% of them point up; --orient auto)");
  }
  return without;
}

} // namespace psc_tool
