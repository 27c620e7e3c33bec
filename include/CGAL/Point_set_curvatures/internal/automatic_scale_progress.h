// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The progress of the automatic scale's passes (automatic_scale_passes(), automatic_scale.h)
// in proportion to the time they take, so that a front end's estimate of the time left (the
// time so far scaled by what remains) holds from the first pass on.
//
// The passes cost very differently from one cloud to the next: the first visits every point
// with the smallest neighbourhood, the next ones only the points it sends on, with a
// neighbourhood 16 times as large. On a clean terrain few points climb and the first pass is
// 75-82% of the time; on a real airborne tile 99% climb and it is 11-17%. A fixed split (half
// to the first pass) made the tool's predicted end up to 106% late on a clean 1M terrain and 79%
// early on lone-star.las (benchmark/README.md, section 9). Here:
// - in the first pass, whose time is not known yet, the fraction is the pass's own divided by
//   1 + q c, where q is the share of the points visited so far that it sent on (the estimators
//   count them) and c the cost of such a point in the next pass, in points of this one
//   (climber_cost: measured 5.5-9.0 on real tiles and clean terrains, for the normals and the
//   curvatures); where the robust ASO computes its areas first, their pass (reported apart)
//   gives the first pass's prior;
// - in a later pass, the time of the passes done plus the time this one is taking, over that
//   plus the time it will take: first the prior (the points it visits times c times the time a
//   point of the previous pass took), then, as its fraction grows, what its own rate says
//   (measured from its first report: the search's set-up before it reports nothing).
// The fractions reported never decrease; the last pass's end reports 1. The clock is a
// parameter, so that the tests give the times.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_PROGRESS_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_PROGRESS_H

#include <CGAL/Point_set_curvatures/internal/work_rate.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <utility>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

class Automatic_scale_progress
{
public:
  // The cost of a point sent on to the next pass, in points of the pass that sent it (the
  // default's ladder, 40 to 640: the next pass searches 16 times as many neighbours and fits up
  // to five rungs; measured 5.5 and 9.0 on a clean 1M terrain, 6.7 and 7.9 on data/real/
  // sample_c.las, for the curvatures and the normals).
  static constexpr double climber_cost = 7;
  // The cost of a point's area (the robust ASO's sample weights, computed before the first
  // pass), in points of the first pass (measured 0.22 on the clean 1M terrain).
  static constexpr double area_cost = 0.25;
  // The share of the points sent on that is assumed before the first pass has visited any, and
  // its weight then, in points (q = (sent on + prior_sent_on * prior_points) / (visited +
  // prior_points)).
  static constexpr double prior_sent_on = 0.25;
  static constexpr double prior_points = 20;
  // The share of a pass from which its own rate alone tells its time (below, blended with the
  // prior in proportion).
  static constexpr double own_rate_share = 0.05;

  // The callbacks of a pass: `areas` that of its area pass, if it has one, `points` that of its
  // points (both empty without a caller's callback).
  struct Callbacks
  {
    std::function<bool(double)> areas, points;
  };

  // `callback`: the caller's (may be empty: nothing is reported); `now`: seconds from any
  // origin (empty: the steady clock).
  explicit Automatic_scale_progress(std::function<bool(double)> callback, std::function<double()> now = {})
      : m_callback(std::move(callback)), m_now(now ? std::move(now) : std::function<double()>(&steady_seconds))
  {}

  Automatic_scale_progress(const Automatic_scale_progress&) = delete;
  Automatic_scale_progress& operator=(const Automatic_scale_progress&) = delete;

  // Starts a pass over `points` points (`last`: no pass follows it) and returns its callbacks,
  // which take the fraction in [0, 1] of its area pass and of its points. The counter sent_on()
  // counts the points this pass sends on.
  Callbacks start_pass(std::size_t points, bool last)
  {
    const double t = m_now();
    if(m_passes > 0)
    {
      const double took = t - m_start;
      // the prior of this pass: its points at climber_cost points of the previous one
      m_prior = m_points > 0 ? climber_cost * double(points) * took / double(m_points) : 0;
      m_done += took;
    }
    ++m_passes;
    m_start = t;
    m_rate.restart();
    m_in_areas = false;
    m_points = points;
    m_last = last;
    m_sent_on.store(0, std::memory_order_relaxed);
    if(!m_callback)
      return {};
    return {[this](double f) { return report(area_fraction(f)); }, [this](double f) { return report(fraction(f)); }};
  }

  // The points of the current pass sent on so far (the estimators add to it).
  std::atomic<std::size_t>& sent_on() { return m_sent_on; }

  // Reports the end of every pass (the passes stopped before the last: no point climbed).
  bool finish() { return m_callback ? report(1.0) : true; }

  // The overall fraction at the fraction `f` of the current pass's area pass (exposed for the
  // tests): the areas, then the points at 1 / area_cost areas each, then those sent on.
  double area_fraction(double f)
  {
    f = std::clamp(f, 0.0, 1.0);
    m_areas_end = m_now();
    m_in_areas = true;
    if(f <= 0)
      return 0;  // (nothing to tell the areas' time by)
    const double elapsed = std::max(0.0, m_areas_end - m_start);
    const double areas = elapsed / f;
    const double total = m_done + areas * (1 + (1 + rest(0)) / area_cost);
    return total > 0 ? (m_done + elapsed) / total : 0.0;
  }

  // The overall fraction at the fraction `f` of the current pass's points (exposed for the
  // tests).
  double fraction(double f)
  {
    f = std::clamp(f, 0.0, 1.0);
    if(m_in_areas)
    {
      // the area pass ended: its time is done, and tells the points' prior
      const double areas = std::max(0.0, m_areas_end - m_start);
      m_done += areas;
      m_prior = areas / area_cost;
      m_start = m_areas_end;
      m_in_areas = false;
    }
    const double r = rest(f);
    if(m_done <= 0 && m_prior <= 0)
      return f / (1 + r);  // the first pass, no time known: its own
    const double t = m_now(), elapsed = std::max(0.0, t - m_start);
    // seconds per unit of the pass's fraction: the prior's, then, as the fraction grows, its own
    // (from its first report on: the search's set-up reports nothing)
    m_rate.report(t, f);
    const double rate = m_rate.blended(t, f, m_prior, own_rate_share);
    const double pass_seconds = elapsed + (1 - f) * rate;
    const double total = m_done + pass_seconds * (1 + r);
    return total > 0 ? (m_done + elapsed) / total : f;
  }

private:
  // The time of the passes after the current one, in units of its time, at its fraction `f`:
  // q climber_cost, q the share of the points visited that it sent on.
  double rest(double f) const
  {
    if(m_last)
      return 0;
    const double visited = f * double(m_points);
    const double q =
      (double(m_sent_on.load(std::memory_order_relaxed)) + prior_sent_on * prior_points) / (visited + prior_points);
    return std::min(1.0, q) * climber_cost;
  }

  bool report(double fraction)
  {
    m_reported = std::max(m_reported, std::min(1.0, fraction));
    return m_callback(m_reported);
  }

  std::function<bool(double)> m_callback;
  std::function<double()> m_now;
  std::size_t m_passes = 0, m_points = 0;
  double m_start = 0, m_done = 0, m_prior = 0, m_reported = 0, m_areas_end = 0;
  Work_rate m_rate;  // the current pass's (its points')
  bool m_last = true, m_in_areas = false;
  std::atomic<std::size_t> m_sent_on{0};
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif  // CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_PROGRESS_H
