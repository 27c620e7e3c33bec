// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The rate of a piece of work (a pass, a tile's step, a phase of the tool), in seconds per unit
// of its fraction done, for the estimates of the time left: its own rate is measured from its
// first report on (the set-up before it, a reader's or a search's, reports nothing and tells
// nothing of what is left), blended in from a prior rate as the fraction grows past that report,
// alone once it has grown by `own_share`. Used by the automatic scale's progress
// (automatic_scale_progress.h) and by the tool's progress line and pass over the tiles.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_WORK_RATE_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_WORK_RATE_H

#include <algorithm>
#include <chrono>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// Seconds on the steady clock, from any origin.
inline double steady_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class Work_rate
{
public:
  // The work starts again (its next report is its first).
  void restart() { m_first_time = -1; }

  // Notes a report at time `t` (seconds) and fraction `f`: the first one after restart() is
  // where the own rate is measured from.
  void report(double t, double f)
  {
    if(m_first_time < 0)
    {
      m_first_time = t;
      m_first_fraction = f;
    }
  }

  bool reported() const { return m_first_time >= 0; }

  // The own rate at time `t` and fraction `f` (after report()); `none` until the fraction has
  // grown since the first report.
  double own(double t, double f, double none) const
  {
    return reported() && f > m_first_fraction ? (t - m_first_time) / (f - m_first_fraction) : none;
  }

  // `prior` blended into the own rate as the fraction grows since the first report, the own rate
  // alone from `own_share` on (before any growth: the prior).
  double blended(double t, double f, double prior, double own_share) const
  {
    if(!reported() || !(f > m_first_fraction))
      return prior;
    const double w = std::min(1.0, (f - m_first_fraction) / own_share);
    return (1 - w) * prior + w * own(t, f, prior);
  }

private:
  double m_first_time = -1, m_first_fraction = 0;
};

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif  // CGAL_POINT_SET_CURVATURES_INTERNAL_WORK_RATE_H
