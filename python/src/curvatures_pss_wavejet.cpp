// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: Point Set Surfaces and order-2 wavejets.

#include "common.h"

#include <CGAL/estimate_pss_curvatures.h>
#include <CGAL/estimate_wavejet_curvatures.h>

namespace psc_py {

std::vector<Estimate> estimate_pss_wavejet(const std::string& method, const Cloud& cloud, const Scale& s,
                                           const Options& o, const Tile_arg& t, bool parallel, const Callback& cb)
{
  namespace D = CGAL::Point_set_curvatures::default_min_neighbors;
  const auto same = [](const auto& base) { return base; };
  if(method == "pss")
    return dispatch(cloud, s, t, parallel, common_parameters(s, o, cb, D::pss, same),
                    PSC_PY_FUNCTION(estimate_pss_curvatures));
  return dispatch(cloud, s, t, parallel, common_parameters(s, o, cb, D::wavejet, same),
                  PSC_PY_FUNCTION(estimate_wavejet_curvatures));
}

}  // namespace psc_py
