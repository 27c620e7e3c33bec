// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Neighbourhoods by count (issue 3): the library's neighbor_count named parameter and its driver
// for_each_neighborhood_knn against brute force, ties and extreme scales; the automatic scale's rungs
// bit for bit the driver's neighbourhoods; the grid's radix sort. Built into the test_tool program.

#include "test_tool_support.h"

using namespace psc_tool_test;

// =======================================================================================
// Neighbourhoods by count: the library

TEST_CASE("neighbor_count: the neighbourhood of each point is the ball of radius "
          "(1 + 2^-20) d_k, d_k brute-force distance to its k-th nearest (itself first)")
{
  // A cloud with density varying 1:10, some duplicated points and an unusable point.
  std::vector<Oriented_point> pts = varying_density(1500);
  for(std::size_t i = 0; i < 20; ++i)
    pts.push_back(pts[37 * i]);  // exact duplicates: ties at distance 0
  pts.emplace_back(Point(1, 1, std::numeric_limits<double>::quiet_NaN()), Vector(0, 0, 1));
  // isolated points far from the rest and from each other: the grid cannot serve them, the
  // k-d tree does (knn_neighborhoods.h)
  for(int i = 0; i < 5; ++i)
    pts.insert(pts.begin() + 100 * i, Oriented_point(Point(30 + 7 * i, -20, 5 * i), Vector(0, 0, 1)));
  const std::size_t k = 12;

  struct Seen
  {
    double radius = 0, max_q2 = 0, sum[3] = {0, 0, 0};
    std::size_t size = 0;
  };
  std::vector<Seen> seen(pts.size());
  // distinct indices from the worker threads: no lock needed
  auto visit = [&](std::size_t i, const PSC::internal::Neighborhood& nb) {
    Seen& s = seen[i];
    s.radius = nb.radius;
    s.size = nb.size;
    for(std::size_t j = 0; j < nb.size; ++j)
    {
      s.max_q2 = std::max(s.max_q2, nb.qx[j] * nb.qx[j] + nb.qy[j] * nb.qy[j] + nb.qz[j] * nb.qz[j]);
      s.sum[0] += nb.qx[j];
      s.sum[1] += nb.qy[j];
      s.sum[2] += nb.qz[j];
    }
  };
  const std::vector<CGAL::Curvature_estimate_status> status =
    PSC::internal::for_each_neighborhood_knn<CGAL::Parallel_tag>(pts, Point_map(), Normal_map(), k,
                                                                 PSC::internal::Neighborhood_options(), visit);
  CHECK(status.back() == CGAL::Curvature_estimate_status::NON_FINITE_POINT);
  const std::size_t usable = pts.size() - 1;
  std::size_t not_visited = 0, wrong_radius = 0, wrong_size = 0, outside = 0, wrong_members = 0;
  for(std::size_t i = 0; i < usable; ++i)
  {
    not_visited += status[i] != CGAL::Curvature_estimate_status::VALID;
    const Seen& s = seen[i];
    std::vector<double> d2;
    for(std::size_t j = 0; j < usable; ++j)
      d2.push_back(CGAL::squared_distance(pts[i].first, pts[j].first));
    std::vector<double> sorted = d2;
    std::sort(sorted.begin(), sorted.end());
    // d_k > 0 here: no point has k copies
    const double expected_radius = (1 + 1.0 / 1048576) * std::sqrt(sorted[k - 1]);
    // same doubles, same operations: equal up to the last bit
    wrong_radius += std::abs(s.radius - expected_radius) > 4e-16 * expected_radius;
    // the ball of the reported radius, brute force: its size and the sum of its scaled offsets
    std::size_t inside = 0;
    double sum[3] = {0, 0, 0};
    for(std::size_t j = 0; j < usable; ++j)
      if(d2[j] < s.radius * s.radius)
      {
        ++inside;
        sum[0] += (pts[j].first.x() - pts[i].first.x()) / s.radius;
        sum[1] += (pts[j].first.y() - pts[i].first.y()) / s.radius;
        sum[2] += (pts[j].first.z() - pts[i].first.z()) / s.radius;
      }
    wrong_size += (s.size != inside || inside < k);
    outside += !(s.max_q2 < 1);
    // same members: the sums of ~12 offsets of norm < 1 agree up to rounding (1e-12)
    for(int a = 0; a < 3; ++a)
      wrong_members += std::abs(s.sum[a] - sum[a]) > 1e-12;
  }
  CHECK(not_visited == 0);
  CHECK(wrong_radius == 0);
  CHECK(wrong_size == 0);
  CHECK(outside == 0);
  CHECK(wrong_members == 0);
}

// The automatic scale's rungs (automatic_scale.h) are taken from the neighbourhood of a larger
// count; each must be the neighbourhood the driver gives for the rung's count, bit for bit, so
// that an estimate at a rung is the one a run at that count would give (grid and tree, ties).
TEST_CASE("automatic scale: a rung is bit for bit the driver's neighbourhood of its count")
{
  std::vector<Oriented_point> pts = varying_density(1500);
  for(std::size_t i = 0; i < 20; ++i)
    pts.push_back(pts[37 * i]);  // exact duplicates
  for(int i = 0; i < 5; ++i)     // isolated points: the k-d tree serves them
    pts.insert(pts.begin() + 100 * i, Oriented_point(Point(30 + 7 * i, -20, 5 * i), Vector(0, 0, 1)));
  for(int i = 0; i < 30; ++i)  // a regular grid: equidistant neighbours, ties at the k-th
    for(int j = 0; j < 30; ++j)
      pts.emplace_back(Point(-20 + 0.1 * i, 0.1 * j, 0), Vector(0, 0, 1));
  struct Seen
  {
    double radius = 0;
    std::vector<double> q;
    std::vector<std::uint32_t> input;
  };
  const auto record = [](Seen& s, const PSC::internal::Neighborhood& nb) {
    s.radius = nb.radius;
    for(std::size_t j = 0; j < nb.size; ++j)
    {
      s.q.insert(s.q.end(), {nb.qx[j], nb.qy[j], nb.qz[j]});
      s.input.push_back(nb.input_index[nb.index[j]]);
    }
  };
  for(std::size_t k : {20, 40})
  {
    std::vector<Seen> direct(pts.size()), rung(pts.size());
    PSC::internal::for_each_neighborhood_knn<CGAL::Parallel_tag>(
      pts, Point_map(), Normal_map(), k, PSC::internal::Neighborhood_options(),
      [&](std::size_t i, const PSC::internal::Neighborhood& nb) { record(direct[i], nb); });
    PSC::internal::for_each_neighborhood_knn<CGAL::Parallel_tag>(
      pts, Point_map(), Normal_map(), 8 * k, PSC::internal::Neighborhood_options(),
      [&](std::size_t i, const PSC::internal::Neighborhood& whole) {
        PSC::internal::Neighbor_offsets offsets;
        offsets.assign(whole);
        PSC::internal::Distance_ranks ranks;
        ranks.assign(offsets.d2, 1.0 / (offsets.limit * offsets.limit));
        const double d2_k = ranks.kth(k);
        if(d2_k == 0)
          return;  // (copies: the ladder has no rung there)
        PSC::internal::Sub_neighborhood sub;
        sub.take(whole, PSC::internal::Scale_ladder::rung_radius(offsets, d2_k), offsets);
        sub.take_attributes(whole);
        record(rung[i], sub.nb);
      });
    std::size_t compared = 0, differ = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
      if(!rung[i].input.empty())
      {
        ++compared;
        differ += rung[i].radius != direct[i].radius || rung[i].q != direct[i].q || rung[i].input != direct[i].input;
      }
    INFO("k = " << k);
    CHECK(compared > pts.size() - 100);
    CHECK(differ == 0);
  }
}

// parameters::scale_choices: the normals' automatic scale records the curvatures' choices where it
// climbs, and the curvatures estimate those points from the neighbourhood of their count; the
// estimates must be the ladder's, bit for bit (a noisy scan, where most points climb; the
// position fit blended in or not; a point whose normal is unusable, so that its neighbours'
// records do not fit their neighbourhoods and the ladder decides there).
TEST_CASE("automatic scale: the curvatures from the normals' scale choices are the ladder's, bit for bit")
{
  namespace P = PSC::parameters;
  // the airborne lines with each setting; a noisy mobile scan, whose first and last profiles take
  // the quadric's curvatures (automatic_scale_quadric_agreement), with the tool's blend
  for(int cloud = 0; cloud < 2; ++cloud)
  {
    scan::Noise noise;
    std::vector<scan::Sample> samples;
    if(cloud == 0)
    {
      noise.range_sigma = 0.03;
      samples = scan::airborne_lines(scan::wavy_terrain(), 4, 0.1, 0.25, noise);
    }
    else
      samples = scan::with_range_noise(
        0.3, [](const scan::Noise& n) { return scan::mobile_profiles(scan::wavy_terrain(), 1.5, 0.1, 0.0035, n); });
    INFO((cloud == 0 ? "airborne lines" : "mobile profiles"));
    Point_set ps;
    ps.add_normal_map();
    for(const scan::Sample& s : samples)
      ps.insert(s.p);
    PSC::Scale_choices choices;
    CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
      ps, P::neighbor_count(
            40, P::automatic_scale(640, P::normal_orientation(CGAL::Normal_orientation::along_vector(0, 0, 1),
                                                              P::scale_choices(choices)))));
    REQUIRE(choices.size() == ps.size());
    std::size_t recorded = 0;
    for(std::size_t i = 0; i < ps.size(); ++i)
      recorded += choices.records().of(i) && choices.records().of(i)->count > 0 ? 1 : 0;
    INFO(recorded << " of " << ps.size() << " points with a choice");
    CHECK(recorded > ps.size() / 2);
    const auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    const auto same_vector = [&](const Vector& a, const Vector& b) {
      return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z());
    };
    for(int unusable = 0; unusable < 2; ++unusable)
      for(double blend : {0.0, 0.5})
      {
        if(cloud == 1 && (unusable || blend == 0.0))
          continue;
        if(unusable)
          ps.normal(*(ps.begin() + 1234)) = CGAL::NULL_VECTOR;
        INFO("position blend " << blend << (unusable ? ", a point without a usable normal" : ""));
        const auto np = P::neighbor_count(40, P::automatic_scale(640, P::position_fit_blend(blend)));
        const std::vector<Estimate> ladder = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ps, np);
        const std::vector<Estimate> chosen =
          CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(ps, P::scale_choices(choices, np));
        const std::vector<Estimate> sequential =
          CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(ps, P::scale_choices(choices, np));
        std::size_t differ = 0, climbed = 0;
        for(std::size_t i = 0; i < ps.size(); ++i)
          for(const std::vector<Estimate>* e : {&chosen, &sequential})
          {
            const Estimate &a = ladder[i], &b = (*e)[i];
            differ += !(a.status == b.status && a.neighbor_count == b.neighbor_count &&
                        same(a.mean_curvature, b.mean_curvature) && same(a.min_curvature, b.min_curvature) &&
                        same(a.max_curvature, b.max_curvature) && same(a.gaussian_curvature, b.gaussian_curvature) &&
                        same(a.mean_curvature_error, b.mean_curvature_error) &&
                        same(a.normal_coherence, b.normal_coherence) && same_vector(a.normal, b.normal) &&
                        same_vector(a.min_direction, b.min_direction) && same_vector(a.max_direction, b.max_direction));
            climbed += a.neighbor_count > 40 ? 1 : 0;
          }
        CHECK(climbed > ps.size() / 2);
        CHECK(differ == 0);
      }
  }
}

TEST_CASE("neighbor_count: ties, k above the number of points, coincident points")
{
  const auto count_of = [](const std::vector<Oriented_point>& pts, std::size_t k) {
    const std::vector<Estimate> e =
      CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(k, pair_maps));
    std::vector<std::size_t> counts;
    for(const Estimate& x : e)
      counts.push_back(x.neighbor_count);
    return std::make_pair(counts, e);
  };
  // Regular grid of spacing 0.1 (coordinates 0.1 i are not exact: the distances of the 4
  // axis neighbours differ in the last bits). An interior point has itself, 4 neighbours at
  // h and 4 at h sqrt(2): k = 5 gives exactly 5, k = 6 takes the whole tied ring, 9.
  std::vector<Oriented_point> grid;
  for(int i = 0; i < 15; ++i)
    for(int j = 0; j < 15; ++j)
      grid.emplace_back(Point(0.1 * i, 0.1 * j, 0), Vector(0, 0, 1));
  const std::size_t centre = 7 * 15 + 7;
  CHECK(count_of(grid, 5).first[centre] == 5);
  CHECK(count_of(grid, 6).first[centre] == 9);
  CHECK(count_of(grid, 9).first[centre] == 9);
  CHECK(count_of(grid, 10).first[centre] == 13);  // next ring: 4 points at 2h
  // A plane: valid, zero curvature, at every point (k = 13: the default minimum is 12).
  const auto plane_run = count_of(grid, 13).second;
  std::size_t flat = 0;
  for(const Estimate& e : plane_run)
    flat += e.is_valid() && std::abs(e.mean_curvature) < 1e-9 && std::abs(e.gaussian_curvature) < 1e-9;
  CHECK(flat == grid.size());

  // k larger than the number of usable points: every usable point is everybody's neighbour.
  std::vector<Oriented_point> small = sphere(30, 1.0);
  small.emplace_back(Point(0, 0, 0), Vector(0, 0, 0));  // unusable: nobody's neighbour
  const auto all = count_of(small, 1000);
  for(std::size_t i = 0; i < 30; ++i)
    CHECK(all.first[i] == 30);
  CHECK(all.second[30].status == CGAL::Curvature_estimate_status::INVALID_NORMAL);

  // Each point 5 times, k = 3: d_k = 0, the scale comes from the nearest other point, whose
  // 5 copies come along: at least 10 points.
  std::vector<Oriented_point> copies;
  for(const Oriented_point& p : sphere(200, 1.0))
    for(int c = 0; c < 5; ++c)
      copies.push_back(p);
  const auto dup = count_of(copies, 3);
  CHECK(*std::min_element(dup.first.begin(), dup.first.end()) >= 10);

  // Every point at the same place: r = 1, the fit is degenerate, nothing crashes.
  const std::vector<Oriented_point> one_place(10, Oriented_point(Point(1, 2, 3), Vector(0, 0, 1)));
  for(const Estimate& e : count_of(one_place, 4).second)
  {
    CHECK(e.neighbor_count == 10);
    CHECK(!e.is_valid());
  }
}

TEST_CASE("neighbor_count: at scales down to 1e-158 and up to 1e8, at least k neighbours, d_k from brute force")
{
  // At a cell side below about 4e-154, 32 / side² overflows (the grid's histogram selection);
  // at 1e-158 squared distances are subnormal and (1 + 2^-20)² is lost to rounding.
  for(double scale : {1e8, 1e-8, 1e-153, 1e-155, 1e-158})
  {
    INFO("scale " << scale);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Oriented_point> pts;
    for(int i = 0; i < 2000; ++i)
      pts.emplace_back(Point(scale * u(rng), scale * u(rng), 0), Vector(0, 0, 1));
    const std::size_t k = 12;
    std::vector<double> radius(pts.size(), -1);
    std::vector<std::size_t> size(pts.size(), 0);
    auto visit = [&](std::size_t i, const PSC::internal::Neighborhood& nb) {
      radius[i] = nb.radius;
      size[i] = nb.size;
    };
    PSC::internal::for_each_neighborhood_knn<CGAL::Parallel_tag>(pts, Point_map(), Normal_map(), k,
                                                                 PSC::internal::Neighborhood_options(), visit);
    std::size_t too_small = 0, wrong_radius = 0;
    for(std::size_t i = 0; i < pts.size(); i += 7)
    {
      too_small += size[i] < k;
      std::vector<double> d2;
      for(const Oriented_point& p : pts)
        d2.push_back(CGAL::squared_distance(pts[i].first, p.first));
      std::nth_element(d2.begin(), d2.begin() + (k - 1), d2.end());
      const double expected = (1 + 1.0 / 1048576) * std::sqrt(d2[k - 1]);
      wrong_radius += !(std::abs(radius[i] - expected) <= 4e-16 * expected);
    }
    CHECK(too_small == 0);
    CHECK(wrong_radius == 0);
  }
}

TEST_CASE("neighbor_count: density varying 1:10, at least k neighbours everywhere, exact "
          "sphere curvature, Sequential == Parallel, cancellation")
{
  const std::vector<Oriented_point> pts = varying_density(20000);
  // The cloud's density really varies 1:10: with a fixed radius, the points of a strip at the
  // dense end have many times the neighbours of those of a strip at the sparse end.
  {
    const std::vector<Estimate> e = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 0.08, pair_maps);
    double sparse = 0, dense = 0;
    std::size_t n_sparse = 0, n_dense = 0;
    for(std::size_t i = 0; i < pts.size(); ++i)
    {
      const double x = pts[i].first.x(), y = pts[i].first.y();
      if(y < 0.1 || y > 1.9)
        continue;  // away from the borders
      if(x > 0.1 && x < 0.3)
      {
        sparse += e[i].neighbor_count;
        ++n_sparse;
      }
      if(x > 3.7 && x < 3.9)
      {
        dense += e[i].neighbor_count;
        ++n_dense;
      }
    }
    const double ratio = (dense / n_dense) / (sparse / n_sparse);
    measured("neighbour count ratio dense/sparse strips, fixed radius 0.08", ratio);
    // the density 1 + 9 x/4 is linear, so a ball's count is proportional to the density at
    // its centre: 1.45 and 9.55 at the strips' middles, ratio 6.6; measured 6.25 (sampling
    // noise of a few hundred points per strip, slightly different slopes of the surface).
    // +-15% around 6.6 says "about 1:10 end to end", and fails for a uniform cloud
    CHECK(ratio > 0.85 * 6.6);
    CHECK(ratio < 1.15 * 6.6);
  }
  const std::size_t k = 20;
  std::vector<double> progress;
  const auto np = PSC::parameters::neighbor_count(k, pair_maps.callback(std::function<bool(double)>([&](double f) {
    progress.push_back(f);
    return true;
  })));
  const std::vector<Estimate> seq = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, np);
  const std::size_t seq_reports = progress.size();
  const std::vector<Estimate> par = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(pts, np);
  const std::vector<Estimate> apss_seq =
    CGAL::estimate_apss_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(k, pair_maps));
  const std::vector<Estimate> apss_par =
    CGAL::estimate_apss_curvatures<CGAL::Parallel_tag>(pts, PSC::parameters::neighbor_count(k, pair_maps));
  std::size_t exactly_k = 0, valid = 0, different = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    // random positions: no ties, so exactly k points in every ball
    exactly_k += (seq[i].neighbor_count == k);
    valid += seq[i].is_valid();
    different += !same(seq[i], par[i]) + !same(apss_seq[i], apss_par[i]);
  }
  CHECK(exactly_k == pts.size());
  CHECK(valid == pts.size());
  CHECK(different == 0);
  // progress at most 1% of the points apart (the documented rule), ending at 1
  REQUIRE(seq_reports >= 100);
  double widest_step = progress[0];
  for(std::size_t i = 1; i < seq_reports; ++i)
    widest_step = std::max(widest_step, progress[i] - progress[i - 1]);
  CHECK(widest_step <= 0.01 + 1e-12);
  CHECK(progress[seq_reports - 1] == 1.0);

  // Cancelled at the first report: the points of the first batch are computed as before, the
  // rest is NOT_COMPUTED with NaN (the paper's variant: one pass, whose first report follows
  // the first batch of estimates; the default's first pass computes sample weights).
  const auto paper = PSC::parameters::aso_variant(CGAL::Aso_variant::PAPER, pair_maps);
  const std::vector<Estimate> seq_paper =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(k, paper));
  double first_report = -1;
  const std::vector<Estimate> cut = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    pts, PSC::parameters::neighbor_count(k, paper.callback(std::function<bool(double)>([&first_report](double f) {
      first_report = f;
      return false;
    }))));
  const std::size_t first_batch = static_cast<std::size_t>(std::lround(first_report * 20000));
  CHECK(first_report * 20000 == Approx(double(first_batch)).epsilon(1e-12));
  CHECK(first_batch >= 1);
  CHECK(first_batch <= 200);  // at most 1%
  std::size_t not_computed = 0, unchanged = 0;
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(cut[i].status == CGAL::Curvature_estimate_status::NOT_COMPUTED)
      not_computed += std::isnan(cut[i].mean_curvature) && cut[i].neighbor_count == 0;
    else
      unchanged += same(cut[i], seq_paper[i]);
  CHECK(not_computed == 20000 - first_batch);
  CHECK(unchanged == first_batch);

  // On a sphere the ASO is exact whatever the neighbourhood: by count too.
  const std::vector<Estimate> s = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    sphere(3000, 2.0), PSC::parameters::neighbor_count(30, pair_maps));
  double worst = 0;
  for(const Estimate& e : s)
    worst =
      std::max(worst, e.is_valid() ? std::max(std::abs(e.min_curvature - 0.5), std::abs(e.max_curvature - 0.5)) : 1.0);
  measured("sphere R=2, 30 nearest: max |k - 1/2|", worst);
  // the fit is exact on a sphere: measured 3.6e-15 (rounding); 1e-12 allows 300x more
  // rounding (other compilers, FMA) and still fails on any real error
  CHECK(worst < 1e-12);

  CHECK_THROWS_AS(
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(0, pair_maps)),
    std::invalid_argument);
}

TEST_CASE("grid sort: the radix sort orders (cell key, index) pairs exactly as std::sort")
{
  // The driver sorts the points into its grid with sort_by_key_then_index(); the neighbours'
  // order, hence every sum, depends on it being the order of std::sort on the pairs (key, then
  // input index). Small inputs (std::sort itself), few distinct keys (long runs of ties), keys
  // of 20 bits (two digits) and of 62 bits (six digits, a very sparse cloud), unsorted keys;
  // 300000 pairs make 5 chunks.
  typedef PSC::internal::Neighbor_grid::Keyed_index Keyed;
  std::mt19937_64 rng(7);
  for(const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(100), std::size_t(2047), std::size_t(2048),
                             std::size_t(50000), std::size_t(300000)})
    for(const int bits : {1, 4, 20, 62})
    {
      std::vector<Keyed> keyed(n);
      for(std::size_t i = 0; i < n; ++i)
        keyed[i] = Keyed(rng() >> (64 - bits), static_cast<std::uint32_t>(i));
      std::vector<Keyed> expected = keyed, scratch;
      std::sort(expected.begin(), expected.end());
      INFO("n = " << n << ", key bits = " << bits);
      // chunks in order, in reverse order and on TBB's threads: the same order
      std::vector<Keyed> reversed = keyed, parallel = keyed;
      PSC::internal::sort_by_key_then_index(keyed, scratch);
      CHECK(keyed == expected);
      PSC::internal::sort_by_key_then_index(reversed, scratch, [](std::size_t chunks, const auto& f) {
        for(std::size_t c = chunks; c > 0; --c)
          f(c - 1);
      });
      CHECK(reversed == expected);
#ifdef CGAL_LINKED_WITH_TBB
      PSC::internal::sort_by_key_then_index(parallel, scratch, [](std::size_t chunks, const auto& f) {
        tbb::parallel_for(std::size_t(0), chunks, [&f](std::size_t c) { f(c); });
      });
      CHECK(parallel == expected);
#endif
    }
}
