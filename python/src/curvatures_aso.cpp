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
  // The options not given take the library's preset of the variant (passed explicitly: the
  // named parameters are types, one call serves every combination).
  const CGAL::Point_set_curvatures::Aso_variant_options preset = CGAL::Point_set_curvatures::aso_variant_options(variant);
  const CGAL::Apss_weight_kernel kernel =
    o.weight_kernel >= 0 ? CGAL::Apss_weight_kernel(o.weight_kernel) : preset.weight_kernel;
  const CGAL::Sample_weights weights =
    o.sample_weights >= 0 ? CGAL::Sample_weights(o.sample_weights) : preset.sample_weights;
  const bool robust = o.robust_orientation >= 0 ? o.robust_orientation != 0 : preset.robust_orientation;
  const bool blend = o.normal_field_blend >= 0 ? o.normal_field_blend != 0 : preset.normal_field_blend;
  const auto np = common_parameters(s, o, cb, CGAL::Point_set_curvatures::default_min_neighbors::aso,
    [&](const auto& base) {
      return P::aso_variant(variant,
             P::weight_kernel(kernel,
             P::sample_weights(weights,
             P::robust_orientation(robust,
             P::normal_field_blend(blend,
             P::normal_refinement(static_cast<std::size_t>(o.normal_refinement),
             P::position_fit_blend(o.position_fit_blend,
             P::aso_projection(CGAL::Aso_projection(o.aso_projection),
             P::automatic_scale(s.automatic_largest, base)))))))));
    });
  return with_given_weights(cloud, o, np, [&](const auto& np2) {
    return dispatch(cloud, s, t, parallel, np2, PSC_PY_FUNCTION(estimate_aso_curvatures));
  });
}

} // namespace psc_py
