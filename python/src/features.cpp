// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the algebraic sphere features, the flow and the normal estimation.

#include "features.h"
#include "run.h"

#include <CGAL/apss_smooth_point_set.h>
#include <CGAL/estimate_tangent_voronoi_areas.h>
#include <CGAL/estimate_oriented_normals.h>

namespace psc_py {

namespace {

CGAL::Apss_weight_kernel sphere_kernel(const Options& o)
{
  return o.weight_kernel >= 0 ? CGAL::Apss_weight_kernel(o.weight_kernel) : CGAL::Apss_weight_kernel::SMOOTH;
}

}  // namespace

std::vector<Features> sphere_features(const Cloud& cloud, const Scale& s, const Options& o, const Tile_arg& t,
                                      bool parallel, const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  const CGAL::Sample_weights weights =
    o.sample_weights >= 0 ? CGAL::Sample_weights(o.sample_weights) : CGAL::Sample_weights::UNIFORM;
  const auto np = common_parameters(
    s, o, cb, CGAL::Point_set_curvatures::default_min_neighbors::sphere_features,
    [&](const auto& base) { return P::weight_kernel(sphere_kernel(o), P::sample_weights(weights, base)); });
  return with_given_weights(cloud, o, np, [&](const auto& np2) {
    return dispatch(cloud, s, t, parallel, np2, PSC_PY_FUNCTION(estimate_algebraic_sphere_features));
  });
}

bool tangent_voronoi_areas(Cloud& cloud, const Scale& s, bool accept_unnormalized_normals, bool parallel,
                           const Callback& cb, std::vector<double>& areas)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  areas.assign(cloud.size(), 0.0);
  const auto np = P::sample_weight_map(
    Cloud_weight_map<double>{cloud.data(), areas.data()},
    P::accept_unnormalized_normals(
      accept_unnormalized_normals,
      P::neighbor_count(s.by_count ? s.k : 0, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())
                                                .normal_map(CGAL::Second_of_pair_property_map<Oriented>())
                                                .callback(cb))));
  auto go = [&](auto tag) {
    typedef decltype(tag) Tag;
    return s.by_count ? CGAL::estimate_tangent_voronoi_areas<Tag>(cloud, np)
                      : CGAL::estimate_tangent_voronoi_areas<Tag>(cloud, s.radius, np);
  };
  return parallel ? go(CGAL::Parallel_tag()) : go(CGAL::Sequential_tag());
}

std::vector<std::vector<Features> > multiscale_sphere_features(const Cloud& cloud, const std::vector<double>& radii,
                                                               const Options& o, bool parallel, const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  const Scale by_radius;  // neighbor_count(0): the multi-scale function refuses a count
  const CGAL::Sample_weights weights =
    o.sample_weights >= 0 ? CGAL::Sample_weights(o.sample_weights) : CGAL::Sample_weights::UNIFORM;
  const auto np = common_parameters(
    by_radius, o, cb, CGAL::Point_set_curvatures::default_min_neighbors::sphere_features,
    [&](const auto& base) { return P::weight_kernel(sphere_kernel(o), P::sample_weights(weights, base)); });
  if(parallel)
    return CGAL::estimate_multiscale_algebraic_sphere_features<CGAL::Parallel_tag>(cloud, radii, np);
  return CGAL::estimate_multiscale_algebraic_sphere_features<CGAL::Sequential_tag>(cloud, radii, np);
}

std::vector<CGAL::Curvature_estimate_status> smooth_point_set(Cloud& cloud, double radius, long long iterations,
                                                              bool update_normals, const Options& o, bool parallel,
                                                              const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  // number_of_iterations is read as a signed integer and checked by the function.
  const auto np = P::weight_kernel(
    sphere_kernel(o),
    P::update_normals(update_normals, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())
                                        .normal_map(CGAL::Second_of_pair_property_map<Oriented>())
                                        .callback(cb)
                                        .number_of_iterations(iterations)));
  if(parallel)
    return CGAL::apss_smooth_point_set<CGAL::Parallel_tag>(cloud, radius, np);
  return CGAL::apss_smooth_point_set<CGAL::Sequential_tag>(cloud, radius, np);
}

std::size_t default_normal_neighbors(int fit)
{
  return CGAL::Point_set_curvatures::default_normal_neighbors(CGAL::Normal_fit(fit));
}

namespace {

CGAL::Normal_orientation normal_orientation(int orientation, const double target[3])
{
  if(orientation == 1)
    return CGAL::Normal_orientation::along_vector(target[0], target[1], target[2]);
  if(orientation == 2)
    return CGAL::Normal_orientation::towards_point(target[0], target[1], target[2]);
  if(orientation == 3)
    return CGAL::Normal_orientation::automatic();
  return CGAL::Normal_orientation::minimum_spanning_tree();
}

// The normals' named parameters but the orientation's.
template <class Base>
auto normal_parameters(const Scale& s, int fit, const Base& base)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  return P::normal_fit(fit == 0 ? CGAL::Normal_fit::PLANE : CGAL::Normal_fit::QUADRIC,
                       P::automatic_scale(s.automatic_largest, P::neighbor_count(s.by_count ? s.k : 0, base)));
}

}  // namespace

std::size_t oriented_normals(Cloud& cloud, const Scale& s, int orientation, const double target[3], int fit,
                             bool parallel, const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  const auto np =
    P::normal_orientation(normal_orientation(orientation, target),
                          normal_parameters(s, fit,
                                            CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())
                                              .normal_map(CGAL::Second_of_pair_property_map<Oriented>())
                                              .callback(cb)));
  if(parallel)
    return s.by_count ? CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(cloud, np)
                      : CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(cloud, s.radius, np);
  return s.by_count ? CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(cloud, np)
                    : CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(cloud, s.radius, np);
}

std::vector<Normal_record> normal_records(Cloud& cloud, const Scale& s, int fit, const Tile_arg& t, bool parallel,
                                          const Callback& cb)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  namespace I = CGAL::Point_set_curvatures::internal;
  const auto np = normal_parameters(s, fit,
                                    P::tile(t.has ? t.tile : CGAL::Point_set_curvatures::Tile::whole_space(),
                                            CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())));
  bool cancelled = false;
  std::vector<Normal_record> records =
    parallel ? I::estimate_normal_records<CGAL::Parallel_tag>(cloud, !s.by_count, s.radius, np, cb, cancelled)
             : I::estimate_normal_records<CGAL::Sequential_tag>(cloud, !s.by_count, s.radius, np, cb, cancelled);
  if(cancelled)
    throw Cancelled_error();
  return records;
}

void orient_normal_records(const std::vector<Normal_record>& records, const std::vector<double>& xyz, int orientation,
                           const double target[3], std::vector<double>& normals, const Callback& cb)
{
  if(!CGAL::Point_set_curvatures::internal::orient_normal_records(records, xyz, normal_orientation(orientation, target),
                                                                  normals, cb))
    throw Cancelled_error();
}

}  // namespace psc_py
