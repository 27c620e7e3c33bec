// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See range_estimator.h.

#include "range_estimator.h"

#include "interruption.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;

Range_estimator::Range_estimator(const Options& o, const Estimation_settings& scale, Orientation_choice& orientation,
                                 bool with_normals)
    : m_o(o), m_scale(scale), m_orientation(orientation), m_with_normals(with_normals)
{}

Estimates Range_estimator::estimate(Point_set& ps, const PSC::Tile& tile, const Pulse_values& pulses,
                                    const std::function<Progress(const char*)>& phase)
{
  std::size_t undirected = 0;  // (counted once the estimate succeeds)
  if(!m_with_normals)
  {
    if(!tile.is_whole_space())
      throw std::logic_error("Range_estimator: normals are estimated here for the whole cloud only (a tiled run "
                             "estimates them first: tiled_normals.h)");
    const auto start = std::chrono::steady_clock::now();
    try
    {
      // (with the automatic scale of both, the curvatures then skip the ladder where the
      // normals' passes chose their count: parameters::scale_choices)
      const bool share = m_scale.by_count && m_scale.automatic_largest > 0;
      estimate_normals(ps, m_o, m_orientation, phase("normals"), tile, share ? &m_choices : nullptr);
      m_scale.choices = share ? &m_choices : nullptr;
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
        [&ps](std::size_t i) {
          // a finite point whose normal stays +z
          const Point& p = ps.point(*(ps.begin() + i));
          return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()) &&
                 ps.normal(*(ps.begin() + i)) != CGAL::NULL_VECTOR;
        });
    }
    m_normals_seconds += seconds_since(start);
  }
  Estimates estimates = m_o.method->run(ps, m_scale, phase("curvatures"), tile);
  m_choices.clear();
  m_scale.choices = nullptr;
  m_undirected += undirected;
  return estimates;
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
    warnings.push_back(cat(without,
                           " points got no normal (coincident neighbours, neighbours along one line such "
                           "as a single scan line: try a larger --normal-neighbors; non-finite coordinates) and "
                           "are invalid_normal"));
  if(undirected > 0)
    warnings.push_back(
      cat("--orient scanner: ", undirected, " points have no pulse direction and keep normals oriented to +z"));
}

}  // namespace psc_tool
