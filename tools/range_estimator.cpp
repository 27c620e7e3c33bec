// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See range_estimator.h.

#include "range_estimator.h"

#include "interruption.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;

namespace {

const double inf = std::numeric_limits<double>::infinity();

// The normals' share of a range's halo H when the curvatures need h (rounded down), and the
// halo that holds both needs (rounded up).
double normal_share(double H, double h) { return std::nextafter(H - h, -inf); }
double total_halo(double h, double normal) { return std::nextafter(h + normal, inf); }

} // namespace

Range_estimator::Range_estimator(const Options& o, const Estimation_settings& scale, Orientation_choice& orientation,
                                 bool with_normals, double curvature_halo_guess, double normal_halo_guess)
  : m_o(o), m_scale(scale), m_orientation(orientation), m_with_normals(with_normals),
    m_curvature_halo_guess(curvature_halo_guess), m_normal_halo_guess(with_normals ? 0.0 : normal_halo_guess),
    m_curvature_halo(curvature_halo_guess)
{
}

Estimates Range_estimator::estimate(Point_set& ps, const PSC::Tile& tile, const Pulse_values& pulses,
                                    const std::function<Progress(const char*)>& phase)
{
  if(!(tile.core == m_last_core))
    m_curvature_halo = m_curvature_halo_guess;  // a new tile
  m_last_core = tile.core;
  const double H = tile.halo;  // infinite: the range is the whole cloud
  if(m_with_normals || H == inf)
    m_curvature_halo = H;
  std::size_t undirected = 0;  // (counted once the estimate succeeds)
  for(;;)
  {
    if(!m_with_normals)
    {
      // the normals of the points within the curvature halo of the core
      const auto start = std::chrono::steady_clock::now();
      const double h = m_curvature_halo, normal_halo = H == inf ? inf : normal_share(H, h);
      if(!(normal_halo >= 0))
        throw PSC::Halo_too_small(total_halo(h, m_normal_halo_guess), H);
      const CGAL::Bbox_3& b = tile.core;
      const PSC::Tile normal_tile =
        tile.is_whole_space() ? tile
                              : PSC::Tile(CGAL::Bbox_3(b.xmin() - h, b.ymin() - h, b.zmin() - h, b.xmax() + h,
                                                       b.ymax() + h, b.zmax() + h),
                                          normal_halo);
      try
      {
        estimate_normals(ps, m_o, m_orientation, phase("normals"), normal_tile);
      }
      catch(const PSC::Halo_too_small& e)
      {
        throw PSC::Halo_too_small(total_halo(h, e.required_halo()), H);
      }
      catch(const std::invalid_argument& e)
      {
        throw Error(e.what());  // (not the curvatures' refusal: the callers complete those)
      }
      if(m_orientation.scanner)
      {
        if(!pulses[0] || !pulses[1] || !pulses[2])
          throw std::logic_error("Range_estimator: --orient scanner without pulse directions");
        undirected = orient_towards_scanner(
          ps.size(), [&ps](std::size_t i) -> Vector& { return ps.normal(*(ps.begin() + i)); },
          [&pulses](std::size_t i) {
            return std::array<double, 3>{{(*pulses[0])[i], (*pulses[1])[i], (*pulses[2])[i]}};
          },
          [&ps, &tile](std::size_t i) {
            // an own point (the finite points of the whole cloud) whose normal stays +z
            const Point& p = ps.point(*(ps.begin() + i));
            return tile.owns(p.x(), p.y(), p.z()) && ps.normal(*(ps.begin() + i)) != CGAL::NULL_VECTOR;
          });
      }
      m_normals_seconds += seconds_since(start);
    }
    try
    {
      Estimates estimates = m_o.method->run(ps, m_scale, phase("curvatures"), PSC::Tile(tile.core, m_curvature_halo));
      m_undirected += undirected;
      return estimates;
    }
    catch(const PSC::Halo_too_small& e)
    {
      if(m_with_normals || H == inf)
        throw;
      const double normal_halo = normal_share(H, m_curvature_halo);
      m_curvature_halo = e.required_halo();
      // the range may hold the larger curvature halo and the normals' share: estimate again
      if(total_halo(m_curvature_halo, m_normal_halo_guess) <= H)
        continue;
      throw PSC::Halo_too_small(total_halo(m_curvature_halo, std::max(normal_halo, m_normal_halo_guess)), H);
    }
  }
}

void add_normal_warnings(std::vector<std::string>& warnings, const Options& o, bool with_normals,
                         const Orientation_choice& orientation, const Row_summary& summary, std::size_t undirected)
{
  if(with_normals)
    return;
  warnings.push_back(cat(in_quotes(o.input), " has no normals: estimating them (", normal_fit_description(o),
                         ", oriented ", orientation.text, "); a wrong orientation flips the sign of the curvatures"));
  std::size_t without = 0;
  for(const auto& s : summary.invalid())
    if(s.first == int(CGAL::Curvature_estimate_status::INVALID_NORMAL) ||
       s.first == int(CGAL::Curvature_estimate_status::NON_FINITE_POINT))
      without += s.second;
  if(without > 0)
    warnings.push_back(cat(without, " points got no normal (coincident neighbours, neighbours along one line such "
                           "as a single scan line: try a larger --normal-neighbors; non-finite coordinates) and "
                           "are invalid_normal"));
  if(undirected > 0)
    warnings.push_back(
      cat("--orient scanner: ", undirected, " points have no pulse direction and keep normals oriented to +z"));
}

} // namespace psc_tool
