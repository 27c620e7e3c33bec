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
    c.text = "mst: along a minimum spanning tree, closed parts outward, open parts up, parts seen from all sides "
             "checked point by point by the parity of the crossings along the normals (--orient auto)";
  }
  return c;
}

namespace {

// The named parameters of the normals' estimation as the options say, oriented by `orientation`.
template <class Callback>
auto normal_parameters(const Options& o, const CGAL::Normal_orientation& orientation, const PSC::Tile& tile,
                       const Callback& progress, PSC::Scale_choices* choices = nullptr)
{
  return PSC::parameters::neighbor_count(
    normal_neighbor_count(o),
    PSC::parameters::automatic_scale(
      normal_automatic_largest(o),
      PSC::parameters::normal_fit(
        o.normal_fit, PSC::parameters::normal_orientation(
                        orientation, PSC::parameters::tile(tile, PSC::parameters::scale_choices(
                                                                   choices, CGAL::parameters::callback(progress)))))));
}

}  // namespace

void Vertical_count::add(double x, double y, double z)
{
  if(x == 0 && y == 0 && z == 0)
    return;
  ++usable;
  up += z > 0 ? 1 : 0;
  if(PSC::is_near_vertical(x, y, z))
  {
    ++vertical;
    vertical_up += z > 0 ? 1 : 0;
  }
}

std::string automatic_orientation_text(const Vertical_count& c)
{
  const std::string within =
    cat(percent_text(c.vertical, c.usable), "% of the estimated normals within 60 degrees of the vertical");
  if(c.usable == 0)
    return "none: no normal could be estimated (--orient auto)";
  if(PSC::is_two_and_a_half_d(c.vertical, c.usable))
    return cat("+z (LAS file, 2.5-D: ", within, "; ", percent_text(c.vertical_up, c.vertical), "% of those point up",
               c.vertical_up < c.vertical ? ", the others are the undersides of closed objects, turned outward" : "",
               "; the steeper ones along a minimum spanning tree; --orient auto)");
  return cat("mst (LAS file, not 2.5-D: ", within,
             "): along a minimum spanning tree, closed parts "
             "outward, open parts up, parts seen from all sides checked point by point by the parity of the "
             "crossings along the normals; ",
             percent_text(c.up, c.usable), "% of them point up; --orient auto)");
}

std::size_t estimate_normals(Point_set& ps, const Options& o, Orientation_choice& choice, const Progress& progress,
                             const PSC::Tile& tile, PSC::Scale_choices* choices)
{
  if(!ps.has_normal_map())
    ps.add_normal_map();
  const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    ps, normal_parameters(o, choice.orientation, tile, progress, choices));
  if(interrupted)
    throw Cancelled();
  if(choice.orientation.kind == CGAL::Normal_orientation::AUTOMATIC)
  {
    // what the estimated normals hold (measured, not what the rule meant to do; the output holds
    // the estimators' corrected normals, which may turn a few: the report states those apart)
    Vertical_count count;
    for(Point_set::Index i : ps)
      count.add(ps.normal(i).x(), ps.normal(i).y(), ps.normal(i).z());
    choice.text = automatic_orientation_text(count);
  }
  return without;
}

std::vector<PSC::internal::Normal_record> estimate_normal_records(Point_set& ps, const Options& o,
                                                                  const Progress& progress, const PSC::Tile& tile)
{
  bool cancelled = false;
  std::vector<PSC::internal::Normal_record> records = PSC::internal::estimate_normal_records<CGAL::Parallel_tag>(
    ps, false, 0.0, normal_parameters(o, CGAL::Normal_orientation::along_vector(0, 0, 1), tile, progress), progress,
    cancelled);
  if(cancelled || interrupted)
    throw Cancelled();
  return records;
}

}  // namespace psc_tool
