// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the experiments of paper_experiments.cpp share: options, the estimators compared, the
// time budget, the Goursat samples, the errors against the analytic values, tables, the
// Markdown report, gnuplot data and the context every experiment receives.

#ifndef PSC_BENCHMARK_PAPER_EXPERIMENTS_SUPPORT_H
#define PSC_BENCHMARK_PAPER_EXPERIMENTS_SUPPORT_H

#include "bench_support.h"
#include "goursat_sampler.h"
#include "render_points.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/estimate_apss_curvatures.h>
#include <CGAL/estimate_aso_curvatures.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#if __has_include(<CGAL/estimate_barycenter_curvatures.h>)
#include <CGAL/estimate_barycenter_curvatures.h>
#define PSC_HAS_BARYCENTER 1
#endif
#if __has_include(<CGAL/estimate_pca_plane_curvatures.h>)
#include <CGAL/estimate_pca_plane_curvatures.h>
#define PSC_HAS_PCA_PLANE 1
#endif
#if __has_include(<CGAL/estimate_pss_curvatures.h>)
#include <CGAL/estimate_pss_curvatures.h>
#define PSC_HAS_PSS 1
#endif
#if __has_include(<CGAL/estimate_jet_curvatures.h>)
#include <CGAL/estimate_jet_curvatures.h>
#define PSC_HAS_JET 1
#endif
#if __has_include(<CGAL/estimate_wavejet_curvatures.h>)
#include <CGAL/estimate_wavejet_curvatures.h>
#define PSC_HAS_WAVEJET 1
#endif
#if __has_include(<CGAL/estimate_vcm_curvatures.h>)
#include <CGAL/estimate_vcm_curvatures.h>
#define PSC_HAS_VCM 1
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace psc_paper {
namespace {  // one translation unit: paper_experiments.cpp

typedef psc_test::Kernel Kernel;
typedef psc_test::Point Point;
typedef psc_test::Vector Vector;
typedef psc_test::Oriented_point Oriented_point;
typedef psc_test::Point_map Point_map;
typedef psc_test::Normal_map Normal_map;
typedef std::vector<Oriented_point> Cloud;
typedef CGAL::Curvature_estimate<Kernel> Estimate;

const double nan_value = std::numeric_limits<double>::quiet_NaN();

using psc_bench::seconds_since;

std::string format(double v, int digits = 3)
{
  if(!std::isfinite(v))
    return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

std::string format_fixed(double v, int decimals)
{
  if(!std::isfinite(v))
    return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

std::string format_count(std::size_t n)
{
  if(n >= 1000000 && n % 1000000 == 0)
    return std::to_string(n / 1000000) + "M";
  if(n >= 1000 && n % 1000 == 0)
    return std::to_string(n / 1000) + "K";
  return std::to_string(n);
}

// ------------------------------------------------------------------------------------
// Options

struct Options
{
  bool quick = false;
  std::string out = "benchmark/results";
  std::string data = PSC_DATA_DIR;
  std::uint64_t seed = 2021;
  std::set<std::string> only;
  double budget_scale = 1;

  bool run(const std::string& part) const { return only.empty() || only.count(part) != 0; }
};

Options parse_options(int argc, char** argv)
{
  Options o;
  psc_bench::Arguments args(argc, argv);
  for(std::string a; args.next(a);)
  {
    if(a == "--quick")
      o.quick = true;
    else if(a == "--out")
      o.out = args.value();
    else if(a == "--data")
      o.data = args.value();
    else if(a == "--seed")
      o.seed = std::stoull(args.value());
    else if(a == "--budget-scale")
      o.budget_scale = std::stod(args.value());
    else if(a == "--only")
    {
      const std::vector<std::string> parts = args.list();
      o.only.insert(parts.begin(), parts.end());
    }
    else
      throw std::invalid_argument("unknown option " + a +
                                  " (usage: paper_experiments [--quick] [--out DIR] [--data DIR] "
                                  "[--seed S] [--only LIST] [--budget-scale X])");
  }
  return o;
}

// ------------------------------------------------------------------------------------
// Estimators

struct Estimator
{
  std::string name;
  // Gives |k_min| <= |k_max| (curvature magnitudes, no sign): principal curvatures and
  // directions are then compared with the true ones sorted by magnitude.
  bool unsigned_curvatures;
  std::function<std::vector<Estimate>(const Cloud&, double, bool)> run;
  // by count (parallel), with the validity threshold given (min_neighbors)
  std::function<std::vector<Estimate>(const Cloud&, std::size_t, std::size_t)> run_by_count;
};

#define PSC_ESTIMATOR(NAME, FUNCTION, UNSIGNED)                                                                        \
  list.push_back(Estimator{                                                                                            \
    NAME, UNSIGNED,                                                                                                    \
    [](const Cloud& c, double r, bool parallel) {                                                                      \
      const auto np = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());                               \
      return parallel ? CGAL::FUNCTION<CGAL::Parallel_tag>(c, r, np) : CGAL::FUNCTION<CGAL::Sequential_tag>(c, r, np); \
    },                                                                                                                 \
    [](const Cloud& c, std::size_t k, std::size_t minimum) {                                                           \
      namespace P = CGAL::Point_set_curvatures::parameters;                                                            \
      return CGAL::FUNCTION<CGAL::Parallel_tag>(                                                                       \
        c, P::neighbor_count(                                                                                          \
             k, P::min_neighbors(minimum, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()))));        \
    }})

// In the order of the paper's Table 2.
std::vector<Estimator> all_estimators()
{
  std::vector<Estimator> list;
#ifdef PSC_HAS_BARYCENTER
  PSC_ESTIMATOR("Barycenter", estimate_barycenter_curvatures, false);
#endif
#ifdef PSC_HAS_PCA_PLANE
  PSC_ESTIMATOR("PCA-plane", estimate_pca_plane_curvatures, false);
#endif
  PSC_ESTIMATOR("APSS", estimate_apss_curvatures, false);
  PSC_ESTIMATOR("ASO", estimate_aso_curvatures, false);  // the package's default (ROBUST)
  // the paper's estimator (Aso_variant::PAPER), side by side with the default
  list.push_back(Estimator{
    "ASO-paper", false,
    [](const Cloud& c, double r, bool parallel) {
      namespace P = CGAL::Point_set_curvatures::parameters;
      const auto np =
        P::aso_variant(CGAL::Aso_variant::PAPER, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
      return parallel ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(c, r, np)
                      : CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(c, r, np);
    },
    [](const Cloud& c, std::size_t k, std::size_t minimum) {
      namespace P = CGAL::Point_set_curvatures::parameters;
      return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
        c, P::neighbor_count(
             k, P::min_neighbors(minimum,
                                 P::aso_variant(CGAL::Aso_variant::PAPER,
                                                CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())))));
    }});
#ifdef PSC_HAS_JET
  PSC_ESTIMATOR("OJets", estimate_jet_curvatures, false);
#endif
#ifdef PSC_HAS_WAVEJET
  PSC_ESTIMATOR("WJets", estimate_wavejet_curvatures, false);
#endif
#ifdef PSC_HAS_PSS
  PSC_ESTIMATOR("PSS", estimate_pss_curvatures, false);
#endif
#ifdef PSC_HAS_VCM
  PSC_ESTIMATOR("VCM", estimate_vcm_curvatures, true);
#endif
  return list;
}

const Estimator& find_estimator(const std::vector<Estimator>& list, const std::string& name)
{
  for(const Estimator& e : list)
    if(e.name == name)
      return e;
  throw std::logic_error("no estimator " + name);
}

// ------------------------------------------------------------------------------------
// Time budgets: every estimator gets `cap` seconds per experiment. The cost of a run is
// predicted from the estimator's previous run in the same experiment, proportionally to
// points x (neighbours + 10) (10: the per-point overhead of the driver, measured about 10
// neighbours' worth for ASO). The first run of every estimator is never skipped, unless
// the whole program has passed its deadline (16 minutes, 100 seconds with --quick), which
// keeps the suite under its limits (20 minutes, 2 minutes with --quick) with the build and
// the plots, whatever the baselines cost.

struct Skipped_run
{
  std::string experiment, estimator, setting;
  double predicted;
};

class Budget
{
public:
  Budget(std::string experiment, double cap) : m_experiment(std::move(experiment)), m_cap(cap) {}

  static double work(double points, double neighbors) { return points * (neighbors + 10); }

  static std::chrono::steady_clock::time_point& start()
  {
    static std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
    return t;
  }
  static double& deadline()
  {
    static double seconds = 960;
    return seconds;
  }
  static double elapsed() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start()).count(); }

  // true if the run fits; otherwise records it as skipped.
  bool allow(const std::string& key, double work, const std::string& setting, std::vector<Skipped_run>& skipped)
  {
    auto it = m_last.find(key);
    const double predicted = it == m_last.end() ? 0 : it->second.first * work / it->second.second;
    const bool fits = it == m_last.end() || m_spent[key] + predicted <= m_cap;
    const bool in_time = elapsed() + predicted <= deadline();
    if(fits && in_time)
      return true;
    skipped.push_back(Skipped_run{m_experiment, key, setting + (in_time ? "" : " (program deadline)"), predicted});
    std::cerr << "  skip " << key << " " << setting << ": predicted " << format(predicted) << " s, budget left "
              << format(m_cap - m_spent[key]) << " s, program time " << format(elapsed()) << " s of "
              << format(deadline()) << " s\n";
    return false;
  }

  void record(const std::string& key, double seconds, double work)
  {
    m_spent[key] += seconds;
    m_last[key] = {std::max(seconds, 1e-3), work};
  }

  // Time spent by `key` beyond its recorded run (repetitions).
  void charge(const std::string& key, double seconds) { m_spent[key] += seconds; }

private:
  std::string m_experiment;
  double m_cap;
  std::map<std::string, double> m_spent;
  std::map<std::string, std::pair<double, double> > m_last;
};

// ------------------------------------------------------------------------------------
// Goursat samples and test clouds

struct Goursat_sample
{
  Cloud points;
  double seconds = 0;
  double max_residual = 0;  // relative to the bounding-box diagonal
};

class Sample_cache
{
public:
  explicit Sample_cache(std::uint64_t seed) : m_seed(seed) {}

  const Goursat_sample& get(std::size_t n)
  {
    auto it = m_samples.find(n);
    if(it != m_samples.end())
      return it->second;
    goursat::Sampling_options o;
    o.size = n;
    o.seed = m_seed + n;
    const auto t0 = std::chrono::steady_clock::now();
    Goursat_sample s;
    s.points = goursat::sample(o);
    s.seconds = seconds_since(t0);
    s.max_residual = goursat::max_relative_residual(s.points);
    if(!(s.max_residual < 1e-9))  // the requirement; measured about 2e-16
      throw std::runtime_error("Goursat sample of " + std::to_string(n) + " points: residual " +
                               format(s.max_residual) + " of the diagonal, above 1e-9");
    std::cerr << "  sampled Goursat N=" << n << " in " << format(s.seconds) << " s, max residual "
              << format(s.max_residual) << " of the diagonal\n";
    return m_samples.emplace(n, std::move(s)).first->second;
  }

  const std::map<std::size_t, Goursat_sample>& all() const { return m_samples; }

private:
  std::uint64_t m_seed;
  std::map<std::size_t, Goursat_sample> m_samples;
};

// Distance from p to the cone C = {x >= y >= z >= 0}, a fundamental domain of the
// surface's 48 symmetries (coordinate permutations and sign changes). The projection onto
// C is the non-increasing isotonic regression of (x, y, z) (pool adjacent violators),
// clamped at 0.
double distance_to_fundamental_cone(const double p[3])
{
  double value[3] = {p[0], p[1], p[2]}, weight[3] = {1, 1, 1};
  int start[3] = {0, 1, 2};
  int blocks = 0;
  for(int i = 0; i < 3; ++i)
  {
    value[blocks] = p[i];
    weight[blocks] = 1;
    start[blocks] = i;
    ++blocks;
    while(blocks > 1 && value[blocks - 2] < value[blocks - 1])
    {
      const double w = weight[blocks - 2] + weight[blocks - 1];
      value[blocks - 2] = (weight[blocks - 2] * value[blocks - 2] + weight[blocks - 1] * value[blocks - 1]) / w;
      weight[blocks - 2] = w;
      --blocks;
    }
  }
  double projection[3];
  for(int b = 0; b < blocks; ++b)
  {
    const int end = b + 1 < blocks ? start[b + 1] : 3;
    for(int i = start[b]; i < end; ++i)
      projection[i] = std::max(0.0, value[b]);
  }
  return std::sqrt((p[0] - projection[0]) * (p[0] - projection[0]) + (p[1] - projection[1]) * (p[1] - projection[1]) +
                   (p[2] - projection[2]) * (p[2] - projection[2]));
}

bool in_fundamental_cone(const Point& p) { return p.x() >= p.y() && p.y() >= p.z() && p.z() >= 0; }

// What an estimator runs on, and which of its points are scored against which truth.
struct Test_cloud
{
  Cloud points;
  std::vector<std::uint32_t> scored;   // indices into points
  std::vector<psc_test::Truth> truth;  // per scored point
  std::size_t sample_size = 0;         // N of the whole sample
  bool domain = false;                 // scored on the fundamental domain only
};

// Clouds of N >= 100K points are scored on the fundamental domain (1/48 of the surface)
// only, and the estimators run on that domain plus every point that can be a neighbour of
// it: the same errors in expectation (the sample, the noise and the estimators are all
// invariant under the symmetries), for 3-6% of the cost.
const std::size_t domain_threshold = 100000;

// `clean`: the sample (truth is taken at its points); `input`: what the estimators get
// (same order, possibly perturbed positions or normals).
Test_cloud make_test_cloud(const Cloud& clean, const Cloud& input, double radius)
{
  Test_cloud t;
  t.sample_size = clean.size();
  t.domain = clean.size() >= domain_threshold;
  if(!t.domain)
  {
    t.points = input;
    t.scored.resize(clean.size());
    t.truth.resize(clean.size());
    for(std::size_t i = 0; i < clean.size(); ++i)
    {
      t.scored[i] = std::uint32_t(i);
      t.truth[i] = psc_test::goursat_truth(clean[i].first);
    }
    return t;
  }
  // A scored point moved by at most `shift` from the cone; its neighbours are within
  // radius + shift of the cone.
  double shift = 0;
  for(std::size_t i = 0; i < clean.size(); ++i)
    if(in_fundamental_cone(clean[i].first))
      shift = std::max(shift, std::sqrt(CGAL::squared_distance(clean[i].first, input[i].first)));
  const double reach = radius + shift;
  for(std::size_t i = 0; i < clean.size(); ++i)
  {
    const double p[3] = {input[i].first.x(), input[i].first.y(), input[i].first.z()};
    const bool scored = in_fundamental_cone(clean[i].first);
    if(!scored && !(distance_to_fundamental_cone(p) < reach))
      continue;
    if(scored)
    {
      t.scored.push_back(std::uint32_t(t.points.size()));
      t.truth.push_back(psc_test::goursat_truth(clean[i].first));
    }
    t.points.push_back(input[i]);
  }
  return t;
}

// ------------------------------------------------------------------------------------
// Errors

// Principal directions are compared where the true principal curvatures differ by at
// least this much (1/length): 75% of the Goursat surface (the quantiles of k_max - k_min
// over the surface: 1% 0.0045, 10% 0.026, 25% 0.050, 50% 0.11, max 0.50).
const double direction_gap = 0.05;

struct Errors
{
  double H = nan_value, normal = nan_value, kmin = nan_value, kmax = nan_value, direction = nan_value;
  double valid_fraction = 0;
  double mean_neighbors = 0;
};

Errors score(const Test_cloud& t, const std::vector<Estimate>& est, bool unsigned_curvatures)
{
  double sum[5] = {0, 0, 0, 0, 0};
  std::size_t count[5] = {0, 0, 0, 0, 0};
  std::size_t valid = 0;
  double neighbors = 0;
  for(std::size_t s = 0; s < t.scored.size(); ++s)
  {
    const Estimate& e = est[t.scored[s]];
    const psc_test::Truth& truth = t.truth[s];
    if(!e.is_valid())
      continue;
    ++valid;
    neighbors += double(e.neighbor_count);
    if(std::isfinite(e.mean_curvature))
    {
      sum[0] += std::abs(std::abs(e.mean_curvature) - std::abs(truth.mean));
      ++count[0];
    }
    const double nl = std::sqrt(e.normal.squared_length());
    if(std::isfinite(nl) && nl > 0)
    {
      sum[1] += 1 - std::abs(e.normal * truth.normal) / nl;
      ++count[1];
    }
    const double k1 = e.min_curvature, k2 = e.max_curvature;
    if(std::isfinite(k1) && std::isfinite(k2))
    {
      if(unsigned_curvatures)
      {
        const double a = std::min(std::abs(k1), std::abs(k2)), b = std::max(std::abs(k1), std::abs(k2));
        const double ta = std::min(std::abs(truth.k_min), std::abs(truth.k_max));
        const double tb = std::max(std::abs(truth.k_min), std::abs(truth.k_max));
        sum[2] += std::abs(a - ta);
        sum[3] += std::abs(b - tb);
      }
      else
      {
        sum[2] += std::abs(k1 - truth.k_min);
        sum[3] += std::abs(k2 - truth.k_max);
      }
      ++count[2];
      ++count[3];
    }
    if(std::isfinite(e.max_direction.x()) && std::isfinite(e.min_direction.x()))
    {
      if(unsigned_curvatures)
      {
        // direction of the larger curvature magnitude, on both sides
        if(std::abs(std::abs(truth.k_max) - std::abs(truth.k_min)) >= direction_gap)
        {
          const Vector& d = std::abs(k2) >= std::abs(k1) ? e.max_direction : e.min_direction;
          const Vector& td = std::abs(truth.k_max) >= std::abs(truth.k_min) ? truth.d_max : truth.d_min;
          sum[4] += psc_test::line_angle_degrees(d, td);
          ++count[4];
        }
      }
      else if(truth.k_max - truth.k_min >= direction_gap)
      {
        sum[4] += psc_test::line_angle_degrees(e.max_direction, truth.d_max);
        ++count[4];
      }
    }
  }
  Errors r;
  double* out[5] = {&r.H, &r.normal, &r.kmin, &r.kmax, &r.direction};
  for(int q = 0; q < 5; ++q)
    if(count[q] > 0)
      *out[q] = sum[q] / double(count[q]);
  r.valid_fraction = t.scored.empty() ? 0 : double(valid) / double(t.scored.size());
  r.mean_neighbors = valid > 0 ? neighbors / double(valid) : 0;
  return r;
}

struct Error_row
{
  std::string estimator;
  std::size_t N;
  double radius;
  std::string condition;
  Errors errors;
  double seconds;
  std::size_t points_run;  // size of the cloud the estimator ran on
};

const char* error_csv_header =
  "estimator,N,radius,condition,err_H,err_normal,err_kmin,err_kmax,err_direction_deg,valid_fraction";

void write_error_csv(const std::string& file, const std::vector<Error_row>& rows)
{
  std::ofstream out(file);
  if(!out)
    throw std::runtime_error("cannot write " + file);
  out << error_csv_header << "\n";
  for(const Error_row& r : rows)
    out << r.estimator << "," << r.N << "," << format(r.radius, 6) << "," << r.condition << "," << format(r.errors.H, 6)
        << "," << format(r.errors.normal, 6) << "," << format(r.errors.kmin, 6) << "," << format(r.errors.kmax, 6)
        << "," << format(r.errors.direction, 6) << "," << format(r.errors.valid_fraction, 6) << "\n";
}

// ------------------------------------------------------------------------------------
// Markdown

struct Table
{
  std::vector<std::string> header;
  std::vector<std::vector<std::string> > rows;

  std::string markdown() const
  {
    std::ostringstream s;
    auto line = [&](const std::vector<std::string>& cells) {
      s << "|";
      for(const std::string& c : cells)
        s << " " << (c.empty() ? "–" : c) << " |";
      s << "\n";
    };
    line(header);
    s << "|";
    for(std::size_t i = 0; i < header.size(); ++i)
      s << (i == 0 ? ":---|" : "---:|");
    s << "\n";
    for(const auto& r : rows)
      line(r);
    return s.str();
  }
};

Table error_table(const std::vector<Error_row>& rows, bool with_n, bool with_condition)
{
  Table t;
  t.header = {"estimator"};
  if(with_n)
    t.header.push_back("N");
  t.header.push_back("r");
  if(with_condition)
    t.header.push_back("condition");
  for(const char* h : {"mean abs(abs(H)-abs(H*))", "mean 1-abs(n.n*)", "mean abs(k_min err)", "mean abs(k_max err)",
                       "direction err (deg)", "valid", "seconds"})
    t.header.push_back(h);
  for(const Error_row& r : rows)
  {
    std::vector<std::string> c = {r.estimator};
    if(with_n)
      c.push_back(format_count(r.N));
    c.push_back(format(r.radius));
    if(with_condition)
      c.push_back(r.condition);
    c.push_back(format(r.errors.H));
    c.push_back(format(r.errors.normal));
    c.push_back(format(r.errors.kmin));
    c.push_back(format(r.errors.kmax));
    c.push_back(format_fixed(r.errors.direction, 2));
    c.push_back(format_fixed(r.errors.valid_fraction, 4));
    c.push_back(format(r.seconds));
    t.rows.push_back(c);
  }
  return t;
}

class Report
{
public:
  explicit Report(std::string file) : m_file(std::move(file)) {}
  void section(const std::string& title) { add("\n## " + title + "\n\n"); }
  void text(const std::string& s) { add(s + "\n"); }
  void table(const Table& t) { add(t.markdown() + "\n"); }
  void add(const std::string& s)
  {
    std::cout << s << std::flush;
    m_text += s;
    std::ofstream out(m_file);  // rewritten each time: a partial run leaves a usable summary
    out << m_text;
  }

private:
  std::string m_file;
  std::string m_text;
};

// ------------------------------------------------------------------------------------
// gnuplot scripts (data inline, so each .gp is self-contained)

const char* gnuplot_colors[] = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e",
                                "#e6ab02", "#a6761d", "#666666", "#1f78b4", "#b2df8a"};

std::string gp_quote(const std::string& s) { return "'" + s + "'"; }

// One data block per estimator, columns: x value of each quantity.
struct Series
{
  std::string name;
  std::vector<std::pair<double, std::array<double, 5> > > points;
};

std::string data_block(const std::string& var, const std::vector<Series>& series)
{
  std::ostringstream s;
  s << "$" << var << " << EOD\n";
  for(std::size_t i = 0; i < series.size(); ++i)
  {
    s << "# " << series[i].name << "\n";
    for(const auto& p : series[i].points)
    {
      s << std::setprecision(8) << p.first;
      for(double v : p.second)
        s << " " << (std::isfinite(v) && v > 0 ? format(v, 8) : std::string("NaN"));
      s << "\n";
    }
    s << "\n\n";
  }
  s << "EOD\n";
  return s.str();
}

const char* quantity_titles[5] = {"mean | |H| - |H*| |", "mean 1 - |n . n*|", "mean |k_{min} error|",
                                  "mean |k_{max} error|", "mean direction error (deg)"};

std::array<double, 5> as_array(const Errors& e) { return {{e.H, e.normal, e.kmin, e.kmax, e.direction}}; }

// ------------------------------------------------------------------------------------
// Experiments

struct Context
{
  Options options;
  std::vector<Estimator> estimators;
  Sample_cache samples;
  Report report;
  std::vector<Skipped_run> skipped;

  Context(const Options& o) : options(o), estimators(all_estimators()), samples(o.seed), report(o.out + "/summary.md")
  {}

  std::string path(const std::string& name) const { return options.out + "/" + name; }
  double budget(double full, double quick) const { return (options.quick ? quick : full) * options.budget_scale; }
  double diagonal() const { return goursat::surface_constants().diagonal; }
  double area() const { return goursat::surface_constants().area; }
  double expected_neighbors(std::size_t n, double r) const { return double(n) / area() * M_PI * r * r; }
};

// Runs one estimator on a test cloud (Parallel_tag) and scores it; false if skipped.
bool run_and_score(Context& ctx, Budget& budget, const Estimator& e, const Test_cloud& t, double radius,
                   const std::string& condition, std::vector<Error_row>& rows,
                   std::function<void(const std::vector<Estimate>&)> also = {})
{
  const double work = Budget::work(double(t.points.size()), ctx.expected_neighbors(t.sample_size, radius));
  const std::string setting = "N=" + format_count(t.sample_size) + " r=" + format(radius) + " " + condition;
  if(!budget.allow(e.name, work, setting, ctx.skipped))
    return false;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Estimate> est = e.run(t.points, radius, true);
  const double seconds = seconds_since(t0);
  budget.record(e.name, seconds, work);
  rows.push_back(Error_row{e.name, t.sample_size, radius, condition, score(t, est, e.unsigned_curvatures), seconds,
                           t.points.size()});
  std::cerr << "  " << e.name << " " << setting << ": " << format(seconds) << " s on " << t.points.size()
            << " points\n";
  if(also)
    also(est);
  return true;
}

std::string skipped_text(const Context& ctx, const std::string& experiment)
{
  std::ostringstream s;
  for(const Skipped_run& k : ctx.skipped)
    if(k.experiment == experiment)
      s << "- skipped (time budget): " << k.estimator << ", " << k.setting << ", predicted " << format(k.predicted)
        << " s\n";
  return s.str();
}

// Errors against x for every estimator, as a gnuplot script (experiments 1, 2, 3 and 6).
void plot_errors_vs_x(Context& ctx, const std::string& file, const std::string& title,
                      const std::vector<std::pair<std::string, std::vector<Error_row> > >& rows_per_row,
                      const std::string& xlabel, std::function<double(const Error_row&)> x, bool logx,
                      const std::vector<std::string>& xtics = {}, const char* first_title = quantity_titles[0])
{
  std::ofstream gp(ctx.path(file + ".gp"));
  const int columns = 5;
  auto has_value = [&](std::size_t row, const std::string& name, int q) {
    for(const Error_row& r : rows_per_row[row].second)
      if(r.estimator == name && std::isfinite(as_array(r.errors)[q]) && as_array(r.errors)[q] > 0)
        return true;
    return false;
  };
  // Layout in pixels: 75 for the figure and panel titles, 300 per row of graphs, 95 between
  // rows, the x labels (120 for rotated names), 35 for the legend of the whole figure.
  const double rows_count = double(rows_per_row.size());
  const bool rotated_tics =
    std::any_of(xtics.begin(), xtics.end(), [](const std::string& t) { return t.find("rotate") != std::string::npos; });
  const double labels = rotated_tics ? 120 : 55;
  const double height = 75 + 300 * rows_count + 95 * (rows_count - 1) + labels + 35;
  gp << "set terminal pngcairo size 1900," << int(height) << " font ',10'\n";
  gp << "set output '" << file << ".png'\n";
  // One data block per estimator that has rows; block_of[row][estimator] = its index.
  std::vector<std::vector<int> > block_of(rows_per_row.size(), std::vector<int>(ctx.estimators.size(), -1));
  std::vector<bool> in_figure(ctx.estimators.size(), false);
  for(std::size_t row = 0; row < rows_per_row.size(); ++row)
  {
    std::vector<Series> series;
    for(std::size_t i = 0; i < ctx.estimators.size(); ++i)
    {
      Series s;
      s.name = ctx.estimators[i].name;
      for(const Error_row& r : rows_per_row[row].second)
        if(r.estimator == s.name)
          s.points.push_back({x(r), as_array(r.errors)});
      if(s.points.empty())
        continue;
      block_of[row][i] = int(series.size());
      in_figure[i] = true;
      series.push_back(s);
    }
    gp << data_block("D" + std::to_string(row), series);
  }
  auto style = [&](std::size_t i) {
    std::ostringstream s;
    s << "with linespoints lw 2 pt " << (i % 13) + 1 << " ps 0.8 lc rgb '" << gnuplot_colors[i % 10] << "'";
    return s.str();
  };
  gp << "set multiplot title " << gp_quote(title) << " font ',13'\n";
  gp << "set logscale y\nset format y '%g'\nset grid\nunset key\n";
  if(logx)
    gp << "set logscale x\n";
  for(const std::string& t : xtics)
    gp << t << "\n";
  gp << "set xlabel " << gp_quote(xlabel) << "\n";
  const double left = 0.04, right = 0.99, gap = 0.045;
  const double width = (right - left - gap * (columns - 1)) / columns;
  for(std::size_t row = 0; row < rows_per_row.size(); ++row)
    for(int q = 0; q < columns; ++q)
    {
      const double x0 = left + q * (width + gap);
      const double y1 = 1 - (75 + double(row) * 395) / height;
      gp << "set lmargin at screen " << x0 << "\nset rmargin at screen " << x0 + width << "\n";
      gp << "set tmargin at screen " << y1 << "\nset bmargin at screen " << y1 - 300 / height << "\n";
      gp << "set title "
         << gp_quote(std::string(q == 0 ? first_title : quantity_titles[q]) + " — " + rows_per_row[row].first) << "\n";
      gp << "plot ";
      bool first = true;
      for(std::size_t i = 0; i < ctx.estimators.size(); ++i)
      {
        if(block_of[row][i] < 0 || !has_value(row, ctx.estimators[i].name, q))
          continue;
        gp << (first ? "" : ", \\\n     ") << "$D" << row << " index " << block_of[row][i] << " using 1:" << q + 2
           << " " << style(i) << " notitle";
        first = false;
      }
      if(first)
        gp << "NaN notitle";
      gp << "\n";
    }
  // The legend of the whole figure: an empty plot along the bottom.
  gp << "unset title\nunset xlabel\nunset ylabel\nunset border\nunset tics\nunset grid\nunset logscale\n"
        "set xrange [0:1]\nset yrange [0:1]\n";
  gp << "set lmargin at screen 0\nset rmargin at screen 1\nset bmargin at screen 0\nset tmargin at screen "
     << 35 / height << "\n";
  gp << "set key center center horizontal maxcols 12 font ',10' samplen 3 width 2\nplot ";
  bool first = true;
  for(std::size_t i = 0; i < ctx.estimators.size(); ++i)
    if(in_figure[i])
    {
      gp << (first ? "" : ", ") << "NaN " << style(i) << " title " << gp_quote(ctx.estimators[i].name);
      first = false;
    }
  if(first)
    gp << "NaN notitle";
  gp << "\nunset multiplot\n";
}

// Every point of `points` scored, against the Goursat truth at the point or (`project`) at its
// radial projection (experiments 6 and 7).
Test_cloud scored_everywhere(const Cloud& points, bool project)
{
  Test_cloud t;
  t.points = points;
  t.sample_size = points.size();
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    double p[3] = {points[i].first.x(), points[i].first.y(), points[i].first.z()};
    if(project)  // truth at the radial projection (positions of the LiDAR cloud are noisy)
    {
      const double v[3] = {p[0], p[1], p[2]};
      goursat::project_radially(v, p);
    }
    t.scored.push_back(std::uint32_t(i));
    t.truth.push_back(psc_test::goursat_truth(Point(p[0], p[1], p[2])));
  }
  return t;
}
}  // namespace
}  // namespace psc_paper

#endif
