// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The fraction done of a pass over the tiles (visit_tiles(), tiled_run.h), shown on one
// progress line whatever the number of tiles, in proportion to the time expected, so that the
// line's estimate of the time left (the time so far scaled by what remains) holds over the
// whole pass: a line per tile (as before) gave each tile's time left, and within a tile the
// automatic scale's passes made it up to twice too long. Header-only and free of the rest of
// the tool, so that test_tool checks it with its own clock.
//
// Each tile reads the file (its points and halo) and estimates its points. The time left is the
// rest of the current step plus, for every tile to come, a read and its points' estimation:
// - a read: the mean of the tiles done (their reads again with a larger halo included), before
//   any, the density pass's (one read of the file as well);
// - an estimation: the seconds per own point of the tiles done (their refused tries included),
//   times the tile's own points (the density's count); before any, the current tile's own rate,
//   and before that the tile's share of estimation_prior reads;
// - the current step: its prior, then, as its fraction grows, its own rate (from its first
//   report: the reader's or the search's set-up reports nothing).
// The fractions never decrease.

#ifndef POINT_SET_CURVATURES_TOOL_TILE_PASS_PROGRESS_H
#define POINT_SET_CURVATURES_TOOL_TILE_PASS_PROGRESS_H

#include <CGAL/Point_set_curvatures/internal/work_rate.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace psc_tool {

class Tile_pass_progress
{
public:
  // The estimation of the whole cloud before any is measured, in reads of the file (the
  // 100M-point terrain in 9 tiles: 107 with the default scale, 35 with --radius 3.5); a tile's
  // is its share of the own points.
  static constexpr double estimation_prior = 60;
  // The share of a step from which its own rate alone tells its time (below, blended with the
  // prior in proportion).
  static constexpr double own_rate_share = 0.05;

  // `own`: the own points of each tile the pass visits, in their order (the density's counts);
  // `read_seconds`: the time of a read of the file (the density pass's); `now`: seconds from
  // any origin (empty: the steady clock).
  Tile_pass_progress(std::vector<double> own, double read_seconds, std::function<double()> now = {})
      : m_own(std::move(own)), m_read_prior(std::max(0.0, read_seconds)),
        m_now(now ? std::move(now) : std::function<double()>(&CGAL::Point_set_curvatures::internal::steady_seconds)),
        m_start(m_now())
  {
    m_own_from.assign(m_own.size() + 1, 0.0);
    for(std::size_t v = m_own.size(); v-- > 0;)
      m_own_from[v] = m_own_from[v + 1] + std::max(0.0, m_own[v]);
  }

  // Tile `v` (an index of `own`) starts reading (again, if its halo grew) / estimating.
  void begin_read(std::size_t v) { begin(v, READ); }
  void begin_estimation(std::size_t v) { begin(v, ESTIMATION); }
  // The current tile is done: its estimation kept, or (`estimated` false) no own point read.
  void end_tile(bool estimated = true)
  {
    end_step(m_now());
    m_read_seconds += m_tile_read;
    m_estimation_seconds += m_tile_estimation;
    if(estimated)
      m_done_own += std::max(0.0, m_own[m_tile]);
    ++m_done_tiles;
    m_tile_read = m_tile_estimation = 0;
    m_step = NONE;
  }

  // The fraction of the pass when the current step has done `f` of its work.
  double at(double f)
  {
    f = std::clamp(f, 0.0, 1.0);
    const double t = m_now();
    if(m_step != NONE)
      m_rate.report(t, f);
    const double elapsed = std::max(0.0, t - m_start);
    const double read = mean_read();
    double left = 0;
    double per_point = estimation_per_point();
    if(m_step != NONE)
    {
      const double own = std::max(0.0, m_own[m_tile]);
      const double prior = m_step == READ ? read : per_point > 0 ? per_point * own : estimation_prior_of(own, read);
      const double step_left = (1 - f) * m_rate.blended(t, f, prior, own_rate_share);
      left += step_left;
      if(m_step == READ)
        left += per_point > 0 ? per_point * own : estimation_prior_of(own, read);
      else if(per_point <= 0 && own > 0)
        per_point = (t - m_step_start + step_left) / own;  // (the first tile: its own rate)
    }
    // the tiles to come: a read each, and their own points' estimation
    const std::size_t next = std::min(m_step == NONE ? m_done_tiles : m_tile + 1, m_own.size());
    const double own_to_come = m_own_from[next];
    left += double(m_own.size() - next) * read +
            (per_point > 0 ? per_point * own_to_come : estimation_prior_of(own_to_come, read));
    const double total = elapsed + left;
    m_reported = std::max(m_reported, total > 0 ? std::min(1.0, elapsed / total) : m_own.empty() ? 1.0 : 0.0);
    return m_reported;
  }

private:
  enum Step { NONE, READ, ESTIMATION };

  void begin(std::size_t v, Step step)
  {
    const double t = m_now();
    end_step(t);
    m_tile = std::min(v, m_own.empty() ? 0 : m_own.size() - 1);
    m_step = m_own.empty() ? NONE : step;
    m_step_start = t;
    m_rate.restart();
  }

  // A step ended (a read, or an estimation refused for a short halo): its time is the tile's.
  void end_step(double t)
  {
    if(m_step == READ)
      m_tile_read += t - m_step_start;
    else if(m_step == ESTIMATION)
      m_tile_estimation += t - m_step_start;
  }

  double estimation_prior_of(double own, double read) const
  {
    const double own_total = m_own_from.front();  // (every tile's)
    return own_total > 0 ? estimation_prior * read * own / own_total : 0.0;
  }
  double mean_read() const { return m_done_tiles > 0 ? m_read_seconds / double(m_done_tiles) : m_read_prior; }
  double estimation_per_point() const { return m_done_own > 0 ? m_estimation_seconds / m_done_own : 0.0; }

  std::vector<double> m_own;
  std::vector<double> m_own_from;  // the own points of the tiles from v on (m_own.size() + 1 sums)
  double m_read_prior;
  std::function<double()> m_now;
  double m_start;
  // the tiles done: their number, own points, and the time of their reads and estimations
  std::size_t m_done_tiles = 0;
  double m_done_own = 0, m_read_seconds = 0, m_estimation_seconds = 0;
  // the current tile: its reads and estimations so far (a tile read again), its current step
  double m_tile_read = 0, m_tile_estimation = 0;
  std::size_t m_tile = 0;
  Step m_step = NONE;
  double m_step_start = 0;
  CGAL::Point_set_curvatures::internal::Work_rate m_rate;  // the current step's
  double m_reported = 0;
};

}  // namespace psc_tool

#endif
