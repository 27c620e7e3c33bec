// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The table of methods (methods.h): the one translation unit of the tool that instantiates
// the curvature estimators.

#include "methods.h"

#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
// The baseline estimators, when the package has them (same signatures as the ones above).
#if __has_include(<CGAL/estimate_barycenter_curvatures.h>)
#include <CGAL/estimate_barycenter_curvatures.h>
#define PSC_TOOL_HAS_BARYCENTER 1
#endif
#if __has_include(<CGAL/estimate_pca_plane_curvatures.h>)
#include <CGAL/estimate_pca_plane_curvatures.h>
#define PSC_TOOL_HAS_PCA_PLANE 1
#endif
#if __has_include(<CGAL/estimate_pss_curvatures.h>)
#include <CGAL/estimate_pss_curvatures.h>
#define PSC_TOOL_HAS_PSS 1
#endif
#if __has_include(<CGAL/estimate_jet_curvatures.h>)
#include <CGAL/estimate_jet_curvatures.h>
#define PSC_TOOL_HAS_JET 1
#endif
#if __has_include(<CGAL/estimate_vcm_curvatures.h>)
#include <CGAL/estimate_vcm_curvatures.h>
#define PSC_TOOL_HAS_VCM 1
#endif
#if __has_include(<CGAL/estimate_wavejet_curvatures.h>)
#include <CGAL/estimate_wavejet_curvatures.h>
#define PSC_TOOL_HAS_WAVEJET 1
#endif

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;

// One table entry per estimator; the Point_set_3's point and normal maps are the defaults.
#define PSC_TOOL_METHOD(NAME, DESCRIPTION, GOOD)                                               \
  Method{#NAME, DESCRIPTION,                                                                   \
         [](const Point_set& points, const Scale& scale, const Progress& callback,             \
            const PSC::Tile& tile) -> Estimates {                                               \
           const auto np = PSC::parameters::min_neighbors(                                      \
             scale.min_neighbors ? scale.min_neighbors : PSC::default_min_neighbors::NAME, \
             PSC::parameters::aso_variant(scale.variant, PSC::parameters::position_fit_blend(   \
               scale.position_fit_blend, PSC::parameters::automatic_scale(scale.automatic_largest, \
               PSC::parameters::tile(tile, CGAL::parameters::callback(callback)))))); \
           if(scale.by_count)                                                                   \
             return CGAL::estimate_##NAME##_curvatures<CGAL::Parallel_tag>(                    \
               points, PSC::parameters::neighbor_count(scale.neighbors, np));                   \
           return CGAL::estimate_##NAME##_curvatures<CGAL::Parallel_tag>(points, scale.radius, np); \
         },                                                                                     \
         PSC::default_min_neighbors::NAME, GOOD}

const std::vector<Method>& methods()
{
  static const std::vector<Method> table = {
    PSC_TOOL_METHOD(aso, "Algebraic Shape Operator (Lejemble et al. 2021): full curvature tensor", 12),
    PSC_TOOL_METHOD(apss, "APSS algebraic sphere: corrected normal and mean curvature only", 20),
#ifdef PSC_TOOL_HAS_BARYCENTER
    PSC_TOOL_METHOD(barycenter, "baseline: distance to the barycentre", 25),
#endif
#ifdef PSC_TOOL_HAS_PCA_PLANE
    PSC_TOOL_METHOD(pca_plane, "baseline: distance to the PCA plane", 15),
#endif
#ifdef PSC_TOOL_HAS_PSS
    PSC_TOOL_METHOD(pss, "baseline: point set surface", 20),
#endif
#ifdef PSC_TOOL_HAS_JET
    PSC_TOOL_METHOD(jet, "baseline: osculating jet", 12),
#endif
#ifdef PSC_TOOL_HAS_VCM
    PSC_TOOL_METHOD(vcm, "baseline: Voronoi covariance measure", 25),
#endif
#ifdef PSC_TOOL_HAS_WAVEJET
    PSC_TOOL_METHOD(wavejet, "baseline: wavejet", 12),
#endif
  };
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

} // namespace psc_tool
