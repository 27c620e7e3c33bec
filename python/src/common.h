// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: what the translation units of the module share. Every option of the C++
// API is a runtime value here; each estimation function is instantiated once per concurrency
// tag and per "tile or not", with every named parameter always passed: the defaults the C++
// functions would choose are passed explicitly, which gives the same results bit for bit (the
// parameters are only read through choose_parameter; the ASO's four variant options go as one
// aso_options value, and vcm_offset_radius is handled in its own file).

#ifndef PSC_PYTHON_COMMON_H
#define PSC_PYTHON_COMMON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/Tile.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace psc_py {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::pair<K::Point_3, K::Vector_3> Oriented;
typedef std::vector<Oriented> Cloud;
typedef CGAL::Curvature_estimate<K> Estimate;
typedef std::function<bool(double)> Callback;

// Every option of the estimators, as plain values; -1 means "the function's default".
struct Options
{
  long long min_neighbors = -1;
  bool accept_unnormalized_normals = false;
  // ASO (and partly APSS / sphere features)
  int aso_variant = 1;          // CGAL::Aso_variant: 0 PAPER, 1 ROBUST
  int weight_kernel = -1;       // CGAL::Apss_weight_kernel: 0 SMOOTH, 1 CONSTANT, 2 CUBIC, 3 QUARTIC
  int sample_weights = -1;      // CGAL::Sample_weights: 0 UNIFORM, 1 TANGENT_VORONOI_AREA
  int robust_orientation = -1;  // 0 / 1
  int normal_field_blend = -1;  // 0 / 1
  long long normal_refinement = 0;
  double position_fit_blend = 0;  // [0, 1]
  int aso_projection = 0;         // CGAL::Aso_projection: 0 CORRECTED_NORMAL, 1 AUTHORS_IMPLEMENTATION
  // jets
  long long degree_fitting = 2;
  long long degree_monge = 2;
  // VCM (NaN: the C++ default, the radius or the median radius by count)
  double vcm_offset_radius = std::numeric_limits<double>::quiet_NaN();
  // Sample weights given per point (ASO, APSS, sphere features: sample_weight_map), in cloud
  // order, or null (set by the module from the sample_weights array; not an attribute).
  const std::vector<double>* given_weights = nullptr;
};

// Per-point weights of a cloud through a property map on its elements: an element's index is
// its position in the cloud (the functions are called on the cloud itself, never on a copy).
// Readable (const double: given weights) or also writable (double: the areas computed).
template <class Value>
struct Cloud_weight_map
{
  typedef Oriented key_type;
  typedef double value_type;
  typedef double reference;
  typedef std::conditional_t<std::is_const<Value>::value, boost::readable_property_map_tag,
                             boost::read_write_property_map_tag>
    category;
  const Oriented* base = nullptr;
  Value* weights = nullptr;

  friend double get(const Cloud_weight_map& m, const Oriented& p) { return m.weights[&p - m.base]; }
  // defined only where used: never for const double
  friend void put(const Cloud_weight_map& m, const Oriented& p, double v) { m.weights[&p - m.base] = v; }
};

// `f(np)`, or with the given weights `f(sample_weight_map(their map, np))`.
template <class NP, class F>
auto with_given_weights(const Cloud& cloud, const Options& o, const NP& np, const F& f)
{
  if(o.given_weights)
    return f(CGAL::Point_set_curvatures::parameters::sample_weight_map(
      Cloud_weight_map<const double>{cloud.data(), o.given_weights->data()}, np));
  return f(np);
}

// The scale: a radius, or a neighbour count.
struct Scale
{
  bool by_count = false;
  double radius = 0;
  std::size_t k = 0;
  std::size_t automatic_largest = 0;  // neighbors="auto": the ladder k, 2 k, ... up to this
};

// An optional tile.
struct Tile_arg
{
  bool has = false;
  CGAL::Point_set_curvatures::Tile tile;
};

// What every curvature TU exports: the estimates of `method` (one of its methods).
std::vector<Estimate> estimate_aso(const Cloud&, const Scale&, const Options&, const Tile_arg&, bool parallel,
                                   const Callback&);
std::vector<Estimate> estimate_apss(const Cloud&, const Scale&, const Options&, const Tile_arg&, bool parallel,
                                    const Callback&);
std::vector<Estimate> estimate_simple(const std::string& method, const Cloud&, const Scale&, const Options&,
                                      const Tile_arg&, bool parallel, const Callback&);
std::vector<Estimate> estimate_pss_wavejet(const std::string& method, const Cloud&, const Scale&, const Options&,
                                           const Tile_arg&, bool parallel, const Callback&);
std::vector<Estimate> estimate_jet(const Cloud&, const Scale&, const Options&, const Tile_arg&, bool parallel,
                                   const Callback&);
std::vector<Estimate> estimate_vcm(const Cloud&, const Scale&, const Options&, const Tile_arg&, bool parallel,
                                   const Callback&);
// CGAL::estimate_tangent_voronoi_areas (in features.cpp): per point, 0 for unusable points;
// false if the callback cancelled.
bool tangent_voronoi_areas(Cloud&, const Scale&, bool accept_unnormalized_normals, bool parallel, const Callback&,
                           std::vector<double>& areas);

// The named parameters shared by every estimator: maps, callback, neighbour count (0 with
// a radius), accept_unnormalized_normals and min_neighbors (the estimator's default if
// not given), on top of `extra(base)` (the estimator's own options).
template <class Extra>
auto common_parameters(const Scale& s, const Options& o, const Callback& cb, std::size_t default_min,
                       const Extra& extra)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  const auto base = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())
                      .normal_map(CGAL::Second_of_pair_property_map<Oriented>())
                      .callback(cb);
  return P::min_neighbors(o.min_neighbors < 0 ? default_min : static_cast<std::size_t>(o.min_neighbors),
                          P::accept_unnormalized_normals(o.accept_unnormalized_normals,
                                                         P::neighbor_count(s.by_count ? s.k : 0, extra(base))));
}

// Calls `f(tag, cloud, [radius,] np)` with the concurrency tag and the tile (if any) chosen at
// run time: 4 instantiations of the estimation function.
template <class NP, class F>
auto dispatch(const Cloud& cloud, const Scale& s, const Tile_arg& t, bool parallel, const NP& np, const F& f)
{
  namespace P = CGAL::Point_set_curvatures::parameters;
  auto go = [&](auto tag, const auto& np2) { return s.by_count ? f(tag, cloud, np2) : f(tag, cloud, s.radius, np2); };
  if(parallel)
    return t.has ? go(CGAL::Parallel_tag(), P::tile(t.tile, np)) : go(CGAL::Parallel_tag(), np);
  return t.has ? go(CGAL::Sequential_tag(), P::tile(t.tile, np)) : go(CGAL::Sequential_tag(), np);
}

}  // namespace psc_py

// An estimation function as a generic callable: f(tag, cloud, radius, np) or f(tag, cloud, np).
#define PSC_PY_FUNCTION(name)                                                                                          \
  [](auto tag, const ::psc_py::Cloud& c, const auto&... args) { return CGAL::name<decltype(tag)>(c, args...); }

#endif
