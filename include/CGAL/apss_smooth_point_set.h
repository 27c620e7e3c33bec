// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_APSS_SMOOTH_POINT_SET_H
#define CGAL_APSS_SMOOTH_POINT_SET_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere_features.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_algebraic_sphere_features.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// One step of the bilaplacian flow at one point (Section 4.5): the displacement onto the
// sphere fitted around it (Equation 20 at the evaluation point, in input units) and the
// sphere's unit normal there. Returns the status of the fit.
template <class WeightKernel>
Curvature_estimate_status apss_flow_step(const Neighborhood& nb, double displacement[3], double normal[3])
{
  Algebraic_sphere_sums<WeightKernel> sums;
  sums.add(nb);
  if(sums.count < apss_min_neighbors)
    return Curvature_estimate_status::TOO_FEW_NEIGHBORS;
  const Algebraic_sphere sphere = fit_algebraic_sphere(sums);
  if(!sphere.valid)
    return Curvature_estimate_status::DEGENERATE_FIT;
  const double origin[3] = {0, 0, 0};
  double step[3];
  if(!project_on_sphere(sphere, origin, step, normal))
    return Curvature_estimate_status::DEGENERATE_FIT;
  for(int a = 0; a < 3; ++a)
    displacement[a] = nb.radius * step[a];
  return Curvature_estimate_status::VALID;
}

template <class T>
bool is_negative(T x)
{
  if constexpr(std::is_signed<T>::value)
    return x < 0;
  else
    return false;
}

template <class Map>
constexpr bool is_writable_map()
{
  return std::is_convertible<typename boost::property_traits<Map>::category, boost::writable_property_map_tag>::value;
}

// The visitor of one iteration of apss_smooth_point_set(): per point, the status of the step
// and, where valid, the moved point with its new normal (`update_normals`) or its old one.
// A named type, so that the traversal is compiled once whatever the named parameters.
struct Apss_flow_visitor
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::pair<K::Point_3, K::Vector_3> Oriented;
  Apss_weight_kernel kernel;
  bool update_normals;
  const std::vector<Oriented>* state;
  std::vector<Oriented>* next;
  std::vector<Curvature_estimate_status>* fit_status;

  void operator()(std::size_t i, const Neighborhood& nb) const
  {
    double d[3], normal[3];
    (*fit_status)[i] = with_weight_kernel(kernel, [&](auto k) { return apss_flow_step<decltype(k)>(nb, d, normal); });
    if((*fit_status)[i] == Curvature_estimate_status::VALID)
      (*next)[i] = Oriented(K::Point_3(nb.center[0] + d[0], nb.center[1] + d[1], nb.center[2] + d[2]),
                            update_normals ? K::Vector_3(normal[0], normal[1], normal[2]) : (*state)[i].second);
  }
};

}  // namespace internal
}  // namespace Point_set_curvatures

/// \ingroup PkgPointSetCurvaturesRef
///
/// Smooths an oriented point cloud with the bilaplacian flow of the algebraic sphere fit
/// (Lejemble et al. 2021, Section 4.5, Proposition 3), in the style of
/// `CGAL::jet_smooth_point_set()`: at each iteration every point is moved onto the APSS
/// algebraic sphere fitted to its neighbours at distance `< radius` (Equation 20, the plane
/// case included), all points being updated from the same previous state. One step moves a
/// point by `-u_c` along the normal (`u_c` of `CGAL::Algebraic_sphere_features`), that is
/// `-(19H³ - 11KH - 2ΔH) r⁴ / 640` with the smooth kernel and `-(9H³ - 5KH - ΔH) r⁴ / 96` with
/// the constant one, a term in the bilaplacian of the surface: iterating it rounds the shape
/// (spheres are fixed) without the shrinking of the mean curvature flow of plane (PCA)
/// projections. On noisy clouds the first iterations remove most of the noise.
///
/// Normals: by default the input normals are used by every iteration and left untouched: the
/// points move to the surface that best agrees with them (denoising of positions with trusted
/// normals). With `update_normals(true)` each iteration fits with the normals of the previous
/// iteration's spheres at the moved points, and the last ones are written through the normal
/// map: positions and normals evolve together, the geometric flow of the paper's Figure 3,
/// which rounds shapes over tens of iterations while keeping their size.
///
/// Points that cannot be fitted at an iteration (fewer than 3 neighbours, degenerate fit) stay
/// where they are for that iteration; points with non-finite coordinates or a zero normal are
/// never moved and are nobody's neighbour.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB); the
///         result does not depend on it.
/// \tparam PointRange a model of `Range` whose iterator value type is the key type of the
///         point and normal maps
///
/// \param points the oriented point cloud, modified in place through the point map
/// \param radius radius `r` of the neighbourhoods and of the weight kernel, in the unit of the
///        coordinates
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of `points`}
///     \cgalParamType{a model of `ReadWritePropertyMap` whose value type is `geom_traits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`; for
///       `CGAL::Point_set_3`, its point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{a property map associating oriented normals to the elements of
///       `points` (required, except for `CGAL::Point_set_3`); writable with `update_normals(true)`}
///     \cgalParamType{a model of `ReadablePropertyMap` (`ReadWritePropertyMap` to update the
///       normals) whose value type is `geom_traits::Vector_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{number of flow iterations}
///     \cgalParamType{unsigned int}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::update_normals}
///     \cgalParamDescription{if `true`, every iteration replaces the normals by those of the
///       fitted spheres at the moved points (unit, oriented like the input normals), the next
///       iteration fits with them, and the last ones are written through the normal map;
///       if `false`, the input normals are used throughout and not modified}
///     \cgalParamType{bool}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{Point_set_curvatures::parameters::weight_kernel}
///     \cgalParamDescription{the weight kernel of the fits}
///     \cgalParamType{`CGAL::Apss_weight_kernel`}
///     \cgalParamDefault{`CGAL::Apss_weight_kernel::SMOOTH`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel` with a floating-point `FT`}
///     \cgalParamDefault{the kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called from the calling thread with the fraction of the work done
///       (in `[0,1]`, over all iterations); if it returns `false` the flow stops: the points
///       already processed in the current iteration are moved, the others are left unchanged}
///     \cgalParamType{an instance of `std::function<bool(double)>`}
///     \cgalParamDefault{no callback}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns, per element of `points`, the status of its last iteration: `VALID` (moved),
///          `TOO_FEW_NEIGHBORS` or `DEGENERATE_FIT` (left in place), `NON_FINITE_POINT` or
///          `INVALID_NORMAL` (never moved), `NOT_COMPUTED` (not reached before cancellation,
///          or no iteration asked for).
/// \throws std::invalid_argument if `radius` is not positive and finite, or if
///         `update_normals(true)` is given with a normal map that is not writable.
template <typename ConcurrencyTag, typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Curvature_estimate_status> apss_smooth_point_set(PointRange& points, double radius,
                                                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace PSC = Point_set_curvatures;
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits Geom_traits;
  typedef typename NP_helper::Point_map Point_map;
  typedef typename NP_helper::Normal_map Normal_map;
  typedef typename Geom_traits::FT FT;
  static_assert(NP_helper::has_normal_map(),
                "Error: no normal map. Pass CGAL::parameters::normal_map(...): the algebraic "
                "sphere fit needs oriented normals.");
  const char* name = "apss_smooth_point_set";
  PSC::internal::check_radius(radius, name);
  const auto asked_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1u);
  if(PSC::internal::is_negative(asked_iterations))
    throw std::invalid_argument(std::string(name) + ": parameter 'number_of_iterations' must be non-negative");
  const std::size_t iterations = static_cast<std::size_t>(asked_iterations);
  const bool update_normals = choose_parameter(get_parameter(np, PSC::internal_np::update_normals), false);
  const Apss_weight_kernel kernel = PSC::internal::weight_kernel_parameter(np);
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  constexpr bool normals_writable = PSC::internal::is_writable_map<Normal_map>();
  if(update_normals && !normals_writable)
    throw std::invalid_argument(std::string(name) + ": parameter 'update_normals' needs a writable normal map");

  Point_map point_map = NP_helper::get_point_map(points, np);
  Normal_map normal_map = NP_helper::get_normal_map(points, np);

  // The state of the flow, in double precision and input order.
  typedef PSC::internal::Apss_flow_visitor::K K;
  typedef PSC::internal::Apss_flow_visitor::Oriented Oriented;
  std::vector<Oriented> state;
  for(auto it = points.begin(); it != points.end(); ++it)
  {
    const auto& p = get(point_map, *it);
    const auto& v = get(normal_map, *it);
    state.emplace_back(K::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())),
                       K::Vector_3(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())));
  }
  const std::size_t n = state.size();
  std::vector<Curvature_estimate_status> status(n, Curvature_estimate_status::NOT_COMPUTED);
  if(n == 0 || iterations == 0)
    return status;

  std::vector<Oriented> next(state);
  std::vector<Curvature_estimate_status> fit_status(n);
  bool cancelled = false;
  for(std::size_t iteration = 0; iteration < iterations && !cancelled; ++iteration)
  {
    PSC::internal::Neighborhood_options options;
    options.function_name = name;
    if(callback)
      options.callback = [&callback, &cancelled, iteration, iterations](double done) {
        const bool go_on = callback((double(iteration) + done) / double(iterations));
        cancelled = cancelled || !go_on;
        return go_on;
      };
    const PSC::internal::Apss_flow_visitor visit{kernel, update_normals, &state, &next, &fit_status};
    const std::vector<Curvature_estimate_status> visited = PSC::internal::for_each_neighborhood<ConcurrencyTag>(
      state, CGAL::First_of_pair_property_map<Oriented>(), CGAL::Second_of_pair_property_map<Oriented>(), radius,
      options, visit);
    for(std::size_t i = 0; i < n; ++i)
    {
      status[i] = visited[i] == Curvature_estimate_status::VALID ? fit_status[i] : visited[i];
      if(status[i] == Curvature_estimate_status::VALID)
        state[i] = next[i];
    }
  }

  std::size_t i = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++i)
  {
    if(status[i] == Curvature_estimate_status::NON_FINITE_POINT ||
       status[i] == Curvature_estimate_status::INVALID_NORMAL)
      continue;
    const K::Point_3& p = state[i].first;
    put(point_map, *it, typename Geom_traits::Point_3(FT(p.x()), FT(p.y()), FT(p.z())));
    if constexpr(normals_writable)
      if(update_normals)
      {
        const K::Vector_3& v = state[i].second;
        put(normal_map, *it, typename Geom_traits::Vector_3(FT(v.x()), FT(v.y()), FT(v.z())));
      }
  }
  return status;
}

}  // namespace CGAL

#endif
