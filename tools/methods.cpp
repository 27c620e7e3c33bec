// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The table of methods (methods.h): the one translation unit of the tool that instantiates
// the curvature estimators.

#include "methods.h"

#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_barycenter_curvatures.h>
#include <CGAL/estimate_jet_curvatures.h>
#include <CGAL/estimate_pca_plane_curvatures.h>
#include <CGAL/estimate_pss_curvatures.h>
#include <CGAL/estimate_vcm_curvatures.h>
#include <CGAL/estimate_wavejet_curvatures.h>

#include <iterator>
#include <stdexcept>

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;

// The run function of an estimator; the Point_set_3's point and normal maps are the defaults.
// clang-format off
#define PSC_TOOL_RUN(NAME)                                                                     \
  Run{#NAME, [](const Point_set& points, const Estimation_settings& scale, const Progress& callback,          \
                const PSC::Tile& tile) -> Estimates {                                           \
        const auto np = PSC::parameters::min_neighbors(                                         \
          scale.min_neighbors ? scale.min_neighbors : PSC::default_min_neighbors::NAME,         \
          PSC::parameters::aso_variant(scale.variant, PSC::parameters::position_fit_blend(      \
            scale.position_fit_blend, PSC::parameters::automatic_scale(scale.automatic_largest, \
            PSC::parameters::tile(tile, PSC::parameters::scale_choices(scale.choices,           \
            CGAL::parameters::callback(callback)))))));                                          \
        if(scale.by_count)                                                                      \
          return CGAL::estimate_##NAME##_curvatures<CGAL::Parallel_tag>(                       \
            points, PSC::parameters::neighbor_count(scale.neighbors, np));                      \
        return CGAL::estimate_##NAME##_curvatures<CGAL::Parallel_tag>(points, scale.radius, np); \
      }}

namespace {

struct Run
{
  const char* name;
  Run_method run;
};

// Every estimator of the package (CGAL::Point_set_curvatures::estimators), in any order.
const Run runs[] = {
  PSC_TOOL_RUN(aso), PSC_TOOL_RUN(apss), PSC_TOOL_RUN(barycenter), PSC_TOOL_RUN(pca_plane),
  PSC_TOOL_RUN(pss), PSC_TOOL_RUN(jet), PSC_TOOL_RUN(vcm), PSC_TOOL_RUN(wavejet),
};
// clang-format on
static_assert(std::size(runs) == std::size(PSC::estimators), "one run per described estimator");

}  // namespace

const std::vector<Method>& methods()
{
  static const std::vector<Method> table = [] {
    std::vector<Method> t;
    for(const PSC::Estimator_description& e : PSC::estimators)
      for(const Run& r : runs)
        if(std::string(r.name) == e.name)
          t.push_back(Method{e, r.run});
    if(t.size() != std::size(runs))
      throw std::logic_error("a run of tools/methods.cpp has no description in estimators.h");
    return t;
  }();
  return table;
}

const Method* find_method(const std::string& name)
{
  for(const Method& m : methods())
    if(name == m.name)
      return &m;
  return nullptr;
}

std::string method_names()
{
  std::string s;
  for(const Method& m : methods())
    s += (s.empty() ? "" : "|") + std::string(m.name);
  return s;
}

}  // namespace psc_tool
