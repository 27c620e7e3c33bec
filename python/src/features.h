// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the algebraic sphere features, the flow and the normal estimation
// (implemented in features.cpp).

#ifndef PSC_PYTHON_FEATURES_H
#define PSC_PYTHON_FEATURES_H

#include "common.h"

#include <CGAL/estimate_algebraic_sphere_features.h>
#include <CGAL/estimate_oriented_normals.h>

namespace psc_py {

typedef CGAL::Algebraic_sphere_features<K> Features;

std::vector<Features> sphere_features(const Cloud&, const Scale&, const Options&, const Tile_arg&, bool parallel,
                                      const Callback&);
std::vector<std::vector<Features> > multiscale_sphere_features(const Cloud&, const std::vector<double>& radii,
                                                               const Options&, bool parallel, const Callback&);
// The flow moves the points (and the normals with update_normals) of `cloud` in place.
std::vector<CGAL::Curvature_estimate_status> smooth_point_set(Cloud& cloud, double radius, long long iterations,
                                                              bool update_normals, const Options&, bool parallel,
                                                              const Callback&);
// Writes the normals into cloud[i].second; orientation: 0 spanning tree, 1 along, 2 towards,
// 3 automatic; fit: 0 plane, 1 quadric (CGAL::Normal_fit).
std::size_t oriented_normals(Cloud& cloud, const Scale&, int orientation, const double target[3], int fit,
                             bool parallel, const Callback&);
// The two steps of oriented_normals() apart, for a cloud estimated in tiles (the Dask file
// route): the unoriented normal and 12 nearest neighbours of every point (of the tile's own
// points with a tile: the others NOT_COMPUTED), then their orientation over the records of the
// whole cloud, `xyz` 3 coordinates a record, into `normals` (3 a record, zero where a record
// is not VALID). Both are CGAL::estimate_oriented_normals()'s, bitwise.
typedef CGAL::Point_set_curvatures::internal::Normal_record Normal_record;
std::vector<Normal_record> normal_records(Cloud& cloud, const Scale&, int fit, const Tile_arg&, bool parallel,
                                          const Callback&);
void orient_normal_records(const std::vector<Normal_record>& records, const std::vector<double>& xyz, int orientation,
                           const double target[3], std::vector<double>& normals, const Callback&);
// CGAL::Point_set_curvatures::default_normal_neighbors() of a fit (0 plane, 1 quadric).
std::size_t default_normal_neighbors(int fit);

}  // namespace psc_py

#endif
