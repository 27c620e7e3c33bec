// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of issue 3: neighbourhoods by count (the library's neighbor_count named parameter and
// its driver for_each_neighborhood_knn) and the command-line tool point_set_curvatures, run as
// a separate process (its path comes from tools/CMakeLists.txt as PSC_TOOL_PATH): output
// files read back with CGAL's PLY reader, every error case (exit status 2, one line on
// stderr naming the file or option, no output file), the normals estimated for files without.

#include "scan_simulator.h"
#include "test_support.h"

#include "progress_line.h"
#include "tile_pass_progress.h"

#include <CGAL/Point_set_curvatures/estimators.h>
#include <CGAL/Point_set_curvatures/field_descriptions.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/estimate_oriented_normals.h>
#include <CGAL/estimate_pss_curvatures.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <catch2/catch.hpp>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace psc_test;
namespace PSC = CGAL::Point_set_curvatures;
namespace fs = std::filesystem;
typedef CGAL::Curvature_estimate<Kernel> Estimate;
typedef CGAL::Point_set_3<Point, Vector> Point_set;

namespace {

const auto pair_maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());

// Prints a measured value when PSC_TEST_PRINT is set, to re-measure the numbers quoted in the
// comments next to the tolerances.
void measured(const std::string& what, double value)
{
  if(std::getenv("PSC_TEST_PRINT"))
    std::printf("[measured] %-70s %.4g\n", what.c_str(), value);
}

// ---------------------------------------------------------------------------------------
// Clouds

// Height field z = 0.2 sin(x) cos(y) over [0, 4] x [0, 2] whose sampling density grows
// linearly from 1 to 10 along x (inverse transform sampling of the density 1 + 9 x/4).
// Exact unit normals (pointing to +z). Random positions: no two distances tie.
std::vector<Oriented_point> varying_density(std::size_t n, unsigned seed = 7)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<Oriented_point> pts;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double t = (-1 + std::sqrt(1 + 99 * uniform(rng))) / 9;  // density 1 + 9t on [0, 1]
    const double x = 4 * t, y = 2 * uniform(rng);
    const double z = 0.2 * std::sin(x) * std::cos(y);
    const Vector g(-0.2 * std::cos(x) * std::cos(y), 0.2 * std::sin(x) * std::sin(y), 1);
    pts.emplace_back(Point(x, y, z), g / std::sqrt(g.squared_length()));
  }
  return pts;
}

// ---------------------------------------------------------------------------------------
// Files and processes

// A fresh folder for this process, removed at exit.
const fs::path& work_dir()
{
  static struct Dir
  {
    fs::path path;
    Dir()
    {
      path = fs::temp_directory_path() / ("psc_test_tool_" + std::to_string(::getpid()));
      fs::remove_all(path);
      fs::create_directories(path);
    }
    ~Dir() { fs::remove_all(path); }
  } dir;
  return dir.path;
}

std::string file(const std::string& name) { return (work_dir() / name).string(); }

void write_text(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_xyz(const std::string& path, const std::vector<Oriented_point>& pts, bool normals = true)
{
  std::ofstream out(path);
  out.precision(17);
  for(const Oriented_point& p : pts)
  {
    out << p.first.x() << " " << p.first.y() << " " << p.first.z();
    if(normals)
      out << " " << p.second.x() << " " << p.second.y() << " " << p.second.z();
    out << "\n";
  }
}

struct Run
{
  int status = -1;
  std::string out, err;
};

// Runs the tool with `args` (already quoted where needed).
Run run_tool(const std::string& args)
{
  const std::string out = file("stdout.txt"), err = file("stderr.txt");
  const std::string command = std::string("'") + PSC_TOOL_PATH + "' " + args + " > '" + out + "' 2> '" + err + "'";
  const int raw = std::system(command.c_str());
  Run r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

std::string q(const std::string& path) { return "'" + path + "'"; }

// (sanitizers whose shadow memory or quarantine makes the resident memory no measure of the tool's)
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define PSC_TEST_MEMORY_SANITIZED
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define PSC_TEST_MEMORY_SANITIZED
#endif
#endif

// The tool's exit status and its peak resident memory in KB (the rusage of its shell, which
// includes the children it waited for), its output discarded.
[[maybe_unused]] std::pair<int, long> run_tool_peak_kb(const std::string& args)
{
  const std::string command = std::string("'") + PSC_TOOL_PATH + "' " + args + " > /dev/null 2>&1";
  std::vector<char> sh(std::begin("sh"), std::end("sh")), c(std::begin("-c"), std::end("-c")),
    line(command.c_str(), command.c_str() + command.size() + 1);
  char* argv[] = {sh.data(), c.data(), line.data(), nullptr};
  pid_t pid;
  if(::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv, environ) != 0)
    return {-1, 0};
  int status = 0;
  struct rusage usage;
  if(::wait4(pid, &status, 0, &usage) != pid)
    return {-1, 0};
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
}

// Files left in the work folder whose name starts with `prefix` (temporary outputs).
std::size_t files_starting_with(const std::string& prefix)
{
  std::size_t n = 0;
  for(const auto& entry : fs::directory_iterator(work_dir()))
    if(entry.path().filename().string().rfind(prefix, 0) == 0)
      ++n;
  return n;
}

// Bitwise equality of doubles, NaN included (NaN == NaN here).
bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

bool same(const Vector& a, const Vector& b) { return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z()); }

bool same(const Estimate& a, const Estimate& b)
{
  return a.status == b.status && a.neighbor_count == b.neighbor_count && same(a.normal, b.normal) &&
         same(a.mean_curvature, b.mean_curvature) && same(a.gaussian_curvature, b.gaussian_curvature) &&
         same(a.min_curvature, b.min_curvature) && same(a.max_curvature, b.max_curvature) &&
         same(a.min_direction, b.min_direction) && same(a.max_direction, b.max_direction);
}

// The property map `name` of type T of a point set read from PLY (fails the test if absent).
template <class T>
typename Point_set::template Property_map<T> property(const Point_set& ps, const std::string& name)
{
  auto found = ps.template property_map<T>(name);
  INFO("PLY property " << name);
  REQUIRE(found.second);
  return found.first;
}

// Compares a result PLY read back with CGAL's reader to the library's estimates.
void check_ply_matches(const std::string& path, const std::vector<Oriented_point>& input,
                       const std::vector<Estimate>& expected, bool with_color)
{
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(path, ps));
  REQUIRE(ps.size() == input.size());
  REQUIRE(ps.has_normal_map());
  const auto k_min = property<double>(ps, "k_min");
  const auto k_max = property<double>(ps, "k_max");
  const auto mean = property<double>(ps, "mean");
  const auto gaussian = property<double>(ps, "gaussian");
  const char* direction_names[6] = {"dmin_x", "dmin_y", "dmin_z", "dmax_x", "dmax_y", "dmax_z"};
  std::vector<Point_set::Property_map<double> > directions;
  for(const char* name : direction_names)
    directions.push_back(property<double>(ps, name));
  const auto neighbors = property<std::int32_t>(ps, "neighbors");
  const auto valid = property<std::uint8_t>(ps, "valid");
  std::size_t i = 0, mismatches = 0;
  for(Point_set::Index p : ps)
  {
    const Estimate& e = expected[i];
    const double d[6] = {e.min_direction.x(), e.min_direction.y(), e.min_direction.z(),
                         e.max_direction.x(), e.max_direction.y(), e.max_direction.z()};
    bool ok = ps.point(p) == input[i].first && same(ps.normal(p), e.normal) && same(k_min[p], e.min_curvature) &&
              same(k_max[p], e.max_curvature) && same(mean[p], e.mean_curvature) &&
              same(gaussian[p], e.gaussian_curvature) && neighbors[p] == std::int32_t(e.neighbor_count) &&
              valid[p] == (e.is_valid() ? 1 : 0);
    for(int a = 0; a < 6; ++a)
      ok = ok && same(directions[a][p], d[a]);
    mismatches += ok ? 0 : 1;
    ++i;
  }
  CHECK(mismatches == 0);
  CHECK(ps.property_map<std::uint8_t>("red").second == with_color);
}

// Sphere of radius 2 plus an isolated point (TOO_FEW_NEIGHBORS) and a point with a zero
// normal (INVALID_NORMAL): the output has valid and invalid rows.
std::vector<Oriented_point> sphere_with_invalid_points()
{
  std::vector<Oriented_point> pts = sphere(2000, 2.0);
  pts.emplace_back(Point(50, 50, 50), Vector(0, 0, 1));
  pts.emplace_back(Point(0, 0, 2.001), Vector(0, 0, 0));
  return pts;
}

// The rows of a CSV output, header first.
std::vector<std::string> csv_rows(const std::string& text)
{
  std::vector<std::string> rows;
  std::istringstream lines(text);
  std::string line;
  while(std::getline(lines, line))
    rows.push_back(line);
  return rows;
}

// Field `name` of every data row of a CSV output.
std::vector<std::string> csv_column(const std::string& text, const std::string& name)
{
  const std::vector<std::string> rows = csv_rows(text);
  std::vector<std::string> values;
  if(rows.empty())
    return values;
  auto split = [](const std::string& row) {
    std::vector<std::string> fields;
    std::istringstream s(row);
    std::string f;
    while(std::getline(s, f, ','))
      fields.push_back(f);
    return fields;
  };
  const std::vector<std::string> header = split(rows[0]);
  const std::size_t at = std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
  for(std::size_t i = 1; i < rows.size(); ++i)
  {
    const std::vector<std::string> fields = split(rows[i]);
    values.push_back(at < fields.size() ? fields[at] : "<missing>");
  }
  return values;
}

}  // namespace

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
  scan::Noise noise;
  noise.range_sigma = 0.03;
  Point_set ps;
  ps.add_normal_map();
  for(const scan::Sample& s : scan::airborne_lines(scan::wavy_terrain(), 4, 0.1, 0.25, noise))
    ps.insert(s.p);
  PSC::Scale_choices choices;
  CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    ps,
    P::neighbor_count(40, P::automatic_scale(640, P::normal_orientation(CGAL::Normal_orientation::along_vector(0, 0, 1),
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

// =======================================================================================
// The tool

TEST_CASE("tool: binary and ASCII PLY read back with CGAL's PLY reader, every property right")
{
  const std::vector<Oriented_point> pts = sphere(2000, 2.0);
  const std::string input = file("sphere.xyz");
  write_xyz(input, pts);
  const double radius = 0.4;
  const std::vector<Estimate> expected = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, radius, pair_maps);

  const Run binary = run_tool(q(input) + " " + q(file("sphere_binary.ply")) + " --radius 0.4");
  INFO(binary.err);
  REQUIRE(binary.status == 0);
  CHECK(read_text(file("sphere_binary.ply")).rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0);
  check_ply_matches(file("sphere_binary.ply"), pts, expected, false);
  // the summary
  CHECK(binary.out.find("points      2000") != std::string::npos);
  CHECK(binary.out.find("valid       2000 (100.00 %)") != std::string::npos);

  // ASCII: 17 significant digits give back the same doubles.
  const Run ascii = run_tool(q(input) + " " + q(file("sphere_ascii.ply")) + " --radius=0.4 --ascii --color mean");
  REQUIRE(ascii.status == 0);
  CHECK(read_text(file("sphere_ascii.ply")).rfind("ply\nformat ascii 1.0\n", 0) == 0);
  check_ply_matches(file("sphere_ascii.ply"), pts, expected, true);
  // H = 1/2 everywhere: the robust range is 1/2, every point at the red end of the map
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("sphere_ascii.ply"), ps));
  const auto red = property<std::uint8_t>(ps, "red");
  const auto green = property<std::uint8_t>(ps, "green");
  const auto blue = property<std::uint8_t>(ps, "blue");
  std::size_t red_points = 0;
  for(Point_set::Index p : ps)
    red_points += (red[p] == 180 && green[p] == 4 && blue[p] == 38);
  CHECK(red_points == 2000);

  // --threads 1 and every core write the same bytes.
  REQUIRE(run_tool(q(input) + " " + q(file("sphere_1thread.ply")) + " --radius 0.4 --threads 1 --quiet").status == 0);
  CHECK(read_text(file("sphere_1thread.ply")) == read_text(file("sphere_binary.ply")));
}

namespace {

// A PLY of sphere_with_invalid_points() with attributes: red (a --color clash), intensity,
// k_min (a clash with an estimate), scalar_Intensity (as CloudCompare names a scalar field
// Intensity in its PLY files) and scalar_mean (the CloudCompare name of the tool's mean).
std::string write_ply_with_attributes(const std::string& name)
{
  const std::vector<Oriented_point> pts = sphere_with_invalid_points();
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty float nx\nproperty float ny\n"
         "property float nz\nproperty uchar red\nproperty float intensity\nproperty short k_min\n"
         "property float scalar_Intensity\nproperty float scalar_mean\nend_header\n";
  for(std::size_t i = 0; i < pts.size(); ++i)
    ply << pts[i].first.x() << " " << pts[i].first.y() << " " << pts[i].first.z() << " " << pts[i].second.x() << " "
        << pts[i].second.y() << " " << pts[i].second.z() << " " << i % 256 << " " << 0.5 * double(i) << " " << -int(i)
        << " " << 0.25 * double(i) << " " << 2.0 * double(i) << "\n";
  write_text(file(name), ply.str());
  return file(name);
}

// The property names of a PLY header, in order.
std::vector<std::string> ply_property_names(const std::string& path)
{
  std::istringstream header(read_text(path));
  std::vector<std::string> names;
  std::string line;
  while(std::getline(header, line) && line != "end_header")
    if(line.rfind("property ", 0) == 0)
      names.push_back(line.substr(line.rfind(' ') + 1));
  return names;
}

}  // namespace

TEST_CASE("tool: --ply-names scalar names every property but x y z, normals and colours scalar_NAME, same data")
{
  const std::string input = write_ply_with_attributes("cc_input.ply");
  for(const char* format : {"", " --ascii"})
  {
    INFO("format" << format);
    const std::string plain = file("cc_plain.ply"), scalar = file("cc_scalar.ply");
    const std::string args = std::string(" --radius 0.4 --color mean --quiet") + format;
    REQUIRE(run_tool(q(input) + " " + q(plain) + args).status == 0);
    const Run r = run_tool(q(input) + " " + q(scalar) + args + " --ply-names scalar");
    INFO(r.err);
    REQUIRE(r.status == 0);
    // clang-format off
    const std::vector<std::string> expected_plain = {
      "x", "y", "z", "nx", "ny", "nz", "k_min", "k_max", "mean", "gaussian", "dmin_x", "dmin_y", "dmin_z",
      "dmax_x", "dmax_y", "dmax_z", "normal_coherence", "neighbors", "valid", "red", "green", "blue",
      "input_red", "intensity", "input_k_min", "scalar_Intensity", "scalar_mean"};
    // clang-format on
    // readers that look for mean, k_min, ... find them without the option
    CHECK(ply_property_names(plain) == expected_plain);
    // x y z, the normals and --color's colours keep their names (CloudCompare loads them as
    // such); every other property gets scalar_, but for a name that has it already
    // (CloudCompare's own scalar_Intensity stays the field Intensity) unless the name is
    // taken: the input's scalar_mean becomes scalar_scalar_mean, the tool's mean scalar_mean.
    // clang-format off
    const std::vector<std::string> expected_scalar = {
      "x", "y", "z", "nx", "ny", "nz", "scalar_k_min", "scalar_k_max", "scalar_mean", "scalar_gaussian",
      "scalar_dmin_x", "scalar_dmin_y", "scalar_dmin_z", "scalar_dmax_x", "scalar_dmax_y", "scalar_dmax_z",
      "scalar_normal_coherence", "scalar_neighbors", "scalar_valid", "red", "green", "blue",
      "scalar_input_red", "scalar_intensity", "scalar_input_k_min", "scalar_Intensity", "scalar_scalar_mean"};
    // clang-format on
    CHECK(ply_property_names(scalar) == expected_scalar);
    // only the names differ: the types, the comments and every byte of the data are the same
    const std::string a = read_text(plain), b = read_text(scalar);
    CHECK(a.substr(a.find("end_header\n")) == b.substr(b.find("end_header\n")));
    std::string renamed = b.substr(0, b.find("end_header\n"));
    for(std::size_t at = 0; (at = renamed.find(" scalar_", at)) != std::string::npos;)
      renamed.erase(at + 1, 7);
    std::string original = a.substr(0, a.find("end_header\n"));
    for(std::size_t at = 0; (at = original.find(" scalar_", at)) != std::string::npos;)
      original.erase(at + 1, 7);
    CHECK(renamed == original);
  }
  // --ply-names plain is the default; the option is for .ply outputs only, and checked
  const std::string plain_again = file("cc_plain_again.ply");
  REQUIRE(run_tool(q(input) + " " + q(plain_again) + " --radius 0.4 --color mean --quiet --ply-names plain").status ==
          0);
  CHECK(ply_property_names(plain_again) == ply_property_names(file("cc_plain.ply")));
  const Run csv = run_tool(q(input) + " " + q(file("cc.csv")) + " --radius 0.4 --ply-names scalar");
  CHECK(csv.status == 2);
  CHECK(csv.err.find("--ply-names scalar names the properties of a .ply output") != std::string::npos);
  CHECK(!fs::exists(file("cc.csv")));
  const Run unknown = run_tool(q(input) + " " + q(file("cc_unknown.ply")) + " --radius 0.4 --ply-names cloudcompare");
  CHECK(unknown.status == 2);
  CHECK(unknown.err.find("--ply-names: unknown naming 'cloudcompare'") != std::string::npos);

  // a text column named with a space (CloudCompare's "Scalar field"): '_' in the PLY header,
  // whose lines split on white space, so that the output reads back
  {
    std::ostringstream asc;
    asc.precision(17);
    asc << "//X,Y,Z,Nx,Ny,Nz,Scalar field,Scalar_field\n";
    for(int i = 0; i < 60; ++i)
    {
      const double u = 0.37 * i, v = 0.11 * i;
      const double x = std::cos(u) * std::sin(v + 0.3), y = std::sin(u) * std::sin(v + 0.3), z = std::cos(v + 0.3);
      asc << x << "," << y << "," << z << "," << x << "," << y << "," << z << "," << i << "," << 2 * i << "\n";
    }
    write_text(file("spaced.asc"), asc.str());
    for(const char* naming : {"plain", "scalar"})
    {
      INFO(naming);
      const std::string out = file(std::string("spaced_") + naming + ".ply");
      const Run r = run_tool(q(file("spaced.asc")) + " " + q(out) + " --neighbors 12 --quiet --ply-names " + naming);
      INFO(r.err);
      REQUIRE(r.status == 0);
      const std::vector<std::string> names = ply_property_names(out);
      const std::string prefix = std::string(naming) == "scalar" ? "scalar_" : "";
      CHECK(names[names.size() - 2] == prefix + "Scalar_field_");
      CHECK(names.back() == prefix + "Scalar_field");
      const Run back = run_tool(q(out) + " " + q(file("spaced_back.csv")) + " --neighbors 12 --quiet");
      INFO(back.err);
      CHECK(back.status == 0);
    }
  }
}

namespace {

// A test that cannot run here says so with this line, which CTest turns into a skip (the
// property SKIP_REGULAR_EXPRESSION of test/CMakeLists.txt), so that a skip shows in the
// summary instead of passing (issue 45). CTest then ignores the exit status: only test cases
// that assert nothing before skipping may call it (each does so first), or the skip would
// hide their failures; the CTest test test_skips_come_first (test/skips_come_first.cmake)
// checks the source for assertion macros before each call.
void skip_test(const std::string& why) { std::cout << "PSC_TEST_SKIPPED: " << why << std::endl; }

bool has_cloudcompare() { return std::system("command -v CloudCompare > /dev/null 2>&1") == 0; }

}  // namespace

// DIR/out.ply opened by CloudCompare headless and saved as ASCII with a header line naming the
// columns (X Y Z R G B, the scalar fields, Nx Ny Nz): the path of that .asc file.
std::string cloudcompare_asc(const fs::path& dir)
{
  const std::string command = "cd " + q(dir.string()) +
                              " && QT_QPA_PLATFORM=offscreen CloudCompare -SILENT -O out.ply -C_EXPORT_FMT ASC"
                              " -ADD_HEADER -SAVE_CLOUDS > cloudcompare.log 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  std::string asc;
  for(const auto& entry : fs::directory_iterator(dir))
    if(entry.path().extension() == ".asc")
      asc = entry.path().string();
  INFO(read_text((dir / "cloudcompare.log").string()));
  REQUIRE(!asc.empty());
  return asc;
}

// Runs only where CloudCompare is installed (Debian's cloudcompare package, which CI installs):
// skipped, visibly, without it.
TEST_CASE("tool: CloudCompare loads every estimate and attribute of a --ply-names scalar PLY by its name")
{
  if(!has_cloudcompare())
  {
    skip_test("CloudCompare is not installed (Debian: apt-get install cloudcompare)");
    return;
  }
  const std::string input = write_ply_with_attributes("cc_in.ply");
  // The tool's output with `options` in a folder of its own, opened by CloudCompare headless
  // and saved as ASCII with a header line naming the columns (X Y Z R G B, the scalar fields,
  // Nx Ny Nz): the path of that .asc file
  const auto cloudcompare_export = [&](const std::string& folder, const std::string& options) {
    const fs::path dir = work_dir() / folder;
    fs::create_directories(dir);
    REQUIRE(run_tool(q(input) + " " + q((dir / "out.ply").string()) + " --radius 0.4 --color mean --quiet" + options)
              .status == 0);
    return cloudcompare_asc(dir);
  };
  const std::string asc = cloudcompare_export("cloudcompare", " --ply-names scalar");
  std::istringstream lines(read_text(asc));
  std::string header;
  std::getline(lines, header);
  // the names CloudCompare 2.11.3 gives the fields
  // clang-format off
  const std::vector<std::string> expected = {
    "//X", "Y", "Z", "R", "G", "B", "k_min", "k_max", "mean", "gaussian", "dmin_x", "dmin_y", "dmin_z",
    "dmax_x", "dmax_y", "dmax_z", "normal_coherence", "neighbors", "valid", "input_red", "intensity",
    "input_k_min", "Intensity", "scalar_mean", "Nx", "Ny", "Nz"};
  // clang-format on
  std::istringstream words(header);
  std::vector<std::string> columns;
  for(std::string w; words >> w;)
    columns.push_back(w);
  CHECK(columns == expected);
  REQUIRE(columns.size() == expected.size());

  // the values: CloudCompare's scalar fields are float32; NaN (invalid points) stays NaN
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY((work_dir() / "cloudcompare" / "out.ply").string(), ps));
  const char* checked[] = {"mean", "k_min", "gaussian", "dmax_z", "normal_coherence"};
  std::vector<Point_set::Property_map<double> > maps;
  for(const char* name : checked)
    maps.push_back(property<double>(ps, std::string("scalar_") + name));
  const auto intensity = property<float>(ps, "scalar_intensity");
  std::size_t rows = 0, wrong = 0, nan = 0;
  auto close = [](double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::abs(a - b) <= 1e-6 * std::abs(b) + 1e-9;
  };
  for(Point_set::Index p : ps)
  {
    std::string line;
    REQUIRE(std::getline(lines, line));
    std::istringstream row(line);
    std::vector<double> v;
    for(std::string w; row >> w;)
      v.push_back(w == "nan" || w == "-nan" ? std::nan("") : std::stod(w));
    REQUIRE(v.size() == expected.size());
    for(std::size_t k = 0; k < maps.size(); ++k)
    {
      const std::size_t column = std::find(expected.begin(), expected.end(), checked[k]) - expected.begin();
      wrong += close(v[column], maps[k][p]) ? 0 : 1;
    }
    wrong += close(v[20], intensity[p]) ? 0 : 1;
    nan += std::isnan(v[8]) ? 1 : 0;
    ++rows;
  }
  CHECK(rows == ps.size());
  CHECK(wrong == 0);
  CHECK(nan == 2);  // the isolated point and the point with a zero normal

  // without the option CloudCompare loads none of the estimates (the reason for it); it does
  // load a property named intensity, and the input's scalar_Intensity and scalar_mean
  std::istringstream plain_lines(read_text(cloudcompare_export("cloudcompare_plain", "")));
  std::string plain_header;
  std::getline(plain_lines, plain_header);
  CHECK(plain_header == "//X Y Z R G B intensity Intensity mean Nx Ny Nz");
}

namespace {

typedef std::array<std::uint16_t, 3> Rgb16;

// A LAS 1.2 file of format 3 (red green blue at bytes 28, 30, 32 of each 34-byte record) with
// the colour c(i) on point i.
void write_coloured_las(const std::string& name, const std::vector<Oriented_point>& pts,
                        const std::function<Rgb16(std::size_t)>& c)
{
  const double offset[3] = {0, 0, 0};
  std::string las = las_file(pts, 3, 2, 1e-4, offset);
  for(std::size_t i = 0; i < pts.size(); ++i)
    for(int k = 0; k < 3; ++k)
      put_le<std::uint16_t>(las, 227 + 34 * i + 28 + 2 * k, c(i)[k]);
  write_text(file(name), las);
}

// 16-bit colours as the specification says (v * 256 and the full-scale v * 257)
Rgb16 wide_colour(std::size_t i)
{
  return Rgb16{{std::uint16_t(256 * (i % 256)), std::uint16_t(257 * (i % 200)), 65535}};
}

}  // namespace

// Issue 42, item 1: the input's colours (LAS: 16 bits) are written to PLY as the 8-bit colours
// viewers read (CloudCompare 2.11.3 showed ushort red green blue as black on every point): the
// high byte, or the value itself where no value of the file exceeds 255 (8-bit colours in 16-bit
// fields); the same in tiles; CSV keeps the 16 bits.
TEST_CASE("tool: LAS colours come out as 8-bit PLY colours, 16 bits in CSV, the same in tiles")
{
  const std::vector<Oriented_point> pts = sphere(3000, 1.0);
  // 16 bits (wide_colour), and 8 bits stored in them
  const auto narrow = [](std::size_t i) {
    return std::array<std::uint16_t, 3>{{std::uint16_t(i % 256), std::uint16_t(255 - i % 256), 7}};
  };
  // 8 bits but for one red of 300 on the point of largest x (in a corner tile): the file is
  // 16-bit, in every tile
  std::size_t east = 0;
  for(std::size_t i = 1; i < pts.size(); ++i)
    east = pts[i].first.x() > pts[east].first.x() ? i : east;
  const auto one_wide = [&](std::size_t i) {
    std::array<std::uint16_t, 3> c = narrow(i);
    c[0] = i == east ? 300 : c[0];
    return c;
  };
  write_coloured_las("wide.las", pts, wide_colour);
  write_coloured_las("narrow.las", pts, narrow);
  write_coloured_las("one_wide.las", pts, one_wide);
  for(const int kind : {0, 1, 2})
  {
    const char* names[] = {"wide.las", "narrow.las", "one_wide.las"};
    INFO(names[kind]);
    const auto colour = [&](std::size_t i) { return kind == 0 ? wide_colour(i) : kind == 1 ? narrow(i) : one_wide(i); };
    const int shift = kind == 1 ? 0 : 8;
    const std::string in = q(file(names[kind]));
    const std::string options = " --neighbors 20 --orient +z";
    REQUIRE(run_tool(in + " " + q(file("colours.ply")) + options + " --quiet").status == 0);
    REQUIRE(run_tool(in + " " + q(file("colours.csv")) + options + " --quiet").status == 0);
    const Run tiled = run_tool(in + " " + q(file("colours_tiled.ply")) + options + " --memory-limit 600K");
    REQUIRE(tiled.status == 0);
    const std::size_t tiles = tiled.out.find("  tiles       ");
    REQUIRE(tiles != std::string::npos);
    CHECK(std::stoul(tiled.out.substr(tiles + 14)) > 1);
    CHECK(read_text(file("colours_tiled.ply")) == read_text(file("colours.ply")));
    const std::string ply = read_text(file("colours.ply"));
    CHECK(ply.find("property uchar red\nproperty uchar green\nproperty uchar blue\n") != std::string::npos);
    Point_set ps;
    REQUIRE(CGAL::IO::read_PLY(file("colours.ply"), ps));
    const auto red = property<std::uint8_t>(ps, "red"), green = property<std::uint8_t>(ps, "green"),
               blue = property<std::uint8_t>(ps, "blue");
    const std::vector<std::string> csv_red = csv_column(read_text(file("colours.csv")), "red"),
                                   csv_blue = csv_column(read_text(file("colours.csv")), "blue");
    REQUIRE(csv_red.size() == pts.size());
    std::size_t i = 0, wrong = 0;
    for(Point_set::Index p : ps)
    {
      const std::array<std::uint16_t, 3> c = colour(i);
      wrong += red[p] != c[0] >> shift || green[p] != c[1] >> shift || blue[p] != c[2] >> shift;
      wrong += csv_red[i] != std::to_string(c[0]) || csv_blue[i] != std::to_string(c[2]);  // 16 bits
      ++i;
    }
    CHECK(wrong == 0);
  }
}

// The same colours as CloudCompare shows them (R G B after X Y Z in its ASCII export); where
// CloudCompare is installed (CI installs it), skipped visibly elsewhere.
TEST_CASE("tool: CloudCompare shows the 8-bit PLY colours of a LAS file's 16-bit colours")
{
  if(!has_cloudcompare())
  {
    skip_test("CloudCompare is not installed (Debian: apt-get install cloudcompare)");
    return;
  }
  const std::vector<Oriented_point> pts = sphere(3000, 1.0);
  write_coloured_las("cc_wide.las", pts, wide_colour);
  const fs::path dir = work_dir() / "cloudcompare_colours";
  fs::create_directories(dir);
  REQUIRE(run_tool(q(file("cc_wide.las")) + " " + q((dir / "out.ply").string()) + " --neighbors 20 --orient +z --quiet")
            .status == 0);
  std::istringstream lines(read_text(cloudcompare_asc(dir)));
  std::string header;
  std::getline(lines, header);
  REQUIRE(header.rfind("//X Y Z R G B ", 0) == 0);
  std::size_t i = 0, wrong = 0;
  for(std::string line; std::getline(lines, line); ++i)
  {
    std::istringstream row(line);
    double x, y, z, r, g, b;
    row >> x >> y >> z >> r >> g >> b;
    wrong += r != wide_colour(i)[0] >> 8 || g != wide_colour(i)[1] >> 8 || b != 255;
  }
  CHECK(i == pts.size());
  CHECK(wrong == 0);
}

// The LAS output read by a reader not written here: loaders.gl's LAS loader under Node.js
// (test/las_third_party.mjs), from the node_modules folder named by PSC_LAS_READER_MODULES
// (CI: npm install --prefix DIR @loaders.gl/las@4.5.1); skipped visibly without node or it.
// The loader gives positions as float32 and no extra bytes: the points, header and standard
// fields are compared here, the estimates' values by the tool's own tests.
TEST_CASE("tool: a third-party LAS reader (loaders.gl) reads the LAS output: header, points and fields of the input")
{
  const char* modules = std::getenv("PSC_LAS_READER_MODULES");
  if(std::system("command -v node > /dev/null 2>&1") != 0 || modules == nullptr ||
     !fs::exists(fs::path(modules) / "@loaders.gl" / "las"))
  {
    skip_test("no third-party LAS reader: install Node.js, run npm install --prefix DIR @loaders.gl/las@4.5.1 "
              "and set PSC_LAS_READER_MODULES=DIR/node_modules");
    return;
  }
  const std::string script = q(std::string(PSC_DATA_DIR) + "/../test/las_third_party.mjs");
  // the reader's lines "name values..." as a map
  const auto reader = [&](const std::string& output, const std::string& mode, const std::string& input) {
    const std::string log = file("third_party.txt");
    const std::string command =
      "node " + script + " " + q(modules) + " " + q(output) + " " + mode + " " + q(input) + " > " + q(log) + " 2>&1";
    const int status = std::system(command.c_str());
    const std::string text = read_text(log);
    INFO(text);
    REQUIRE(status == 0);
    std::map<std::string, std::string> facts;
    std::istringstream lines(text);
    for(std::string line; std::getline(lines, line);)
    {
      const std::size_t space = line.find(' ');
      facts[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
    }
    return facts;
  };
  // a LAS input (point format 3, with intensity, classification and colours): its format, its
  // scale and offset, its points bit for bit (the same float32 from the same records) and its fields
  const std::string las_in = repo_data("real/sample_c.las");
  REQUIRE(run_tool(q(las_in) + " " + q(file("third_party.las")) + " --neighbors 40 --quiet").status == 0);
  std::map<std::string, std::string> facts = reader(file("third_party.las"), "--las", las_in);
  CHECK(facts["version"] == "1.4");
  CHECK(facts["input_format"] == "3");
  CHECK(facts["format"] == "3");
  // format 3's 34 bytes, then the estimates: 14 doubles (nx ny nz k_min k_max mean gaussian,
  // the two directions, normal_coherence, mean_error), neighbors (uint32) and valid (uchar)
  CHECK(facts["record_length"] == std::to_string(34 + 14 * 8 + 4 + 1));
  CHECK(facts["count"] == "14408 14408");
  CHECK(facts["scale"] == "0.01 0.01 0.01");
  CHECK(facts["position_difference"] == "0");
  CHECK(facts["attributes_equal"] == "COLOR_0 classification intensity");
  CHECK(facts["attributes_differ"].empty());
  // a text input: format 6, the coordinates within half the scale (and float32's rounding of
  // values below 10, 2^-24 * 16), float32 estimates of two fields
  std::ofstream(file("third_party.xyz")) << read_text(repo_data("goursat_010000.xyz"));
  REQUIRE(run_tool(q(file("third_party.xyz")) + " " + q(file("third_party_6.las")) +
                   " --neighbors 40 --float --fields mean,valid --quiet")
            .status == 0);
  facts = reader(file("third_party_6.las"), "--text", file("third_party.xyz"));
  CHECK(facts["version"] == "1.4");
  CHECK(facts["format"] == "6");
  CHECK(facts["record_length"] == std::to_string(30 + 4 + 1));
  CHECK(facts["count"] == "10000 10000");
  std::istringstream scale(facts["scale"]);
  double sx = 0, sy = 0, sz = 0;
  scale >> sx >> sy >> sz;
  CHECK(sx > 0);
  CHECK(sx <= 0.001);
  CHECK(sy == sx);
  CHECK(sz == sx);
  const double difference = std::stod(facts["position_difference"]);
  CHECK(difference <= 0.5 * sx + 16 * std::ldexp(1.0, -24));
}

TEST_CASE("tool: .xyz, .pwn, .off and ASCII, little- and big-endian binary .ply give the same result")
{
  const std::vector<Oriented_point> pts = sphere(500, 1.0);
  write_xyz(file("formats.xyz"), pts);
  write_xyz(file("formats.pwn"), pts);
  std::ostringstream off, ascii;
  off.precision(17);
  ascii.precision(17);
  off << "NOFF\n" << pts.size() << " 1 0\n";
  const std::string header_end = "property double nx\nproperty double ny\nproperty double nz\n"
                                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string header = "element vertex " + std::to_string(pts.size()) +
                             "\nproperty double x\nproperty double y\nproperty double z\n" + header_end;
  ascii << "ply\nformat ascii 1.0\n" << header;
  std::string little = "ply\nformat binary_little_endian 1.0\n" + header;
  std::string big = "ply\nformat binary_big_endian 1.0\n" + header;
  auto put = [](std::string& out, const char* bytes, std::size_t size, bool reverse) {
    std::string b(bytes, size);
    if(reverse)
      std::reverse(b.begin(), b.end());
    out += b;
  };
  std::uint16_t probe = 1;
  const bool host_little = *reinterpret_cast<unsigned char*>(&probe) == 1;
  for(const Oriented_point& p : pts)
  {
    const double v[6] = {p.first.x(), p.first.y(), p.first.z(), p.second.x(), p.second.y(), p.second.z()};
    for(int a = 0; a < 6; ++a)
    {
      off << v[a] << (a == 5 ? "\n" : " ");
      ascii << v[a] << (a == 5 ? "\n" : " ");
      put(little, reinterpret_cast<const char*>(&v[a]), 8, !host_little);
      put(big, reinterpret_cast<const char*>(&v[a]), 8, host_little);
    }
  }
  // one triangle after the vertices: the readers must skip it
  off << "3 0 1 2\n";
  ascii << "3 0 1 2\n";
  const std::int32_t face[3] = {0, 1, 2};
  little += char(3);
  big += char(3);
  for(int c = 0; c < 3; ++c)
  {
    put(little, reinterpret_cast<const char*>(&face[c]), 4, !host_little);
    put(big, reinterpret_cast<const char*>(&face[c]), 4, host_little);
  }
  write_text(file("formats.off"), off.str());
  write_text(file("formats_ascii.ply"), ascii.str());
  write_text(file("formats_little.ply"), little);
  write_text(file("formats_big.ply"), big);

  REQUIRE(run_tool(q(file("formats.xyz")) + " " + q(file("formats_xyz.csv")) + " --radius 0.6").status == 0);
  const std::string reference = read_text(file("formats_xyz.csv"));
  CHECK(std::count(reference.begin(), reference.end(), '\n') == 501);
  for(const char* name : {"formats.pwn", "formats.off", "formats_ascii.ply", "formats_little.ply", "formats_big.ply"})
  {
    const Run r = run_tool(q(file(name)) + " " + q(file("formats_other.csv")) + " --radius 0.6");
    INFO(name << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());  // normals found: no warning
    CHECK(read_text(file("formats_other.csv")) == reference);
  }
}

TEST_CASE("tool: invalid rows are NaN with valid = 0, in PLY and CSV, with --neighbors")
{
  const std::vector<Oriented_point> pts = sphere_with_invalid_points();
  const std::string input = file("sphere_invalid.xyz");
  write_xyz(input, pts);
  const std::vector<Estimate> expected =
    CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, PSC::parameters::neighbor_count(25, pair_maps));
  // the isolated point sees 24 points of the sphere (k counts): valid but meaningless;
  // the zero normal is invalid
  REQUIRE(expected[2001].status == CGAL::Curvature_estimate_status::INVALID_NORMAL);

  const Run r = run_tool(q(input) + " " + q(file("invalid.ply")) + " --neighbors 25 --color gaussian");
  INFO(r.err);
  REQUIRE(r.status == 0);
  check_ply_matches(file("invalid.ply"), pts, expected, true);
  CHECK(r.out.find("1 invalid_normal") != std::string::npos);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("invalid.ply"), ps));
  const Point_set::Index last = *(ps.end() - 1);
  CHECK(property<std::uint8_t>(ps, "red")[last] == 128);  // grey where invalid

  // CSV: header, one row per point, the same values.
  const Run c = run_tool(q(input) + " " + q(file("invalid.csv")) + " --neighbors 25 --quiet");
  REQUIRE(c.status == 0);
  CHECK(c.out.empty());  // --quiet
  std::istringstream csv(read_text(file("invalid.csv")));
  std::string line;
  std::getline(csv, line);
  CHECK(line == "x,y,z,nx,ny,nz,k_min,k_max,mean,gaussian,dmin_x,dmin_y,dmin_z,dmax_x,dmax_y,"
                "dmax_z,normal_coherence,neighbors,valid");
  std::size_t rows = 0, mismatches = 0;
  while(std::getline(csv, line))
  {
    std::vector<double> v;
    std::istringstream fields(line);
    for(std::string f; std::getline(fields, f, ',');)
      v.push_back(f == "nan" ? std::numeric_limits<double>::quiet_NaN() : std::strtod(f.c_str(), nullptr));
    const Estimate& e = expected[rows];
    const bool ok = v.size() == 19 && v[0] == pts[rows].first.x() && same(v[3], e.normal.x()) &&
                    same(v[6], e.min_curvature) && same(v[8], e.mean_curvature) && same(v[9], e.gaussian_curvature) &&
                    same(v[15], e.max_direction.z()) && same(v[16], e.normal_coherence) &&
                    v[17] == double(e.neighbor_count) && v[18] == (e.is_valid() ? 1 : 0);
    mismatches += !ok;
    ++rows;
  }
  CHECK(rows == pts.size());
  CHECK(mismatches == 0);

  // APSS gives no Gaussian curvature: NaN in every row, written "nan" in ASCII PLY. (CGAL
  // 5.5's ASCII PLY reader cannot read "nan", so this file is checked as text.)
  const Run a = run_tool(q(input) + " " + q(file("apss.ply")) + " --method apss --radius 0.4 --ascii");
  REQUIRE(a.status == 0);
  CHECK(a.out.find("n/a (not estimated by this method)") != std::string::npos);
  std::istringstream ply(read_text(file("apss.ply")));
  while(std::getline(ply, line) && line != "end_header")
  {}
  std::size_t nan_gaussian = 0, finite_mean = 0;
  while(std::getline(ply, line))
  {
    std::istringstream fields(line);
    std::vector<std::string> f;
    for(std::string w; fields >> w;)
      f.push_back(w);
    nan_gaussian += (f.size() == 19 && f[9] == "nan");
    finite_mean += (f.size() == 19 && f[18] == "1" && std::isfinite(std::strtod(f[8].c_str(), nullptr)));
  }
  CHECK(nan_gaussian == pts.size());
  CHECK(finite_mean == 2000);  // the sphere; radius 0.4 leaves the isolated point alone
}

TEST_CASE("tool: --neighbors K on a cloud with density varying 1:10 gives every point at least K neighbours")
{
  const std::vector<Oriented_point> pts = varying_density(5000, 11);
  const std::string input = file("varying.xyz");
  write_xyz(input, pts);
  for(const char* k : {"12", "30"})
  {
    const Run r = run_tool(q(input) + " " + q(file("varying.csv")) + " --neighbors " + k);
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::istringstream csv(read_text(file("varying.csv")));
    std::string line;
    std::getline(csv, line);
    std::size_t rows = 0, enough = 0;
    const long kk = std::atol(k);
    while(std::getline(csv, line))
    {
      const std::size_t comma = line.find_last_of(',');
      const std::size_t before = line.find_last_of(',', comma - 1);
      const long neighbors = std::atol(line.substr(before + 1, comma - before - 1).c_str());
      enough += (neighbors >= kk && line.substr(comma + 1) == "1");
      ++rows;
    }
    CHECK(rows == pts.size());
    CHECK(enough == pts.size());
  }
  // With a fixed radius the sparse part has too few points: the count mode is what helps.
  const Run r = run_tool(q(input) + " " + q(file("varying_radius.csv")) + " --radius 0.05");
  REQUIRE(r.status == 0);
  CHECK(r.out.find("too_few_neighbors") != std::string::npos);
}

TEST_CASE("tool: a file without normals gets estimated, oriented normals and a warning")
{
  // The Goursat blue-noise sample shipped in data/, positions only.
  const std::vector<Oriented_point> pts = read_xyz(repo_data("goursat_010000.xyz"));
  const std::string input = file("goursat_positions.xyz");
  write_xyz(input, pts, false);
  const Run r = run_tool(q(input) + " " + q(file("goursat_estimated.ply")) + " --radius 1.5");
  REQUIRE(r.status == 0);
  CHECK(r.err.find("warning: '" + input + "' has no normals") != std::string::npos);
  CHECK(r.out.find("(normals estimated)") != std::string::npos);
  const std::vector<Estimate> truth = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(pts, 1.5, pair_maps);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("goursat_estimated.ply"), ps));
  const auto mean = property<double>(ps, "mean");
  std::size_t i = 0, agree = 0, outward = 0;
  double worst = 0;
  for(Point_set::Index p : ps)
  {
    outward += (ps.normal(p) * pts[i].second > 0);
    const double dh = std::abs(mean[p] - truth[i].mean_curvature);
    agree += dh < 0.02;
    worst = std::max(worst, dh);
    ++i;
  }
  measured("normals estimated by the tool: outward (of 10000)", double(outward));
  measured("normals estimated by the tool: max |H - H(exact normals)|", worst);
  // Orientation: the spanning tree's part is closed, so its sign is chosen outward;
  // measured 10000/10000.
  CHECK(outward == pts.size());
  // H with the tool's normals (a quadric of 40 neighbours) vs exact normals (|H| up to 0.35):
  // measured max difference 0.0067 (0.026 with PCA normals of 18, 0.0104 with CGAL's jet normals).
  // 0.02 for 99% of the points: a wrong orientation flips H (differences ~0.2), so does a
  // normal estimation off by tens of degrees
  CHECK(agree > 0.99 * pts.size());
  CHECK(worst < 0.01);

  // --require-normals makes it an error.
  const Run strict = run_tool(q(input) + " " + q(file("strict.ply")) + " --require-normals");
  CHECK(strict.status == 2);
  CHECK(strict.err.find("has no normals") != std::string::npos);
  CHECK(!fs::exists(file("strict.ply")));
}

TEST_CASE("tool: every error exits with status 2, one line naming the file or option, no output")
{
  const std::vector<Oriented_point> pts = sphere(500, 1.0);
  const std::string good = file("good.xyz");
  write_xyz(good, pts);
  // A valid binary PLY to truncate.
  REQUIRE(run_tool(q(good) + " " + q(file("good_binary.ply")) + " --radius 0.3 --quiet").status == 0);
  const std::string binary = read_text(file("good_binary.ply"));
  write_text(file("truncated_binary.ply"), binary.substr(0, binary.size() / 2));
  const std::string ascii_header =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
    "property double z\nproperty double nx\nproperty double ny\nproperty double nz\nend_header\n";
  const std::string ascii_rows = "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n";
  write_text(file("truncated_ascii.ply"), ascii_header + "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0");
  write_text(file("text_ascii.ply"), ascii_header + "0 0 0 0 0 1\n1 0 zero 0 0 1\n0 1 0 0 0 1\n");
  std::string more = ascii_header;
  more.replace(more.find("vertex 3"), 8, "vertex 4");
  write_text(file("count_more.ply"), more + ascii_rows);
  std::string fewer = ascii_header;
  fewer.replace(fewer.find("vertex 3"), 8, "vertex 2");
  write_text(file("count_fewer.ply"), fewer + ascii_rows);
  std::string binary_fewer = binary;
  binary_fewer.replace(binary_fewer.find("vertex 500"), 10, "vertex 499");
  write_text(file("count_fewer_binary.ply"), binary_fewer);
  write_text(file("text.xyz"), "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1x\n");
  write_text(file("text_normal.xyz"), "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 abc 0 1\n");
  write_text(file("columns.xyz"), "0 0 0 0 0 1\n1 0 0\n");
  write_text(file("count.xyz"), "4\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n");
  write_text(file("text.off"), "OFF\n3 0 0\n0 0 0\n1 x 0\n0 1 0\n");
  write_text(file("count.off"), "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  write_text(file("faces.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
  write_text(file("empty.xyz"), "");
  write_text(file("not_ply.ply"), "solid ascii\n");
  write_text(file("positions.xyz"), "0 0 0\n1 0 0\n0 1 0\n");
  fs::create_directories(file("a_directory.xyz"));
  // headers whose counts or layout cannot be trusted: refused before anything is allocated
  const std::string vertex_xyz = "property float x\nproperty float y\nproperty float z\n";
  write_text(file("property_first.ply"), "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n");
  write_text(file("no_xyz.ply"), "ply\nformat ascii 1.0\nelement vertex 1\nproperty float u\nend_header\n0\n");
  write_text(file("huge_count.ply"), "ply\nformat binary_little_endian 1.0\nelement vertex 999999999999999999\n" +
                                       vertex_xyz + "end_header\n" + std::string(24, '\0'));
  std::string huge_list = "ply\nformat binary_little_endian 1.0\nelement vertex 1\n" + vertex_xyz +
                          "element face 1\nproperty list int int vertex_indices\nend_header\n" + std::string(12, '\0');
  huge_list += std::string("\x00\x94\x35\x77", 4);  // a list of 2e9 items
  write_text(file("huge_list.ply"), huge_list);
  write_text(file("negative_list.ply"),
             "ply\nformat ascii 1.0\nelement vertex 1\n" + vertex_xyz +
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n-1\n");
  write_text(file("partial_normals.ply"),
             "ply\nformat ascii 1.0\nelement vertex 1\n" + vertex_xyz + "property float nx\nend_header\n0 0 0 1\n");
  write_text(file("nine.xyz"), "0 0 0 1 2 3 0 0 1\n");
  write_text(file("colours.off"), "OFF\n3 0 0\n0 0 0 200 120 35\n1 0 0 200 120 35\n0 1 0 200 120 35\n");
  write_text(file("wrapped.ply"),
             "ply\nformat ascii 1.0\nelement vertex 2\n" + vertex_xyz + "end_header\n1 2\n3 4 5 6\n");
  write_text(file("two_per_line.ply"),
             "ply\nformat ascii 1.0\nelement vertex 2\n" + vertex_xyz + "end_header\n1 2 3 4 5 6\n");
  write_text(file("plus_minus.xyz"), "0 0 0\n+-1 0 0\n0 1 0\n");
  {
    std::string same;
    for(int i = 0; i < 19; ++i)
      same += "1 2 3\n";
    write_text(file("identical.xyz"), same);  // crashed CGAL's jet normals (issue 14)
  }
  ::mkfifo(file("fifo.xyz").c_str(), 0600);

  struct Case
  {
    std::string args, message;
  };
  const std::string out = file("out.ply");
  const std::vector<Case> cases = {
    {q(file("missing.xyz")) + " " + q(out), "cannot open input '" + file("missing.xyz") + "': No such file"},
    {q(file("a_directory.xyz")) + " " + q(out), "'" + file("a_directory.xyz") + "': it is a directory"},
    {q(file("truncated_binary.ply")) + " " + q(out), "'" + file("truncated_binary.ply") + "': truncated"},
    {q(file("truncated_ascii.ply")) + " " + q(out),
     "'" + file("truncated_ascii.ply") + "': truncated: the file ends in vertex 3"},
    {q(file("text_ascii.ply")) + " " + q(out), "'" + file("text_ascii.ply") + "': line 12: 'zero' is not a number"},
    {q(file("count_more.ply")) + " " + q(out),
     "'" + file("count_more.ply") + "': truncated: the file ends in vertex 4 of the 4"},
    {q(file("count_fewer.ply")) + " " + q(out),
     "'" + file("count_fewer.ply") + "': line 13: more data than the 2 vertices"},
    {q(file("count_fewer_binary.ply")) + " " + q(out), "more data than the 499 vertices"},
    {q(file("text.xyz")) + " " + q(out), "'" + file("text.xyz") + "' line 3: '1x' is not a number"},
    {q(file("text_normal.xyz")) + " " + q(out), "line 3: 'abc' is not a number"},
    {q(file("columns.xyz")) + " " + q(out), "line 2: 3 values where the previous lines have 6"},
    {q(file("count.xyz")) + " " + q(out), "first line declares 4 points but it has 3"},
    {q(file("text.off")) + " " + q(out), "'" + file("text.off") + "' line 4: 'x' is not a number"},
    {q(file("count.off")) + " " + q(out), "'" + file("count.off") +
                                            "' line 6: expected 3 (x y z) or 6 (x y z nx ny nz) values like the other "
                                            "vertices, found 4 (wrong vertex count in the header?)"},
    {q(file("faces.off")) + " " + q(out),
     "'" + file("faces.off") + "' line 7: unexpected line after the 3 vertices and 1 faces declared"},
    {q(file("empty.xyz")) + " " + q(out), "'" + file("empty.xyz") + "' contains no points"},
    {q(file("not_ply.ply")) + " " + q(out), "not a PLY file"},
    {q(file("positions.xyz")) + " " + q(out) + " --require-normals", "has no normals"},
    {q(good) + " " + q(out) + " --frobnicate", "unknown option '--frobnicate'"},
    {q(file("property_first.ply")) + " " + q(out), "PLY header line 3: a property before any element"},
    {q(file("no_xyz.ply")) + " " + q(out), "the PLY vertex element has no scalar property x"},
    {q(file("huge_count.ply")) + " " + q(out), "truncated: the file ends in vertex 3 of the 999999999999999999"},
    {q(file("huge_list.ply")) + " " + q(out), "truncated: the file ends in face 1 of the 1"},
    {q(file("negative_list.ply")) + " " + q(out), "invalid list length -1 (face 1 of the 1"},
    {q(file("partial_normals.ply")) + " " + q(out), "has only some of nx ny nz"},
    {q(file("nine.xyz")) + " " + q(out), "found 9; give --columns to name them"},
    {q(file("colours.off")) + " " + q(out), "the 4th to 6th values of its vertex lines are not unit normals"},
    {q(file("wrapped.ply")) + " " + q(out), "line 8: fewer values than the properties of vertex 1 of the 2"},
    {q(file("two_per_line.ply")) + " " + q(out), "line 8: more values than the properties of vertex 1 of the 2"},
    {q(file("plus_minus.xyz")) + " " + q(out), "line 2: '+-1' is not a number"},
    // warnings (no normals) come after a success only: the error stays one line
    {q(file("identical.xyz")) + " " + q(out) + " --radius 4x", "is 0 (coincident points?)"},
    {q(good) + " " + q(out) + " --columns x,y,nx", "--columns 'x,y,nx' does not name all of x, y, z"},
    {q(good) + " " + q(out) + " --columns x,y,z,nx,nx,nz", "names nx twice"},
    {q(file("good_binary.ply")) + " " + q(out) + " --columns x,y,z", "--columns applies to text point files"},
    {q(file("fifo.xyz")) + " " + q(out), "not a regular file"},
    {q(file("good_binary.ply")) + " " + q(file("good_binary.ply")), "is the input file"},
    {q(good) + " " + q(out) + " --neighbors 8", "--neighbors 8 is below the 12 neighbours of a valid aso estimate"},
    {q(good) + " " + q(out) + " --radius 0", "--radius must be positive, got '0'"},
    {q(good) + " " + q(out) + " --radius -1.5", "--radius must be positive, got '-1.5'"},
    {q(good) + " " + q(out) + " --radius 0x", "--radius must be positive, got '0x'"},
    {q(good) + " " + q(out) + " --radius big", "--radius expects a positive length"},
    {q(good) + " " + q(out) + " --radius", "option --radius needs a value"},
    {q(good) + " " + q(out) + " --neighbors 2", "--neighbors must be an integer >= 3"},
    {q(good) + " " + q(out) + " --neighbors 1.5", "--neighbors must be an integer >= 3"},
    {q(good) + " " + q(out) + " --radius 1 --neighbors 10", "either --radius or --neighbors"},
    {q(good) + " " + q(out) + " --method magic", "--method: unknown method 'magic'"},
    {q(good) + " " + q(out) + " --color blue", "--color: unknown quantity 'blue'"},
    {q(good) + " " + q(out) + " --threads 0", "--threads must be a positive integer"},
    {q(good) + " " + q(out) + " --quiet=yes", "option --quiet takes no value"},
    {q(good), "missing OUTPUT"},
    {q(good) + " " + q(out) + " extra", "unexpected argument 'extra'"},
    {q(good) + " " + q(file("out.txt")), "unsupported output format '.txt'"},
    {q(file("good_binary.ply")) + "x " + q(out), "cannot open input"},
    {q(good) + " " + q(file("no_such_folder/out.ply")), "cannot write output '" + file("no_such_folder/out.ply") + "'"},
  };
  for(const Case& c : cases)
  {
    fs::remove(out);
    const Run r = run_tool(c.args);
    INFO("arguments: " << c.args << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("point_set_curvatures: error: ", 0) == 0);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(out));
    CHECK(!fs::exists(file("out.txt")));
    CHECK(files_starting_with(".out.") == 0);  // no temporary file left behind
  }

  // A failing run leaves an existing OUTPUT untouched.
  write_text(out, "previous result");
  CHECK(run_tool(q(file("truncated_binary.ply")) + " " + q(out)).status == 2);
  CHECK(read_text(out) == "previous result");
  CHECK(files_starting_with(".out.") == 0);
}

// Issue 10: columns that are not normals, normals under other names, small neighbourhoods.
TEST_CASE("tool: rgb columns are refused with a message naming --columns, and --columns, CSV headers and normal_x PLY "
          "read the same cloud")
{
  const std::vector<Oriented_point> pts = sphere(500, 1.0);
  write_xyz(file("cols.xyz"), pts);
  REQUIRE(run_tool(q(file("cols.xyz")) + " " + q(file("cols_ref.csv")) + " --radius 0.6").status == 0);
  const std::string reference = read_text(file("cols_ref.csv"));

  std::ostringstream rgb, nine, csv, cloudcompare, asc;
  for(std::ostringstream* s : {&rgb, &nine, &csv, &cloudcompare, &asc})
    s->precision(17);
  cloudcompare << "//X,Y,Z,R,G,B,Nx,Ny,Nz\n";
  asc << "//X Y Z R G B Nx Ny Nz\n";  // CloudCompare's .asc export, separated by spaces
  for(const Oriented_point& p : pts)
  {
    const double x = p.first.x(), y = p.first.y(), z = p.first.z();
    const double nx = p.second.x(), ny = p.second.y(), nz = p.second.z();
    rgb << x << " " << y << " " << z << " 200 120 35\n";
    nine << x << " " << y << " " << z << " 200 120 35 " << nx << " " << ny << " " << nz << "\n";
    csv << x << "," << y << "," << z << "," << nx << "," << ny << "," << nz << "\n";
    cloudcompare << x << "," << y << "," << z << ",200,120,35," << nx << "," << ny << "," << nz << "\n";
    asc << x << " " << y << " " << z << " 200 120 35 " << nx << " " << ny << " " << nz << "\n";
  }
  write_text(file("rgb.xyz"), rgb.str());
  write_text(file("nine.txt"), nine.str());
  write_text(file("plain.csv"), csv.str());
  write_text(file("cloudcompare.csv"), cloudcompare.str());
  write_text(file("cloudcompare.asc"), asc.str());
  write_text(file("plain.asc"), csv.str());

  // x y z r g b: never read as normals without being told
  fs::remove(file("out.ply"));  // (another test case of this process may have written one)
  const Run refused = run_tool(q(file("rgb.xyz")) + " " + q(file("out.ply")));
  CHECK(refused.status == 2);
  CHECK(refused.err.find("columns 4-6 are not unit normals (median length 235.") != std::string::npos);
  CHECK(refused.err.find("--columns x,y,z,r,g,b") != std::string::npos);
  CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  CHECK(!fs::exists(file("out.ply")));
  // told: positions only, normals estimated with a warning
  const Run told = run_tool(q(file("rgb.xyz")) + " " + q(file("out.ply")) + " --columns x,y,z,r,g,b --radius 0.6");
  CHECK(told.status == 0);
  CHECK(told.err.find("has no normals: estimating them") != std::string::npos);

  // the same cloud through --columns, a comma-separated file and CloudCompare's header, and
  // CloudCompare's .asc export, read like .txt (issue 28: refused as an unknown extension)
  // (the colour columns of CloudCompare's files are attributes, dropped here to compare)
  for(const std::string& args : {q(file("nine.txt")) + " --columns x,y,z,_,_,_,nx,ny,nz", q(file("plain.csv")),
                                 q(file("cloudcompare.csv")), q(file("cloudcompare.asc")), q(file("plain.asc")),
                                 q(file("cloudcompare.asc")) + " --columns x,y,z,_,_,_,nx,ny,nz"})
  {
    const Run r = run_tool(args + " " + q(file("cols_other.csv")) + " --radius 0.6 --drop-attributes");
    INFO(args << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    CHECK(read_text(file("cols_other.csv")) == reference);
  }

  // PLY as PCL and Open3D write it: normal_x normal_y normal_z, properties in any order,
  // an extra property and a face element
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
      << "\nproperty double normal_x\nproperty double z\nproperty uchar red\nproperty double x\n"
         "property double normal_z\nproperty double y\nproperty double normal_y\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for(const Oriented_point& p : pts)
    ply << p.second.x() << " " << p.first.z() << " 7 " << p.first.x() << " " << p.second.z() << " " << p.first.y()
        << " " << p.second.y() << "\n";
  ply << "3 0 1 2\n";
  write_text(file("open3d.ply"), ply.str());
  const Run r = run_tool(q(file("open3d.ply")) + " " + q(file("cols_other.csv")) + " --radius 0.6 --drop-attributes");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());  // normals found: no warning
  CHECK(read_text(file("cols_other.csv")) == reference);
}

TEST_CASE("tool: 3-neighbour estimates are invalid, and a run without a valid estimate exits 3 with one line "
          "suggesting a scale")
{
  // The simulated LiDAR scan at r = 0.3: every point has about 3 neighbours. They used to be
  // reported valid (86.9%) with a mean H error of 0.072; then all invalid with exit status 0,
  // which a pipeline took for a success (issue 28). Exit 3, the output written, all invalid.
  for(const std::string quiet : {"", " --quiet"})
  {
    const Run r = run_tool(q(repo_data("goursat-lidar.xyz")) + " " + q(file("lidar.csv")) + " --radius 0.3" + quiet);
    INFO(r.err);
    REQUIRE(r.status == 3);
    if(quiet.empty())
      CHECK(r.out.find("valid       0 (0.00 %); 2947 too_few_neighbors") != std::string::npos);
    else
      CHECK(r.out.empty());
    CHECK(
      r.err.rfind("point_set_curvatures: error: no valid estimate: all 2947 points are too_few_neighbors: the median "
                  "neighbourhood holds 3 points: fewer than 12 neighbours, the least count of a valid aso estimate; "
                  "for about 40 neighbours, try --radius ",
                  0) == 0);
    CHECK(r.err.find("' was written, every row invalid\n") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  const Run r = run_tool(q(repo_data("goursat-lidar.xyz")) + " " + q(file("lidar.csv")) + " --radius 0.3");
  const std::string rows = read_text(file("lidar.csv"));
  CHECK(std::count(rows.begin(), rows.end(), '\n') == 2948);  // the header and every point
  CHECK(rows.find(",1\n") == std::string::npos);              // no row ends with valid = 1

  // at the scale it suggests (about 40 neighbours), no warning and every point valid but a few
  const std::size_t at = r.err.find("try --radius ") + 13;
  const std::string suggested = r.err.substr(at, r.err.find_first_of("\n ", at) - at);
  const Run again = run_tool(q(repo_data("goursat-lidar.xyz")) + " " + q(file("lidar.csv")) + " --radius " + suggested);
  INFO(again.out << again.err);
  CHECK(again.status == 0);
  CHECK(again.err.empty());

  // --neighbors below the method's minimum is refused at once
  const Run few = run_tool(q(repo_data("goursat-lidar.xyz")) + " " + q(file("lidar.csv")) + " --neighbors 5");
  CHECK(few.status == 2);
  CHECK(few.err.find("--neighbors 5 is below the 12 neighbours of a valid aso estimate") != std::string::npos);
  // and allowed with --min-neighbors
  CHECK(run_tool(q(repo_data("goursat-lidar.xyz")) + " " + q(file("lidar.csv")) +
                 " --neighbors 5 --min-neighbors 5 --quiet")
          .status == 0);
}

// Issue 28: a file smaller than a good neighbourhood is told so, not to try the count it ran
// with; counts of one are singular.
TEST_CASE(
  "tool: a file with fewer points than a good neighbourhood is told it is too small, and one point is one point")
{
  // 10 points of a plane and one point far from them; --min-neighbors 5 lets the 10 be valid
  std::vector<Oriented_point> pts;
  for(int i = 0; i < 10; ++i)
    pts.emplace_back(Point(0.1 * (i % 4), 0.1 * (i / 4), 0), Vector(0, 0, 1));
  write_xyz(file("ten.xyz"), pts);
  pts.emplace_back(Point(100, 100, 0), Vector(0, 0, 1));
  write_xyz(file("eleven.xyz"), pts);
  const Run ten = run_tool(q(file("ten.xyz")) + " " + q(file("ten.csv")) + " --min-neighbors 5");
  INFO(ten.err);
  REQUIRE(ten.status == 0);
  CHECK(ten.out.find("valid       10 (100.00 %)") != std::string::npos);
  CHECK(ten.err.find("warning: '" + file("ten.xyz") + "' is too small for aso: it holds 10 usable points") !=
        std::string::npos);
  CHECK(ten.err.find("--neighbors 40") == std::string::npos);  // the smallest count it ran with
  CHECK(std::count(ten.err.begin(), ten.err.end(), '\n') == 1);
  // the default automatic scale on 10 points: the estimate of the fixed count, with an error
  // of 0 where a quadric fits the plane exactly, NaN where too few neighbours weigh for one
  CHECK(
    run_tool(q(file("ten.xyz")) + " " + q(file("ten_40.csv")) + " --quiet --min-neighbors 5 --neighbors 40").status ==
    0);
  CHECK(csv_column(read_text(file("ten.csv")), "mean") == csv_column(read_text(file("ten_40.csv")), "mean"));
  CHECK(csv_column(read_text(file("ten.csv")), "dmax_x") == csv_column(read_text(file("ten_40.csv")), "dmax_x"));
  for(const std::string& e : csv_column(read_text(file("ten.csv")), "mean_error"))
    CHECK((e == "nan" || e == "0"));
  // by radius too, and the isolated point is "1 point", never "1 points"
  const Run eleven = run_tool(q(file("eleven.xyz")) + " " + q(file("eleven.csv")) + " --min-neighbors 5 --radius 1");
  INFO(eleven.err);
  REQUIRE(eleven.status == 0);
  CHECK(eleven.out.find("valid       10 (90.91 %); 1 too_few_neighbors") != std::string::npos);
  CHECK(eleven.err.find("is too small for aso: it holds 11 usable points") != std::string::npos);
  CHECK(eleven.err.find("; 1 point has too few neighbours for a fit and is invalid (too_few_neighbors)") !=
        std::string::npos);
  CHECK(eleven.err.find("1 points") == std::string::npos);
  CHECK(eleven.err.find("try --") == std::string::npos);  // no scale gives more points

  // the count the warning uses is the variant's (estimators.h): 15 points are enough for the
  // default ASO (12), too few for the paper's (20)
  std::vector<Oriented_point> fifteen;
  for(int i = 0; i < 15; ++i)
    fifteen.emplace_back(Point(0.1 * (i % 4), 0.1 * (i / 4), 0.01 * (i % 3)), Vector(0, 0, 1));
  write_xyz(file("fifteen.xyz"), fifteen);
  const Run robust = run_tool(q(file("fifteen.xyz")) + " " + q(file("fifteen.csv")) + " --neighbors 40");
  INFO(robust.err);
  CHECK(robust.status == 0);
  CHECK(robust.err.find("too small") == std::string::npos);
  const Run paper = run_tool(q(file("fifteen.xyz")) + " " + q(file("fifteen.csv")) + " --neighbors 40 --variant paper");
  INFO(paper.err);
  CHECK(paper.status == 0);
  CHECK(paper.err.find("is too small for aso: it holds 15 usable points (finite, with a normal), fewer than the 20 "
                       "neighbours") != std::string::npos);

  // without --min-neighbors nothing is valid: exit 3, one line saying the file is too small
  const Run none = run_tool(q(file("ten.xyz")) + " " + q(file("ten.csv")));
  INFO(none.err);
  CHECK(none.status == 3);
  CHECK(none.err == "point_set_curvatures: error: no valid estimate: all 10 points are too_few_neighbors: '" +
                      file("ten.xyz") +
                      "' is too small for aso: it holds 10 usable points (finite, with a normal), "
                      "fewer than the 12 neighbours from which aso's errors stay within twice those at 40 (measured, "
                      "see the manual), whatever --radius or --neighbors (--min-neighbors lowers the least count of a "
                      "valid estimate, at a cost in accuracy); '" +
                      file("ten.csv") + "' was written, every row invalid\n");
}

// Issue 28: every other reason for a run without a valid estimate is named, with exit status 3.
TEST_CASE("tool: runs without a valid estimate exit 3 naming the most frequent status: degenerate_fit, invalid_normal, "
          "non_finite_point, two_sheets")
{
  const std::vector<Oriented_point> pts = sphere(500, 1.0);
  write_xyz(file("ball.xyz"), pts);
  std::vector<Oriented_point> zero = pts, plate;
  for(Oriented_point& p : zero)
    p.second = Vector(0, 0, 0);
  write_xyz(file("zero.xyz"), zero);
  write_text(file("nan.xyz"), "nan 0 0 0 0 1\n0 inf 0 0 0 1\n");
  // two sheets 0.02 apart with opposite normals (a thin plate)
  for(int i = 0; i < 400; ++i)
    for(int side : {0, 1})
      plate.emplace_back(Point(0.05 * (i % 20), 0.05 * (i / 20), 0.02 * side), Vector(0, 0, side ? 1 : -1));
  write_xyz(file("plate.xyz"), plate);
  struct Case
  {
    std::string args, message;
  };
  const Case cases[] = {
    {q(file("ball.xyz")) + " --radius 1e300", "no valid estimate: all 500 points are degenerate_fit: coincident "
                                              "neighbours, neighbours along one line (a single scan line), or a radius "
                                              "far larger than the cloud; --radius 3.5x gives about 40 neighbours"},
    {q(file("zero.xyz")) + " --radius 0.5 --columns x,y,z,nx,ny,nz",
     "no valid estimate: all 500 points are invalid_normal: the normals are zero"},
    {q(file("nan.xyz")), "no valid estimate: all 2 points are non_finite_point: NaN or infinite coordinates"},
    {q(file("plate.xyz")) + " --radius 0.3",
     "points are two_sheets: two layers with opposite normals in every neighbourhood"},
  };
  for(const Case& c : cases)
  {
    fs::remove(file("none.csv"));
    const Run r = run_tool(c.args + " " + q(file("none.csv")) + " --quiet");
    INFO(c.args << "\n" << r.err);
    CHECK(r.status == 3);
    CHECK(r.err.rfind("point_set_curvatures: error: ", 0) == 0);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(fs::exists(file("none.csv")));
  }
}

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
  double sum = 0, worst = 0;
  for(std::size_t i = 0; i < t.size(); ++i)
  {
    const double a = line_angle_degrees(t[i].second, terrain[i].truth.normal);
    sum += a;
    worst = std::max(worst, a);
  }
  measured("airborne 5:1 lines, quadric normals: mean angle (deg)", sum / double(t.size()));
  measured("airborne 5:1 lines, quadric normals: worst angle (deg)", worst);
  CHECK(sum / double(t.size()) < 0.5);  // measured 0.20 (worst 0.81)

  // A mobile profiler with range noise of 0.3 spacings (issue 44, item 5): near the track the 40
  // nearest are the query's profile and the next profiles' points at the kernel's rim, where
  // the weight vanishes: the weights leave one noisy line, whose band set the quadric's frame,
  // and the normal lay about the line, sideways (19% of them more than 60 degrees off on a
  // 16 x 16 m scan). The frame now comes from the unweighted neighbourhood there, and the
  // automatic scale (the default) climbs to a rung that spreads in two directions.
  const std::vector<scan::Sample> clean_profiles = scan::mobile_profiles(scan::wavy_terrain(), 2.0);
  scan::Noise range_noise;
  range_noise.range_sigma = 0.3 * scan::median_spacing(clean_profiles);
  const std::vector<scan::Sample> profiles = scan::mobile_profiles(scan::wavy_terrain(), 2.0, 0.1, 0.0035, range_noise);
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

// Issue 14: Ctrl-C is honoured within a batch (at most 1% of the points, ~0.25 s) even when
// one grid cell holds every point, and neither one nor two interrupts leave a temporary file.
TEST_CASE("tool: SIGINT during a long run exits 130, SIGTERM 143, and neither leaves a temporary file, once or twice")
{
  // 20K points and a radius covering them all: 4e8 pairs, tens of seconds if not stopped
  write_xyz(file("slow.xyz"), sphere(20000, 1.0));
  struct Case
  {
    std::string signal;
    int signals, status;
  };
  // the second signal exits from the handler at once, with the same status
  for(const Case& c : {Case{"INT", 1, 130}, Case{"INT", 2, 130}, Case{"TERM", 1, 143}, Case{"TERM", 2, 143}})
  {
    INFO(c.signals << " SIG" << c.signal);
    fs::remove(file("slow.ply"));
    // (\$: expanded by bash -c, not by the shell of std::system)
    const std::string kill = "kill -" + c.signal + " \\$pid";
    const std::string kills = c.signals == 1 ? kill : kill + "; " + kill;
    const std::string script = std::string("'") + PSC_TOOL_PATH + "' '" + file("slow.xyz") + "' '" + file("slow.ply") +
                               "' --radius 3 --quiet 2> '" + file("slow.err") + "' & pid=\\$!; sleep 1; " + kills +
                               "; wait \\$pid; echo \\$? > '" + file("slow.status") + "'";
    REQUIRE(std::system(("bash -c \"" + script + "\"").c_str()) == 0);
    CHECK(std::atoi(read_text(file("slow.status")).c_str()) == c.status);
    CHECK(!fs::exists(file("slow.ply")));
    CHECK(files_starting_with(".slow.ply.tmp") == 0);
    // one signal: handled, the run stops at its next check and says so; the signal's default
    // action also gives 128 + signal but says nothing (measured: a tool without its SIGTERM
    // handler fails here only), and a run that ignored it would end with status 0
    if(c.signals == 1)
      CHECK(read_text(file("slow.err")).find("interrupted (") != std::string::npos);
  }
}

// Review findings: formats some writers produce are read, not refused.
TEST_CASE("tool: readers accept trailing comments, a count before a header, OFF counts on the first line, a line break "
          "after binary PLY data, out-of-range numbers")
{
  const std::vector<Oriented_point> pts = sphere(500, 1.0);
  write_xyz(file("ref.xyz"), pts);
  REQUIRE(run_tool(q(file("ref.xyz")) + " " + q(file("ref.csv")) + " --radius 0.6").status == 0);
  const std::string reference = read_text(file("ref.csv"));
  std::ostringstream commented, counted, off;
  for(std::ostringstream* s : {&commented, &counted, &off})
    s->precision(17);
  counted << pts.size() << "\nx y z nx ny nz\n";
  off << "NOFF " << pts.size() << " 0 0\n";
  for(const Oriented_point& p : pts)
  {
    const std::string row = [&] {
      std::ostringstream r;
      r.precision(17);
      r << p.first.x() << " " << p.first.y() << " " << p.first.z() << " " << p.second.x() << " " << p.second.y() << " "
        << p.second.z();
      return r.str();
    }();
    commented << row << "  # a comment\n";
    counted << row << "\n";
    off << row << "\n";
  }
  write_text(file("commented.xyz"), commented.str());
  write_text(file("counted.xyz"), counted.str());
  write_text(file("counts_inline.off"), off.str());
  REQUIRE(run_tool(q(file("ref.xyz")) + " " + q(file("ref.ply")) + " --radius 0.6 --quiet").status == 0);
  // a binary PLY (the tool's own output: x y z nx ny nz among its properties) plus a line break
  write_text(file("newline.ply"), read_text(file("ref.ply")) + "\n");
  for(const char* name : {"commented.xyz", "counted.xyz", "counts_inline.off"})
  {
    const Run r = run_tool(q(file(name)) + " " + q(file("other.csv")) + " --radius 0.6");
    INFO(name << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(read_text(file("other.csv")) == reference);
  }
  const Run nl = run_tool(q(file("newline.ply")) + " " + q(file("other.csv")) + " --radius 0.6");
  INFO(nl.err);
  CHECK(nl.status == 0);
  // 1e400 is infinite (a non-finite point), 1e-400 is 0
  write_text(file("range.xyz"), "1e400 0 0\n1e-400 0 0\n");
  const Run range =
    run_tool(q(file("range.xyz")) + " " + q(file("range.csv")) + " --radius 1 --min-neighbors 1 --quiet");
  CHECK(range.status == 3);  // read: no estimate is possible (one finite point), said with exit status 3
  CHECK(fs::exists(file("range.csv")));
}

// Issue 14 reproducers that are not errors: a UTF-8 byte order mark, integer coordinates in a
// PLY, 19 identical points without normals (once a crash), neighbor_count(SIZE_MAX).
TEST_CASE("tool and library: BOM, integer PLY coordinates, identical points, neighbor_count(SIZE_MAX)")
{
  // (the literal split where a hex escape would take the digit that follows)
  write_text(file("bom.xyz"), "\xEF\xBB\xBF"
                              "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n");
  CHECK(run_tool(q(file("bom.xyz")) + " " + q(file("bom.csv")) + " --quiet --min-neighbors 3").status == 0);
  write_text(file("int.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty float y\n"
                              "property double z\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  CHECK(run_tool(q(file("int.ply")) + " " + q(file("int.csv")) + " --quiet").status == 3);  // 3 points: no normals
  const std::string rows = read_text(file("int.csv"));
  CHECK(std::count(rows.begin(), rows.end(), '\n') == 4);  // header and three points
  std::string same;
  for(int i = 0; i < 19; ++i)
    same += "1 2 3\n";
  write_text(file("same.xyz"), same);
  const Run r = run_tool(q(file("same.xyz")) + " " + q(file("same.csv")));
  CHECK(r.status == 3);  // no crash, and no valid estimate
  CHECK(r.out.find("19 invalid_normal") != std::string::npos);
  CHECK(r.err.find("error: no valid estimate: all 19 points are invalid_normal: no normal could be estimated") !=
        std::string::npos);

  const auto pts = sphere(100, 1.0);
  const auto e = CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(
    pts, PSC::parameters::neighbor_count(std::numeric_limits<std::size_t>::max(), pair_maps));
  std::size_t all = 0;
  for(const auto& x : e)
    all += x.neighbor_count == pts.size();
  CHECK(all == pts.size());
}

// ---------------------------------------------------------------------------------------
// LAS input, attributes carried to the output, --fields, --float (issue 12)

namespace {

std::vector<std::array<double, 3> > write_las(const std::string& path, const std::vector<Oriented_point>& pts,
                                              int format, int minor, double scale, const double offset[3],
                                              std::size_t extra = 0, const double* beam_from = nullptr)
{
  std::vector<std::array<double, 3> > quantised;
  write_text(path, las_file(pts, format, minor, scale, offset, extra, &quantised, beam_from));
  return quantised;
}

}  // namespace

TEST_CASE("tool: LAS 1.0-1.4 point formats 0-10 with their fields as attributes, refused and suspicious LAS files")
{
  // a sphere of radius 2 in LiDAR coordinates (offset 1e6, 2e6, 100; millimetre scale)
  const double offset[3] = {1e6, 2e6, 100};
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(3000, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  const std::string viewpoint = " --orient viewpoint:1000003,2000004,105";  // normals inwards: H = -1/2
  std::string reference_curvatures;
  // each format in the first version that has it, and formats 0 and 1 in LAS 1.0 and 1.1 too
  // (the same 227-byte header as 1.2 for what the reader uses)
  std::vector<std::pair<int, int> > versions;
  for(int format = 0; format <= 10; ++format)
    versions.emplace_back(format, format >= 6 ? 4 : format >= 4 ? 3 : 2);
  for(int minor : {0, 1})
    for(int format : {0, 1})
      versions.emplace_back(format, minor);
  for(const auto& version : versions)
  {
    const int format = version.first, minor = version.second;
    INFO("point format " << format << ", LAS 1." << minor);
    const std::string las =
                        file("f" + std::to_string(format) + (minor < 2 ? "_1" + std::to_string(minor) : "") + ".las"),
                      out = file("f.ply");
    const auto quantised = write_las(las, pts, format, minor, 0.001, offset, format == 8 ? 5 : 0);
    const Run r = run_tool(q(las) + " " + q(out) + " --radius 0.5" + viewpoint);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("valid       3000 (100.00 %)") != std::string::npos);
    Point_set ps;
    REQUIRE(CGAL::IO::read_PLY(out, ps));
    REQUIRE(ps.size() == pts.size());
    const auto mean = property<double>(ps, "mean");
    const auto intensity = property<std::uint16_t>(ps, "intensity");
    const auto classification = property<std::uint8_t>(ps, "classification");
    const auto returns = property<std::uint8_t>(ps, "number_of_returns");
    const auto angle = property<float>(ps, "scan_angle");
    std::size_t i = 0, wrong = 0;
    double worst_h = 0;
    std::ostringstream curvatures;
    curvatures.precision(17);
    for(Point_set::Index p : ps)
    {
      const Point& x = ps.point(p);
      wrong += (x.x() != quantised[i][0] || x.y() != quantised[i][1] || x.z() != quantised[i][2]) ? 1 : 0;
      wrong += intensity[p] != las_intensity(i) || classification[p] != las_classification(i) || returns[p] != 2 ||
               std::abs(angle[p] + 12) > 1e-4;
      worst_h = std::max(worst_h, std::abs(mean[p] + 0.5));
      curvatures << mean[p] << " ";
      ++i;
    }
    CHECK(wrong == 0);
    CHECK(worst_h < 0.05);
    // the same positions whatever the format: the same curvatures
    if(reference_curvatures.empty())  // format 0, LAS 1.2: every other row is compared with it
      reference_curvatures = curvatures.str();
    CHECK(curvatures.str() == reference_curvatures);
    const bool gps = format != 0 && format != 2, rgb = format == 2 || format == 3 || format == 5 || format >= 7;
    CHECK(ps.property_map<double>("gps_time").second == gps);
    CHECK(ps.property_map<std::uint8_t>("red").second == (rgb && format != 9));  // (8 bits in PLY)
    CHECK(ps.property_map<std::uint8_t>("overlap").second == (format >= 6));
    CHECK(ps.property_map<std::uint16_t>("nir").second == (format == 8 || format == 10));
    if(gps)
    {
      const auto t = property<double>(ps, "gps_time");
      std::size_t k = 0, bad = 0;
      for(Point_set::Index p : ps)
        bad += t[p] != las_gps_time(k++);
      CHECK(bad == 0);
    }
    if(format == 3 || format == 8)
    {
      const auto red = property<std::uint8_t>(ps, "red");
      std::size_t k = 0, bad = 0;
      for(Point_set::Index p : ps)
        bad += red[p] != las_red(k++) >> 8;
      CHECK(bad == 0);
    }
  }

  // Refused, exit 2, one line, no output: .laz, a compressed format byte, a truncated file,
  // a record length below the format's, no signature, a format not valid in the version.
  const std::string good = read_text(file("f3.las"));
  auto variant = [&](const std::string& name, std::size_t at, const std::string& bytes, std::size_t keep = 0) {
    std::string s = good;
    if(keep)
      s.resize(keep);
    s.replace(at, bytes.size(), bytes);
    write_text(file(name), s);
  };
  write_text(file("c.laz"), good);
  variant("compressed.las", 104, std::string(1, char(0x83)));
  variant("truncated.las", 0, "L", good.size() - 10);
  variant("short_record.las", 105, std::string("\x10\x00", 2));
  variant("signature.las", 0, "LASX");
  variant("format7_in_12.las", 104, std::string(1, char(7)));
  const std::pair<const char*, const char*> refused[] = {
    {"c.laz", "decompress it first"},
    {"compressed.las", "compressed LAS (LAZ) data"},
    {"truncated.las", "truncated: the header declares 3000 points"},
    {"short_record.las", "point record length 16 is smaller than the 34 bytes of point format 3"},
    {"signature.las", "no 'LASF' signature"},
    {"format7_in_12.las", "point data record format 7 is not valid in LAS 1.2"}};
  for(const auto& c : refused)
  {
    INFO(c.first);
    fs::remove(file("refused.ply"));
    const Run r = run_tool(q(file(c.first)) + " " + q(file("refused.ply")));
    CHECK(r.status == 2);
    CHECK(r.err.find(c.second) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(file("refused.ply")));
  }
  // --orient scanner: each normal towards the origin of its pulse (the wave packets' x(t) y(t)
  // z(t) of formats 4, 5, 9, 10), here the sphere's centre: the same normals, so the same
  // output, as --orient viewpoint at the centre; in memory and in tiles
  const double centre[3] = {1e6 + 3, 2e6 + 4, 105};
  for(int format : {4, 9, 10})
  {
    INFO("point format " << format);
    const std::string las = file("w" + std::to_string(format) + ".las");
    write_las(las, pts, format, format == 4 ? 3 : 4, 0.001, offset, 0, centre);
    const Run scanner = run_tool(q(las) + " " + q(file("scanner.ply")) + " --radius 0.5 --orient scanner");
    const Run view = run_tool(q(las) + " " + q(file("view.ply")) + " --radius 0.5" + viewpoint);
    REQUIRE(scanner.status == 0);
    REQUIRE(view.status == 0);
    CHECK(scanner.out.find("valid       3000 (100.00 %)") != std::string::npos);
    const std::string a = read_text(file("scanner.ply")), b = read_text(file("view.ply"));
    CHECK(a.substr(a.find("end_header")) == b.substr(b.find("end_header")));
    CHECK(a.find("property float wave_x_t\nproperty float wave_y_t\nproperty float wave_z_t\n") != std::string::npos);
    const Run tiled =
      run_tool(q(las) + " " + q(file("scanner_tiled.ply")) + " --radius 0.5 --orient scanner --memory-limit 1200K");
    REQUIRE(tiled.status == 0);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(read_text(file("scanner_tiled.ply")) == a);
  }
  {
    // pulses without a direction (x(t) y(t) z(t) zero: the last 12 bytes of the first 10
    // records) keep +z, said alike in memory and in tiles (one estimation step for both)
    std::string las = read_text(file("w4.las"));
    std::uint32_t first = 0;
    std::uint16_t length = 0;
    std::memcpy(&first, &las[96], 4);
    std::memcpy(&length, &las[105], 2);
    for(std::size_t i = 0; i < 10; ++i)
      std::fill_n(las.begin() + first + (i + 1) * length - 12, 12, '\0');
    write_text(file("undirected.las"), las);
    const std::string said = "warning: --orient scanner: 10 points have no pulse direction and keep normals "
                             "oriented to +z";
    const Run whole = run_tool(q(file("undirected.las")) + " " + q(file("u.ply")) + " --radius 0.5 --orient scanner");
    const Run tiled = run_tool(q(file("undirected.las")) + " " + q(file("u_tiled.ply")) +
                               " --radius 0.5 --orient scanner --memory-limit 1200K");
    REQUIRE(whole.status == 0);
    REQUIRE(tiled.status == 0);
    CHECK(whole.err.find(said) != std::string::npos);
    CHECK(tiled.err.find(said) != std::string::npos);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(read_text(file("u_tiled.ply")) == read_text(file("u.ply")));
    // a file with normals and no pulses: --orient scanner has nothing to turn, in memory and
    // in tiles (it indexed the missing pulse attributes)
    write_xyz(file("oriented.xyz"), sphere(3000, 1.0));
    for(const char* limit : {"", " --memory-limit 400K"})
    {
      INFO("oriented.xyz --orient scanner" << limit);
      const Run r =
        run_tool(q(file("oriented.xyz")) + " " + q(file("o.ply")) + " --radius 0.2 --orient scanner" + limit);
      CHECK(r.status == 0);
      CHECK(r.out.find("valid       3000 (100.00 %)") != std::string::npos);
    }
  }
  {
    const Run r = run_tool(q(file("f3.las")) + " " + q(file("x.ply")) + " --radius 0.5 --orient scanner");
    CHECK(r.status == 2);
    CHECK(r.err.find("--orient scanner: ") != std::string::npos);
    CHECK(r.err.find("holds no pulse directions") != std::string::npos);
  }

  // header bounds that do not hold the points: read, with a warning
  std::string wrong_bounds = good;
  put_le<double>(wrong_bounds, 179, 1e6 + 4.0);  // max x below the sphere's 1e6 + 5
  write_text(file("bounds.las"), wrong_bounds);
  const Run w = run_tool(q(file("bounds.las")) + " " + q(file("bounds.ply")) + " --radius 0.5" + viewpoint);
  CHECK(w.status == 0);
  CHECK(w.err.find("is not within the header's bounds") != std::string::npos);
  // with every digit the numbers need (issue 28: six digits printed "[999999, 1e+06] is not
  // within the header's bounds [999999, 1e+06]"): "x range [LO, HI] is not within the
  // header's bounds [LO', HI']", each reading back as the exact value
  double quantised_max = -HUGE_VAL;
  for(const Oriented_point& p : pts)
    quantised_max = std::max(quantised_max, double(std::lround((p.first.x() - offset[0]) / 0.001)) * 0.001 + offset[0]);
  auto bracket = [&](const std::string& before) {
    const std::size_t at = w.err.find(before);
    REQUIRE(at != std::string::npos);
    const std::size_t open = at + before.size(), comma = w.err.find(", ", open), close = w.err.find(']', open);
    return std::make_pair(w.err.substr(open, comma - open), w.err.substr(comma + 2, close - comma - 2));
  };
  const auto range = bracket("x range ["), bounds = bracket("header's bounds [");
  INFO(w.err);
  CHECK(std::stod(range.second) == quantised_max);
  CHECK(std::stod(bounds.second) == 1e6 + 4.0);
  CHECK(range.second != bounds.second);
  CHECK(bounds.second == "1000004");
}

// ---------------------------------------------------------------------------------------
// LAS output, extra bytes, geographic coordinates, truncated files (issue 28)

#include "las_test_reader.h"

namespace {

// The values of column `name` of a CSV file with a header line.
std::vector<double> csv_values(const std::string& csv, const std::string& name)
{
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for(std::size_t b = 0;;)
  {
    const std::size_t comma = line.find(',', b);
    names.push_back(line.substr(b, comma == std::string::npos ? std::string::npos : comma - b));
    if(comma == std::string::npos)
      break;
    b = comma + 1;
  }
  const std::size_t column = std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
  INFO("CSV column " << name << " in " << names.size() << " columns");
  REQUIRE(column < names.size());
  std::vector<double> values;
  while(std::getline(in, line))
  {
    std::size_t b = 0;
    for(std::size_t c = 0; c < column; ++c)
      b = line.find(',', b) + 1;
    values.push_back(std::strtod(line.c_str() + b, nullptr));
  }
  return values;
}

// A LAS 1.2 file of format 3 whose records end with 8 extra bytes described by an extra-bytes
// VLR: Amplitude (float, 0.5 i), Reflectance (int16 with scale 0.01: raw i % 2000 - 1000),
// Deviation (uint16, 7 i); and a GeoTIFF key of a projected CRS.
std::string las_with_extra_bytes(const std::vector<Oriented_point>& pts, const double offset[3],
                                 std::vector<std::array<double, 3> >* quantised)
{
  using namespace psc_las_test;
  std::string in = las_file(pts, 3, 2, 0.001, offset, 8, quantised);
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    const std::size_t r = 227 + i * 42 + 34;
    set_le<float>(in, r, 0.5f * float(i));
    set_le<std::int16_t>(in, r + 4, std::int16_t(int(i % 2000) - 1000));
    set_le<std::uint16_t>(in, r + 6, std::uint16_t(i * 7));
  }
  const std::string descriptors = descriptor(9, "Amplitude") +
                                  descriptor(4, "Reflectance", 8, 0.01, 0, "reflectance dB") +
                                  descriptor(3, "Deviation");
  return with_vlrs(in, {vlr("LASF_Projection", 34735, geokeys(1)), vlr("LASF_Spec", 4, descriptors)});
}

}  // namespace

TEST_CASE("tool: LAS output is LAS 1.4 with the estimates as extra bytes, per an independent reader of the "
          "specification, tiles give the same bytes, read back")
{
  using namespace psc_las_test;
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);  // 2023-11-14, day 318: reproducible headers
  const double offset[3] = {1e6, 2e6, 100};
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(3000, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  pts.emplace_back(Point(1e6 + 30, 2e6 + 4, 105), Vector(0, 0, 1));  // isolated: invalid
  const std::size_t n = pts.size();
  std::vector<std::array<double, 3> > quantised;
  const std::string in = las_with_extra_bytes(pts, offset, &quantised);
  write_text(file("eb.las"), in);
  const std::string viewpoint = " --orient viewpoint:1000003,2000004,105";  // normals inwards: H = -1/2
  const Run r = run_tool(q(file("eb.las")) + " " + q(file("eb_out.las")) + " --radius 0.5" + viewpoint);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("valid       3000 (99.97 %)") != std::string::npos);
  CHECK(r.err.find("meaningless") == std::string::npos);  // a projected CRS: no warning
  const Las l = read_las_1_4(read_text(file("eb_out.las")));
  CHECK(l.major == 1);
  CHECK(l.minor == 4);
  CHECK(l.header_size == 375);
  CHECK(l.format == 3);  // the input's
  CHECK(l.software == "point_set_curvatures");
  CHECK(l.day == 318);
  CHECK(l.year == 2023);
  CHECK(l.count == n);
  CHECK(l.legacy_count == n);  // format 0-5, the count fits
  CHECK(l.by_return[0] == n);  // every point is return 1 of 2
  CHECK(l.legacy_by_return[0] == n);
  CHECK(l.by_return[1] == 0);
  CHECK(l.first_evlr == 0);
  CHECK(l.evlr_count == 0);
  for(int a = 0; a < 3; ++a)
  {
    CHECK(l.scale[a] == 0.001);
    CHECK(l.offset[a] == offset[a]);
    double lo = 1e300, hi = -1e300;
    for(const auto& x : quantised)
    {
      lo = std::min(lo, x[a]);
      hi = std::max(hi, x[a]);
    }
    CHECK(l.min[a] == lo);
    CHECK(l.max[a] == hi);
  }
  // the VLRs: the input's GeoTIFF keys, then the extra-bytes VLR of the output
  REQUIRE(l.vlrs.size() == 2);
  CHECK(l.vlrs[0].user_id == "LASF_Projection");
  CHECK(l.vlrs[0].record_id == 34735);
  CHECK(l.vlrs[0].payload == geokeys(1));
  CHECK(l.vlrs[1].user_id == "LASF_Spec");
  CHECK(l.vlrs[1].record_id == 4);
  const std::vector<std::string> names = {
    "nx",        "ny",     "nz",        "k_min",       "k_max",    "mean",   "gaussian",
    "dmin_x",    "dmin_y", "dmin_z",    "dmax_x",      "dmax_y",   "dmax_z", "normal_coherence",
    "neighbors", "valid",  "Amplitude", "Reflectance", "Deviation"};
  REQUIRE(l.descriptors.size() == names.size());
  for(std::size_t k = 0; k < names.size(); ++k)
  {
    const Descriptor& d = l.descriptors[k];
    INFO(names[k]);
    CHECK(d.name == names[k]);
    CHECK(d.bytes.substr(0, 2) == std::string(2, '\0'));  // reserved
    const int type = k < 14 ? 10 : k == 14 ? 6 : k == 15 ? 1 : k == 16 ? 9 : k == 17 ? 4 : 3;
    CHECK(d.data_type == type);
    if(k < 14)
    {
      CHECK(d.options == 1);  // no_data
      CHECK(std::isnan(le<double>(d.no_data, 0)));
      CHECK(!d.description.empty());
    }
    else if(k == 17)
    {
      CHECK(d.options == 8);  // scale, as in the input
      CHECK(d.scale == 0.01);
      CHECK(d.description == "reflectance dB");
    }
    else
      CHECK(d.options == 0);
  }
  CHECK(l.descriptors[5].description == "mean curvature (k_min+k_max)/2");
  CHECK(l.point_offset == 375 + 54 + 16 + 54 + 192 * names.size());
  CHECK(l.record_length == 34 + 14 * 8 + 4 + 1 + 4 + 2 + 2);
  REQUIRE(l.file.size() == l.point_offset + n * l.record_length);
  std::size_t mean_at = 0, valid_at = 0, neighbors_at = 0, amplitude_at = 0, reflectance_at = 0, deviation_at = 0;
  REQUIRE(l.extra("mean", mean_at));
  REQUIRE(l.extra("valid", valid_at));
  REQUIRE(l.extra("neighbors", neighbors_at));
  REQUIRE(l.extra("Amplitude", amplitude_at));
  REQUIRE(l.extra("Reflectance", reflectance_at));
  REQUIRE(l.extra("Deviation", deviation_at));
  const std::size_t in_offset = le<std::uint32_t>(in, 96);
  std::size_t wrong_standard = 0, wrong_extra = 0;
  double worst_h = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::string rec = l.record(i);
    // every standard field as in the input: the same 34 bytes
    wrong_standard += rec.substr(0, 34) != in.substr(in_offset + i * 42, 34);
    wrong_extra += le<float>(rec, amplitude_at) != 0.5f * float(i) ||
                   le<std::int16_t>(rec, reflectance_at) != int(i % 2000) - 1000 ||
                   le<std::uint16_t>(rec, deviation_at) != std::uint16_t(i * 7);
    const double mean = le<double>(rec, mean_at);
    if(i < 3000)
    {
      wrong_extra += le<std::uint8_t>(rec, valid_at) != 1 || le<std::int32_t>(rec, neighbors_at) < 20;
      worst_h = std::max(worst_h, std::abs(mean + 0.5));
    }
    else  // the isolated point: no_data
      wrong_extra += le<std::uint8_t>(rec, valid_at) != 0 || !std::isnan(mean);
  }
  CHECK(wrong_standard == 0);
  CHECK(wrong_extra == 0);
  CHECK(worst_h < 0.05);

  // in tiles: the same bytes
  const Run tiled =
    run_tool(q(file("eb.las")) + " " + q(file("eb_tiled.las")) + " --radius 0.5 --orient +z --memory-limit 1200K");
  const Run whole = run_tool(q(file("eb.las")) + " " + q(file("eb_whole.las")) + " --radius 0.5 --orient +z");
  REQUIRE(tiled.status == 0);
  REQUIRE(whole.status == 0);
  CHECK(tiled.out.find("  tiles") != std::string::npos);
  CHECK(read_text(file("eb_tiled.las")) == read_text(file("eb_whole.las")));

  // --float: float32 estimates with a NaN no_data (a double, as the specification upcasts floats)
  REQUIRE(
    run_tool(q(file("eb.las")) + " " + q(file("eb_float.las")) + " --radius 0.5 --float --quiet" + viewpoint).status ==
    0);
  const Las f = read_las_1_4(read_text(file("eb_float.las")));
  REQUIRE(f.descriptors.size() == names.size());
  CHECK(f.descriptors[5].data_type == 9);
  CHECK(f.descriptors[5].options == 1);
  CHECK(std::isnan(le<double>(f.descriptors[5].no_data, 0)));
  CHECK(f.record_length == 34 + 14 * 4 + 4 + 1 + 4 + 2 + 2);
  std::size_t float_mean_at = 0;
  REQUIRE(f.extra("mean", float_mean_at));
  CHECK(le<float>(f.record(7), float_mean_at) == float(le<double>(l.record(7), mean_at)));

  // read back by the tool's reader: the estimates and the extra bytes as attributes
  REQUIRE(
    run_tool(q(file("eb_out.las")) + " " + q(file("back.csv")) + " --radius 0.5 --fields mean --quiet" + viewpoint)
      .status == 0);
  const std::string back = read_text(file("back.csv"));
  const std::vector<double> input_mean = csv_values(back, "input_mean"), amplitude = csv_values(back, "Amplitude"),
                            reflectance = csv_values(back, "Reflectance"), deviation = csv_values(back, "Deviation"),
                            x = csv_values(back, "x");
  REQUIRE(input_mean.size() == n);
  std::size_t wrong_back = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double m = le<double>(l.record(i), mean_at);
    wrong_back += !(m == input_mean[i] || (std::isnan(m) && std::isnan(input_mean[i]))) ||
                  amplitude[i] != 0.5 * double(i) || std::abs(reflectance[i] - 0.01 * (int(i % 2000) - 1000)) > 1e-12 ||
                  deviation[i] != double(i * 7 % 65536) || x[i] != quantised[i][0];
  }
  CHECK(wrong_back == 0);

  // a text input: format 6, return 1 of 1, the offset at the floor of the minimum, a scale of
  // a million steps or more across the extent (4: 1e-6)
  std::vector<Oriented_point> ball;
  for(const Oriented_point& p : sphere(2000, 2.0))
    ball.emplace_back(Point(p.first.x() + 10.5, p.first.y() + 20.5, p.first.z() + 30.5), p.second);
  write_xyz(file("ball.xyz"), ball);
  REQUIRE(
    run_tool(q(file("ball.xyz")) + " " + q(file("ball.las")) + " --radius 0.5 --fields mean,valid --quiet").status ==
    0);
  const Las b = read_las_1_4(read_text(file("ball.las")));
  CHECK(b.format == 6);
  CHECK(b.legacy_count == 0);  // formats 6-10: the legacy counts are 0
  CHECK(b.count == ball.size());
  CHECK(b.by_return[0] == ball.size());
  CHECK(b.system_id == "OTHER");
  CHECK(b.record_length == 30 + 8 + 1);
  REQUIRE(b.vlrs.size() == 1);
  REQUIRE(b.descriptors.size() == 2);
  double lo[3] = {1e300, 1e300, 1e300};
  for(const Oriented_point& p : ball)
    for(int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p.first[a]);
  std::size_t wrong_ball = 0;
  for(int a = 0; a < 3; ++a)
  {
    CHECK(b.offset[a] == std::floor(lo[a]));
    CHECK(b.scale[a] == 1e-6);
  }
  double worst_ball = 0;
  std::size_t ball_mean_at = 0;
  REQUIRE(b.extra("mean", ball_mean_at));
  for(std::size_t i = 0; i < ball.size(); ++i)
  {
    for(int a = 0; a < 3; ++a)
      wrong_ball += std::abs(b.coordinate(i, a) - ball[i].first[a]) > 0.5e-6 * (1 + 1e-9);
    wrong_ball += b.record(i)[14] != char(0x11);  // return 1 of 1
    worst_ball = std::max(worst_ball, std::abs(le<double>(b.record(i), ball_mean_at) - 0.5));
  }
  CHECK(wrong_ball == 0);
  CHECK(worst_ball < 0.01);

  // in tiles, the scale and offset from the same bounds: the same bytes
  const Run ball_tiled = run_tool(q(file("ball.xyz")) + " " + q(file("ball_tiled.las")) +
                                  " --radius 0.5 --fields mean,valid --memory-limit 100K");
  REQUIRE(ball_tiled.status == 0);
  CHECK(ball_tiled.out.find("  tiles") != std::string::npos);
  CHECK(read_text(file("ball_tiled.las")) == read_text(file("ball.las")));
  // a point with a non-finite coordinate: at the offset, withheld, out of the bounds, warned of
  {
    std::ofstream add(file("ball.xyz"), std::ios::app);
    add << "nan 20 30 0 0 1\n";
  }
  const Run nan_run =
    run_tool(q(file("ball.xyz")) + " " + q(file("ball_nan.las")) + " --radius 0.5 --fields mean,valid");
  REQUIRE(nan_run.status == 0);
  CHECK(
    nan_run.err.find("1 points with non-finite coordinates are written to the LAS output at its offset, withheld") !=
    std::string::npos);
  const Las bn = read_las_1_4(read_text(file("ball_nan.las")));
  REQUIRE(bn.count == ball.size() + 1);
  CHECK((bn.record(ball.size())[15] & 4) == 4);  // withheld (formats 6-10: bit 2 of byte 15)
  CHECK((bn.record(0)[15] & 4) == 0);
  CHECK(bn.coordinate(ball.size(), 0) == bn.offset[0]);
  for(int a = 0; a < 3; ++a)
  {
    CHECK(bn.min[a] == b.min[a]);
    CHECK(bn.max[a] == b.max[a]);
  }
  // --drop-attributes: a LAS input's standard fields stay, its extra bytes go
  REQUIRE(run_tool(q(file("eb.las")) + " " + q(file("eb_drop.las")) +
                   " --radius 0.5 --fields mean --drop-attributes --quiet" + viewpoint)
            .status == 0);
  const Las dropped = read_las_1_4(read_text(file("eb_drop.las")));
  REQUIRE(dropped.descriptors.size() == 1);
  CHECK(dropped.descriptors[0].name == "mean");
  CHECK(dropped.format == 3);
  CHECK(dropped.record_length == 34 + 8);
  CHECK(dropped.record(42).substr(0, 34) == in.substr(in_offset + 42 * 42, 34));

  // LAS 1.4 format 6 with a WKT CRS in an extended VLR: copied after the points, the WKT bit kept
  std::string v14 = las_file(pts, 6, 4, 0.001, offset);
  const std::string wkt = "PROJCS[\"WGS 84 / UTM zone 32N\",GEOGCS[\"WGS 84\"],UNIT[\"metre\",1]]";
  set_le<std::uint16_t>(v14, 6, 16);  // WKT
  set_le<std::uint64_t>(v14, 235, v14.size());
  set_le<std::uint32_t>(v14, 243, 1);
  v14 += evlr("LASF_Projection", 2112, wkt + std::string(1, '\0'));
  write_text(file("evlr.las"), v14);
  const Run e =
    run_tool(q(file("evlr.las")) + " " + q(file("evlr_out.las")) + " --radius 0.5 --fields mean" + viewpoint);
  INFO(e.err);
  REQUIRE(e.status == 0);
  CHECK(e.err.find("meaningless") == std::string::npos);
  const Las el = read_las_1_4(read_text(file("evlr_out.las")));
  CHECK(el.format == 6);
  CHECK(el.global_encoding == 16);
  CHECK(el.legacy_count == 0);
  REQUIRE(el.evlr_count == 1);
  CHECK(el.first_evlr == el.point_offset + n * el.record_length);
  REQUIRE(el.evlrs.size() == 1);
  CHECK(el.evlrs[0].user_id == "LASF_Projection");
  CHECK(el.evlrs[0].record_id == 2112);
  CHECK(el.evlrs[0].payload == wkt + std::string(1, '\0'));
  CHECK(el.file.size() == el.first_evlr + 60 + wkt.size() + 1);
  CHECK(el.record(5).substr(0, 30) == v14.substr(375 + 5 * 30, 30));

  // an extra-bytes descriptor held in an EVLR (not read, not copied: the output's VLR
  // describes its own fields) beside another EVLR: the file ends where the copied EVLR ends (the reserved size
  // counted both: a file cut at the reservation had zeros after its end)
  {
    std::string eb = las_file(pts, 6, 4, 0.001, offset, 4);
    for(std::size_t i = 0; i < n; ++i)
      set_le<float>(eb, 375 + i * 34 + 30, 0.25f * float(i));
    set_le<std::uint64_t>(eb, 235, eb.size());
    set_le<std::uint32_t>(eb, 243, 2);
    const std::string mine(100, 'x');
    eb += evlr("LASF_Spec", 4, descriptor(9, "Amplitude")) + evlr("MyStuff", 7, mine);
    write_text(file("evlr_eb.las"), eb);
    const Run r =
      run_tool(q(file("evlr_eb.las")) + " " + q(file("evlr_eb_out.las")) + " --radius 0.5 --fields mean" + viewpoint);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const Las l = read_las_1_4(read_text(file("evlr_eb_out.las")));
    REQUIRE(l.evlr_count == 1);
    REQUIRE(l.evlrs.size() == 1);
    CHECK(l.evlrs[0].user_id == "MyStuff");
    CHECK(l.file.size() == l.first_evlr + 60 + mine.size());
    CHECK(l.first_evlr == l.point_offset + n * l.record_length);
    CHECK(l.record_length == 30 + 8);  // mean as double; the undescribed extra bytes are not kept
  }

  // every point format 0-10: the standard fields of each record written back bytewise (flags,
  // scan angles, GPS times, colours, NIR, wave packets with their byte offsets and pulses)
  {
    static const std::size_t standard[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
    const std::vector<Oriented_point> few(pts.begin(), pts.begin() + 400);
    const double centre[3] = {1e6 + 3, 2e6 + 4, 105};
    for(int format = 0; format <= 10; ++format)
    {
      INFO("point format " << format);
      const int minor = format >= 6 ? 4 : format >= 4 ? 3 : 2;
      std::string src = las_file(few, format, minor, 0.001, offset, 0, nullptr, centre);
      const std::size_t header = le<std::uint16_t>(src, 94);
      if(format == 4 || format == 5 || format == 9 || format == 10)
        for(std::size_t i = 0; i < few.size(); ++i)
          set_le<std::uint64_t>(src,
                                header + i * standard[format] +
                                  (format == 4   ? 28
                                   : format == 5 ? 34
                                   : format == 9 ? 30
                                                 : 38) +
                                  1,
                                std::uint64_t(1000 + 256 * i));
      write_text(file("fmt.las"), src);
      const Run fr =
        run_tool(q(file("fmt.las")) + " " + q(file("fmt_out.las")) + " --radius 0.5 --fields mean --quiet" + viewpoint);
      INFO(fr.err);
      REQUIRE(fr.status == 0);
      const Las fl = read_las_1_4(read_text(file("fmt_out.las")));
      CHECK(fl.format == format);
      CHECK(fl.record_length == standard[format] + 8);
      CHECK(fl.legacy_count == (format <= 5 ? few.size() : 0));
      std::size_t different = 0;
      for(std::size_t i = 0; i < few.size(); ++i)
        different +=
          fl.record(i).substr(0, standard[format]) != src.substr(header + i * standard[format], standard[format]);
      CHECK(different == 0);
    }
  }

  // refused before any work: --color and --ascii with a .las output
  for(const char* option : {" --color mean", " --ascii"})
  {
    const Run bad = run_tool(q(file("eb.las")) + " " + q(file("bad.las")) + option);
    CHECK(bad.status == 2);
    CHECK(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
    CHECK(!fs::exists(file("bad.las")));
  }
  ::unsetenv("SOURCE_DATE_EPOCH");
}

TEST_CASE("tool: LAS extra bytes are read in their types (float Amplitude, int16 Reflectance with a scale, uint16 "
          "Deviation) and carried to PLY and CSV, deprecated and undocumented ones are warned of")
{
  using namespace psc_las_test;
  const double offset[3] = {1e6, 2e6, 100};
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(1500, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  write_text(file("eb2.las"), las_with_extra_bytes(pts, offset, nullptr));
  const Run r = run_tool(q(file("eb2.las")) + " " + q(file("eb2.ply")) + " --radius 0.5 --orient +z");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("extra bytes") == std::string::npos);  // every extra byte described and read
  const std::string ply = read_text(file("eb2.ply"));
  CHECK(ply.find("property float Amplitude\nproperty double Reflectance\nproperty ushort Deviation\n") !=
        std::string::npos);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("eb2.ply"), ps));
  REQUIRE(ps.size() == pts.size());
  const auto amplitude = property<float>(ps, "Amplitude");
  const auto reflectance = property<double>(ps, "Reflectance");
  const auto deviation = property<std::uint16_t>(ps, "Deviation");
  std::size_t i = 0, wrong = 0;
  for(Point_set::Index p : ps)
  {
    wrong += amplitude[p] != 0.5f * float(i) || reflectance[p] != double(int(i % 2000) - 1000) * 0.01 ||
             deviation[p] != std::uint16_t(i * 7);
    ++i;
  }
  CHECK(wrong == 0);
  REQUIRE(run_tool(q(file("eb2.las")) + " " + q(file("eb2.csv")) + " --radius 0.5 --orient +z --fields mean --quiet")
            .status == 0);
  const std::string csv = read_text(file("eb2.csv"));
  CHECK(csv.substr(0, csv.find('\n')).find(",gps_time,red,green,blue,Amplitude,Reflectance,Deviation") !=
        std::string::npos);
  CHECK(csv_values(csv, "Reflectance")[3] == -9.97);
  CHECK(csv_values(csv, "Deviation")[1499] == 1499 * 7);

  // a deprecated array type (13: two ushorts) and 2 undocumented bytes: skipped, with warnings
  std::string odd = las_file(pts, 1, 2, 0.001, offset, 8);
  for(std::size_t k = 0; k < pts.size(); ++k)
    set_le<std::uint16_t>(odd, 227 + k * 36 + 28 + 4, std::uint16_t(k));
  odd = with_vlrs(odd, {vlr("LASF_Spec", 4, descriptor(13, "Pair") + descriptor(3, "Width"))});
  write_text(file("odd.las"), odd);
  const Run o = run_tool(q(file("odd.las")) + " " + q(file("odd.csv")) + " --radius 0.5 --orient +z --fields mean");
  INFO(o.err);
  REQUIRE(o.status == 0);
  CHECK(o.err.find("extra bytes fields not read: 'Pair' (deprecated array type)") != std::string::npos);
  CHECK(o.err.find("2 extra bytes per point record beyond those the extra-bytes VLR describes are not read") !=
        std::string::npos);
  const std::vector<double> width = csv_values(read_text(file("odd.csv")), "Width");
  REQUIRE(width.size() == pts.size());
  CHECK(width[1234] == 1234);
}

TEST_CASE("tool: a geographic LAS (GeoTIFF key, WKT GEOGCS, or x y like degrees) gets one warning naming the "
          "reprojection, a projected one none")
{
  using namespace psc_las_test;
  const double offset[3] = {1e6, 2e6, 100};
  std::vector<Oriented_point> pts;
  for(const Oriented_point& p : sphere(1500, 2.0))
    pts.emplace_back(Point(p.first.x() + 1e6 + 3, p.first.y() + 2e6 + 4, p.first.z() + 105), p.second);
  const std::string base = las_file(pts, 1, 2, 0.001, offset);
  const std::string wkt = "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\"],UNIT[\"degree\",0.0174532925199433]]";
  // a lon/lat terrain: 0.01 degree wide, 30 m high
  std::vector<Oriented_point> terrain;
  for(int u = 0; u < 40; ++u)
    for(int v = 0; v < 40; ++v)
      terrain.emplace_back(
        Point(7.1 + 0.00025 * u, 46.2 + 0.00025 * v, 500 + 15 * std::sin(0.2 * u) * std::cos(0.15 * v)),
        Vector(0, 0, 1));
  const double geo_offset[3] = {7, 46, 0};
  const std::pair<std::string, std::string> cases[] = {
    {with_vlrs(base, {vlr("LASF_Projection", 34735, geokeys(2))}), "GTModelTypeGeoKey 1024 = 2"},
    {with_vlrs(base, {vlr("LASF_Projection", 2112, wkt)}), "WKT GEOGCS"},
    {las_file(terrain, 1, 2, 1e-7, geo_offset), "x and y look like longitude and latitude (x in [7.1, 7.10975]"},
    {with_vlrs(base, {vlr("LASF_Projection", 34735, geokeys(1))}), ""},
    {base, ""}};
  int k = 0;
  for(const auto& c : cases)
  {
    INFO("case " << k);
    const std::string las = file("geo" + std::to_string(k++) + ".las");
    write_text(las, c.first);
    const Run r = run_tool(q(las) + " " + q(file("geo.ply")) + " --radius 0.5 --orient +z");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::size_t at = r.err.find("curvatures in 1/degree are meaningless");
    if(c.second.empty())
      CHECK(at == std::string::npos);
    else
    {
      REQUIRE(at != std::string::npos);
      CHECK(r.err.find(c.second) != std::string::npos);
      // one line, naming what to do
      const std::size_t begin = r.err.rfind('\n', at) + 1, end = r.err.find('\n', at);
      const std::string line = r.err.substr(begin, end - begin);
      CHECK(line.find("reproject to a projected CRS in metres") != std::string::npos);
      CHECK(line.find("pdal translate IN.las OUT.las reprojection --filters.reprojection.out_srs=EPSG:326xx") !=
            std::string::npos);
      CHECK(line.find("--radius in degrees") != std::string::npos);
    }
  }
}

TEST_CASE("tool: a truncated LAS is refused, and read to its last complete record with --allow-truncated and a warning")
{
  const double offset[3] = {0, 0, 0};
  const std::vector<Oriented_point> pts = sphere(1065, 2.0);
  std::string las = las_file(pts, 1, 2, 0.001, offset);
  las.resize(las.size() - 10);  // 1064 complete records
  write_text(file("cut.las"), las);
  const Run refused = run_tool(q(file("cut.las")) + " " + q(file("cut.ply")) + " --radius 0.5");
  CHECK(refused.status == 2);
  CHECK(refused.err.find("truncated: the header declares 1065 points") != std::string::npos);
  CHECK(refused.err.find("(1064 complete records: --allow-truncated reads them)") != std::string::npos);
  CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  CHECK(!fs::exists(file("cut.ply")));
  const Run r = run_tool(q(file("cut.las")) + " " + q(file("cut.ply")) + " --radius 0.5 --orient +z --allow-truncated");
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.err.find("truncated: read the 1064 complete points of the 1065 the header declares (--allow-truncated)") !=
        std::string::npos);
  CHECK(r.out.find("points      1064") != std::string::npos);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("cut.ply"), ps));
  CHECK(ps.size() == 1064);
  // to LAS: the count written is the points read
  REQUIRE(
    run_tool(q(file("cut.las")) + " " + q(file("cut_out.las")) + " --radius 0.5 --orient +z --allow-truncated --quiet")
      .status == 0);
  const psc_las_test::Las l = psc_las_test::read_las_1_4(read_text(file("cut_out.las")));
  CHECK(l.count == 1064);
  CHECK(l.legacy_count == 1064);
  CHECK(l.file.size() == l.point_offset + 1064 * std::size_t(l.record_length));
}

TEST_CASE("tool: input attributes carried in their types, renamed on a clash, --fields, --float, --drop-attributes")
{
  const std::vector<Oriented_point> pts = sphere(800, 1.0);
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty float nx\nproperty float ny\n"
         "property float nz\nproperty uchar red\nproperty float intensity\nproperty short k_min\nend_header\n";
  for(std::size_t i = 0; i < pts.size(); ++i)
    ply << pts[i].first.x() << " " << pts[i].first.y() << " " << pts[i].first.z() << " " << pts[i].second.x() << " "
        << pts[i].second.y() << " " << pts[i].second.z() << " " << i % 256 << " " << 0.5 * double(i) << " " << -int(i)
        << "\n";
  write_text(file("attr.ply"), ply.str());
  REQUIRE(run_tool(q(file("attr.ply")) + " " + q(file("attr_out.ply")) + " --radius 0.3 --color mean --quiet").status ==
          0);
  Point_set ps;
  REQUIRE(CGAL::IO::read_PLY(file("attr_out.ply"), ps));
  const auto red_in = property<std::uint8_t>(ps, "input_red");  // red is --color's
  const auto intensity = property<float>(ps, "intensity");
  const auto k_min_in = property<std::int16_t>(ps, "input_k_min");  // k_min is the estimate's
  const auto k_min = property<double>(ps, "k_min");
  std::size_t i = 0, wrong = 0;
  for(Point_set::Index p : ps)
  {
    wrong += red_in[p] != i % 256 || intensity[p] != float(0.5 * double(i)) || k_min_in[p] != -int(i) ||
             std::abs(k_min[p] - 1) > 0.05;
    ++i;
  }
  CHECK(wrong == 0);

  // --fields: x y z and the fields named, in the tool's order; --float: float32 estimates,
  // double positions; CSV the same columns
  REQUIRE(run_tool(q(file("attr.ply")) + " " + q(file("fields.ply")) +
                   " --radius 0.3 --fields valid,mean,dmin --float --drop-attributes --quiet")
            .status == 0);
  const std::string fields = read_text(file("fields.ply"));
  const std::string header = fields.substr(0, fields.find("end_header"));
  CHECK(header.find("property double x\nproperty double y\nproperty double z\nproperty float mean\n"
                    "property float dmin_x\nproperty float dmin_y\nproperty float dmin_z\nproperty uchar valid\n") !=
        std::string::npos);
  CHECK(header.find("intensity") == std::string::npos);
  CHECK(header.find("k_min") == std::string::npos);
  // 3 doubles + 4 floats + 1 byte per point
  CHECK(fields.size() - fields.find("end_header\n") - 11 == pts.size() * (24 + 16 + 1));
  REQUIRE(run_tool(q(file("attr.ply")) + " " + q(file("fields.csv")) + " --radius 0.3 --fields mean --quiet").status ==
          0);
  const std::string csv = read_text(file("fields.csv"));
  CHECK(csv.substr(0, csv.find('\n')) == "x,y,z,mean,red,intensity,input_k_min");
  const Run bad = run_tool(q(file("attr.ply")) + " " + q(file("x.ply")) + " --fields mean,curvedness");
  CHECK(bad.status == 2);
  CHECK(bad.err.find("--fields: unknown field 'curvedness'") != std::string::npos);

  // text columns named by a header line are attributes too
  std::ostringstream txt;
  txt.precision(17);
  txt << "x y z nx ny nz reflectance _\n";
  for(std::size_t k = 0; k < pts.size(); ++k)
    txt << pts[k].first.x() << " " << pts[k].first.y() << " " << pts[k].first.z() << " " << pts[k].second.x() << " "
        << pts[k].second.y() << " " << pts[k].second.z() << " " << 0.25 * double(k) << " 9\n";
  write_text(file("attr.txt"), txt.str());
  REQUIRE(
    run_tool(q(file("attr.txt")) + " " + q(file("attr_txt.csv")) + " --radius 0.3 --fields mean --quiet").status == 0);
  const std::string out = read_text(file("attr_txt.csv"));
  CHECK(out.substr(0, out.find('\n')) == "x,y,z,mean,reflectance");
  CHECK(out.find(",199.75\n") != std::string::npos);  // the last point's reflectance
}

// The columns come from the package's table of fields (field_descriptions.h), by name: the CSV
// header is x y z and the table's names in its order (mean_error with the automatic scale
// only), each value under its own name (the unit sphere: mean 1), a --fields group is its
// components, --color the table's summarised curvatures, a LAS extra bytes' description its row's.
TEST_CASE("tool: the output's columns are the package's table of fields, in its order, by name")
{
  namespace PSC = CGAL::Point_set_curvatures;
  write_xyz(file("table.xyz"), sphere(1000, 1.0));
  for(const bool automatic : {false, true})
  {
    INFO("automatic scale " << automatic);
    REQUIRE(
      run_tool(q(file("table.xyz")) + " " + q(file("table.csv")) + (automatic ? "" : " --neighbors 40") + " --quiet")
        .status == 0);
    std::string expected = "x,y,z";
    for(const PSC::Field_description& f : PSC::field_descriptions)
      if(f.name && (automatic || !f.automatic_scale_only))
        expected += std::string(",") + f.name;
    std::istringstream csv(read_text(file("table.csv")));
    std::string header, row;
    REQUIRE(std::getline(csv, header));
    REQUIRE(std::getline(csv, row));
    CHECK(header == expected);
    std::map<std::string, double> value;
    std::istringstream names(header), values(row);
    for(std::string name, v; std::getline(names, name, ',') && std::getline(values, v, ',');)
      value[name] = std::stod(v);
    CHECK(std::abs(value.at("mean") - 1) < 0.05);
    CHECK(std::abs(value.at("gaussian") - 1) < 0.1);
    CHECK(std::abs(std::hypot(value.at("nx"), value.at("ny"), value.at("nz")) - 1) < 1e-9);
    CHECK(value.at("valid") == 1);
    CHECK(value.at("neighbors") >= 40);
    CHECK(value.count("mean_error") == (automatic ? 1u : 0u));
  }
  REQUIRE(run_tool(q(file("table.xyz")) + " " + q(file("group.csv")) + " --neighbors 40 --fields dmax,normal --quiet")
            .status == 0);
  const std::string group = read_text(file("group.csv"));
  CHECK(group.substr(0, group.find('\n')) == "x,y,z,nx,ny,nz,dmax_x,dmax_y,dmax_z");
  for(const char* bad : {"k_min,", "' '"})
  {
    INFO("--fields " << bad);
    const Run r = run_tool(q(file("table.xyz")) + " " + q(file("bad.csv")) + " --neighbors 40 --fields " + bad);
    CHECK(r.status == 2);
    CHECK(r.err.find("--fields: unknown field ''") != std::string::npos);
  }
  // --color: the summarised fields, named in the message of an unknown one
  std::string summarised;
  for(const PSC::Field_description& f : PSC::field_descriptions)
    if(f.name && f.summarised)
      summarised += (summarised.empty() ? "" : "|") + std::string(f.name);
  const Run color = run_tool(q(file("table.xyz")) + " " + q(file("c.ply")) + " --neighbors 40 --color curvedness");
  CHECK(color.status == 2);
  CHECK(color.err.find("(available: " + summarised + ")") != std::string::npos);
  REQUIRE(run_tool(q(file("table.xyz")) + " " + q(file("table.las")) + " --neighbors 40 --quiet").status == 0);
  const std::string las = read_text(file("table.las"));
  for(const PSC::Field_description& f : PSC::field_descriptions)
    if(f.name && !f.automatic_scale_only)
    {
      INFO(f.name);
      CHECK(las.find(std::string(f.description)) != std::string::npos);
    }
}

// ---------------------------------------------------------------------------------------
// Inputs larger than --memory-limit: estimated in tiles, bitwise as in memory (issue 12)

TEST_CASE("tool: --memory-limit tiles give the in-memory output bitwise, by radius and by count, PLY CSV and ASCII, "
          "attributes, invalid points, colours")
{
  // density varying 1:10 (the halo by count differs across the cloud), an attribute, a
  // point far away (too few neighbours), a zero normal, a NaN coordinate
  std::vector<Oriented_point> pts = varying_density(6000, 11);
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size() + 3
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty double nx\nproperty double ny\n"
         "property double nz\nproperty ushort intensity\nend_header\n";
  for(std::size_t i = 0; i < pts.size(); ++i)
  {
    ply << pts[i].first.x() << " " << pts[i].first.y() << " " << pts[i].first.z() << " " << pts[i].second.x() << " "
        << pts[i].second.y() << " " << pts[i].second.z() << " " << i % 65536 << "\n";
    if(i == 1000)
      ply << "40 40 40 0 0 1 7\n";
    if(i == 2000)
      ply << "1 1 0.1 0 0 0 8\n";
    if(i == 3000)
      ply << "nan 1 0.1 0 0 1 9\n";
  }
  write_text(file("big.ply"), ply.str());
  // 6003 points of about 366 bytes (one attribute): 2.2 MB in memory; 300K: tiles
  const std::string in = q(file("big.ply"));
  struct Case
  {
    std::string options, output;
  };
  const Case cases[] = {
    {"--radius 0.12 --color mean", "r.ply"},  // robust ASO, sample weights
    {"--radius 0.12 --method apss --ascii", "apss.ply"},
    {"--neighbors 30 --variant paper --fields mean,k_min,valid --float", "k.ply"},
    {"--neighbors 30 --color gaussian", "kw.ply"},  // robust ASO by count
    {"--neighbors 20 --method apss --color k_max", "k.csv"},
  };
  for(const Case& c : cases)
  {
    INFO(c.options);
    const Run memory = run_tool(in + " " + q(file("memory_" + c.output)) + " " + c.options);
    REQUIRE(memory.status == 0);
    CHECK(memory.out.find("  tiles") == std::string::npos);
    const Run tiled = run_tool(in + " " + q(file("tiled_" + c.output)) + " " + c.options + " --memory-limit 300K");
    REQUIRE(tiled.status == 0);
    INFO(tiled.out);
    // several tiles, each with fewer points than the cloud
    std::size_t tiles = 0, largest = 0;
    const std::size_t at = tiled.out.find("  tiles       ");
    REQUIRE(at != std::string::npos);
    std::istringstream(tiled.out.substr(at + 14)) >> tiles;
    const std::size_t most = tiled.out.find("at most ", at);
    REQUIRE(most != std::string::npos);
    std::istringstream(tiled.out.substr(most + 8)) >> largest;
    CHECK(tiles >= 4);
    // by count, the far point's tile reaches its 30 nearest: most of the cloud
    if(c.options.find("--radius") != std::string::npos)
      CHECK(largest < pts.size() / 2);
    const std::string a = read_text(file("memory_" + c.output)), b = read_text(file("tiled_" + c.output));
    CHECK(a.size() > 6000 * 30);
    CHECK(a == b);
    // the same report: counts of valid and invalid points, neighbours, H and K
    auto report = [](const std::string& out) {
      const std::size_t v = out.find("  valid"), t = out.find("  time"), h = out.find("  H (mean)");
      return out.substr(v, t - v) + out.substr(h);
    };
    CHECK(report(memory.out) == report(tiled.out));
  }
  // the invalid rows are there, in place: the far point, the zero normal, the NaN
  {
    const std::string csv = read_text(file("tiled_k.csv"));
    std::istringstream lines(csv);
    std::string line;
    std::vector<std::string> rows;
    while(std::getline(lines, line))
      rows.push_back(line);
    REQUIRE(rows.size() == pts.size() + 4);
    auto ends_with = [](const std::string& s, const std::string& end) {
      return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
    };
    CHECK(rows[1002].rfind("40,40,40,", 0) == 0);
    CHECK(ends_with(rows[1002], ",7"));  // intensity
    // neighbors 0, valid 0, grey, the intensity
    CHECK(rows[2003].rfind("1,1,0.10000000000000001,nan,", 0) == 0);
    CHECK(ends_with(rows[2003], ",0,0,128,128,128,8"));
    CHECK(rows[3004].rfind("nan,1,", 0) == 0);
    CHECK(ends_with(rows[3004], ",0,0,128,128,128,9"));
  }
  // no temporary file is left
  CHECK(files_starting_with(".tiled_") == 0);

  // without normals, a first pass of tiles estimates them (here with a local orientation)
  write_xyz(file("no_normals.xyz"), pts, false);
  for(const std::string scale : {"--radius 0.12", "--neighbors 30"})
  {
    INFO(scale);
    const std::string options = " " + scale + " --orient +z --normal-neighbors 12 --fields normal,mean,valid";
    const Run memory = run_tool(q(file("no_normals.xyz")) + " " + q(file("nn_memory.ply")) + options);
    const Run tiled =
      run_tool(q(file("no_normals.xyz")) + " " + q(file("nn_tiled.ply")) + options + " --memory-limit 300K");
    REQUIRE(memory.status == 0);
    REQUIRE(tiled.status == 0);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(tiled.out.find("(normals estimated)") != std::string::npos);
    CHECK(tiled.err.find("has no normals: estimating them") != std::string::npos);
    const std::string a = read_text(file("nn_memory.ply")), b = read_text(file("nn_tiled.ply"));
    CHECK(a.size() > 6000 * 40);
    CHECK(a == b);
  }

  // the default orientation (a spanning tree over the whole cloud) and the default scale: the
  // normals estimated in tiles first, oriented over the whole cloud, then the curvature tiles
  // (6000 points: 3.0 MB in memory with the automatic scale, 2.5 MB for the gathered normals)
  {
    const std::string options = " --normal-neighbors 12 --fields normal,mean,valid,neighbors";
    const Run memory = run_tool(q(file("no_normals.xyz")) + " " + q(file("mst_memory.ply")) + options);
    const Run tiled =
      run_tool(q(file("no_normals.xyz")) + " " + q(file("mst_tiled.ply")) + options + " --memory-limit 2900K");
    REQUIRE(memory.status == 0);
    REQUIRE(tiled.status == 0);
    INFO(tiled.out);
    CHECK(memory.out.find("  tiles") == std::string::npos);
    CHECK(tiled.out.find("oriented over the whole cloud in memory") != std::string::npos);
    CHECK(tiled.out.find("oriented mst: along a minimum spanning tree") != std::string::npos);
    const std::string a = read_text(file("mst_memory.ply")), b = read_text(file("mst_tiled.ply"));
    CHECK(a.size() > 6000 * 40);
    CHECK(a == b);
  }

  // what cannot be tiled is refused with the reason and what to do
  {
    const Run r = run_tool(q(file("no_normals.xyz")) + " " + q(file("x.ply")) + " --radius 0.12 --memory-limit 300K");
    CHECK(r.status == 2);
    CHECK(r.err.find("orienting them along a spanning tree over the whole cloud (--orient auto here) needs "
                     "--memory-limit 2.") != std::string::npos);
    CHECK(r.err.find("or orient them locally, tile by tile: --orient +z") != std::string::npos);
    const Run s = run_tool(in + " " + q(file("x.ply")) + " --radius 3x --memory-limit 300K");
    CHECK(s.status == 2);
    CHECK(s.err.find("--radius 3x needs the whole cloud") != std::string::npos);
    const Run u = run_tool(in + " " + q(file("x.ply")) + " --memory-limit 12Q");
    CHECK(u.status == 2);
    CHECK(u.err.find("--memory-limit expects a positive size") != std::string::npos);
    CHECK(files_starting_with("x.ply") == 0);
  }
}

// ---------------------------------------------------------------------------------------
// Tiles under adversarial input, VCM reproducible, signals in every phase (issue 30)

namespace {

// run_tool() under `timeout`: a run that hangs fails (status 124 or 137) instead of holding
// up the suite; `env` is put before the command (NAME=value ...).
Run run_tool_within(int seconds, const std::string& args, const std::string& env = "")
{
  const std::string out = file("stdout.txt"), err = file("stderr.txt");
  const std::string command = env + " timeout -k 5 " + std::to_string(seconds) + " '" + PSC_TOOL_PATH + "' " + args +
                              " > '" + out + "' 2> '" + err + "'";
  const int raw = std::system(command.c_str());
  Run r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// Runs `input` whole, then in tiles at each memory limit: the same exit status (0, or 3 when
// no point is valid) and the same output bytes, and the tiled runs in tiles indeed. Returns
// the whole run's output.
std::string same_whole_and_tiled(const std::string& input, const std::string& options,
                                 const std::vector<std::string>& limits, const std::string& extension = ".ply",
                                 int status = 0)
{
  const std::string whole_output = file("whole" + extension);
  const Run whole = run_tool_within(120, q(input) + " " + q(whole_output) + " " + options);
  INFO(options << "\n" << whole.err);
  REQUIRE(whole.status == status);
  CHECK(whole.out.find("  tiles") == std::string::npos);
  const std::string expected = read_text(whole_output);
  for(const std::string& limit : limits)
  {
    INFO("--memory-limit " << limit);
    const std::string tiled_output = file("tiled" + extension);
    fs::remove(tiled_output);
    const Run tiled =
      run_tool_within(120, q(input) + " " + q(tiled_output) + " " + options + " --memory-limit " + limit);
    INFO(tiled.err);
    CHECK(tiled.status == status);
    CHECK(tiled.out.find("  tiles") != std::string::npos);
    CHECK(read_text(tiled_output) == expected);
  }
  return expected;
}

}  // namespace

// Two real airborne tiles without normals (data/real, PDAL's test data): the default pipeline
// orients them upwards because they are 2.5-D, gives every ground normal up and a valid estimate
// on vegetation with a lower normal coherence, and vegetation rougher than ground. Measured
// (2026-11-27): ground up 100% on both, vegetation valid 100%, median |H| vegetation / ground
// 8.76 (sample_c) and 2.23 (warsaw_small), median coherence ground 0.999 and 0.996, vegetation
// 0.93 and 0.85-0.99.
TEST_CASE("tool: real airborne tiles without normals, ground up, vegetation valid, vegetation rougher than ground")
{
  for(const std::string name : {"sample_c", "warsaw_small"})
  {
    const std::string out = file(name + "_default.csv");
    const Run r = run_tool(q(repo_data("real/" + name + ".las")) + " " + q(out));
    INFO(name << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("oriented +z (LAS file, 2.5-D") != std::string::npos);
    const std::string csv = read_text(out);
    {
      // The "normals" line's shares are those of the estimated normals; the output holds the
      // ASO's corrected normals, which turn a few of them (vegetation: measured 0 on sample_c
      // and 57 of 2560 near-vertical ones on warsaw_small), and the "output" line states those.
      const std::vector<std::string> nx = csv_column(csv, "nx"), ny = csv_column(csv, "ny"),
                                     nzs = csv_column(csv, "nz");
      std::size_t usable = 0, vertical = 0, up = 0;
      for(std::size_t i = 0; i < nx.size(); ++i)
      {
        const double v[3] = {std::stod(nx[i]), std::stod(ny[i]), std::stod(nzs[i])};
        if(!std::isfinite(v[0]) || v[0] * v[0] + v[1] * v[1] + v[2] * v[2] == 0)
          continue;
        ++usable;
        if(PSC::is_near_vertical(v[0], v[1], v[2]))
        {
          ++vertical;
          up += v[2] > 0 ? 1 : 0;
        }
      }
      REQUIRE(usable > 1000);
      const std::string claim = "% of the estimated normals within 60 degrees of the vertical; 100% of those point up";
      const std::size_t at = r.err.find(claim);
      REQUIRE(at != std::string::npos);
      const std::size_t from = r.err.rfind(' ', at) + 1;
      const double claimed = std::stod(r.err.substr(from, at - from));
      CHECK(std::abs(claimed - 100.0 * double(vertical) / double(usable)) < 1.0);
      CHECK(double(up) >= 0.97 * double(vertical));
      // the output line: the output's own shares, to 0.1%, and its count of normals down exactly
      const std::string output_claim = "% of the valid rows' normals within 60 degrees of the vertical, ";
      const std::size_t o = r.out.find(output_claim);
      REQUIRE(o != std::string::npos);
      const std::size_t o_from = r.out.rfind(' ', o) + 1;
      CHECK(std::abs(std::stod(r.out.substr(o_from, o - o_from)) - 100.0 * double(vertical) / double(usable)) <= 0.051);
      const std::size_t u = o + output_claim.size();
      CHECK(std::abs(std::stod(r.out.substr(u)) - 100.0 * double(up) / double(vertical)) <= 0.051);
      const std::size_t d = r.out.find("point up (", u);
      REQUIRE(d != std::string::npos);
      CHECK(std::stoul(r.out.substr(d + 10)) == vertical - up);
    }
    const std::vector<std::string> cls = csv_column(csv, "classification"), nz = csv_column(csv, "nz"),
                                   valid = csv_column(csv, "valid"), mean = csv_column(csv, "mean"),
                                   coherence = csv_column(csv, "normal_coherence");
    REQUIRE(cls.size() > 1000);
    std::size_t ground = 0, ground_up = 0, vegetation = 0, vegetation_valid = 0;
    std::vector<double> ground_h, vegetation_h, ground_c, vegetation_c;
    for(std::size_t i = 0; i < cls.size(); ++i)
    {
      const int c = std::stoi(cls[i]) & 31;
      const bool ok = valid[i] == "1";
      if(c == 2)
      {
        ++ground;
        ground_up += std::stod(nz[i]) > 0;
        if(ok)
        {
          ground_h.push_back(std::abs(std::stod(mean[i])));
          ground_c.push_back(std::stod(coherence[i]));
        }
      }
      else if(c >= 3 && c <= 5)
      {
        ++vegetation;
        vegetation_valid += ok;
        if(ok)
        {
          vegetation_h.push_back(std::abs(std::stod(mean[i])));
          vegetation_c.push_back(std::stod(coherence[i]));
        }
      }
    }
    const auto median = [](std::vector<double> v) {
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      return v[v.size() / 2];
    };
    REQUIRE(ground > 1000);
    REQUIRE(vegetation > 100);
    CHECK(double(ground_up) >= 0.99 * double(ground));
    CHECK(double(vegetation_valid) >= 0.95 * double(vegetation));
    REQUIRE(ground_h.size() > 1000);
    CHECK(median(vegetation_h) > 1.5 * median(ground_h));
    CHECK(median(ground_c) > 0.98);
    CHECK(median(vegetation_c) < median(ground_c));
  }
}

// Issue 42, item 2: the default on a real LAS file larger than the memory limit, without
// normals. --orient auto makes it 2.5-D (a spanning tree over the whole cloud, with its
// near-vertical normals up): the normals are estimated in tiles first and oriented over the
// whole cloud, bitwise as in memory (sample_c: 22 curvature tiles after 4 tiles of normals at
// 8M; warsaw_small in one tile of each).
TEST_CASE("tool: the default tiles a real LAS file without normals, bitwise as in memory")
{
  same_whole_and_tiled(repo_data("real/sample_c.las"), "", {"8M"}, ".csv");
  same_whole_and_tiled(repo_data("real/warsaw_small.las"), "--fields mean,normal,valid", {"1500K"}, ".csv");
}

// Class 1 of issue 30: the tiles' halo retry when the cloud has fewer points than a
// neighbourhood asks for. The whole run gives every point all the others; the tiled run
// failed with "internal error: the tile's halo inf is too small ...; a halo of inf suffices"
// (exit 1), or with a finite halo said too small and sufficient at once.
TEST_CASE("tool: tiles of clouds smaller than a neighbourhood give the whole run's bytes (3 and 39 points, 60 LAS "
          "points with normals from 200 neighbours, pairs on a line)")
{
  for(std::size_t n : {std::size_t(3), std::size_t(39)})
  {
    INFO(n << " points with normals, the default scale");
    write_xyz(file("few.xyz"), sphere(n, 1.0));
    // (3 points: no valid estimate, exit status 3 in both runs)
    const std::string csv =
      same_whole_and_tiled(file("few.xyz"), "--fields mean,neighbors,valid", {"100", "500"}, ".csv", n == 3 ? 3 : 0);
    // every point has every point as neighbour; 3 are too few (too_few_neighbors), 39 enough
    const std::vector<std::string> neighbors = csv_column(csv, "neighbors"), valid = csv_column(csv, "valid");
    REQUIRE(neighbors.size() == n);
    CHECK(std::count(neighbors.begin(), neighbors.end(), std::to_string(n)) == std::ptrdiff_t(n));
    CHECK(std::count(valid.begin(), valid.end(), n == 3 ? "0" : "1") == std::ptrdiff_t(n));
  }
  {
    INFO("60 LAS points without normals, --orient scanner --normal-neighbors 200");
    const double offset[3] = {0, 0, 0}, scanner[3] = {0, 0, 0};
    write_las(file("few.las"), sphere(60, 1.0), 4, 3, 0.001, offset, 0, scanner);
    const std::string csv = same_whole_and_tiled(
      file("few.las"), "--orient scanner --normal-neighbors 200 --drop-attributes", {"1K", "4K"}, ".csv");
    // (every normal is the fit of the whole sphere: meaningless, but the same) 40 neighbours
    const std::vector<std::string> neighbors = csv_column(csv, "neighbors");
    REQUIRE(neighbors.size() == 60);
    CHECK(std::count(neighbors.begin(), neighbors.end(), "40") == 60);
  }
  {
    // pairs of coincident points 2 apart on a line: a tile (halo 2r = 0.6 and a normal halo
    // of 1e-150 guessed from the line's zero area) holds one pair, fewer than the normals' 18
    // neighbours, of extent 0; the normals asked for 2e-150 more, which rounded away in
    // 0.6 + 2e-150: "the tile's halo 0.59999999999999998 is too small for exact results; a
    // halo of 0.59999999999999998 suffices". Collinear: no normal in either run.
    INFO("pairs on a line without normals, jets --radius 0.3 --orient +z");
    std::vector<Oriented_point> line;
    for(int i = 0; i < 24; ++i)
      line.emplace_back(Point(2.0 * (i / 2), 0, 0), Vector(0, 0, 1));
    const double offset[3] = {0, 0, 0};
    write_las(file("line.las"), line, 0, 2, 0.001, offset);
    const std::string csv = same_whole_and_tiled(
      file("line.las"), "--method jet --radius 0.3 --orient +z --drop-attributes", {"1K", "2K"}, ".csv", 3);
    const std::vector<std::string> valid = csv_column(csv, "valid");
    CHECK(std::count(valid.begin(), valid.end(), "0") == 24);
  }
}

// Class 2 of issue 30: coordinates whose extent overflows a double. The tiled run hung (the
// tile grid's side stayed infinite; SIGTERM did not end it); now it tiles with arithmetic
// that cannot overflow and gives the whole run's bytes.
TEST_CASE("tool: clouds whose extent overflows a double are tiled as the whole run (points at -1e308 and 1e308 in .xyz "
          ".ply .off, a LAS X scale of 1.5e304)")
{
  std::vector<Oriented_point> pts = sphere(80, 1.0);
  pts.insert(pts.begin() + 30, Oriented_point(Point(-1e308, 0, 0), Vector(0, 0, 1)));
  pts.emplace_back(Point(1e308, 0, 0), Vector(0, 0, 1));
  write_xyz(file("overflow.xyz"), pts);
  // the same points in ASCII PLY and OFF
  {
    std::ostringstream ply, off;
    ply.precision(17);
    off.precision(17);
    ply << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty double nx\nproperty double ny\n"
           "property double nz\nend_header\n";
    off << "NOFF\n" << pts.size() << " 0 0\n";
    for(const Oriented_point& p : pts)
    {
      ply << p.first << " " << p.second << "\n";
      off << p.first << " " << p.second << "\n";
    }
    write_text(file("overflow.ply"), ply.str());
    write_text(file("overflow.off"), off.str());
  }
  const std::pair<std::string, std::string> cases[] = {
    {"overflow.xyz", "--method aso"}, {"overflow.ply", "--method apss"}, {"overflow.off", "--method wavejet"}};
  for(const auto& c : cases)
  {
    INFO(c.first << " " << c.second);
    const std::string csv =
      same_whole_and_tiled(file(c.first), c.second + " --fields mean,neighbors,valid", {"2K", "8K"}, ".csv");
    // the sphere's points valid, the two far points not (degenerate_fit); 40 neighbours each
    const std::vector<std::string> valid = csv_column(csv, "valid"), neighbors = csv_column(csv, "neighbors"),
                                   mean = csv_column(csv, "mean");
    REQUIRE(valid.size() == 82);
    CHECK(std::count(valid.begin(), valid.end(), "1") == 80);
    CHECK(valid[30] == "0");
    CHECK(valid[81] == "0");
    CHECK(std::count(neighbors.begin(), neighbors.end(), "40") == 82);
    if(c.second != "--method wavejet")  // (wavejets fit a half sphere poorly: H 1.77 to 1.88)
    {
      std::size_t near_one = 0;
      for(const std::string& h : mean)
        near_one += std::abs(std::atof(h.c_str()) - 1) < 0.01;
      CHECK(near_one == 80);
    }
  }
  {
    // a LAS file whose X scale, 1.5e304, is finite (the reader accepts it): x from -1.5e308
    // to 1.5e308, so far apart that no normal is defined (collinear neighbourhoods)
    INFO("LAS X scale 1.5e304");
    const double offset[3] = {0, 0, 0};
    write_las(file("xscale.las"), sphere(80, 10.0), 0, 2, 0.001, offset);
    std::string las = read_text(file("xscale.las"));
    put_le<double>(las, 131, 1.5e304);
    write_text(file("xscale.las"), las);
    // (no valid estimate: exit status 3 in both runs)
    const std::string csv =
      same_whole_and_tiled(file("xscale.las"), "--orient +z --drop-attributes --fields mean,valid", {"2K"}, ".csv", 3);
    const std::vector<std::string> x = csv_column(csv, "x"), valid = csv_column(csv, "valid");
    REQUIRE(x.size() == 80);
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end(), [](const std::string& a, const std::string& b) {
      return std::atof(a.c_str()) < std::atof(b.c_str());
    });
    CHECK(std::atof(hi->c_str()) - std::atof(lo->c_str()) == HUGE_VAL);  // the extent overflows
    CHECK(std::count(valid.begin(), valid.end(), "0") == 80);
  }
}

// Class 3 of issue 30: VCM depended on memory addresses (CGAL's convex hull orders the edges
// of its visible sets by vertex address): two runs with --threads 1 differed in the last bits
// in 78 of 80 rows, one result of three at random. Its cells are now computed from data
// alone: every run, sequential or parallel, gives the same bytes. VCM's tiles stay refused.
TEST_CASE("tool: VCM gives the same bytes in every run, sequential and parallel, by radius and by count, and tiled VCM "
          "is refused")
{
  write_xyz(file("vcm.xyz"), sphere(80, 1.0));
  for(const std::string scale : {"--radius 1.2", "--neighbors 20"})
  {
    INFO(scale);
    std::string first;
    for(int run = 0; run < 8; ++run)
    {
      const std::string options = " --method vcm " + scale + (run % 2 ? " --threads 1" : "");
      const Run r = run_tool_within(60, q(file("vcm.xyz")) + " " + q(file("vcm.ply")) + options);
      REQUIRE(r.status == 0);
      const std::string bytes = read_text(file("vcm.ply"));
      if(run == 0)
      {
        first = bytes;
        // valid estimates (not a reproducible run of NaN)
        CHECK(r.out.find("valid       80 (100.00 %)") != std::string::npos);
      }
      INFO("run " << run);
      CHECK(bytes == first);
    }
  }
  const Run tiled =
    run_tool_within(60, q(file("vcm.xyz")) + " " + q(file("vcm.ply")) + " --method vcm --memory-limit 2K");
  CHECK(tiled.status == 2);
  CHECK(std::count(tiled.err.begin(), tiled.err.end(), '\n') == 1);
  CHECK(tiled.err.find("--method vcm needs the whole cloud") != std::string::npos);
}

// Issue 30: SIGINT and SIGTERM stop every phase of a tiled run at its next progress report
// (about 1% of its work or 0.25 s). The tool's test hook PSC_TOOL_TEST_SIGNAL=SIG@PHASE raises
// the signal as the phase begins (PHASE: the start of its name, '*' standing for any text);
// the run must exit 130 (SIGINT) or 143 (SIGTERM) naming that phase (a phase that went on
// would let the next one stop instead), leaving no output and no temporary file.
TEST_CASE("tool: SIGINT and SIGTERM stop every phase of a tiled run, with and without normals")
{
  write_xyz(file("phases.xyz"), sphere(1000, 1.0));
  write_xyz(file("phases_nn.xyz"), sphere(1000, 1.0), false);
  struct Case
  {
    std::string input, options, phase;
  };
  // (1000 points of about 300 bytes: 60K gives 56 to 345 tiles with normals, 250K 8 without;
  // fixed counts: the automatic scale's halo of 640 neighbours would cover this small sphere)
  const Case cases[] = {
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "reading"},
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "density"},
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "tile *read"},
    {"phases.xyz", "--memory-limit 60K --neighbors 40", "tile *curvatures"},
    {"phases.xyz", "--memory-limit 60K --neighbors 30", "tile *read#9"},  // a halo grown: tiles read again
    {"phases.xyz", "--memory-limit 60K --neighbors 30", "tile *curvatures#9"},
    {"phases.xyz", "--memory-limit 60K --radius 0.25", "tile *curvatures#20"},
    {"phases.xyz", "--memory-limit 60K --radius 0.25", "writing"},
    {"phases_nn.xyz", "--memory-limit 250K --orient +z --neighbors 40",
     "tile *curvatures#3"},  // the normals, then the curvatures
    {"phases_nn.xyz", "--memory-limit 250K --orient +z --radius 0.25", "writing"},
  };
  for(const Case& c : cases)
    for(const std::string signal : {"INT", "TERM"})
    {
      INFO(c.input << " " << c.options << ", SIG" << signal << " as phase '" << c.phase << "' begins");
      fs::remove(file("phases.ply"));
      const Run r = run_tool_within(120, q(file(c.input)) + " " + q(file("phases.ply")) + " " + c.options,
                                    "PSC_TOOL_TEST_SIGNAL='" + signal + "@" + c.phase + "'");
      INFO(r.err);
      CHECK(r.status == (signal == "TERM" ? 143 : 130));  // 128 + the signal, as a shell reports it
      // "interrupted (tile 9/23 curvatures), nothing written"
      const std::string name = c.phase.substr(0, c.phase.find('#'));
      const std::size_t star = name.find('*');
      const std::string head = name.substr(0, star), tail = star == std::string::npos ? "" : name.substr(star + 1);
      const std::size_t at = r.err.find("interrupted (" + head);
      CHECK(at != std::string::npos);
      CHECK(r.err.find(tail + "), nothing written", at) != std::string::npos);
      CHECK(!fs::exists(file("phases.ply")));
      CHECK(files_starting_with(".phases.ply") == 0);
    }
  // undisturbed, the same runs are tiled and succeed
  for(const std::string input : {"phases.xyz --memory-limit 60K", "phases_nn.xyz --memory-limit 250K --orient +z"})
  {
    const Run r = run_tool_within(120, q(file(input.substr(0, input.find(' ')))) + " " + q(file("phases.ply")) +
                                         input.substr(input.find(' ')));
    CHECK(r.status == 0);
    CHECK(r.out.find("  tiles") != std::string::npos);
  }
}

// A real SIGTERM during a long tiled run (every point every point's neighbour) stops it.
TEST_CASE("tool: SIGTERM during a long tiled run exits 143 and leaves no file")
{
  write_xyz(file("long.xyz"), sphere(20000, 1.0));
  fs::remove(file("long.ply"));
  // (\$: expanded by bash -c, not by the shell of std::system; the watchdog, its output away
  // from the test's, only keeps a run that ignored the signal from holding up the suite)
  const std::string script = std::string("'") + PSC_TOOL_PATH + "' '" + file("long.xyz") + "' '" + file("long.ply") +
                             "' --radius 3 --memory-limit 2M --quiet 2> '" + file("long.err") +
                             "' & pid=\\$!; (sleep 300; kill -KILL \\$pid) > /dev/null 2>&1 & dog=\\$!; sleep 1; "
                             "kill -TERM \\$pid; wait \\$pid; echo \\$? > '" +
                             file("long.status") + "'; kill \\$dog 2> /dev/null; true";
  REQUIRE(std::system(("bash -c \"" + script + "\"").c_str()) == 0);
  CHECK(std::atoi(read_text(file("long.status")).c_str()) == 143);
  CHECK(read_text(file("long.err")).find("interrupted (") != std::string::npos);
  CHECK(!fs::exists(file("long.ply")));
  CHECK(files_starting_with(".long.ply") == 0);
}

// Issue 28, item 12: the progress bar's line (drawn on a terminal only, redrawn twice a second
// by a timer even when a phase reports no progress): the elapsed time, and an ETA once a
// fraction of at least 1% is known and a second has passed.
// Issue 43, item 4: a pass over the tiles is one progress line whose fraction follows the time
// expected (tile_pass_progress.h), so that its ETA holds from the first tiles on.
TEST_CASE("tool: the fraction of a pass over the tiles follows the time the tiles take")
{
  double now = 0;
  // three tiles of 100 own points, one of 50; a read of the file took 1 s (the density pass)
  psc_tool::Tile_pass_progress pass({100, 100, 100, 50}, 1.0, [&now]() { return now; });
  const double prior = psc_tool::Tile_pass_progress::estimation_prior;
  pass.begin_read(0);
  CHECK(pass.at(0.0) == Approx(0.0));
  now = 0.5;  // half the first read in 0.5 s: nothing measured yet, 4 reads and estimations to go
  CHECK(pass.at(0.5) == Approx(0.5 / (0.5 + 0.5 * 1 + prior + 3 * 1)));  // (the estimations: `prior` reads in all)
  now = 1;
  pass.begin_estimation(0);
  now = 1.5;                                     // its first report after 0.5 s of set-up
  CHECK(pass.at(0.0) >= 0.5 / (1 + prior + 3));  // (never less than reported)
  now = 5.5;  // a tenth in 4 s: 40 s the whole from its first report, 40.5 s the tile's estimation
  pass.at(0.1);
  now = 9.5;
  CHECK(pass.at(0.2) == Approx(9.5 / (9.5 + 0.8 * 40 + 3 * 1 + (40.5 / 100) * 250)));
  now = 41.5;
  CHECK(pass.at(1.0) == Approx(41.5 / (41.5 + 3 * 1 + 0.405 * 250)));
  pass.end_tile();
  // from the first tile done on: 1 s a read, 0.405 s a point
  now = 42;
  pass.begin_read(1);
  CHECK(pass.at(0.0) == Approx(42 / (42 + 1 + 40.5 + 2 * 1 + 0.405 * 150)));
  // a tile read again (its halo grew): its refused try is time the pass took, never a step back;
  // the reads are those of the tiles done (not the current one's as well)
  now = 43;
  pass.begin_estimation(1);
  const double before = pass.at(0.0);
  CHECK(before == Approx(43 / (43 + 40.5 + 2 * 1 + 0.405 * 150)));
  now = 50;
  pass.begin_read(1);
  CHECK(pass.at(0.0) >= before);
  now = 51;
  pass.begin_estimation(1);
  pass.at(0.0);
  now = 91.5;
  CHECK(pass.at(1.0) < 1.0);  // (the others to come)
  pass.end_tile();
  now = 92;
  pass.begin_read(2);
  CHECK(pass.at(0.0) < 1.0);
  // no tile: the whole pass at once
  psc_tool::Tile_pass_progress empty({}, 1.0, [&now]() { return now; });
  CHECK(empty.at(1.0) == 1.0);
}

TEST_CASE("tool: the progress line shows the elapsed time, an ETA once a fraction is known, at one width")
{
  using psc_tool::progress_line;
  const std::string frozen = progress_line("curvatures", 0.0, 14.2);  // no progress yet: the time still moves
  CHECK(frozen.find("  0%") != std::string::npos);
  CHECK(frozen.find("14.2 s") != std::string::npos);
  CHECK(frozen.find("ETA") == std::string::npos);
  CHECK(progress_line("curvatures", 0.25, 10.0).find(" 25%") != std::string::npos);
  CHECK(progress_line("curvatures", 0.25, 10.0).find("ETA 30 s") != std::string::npos);
  CHECK(progress_line("curvatures", 0.5, 150.0).find("ETA 2 min 30 s") != std::string::npos);
  CHECK(progress_line("curvatures", 0.01, 100.0).find("ETA 2 h 45 min") != std::string::npos);  // 9900 s
  CHECK(progress_line("curvatures", 0.5, 0.5).find("ETA") == std::string::npos);   // under a second: no guess
  CHECK(progress_line("curvatures", 1.0, 20.0).find("ETA") == std::string::npos);  // done
  CHECK(progress_line("curvatures", std::nan(""), 3.0).find("  0%") != std::string::npos);
  CHECK(psc_tool::eta_text(59.6) == "1 min 00 s");
  // drawn over each other after '\r': one width, or a shorter line would leave a tail
  for(const auto& fs : {std::make_pair(0.0, 0.0), std::make_pair(0.5, 150.0), std::make_pair(0.01, 100.0),
                        std::make_pair(1.0, 20.0), std::make_pair(0.999, 5e4)})
    CHECK(progress_line("curvatures", fs.first, fs.second).size() == frozen.size());
  // a pass over the tiles: its step after the line, padded to the phase's longest
  const std::string step = progress_line("curvatures", 0.5, 150.0, "tile 3/12 read", 20);
  CHECK(step.size() == frozen.size() - 10 + 21);
  CHECK(step.find("ETA 2 min 30 s") != std::string::npos);
  CHECK(step.find(" tile 3/12 read      ") == frozen.size() - 10);
  CHECK(progress_line("curvatures", 0.5, 150.0, "tile 3/9 curvatures", 19).size() <= 88);

  // not on a terminal (stderr is a file here): no bar, no '\r', as before
  write_xyz(file("bar.xyz"), sphere(500, 1.0));
  const Run r = run_tool(q(file("bar.xyz")) + " " + q(file("bar.ply")) + " --radius 0.3");
  REQUIRE(r.status == 0);
  CHECK(r.err.find('\r') == std::string::npos);
  CHECK(r.err.find("ETA") == std::string::npos);
}

// Issue 28, item 13: a run killed (SIGKILL) while it computes leaves no file: the output's
// temporary file is created when writing starts (the space reserved before is held by a file
// unlinked at once). One killed while writing leaves ".OUTPUT.tmp-PID-XXXXXX", which the next
// run writing OUTPUT removes, with a note, as it does those of earlier versions
// (".OUTPUT.tmp-XXXXXX"), never those of a run still going (its PID alive).
TEST_CASE(
  "tool: a run killed while computing leaves no temporary file, and the next run removes a killed run's with a note")
{
  write_xyz(file("killed.xyz"), sphere(2000, 1.0));
  write_xyz(file("killed_nn.xyz"), sphere(2000, 1.0), false);
  const struct
  {
    std::string input, options, phase;
  } cases[] = {{"killed.xyz", "--radius 0.3", "curvatures"},
               {"killed.xyz", "--radius 0.3x", "spacing"},
               {"killed_nn.xyz", "--radius 0.3", "normals"},
               {"killed.xyz", "--radius 0.3 --memory-limit 100K", "tile *curvatures#2"},
               {"killed_nn.xyz", "--radius 0.3 --memory-limit 300K --orient +z --ascii", "tile *curvatures#2"},
               {"killed.xyz", "--radius 0.3 --memory-limit 100K", "tile *read#3"}};
  for(const auto& c : cases)
  {
    INFO(c.input << " " << c.options << ", SIGKILL as phase '" << c.phase << "' begins");
    const Run r = run_tool_within(60, q(file(c.input)) + " " + q(file("killed.ply")) + " " + c.options,
                                  "PSC_TOOL_TEST_SIGNAL='KILL@" + c.phase + "'");
    CHECK(r.status == 137);  // killed (timeout reports 128 + SIGKILL)
    CHECK(!fs::exists(file("killed.ply")));
    CHECK(files_starting_with(".killed.ply") == 0);
  }

  // killed while writing: the partial temporary file stays, and the next run removes it
  const Run w = run_tool_within(60, q(file("killed.xyz")) + " " + q(file("killed.ply")) + " --radius 0.3",
                                "PSC_TOOL_TEST_SIGNAL='KILL@writing'");
  CHECK(w.status == 137);
  CHECK(files_starting_with(".killed.ply.tmp-") == 1);
  // planted: a run of an earlier version, and killed ones (a PID above Linux's largest)
  for(const std::string name :
      {".killed.ply.tmp-AbC123", ".killed.ply.tmp-4194305-xYz789", ".killed.ply.tmp-4194305-tile3-aBcDeF"})
    write_text(file(name), "partial");
  // kept: a run still going (this process), other names
  const std::string running = ".killed.ply.tmp-" + std::to_string(::getpid()) + "-kEePmE";
  for(const std::string& name : {running, std::string(".killed.ply.tmp-notes.txt"),
                                 std::string(".other.ply.tmp-AbC123"), std::string("killed.ply.tmp-AbC123")})
    write_text(file(name), "keep");
  const Run next = run_tool(q(file("killed.xyz")) + " " + q(file("killed.ply")) + " --radius 0.3");
  INFO(next.err);
  REQUIRE(next.status == 0);
  CHECK(next.err.find("note: removed 4 temporary files of earlier runs writing") != std::string::npos);
  CHECK(std::count(next.err.begin(), next.err.end(), '\n') == 1);
  CHECK(files_starting_with(".killed.ply.tmp-") == 2);  // the running one and notes.txt
  CHECK(fs::exists(file(running)));
  CHECK(fs::exists(file(".killed.ply.tmp-notes.txt")));
  CHECK(fs::exists(file(".other.ply.tmp-AbC123")));
  CHECK(fs::exists(file("killed.ply.tmp-AbC123")));
  CHECK(fs::exists(file("killed.ply")));
  // nothing left to remove: no note
  const Run again = run_tool(q(file("killed.xyz")) + " " + q(file("killed.ply")) + " --radius 0.3");
  CHECK(again.status == 0);
  CHECK(again.err.find("note:") == std::string::npos);
  for(const std::string& name : {running, std::string(".killed.ply.tmp-notes.txt"),
                                 std::string(".other.ply.tmp-AbC123"), std::string("killed.ply.tmp-AbC123")})
    fs::remove(file(name));
}

// Issue 28, item 14: an OUTPUT that cannot be written is refused before the estimation (the
// SIGKILL hook at the estimation's start would kill a run that reached it), with one line:
// a directory, a folder that does not exist or is a file, more than the file size limit
// (ulimit -f: the reservation of the output's size fails with EFBIG); a full disk below.
TEST_CASE(
  "tool: an OUTPUT that is a directory, in a missing folder or over the file size limit fails before the estimation")
{
  write_xyz(file("early.xyz"), sphere(2000, 1.0));
  const std::string kill = "PSC_TOOL_TEST_SIGNAL='KILL@curvatures'";
  auto refused = [&](const std::string& output, const std::string& prefix, const std::string& message) {
    INFO(output << " " << prefix);
    const Run r = run_tool_within(60, q(file("early.xyz")) + " " + q(output) + " --radius 0.3", prefix + " " + kill);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(files_starting_with(".early") == 0);
  };
  fs::create_directories(file("dir.ply"));
  refused(file("dir.ply"), "", "is a directory: give a file name, such as");
  CHECK(fs::is_empty(file("dir.ply")));
  refused(file("missing/sub/out.ply"), "",
          "its folder '" + file("missing/sub") + "' does not exist (create it with mkdir -p");
  CHECK(!fs::exists(file("missing")));
  refused(file("early.xyz/out.ply"), "", "is not a directory; choose another OUTPUT");
  // 277 KB of binary PLY, 860 KB of CSV at most, over a limit of 64 blocks (32 or 64 KB)
  refused(file("early.ply"), "ulimit -f 64;",
          "more than the largest file allowed (the shell's file size limit, ulimit -f");
  refused(file("early.csv"), "ulimit -f 64;", "more than the largest file allowed");
  CHECK(!fs::exists(file("early.ply")));
  // within the limit: the reservation, larger than a CSV written, is cut to the bytes written
  for(const std::string ext : {".ply", ".csv"})
  {
    const Run free_run = run_tool(q(file("early.xyz")) + " " + q(file("early_free" + ext)) + " --radius 0.3");
    const Run limited =
      run_tool_within(60, q(file("early.xyz")) + " " + q(file("early" + ext)) + " --radius 0.3", "ulimit -f 100000;");
    REQUIRE(free_run.status == 0);
    REQUIRE(limited.status == 0);
    const std::string expected = read_text(file("early_free" + ext));
    CHECK(expected.size() > 100000);
    CHECK(read_text(file("early" + ext)) == expected);
  }
}

// A full disk: a 128 KB tmpfs in a user and mount namespace, where the system allows it
// (skipped visibly where it does not, as in some containers).
TEST_CASE("tool: an OUTPUT on a full disk fails before the estimation, naming the space it needs")
{
  fs::create_directories(file("tiny"));
  const std::string mount = "mount -t tmpfs -o size=128k tmpfs '" + file("tiny") + "'";
  if(std::system(("unshare -rm sh -c \"" + mount + "\" > /dev/null 2>&1").c_str()) != 0)
  {
    skip_test("no user namespace to mount a tiny file system in (unshare -rm refused)");
    return;
  }
  write_xyz(file("full.xyz"), sphere(2000, 1.0));
  const std::string kill = "PSC_TOOL_TEST_SIGNAL='KILL@curvatures'";
  const std::string script = mount + " && " + kill + " '" + PSC_TOOL_PATH + "' '" + file("full.xyz") + "' '" +
                             file("tiny/early.ply") + "' --radius 0.3 2> '" + file("tiny.err") + "'; echo \\$? > '" +
                             file("tiny.status") + "'; ls -a '" + file("tiny") + "' | wc -l > '" + file("tiny.files") +
                             "'";
  REQUIRE(std::system(("unshare -rm sh -c \"" + script + "\"").c_str()) == 0);
  const std::string err = read_text(file("tiny.err"));
  INFO(err);
  CHECK(std::atoi(read_text(file("tiny.status")).c_str()) == 2);
  CHECK(err.find("not enough space for output '" + file("tiny/early.ply") +
                 "': it needs up to 277.0 KB (binary PLY "
                 "of 2000 points, 19 fields), the file system holding it has 128.0 KB free") != std::string::npos);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK(std::atoi(read_text(file("tiny.files")).c_str()) == 2);  // . and ..: nothing left
}

// Issue 28, item 15: a --memory-limit so small that it makes hundreds of tiles (each read
// again from the input with its halo: 1K on 2025 points makes about 750) is warned of with a
// limit giving at most 100; one above the machine's RAM too.
TEST_CASE("tool: a --memory-limit making hundreds of tiles or above the RAM is warned of, with the limit to give")
{
  // (a fixed count: the automatic scale's halo of 640 neighbours would cover this small plane;
  // a plane, as smaller tiles keep lowering the most points a tile reads: on a sphere of 1000
  // points, where they soon stop, the tiles are fewer than 500)
  write_xyz(file("limits.xyz"), plane(45, 0.2));
  const Run tiny =
    run_tool_within(120, q(file("limits.xyz")) + " " + q(file("limits.ply")) + " --memory-limit 1K --neighbors 40");
  INFO(tiny.err);
  REQUIRE(tiny.status == 0);
  const std::size_t at = tiny.err.find("warning: --memory-limit 1.0 KB makes ");
  REQUIRE(at != std::string::npos);
  const std::size_t tiles = std::stoul(tiny.err.substr(at + 37));
  CHECK(tiles > 500);
  CHECK(tiny.out.find("  tiles       " + std::to_string(tiles) + " ") != std::string::npos);
  const std::size_t give = tiny.err.find("; --memory-limit ", at);
  REQUIRE(give != std::string::npos);
  const std::string suggested = tiny.err.substr(give + 17, tiny.err.find(' ', give + 17) - give - 17);
  const std::size_t most = std::stoul(tiny.err.substr(tiny.err.find(" gives at most ", give) + 15));
  CHECK(most <= 100);
  CHECK(std::count(tiny.err.begin(), tiny.err.end(), '\n') == 1);
  // the memory stays bounded however many tiles: one temporary file for all their rows, read
  // back through buffers within the limit (a file per tile held a 1 MB buffer each: 750 MB
  // here; 10 MB now). Not under the sanitizers (AddressSanitizer's quarantine keeps freed memory).
#ifndef PSC_TEST_MEMORY_SANITIZED
  const std::pair<int, long> peak =
    run_tool_peak_kb(q(file("limits.xyz")) + " " + q(file("peak.ply")) + " --memory-limit 1K --neighbors 40");
  CHECK(peak.first == 0);
  CHECK(peak.second < 150 * 1024);
#endif
  // the limit suggested gives at most that many tiles, the same bytes, and no warning
  const std::string expected = read_text(file("limits.ply"));
  const Run fewer = run_tool_within(120, q(file("limits.xyz")) + " " + q(file("limits.ply")) +
                                           " --neighbors 40 --memory-limit " + suggested);
  INFO(suggested << "\n" << fewer.out);
  REQUIRE(fewer.status == 0);
  CHECK(fewer.err.empty());
  const std::size_t t = fewer.out.find("  tiles       ");
  REQUIRE(t != std::string::npos);
  CHECK(std::stoul(fewer.out.substr(t + 14)) <= most);
  CHECK(std::stoul(fewer.out.substr(t + 14)) > 1);
  CHECK(read_text(file("limits.ply")) == expected);

  // above the RAM
  const double ram = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  char ram_text[64];
  std::snprintf(ram_text, sizeof ram_text, "%.1f GB of RAM", ram / (1024.0 * 1024 * 1024));
  const Run huge =
    run_tool(q(file("limits.xyz")) + " " + q(file("limits.ply")) + " --memory-limit 1024T --neighbors 40");
  INFO(huge.err);
  CHECK(huge.status == 0);
  CHECK(huge.err.find("warning: --memory-limit 1024.0 TB exceeds this machine's memory (" + std::string(ram_text) +
                      "): ") != std::string::npos);
  CHECK(std::count(huge.err.begin(), huge.err.end(), '\n') == 1);
  // within it: silent
  const Run within = run_tool(q(file("limits.xyz")) + " " + q(file("limits.ply")) + " --memory-limit 100M");
  CHECK(within.status == 0);
  CHECK(within.err.empty());
}

// The peak memory of a tiled run against the limit (issue 45): a cloud of 200,000 points whose
// run in memory takes several times the limit above the tool's own base (its run on a few
// points), run in tiles under --memory-limit 10M. Measured: base 6.9 MB, in memory +70 MB,
// in tiles +25 MB. Not under the sanitizers (their shadow memory is no measure of the tool's).
TEST_CASE("tool: --memory-limit bounds the peak memory of a run in tiles, a few times the limit above the base")
{
#ifdef PSC_TEST_MEMORY_SANITIZED
  skip_test("peak memory is not measured under the sanitizers");
#else
  {
    std::ofstream out(file("peak_terrain.xyz"));
    out.precision(10);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    for(int i = 0; i < 500; ++i)
      for(int j = 0; j < 400; ++j)
      {
        const double x = i + jitter(random), y = j + jitter(random);
        out << x << " " << y << " " << 5 * std::sin(0.05 * x) * std::cos(0.04 * y) << "\n";
      }
  }
  write_xyz(file("peak_small.xyz"), plane(20, 0.2), false);
  const std::string options = " --neighbors 40 --orient +z";
  const std::pair<int, long> base = run_tool_peak_kb(q(file("peak_small.xyz")) + " " + q(file("peak.ply")) + options);
  const std::pair<int, long> whole =
    run_tool_peak_kb(q(file("peak_terrain.xyz")) + " " + q(file("peak.ply")) + options);
  const std::pair<int, long> tiled =
    run_tool_peak_kb(q(file("peak_terrain.xyz")) + " " + q(file("peak.ply")) + options + " --memory-limit 10M");
  REQUIRE(base.first == 0);
  REQUIRE(whole.first == 0);
  REQUIRE(tiled.first == 0);
  const long limit_kb = 10 * 1024;
  INFO("peak KB: base " << base.second << ", in memory " << whole.second << ", in tiles " << tiled.second);
  CHECK(whole.second - base.second > 6 * limit_kb);  // (so that the limit has something to bound)
  CHECK(tiled.second - base.second < 4 * limit_kb);
  CHECK(2 * tiled.second < whole.second);
#endif
}

// The tool without normals: quadric normals, orientation by the input's kind (said in the
// summary), the position blend; the plain pipeline stays reachable.
TEST_CASE("tool: without normals, the default pipeline and what the summary says of it")
{
  const std::vector<scan::Sample> terrain = scan::airborne_lines(scan::wavy_terrain(), 6, 0.1, 0.5);
  const std::vector<Oriented_point> pts = scan::with_true_normals(terrain);
  const double offset[3] = {500000, 4000000, 100};
  std::vector<Oriented_point> shifted;
  for(const Oriented_point& p : pts)
    shifted.emplace_back(p.first + Vector(offset[0], offset[1], offset[2]), p.second);
  write_text(file("terrain.las"), las_file(shifted, 1, 2, 1e-4, offset));
  write_xyz(file("terrain.xyz"), pts, false);
  const Run las = run_tool(q(file("terrain.las")) + " " + q(file("terrain_las.csv")) + " --fields mean,normal,valid");
  REQUIRE(las.status == 0);
  // the default scale is automatic, for the normals too
  CHECK(las.out.find("normals     a quadric fitted to the nearest neighbours, their count chosen per point from 40 to "
                     "640, oriented +z (LAS file, 2.5-D") != std::string::npos);
  CHECK(las.out.find("scale       automatic scale: 40 to 640") != std::string::npos);
  CHECK(las.out.find("blended with a position fit, weight 0.5") != std::string::npos);
  const Run xyz = run_tool(q(file("terrain.xyz")) + " " + q(file("terrain_xyz.csv")) + " --fields mean,normal,valid");
  REQUIRE(xyz.status == 0);
  CHECK(xyz.out.find("oriented mst: along a minimum spanning tree") != std::string::npos);
  // the plain pipeline: PCA normals of 18, no blend
  const Run plain = run_tool(q(file("terrain.xyz")) + " " + q(file("terrain_plain.csv")) +
                             " --normal-fit plane --position-blend 0 --fields mean,valid");
  REQUIRE(plain.status == 0);
  CHECK(plain.out.find("the PCA plane of the 18 nearest neighbours") != std::string::npos);
  CHECK(plain.out.find("blended") == std::string::npos);
  auto error_of = [&](const std::string& csv) {
    const std::vector<std::string> mean = csv_column(read_text(csv), "mean");
    REQUIRE(mean.size() == terrain.size());
    double sum = 0;
    for(std::size_t i = 0; i < mean.size(); ++i)
      sum += std::abs(std::stod(mean[i]) - terrain[i].truth.mean);
    return sum / double(mean.size());
  };
  const double e_las = error_of(file("terrain_las.csv")), e_xyz = error_of(file("terrain_xyz.csv")),
               e_plain = error_of(file("terrain_plain.csv"));
  measured("tool on airborne lines without normals: mean |H error|, LAS default", e_las);
  measured("tool on airborne lines without normals: mean |H error|, text default", e_xyz);
  measured("tool on airborne lines without normals: mean |H error|, plane normals, no blend", e_plain);
  // measured 1.44e-3 / 1.42e-3 (automatic scale; 1.40e-3 at 40 neighbours) against 3.31e-3
  CHECK(e_las < 0.7 * e_plain);
  CHECK(e_xyz < 0.7 * e_plain);
  // the paper's variant stays the paper's estimator unless the blend is asked for
  const Run paper = run_tool(q(file("terrain.las")) + " " + q(file("paper.csv")) + " --variant paper");
  REQUIRE(paper.status == 0);
  CHECK(paper.out.find("aso (paper's variant)") != std::string::npos);
  CHECK(paper.out.find("blended") == std::string::npos);
  // in tiles the automatic orientation (a spanning tree over the whole cloud) orients the
  // normals gathered from the tiles in memory; below the memory they need it is refused with
  // what to do: the tiled run never differs from the whole one
  fs::remove(file("tiled.csv"));  // (same_whole_and_tiled() writes one)
  const Run tiled = run_tool(q(file("terrain.las")) + " " + q(file("tiled.csv")) + " --memory-limit 200K");
  CHECK(tiled.status == 2);
  CHECK(tiled.err.find("--orient +z") != std::string::npos);
  CHECK(!fs::exists(file("tiled.csv")));
  const Run tiled_z =
    run_tool(q(file("terrain.las")) + " " + q(file("tiled_z.csv")) + " --orient +z --memory-limit 200K");
  const Run whole_z = run_tool(q(file("terrain.las")) + " " + q(file("whole_z.csv")) + " --orient +z");
  REQUIRE(tiled_z.status == 0);
  REQUIRE(whole_z.status == 0);
  // neighbourhoods of up to 640 points span these 3000: no tiling lowers the peak, so one tile
  // (641 before, each the whole cloud: 200 times as long)
  CHECK(tiled_z.out.find("  tiles       1 (memory limit 0.195312 MB; at most 3000 points with a halo of inf; "
                         "the normals first in 1 tile)") != std::string::npos);
  CHECK(read_text(file("tiled_z.csv")) == read_text(file("whole_z.csv")));
  // bad values
  CHECK(run_tool(q(file("terrain.xyz")) + " " + q(file("x.csv")) + " --position-blend 1.5").status == 2);
  CHECK(run_tool(q(file("terrain.xyz")) + " " + q(file("x.csv")) + " --normal-fit cubic").status == 2);
  CHECK(run_tool(q(file("terrain.xyz")) + " " + q(file("x.csv")) + " --normal-neighbors 5").status == 2);
}

// --help is the reference list of the options: the library's methods and their least counts,
// and the manual's section on the tool names every option it lists, and no other.
TEST_CASE("tool: --help lists the library's methods, and the manual names exactly the options of --help")
{
  const Run help = run_tool("--help");
  REQUIRE(help.status == 0);
  std::string methods;
  for(const CGAL::Point_set_curvatures::Estimator_description& e : CGAL::Point_set_curvatures::estimators)
    methods += (methods.empty() ? "" : "|") + std::string(e.name);
  CHECK(help.out.find("--method M         estimator: " + methods + " (default aso)") != std::string::npos);
  std::set<std::string> in_help, in_manual;
  std::istringstream lines(help.out);
  for(std::string line; std::getline(lines, line);)
    if(line.rfind("  --", 0) == 0)
      in_help.insert(line.substr(2, line.find(' ', 2) - 2));
  REQUIRE(in_help.size() >= 20);
  const std::string manual = read_text(repo_data("../doc/user_manual.md"));
  const std::size_t from = manual.find("{#psc_tool}"), to = manual.find("\n## ", from);
  REQUIRE(from != std::string::npos);
  const std::string section = manual.substr(from, to - from);
  for(std::size_t at = section.find("`--"); at != std::string::npos; at = section.find("`--", at + 1))
  {
    std::size_t end = at + 3;
    while(end < section.size() && (std::islower(static_cast<unsigned char>(section[end])) || section[end] == '-'))
      ++end;
    in_manual.insert(section.substr(at + 1, end - at - 1));
  }
  for(const std::string& o : in_help)
  {
    INFO(o << " is in --help: is it in the manual's section on the tool?");
    CHECK(in_manual.count(o) == 1);
  }
  for(const std::string& o : in_manual)
  {
    INFO(o << " is in the manual's section on the tool: is it in --help?");
    CHECK(in_help.count(o) == 1);
  }
  // and the parser knows each (one table for both: a value missing, or the files, not the option)
  for(const std::string& o : in_help)
  {
    const Run r = run_tool(o);
    INFO(o << ": " << r.err);
    CHECK(r.err.find("unknown option") == std::string::npos);
    CHECK((r.status == 2 || (o == "--help" && r.status == 0)));
  }
}

// The default scale: automatic for the ASO's robust variant only (with its mean_error
// column); 40 neighbours for the paper's variant and the other methods; a radius is a radius.
TEST_CASE("tool: the default scale is automatic for the robust ASO only, 40 neighbours otherwise")
{
  const std::string in = q(repo_data("goursat-lidar.xyz"));
  const Run aso = run_tool(in + " " + q(file("default.csv")));
  REQUIRE(aso.status == 0);
  CHECK(aso.out.find("scale       automatic scale: 40 to 640 nearest neighbours") != std::string::npos);
  const std::vector<std::string> error = csv_column(read_text(file("default.csv")), "mean_error");
  REQUIRE(error.size() == 2947);
  CHECK(std::count(error.begin(), error.end(), "<missing>") == 0);
  CHECK(std::count(error.begin(), error.end(), "nan") == 0);  // (every first rung fits a quadric here)
  for(const std::string options : {"--variant paper", "--method jet", "--method pss", "--method apss"})
  {
    INFO(options);
    const Run r = run_tool(in + " " + q(file("other.csv")) + " " + options);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("scale       40 nearest neighbours per point (itself included)") != std::string::npos);
    CHECK(read_text(file("other.csv")).find("mean_error") == std::string::npos);
  }
  const Run radius = run_tool(in + " " + q(file("radius.csv")) + " --radius 3.5x");
  REQUIRE(radius.status == 0);
  CHECK(radius.out.find("scale       radius ") != std::string::npos);
  CHECK(radius.out.find("automatic") == std::string::npos);
  // the fields asked for by default: mean_error is one of them
  CHECK(run_tool(in + " " + q(file("fields.csv")) + " --fields mean,mean_error --quiet").status == 0);
}

// The automatic scale (issue 27): on real airborne tiles without normals, the ground is
// smoother than with jets (measured median |H| on ground: sample_c 0.0172 against 0.0288,
// warsaw_small 0.0140 against 0.0424), the chosen counts are in the neighbors field and the
// standard error of H in mean_error, other methods are refused.
TEST_CASE("tool: --neighbors auto on real tiles: ground smoother than jets, counts from 40 to 640, aso only")
{
  for(const std::string name : {"sample_c", "warsaw_small"})
  {
    INFO(name);
    const std::string in = q(repo_data("real/" + name + ".las"));
    const Run automatic = run_tool(in + " " + q(file(name + "_auto.csv")) + " --neighbors auto --orient +z");
    const Run jet = run_tool(in + " " + q(file(name + "_jet.csv")) + " --method jet --orient +z");
    REQUIRE(automatic.status == 0);
    REQUIRE(jet.status == 0);
    CHECK(automatic.out.find("automatic scale: 40 to 640 nearest neighbours") != std::string::npos);
    auto ground_median = [](const std::string& csv) {
      const std::vector<std::string> cls = csv_column(csv, "classification"), mean = csv_column(csv, "mean");
      std::vector<double> h;
      for(std::size_t i = 0; i < cls.size(); ++i)
        if((std::stoi(cls[i]) & 31) == 2 && mean[i] != "nan")
          h.push_back(std::abs(std::stod(mean[i])));
      REQUIRE(h.size() > 1000);
      std::nth_element(h.begin(), h.begin() + h.size() / 2, h.end());
      return h[h.size() / 2];
    };
    const std::string csv = read_text(file(name + "_auto.csv"));
    CHECK(ground_median(csv) < 0.8 * ground_median(read_text(file(name + "_jet.csv"))));
    std::size_t larger = 0, counts = 0;
    for(const std::string& k : csv_column(csv, "neighbors"))
    {
      const int c = std::stoi(k);
      CHECK(c >= 40);
      CHECK(c <= 700);
      larger += c > 80 ? 1 : 0;
      ++counts;
    }
    CHECK(larger > counts / 10);
    // the standard error of H at the chosen scale: finite and >= 0 on every valid point, > 0
    // where a count above the first rung was chosen (noise measured), larger in vegetation
    // than on the ground (measured medians: sample_c 0.0124 against 0.0026, warsaw_small
    // 0.0072 against 0.0016)
    const std::vector<std::string> error = csv_column(csv, "mean_error"), mean = csv_column(csv, "mean"),
                                   cls = csv_column(csv, "classification"), count = csv_column(csv, "neighbors");
    REQUIRE(error.size() == counts);
    std::vector<double> ground, vegetation;
    std::size_t bad = 0;
    for(std::size_t i = 0; i < error.size(); ++i)
      if(mean[i] != "nan")
      {
        const double e = std::stod(error[i]);
        bad += std::isfinite(e) && e >= 0 && (e > 0 || std::stoi(count[i]) < 80) ? 0 : 1;
        const int c = std::stoi(cls[i]) & 31;
        if(c == 2)
          ground.push_back(e);
        else if(c >= 3 && c <= 5)
          vegetation.push_back(e);
      }
    CHECK(bad == 0);
    REQUIRE(ground.size() > 1000);
    REQUIRE(vegetation.size() > 20);
    auto median = [](std::vector<double> v) {
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      return v[v.size() / 2];
    };
    CHECK(median(vegetation) > 2 * median(ground));
    CHECK(read_text(file(name + "_jet.csv")).find("mean_error") == std::string::npos);
  }
  // (tiles == whole: test_core's "Automatic scale: sequential == parallel, tiles == whole";
  // the tool's tiles take minutes here, each tile's halo being most of these small files)
  const std::string in = q(repo_data("real/sample_c.las"));
  const Run refused = run_tool(in + " " + q(file("x.ply")) + " --neighbors auto --method jet");
  CHECK(refused.status == 2);
  CHECK(refused.err.find("--neighbors auto chooses the scale of --method aso only") != std::string::npos);
  const Run no_error = run_tool(in + " " + q(file("x.ply")) + " --neighbors 40 --fields mean,mean_error");
  CHECK(no_error.status == 2);
  CHECK(no_error.err.find("--fields: mean_error comes with the automatic scale only: add --neighbors auto") !=
        std::string::npos);
}
