// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Named parameters of the package that CGAL's closed list (CGAL::parameters) does not have.
// They live in CGAL::Point_set_curvatures::parameters and chain with CGAL's own ones by
// taking them as last argument:
//
//   namespace PSC = CGAL::Point_set_curvatures;
//   auto np = PSC::parameters::aso_projection(CGAL::Aso_projection::AUTHORS_IMPLEMENTATION,
//               CGAL::parameters::point_map(pm).normal_map(nm));

#ifndef CGAL_POINT_SET_CURVATURES_PARAMETERS_H
#define CGAL_POINT_SET_CURVATURES_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
/// Tangent plane on which the Algebraic Shape Operator is projected (Equation 27 of
/// Lejemble et al. 2021 leaves it implicit).
enum class Aso_projection
{
  /// The plane orthogonal to `grad f`, the corrected normal that is returned: `W` is the
  /// shape operator of the level set of the fitted field, directions are exactly tangent.
  /// Default.
  CORRECTED_NORMAL,
  /// As in the authors' implementation (STORM-IRIT/algebraic-shape-operator): the plane
  /// orthogonal to the linear coefficient `u_l`, the tensor `Hess f/|grad f| - N N^T Hess f`,
  /// input normals used without normalisation. Reproduces their values to about 1e-12;
  /// directions are then orthogonal to `u_l`, not exactly to the returned normal.
  AUTHORS_IMPLEMENTATION
};

namespace Point_set_curvatures {
namespace internal_np {

enum aso_projection_t { aso_projection };
enum neighbor_count_t { neighbor_count };

} // namespace internal_np

namespace parameters {

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter selecting the tangent plane of `estimate_aso_curvatures()` (default
/// `CGAL::Aso_projection::CORRECTED_NORMAL`). Chains with CGAL named parameters passed as
/// `np`.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<Aso_projection, internal_np::aso_projection_t, NamedParameters>
aso_projection(Aso_projection projection,
               const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<Aso_projection, internal_np::aso_projection_t,
                                         NamedParameters>(projection, np);
}

/// \ingroup PkgPointSetCurvaturesRef
/// Named parameter selecting neighbourhoods by count: each point's kernel radius is the
/// distance to its `k`-th nearest neighbour (the point itself counted as the first), so
/// that the scale follows the sampling density (LiDAR). Use it with the overloads of the
/// estimation functions that take no radius.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Named_function_parameters<std::size_t, internal_np::neighbor_count_t, NamedParameters>
neighbor_count(std::size_t k, const NamedParameters& np = CGAL::parameters::default_values())
{
  return CGAL::Named_function_parameters<std::size_t, internal_np::neighbor_count_t,
                                         NamedParameters>(k, np);
}

} // namespace parameters
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
