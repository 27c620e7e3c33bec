// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the APSS sphere fit.

#include "common.h"

#include <CGAL/estimate_apss_curvatures.h>

namespace psc_py {

std::vector<Estimate> estimate_apss(const Cloud& cloud, const Scale& s, const Options& o, const Tile_arg& t,
                                    bool parallel, const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  const CGAL::Apss_weight_kernel kernel =
    o.weight_kernel >= 0 ? CGAL::Apss_weight_kernel(o.weight_kernel) : CGAL::Apss_weight_kernel::SMOOTH;
  const CGAL::Sample_weights weights =
    o.sample_weights >= 0 ? CGAL::Sample_weights(o.sample_weights) : CGAL::Sample_weights::UNIFORM;
  const bool robust = o.robust_orientation > 0;
  const auto np =
    common_parameters(s, o, cb, CGAL::Point_set_curvatures::default_min_neighbors::apss, [&](const auto& base) {
      return P::weight_kernel(kernel, P::sample_weights(weights, P::robust_orientation(robust, base)));
    });
  return with_given_weights(cloud, o, np, [&](const auto& np2) {
    return dispatch(cloud, s, t, parallel, np2, PSC_PY_FUNCTION(estimate_apss_curvatures));
  });
}

}  // namespace psc_py
