// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: CGAL's osculating jets and Voronoi covariance measure.

#include "common.h"

#include <CGAL/estimate_jet_curvatures.h>
#include <CGAL/estimate_vcm_curvatures.h>

#include <cmath>
#include <stdexcept>

namespace psc_py {

std::vector<Estimate> estimate_jet(const Cloud& cloud, const Scale& s, const Options& o, const Tile_arg& t,
                                   bool parallel, const Callback& cb)
{
  namespace D = CGAL::Point_set_curvatures::default_min_neighbors;
  // CGAL's degree parameters are read as integers and checked by the function itself.
  const auto np = common_parameters(s, o, cb, D::jet, [&](const auto& base) {
    return base.degree_fitting(static_cast<int>(o.degree_fitting)).degree_monge(static_cast<int>(o.degree_monge));
  });
  return dispatch(cloud, s, t, parallel, np, PSC_PY_FUNCTION(estimate_jet_curvatures));
}

std::vector<Estimate> estimate_vcm(const Cloud& cloud, const Scale& s, const Options& o, const Tile_arg& t,
                                   bool parallel, const Callback& cb)
{
  namespace D = CGAL::Point_set_curvatures::default_min_neighbors;
  namespace P = CGAL::Point_set_curvatures::parameters;
  if(t.has)
    throw std::invalid_argument("estimate_vcm_curvatures: parameter 'tile' is not supported (VCM has no fixed halo)");
  const Tile_arg no_tile;
  const auto f = PSC_PY_FUNCTION(estimate_vcm_curvatures);
  if(std::isnan(o.vcm_offset_radius))  // the C++ default (the radius, or the median radius by count)
    return dispatch(cloud, s, no_tile, parallel,
                    common_parameters(s, o, cb, D::vcm, [](const auto& base) { return base; }), f);
  return dispatch(cloud, s, no_tile, parallel,
                  common_parameters(s, o, cb, D::vcm,
                                    [&](const auto& base) { return P::vcm_offset_radius(o.vcm_offset_radius, base); }),
                  f);
}

}  // namespace psc_py
