// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the unsigned baselines, distance to the barycenter and to the PCA plane.

#include "common.h"

#include <CGAL/estimate_barycenter_curvatures.h>
#include <CGAL/estimate_pca_plane_curvatures.h>

namespace psc_py {

std::vector<Estimate> estimate_simple(const std::string& method, const Cloud& cloud, const Scale& s, const Options& o,
                                      const Tile_arg& t, bool parallel, const Callback& cb)
{
  namespace D = CGAL::Point_set_curvatures::default_min_neighbors;
  const auto same = [](const auto& base) { return base; };
  if(method == "barycenter")
    return dispatch(cloud, s, t, parallel, common_parameters(s, o, cb, D::barycenter, same),
                    PSC_PY_FUNCTION(estimate_barycenter_curvatures));
  return dispatch(cloud, s, t, parallel, common_parameters(s, o, cb, D::pca_plane, same),
                  PSC_PY_FUNCTION(estimate_pca_plane_curvatures));
}

}  // namespace psc_py
