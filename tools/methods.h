// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The estimators the point_set_curvatures tool can run: one entry per estimate_*_curvatures()
// function of the package (CGAL::Point_set_curvatures::estimators), with its run function; `Estimation_settings`
// carries the neighbourhood size and the options every method reads. The curvature
// estimators are instantiated in methods.cpp alone: the rest of the tool only sees this table.

#ifndef POINT_SET_CURVATURES_TOOL_METHODS_H
#define POINT_SET_CURVATURES_TOOL_METHODS_H

#include "psc_io/support.h"

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_curvatures/Tile.h>
#include <CGAL/Point_set_curvatures/estimators.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <cstddef>
#include <string>
#include <vector>

namespace psc_tool {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef Kernel::Vector_3 Vector;
typedef CGAL::Point_set_3<Point, Vector> Point_set;

// A point set of the given points and normals (none if `normals` is empty).
inline void fill_point_set(Point_set& ps, const std::vector<double>& xyz, const std::vector<double>& normals)
{
  const std::size_t n = xyz.size() / 3;
  ps.resize(n);  // (every point at once: insert() one by one was a fifth of the read phase)
  if(!normals.empty())
    ps.add_normal_map();
  for(std::size_t i = 0; i < n; ++i)
  {
    const Point_set::Index k = *(ps.begin() + i);
    const double* p = &xyz[3 * i];
    ps.point(k) = Point(p[0], p[1], p[2]);
    if(!normals.empty())
    {
      const double* nv = &normals[3 * i];
      ps.normal(k) = Vector(nv[0], nv[1], nv[2]);
    }
  }
}

typedef CGAL::Curvature_estimate<Kernel> Estimate;
typedef std::vector<Estimate> Estimates;

// The scale of the neighbourhoods and the options every method reads.
struct Estimation_settings
{
  bool by_count = true;
  std::size_t neighbors = CGAL::Point_set_curvatures::front_end_defaults::neighbor_count;  // by count
  double radius = 0;                                      // by radius, in the unit of the coordinates
  double spacing_multiple = 0;                            // > 0 for "--radius Nx"
  double spacing = 0;                                     // CGAL::compute_average_spacing, for "--radius Nx"
  std::size_t min_neighbors = 0;                          // --min-neighbors; 0: the method's default
  CGAL::Aso_variant variant = CGAL::Aso_variant::ROBUST;  // --variant (aso)
  double position_fit_blend = 0;                          // --position-blend (aso)
  // --neighbors auto (aso): the automatic scale's largest count, `neighbors` its smallest; 0: off
  std::size_t automatic_largest = 0;
  // with it, the choices that the normals' passes made for the curvatures (null: none)
  CGAL::Point_set_curvatures::Scale_choices* choices = nullptr;
  // the largest neighbourhood a point's estimate reads, by count
  std::size_t largest_count() const { return automatic_largest > 0 ? automatic_largest : neighbors; }
};

// Every point is estimated with PSC::Tile::whole_space(), a tile's own points otherwise.
typedef Estimates (*Run_method)(const Point_set&, const Estimation_settings&, const Progress&,
                                const CGAL::Point_set_curvatures::Tile&);

// A method: the library's description of its estimator (name, summary, fields, neighbour
// counts, options) and the function that runs it.
struct Method : CGAL::Point_set_curvatures::Estimator_description
{
  Run_method run;
};

// Every method of the package, in the order of CGAL::Point_set_curvatures::estimators.
const std::vector<Method>& methods();

// The method named `name`, null if there is none.
const Method* find_method(const std::string& name);

// "aso|apss|...": the names of every method.
std::string method_names();

}  // namespace psc_tool

#endif
