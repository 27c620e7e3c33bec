// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Neighbourhoods by count: each point's kernel radius is the distance to its k-th nearest
// neighbour (itself counted), then the same visitor contract as for_each_neighborhood().

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_KNN_NEIGHBORHOODS_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_KNN_NEIGHBORHOODS_H

#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>

#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Same contract as for_each_neighborhood(), with a per-point radius: the distance from each
// usable point to its k-th nearest usable point (itself counted as the first).
template <class ConcurrencyTag, class PointRange, class PointMap, class NormalMap, class Visitor>
std::vector<Curvature_estimate_status>
for_each_neighborhood_knn(const PointRange& /* points */, PointMap /* point_map */,
                          NormalMap /* normal_map */, std::size_t /* k */,
                          const Neighborhood_options& options, Visitor /* visit */)
{
  throw std::logic_error(std::string(options.function_name) +
                         ": neighbourhoods by count are not implemented yet");
}

} // namespace internal
} // namespace Point_set_curvatures
} // namespace CGAL

#endif
