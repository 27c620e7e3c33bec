// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic scale's estimates (the rule that chooses a rung: automatic_scale.h).
//
// The estimate is the wrapped estimator's on the chosen rung's neighbourhood. Where a
// rung above the first is chosen (noise dominates, or the rungs below lay along one line), the
// mean curvature is that of the APSS sphere on the same neighbourhood (a fit of the sphere, 2
// to 4 times more robust to position noise than estimators that differentiate a tensor) if it
// lies within kappa standard errors of the rung's quadric (strongly anisotropic shapes bias
// the sphere at large scales) and within automatic_scale_sphere_agreement standard errors of
// the wrapped estimator's (where the two disagree by more, one is biased, and on the simulated
// scans it was the sphere: over airborne scan lines under noise they differ by 9 standard errors
// at the median and the sphere's error is 2.5 times the ASO's; on terrestrial scans, where the
// sphere is the better one, by about one) unless the wrapped estimator's is poorly told (its
// normal_coherence below automatic_scale_sphere_coherence, or the standard error times the
// radius above automatic_scale_sphere_told: a real ground point among vegetation), and the
// anisotropic part (k_max - k_min, the directions) is the wrapped estimator's. Where the rule
// climbed for noise, the sphere is not taken and the wrapped estimator's H lies more than
// automatic_scale_quadric_agreement standard errors from the quadric's, the curvatures are the
// quadric's (its H, its shape operator in the estimate's tangent plane; the normal stays the
// estimator's): there the estimator's H is far from what the positions say (the first and last
// profiles of a scan, where the neighbourhood is one-sided and estimated normals bend). Where
// the rule climbed because noise dominates (Scale_choice::noise_climb), the wrapped estimator
// is the caller's `at_noise_scale` (for the ASO: without the position fit, whose bias at those
// scales exceeds what it saves, and with the quartic kernel in place of the cubic one: the rule
// tolerates a bias of about one standard error, which the narrower kernel reduces). Where the
// rule kept a rung without noise and its neighbours spread evenly around the point
// (spreads_evenly(), in the plane of the rung's reference normal), the wrapped
// estimator is the caller's `where_even` if it gives one (for the ASO: the quartic kernel too,
// where the kernel is the robust variant's cubic; without noise the narrower kernel's lesser
// bias is all gain, but where scan lines lie far apart for the neighbourhood it sees fewer of
// them); not where the first rung could not be fitted (Scale_choice::as_first_rung). kappa, the noise share,
// the sphere's rule and those choices were made on the simulated scans of
// benchmark/scan_experiments (benchmark/README.md, "Automatic scale" and "Scans without
// normals").
//
// The passes. Every point on the smallest rung with the first pass's test, then the points it sends
// on over the rungs of a neighbourhood automatic_scale_pass_growth times larger, and so on
// (automatic_scale_passes()). The normals' second pass, which fits the same rungs of the same
// neighbourhoods, can also choose the curvatures' rung at each point it climbs for
// (curvature_scale_record(), with the normals' fits); the curvatures then estimate those points
// from one search of that count (Known_scale_estimator), the same estimate bit for bit since a
// rung is the driver's neighbourhood of its count (automatic_scale.h).

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_ESTIMATION_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_ESTIMATION_H

#include <CGAL/Point_set_curvatures/internal/automatic_scale.h>
#include <CGAL/Point_set_curvatures/internal/automatic_scale_progress.h>
#include <CGAL/Point_set_curvatures/internal/estimate_at_every_point.h>
#include <CGAL/Point_set_curvatures/internal/normal_field_fit.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The curvatures' choice of scale at one point, made by a pass of the normals' automatic scale
// over the same neighbourhood (curvature_scale_record()), so that the curvatures' passes estimate
// the point at its chosen count directly: a neighbourhood search of that count instead of the
// ladder's passes (Known_scale_estimator). The fields of Scale_choice that the estimate reads;
// `mean` and `reference` with the side of `anchor`.
struct Curvature_scale_record
{
  enum Flags : std::uint8_t { FOUND = 1, AS_FIRST_RUNG = 2, NOISE_CLIMB = 4, REFERENCE_IS_START = 8 };
  double radius = 0, mean = 0, mean_error = 0;
  double reference[3] = {0, 0, 0}, anchor[3] = {0, 0, 0};
  std::uint32_t count = 0;  // the neighbour count of the chosen rung (0: no record)
  std::uint32_t size = 0;   // its neighbourhood's size
  std::uint8_t rung = 0, flags = 0;
};

// The curvatures' choice (Scale_ladder::Statistic::MEAN_CURVATURE) on `whole`, the neighbourhood
// of the pass after the first one of the same ladder, `pass` (the normals' ladder of that pass,
// whose smallest and largest counts the curvatures' share): the first pass's test on the smallest
// rung (its neighbourhood is bit for bit the first pass's), then, where that sends the point on,
// the rule on the rungs of `pass`; the fits are those the normals' rule left in `scratch.cache`
// where it made them. A record with count 0 where the choice is not made in this pass (the top
// rung of a pass that is not the last one) or no rung can be fitted.
inline Curvature_scale_record curvature_scale_record(const Scale_ladder& pass, const Neighborhood& whole,
                                                     Ladder_scratch& scratch)
{
  typedef Curvature_scale_record Record;
  Scale_ladder ladder = pass;
  ladder.statistic = Scale_ladder::Statistic::MEAN_CURVATURE;
  ladder.sent_on = nullptr;
  ladder.record_only = true;
  Scale_ladder first = ladder;
  first.largest = first.smallest;
  first.gate = true;
  first.final_pass = false;
  Scale_choice c = first.choose(whole, scratch);
  Record r;
  if(c.climb)
  {
    ladder.gate = false;
    c = ladder.choose(whole, scratch);
    if(ladder.climbs(c))
      return r;
  }
  if(!c.found && !c.as_first_rung)
    return r;
  r.count = static_cast<std::uint32_t>(c.k);
  r.size = static_cast<std::uint32_t>(c.count);
  r.radius = c.radius;
  r.mean = c.mean;
  r.mean_error = c.mean_error;
  std::copy(c.reference, c.reference + 3, r.reference);
  std::copy(c.anchor, c.anchor + 3, r.anchor);
  r.rung = static_cast<std::uint8_t>(c.rung);
  r.flags = static_cast<std::uint8_t>((c.found ? Record::FOUND : 0) | (c.as_first_rung ? Record::AS_FIRST_RUNG : 0) |
                                      (c.noise_climb ? Record::NOISE_CLIMB : 0) |
                                      (c.reference_is_start ? Record::REFERENCE_IS_START : 0));
  return r;
}

// The records of curvature_scale_record() for a range and the ladder's counts they were made with:
// point i's is records[slot[i]] (no_slot: none), the points of the pass that makes them in input
// order (most points of a clean cloud never climb: 4 bytes each).
struct Curvature_scale_records
{
  static constexpr std::uint32_t no_slot = std::numeric_limits<std::uint32_t>::max();
  std::size_t smallest = 0, largest = 0;
  std::vector<std::uint32_t> slot;
  std::vector<Curvature_scale_record> records;

  bool fit(const Scale_ladder& ladder, std::size_t points) const
  {
    return smallest == ladder.smallest && largest == ladder.largest && slot.size() == points;
  }
  // A slot for each point of `visit` (the pass's mask), the others none.
  void assign_slots(const std::vector<char>& visit)
  {
    slot.assign(visit.size(), no_slot);
    std::uint32_t next = 0;
    for(std::size_t i = 0; i < visit.size(); ++i)
      if(visit[i])
        slot[i] = next++;
    records.assign(next, Curvature_scale_record());
  }
  // Point i's record, or null.
  const Curvature_scale_record* of(std::size_t i) const
  {
    return i < slot.size() && slot[i] != no_slot ? &records[slot[i]] : nullptr;
  }
  Curvature_scale_record* of(std::size_t i)
  {
    return i < slot.size() && slot[i] != no_slot ? &records[slot[i]] : nullptr;
  }
};

// The estimators the automatic scale applies on the chosen rung: `estimator` by default;
// `at_noise_scale` where the rule climbed for noise (Scale_choice::noise_climb); `where_even`,
// if `narrower_where_even`, where the rule kept a rung without noise and the neighbourhood
// spreads evenly around the point (spreads_evenly()).
template <class Estimator>
struct Scale_estimators
{
  Estimator estimator, at_noise_scale, where_even;
  bool narrower_where_even = false;
};

// Whether a neighbourhood spreads evenly around its query, for Scale_estimators::where_even:
// the axis ratio of its tangential spread (tangential_axis_ratio(), with the weights of the
// quartic kernel that where_even takes for the ASO) at least normal_field_anisotropy_start, the
// ratio below which the ASO starts blending in the normal-field fit (normal_field_fit.h). Where
// scan lines lie far apart for the neighbourhood the narrower kernel sees fewer of them and the
// ASO's derivatives follow the weights more (simulated lines 10:1, 8:1: 3.08e-3 -> 3.79e-3,
// 1.98e-3 -> 2.13e-3 with the quartic everywhere; with this test 3.07e-3 and 1.95e-3:
// benchmark/README.md, section 8).
inline bool spreads_evenly(const Neighborhood& nb)
{
  return tangential_axis_ratio<4>(nb) >= normal_field_anisotropy_start;
}

// The principal curvatures and directions of the plain quadric of positions (the rungs' fit,
// without its anisotropy penalty) on `nb`, its shape operator taken in the tangent plane of
// e.normal, into `e` (its normal kept); `e` unchanged where the quadric cannot be fitted.
inline void set_quadric_curvatures(const Neighborhood& nb, Local_estimate& e)
{
  Quadric_fit fit;
  fit.anisotropy_penalty = 0;
  double t1[3], t2[3], W[3];
  tangent_basis(e.normal, t1, t2);
  if(!fit.compute(nb) || !fit.shape_operator_in(e.normal, t1, t2, 1.0 / nb.radius, W))
    return;
  Local_estimate q = e;
  set_principal_curvatures(W[0], W[1], W[2], t1, t2, q);
  if(std::isfinite(q.k_min) && std::isfinite(q.k_max))
    e = q;
}

// The automatic scale around an estimator (see the header comment), with the estimators of
// Scale_estimators.
template <class Estimator, class Sphere>
struct Automatic_scale_estimator : Estimator_base
{
  Scale_estimators<Estimator> estimators;
  Sphere sphere;
  Scale_ladder ladder;

  Automatic_scale_estimator(const Scale_estimators<Estimator>& e, const Sphere& s, const Scale_ladder& l)
      : Estimator_base(e.estimator), estimators(e), sphere(s), ladder(l)
  {}

  Local_estimate operator()(const Neighborhood& nb) const
  {
    thread_local Ladder_scratch scratch;
    const Scale_choice c = ladder.choose(nb, scratch);
    if(!c.found && !c.as_first_rung)
      return Local_estimate::invalid(Curvature_estimate_status::DEGENERATE_FIT);
    if(ladder.climbs(c))
    {
      ladder.count_sent_on();
      // to be replaced by the next pass's estimate (or NOT_COMPUTED if it is cancelled)
      Local_estimate provisional;
      provisional.status = Curvature_estimate_status::VALID;
      provisional.neighbor_count = c.count;
      return provisional;
    }
    return at_choice(c, scratch.chosen.nb);
  }

  // The estimate at the rung `c` chose (found or as_first_rung), whose neighbourhood is `chosen`.
  Local_estimate at_choice(const Scale_choice& c, const Neighborhood& chosen) const
  {
    if(c.as_first_rung)
    {
      Local_estimate e = estimators.estimator(chosen);
      e.neighbor_count = c.count;
      return e;
    }
    Local_estimate e = c.noise_climb                                              ? estimators.at_noise_scale(chosen)
                       : estimators.narrower_where_even && spreads_evenly(chosen) ? estimators.where_even(chosen)
                                                                                  : estimators.estimator(chosen);
    if(e.status == Curvature_estimate_status::VALID && c.rung > 0)
    {
      // the sphere's mean curvature where it agrees with the chosen rung's quadric and, where the
      // wrapped estimator's is well told, with it (elsewhere the sphere is biased: strongly
      // anisotropic shapes at large scales, scan lines under noise); the quadric's H turned to
      // the side of the estimate's normal (the quadric is oriented by the point's normal, the
      // sphere and the ASO by their neighbours')
      const double* up = chosen.query_normal;
      const double along = up[0] * e.normal[0] + up[1] * e.normal[1] + up[2] * e.normal[2];
      const double quadric_mean = along < 0 ? -c.mean : c.mean;
      double mean = e.mean;
      const Local_estimate s = sphere(chosen);
      const bool told = c.mean_error * c.radius <= automatic_scale_sphere_told &&
                        e.normal_coherence >= automatic_scale_sphere_coherence;  // (NaN: not told)
      if(s.status == Curvature_estimate_status::VALID && std::isfinite(s.mean) &&
         std::abs(s.mean - quadric_mean) <= automatic_scale_kappa * c.mean_error &&
         (!told || std::abs(s.mean - mean) <= automatic_scale_sphere_agreement * c.mean_error))
        mean = s.mean;
      else if(c.noise_climb && std::abs(e.mean - quadric_mean) > automatic_scale_quadric_agreement * c.mean_error)
      {
        // the wrapped estimator's H is far from what the positions say (at a scan's first and
        // last profiles): the quadric's curvatures. (A NaN standard error keeps the estimator's;
        // one of 0 comes from a rung the quadric fits exactly, whose H is then exact.)
        mean = quadric_mean;
        set_quadric_curvatures(chosen, e);
      }
      const double half = 0.5 * (e.k_max - e.k_min);
      e.mean = mean;
      e.k_min = mean - half;
      e.k_max = mean + half;
      e.gaussian = e.k_min * e.k_max;
    }
    e.neighbor_count = c.count;
    e.mean_error = c.mean_error;
    return e;
  }
};

// The estimate of Automatic_scale_estimator at a point whose choice its record holds
// (curvature_scale_record()), from the neighbourhood of the record's count: the chosen rung's
// neighbourhood, bit for bit, where its size and radius are the record's; elsewhere (a point
// that the normals' cloud held and this one does not: an unusable normal) an estimate with
// status NOT_COMPUTED, for the ladder's passes to make. The record's side is turned to that of
// the point's normal: the ladder's first rung kept is oriented like it (orient_like()).
template <class Estimator, class Sphere>
struct Known_scale_estimator : Estimator_base
{
  const Automatic_scale_estimator<Estimator, Sphere>* automatic;
  const Curvature_scale_records* records;

  Known_scale_estimator(const Automatic_scale_estimator<Estimator, Sphere>& a, const Curvature_scale_records& r)
      : Estimator_base(a), automatic(&a), records(&r)
  {}

  Local_estimate operator()(const Neighborhood& nb) const
  {
    typedef Curvature_scale_record Record;
    const Record& r = *records->of(nb.query_index);  // (the pass visits the points with one)
    if(nb.size != r.size || nb.radius != r.radius)
      return Local_estimate::invalid(Curvature_estimate_status::NOT_COMPUTED);
    Scale_choice c;
    c.found = (r.flags & Record::FOUND) != 0;
    c.as_first_rung = (r.flags & Record::AS_FIRST_RUNG) != 0;
    c.noise_climb = (r.flags & Record::NOISE_CLIMB) != 0;
    c.rung = r.rung;
    c.count = r.size;
    c.k = r.count;
    c.radius = r.radius;
    c.mean_error = r.mean_error;
    double side[3];
    orient_like(r.anchor, nb.query_normal, side);
    const double s = side[0] == r.anchor[0] && side[1] == r.anchor[1] && side[2] == r.anchor[2] ? 1.0 : -1.0;
    c.mean = s * r.mean;
    Neighborhood chosen = nb;
    if(!(r.flags & Record::REFERENCE_IS_START))
      for(int a = 0; a < 3; ++a)
        chosen.query_normal[a] = s * r.reference[a];
    return automatic->at_choice(c, chosen);
  }
};

// The largest count of the pass after one whose largest count is `previous`, on `ladder`.
inline std::size_t next_pass_largest(const Scale_ladder& ladder, std::size_t previous)
{
  return std::min(ladder.largest, automatic_scale_pass_growth * previous);
}

// The passes of the automatic scale: every point on the ladder's first rung with the test of
// Scale_ladder::gate (the neighbourhood of k); then the points it sends on, on the rungs k, 2 k,
// ..., 16 k (the neighbourhood of 16 k, automatic_scale_pass_growth k, or of `largest` if smaller);
// then, with the neighbourhood of 256 k, ... (each automatic_scale_pass_growth times the previous
// one) up to `largest` in turn, only the points whose previous pass kept its top rung (the rule
// looks at the rungs from the bottom up and stops at the first that disagrees, so a point that
// stopped below the top rung of its pass has its choice on the whole ladder). Smooth surfaces
// without noise stop at the first pass. A point's result does not depend on the pass that computed
// it being shared with other points (the tiles, the concurrency). `run(ladder, visit, progress,
// cancelled)` evaluates the points of the mask `visit` (null: all) with neighbourhoods of
// ladder.largest, reporting the fractions of the pass's area pass, if any, and of its points to
// `progress` (Automatic_scale_progress::Callbacks, empty when there is nothing to report: the
// fractions of the whole are in proportion to the time), and sets `cancelled` if a callback
// returned false; the ladder it gets counts in ladder.sent_on the points it sends
// on; `chosen_count(result)` is a valid result's chosen neighbour count (the one asked for where
// the gate sends it on), else 0; `callback` is told 1 when the passes end before the last.
// `points`: the number of points the first pass estimates (points_to_estimate(), for the
// progress; 0 without a callback).
// Cancelled, the points without their final estimate are a default Result (NOT_COMPUTED).
//
// `settled`, if given, is read after the first pass: the points whose estimate that pass made
// final whatever its count (the points that run() estimated from their records).
template <class Result, class Run, class Chosen_count>
std::vector<Result>
automatic_scale_passes(std::size_t points, const Scale_ladder& ladder, const Run& run, const Chosen_count& chosen_count,
                       const std::function<bool(double)>& callback, const std::vector<char>* settled = nullptr)
{
  Automatic_scale_progress progress(callback);
  Scale_ladder pass = ladder;
  const bool more_passes = ladder.rungs() > 1;
  pass.largest = ladder.smallest;
  pass.gate = more_passes;
  pass.final_pass = !more_passes;
  if(callback)
    pass.sent_on = &progress.sent_on();
  bool cancelled = false;
  std::vector<Result> result = run(pass, nullptr, progress.start_pass(points, !more_passes), cancelled);
  std::vector<char> climb(result.size(), 0);
  const auto is_settled = [settled](std::size_t i) { return settled && !settled->empty() && (*settled)[i]; };
  while(!cancelled && ladder.rungs() > pass.rungs())
  {
    std::size_t climbing = 0;
    for(std::size_t i = 0; i < result.size(); ++i)
    {
      climb[i] = !is_settled(i) && chosen_count(result[i]) >= pass.climb_count() ? 1 : 0;
      climbing += climb[i];
    }
    if(climbing == 0)
    {
      progress.finish();
      break;
    }
    pass.gate = false;
    pass.largest = next_pass_largest(ladder, pass.largest);
    const bool last = ladder.rungs() == pass.rungs();
    pass.final_pass = last;
    const std::vector<Result> more = run(pass, &climb, progress.start_pass(climbing, last), cancelled);
    for(std::size_t i = 0; i < result.size(); ++i)  // (cancelled: the points not reached are NOT_COMPUTED)
      if(climb[i])
        result[i] = more[i];
  }
  // cancelled: the points that would have climbed further have no final estimate either
  if(cancelled && ladder.rungs() > pass.rungs())
    for(std::size_t i = 0; i < result.size(); ++i)
      if(!is_settled(i) && chosen_count(result[i]) >= pass.climb_count())
        result[i] = Result();
  return result;
}

// The points the first of automatic_scale_passes() estimates, for its progress: those of the
// range that `tile` owns (every point without one).
template <class PointRange, class PointMap>
std::size_t points_to_estimate(const PointRange& points, const PointMap& point_map, const Tile& tile)
{
  if(tile.is_whole_space())
    return std::size_t(std::distance(points.begin(), points.end()));
  std::size_t n = 0;
  for(auto it = points.begin(); it != points.end(); ++it)
  {
    const auto& p = get(point_map, *it);
    n += tile.owns(to_double(p.x()), to_double(p.y()), to_double(p.z())) ? 1 : 0;
  }
  return n;
}

// The automatic scale of the estimators (automatic_scale_passes() on estimate_at_every_point();
// Automatic_scale_estimator). With `records` made for this ladder and range (the normals' passes
// with the named parameter scale_choices), the first pass estimates the points that have one
// from the neighbourhood of its count (Known_scale_estimator: a pass per count), the same
// estimate bit for bit, and the ladder's passes the others; not with a tile (whose halo would
// have to cover the ladder's neighbourhoods all the same), a refinement of the normals, or an
// estimator that tests the tangent spread of the neighbourhood the driver gives it.
template <class ConcurrencyTag, class PointRange, class NamedParameters, class Estimator, class Sphere>
auto estimate_at_automatic_scale(const PointRange& points, const NamedParameters& np,
                                 const Scale_estimators<Estimator>& estimators, const Sphere& sphere,
                                 const Scale_ladder& ladder, const char* function_name,
                                 const Curvature_scale_records* records = nullptr)
{
  typedef decltype(estimate_at_every_point<ConcurrencyTag>(points, false, 0.0, np, estimators.estimator,
                                                           function_name)) Results;
  typedef typename Results::value_type Estimate;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Tile tile = choose_parameter(get_parameter(np, internal_np::tile), Tile::whole_space());
  const std::size_t n = std::size_t(std::distance(points.begin(), points.end()));
  const std::size_t min_neighbors = min_neighbors_parameter(np, estimators.estimator.min_neighbors);
  // the points estimated from their records, by count
  std::vector<std::size_t> counts;
  std::vector<std::uint32_t> count_of;  // (empty without records)
  if(records && records->fit(ladder, n) && tile.is_whole_space() && estimators.estimator.normal_refinements == 0 &&
     !estimators.estimator.check_tangent_spread)
  {
    count_of.assign(n, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Curvature_scale_record* r = records->of(i);
      if(r && r->count > 0 && r->size >= min_neighbors)
      {
        count_of[i] = r->count;
        counts.push_back(r->count);
      }
    }
    std::sort(counts.begin(), counts.end());
    counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
  }
  std::vector<char> settled;  // the points their records estimated
  Area_cache areas;           // (the same in every pass)
  Knn_search_cache knn;       // (the search's tree: the same in every pass)
  const auto estimate = [&](const auto& estimator, std::size_t k, const std::vector<char>* visit,
                            const std::function<bool(double)>& progress,
                            const std::function<bool(double)>& area_progress, bool& cancelled) {
    Pass_options pass;
    pass.areas = &areas;
    pass.knn = &knn;
    pass.visit_k = k;
    pass.visit = visit;
    pass.progress = progress;
    pass.area_progress = area_progress;
    pass.cancelled = &cancelled;
    return estimate_at_every_point<ConcurrencyTag>(points, false, 0.0, np, estimator, function_name, pass);
  };
  const auto run = [&](const Scale_ladder& l, const std::vector<char>* visit,
                       const Automatic_scale_progress::Callbacks& progress, bool& cancelled) {
    const Automatic_scale_estimator<Estimator, Sphere> automatic(estimators, sphere, l);
    if(counts.empty() || visit)
      return estimate(automatic, l.largest, visit, progress.points, progress.areas, cancelled);
    // the first pass: the points with a record at their count, then the others on the first rung
    std::size_t done = 0;
    // (each pass's share of the first pass's progress by its points; the ladder's pass, the last,
    // takes the rest, which the points whose record did not fit would otherwise overrun)
    const auto share = [&](std::size_t points) -> std::function<bool(double)> {
      if(!progress.points)
        return {};
      const double from = double(done) / double(n), size = double(std::min(points, n - done)) / double(n);
      return [f = progress.points, from, size](double x) { return f(from + size * x); };
    };
    const Known_scale_estimator<Estimator, Sphere> from_record(automatic, *records);
    Results result(n);
    std::vector<char> mask(n, 0);
    settled.assign(n, 0);
    bool first = true;
    for(std::size_t k : counts)
    {
      std::size_t points = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        mask[i] = count_of[i] == k ? 1 : 0;
        points += mask[i];
      }
      Results part = estimate(from_record, k, &mask, share(points),
                              first ? progress.areas : std::function<bool(double)>(), cancelled);
      first = false;
      done += points;
      if(cancelled)
        return result;
      for(std::size_t i = 0; i < n; ++i)
        if(mask[i] && part[i].status != Curvature_estimate_status::NOT_COMPUTED)
        {
          result[i] = part[i];
          settled[i] = 1;
        }
    }
    std::size_t others = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      mask[i] = settled[i] ? 0 : 1;
      others += mask[i];
    }
    if(others > 0)
    {
      Results part = estimate(automatic, l.largest, &mask, share(others),
                              first ? progress.areas : std::function<bool(double)>(), cancelled);
      for(std::size_t i = 0; i < n; ++i)
        if(mask[i])
          result[i] = part[i];
    }
    return result;
  };
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const std::size_t first_pass_points =
    callback ? points_to_estimate(points, NP_helper::get_const_point_map(points, np), tile) : 0;
  return automatic_scale_passes<Estimate>(
    first_pass_points, ladder, run, [](const Estimate& e) { return e.is_valid() ? e.neighbor_count : std::size_t(0); },
    callback, &settled);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
