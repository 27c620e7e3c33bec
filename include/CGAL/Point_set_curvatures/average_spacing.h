// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The average spacing of a point cloud, as CGAL::compute_average_spacing() defines it, on the
// package's k-nearest traversal: what a radius given in spacings ("3.5x" in the tool) is
// measured in.

#ifndef CGAL_POINT_SET_CURVATURES_AVERAGE_SPACING_H
#define CGAL_POINT_SET_CURVATURES_AVERAGE_SPACING_H

#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {

/// \ingroup PkgPointSetCurvaturesRef
///
/// Computes the average spacing of a point cloud as `CGAL::compute_average_spacing()` of
/// CGAL 5.5 defines it: the mean, over the points with finite coordinates, of the mean
/// distance from a point to its `k + 1` nearest points, itself included (CGAL searches `k + 1`
/// points and divides by `k + 1`), in the unit of the coordinates. It runs on the package's
/// k-nearest traversal, sequentially or in parallel with the same result, and is free of
/// CGAL 5.5's reference to a destroyed temporary of its callback (AddressSanitizer:
/// stack-use-after-scope). Points with non-finite coordinates are nobody's neighbour and are
/// left out of the mean.
///
/// The tool's `--radius Nx` and the user manual's advice ("about 3.5 to 4 times the spacing")
/// use `k = 6`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB); the
///         result does not depend on it.
/// \tparam PointRange a model of `Range`
///
/// \param points input point cloud (normals are not read)
/// \param k the number of neighbours, as for `CGAL::compute_average_spacing()` (6 there)
/// \param np a sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`; for
///       `CGAL::Point_set_3`, its point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called with the fraction of points processed so far (in `[0,1]`)
///       from the calling thread; returning `false` cancels}
///     \cgalParamType{an instance of `std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the average spacing; 0 for a cloud without finite points, or if the callback
///          cancelled the computation.
/// \throws std::invalid_argument if `k` is 0.
template <typename ConcurrencyTag, typename PointRange,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double average_spacing(const PointRange& points, std::size_t k,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Kernel;
  typedef typename std::iterator_traits<typename PointRange::const_iterator>::value_type Key;
  if(k == 0)
    throw std::invalid_argument("average_spacing: k must be at least 1");
  internal::Neighborhood_options options;
  options.function_name = "average_spacing";
  options.callback = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  bool cancelled = false;
  options.callback = internal::noting_cancellation(options.callback, cancelled);
  options.check_normal_length = false;
  const std::size_t searched = k + 1;  // the point itself and its k nearest
  const std::size_t n = static_cast<std::size_t>(std::distance(points.begin(), points.end()));
  std::vector<double> spacing(n, -1.0);
  // (the traversal reads a normal per point: a constant one)
  const CGAL::Constant_property_map<Key, typename Kernel::Vector_3> any_normal(typename Kernel::Vector_3(0, 0, 1));
  internal::for_each_neighborhood_knn<ConcurrencyTag>(
    points, NP_helper::get_const_point_map(points, np), any_normal, searched, options,
    [&spacing, searched](std::size_t i, const internal::Neighborhood& nb) {
      // nb holds the nearest `searched` and any point tied with the last: the smallest distances
      thread_local std::vector<double> d;
      d.clear();
      for(std::size_t j = 0; j < nb.size; ++j)
        d.push_back(std::sqrt(nb.qx[j] * nb.qx[j] + nb.qy[j] * nb.qy[j] + nb.qz[j] * nb.qz[j]) * nb.radius);
      const std::size_t used = std::min(searched, d.size());
      if(used == 0)
        return;
      std::nth_element(d.begin(), d.begin() + (used - 1), d.end());
      double sum = 0;
      for(std::size_t j = 0; j < used; ++j)
        sum += d[j];
      spacing[i] = sum / double(used);
    });
  if(cancelled)
    return 0;
  double sum = 0;
  std::size_t count = 0;
  for(double s : spacing)
    if(s >= 0)
    {
      sum += s;
      ++count;
    }
  return count ? sum / double(count) : 0;
}

}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
