// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the Algebraic Shape Operator (its own translation unit: the heaviest).

#include "common.h"

#include <CGAL/estimate_aso_curvatures.h>

namespace psc_py {

std::vector<Estimate> estimate_aso(const Cloud& cloud, const Scale& s, const Options& o, const Tile_arg& t,
                                   bool parallel, const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  const CGAL::Aso_variant variant = o.aso_variant == 0 ? CGAL::Aso_variant::PAPER : CGAL::Aso_variant::ROBUST;
  // The library's preset of the variant, with the options given replaced: one value.
  CGAL::Point_set_curvatures::Aso_variant_options options = CGAL::Point_set_curvatures::aso_variant_options(variant);
  if(o.weight_kernel >= 0)
    options.weight_kernel = CGAL::Apss_weight_kernel(o.weight_kernel);
  if(o.sample_weights >= 0)
    options.sample_weights = CGAL::Sample_weights(o.sample_weights);
  if(o.robust_orientation >= 0)
    options.robust_orientation = o.robust_orientation != 0;
  if(o.normal_field_blend >= 0)
    options.normal_field_blend = o.normal_field_blend != 0;
  const auto np =
    common_parameters(s, o, cb, CGAL::Point_set_curvatures::default_min_neighbors::aso, [&](const auto& base) {
      return P::aso_variant(
        variant, P::aso_options(
                   options, P::normal_refinement(static_cast<std::size_t>(o.normal_refinement),
                                                 P::position_fit_blend(
                                                   o.position_fit_blend,
                                                   P::aso_projection(CGAL::Aso_projection(o.aso_projection),
                                                                     P::automatic_scale(s.automatic_largest, base))))));
    });
  return with_given_weights(cloud, o, np, [&](const auto& np2) {
    return dispatch(cloud, s, t, parallel, np2, PSC_PY_FUNCTION(estimate_aso_curvatures));
  });
}

}  // namespace psc_py
