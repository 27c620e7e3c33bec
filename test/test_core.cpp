// Core package tests (placeholder; the full suite replaces it).
#include "test_support.h"

#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_apss_curvatures.h>

#include <catch2/catch.hpp>

using namespace psc_test;

TEST_CASE("ASO on a sphere of radius 2 with outward normals gives 1/R")
{
  const auto pts = sphere(20000, 2.0);
  const auto est = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, Point_map(), Normal_map(), 0.2);
  REQUIRE(est.size() == pts.size());
  for(const auto& e : est)
  {
    REQUIRE(e.is_valid());
    CHECK(e.min_curvature == Approx(0.5).epsilon(1e-9));
    CHECK(e.max_curvature == Approx(0.5).epsilon(1e-9));
  }
}
