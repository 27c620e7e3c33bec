// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The helpers of the tool's tests (test_tool.cpp, test_tool_las.cpp, test_tool_tiles.cpp) and of the
// library tests built into the same program (test_neighborhoods.cpp, test_normals.cpp): files in a work
// folder, the tool run as a separate process (its path comes from tools/CMakeLists.txt as PSC_TOOL_PATH),
// PLY and CSV read back.

#ifndef PSC_TEST_TOOL_SUPPORT_H
#define PSC_TEST_TOOL_SUPPORT_H

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
#include <iostream>
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

namespace psc_tool_test {

const auto pair_maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());

// ---------------------------------------------------------------------------------------
// Clouds

// Height field z = 0.2 sin(x) cos(y) over [0, 4] x [0, 2] whose sampling density grows
// linearly from 1 to 10 along x (inverse transform sampling of the density 1 + 9 x/4).
// Exact unit normals (pointing to +z). Random positions: no two distances tie.
inline std::vector<Oriented_point> varying_density(std::size_t n, unsigned seed = 7)
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
inline const fs::path& work_dir()
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

inline std::string file(const std::string& name) { return (work_dir() / name).string(); }

inline void write_text(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string read_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_xyz(const std::string& path, const std::vector<Oriented_point>& pts, bool normals = true)
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

// Runs the tool with `args` (already quoted where needed), `prefix` put before the tool's path
// in the shell command (NAME=value ..., or a command such as timeout).
inline Run run_tool_after(const std::string& prefix, const std::string& args)
{
  const std::string out = file("stdout.txt"), err = file("stderr.txt");
  const std::string command = prefix + "'" + PSC_TOOL_PATH + "' " + args + " > '" + out + "' 2> '" + err + "'";
  const int raw = std::system(command.c_str());
  Run r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// Runs the tool with `args` (already quoted where needed).
inline Run run_tool(const std::string& args) { return run_tool_after("", args); }

inline std::string q(const std::string& path) { return "'" + path + "'"; }

// The tool's CSV output at --radius 0.6 on `pts`, written with their normals as <name>.xyz: the
// reference that the same cloud in other formats and layouts must reproduce.
inline std::string csv_reference(const std::vector<Oriented_point>& pts, const std::string& name)
{
  write_xyz(file(name + ".xyz"), pts);
  REQUIRE(run_tool(q(file(name + ".xyz")) + " " + q(file(name + "_reference.csv")) + " --radius 0.6").status == 0);
  return read_text(file(name + "_reference.csv"));
}

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
[[maybe_unused]] inline std::pair<int, long> run_tool_peak_kb(const std::string& args)
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
inline std::size_t files_starting_with(const std::string& prefix)
{
  std::size_t n = 0;
  for(const auto& entry : fs::directory_iterator(work_dir()))
    if(entry.path().filename().string().rfind(prefix, 0) == 0)
      ++n;
  return n;
}

// Bitwise equality of doubles, NaN included (NaN == NaN here).
inline bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

inline bool same(const Vector& a, const Vector& b)
{
  return same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.z(), b.z());
}

inline bool same(const Estimate& a, const Estimate& b)
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
inline void check_ply_matches(const std::string& path, const std::vector<Oriented_point>& input,
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
inline std::vector<Oriented_point> sphere_with_invalid_points()
{
  std::vector<Oriented_point> pts = sphere(2000, 2.0);
  pts.emplace_back(Point(50, 50, 50), Vector(0, 0, 1));
  pts.emplace_back(Point(0, 0, 2.001), Vector(0, 0, 0));
  return pts;
}

// The rows of a CSV output, header first.
inline std::vector<std::string> csv_rows(const std::string& text)
{
  std::vector<std::string> rows;
  std::istringstream lines(text);
  std::string line;
  while(std::getline(lines, line))
    rows.push_back(line);
  return rows;
}

// Field `name` of every data row of a CSV output.
inline std::vector<std::string> csv_column(const std::string& text, const std::string& name)
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

// A LAS file of `pts` (las_file() of test_support.h): the coordinates as stored, quantised.
inline std::vector<std::array<double, 3> > write_las(const std::string& path, const std::vector<Oriented_point>& pts,
                                                     int format, int minor, double scale, const double offset[3],
                                                     std::size_t extra = 0, const double* beam_from = nullptr)
{
  std::vector<std::array<double, 3> > quantised;
  write_text(path, las_file(pts, format, minor, scale, offset, extra, &quantised, beam_from));
  return quantised;
}

// A test that cannot run here says so with this line, which CTest turns into a skip (the
// property SKIP_REGULAR_EXPRESSION of test/CMakeLists.txt), so that a skip shows in the
// summary instead of passing (issue 45). CTest then ignores the exit status: only test cases
// that assert nothing before skipping may call it (each does so first), or the skip would
// hide their failures; the CTest test test_skips_come_first (test/skips_come_first.cmake)
// checks the sources for assertion macros before each call.
inline void skip_test(const std::string& why) { std::cout << "PSC_TEST_SKIPPED: " << why << std::endl; }

inline bool has_cloudcompare() { return std::system("command -v CloudCompare > /dev/null 2>&1") == 0; }

}  // namespace psc_tool_test

#endif
