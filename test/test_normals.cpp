// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Normals for clouds without (estimate_oriented_normals): quadric normals on simulated scans, one or
// two scan lines, closed objects outward and open ones up, parts turned inward, thin plates by the
// parity of the crossings. Built into the test_tool program.

#include "test_tool_support.h"

using namespace psc_tool_test;

// =======================================================================================
// Normals for clouds without (estimate_oriented_normals)

namespace {

typedef std::tuple<Point, Vector> Position_and_normal;

std::vector<Position_and_normal> positions_of(const std::vector<Oriented_point>& pts)
{
  std::vector<Position_and_normal> out;
  for(const Oriented_point& p : pts)
    out.emplace_back(p.first, Vector(0, 0, 0));
  return out;
}

const auto tuple_maps = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Position_and_normal>())
                          .normal_map(CGAL::Nth_of_tuple_property_map<1, Position_and_normal>());

// Largest angle (degrees) between estimated and true normals, orientation included, and the
// number of estimated normals pointing against the truth.
std::pair<double, std::size_t> normal_agreement(const std::vector<Position_and_normal>& est,
                                                const std::vector<Oriented_point>& truth)
{
  double worst = 0;
  std::size_t flipped = 0;
  for(std::size_t i = 0; i < est.size(); ++i)
  {
    const Vector& n = std::get<1>(est[i]);
    const double c = n * truth[i].second / std::sqrt(n.squared_length() * truth[i].second.squared_length());
    flipped += c < 0;
    worst = std::max(worst, std::acos(std::min(1.0, std::abs(c))) * 180 / M_PI);
  }
  return {worst, flipped};
}

// Mean angle (degrees) between estimated normals and true ones (`truth(i)`) as lines, the
// orientation apart, over the points `keep(i)` accepts.
template <class Truth, class Keep>
double mean_line_angle(const std::vector<Oriented_point>& estimated, const Truth& truth, const Keep& keep)
{
  double sum = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < estimated.size(); ++i)
    if(keep(i))
    {
      sum += line_angle_degrees(estimated[i].second, truth(i));
      ++n;
    }
  return sum / double(n);
}

template <class Truth>
double mean_line_angle(const std::vector<Oriented_point>& estimated, const Truth& truth)
{
  return mean_line_angle(estimated, truth, [](std::size_t) { return true; });
}

}  // namespace

TEST_CASE(
  "estimate_oriented_normals: spheres and a terrain, by spanning tree, vector and point, sequential == parallel")
{
  // Two spheres far apart (two connected parts of the graph), exact outward normals as truth.
  std::vector<Oriented_point> two = sphere(20000, 1.0);
  for(const Oriented_point& p : sphere(5000, 0.5))
    two.emplace_back(p.first + Vector(10, 0, 0), p.second);
  auto seq = positions_of(two), par = positions_of(two);
  const std::size_t without_seq = CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(seq, tuple_maps);
  const std::size_t without_par = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(par, tuple_maps);
  CHECK(without_seq == 0);
  CHECK(without_par == 0);
  std::size_t differ = 0;
  for(std::size_t i = 0; i < seq.size(); ++i)
    differ += !(std::get<1>(seq[i]) == std::get<1>(par[i]));
  CHECK(differ == 0);
  const auto tree = normal_agreement(seq, two);
  // the default quadric of 40 neighbours on a unit sphere sampled with 20K points: measured
  // 0.0004 degrees (the PCA plane of 18 gave 0.79: its tilt is second order in the spacing)
  measured("sphere, quadric normals, worst angle (deg)", tree.first);
  CHECK(tree.first < 0.01);
  CHECK(tree.second == 0);  // both spheres outward: each part is closed, its sign chosen outward

  // towards the centre of the first sphere: every normal of the first sphere inward
  auto inward = positions_of(two);
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    inward, PSC::parameters::normal_orientation(CGAL::Normal_orientation::towards_point(0, 0, 0), tuple_maps));
  std::size_t inward_ok = 0;
  for(std::size_t i = 0; i < 20000; ++i)
    inward_ok += std::get<1>(inward[i]) * two[i].second < 0;
  CHECK(inward_ok == 20000);

  // a terrain (height field), normals along +z, and by radius
  const std::vector<Oriented_point> terrain = varying_density(20000, 3);
  auto up = positions_of(terrain);
  CHECK(CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
          up, 0.1, PSC::parameters::normal_orientation(CGAL::Normal_orientation::along_vector(0, 0, 1), tuple_maps)) ==
        0);
  const auto along = normal_agreement(up, terrain);
  measured("terrain, quadric normals by radius 0.1, worst angle (deg)", along.first);
  CHECK(along.first < 1.0);  // measured 0.18 (0.58 with the PCA plane; the sparse end has few points per ball)
  CHECK(along.second == 0);
  // and the spanning tree agrees on the terrain (an open part: its mean normal up)
  auto propagated = positions_of(terrain);
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(propagated, tuple_maps);
  CHECK(normal_agreement(propagated, terrain).second == 0);
}

TEST_CASE("estimate_oriented_normals: coincident, isolated and non-finite points get a zero normal, no crash")
{
  // The tool once crashed in CGAL's jet fitting on 19 identical points.
  std::vector<Position_and_normal> same(19, Position_and_normal(Point(1, 2, 3), Vector(0, 0, 0)));
  CHECK(CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(same, tuple_maps) == 19);
  for(const auto& p : same)
    CHECK(std::get<1>(p) == Vector(0, 0, 0));
  auto pts = positions_of(sphere(3000, 1.0));
  pts.emplace_back(Point(std::nan(""), 0, 0), Vector(0, 0, 0));
  for(int i = 0; i < 30; ++i)
    pts.emplace_back(Point(50, 50, 50), Vector(0, 0, 0));  // a pile of copies, far away
  CHECK(CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(pts, tuple_maps) == 31);
  CHECK(std::get<1>(pts[0]).squared_length() == Approx(1.0));
  CHECK_THROWS_AS(CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(pts, -1.0, tuple_maps), std::invalid_argument);
  // cancelled: every normal zero
  auto cut = positions_of(sphere(3000, 1.0));
  CHECK(CGAL::estimate_oriented_normals<CGAL::Sequential_tag>(
          cut, tuple_maps.callback(std::function<bool(double)>([](double) { return false; }))) == 3000);
}

// Normals of clouds as scanners give them (test/scan_simulator.h), and their orientation

namespace {

namespace scan = psc_test::scan;

// Mean |H - H*| over the valid estimates, which must be at least 99% of the points (an error
// averaged over a few valid points, or none, would prove nothing; issue 45).
double mean_h_error(const std::vector<Estimate>& est, const std::vector<scan::Sample>& s)
{
  double sum = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < est.size(); ++i)
    if(est[i].is_valid())
    {
      sum += std::abs(est[i].mean_curvature - s[i].truth.mean);
      ++n;
    }
  INFO(n << " valid estimates of " << est.size());
  CHECK(double(n) >= 0.99 * double(est.size()));
  return n ? sum / double(n) : HUGE_VAL;
}

// Share of the non-zero normals on the side of the true normal.
double share_oriented(const std::vector<Oriented_point>& pts, const std::vector<Vector>& truth)
{
  std::size_t with = 0, right = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(pts[i].second != CGAL::NULL_VECTOR)
    {
      ++with;
      right += pts[i].second * truth[i] > 0;
    }
  return with ? double(right) / double(with) : 0.0;
}

// A torus of radii R and r around the z axis, area-uniform random points, outward normals.
std::vector<Oriented_point> random_torus(std::size_t n, double R, double r, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), keep(0, R + r);
  std::vector<Oriented_point> pts;
  while(pts.size() < n)
  {
    const double u = angle(rng), v = angle(rng);
    if(keep(rng) > R + r * std::cos(v))
      continue;
    const Vector radial(std::cos(u), std::sin(u), 0);
    const Vector normal = std::cos(v) * radial + Vector(0, 0, std::sin(v));
    pts.emplace_back(CGAL::ORIGIN + R * radial + r * normal, normal);
  }
  return pts;
}

}  // namespace

// The pipeline for clouds without normals: quadric normals (the default of
// estimate_oriented_normals) and the ASO with position_fit_blend(0.5), against the ASO with the
// exact normals and against PSS (positions only), at 40 neighbours, on the three kinds of scan
// of benchmark/scan_experiments at a lower density.
TEST_CASE("scans without normals: quadric normals and the position blend as accurate as exact normals, ahead of PSS")
{
  const scan::Height_field terrain = scan::wavy_terrain();
  const std::vector<std::pair<std::string, std::vector<scan::Sample> > > clouds = {
    {"terrestrial torus", scan::terrestrial_torus(scan::Noise())},
    {"airborne lines", scan::airborne_lines(terrain, 6, 0.1, 0.5)},
    {"merged terrestrial", scan::merged_terrestrial(terrain, 12, 0.009, 12)}};
  const auto by40 = PSC::parameters::neighbor_count(40, pair_maps);
  for(const auto& c : clouds)
  {
    INFO(c.first);
    const std::vector<Oriented_point> exact = scan::with_true_normals(c.second);
    std::vector<Oriented_point> estimated = exact;
    CHECK(CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(estimated, pair_maps) < exact.size() / 100);
    std::vector<Vector> truth;
    for(const Oriented_point& p : exact)
      truth.push_back(p.second);
    // the default orientation (spanning tree, open parts up) is right on these open surfaces
    const double oriented = share_oriented(estimated, truth);
    measured(c.first + ": estimated normals on the true side", oriented);
    CHECK(oriented > 0.999);
    const double with_exact = mean_h_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(exact, by40), c.second);
    const double blended = mean_h_error(
      CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(estimated, PSC::parameters::position_fit_blend(0.5, by40)),
      c.second);
    const double pss = mean_h_error(CGAL::estimate_pss_curvatures<CGAL::Parallel_tag>(estimated, by40), c.second);
    measured(c.first + ": mean |H error|, ASO with exact normals", with_exact);
    measured(c.first + ": mean |H error|, quadric normals and position blend", blended);
    measured(c.first + ": mean |H error|, PSS", pss);
    // the targets of issue 31 (benchmark/README.md, "Scans without normals"). Measured, blended
    // / exact / PSS (x1e-3): torus 2.50 / 1.85 / 3.38, airborne 1.40 / 1.22 / 22.5, merged
    // 0.230 / 0.236 / 0.251 (the one close call: on smaller merged clouds PSS was 5% ahead)
    CHECK(blended <= 1.5 * with_exact);
    CHECK(blended <= pss);
  }
}

// The cubic's normal against the quadric's on a clean cubic surface sampled at random: where the
// automatic scale keeps 40 as clean, the normal is the cubic's slope at the point, mapped back from
// the fit's frame (a wrong sign or axis would be off by degrees); with the fixed count the quadric's.
TEST_CASE("estimate_oriented_normals: on a clean cubic surface the automatic scale's normals are the cubic's")
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> square(-2, 2);
  std::vector<Oriented_point> exact;
  for(int i = 0; i < 4000; ++i)
  {
    const double x = square(random), y = square(random);
    // z = 0.04 x³ - 0.03 x² y + 0.02 y³ + 0.1 x y
    const Vector n(-(0.12 * x * x - 0.06 * x * y + 0.1 * y), -(-0.03 * x * x + 0.06 * y * y + 0.1 * x), 1);
    exact.emplace_back(Point(x, y, 0.04 * x * x * x - 0.03 * x * x * y + 0.02 * y * y * y + 0.1 * x * y),
                       n / std::sqrt(n.squared_length()));
  }
  const auto mean_angle = [&](const std::vector<Oriented_point>& estimated) {
    return mean_line_angle(
      estimated, [&](std::size_t i) { return exact[i].second; },
      [&](std::size_t i) {  // (away from the border)
        return std::abs(exact[i].first.x()) < 1.5 && std::abs(exact[i].first.y()) < 1.5;
      });
  };
  std::vector<Oriented_point> automatic = exact, fixed = exact;
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    automatic, PSC::parameters::automatic_scale(640, PSC::parameters::neighbor_count(40, pair_maps)));
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(fixed, PSC::parameters::neighbor_count(40, pair_maps));
  const double cubic = mean_angle(automatic), quadric = mean_angle(fixed);
  measured("clean cubic surface: mean angle of the automatic scale's normals (degrees)", cubic);
  measured("clean cubic surface: mean angle of the quadric's at 40 (degrees)", quadric);
  CHECK(cubic < 0.1 * quadric);
}

// Clean zigzag airborne lines 3 times farther apart than the spacing along them (issue 44, item
// 3). Where the normals' first test keeps the first rung as clean, its quadric's slope carries the
// surface's third-order terms (0.24 degrees on average here) and the ASO, which differentiates the
// normal field, reads them as curvature: the default lost to PSS at 40 neighbours (1.67e-3 against
// 1.44e-3 in benchmark/scan_experiments `zigzag3`). There the normal is now the weighted cubic's.
TEST_CASE("scans without normals: the cubic's normal where the first rung is clean, the default ahead of PSS")
{
  const std::vector<scan::Sample> lines =
    scan::airborne_sweeps(scan::wavy_terrain(), 12, 0.15, 0.45, scan::Sweep::ZIGZAG, scan::Noise());
  const std::vector<Oriented_point> exact = scan::with_true_normals(lines);
  std::vector<Oriented_point> estimated = exact;
  CHECK(CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
          estimated, PSC::parameters::automatic_scale(640, PSC::parameters::neighbor_count(40, pair_maps))) == 0);
  const double angle = mean_line_angle(estimated, [&](std::size_t i) { return exact[i].second; });
  std::size_t flipped = 0;
  for(std::size_t i = 0; i < exact.size(); ++i)
    flipped += estimated[i].second * exact[i].second < 0;
  CHECK(flipped == 0);
  const auto by40 = PSC::parameters::neighbor_count(40, pair_maps);
  const double automatic =
    mean_h_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                   estimated, PSC::parameters::automatic_scale(640, PSC::parameters::position_fit_blend(0.5, by40))),
                 lines);
  const double pss = mean_h_error(CGAL::estimate_pss_curvatures<CGAL::Parallel_tag>(estimated, by40), lines);
  measured("clean zigzag lines 3:1: mean angle of the automatic scale's normals (degrees)", angle);
  measured("clean zigzag lines 3:1: mean |H error|, the default's ASO on them", automatic);
  measured("clean zigzag lines 3:1: mean |H error|, PSS at 40", pss);
  // (measured: 0.068 degrees, 1.26e-3 against PSS's 1.44e-3; the quadric's normals gave 0.237
  // degrees and 1.67e-3)
  CHECK(angle < 0.12);
  CHECK(automatic <= pss);
}

TEST_CASE("estimate_oriented_normals: the automatic scale gives up a first rung that cannot tell the slope on noisy "
          "data only")
{
  // A car-roof multi-beam scanner standing still (rings 0.2 to more than 1 m apart, points 1 to
  // 4 cm apart along them), range noise 0.3 times the spacing: at 40 neighbours one or two rings,
  // whose quadric follows the noise across them (or one ring, whose range noise lies in the plane
  // of the ring and the beams): the ladder kept such first rungs where their residuals read as
  // no noise or their interval missed the second rung's, normals 5 to 15 degrees off. Measured on
  // these 43,859 points (benchmark/scan_experiments `rings`; 189 without a normal): mean angle
  // 2.42 -> 0.35 degrees, 5,782 -> 492 normals more than 5 degrees off.
  const scan::Height_field terrain = scan::wavy_terrain();
  const auto angles = [&](const std::vector<scan::Sample>& samples) {
    const std::vector<Oriented_point> exact = scan::with_true_normals(samples);
    std::vector<Oriented_point> estimated = exact;
    // (the points without a normal, at the ends of the rings, apart)
    const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
      estimated, PSC::parameters::automatic_scale(640, PSC::parameters::neighbor_count(40, pair_maps)));
    CHECK(without < samples.size() / 100);
    const auto has_normal = [&](std::size_t i) { return estimated[i].second.squared_length() > 0; };
    std::size_t beyond = 0;
    for(std::size_t i = 0; i < exact.size(); ++i)
      beyond += has_normal(i) && line_angle_degrees(estimated[i].second, exact[i].second) > 5;
    return std::make_pair(mean_line_angle(
                            estimated, [&](std::size_t i) { return exact[i].second; }, has_normal),
                          beyond);
  };
  const auto noisy = angles(scan::with_range_noise(0.3, [&](const scan::Noise& noise) {
    return scan::multibeam_rings(terrain, 12, 32, -0.535, -0.023, 0.0035, noise);
  }));
  measured("noisy multi-beam rings: mean angle of the automatic scale's normals (degrees)", noisy.first);
  measured("  normals more than 5 degrees off", double(noisy.second));
  CHECK(noisy.first < 0.6);
  CHECK(noisy.second < 800);
  // Clean airborne lines 10 times farther apart than the spacing along them: such first rungs
  // are the best ones there; the next two rungs' residuals grow as r^6 and the first is kept
  // (measured: 0.363 degrees; giving them up whatever the next rungs say, 0.73)
  const auto clean = angles(scan::airborne_lines(terrain, 12, 0.1, 1.0, scan::Noise()));
  measured("clean airborne lines 10:1: mean angle of the automatic scale's normals (degrees)", clean.first);
  CHECK(clean.first < 0.45);
}

// Airborne lines 8 times farther apart than the spacing along them, not straight (3 cm of
// attitude wobble): at 40 neighbours one line crosses the query and two graze the kernel's
// rim, and the ASO's derivatives follow the weights moving between lines. The normal-field
// fit blended in where the neighbourhood's spread is that anisotropic (normal_field_fit.h)
// brings the ASO with exact normals under PSS. Measured on this cloud (x1e-3): the ASO 3.91
// without the anisotropy blend, 1.77 with it, PSS 2.43.
TEST_CASE("ASO on sparse airborne lines: with exact normals at most PSS's error at 40 neighbours")
{
  const std::vector<scan::Sample> lines =
    scan::airborne_sweeps(scan::wavy_terrain(), 8, 0.1, 0.8, scan::Sweep::PARALLEL, scan::Noise(), 0.03);
  const std::vector<Oriented_point> exact = scan::with_true_normals(lines);
  const auto by40 = PSC::parameters::neighbor_count(40, pair_maps);
  const double aso = mean_h_error(CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(exact, by40), lines);
  const double pss = mean_h_error(CGAL::estimate_pss_curvatures<CGAL::Parallel_tag>(exact, by40), lines);
  measured("airborne 8:1 wobbly lines, exact normals: mean |H error|, ASO", aso);
  measured("airborne 8:1 wobbly lines: mean |H error|, PSS", pss);
  CHECK(aso <= pss);
  double mean_abs_h = 0;  // the error of a constant zero
  for(const scan::Sample& s : lines)
    mean_abs_h += std::abs(s.truth.mean) / double(lines.size());
  CHECK(aso < 0.05 * mean_abs_h);
}

TEST_CASE("estimate_oriented_normals: one scan line gives no normal, never a sideways one, and quadric normals on two "
          "or three lines")
{
  // Airborne lines 40 times farther apart than the spacing along a line: the 40 nearest of
  // every point lie on its own line, where any normal about the line would fit.
  const scan::Height_field plane = scan::tilted_plane();
  const std::vector<scan::Sample> lines = scan::airborne_lines(plane, 6, 0.05, 2.0);
  std::vector<Oriented_point> pts = scan::with_true_normals(lines);
  for(CGAL::Normal_fit fit : {CGAL::Normal_fit::QUADRIC, CGAL::Normal_fit::PLANE})
  {
    INFO("fit " << int(fit));
    const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
      pts, PSC::parameters::neighbor_count(40, PSC::parameters::normal_fit(fit, pair_maps)));
    double worst = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      if(pts[i].second != CGAL::NULL_VECTOR)
        worst = std::max(worst, line_angle_degrees(pts[i].second, lines[i].truth.normal));
    measured("one scan line per neighbourhood: points without a normal (of " + std::to_string(pts.size()) + ")",
             double(without));
    CHECK(without > 0.99 * double(pts.size()));  // measured 1680 and 1673 of 1680
    CHECK(worst < 1.0);                          // the few with a normal see two lines
    // 200 neighbours reach the next lines: every normal, and right
    const std::size_t without_200 = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
      pts, PSC::parameters::neighbor_count(200, PSC::parameters::normal_fit(fit, pair_maps)));
    CHECK(without_200 == 0);
    worst = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      worst = std::max(worst, line_angle_degrees(pts[i].second, lines[i].truth.normal));
    measured("scan lines at 200 neighbours: worst normal angle (deg)", worst);
    CHECK(worst < 0.01);  // a plane: both fits exact up to rounding
  }
  // Two or three lines per neighbourhood (5:1) over the wavy terrain: the quadric's slope
  // across the lines stays determined (its anisotropic part is penalised; CGAL's jets of 30
  // gave 1.9 degrees on average on such lines, benchmark/README.md)
  const std::vector<scan::Sample> terrain = scan::airborne_lines(scan::wavy_terrain(), 6, 0.1, 0.5);
  std::vector<Oriented_point> t = scan::with_true_normals(terrain);
  CHECK(CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(t, pair_maps) == 0);
  double worst = 0;
  for(std::size_t i = 0; i < t.size(); ++i)
    worst = std::max(worst, line_angle_degrees(t[i].second, terrain[i].truth.normal));
  const double mean = mean_line_angle(t, [&](std::size_t i) { return terrain[i].truth.normal; });
  measured("airborne 5:1 lines, quadric normals: mean angle (deg)", mean);
  measured("airborne 5:1 lines, quadric normals: worst angle (deg)", worst);
  CHECK(mean < 0.5);  // measured 0.20 (worst 0.81)

  // A mobile profiler with range noise of 0.3 spacings (issue 44, item 5): near the track the 40
  // nearest are the query's profile and the next profiles' points at the kernel's rim, where
  // the weight vanishes: the weights leave one noisy line, whose band set the quadric's frame,
  // and the normal lay about the line, sideways (19% of them more than 60 degrees off on a
  // 16 x 16 m scan). The frame now comes from the unweighted neighbourhood there, and the
  // automatic scale (the default) climbs to a rung that spreads in two directions.
  const std::vector<scan::Sample> profiles = scan::with_range_noise(
    0.3, [](const scan::Noise& noise) { return scan::mobile_profiles(scan::wavy_terrain(), 2.0, 0.1, 0.0035, noise); });
  // the share of the normals given that are more than `degrees` off
  const auto share_off = [&](const std::vector<Oriented_point>& estimated, double degrees) {
    std::size_t off = 0, given = 0;
    for(std::size_t i = 0; i < estimated.size(); ++i)
      if(estimated[i].second != CGAL::NULL_VECTOR)
      {
        ++given;
        off += line_angle_degrees(estimated[i].second, profiles[i].truth.normal) > degrees ? 1 : 0;
      }
    return double(off) / double(given);
  };
  std::vector<Oriented_point> automatic = scan::with_true_normals(profiles);
  const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    automatic, PSC::parameters::neighbor_count(40, PSC::parameters::automatic_scale(640, pair_maps)));
  measured("noisy mobile profiles: points without a normal (of " + std::to_string(profiles.size()) + ")",
           double(without));
  measured("noisy mobile profiles: share > 60 deg", share_off(automatic, 60));
  measured("noisy mobile profiles: share > 20 deg", share_off(automatic, 20));
  CHECK(without <= profiles.size() / 1000);  // measured 1 of 19496
  CHECK(share_off(automatic, 60) < 0.002);   // measured 0.02%
  CHECK(share_off(automatic, 20) < 0.02);    // measured 0.82%
  // (with a fixed count of 40 the frame alone does not do: 8% of the normals more than 60
  // degrees off; the fit has too little weight across the line. Not asserted: the default is
  // the automatic scale)

  // The default's curvatures there: the automatic scale passes over the rungs that lie along one
  // line for the weights, the points' own spread aside, and the first pass does not read the
  // noise from a nearest half along one line (the simulated mobile scan of scan_experiments at
  // noise 0.3: mean |H - H*| 0.048 -> 0.021, APSS at 40 0.029)
  const std::vector<Estimate> e = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    automatic, PSC::parameters::neighbor_count(
                 40, PSC::parameters::automatic_scale(640, PSC::parameters::position_fit_blend(0.5, pair_maps))));
  const double error = mean_h_error(e, profiles);  // (99.99% valid)
  measured("noisy mobile profiles, default curvatures: mean |H - H*|", error);
  CHECK(error < 0.067);  // measured 0.0615 (0.0732 before)
}

TEST_CASE("estimate_oriented_normals: closed objects outward, open ones up, automatic orientation")
{
  // Closed: the Goursat sample of data/ and a torus (whose hole makes sum (p - c).n smaller)
  const std::vector<std::pair<std::string, std::vector<Oriented_point> > > closed = {
    {"Goursat 10K", read_xyz(repo_data("goursat_010000.xyz"))}, {"torus", random_torus(20000, 1.0, 0.4, 5)}};
  for(const auto& c : closed)
  {
    std::vector<Oriented_point> pts = c.second;
    std::vector<Vector> truth;
    for(Oriented_point& p : pts)
    {
      truth.push_back(p.second);
      p.second = Vector(0, 0, 0);
    }
    // upside down too: the highest point's side no longer decides
    for(double flip : {1.0, -1.0})
    {
      std::vector<Oriented_point> q = pts;
      std::vector<Vector> t = truth;
      for(std::size_t i = 0; i < q.size(); ++i)
      {
        q[i].first = Point(q[i].first.x(), flip * q[i].first.y(), flip * q[i].first.z());
        t[i] = Vector(t[i].x(), flip * t[i].y(), flip * t[i].z());
      }
      CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(q, pair_maps);
      const double outward = share_oriented(q, t);
      measured(c.first + (flip > 0 ? "" : " upside down") + ": normals outward", outward);
      CHECK(outward >= 0.99);
      // automatic: not 2.5-D, so the spanning tree
      std::vector<Oriented_point> a = q;
      CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
        a, PSC::parameters::normal_orientation(CGAL::Normal_orientation::automatic(), pair_maps));
      CHECK(share_oriented(a, t) == outward);
    }
  }
  // Open, 2.5-D: a terrain scanned from above, its lowest part first in the file; automatic
  // picks +z, the spanning tree agrees
  const std::vector<scan::Sample> terrain = scan::airborne_lines(scan::wavy_terrain(), 6, 0.1, 0.5);
  std::vector<Oriented_point> up = scan::with_true_normals(terrain), tree = up;
  std::vector<Vector> truth;
  for(const scan::Sample& s : terrain)
    truth.push_back(s.truth.normal);
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    up, PSC::parameters::normal_orientation(CGAL::Normal_orientation::automatic(), pair_maps));
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(tree, pair_maps);
  CHECK(share_oriented(up, truth) == 1.0);
  CHECK(share_oriented(tree, truth) == 1.0);
  std::size_t vertical = 0;
  for(const Oriented_point& p : up)
    vertical += PSC::is_near_vertical(p.second.x(), p.second.y(), p.second.z()) ? 1 : 0;
  CHECK(PSC::is_two_and_a_half_d(vertical, up.size()));
  CHECK(!PSC::is_two_and_a_half_d(59, 100));
  CHECK(PSC::is_two_and_a_half_d(60, 100));
  CHECK_THROWS_AS(CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
                    up, PSC::parameters::normal_orientation(
                          CGAL::Normal_orientation::automatic(),
                          PSC::parameters::tile(PSC::Tile(CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 1), pair_maps))),
                  std::invalid_argument);
}

namespace {

// The flat arrays of internal::choose_part_sign(): positions, normals, and every index as the part.
struct Flat_part
{
  std::vector<double> xyz, n;
  std::vector<std::uint32_t> part;
  void add(const Point& p, const Vector& v)
  {
    part.push_back(std::uint32_t(part.size()));
    for(int a = 0; a < 3; ++a)
    {
      xyz.push_back(p[a]);
      n.push_back(v[a]);
    }
  }
  Vector normal(std::size_t i) const { return Vector(n[3 * i], n[3 * i + 1], n[3 * i + 2]); }
};

}  // namespace

// Issue 44 item 1: a real tile (ground, roofs, walls, no pulses) came out with every ground normal
// down: the spanning tree had turned the ground against the roofs, which made one part whose
// normals cancel and whose flux is large (roofs up above, ground down below), so the closed-part
// rule took it for an object and turned it "outward". On a 2.5-D cloud a part is closed only if
// it is seen from all sides (a bottom under its top); a torus lying flat still is.
TEST_CASE("orientation: on a 2.5-D cloud, ground turned against the roofs is not a closed part, a torus lying flat is")
{
  // A block of 40 x 40 m: a building of 27 x 27 m and 15 m in its middle (roof up), the ground
  // around it (down, as the tree left it), a few wall points.
  Flat_part town;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t ground = 0;
  for(int i = 0; i < 80; ++i)
    for(int j = 0; j < 80; ++j)
    {
      const double x = i * 0.5 + 0.1 * u(rng), y = j * 0.5 + 0.1 * u(rng);
      const bool roof = x > 6.5 && x < 33.5 && y > 6.5 && y < 33.5;
      town.add(Point(x, y, roof ? 15.0 : 0.0), Vector(0, 0, roof ? 1 : -1));
      ground += roof ? 0 : 1;
    }
  for(int h = 1; h < 15; ++h)  // a few wall points, outward
    for(int k = 0; k < 8; ++k)
      town.add(Point(6.5, 8 + 3 * k, h), Vector(-1, 0, 0));
  CHECK_FALSE(PSC::internal::choose_part_sign(town.part, town.xyz, town.n, true));
  std::size_t up = 0, vertical = 0;
  for(std::size_t i = 0; i < town.part.size(); ++i)
  {
    const Vector v = town.normal(i);
    if(PSC::is_near_vertical(v.x(), v.y(), v.z()))
    {
      ++vertical;
      up += v.z() > 0 ? 1 : 0;
    }
  }
  CHECK(vertical == 6400);
  CHECK(up == vertical);
  CHECK(ground > 3000);

  // A torus lying flat, sampled all round (67% of its normals near-vertical, so 2.5-D), normals
  // given inward: seen from all sides, so closed, turned outward, bottom down.
  Flat_part torus;
  for(const Oriented_point& p : random_torus(20000, 1.0, 0.4, 5))
    torus.add(p.first, -p.second);
  CHECK(PSC::internal::choose_part_sign(torus.part, torus.xyz, torus.n, true));
  std::size_t outward = 0;
  const std::vector<Oriented_point> truth = random_torus(20000, 1.0, 0.4, 5);
  for(std::size_t i = 0; i < truth.size(); ++i)
    outward += torus.normal(i) * truth[i].second > 0 ? 1 : 0;
  CHECK(outward == truth.size());
}

namespace {

// The graph of internal::repair_closed_part() over points on a sphere: each point's 12 nearest
// (records, the nearest first), made symmetric by internal::normal_graph() as the spanning tree
// makes it.
struct Sphere_graph
{
  std::vector<PSC::internal::Normal_record> records;
  std::vector<std::size_t> offset;
  std::vector<std::uint32_t> adjacency;

  explicit Sphere_graph(const std::vector<Oriented_point>& ball) : records(ball.size())
  {
    constexpr std::size_t k = PSC::internal::normal_graph_degree;
    for(std::size_t i = 0; i < ball.size(); ++i)
    {
      std::vector<std::pair<double, std::uint32_t> > d;
      for(std::size_t j = 0; j < ball.size(); ++j)
        if(j != i)
          d.emplace_back(CGAL::squared_distance(ball[i].first, ball[j].first), std::uint32_t(j));
      std::partial_sort(d.begin(), d.begin() + k, d.end());
      for(std::size_t e = 0; e < k; ++e)
        records[i].neighbor[e] = d[e].second;
      records[i].degree = std::uint8_t(k);
      records[i].status = CGAL::Curvature_estimate_status::VALID;
    }
    PSC::internal::normal_graph(records, offset, adjacency);
  }
};

}  // namespace

// Issue 44 item 2: pieces of a closed part that the tree entered across a thin part or a sharp
// turn are turned back by the winding number of the rest, and the small ones by their neighbours
// along the surface (internal::repair_closed_part()).
TEST_CASE("orientation: a piece of a closed part turned inward is turned back, the others are left")
{
  const std::vector<Oriented_point> ball = sphere(6000, 1.0);
  const Sphere_graph graph(ball);
  const auto outward = [&](const Flat_part& flat) {
    std::size_t count = 0;
    for(std::size_t i = 0; i < ball.size(); ++i)
      count += flat.normal(i) * ball[i].second > 0 ? 1 : 0;
    return count;
  };
  // three pieces: a cap around +x given inward, a cap around -x given outward, the rest
  std::vector<std::uint32_t> piece(ball.size(), 0);
  for(std::size_t i = 0; i < ball.size(); ++i)
    piece[i] = ball[i].first.x() > 0.7 ? 1 : ball[i].first.x() < -0.7 ? 2 : 0;
  Flat_part caps;
  for(std::size_t i = 0; i < ball.size(); ++i)
    caps.add(ball[i].first, piece[i] == 1 ? -ball[i].second : ball[i].second);
  PSC::internal::repair_closed_part(caps.part, piece, graph.records, graph.offset, graph.adjacency, caps.xyz, caps.n);
  CHECK(outward(caps) == ball.size());

  // Beside the caps, 2060 pieces of one point each, the last 12 inward: the winding number tests
  // the 2048 largest pieces only (ties in order), so those 12 are decided by their neighbours
  // in the larger pieces and the ones tested before them (a build without that step leaves them
  // inward)
  std::uint32_t next = 3;
  std::vector<std::size_t> single;
  for(std::size_t i = 0; i < ball.size() && single.size() < 2060; ++i)
    if(piece[i] == 0 && i % 2 == 1)
    {
      piece[i] = next++;
      single.push_back(i);
    }
  REQUIRE(single.size() == 2060);
  Flat_part dots;
  for(std::size_t i = 0; i < ball.size(); ++i)
    dots.add(ball[i].first, piece[i] == 1 ? -ball[i].second : ball[i].second);
  for(std::size_t s = single.size() - 12; s < single.size(); ++s)
    for(int a = 0; a < 3; ++a)
      dots.n[3 * single[s] + a] = -dots.n[3 * single[s] + a];
  PSC::internal::repair_closed_part(dots.part, piece, graph.records, graph.offset, graph.adjacency, dots.xyz, dots.n);
  CHECK(outward(dots) == ball.size());
  // A small piece is turned only where 90% of the weight of its neighbours' agreement is against
  // it: on a plane, a piece of 200 points facing down (the largest), one of 150 facing up, and two
  // single points facing up, one with 7 neighbours of the first and 3 of the second (kept), one
  // with 10 of the first (turned). No record has a neighbour, so no spacing and no winding number.
  Flat_part plane;
  std::vector<std::uint32_t> plane_piece;
  for(std::uint32_t i = 0; i < 352; ++i)
  {
    plane.add(Point(i % 20, i / 20, 0), Vector(0, 0, i < 200 ? -1 : 1));
    plane_piece.push_back(i < 200 ? 0 : i < 350 ? 1 : i - 348);
  }
  const std::vector<std::vector<std::uint32_t> > around = {{0, 1, 2, 3, 4, 5, 6, 200, 201, 202},
                                                           {10, 11, 12, 13, 14, 15, 16, 17, 18, 19}};
  std::vector<std::size_t> offset(353, 0);
  std::vector<std::uint32_t> adjacency;
  for(std::uint32_t i = 0; i < 352; ++i)
  {
    if(i >= 350)
      adjacency.insert(adjacency.end(), around[i - 350].begin(), around[i - 350].end());
    offset[i + 1] = adjacency.size();
  }
  const std::vector<PSC::internal::Normal_record> no_records(352);
  PSC::internal::repair_closed_part(plane.part, plane_piece, no_records, offset, adjacency, plane.xyz, plane.n);
  CHECK(plane.normal(350).z() > 0);  // 70% against: kept
  CHECK(plane.normal(351).z() < 0);  // all against: turned
  CHECK(plane.normal(0).z() < 0);
  CHECK(plane.normal(200).z() > 0);
}

namespace {

// A flattened ellipsoid of semi-axes 1, 0.6 and `t` (a thin plate with a knife-edge rim), `n`
// points at random uniformly on its surface, with its outward unit normals.
std::vector<Oriented_point> thin_plate(std::size_t n, double t, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uniform;
  const double axis[3] = {1, 0.6, t};
  const double largest = std::max({axis[1] * axis[2], axis[0] * axis[2], axis[0] * axis[1]});
  std::vector<Oriented_point> pts;
  while(pts.size() < n)
  {
    double u[3] = {gauss(rng), gauss(rng), gauss(rng)};
    const double l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for(double& x : u)
      x /= l;
    // the area element of the map u -> axis * u, relative to its largest
    const double w = std::sqrt(std::pow(u[0] * axis[1] * axis[2], 2) + std::pow(u[1] * axis[0] * axis[2], 2) +
                               std::pow(u[2] * axis[0] * axis[1], 2));
    if(uniform(rng) * largest >= w)
      continue;
    const Vector g(u[0] / axis[0], u[1] / axis[1], u[2] / axis[2]);
    pts.emplace_back(Point(axis[0] * u[0], axis[1] * u[1], axis[2] * u[2]), g / std::sqrt(g * g));
  }
  return pts;
}

}  // namespace

// Issue 44 item 2: on a thin part the spanning tree reaches the far sheet round a knife-edge
// rim (its radius of curvature t^2 far below the spacing, the normals there the mid-plane's),
// with the near sheet's side: both faces of a plate of 1 x 0.6 x 0.05 came out pointing up, 49.5%
// outward. The parity of the surface crossings along each normal's line, outward even and
// inward odd, turns the far sheet point by point (internal::repair_by_crossing_parity()).
TEST_CASE("orientation: both faces of a thin plate outward, by the parity of the crossings along the normals")
{
  const std::vector<Oriented_point> plate = thin_plate(8000, 0.05, 3);
  const Sphere_graph graph(plate);
  const auto reach = [&](std::uint32_t i) {
    double r = 0;
    for(std::size_t e = 0; e < graph.records[i].degree; ++e)
      r = std::max(r, std::sqrt(CGAL::squared_distance(plate[i].first, plate[graph.records[i].neighbor[e]].first)));
    return r;
  };
  const auto neighbors = [&](std::uint32_t i, const auto& f) {
    for(std::size_t a = graph.offset[i]; a < graph.offset[i + 1]; ++a)
      f(graph.adjacency[a]);
  };
  std::vector<signed char> vote(plate.size(), 0);
  const auto outward = [&](const Flat_part& flat, bool upper_only) {
    std::size_t count = 0, of = 0;
    for(std::size_t i = 0; i < plate.size(); ++i)
      if(!upper_only || plate[i].first.z() > 0)
      {
        ++of;
        count += flat.normal(i) * plate[i].second > 0 ? 1 : 0;
      }
    return double(count) / double(of);
  };
  // the tree's error: the lower face given the upper face's side
  Flat_part flat;
  for(const Oriented_point& p : plate)
    flat.add(p.first, p.first.z() < 0 ? -p.second : p.second);
  REQUIRE(outward(flat, false) < 0.51);
  const std::size_t turned =
    PSC::internal::repair_by_crossing_parity(flat.part, flat.xyz, flat.n, neighbors, reach, vote);
  measured("thin plate, lower face given inward: share outward after the parity", outward(flat, false));
  CHECK(outward(flat, false) >= 0.95);  // (measured 0.964: the rest at the rim, whose rays graze it)
  CHECK(outward(flat, true) >= 0.995);  // the upper face left as it was (4 of its points turned, at the rim)
  CHECK(turned > 3500);
  CHECK(std::count(vote.begin(), vote.end(), 0) == std::ptrdiff_t(vote.size()));  // scratch left zero
  // right already: almost nothing turned (3 of 8000 measured, at the rim); an open surface (the
  // upper half alone): not seen from all sides, nothing checked
  Flat_part right, open;
  for(const Oriented_point& p : plate)
    right.add(p.first, p.second);
  CHECK(PSC::internal::repair_by_crossing_parity(right.part, right.xyz, right.n, neighbors, reach, vote) <= 8);
  for(std::size_t i = 0; i < plate.size(); ++i)
    open.add(plate[i].first, -plate[i].second);  // every normal inward ...
  std::vector<std::uint32_t> upper;
  for(std::uint32_t i = 0; i < plate.size(); ++i)
    if(plate[i].first.z() > 0)
      upper.push_back(i);
  open.part = upper;  // ... of the upper face only, alone: undecided, left
  CHECK(PSC::internal::repair_by_crossing_parity(open.part, open.xyz, open.n, neighbors, reach, vote) == 0);

  // The whole estimation from the positions alone
  std::vector<Oriented_point> estimated = plate;
  std::vector<Vector> truth;
  for(Oriented_point& p : estimated)
  {
    truth.push_back(p.second);
    p.second = CGAL::NULL_VECTOR;
  }
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(estimated, pair_maps);
  measured("thin plate, normals estimated: share outward", share_oriented(estimated, truth));
  CHECK(share_oriented(estimated, truth) >= 0.93);  // (measured 0.951; 0.5 without the parity)
}
