// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Section 6 of Lejemble et al. 2021, measured here (issue 5). One program, run by
// benchmark/paper_experiments.sh, which writes into the output folder:
//
//   sampler:        spacing statistics of the Goursat sampler against the shared samples
//                   (sampler.csv, spacing.png)
//   experiment 1:   convergence with N, fixed and shrinking radius (convergence.csv, .png)
//   experiment 2:   Gaussian noise on the positions (noise_position.csv, .png)
//   experiment 3:   noisy, flipped and PCA normals (noise_normals.csv, .png)
//   experiment 4:   timings, sequential and parallel (timings.csv, .png)
//   experiment 5:   pictures of the bunny and of the Goursat LiDAR cloud coloured by the
//                   estimated curvatures (curvatures_*.png), errors on the LiDAR cloud
//                   (lidar.csv)
//   experiment 6:   error against the neighbour count, which sets each estimator's least
//                   neighbour count of a valid estimate (neighbors.csv, .png)
//   experiment 7:   the ASO's variants beyond the paper against PSS and jets (variants.csv)
//   summary.md:     every table, in Markdown.
//
// Plots are gnuplot scripts (*.gp, data inline) that the shell script runs.
//
// Estimators: ASO and APSS, and every baseline whose header exists (same interface:
// CGAL::estimate_<name>_curvatures<ConcurrencyTag>(points, radius, np)).
//
// Costs are bounded: errors are computed on a region of the surface (below) and every
// estimator has a time budget per experiment; a run whose predicted time (from its
// previous run, scaled by points x neighbours) does not fit is skipped and listed in the
// summary, never silently dropped.
//
// usage: paper_experiments [--quick] [--out DIR] [--data DIR] [--seed S]
//                          [--only LIST] [--budget-scale X]
//   LIST: comma-separated among sampler,convergence,noise_position,noise_normals,timings,pictures,
//         neighbors,variants

#include "goursat_sampler.h"
#include "render_points.h"
#include "bench_support.h"

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

namespace {

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
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if(a == "--quick")
      o.quick = true;
    else if(a == "--out")
      o.out = value();
    else if(a == "--data")
      o.data = value();
    else if(a == "--seed")
      o.seed = std::stoull(value());
    else if(a == "--budget-scale")
      o.budget_scale = std::stod(value());
    else if(a == "--only")
    {
      std::stringstream s(value());
      std::string part;
      while(std::getline(s, part, ','))
        o.only.insert(part);
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

#define PSC_ESTIMATOR(NAME, FUNCTION, UNSIGNED)                                              \
  list.push_back(Estimator{NAME, UNSIGNED, [](const Cloud& c, double r, bool parallel) {      \
                             const auto np =                                                  \
                               CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()); \
                             return parallel ? CGAL::FUNCTION<CGAL::Parallel_tag>(c, r, np)    \
                                             : CGAL::FUNCTION<CGAL::Sequential_tag>(c, r, np); \
                           },                                                                 \
                           [](const Cloud& c, std::size_t k, std::size_t minimum) {           \
                             namespace P = CGAL::Point_set_curvatures::parameters;            \
                             return CGAL::FUNCTION<CGAL::Parallel_tag>(                       \
                               c, P::neighbor_count(k, P::min_neighbors(                      \
                                    minimum, CGAL::parameters::point_map(Point_map())         \
                                               .normal_map(Normal_map()))));                  \
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
  list.push_back(Estimator{"ASO-paper", false,
                           [](const Cloud& c, double r, bool parallel) {
                             namespace P = CGAL::Point_set_curvatures::parameters;
                             const auto np = P::aso_variant(
                               CGAL::Aso_variant::PAPER, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map()));
                             return parallel ? CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(c, r, np)
                                             : CGAL::estimate_aso_curvatures<CGAL::Sequential_tag>(c, r, np);
                           },
                           [](const Cloud& c, std::size_t k, std::size_t minimum) {
                             namespace P = CGAL::Point_set_curvatures::parameters;
                             return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
                               c, P::neighbor_count(k, P::min_neighbors(minimum, P::aso_variant(
                                    CGAL::Aso_variant::PAPER, CGAL::parameters::point_map(Point_map())
                                                                .normal_map(Normal_map())))));
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
  Budget(std::string experiment, double cap)
    : m_experiment(std::move(experiment)), m_cap(cap)
  {}

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
  bool allow(const std::string& key, double work, const std::string& setting,
             std::vector<Skipped_run>& skipped)
  {
    auto it = m_last.find(key);
    const double predicted = it == m_last.end() ? 0 : it->second.first * work / it->second.second;
    const bool fits = it == m_last.end() || m_spent[key] + predicted <= m_cap;
    const bool in_time = elapsed() + predicted <= deadline();
    if(fits && in_time)
      return true;
    skipped.push_back(Skipped_run{m_experiment, key, setting + (in_time ? "" : " (program deadline)"), predicted});
    std::cerr << "  skip " << key << " " << setting << ": predicted " << format(predicted)
              << " s, budget left " << format(m_cap - m_spent[key]) << " s, program time "
              << format(elapsed()) << " s of " << format(deadline()) << " s\n";
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
  explicit Sample_cache(std::uint64_t seed)
    : m_seed(seed)
  {}

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
  return std::sqrt((p[0] - projection[0]) * (p[0] - projection[0]) +
                   (p[1] - projection[1]) * (p[1] - projection[1]) +
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
    out << r.estimator << "," << r.N << "," << format(r.radius, 6) << "," << r.condition << ","
        << format(r.errors.H, 6) << "," << format(r.errors.normal, 6) << "," << format(r.errors.kmin, 6)
        << "," << format(r.errors.kmax, 6) << "," << format(r.errors.direction, 6) << ","
        << format(r.errors.valid_fraction, 6) << "\n";
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
  for(const char* h : {"mean abs(abs(H)-abs(H*))", "mean 1-abs(n.n*)", "mean abs(k_min err)",
                       "mean abs(k_max err)", "direction err (deg)", "valid", "seconds"})
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
  explicit Report(std::string file)
    : m_file(std::move(file))
  {}
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

int estimator_style(const std::vector<Estimator>& list, const std::string& name)
{
  for(std::size_t i = 0; i < list.size(); ++i)
    if(list[i].name == name)
      return int(i);
  return int(list.size());
}

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

  Context(const Options& o)
    : options(o), estimators(all_estimators()), samples(o.seed), report(o.out + "/summary.md")
  {}

  std::string path(const std::string& name) const { return options.out + "/" + name; }
  double budget(double full, double quick) const { return (options.quick ? quick : full) * options.budget_scale; }
  double diagonal() const { return goursat::surface_constants().diagonal; }
  double area() const { return goursat::surface_constants().area; }
  double expected_neighbors(std::size_t n, double r) const { return double(n) / area() * M_PI * r * r; }
};

// Runs one estimator on a test cloud (Parallel_tag) and scores it; false if skipped.
bool run_and_score(Context& ctx, Budget& budget, const Estimator& e, const Test_cloud& t,
                   double radius, const std::string& condition, std::vector<Error_row>& rows,
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
  rows.push_back(Error_row{e.name, t.sample_size, radius, condition, score(t, est, e.unsigned_curvatures),
                           seconds, t.points.size()});
  std::cerr << "  " << e.name << " " << setting << ": " << format(seconds) << " s on "
            << t.points.size() << " points\n";
  if(also)
    also(est);
  return true;
}

std::string skipped_text(const Context& ctx, const std::string& experiment)
{
  std::ostringstream s;
  for(const Skipped_run& k : ctx.skipped)
    if(k.experiment == experiment)
      s << "- skipped (time budget): " << k.estimator << ", " << k.setting << ", predicted "
        << format(k.predicted) << " s\n";
  return s.str();
}

// --- sampler report ---------------------------------------------------------------------

struct Spacing_stats
{
  std::string name;
  std::size_t n = 0;
  double mean = 0, cv = 0, min = 0, p01 = 0, p99 = 0;
  std::vector<double> histogram;  // fraction per bin of nn/h in [0, 1.6), 40 bins
};

Spacing_stats spacing_stats(const std::string& name, const Cloud& points)
{
  std::vector<double> d = goursat::nearest_neighbor_spacing(points);
  Spacing_stats s;
  s.name = name;
  s.n = d.size();
  for(double x : d)
    s.mean += x;
  s.mean /= double(d.size());
  double var = 0;
  for(double x : d)
    var += (x - s.mean) * (x - s.mean);
  s.cv = std::sqrt(var / double(d.size())) / s.mean;
  std::sort(d.begin(), d.end());
  s.min = d.front();
  s.p01 = d[d.size() / 100];
  s.p99 = d[d.size() * 99 / 100];
  s.histogram.assign(40, 0);
  for(double x : d)
    s.histogram[std::min<std::size_t>(39, std::size_t(x / 0.04))] += 1.0 / double(d.size());
  return s;
}

void experiment_sampler(Context& ctx)
{
  ctx.report.section("Sampler: blue noise on the Goursat surface");
  const auto& c = goursat::surface_constants();
  ctx.report.text("Surface `-8 - 2(x²+y²+z²) + 0.03(x⁴+y⁴+z⁴) = 0`: area " + format(c.area, 7) +
                  ", bounding box [-" + format(c.half_extent, 7) + ", " + format(c.half_extent, 7) +
                  "]³, diagonal " + format(c.diagonal, 7) + ". Spacing below is the nearest-neighbour "
                  "distance divided by h = sqrt(area/N) (a hexagonal lattice has 1.075 h, uniform random "
                  "points 0.5 h on average with a coefficient of variation of 0.52).\n");
  std::vector<Spacing_stats> stats;
  std::vector<std::size_t> sizes = {10000, 50000};
  std::vector<Error_row> compared;  // estimators on the shared samples and on ours
  const double r5 = 0.05 * ctx.diagonal();
  auto compare = [&](const std::string& label, const Cloud& cloud) {
    Test_cloud t;
    t.points = cloud;
    t.sample_size = cloud.size();
    for(std::size_t i = 0; i < cloud.size(); ++i)
    {
      t.scored.push_back(std::uint32_t(i));
      t.truth.push_back(psc_test::goursat_truth(cloud[i].first));
    }
    for(const char* name : {"APSS", "ASO", "ASO-paper"})
    {
      const Estimator& e = find_estimator(ctx.estimators, name);
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Estimate> est = e.run(cloud, r5, true);
      compared.push_back(Error_row{e.name, cloud.size(), r5, label, score(t, est, e.unsigned_curvatures),
                                   seconds_since(t0), cloud.size()});
    }
  };
  for(std::size_t n : sizes)
  {
    goursat::Random random(ctx.options.seed + n);
    const std::vector<double> xyz = goursat::uniform_random_points(n, random);
    Cloud pts;
    for(std::size_t i = 0; i < n; ++i)
      pts.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), Vector(0, 0, 1));
    stats.push_back(spacing_stats("uniform random, N=" + format_count(n), pts));
    stats.push_back(spacing_stats("this sampler (" + std::to_string(goursat::Sampling_options().lloyd_iterations) +
                                    " Lloyd iterations), N=" + format_count(n),
                                  ctx.samples.get(n).points));
    compare("this sampler", ctx.samples.get(n).points);
    const std::string file = ctx.options.data + (n == 10000 ? "/goursat_010000.xyz" : "/goursat_050000.xyz");
    std::ifstream probe(file);
    if(probe)
    {
      const Cloud shared = psc_test::read_xyz(file);
      stats.push_back(spacing_stats("shared sample " + file.substr(file.find_last_of('/') + 1), shared));
      compare("shared " + file.substr(file.find_last_of('/') + 1), shared);
    }
  }
  Table t;
  t.header = {"point set", "N", "mean spacing / h", "coefficient of variation", "min / h", "1% quantile / h",
              "99% quantile / h"};
  for(const Spacing_stats& s : stats)
    t.rows.push_back({s.name, std::to_string(s.n), format(s.mean), format(s.cv), format(s.min),
                      format(s.p01), format(s.p99)});
  ctx.report.table(t);
  ctx.report.text("The same estimators on the shared samples and on this sampler's (r = 5% of the diagonal, exact "
                  "normals, every point scored; the shared points lie within 1e-5 of the surface):\n");
  ctx.report.table(error_table(compared, true, true));

  // Spacing statistics of the samples compared above.
  std::ofstream csv(ctx.path("sampler.csv"));
  csv << "point_set,N,mean_spacing_over_h,cv,min_over_h,p01_over_h,p99_over_h\n";
  for(const Spacing_stats& s : stats)
    csv << s.name << "," << s.n << "," << s.mean << "," << s.cv << "," << s.min << "," << s.p01 << ","
        << s.p99 << "\n";

  std::ofstream gp(ctx.path("spacing.gp"));
  gp << "set terminal pngcairo size 900,520 font ',11'\nset output 'spacing.png'\n";
  gp << "$H << EOD\n";
  for(std::size_t b = 0; b < 40; ++b)
  {
    gp << (b + 0.5) * 0.04;
    for(const Spacing_stats& s : stats)
      gp << " " << s.histogram[b];
    gp << "\n";
  }
  gp << "EOD\n";
  gp << "set title 'Nearest-neighbour spacing on the Goursat surface (h = sqrt(area/N))'\n"
        "set xlabel 'nearest-neighbour distance / h'\nset ylabel 'fraction of points'\n"
        "set key top left noenhanced\nset grid\n";
  gp << "plot ";
  for(std::size_t i = 0; i < stats.size(); ++i)
    gp << (i ? ", \\\n     " : "") << "$H using 1:" << i + 2 << " with linespoints lw 2 pt " << (i % 7) + 1
       << " ps 0.6 lc rgb '" << gnuplot_colors[i % 10] << "' title " << gp_quote(stats[i].name);
  gp << "\n";
}

// --- experiment 1 -----------------------------------------------------------------------

// Shrinking radius: r(N) = r5 (N / 10K)^(-1/4), i.e. proportional to sqrt(h): the radius
// tends to 0 while the number of neighbours grows like sqrt(N) (48 at 10K, 480 at 1M), the
// regime where the discrete sums converge to the integrals of Section 4.1.
double shrinking_radius(double r5, std::size_t n) { return r5 * std::pow(double(n) / 10000.0, -0.25); }

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
  const bool rotated_tics = std::any_of(xtics.begin(), xtics.end(), [](const std::string& t) {
    return t.find("rotate") != std::string::npos;
  });
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
      gp << "set title " << gp_quote(std::string(q == 0 ? first_title : quantity_titles[q]) + " — " + rows_per_row[row].first) << "\n";
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

void experiment_convergence(Context& ctx)
{
  ctx.report.section("Experiment 1: convergence (Figure 4)");
  const std::vector<std::size_t> sizes =
    ctx.options.quick ? std::vector<std::size_t>{10000, 25000, 50000}
                      : std::vector<std::size_t>{10000, 25000, 50000, 100000, 250000, 500000, 1000000};
  const double r5 = 0.05 * ctx.diagonal();
  ctx.report.text("Exact positions and normals. Fixed radius r = 5% of the bounding-box diagonal = " + format(r5, 4) +
                  "; shrinking radius r(N) = r5 (N/10K)^(-1/4) (proportional to the square root of the spacing, "
                  "so that r -> 0 while the neighbour count grows like sqrt(N)). Errors are means over the valid "
                  "estimates of the scored points: every point for N < 100K, the points of the fundamental domain "
                  "x >= y >= z >= 0 (1/48 of the surface, the estimators running on it plus an r-margin) from "
                  "100K on. Directions: angle between estimated and true k_max directions where k_max - k_min >= " +
                  format(direction_gap) + ". Empty cell: quantity not given by the estimator.\n");
  Budget budget("convergence", ctx.budget(100, 5));
  std::vector<Error_row> fixed_rows, shrinking_rows;
  struct Domain_check
  {
    std::string estimator;
    std::size_t n;
    Errors whole, domain;
    std::size_t domain_points;
  };
  std::vector<Domain_check> domain_check;
  for(std::size_t n : sizes)
  {
    const Goursat_sample& sample = ctx.samples.get(n);
    for(int rule = 0; rule < 2; ++rule)
    {
      const double r = rule == 0 ? r5 : shrinking_radius(r5, n);
      const Test_cloud t = make_test_cloud(sample.points, sample.points, r);
      for(const Estimator& e : ctx.estimators)
      {
        // Check of the fundamental-domain scoring: at the largest N scored on the whole
        // surface, the same estimates scored on the domain only.
        std::function<void(const std::vector<Estimate>&)> check;
        if(rule == 0 && !t.domain && n * 2 >= domain_threshold)
          check = [&](const std::vector<Estimate>& est) {
            Test_cloud sub;
            sub.sample_size = t.sample_size;
            for(std::size_t s = 0; s < t.scored.size(); ++s)
              if(in_fundamental_cone(t.points[t.scored[s]].first))
              {
                sub.scored.push_back(t.scored[s]);
                sub.truth.push_back(t.truth[s]);
              }
            domain_check.push_back({e.name, n, score(t, est, e.unsigned_curvatures),
                                    score(sub, est, e.unsigned_curvatures), sub.scored.size()});
          };
        run_and_score(ctx, budget, e, t, r, rule == 0 ? "fixed_radius" : "shrinking_radius",
                      rule == 0 ? fixed_rows : shrinking_rows, check);
      }
    }
  }
  std::vector<Error_row> all = fixed_rows;
  all.insert(all.end(), shrinking_rows.begin(), shrinking_rows.end());
  std::stable_sort(all.begin(), all.end(), [](const Error_row& a, const Error_row& b) {
    return std::make_tuple(a.condition, a.N) < std::make_tuple(b.condition, b.N);
  });
  write_error_csv(ctx.path("convergence.csv"), all);
  ctx.report.text("Fixed radius:\n");
  ctx.report.table(error_table(fixed_rows, true, false));
  ctx.report.text("Shrinking radius:\n");
  ctx.report.table(error_table(shrinking_rows, true, false));
  ctx.report.text(skipped_text(ctx, "convergence"));
  if(!domain_check.empty())
  {
    Table c;
    c.header = {"estimator", "N", "H error, whole surface", "H error, domain", "normal error, whole surface",
                "normal error, domain", "k_max error, whole surface", "k_max error, domain"};
    for(const Domain_check& d : domain_check)
      c.rows.push_back({d.estimator, format_count(d.n),
                        format(d.whole.H), format(d.domain.H), format(d.whole.normal), format(d.domain.normal),
                        format(d.whole.kmax), format(d.domain.kmax)});
    ctx.report.text("Check of the domain scoring (fixed radius, same estimates scored on the whole surface and on "
                    "the fundamental domain only, " + std::to_string(domain_check.front().domain_points) + " points):\n");
    ctx.report.table(c);
  }
  plot_errors_vs_x(ctx, "convergence", "Convergence on the Goursat surface (exact normals)",
                   {{"r = 5% diag", fixed_rows}, {"r = r_5 (N/10K)^{-1/4}", shrinking_rows}}, "N (points)",
                   [](const Error_row& r) { return double(r.N); }, true);
}

// --- experiments 2 and 3 ------------------------------------------------------------------

std::size_t noise_sample_size(const Context& ctx) { return ctx.options.quick ? 25000 : 100000; }

void experiment_noise_position(Context& ctx)
{
  ctx.report.section("Experiment 2: Gaussian noise on the positions (Figure 5, Theorem 2)");
  const std::size_t n = noise_sample_size(ctx);
  const double r = 0.05 * ctx.diagonal();
  const Goursat_sample& sample = ctx.samples.get(n);
  ctx.report.text("N = " + format_count(n) + ", r = 5% of the diagonal = " + format(r, 4) +
                  ". Every position moved by an isotropic Gaussian vector of standard deviation sigma per "
                  "coordinate (the paper's 0.005, 0.01, 0.02 at r = 0.1); the input normals stay the exact "
                  "normals of the clean points, and the truth is taken at the clean points.\n");
  Budget budget("noise_position", ctx.budget(25, 3));
  std::vector<Error_row> rows;
  for(double fraction : {0.0, 0.05, 0.1, 0.2})
  {
    const double sigma = fraction * r;
    goursat::Random random(ctx.options.seed * 7 + 11);
    Cloud noisy = sample.points;
    for(Oriented_point& p : noisy)
    {
      const double g0 = random.gaussian(), g1 = random.gaussian(), g2 = random.gaussian();
      p.first = Point(p.first.x() + sigma * g0, p.first.y() + sigma * g1, p.first.z() + sigma * g2);
    }
    const Test_cloud t = make_test_cloud(sample.points, noisy, r);
    const std::string condition = "sigma=" + format(fraction) + "r";
    for(const Estimator& e : ctx.estimators)
      run_and_score(ctx, budget, e, t, r, condition, rows);
  }
  write_error_csv(ctx.path("noise_position.csv"), rows);
  ctx.report.table(error_table(rows, false, true));
  ctx.report.text(skipped_text(ctx, "noise_position"));
  plot_errors_vs_x(ctx, "noise_position",
                   "Gaussian noise on the positions, N = " + format_count(n) + ", r = 5% diag",
                   {{"noise", rows}}, "sigma / r",
                   [](const Error_row& row) { return std::stod(row.condition.substr(6)); }, false,
                   {"set xrange [-0.01:0.21]"});
}

// PCA normals (k nearest neighbours), oriented by a minimum spanning tree, in input order;
// returns the number of points the MST could not orient.
std::size_t pca_oriented_normals(Cloud& points, unsigned k)
{
  typedef std::tuple<Point, Vector, std::size_t> Indexed;
  std::vector<Indexed> work;
  work.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    work.emplace_back(points[i].first, Vector(0, 0, 0), i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Indexed>())
                    .normal_map(CGAL::Nth_of_tuple_property_map<1, Indexed>());
  CGAL::pca_estimate_normals<CGAL::Parallel_tag>(work, k, np);
  const auto unoriented = CGAL::mst_orient_normals(work, k, np);
  const std::size_t failed = std::size_t(std::distance(unoriented, work.end()));
  for(const Indexed& w : work)
    points[std::get<2>(w)].second = std::get<1>(w);
  return failed;
}

void experiment_noise_normals(Context& ctx)
{
  ctx.report.section("Experiment 3: perturbed normals (Figure 6, and PCA normals of Figure 5)");
  const std::size_t n = noise_sample_size(ctx);
  const double r = 0.05 * ctx.diagonal();
  const Goursat_sample& sample = ctx.samples.get(n);
  const unsigned k = 18;
  Budget budget("noise_normals", ctx.budget(30, 6));
  std::vector<Error_row> rows;
  std::vector<std::string> notes;
  struct Condition
  {
    std::string name;
    std::function<void(Cloud&)> apply;
  };
  std::vector<Condition> conditions;
  conditions.push_back({"exact", [](Cloud&) {}});
  for(double degrees : {10.0, 20.0, 30.0})
    conditions.push_back({"angle_sigma=" + format(degrees) + "deg", [&, degrees](Cloud& c) {
                            // Tilt by a Gaussian angle vector of standard deviation `degrees`
                            // per tangent axis (mean tilt 1.25 sigma).
                            goursat::Random random(ctx.options.seed * 13 + std::uint64_t(degrees));
                            double mean_tilt = 0;
                            for(Oriented_point& p : c)
                            {
                              const double nn[3] = {p.second.x(), p.second.y(), p.second.z()};
                              double t1[3], t2[3];
                              goursat::tangent_frame(nn, t1, t2);
                              const double a = random.gaussian() * degrees * M_PI / 180;
                              const double b = random.gaussian() * degrees * M_PI / 180;
                              const double tilt = std::sqrt(a * a + b * b);
                              mean_tilt += tilt;
                              if(tilt == 0)
                                continue;
                              const double cs = std::cos(tilt), sn = std::sin(tilt) / tilt;
                              p.second = Vector(cs * nn[0] + sn * (a * t1[0] + b * t2[0]),
                                                cs * nn[1] + sn * (a * t1[1] + b * t2[1]),
                                                cs * nn[2] + sn * (a * t1[2] + b * t2[2]));
                            }
                            notes.push_back("angle_sigma=" + format(degrees) + "deg: mean tilt " +
                                            format(mean_tilt / double(c.size()) * 180 / M_PI) + " degrees");
                          }});
  for(double p : {0.1, 0.3})
    conditions.push_back({"flip_p=" + format(p), [&, p](Cloud& c) {
                            goursat::Random random(ctx.options.seed * 17 + std::uint64_t(p * 10));
                            for(Oriented_point& q : c)
                              if(random.uniform() < p)
                                q.second = -q.second;
                          }});
  conditions.push_back({"pca_normals_k" + std::to_string(k), [&](Cloud& c) {
                          const auto t0 = std::chrono::steady_clock::now();
                          const std::size_t failed = pca_oriented_normals(c, k);
                          double angle = 0;
                          std::size_t wrong = 0;
                          for(std::size_t i = 0; i < c.size(); ++i)
                          {
                            const Vector& truth = sample.points[i].second;
                            const double d = c[i].second * truth / std::sqrt(c[i].second.squared_length());
                            angle += std::acos(std::min(1.0, std::abs(d))) * 180 / M_PI;
                            if(d < 0)
                              ++wrong;
                          }
                          notes.push_back("pca_normals_k" + std::to_string(k) + ": CGAL::pca_estimate_normals (k = " +
                                          std::to_string(k) + ") + CGAL::mst_orient_normals (k = " + std::to_string(k) +
                                          ") in " + format(seconds_since(t0)) + " s; mean angle to the true normal " +
                                          format(angle / double(c.size())) + " degrees; " + std::to_string(wrong) +
                                          " normals point inwards, " + std::to_string(failed) +
                                          " left unoriented by the MST");
                        }});
  for(const Condition& c : conditions)
  {
    Cloud input = sample.points;
    c.apply(input);
    const Test_cloud t = make_test_cloud(sample.points, input, r);
    for(const char* name : {"APSS", "ASO", "ASO-paper"})
      run_and_score(ctx, budget, find_estimator(ctx.estimators, name), t, r, c.name, rows);
  }
  ctx.report.text("N = " + format_count(n) + ", r = " + format(r, 4) +
                  ", exact positions. Angular noise: each normal tilted by a random tangent angle vector "
                  "with a Gaussian distribution of the given standard deviation per axis. Flips: each normal "
                  "reversed with probability p. The normal error 1 - |n.n*| ignores orientation.\n");
  for(const std::string& s : notes)
    ctx.report.text("- " + s);
  ctx.report.text("");
  write_error_csv(ctx.path("noise_normals.csv"), rows);
  ctx.report.table(error_table(rows, false, true));
  ctx.report.text(skipped_text(ctx, "noise_normals"));

  // Grouped plot: x = condition index.
  std::vector<std::string> names;
  for(const Condition& c : conditions)
    names.push_back(c.name);
  std::string tics = "set xtics (";
  for(std::size_t i = 0; i < names.size(); ++i)
    tics += (i ? ", " : "") + gp_quote(names[i]) + " " + std::to_string(i);
  tics += ") rotate by -30 font ',8' noenhanced";
  plot_errors_vs_x(ctx, "noise_normals", "Perturbed input normals, N = " + format_count(n) + ", r = 5% diag",
                   {{"normals", rows}}, "", [names](const Error_row& row) {
                     return double(std::find(names.begin(), names.end(), row.condition) - names.begin());
                   },
                   false, {tics, "set xrange [-0.5:" + std::to_string(names.size() - 0.5) + "]"});
}

// --- experiment 4 -----------------------------------------------------------------------

struct Timing_row
{
  std::string data;
  std::size_t points;
  double radius, mean_neighbors;
  std::string estimator, execution;
  double seconds;  // NaN: skipped
  std::string note;
};

// Speed-up of a compute-bound TBB loop (no memory traffic) at this moment: what the
// machine offers to Parallel_tag, since it may be shared with other jobs.
void experiment_timings(Context& ctx)
{
  ctx.report.section("Experiment 4: timings (Table 2)");
  const std::size_t n = ctx.options.quick ? 100000 : 1000000;
  const double goursat_r = std::sqrt(40 * ctx.area() / (M_PI * double(n)));
  const double bunny_r = 0.005;
  struct Data
  {
    std::string name;
    Cloud points;
    double radius;
  };
  std::vector<Data> data;
  data.push_back({"bunny", psc_test::read_ascii_ply_xyz_normals(ctx.options.data + "/bunny.ply"), bunny_r});
  data.push_back({"Goursat", ctx.samples.get(n).points, goursat_r});
  const unsigned threads = std::thread::hardware_concurrency();
  Budget budget("timings", ctx.budget(75, 5));
  std::vector<Timing_row> rows;
  for(const Data& d : data)
  {
    double neighbors = nan_value;
    for(const Estimator& e : ctx.estimators)
      for(bool parallel : {false, true})
      {
        const std::string execution = parallel ? "parallel" : "sequential";
        const std::string key = e.name + " " + execution;
        const double nb = std::isfinite(neighbors) ? neighbors : 40;
        const double work = Budget::work(double(d.points.size()), nb);
        if(!budget.allow(key, work, d.name, ctx.skipped))
        {
          rows.push_back({d.name, d.points.size(), d.radius, neighbors, e.name, execution, nan_value,
                          "skipped: predicted " + format(ctx.skipped.back().predicted) + " s"});
          continue;
        }
        // Best of up to 3 runs while they take less than 10 s in all (2 s with --quick): the
        // machine may be shared, and the best run is the least disturbed one.
        double best = std::numeric_limits<double>::max(), total = 0;
        std::size_t valid = 0;
        const double repeat_below = ctx.options.quick ? 2 : 10;
        for(int rep = 0; rep < 3 && (rep == 0 || total + best < repeat_below); ++rep)
        {
          const auto t0 = std::chrono::steady_clock::now();
          const std::vector<Estimate> est = e.run(d.points, d.radius, parallel);
          const double s = seconds_since(t0);
          best = std::min(best, s);
          total += s;
          if(!std::isfinite(neighbors) && e.name == "ASO")
          {
            double sum = 0;
            for(const Estimate& x : est)
              if(x.is_valid())
              {
                sum += double(x.neighbor_count);
                ++valid;
              }
            neighbors = valid ? sum / double(valid) : nan_value;
          }
        }
        budget.record(key, best, work);
        budget.charge(key, total - best);
        rows.push_back({d.name, d.points.size(), d.radius, neighbors, e.name, execution, best, ""});
        std::cerr << "  " << d.name << " " << key << ": " << format(best) << " s\n";
      }
    for(Timing_row& r : rows)
      if(r.data == d.name)
        r.mean_neighbors = neighbors;
  }
  auto aso_seconds = [&](const Timing_row& r) {
    for(const Timing_row& a : rows)
      if(a.data == r.data && a.execution == r.execution && a.estimator == "ASO-paper")
        return a.seconds;
    return nan_value;
  };
  {
    std::ofstream csv(ctx.path("timings.csv"));
    csv << "data,points,radius,mean_neighbors,estimator,execution,seconds,ratio_to_ASO_paper,note\n";
    for(const Timing_row& r : rows)
      csv << r.data << "," << r.points << "," << format(r.radius, 6) << "," << format(r.mean_neighbors, 6) << ","
          << r.estimator << "," << r.execution << "," << format(r.seconds, 6) << ","
          << format(r.seconds / aso_seconds(r), 4) << "," << r.note << "\n";
  }
  ctx.report.text("Same radius for every estimator: bunny r = " + format(bunny_r) + ", Goursat r = " + format(goursat_r, 4) +
                  " (40 expected neighbours). Seconds for the whole cloud (input to results, neighbour search "
                  "included), best of up to 3 runs while they take under " + format(ctx.options.quick ? 2 : 10) +
                  " s in all; parallel = CGAL::Parallel_tag "
                  "on " + std::to_string(threads) + " hardware threads (the parallel rows are meaningful "
                  "only if no other job used the cores: the last table gives the speed-ups measured).\n");
  Table t;
  t.header = {"data", "execution"};
  for(const Estimator& e : ctx.estimators)
    t.header.push_back(e.name);
  Table ratio = t;
  Table speedup = t;
  auto seconds_of = [&](const std::string& data_name, const std::string& execution, const std::string& estimator) {
    for(const Timing_row& r : rows)
      if(r.data == data_name && r.execution == execution && r.estimator == estimator)
        return r.seconds;
    return nan_value;
  };
  for(const Data& d : data)
  {
    std::vector<std::string> c = {d.name + " (" + format_count(d.points.size()) + ")", "sequential / parallel"};
    for(const Estimator& e : ctx.estimators)
      c.push_back(format(seconds_of(d.name, "sequential", e.name) / seconds_of(d.name, "parallel", e.name), 3));
    speedup.rows.push_back(c);
  }
  for(const Data& d : data)
    for(const char* execution : {"sequential", "parallel"})
    {
      std::vector<std::string> c = {d.name + " (" + format_count(d.points.size()) + ")", execution};
      std::vector<std::string> c2 = c;
      for(const Estimator& e : ctx.estimators)
      {
        std::string cell, cell2;
        for(const Timing_row& r : rows)
          if(r.data == d.name && r.execution == execution && r.estimator == e.name)
          {
            cell = std::isfinite(r.seconds) ? format(r.seconds) : "(" + r.note + ")";
            cell2 = format(r.seconds / aso_seconds(r), 3);
          }
        c.push_back(cell);
        c2.push_back(cell2);
      }
      t.rows.push_back(c);
      ratio.rows.push_back(c2);
    }
  ctx.report.text("Seconds:\n");
  ctx.report.table(t);
  ctx.report.text("Ratio to ASO (same data, same execution):\n");
  ctx.report.table(ratio);
  ctx.report.text("Parallel speed-up (sequential time over parallel time):\n");
  ctx.report.table(speedup);
  ctx.report.text(skipped_text(ctx, "timings"));

  std::ofstream gp(ctx.path("timings.gp"));
  gp << "set terminal pngcairo size 1200,520 font ',10'\nset output 'timings.png'\n";
  gp << "$T << EOD\n";
  for(const Estimator& e : ctx.estimators)
  {
    gp << "\"" << e.name << "\"";
    for(const Data& d : data)
      for(const char* execution : {"sequential", "parallel"})
      {
        double s = nan_value;
        for(const Timing_row& r : rows)
          if(r.data == d.name && r.execution == execution && r.estimator == e.name)
            s = r.seconds;
        gp << " " << (std::isfinite(s) ? format(s, 6) : std::string("NaN"));
      }
    gp << "\n";
  }
  gp << "EOD\n";
  gp << "set multiplot layout 1,2 title 'Timings, whole cloud, same radius for all estimators'\n"
        "set style data histogram\nset style histogram cluster gap 1\nset style fill solid 0.8 border -1\n"
        "set logscale y\nset ylabel 'seconds'\nset grid y\nset xtics rotate by -30\nset key top left\n";
  for(std::size_t i = 0; i < data.size(); ++i)
    gp << "set title " << gp_quote(data[i].name + " (" + format_count(data[i].points.size()) + " points, r = " +
                                   format(data[i].radius) + ")")
       << "\nplot $T using " << 2 + 2 * i << ":xtic(1) title 'sequential' lc rgb '#7570b3', '' using " << 3 + 2 * i
       << " title 'parallel' lc rgb '#1b9e77'\n";
  gp << "unset multiplot\n";
}

// --- experiment 6: the least neighbour count of a valid estimate ---------------------------
//
// Not in the paper. Every estimator by count (neighbor_count(k): exactly k neighbours per
// point on these random positions) with the validity threshold lowered to 1, so that every
// estimate the fit can produce is scored. Primary error: mean |H - H*| (| |H| - |H*| | for the
// unsigned barycenter and PCA-plane estimators; VCM, which gives no H, by its k_max error).
// The minimum of an estimator is the smallest k from which its primary error stays within
// `factor` times its error at k = 40 (the recommended neighbourhood) on every cloud; the
// package's default is that, and never below 6.

struct Count_cloud
{
  std::string name;
  Test_cloud cloud;
};

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

// The smallest k from which the error stays within `factor` times its value at the last k, on
// every cloud where that value was measured (runs skipped by the time budget are NaN: a
// cloud without its last value, or a NaN in the middle, says nothing). 0 if no cloud counts.
// `reference_per_cloud`: whose error at the last k is the reference (the estimator itself,
// or for the ASO the paper's ASO: a better default must not raise its own bar).
std::size_t minimum_by_rule(const std::vector<std::vector<double> >& errors_per_cloud,
                            const std::vector<std::vector<double> >& reference_per_cloud,
                            const std::vector<std::size_t>& ks, double factor)
{
  bool measured = false;
  for(const std::vector<double>& e : reference_per_cloud)
    measured = measured || std::isfinite(e.back());
  if(!measured)
    return 0;
  std::size_t minimum = ks.back();
  for(std::size_t i = ks.size(); i-- > 0;)
  {
    bool ok = true;
    for(std::size_t c = 0; c < errors_per_cloud.size(); ++c)
    {
      const double ref = reference_per_cloud[c].back(), e = errors_per_cloud[c][i];
      ok = ok && (!std::isfinite(ref) || !std::isfinite(e) || e <= factor * ref);
    }
    if(!ok)
      break;
    minimum = ks[i];
  }
  return minimum;
}

void experiment_neighbors(Context& ctx)
{
  ctx.report.section("Experiment 6: error against the neighbour count (the minimum of a valid estimate)");
  const std::vector<std::size_t> ks = ctx.options.quick
    ? std::vector<std::size_t>{3, 4, 6, 8, 12, 20, 40}
    : std::vector<std::size_t>{3, 4, 5, 6, 7, 8, 10, 12, 15, 20, 25, 30, 40};
  std::vector<Count_cloud> clouds;
  clouds.push_back({"Goursat 10K blue noise",
                    scored_everywhere(psc_test::read_xyz(ctx.options.data + "/goursat_010000.xyz"), false)});
  if(!ctx.options.quick)
    clouds.push_back({"Goursat 50K blue noise",
                      scored_everywhere(psc_test::read_xyz(ctx.options.data + "/goursat_050000.xyz"), false)});
  clouds.push_back({"Goursat 10K i.i.d. random",
                    scored_everywhere(goursat::iid_sample(10000, ctx.options.seed * 31 + 5), false)});
  clouds.push_back({"Goursat simulated LiDAR",
                    scored_everywhere(psc_test::read_xyz(ctx.options.data + "/goursat-lidar.xyz"), true)});
  ctx.report.text("Every estimator by count, `neighbor_count(k)` with `min_neighbors(1)` (every estimate the fit "
                  "can produce is scored), exact normals, Goursat surface. Primary error: mean |H - H*| (mean "
                  "| |H| - |H*| | for the unsigned barycenter and PCA-plane estimators, mean k_max error for VCM). "
                  "Clouds: `goursat_010000.xyz` and `goursat_050000.xyz` (the authors' blue-noise samples), 10K "
                  "area-uniform i.i.d. points of the same surface, `goursat-lidar.xyz` (simulated scan lines, "
                  "truth at the radial projection). The minimum of an estimator is the smallest k from which "
                  "its primary error stays within a factor (2 or 3) of its error at k = 40 on every cloud; "
                  "for the ASO (the default variant), of the paper's ASO at k = 40 (row ASO-paper), so that a "
                  "better default does not raise its own bar.\n");

  auto primary = [](const Estimator& e, const Test_cloud& t, const std::vector<Estimate>& est) {
    const bool unsigned_h = e.name == "Barycenter" || e.name == "PCA-plane";
    double sum = 0;
    std::size_t count = 0;
    for(std::size_t s = 0; s < t.scored.size(); ++s)
    {
      const Estimate& x = est[t.scored[s]];
      if(!x.is_valid())
        continue;
      double err;
      if(e.name == "VCM")
        err = std::abs(std::max(std::abs(x.min_curvature), std::abs(x.max_curvature)) -
                       std::max(std::abs(t.truth[s].k_min), std::abs(t.truth[s].k_max)));
      else if(unsigned_h)
        err = std::abs(std::abs(x.mean_curvature) - std::abs(t.truth[s].mean));
      else
        err = std::abs(x.mean_curvature - t.truth[s].mean);
      if(!std::isfinite(err))
        continue;
      sum += err;
      ++count;
    }
    return count ? sum / double(count) : nan_value;
  };

  Budget budget("neighbors", ctx.budget(200, 8));
  std::vector<std::pair<std::string, std::vector<Error_row> > > plot_rows;
  std::vector<Error_row> all_rows;
  // errors[estimator][cloud][k]
  std::map<std::string, std::vector<std::vector<double> > > errors;
  const std::vector<Estimator>& estimators = ctx.estimators;
  for(const Count_cloud& c : clouds)
  {
    std::vector<Error_row> rows;
    for(const Estimator& e : estimators)
    {
      std::vector<double>& curve = (errors[e.name].emplace_back(), errors[e.name].back());
      for(std::size_t k : ks)
      {
        const double work = Budget::work(double(c.cloud.points.size()), double(k));
        const std::string setting = c.name + " k=" + std::to_string(k);
        if(!budget.allow(e.name, work, setting, ctx.skipped))
        {
          curve.push_back(nan_value);
          continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<Estimate> est = e.run_by_count(c.cloud.points, k, 1);
        const double seconds = seconds_since(t0);
        budget.record(e.name, seconds, work);
        Errors err = score(c.cloud, est, e.unsigned_curvatures);
        err.H = primary(e, c.cloud, est);
        curve.push_back(err.H);
        rows.push_back(Error_row{e.name, c.cloud.sample_size, nan_value, "k=" + std::to_string(k), err, seconds,
                                 c.cloud.points.size()});
        all_rows.push_back(rows.back());
        all_rows.back().condition = c.name + " k=" + std::to_string(k);
      }
      std::cerr << "  " << e.name << " on " << c.name << " done\n";
    }
    plot_rows.push_back({c.name, rows});
  }
  write_error_csv(ctx.path("neighbors.csv"), all_rows);

  Table t;
  t.header = {"estimator"};
  for(const Count_cloud& c : clouds)
    t.header.push_back(c.name + ": error at k = 3 / 6 / 10 / 20 / 40");
  t.header.push_back("minimum, factor 2");
  t.header.push_back("minimum, factor 3");
  for(const Estimator& e : estimators)
  {
    std::vector<std::string> row = {e.name};
    for(const std::vector<double>& curve : errors[e.name])
    {
      std::string cell;
      for(std::size_t k : {3, 6, 10, 20, 40})
      {
        const auto it = std::find(ks.begin(), ks.end(), k);
        const double v = it == ks.end() ? nan_value : curve[std::size_t(it - ks.begin())];
        cell += (cell.empty() ? "" : " / ") + (std::isfinite(v) ? format(v, 2) : std::string("-"));
      }
      row.push_back(cell);
    }
    const auto& reference = errors[e.name == "ASO" ? "ASO-paper" : e.name];
    for(double factor : {2.0, 3.0})
    {
      const std::size_t m = minimum_by_rule(errors[e.name], reference, ks, factor);
      row.push_back(m ? std::to_string(m) : std::string("-"));
    }
    t.rows.push_back(row);
  }
  ctx.report.table(t);
  ctx.report.text(skipped_text(ctx, "neighbors"));
  plot_errors_vs_x(ctx, "neighbors", "Error against the neighbour count k (by count, exact normals)", plot_rows,
                   "k (neighbours, query included)",
                   [](const Error_row& row) { return std::stod(row.condition.substr(2)); }, true,
                   {"set xrange [2.8:45]", "set xtics (3, 4, 6, 8, 12, 20, 40)"},
                   "primary error (mean |H - H*|, see text)");
}

// --- experiment 7: the ASO beyond the paper ----------------------------------------------
//
// The variants of estimate_aso_curvatures() (kernel exponent, sample weights, robust
// orientation, normal refinement) against the paper's estimator and the best baselines, on
// the clouds where the paper's ASO is weak: i.i.d. samples, scan lines, a density ramp,
// flipped and noisy normals, position noise. Mean |H - H*| and mean k_max error.
// Fairness: the kernel (1 - d^2/r^2)^P has the width of a Gaussian exp(-P d^2/r^2), so a
// larger P at the same r averages over fewer points; rows "matched width" run P = 3 at
// r sqrt(3/2), whose kernel has the width of P = 2 at r.

struct Variant
{
  std::string name;
  std::function<std::vector<Estimate>(const Cloud&, double)> run;
  double radius_factor = 1;
};

Cloud rotated_normals(const Cloud& c, double degrees, std::uint64_t seed)
{
  // every normal tilted by exactly `degrees`, towards a random tangent direction
  goursat::Random random(seed);
  Cloud out = c;
  for(Oriented_point& p : out)
  {
    const double n[3] = {p.second.x(), p.second.y(), p.second.z()};
    double t1[3], t2[3];
    goursat::tangent_frame(n, t1, t2);
    const double phi = 2 * M_PI * random.uniform(), a = degrees * M_PI / 180;
    const double ct = std::cos(phi), st = std::sin(phi);
    p.second = Vector(std::cos(a) * n[0] + std::sin(a) * (ct * t1[0] + st * t2[0]),
                      std::cos(a) * n[1] + std::sin(a) * (ct * t1[1] + st * t2[1]),
                      std::cos(a) * n[2] + std::sin(a) * (ct * t1[2] + st * t2[2]));
  }
  return out;
}

void experiment_variants(Context& ctx)
{
  ctx.report.section("Experiment 7: the ASO beyond the paper (variants, against PSS and jets)");
  namespace P = CGAL::Point_set_curvatures::parameters;
  const auto maps = CGAL::parameters::point_map(Point_map()).normal_map(Normal_map());
  auto aso_with = [maps](CGAL::Apss_weight_kernel kernel, CGAL::Sample_weights weights, bool robust,
                         std::size_t refinement, bool blend) {
    return [=](const Cloud& c, double r) {
      return CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
        c, r, P::aso_variant(CGAL::Aso_variant::PAPER,
                             P::weight_kernel(kernel, P::sample_weights(weights, P::robust_orientation(
                                                                                    robust, P::normal_refinement(refinement,
                                                                                    P::normal_field_blend(blend, maps)))))));
    };
  };
  typedef CGAL::Apss_weight_kernel W;
  typedef CGAL::Sample_weights S;
  const W P3 = W::SMOOTH_CUBIC;
  const S areas = S::TANGENT_VORONOI_AREA;
  std::vector<Variant> variants = {
    {"ASO, paper", aso_with(W::SMOOTH, S::UNIFORM, false, 0, false)},
    {"ASO, P=3", aso_with(P3, S::UNIFORM, false, 0, false)},
    {"ASO, areas", aso_with(W::SMOOTH, areas, false, 0, false)},
    {"ASO, orientation", aso_with(W::SMOOTH, S::UNIFORM, true, 0, false)},
    {"ASO, normal-field blend", aso_with(W::SMOOTH, S::UNIFORM, false, 0, true)},
    {"ASO, P=3 + areas", aso_with(P3, areas, false, 0, false)},
    {"ASO, P=3 + areas + orientation", aso_with(P3, areas, true, 0, false)},
    {"ASO, P=3 + areas + orientation + blend (ROBUST)", aso_with(P3, areas, true, 0, true)},
    {"ASO, ROBUST at matched width", aso_with(P3, areas, true, 0, true), std::sqrt(1.5)},
    {"ASO, P=4 + areas + orientation + blend", aso_with(W::SMOOTH_QUARTIC, areas, true, 0, true)},
    {"ASO, ROBUST + normal_refinement(1)", aso_with(P3, areas, true, 1, true)},
    {"ASO, ROBUST + normal_refinement(2)", aso_with(P3, areas, true, 2, true)},
    {"ASO, ROBUST at matched width + normal_refinement(1)", aso_with(P3, areas, true, 1, true), std::sqrt(1.5)},
  };
  for(const char* name : {"PSS", "OJets"})
    for(const Estimator& e : ctx.estimators)
      if(e.name == name)
        variants.push_back({e.name, [&e](const Cloud& c, double r) { return e.run(c, r, true); }});

  struct Condition
  {
    std::string name;
    Test_cloud cloud;
    double radius;
  };
  std::vector<Condition> conditions;
  const Cloud g50 = psc_test::read_xyz(ctx.options.data + "/goursat_050000.xyz");
  const Cloud g10 = psc_test::read_xyz(ctx.options.data + "/goursat_010000.xyz");
  conditions.push_back({"Goursat 50K blue noise", scored_everywhere(g50, false), 1.5});
  conditions.push_back(
    {"Goursat 10K i.i.d.", scored_everywhere(goursat::iid_sample(10000, ctx.options.seed * 37 + 1), false), 1.5});
  conditions.push_back({"Goursat LiDAR", scored_everywhere(psc_test::read_xyz(ctx.options.data + "/goursat-lidar.xyz"), true), 1.4});
  {
    // i.i.d. ellipsoid 1 x 0.7 x 0.45 with a density ramp 1:4 along x (rejection sampling)
    const double a = 1, b = 0.7, c = 0.45;
    std::mt19937_64 rng(ctx.options.seed * 41 + 3);
    std::uniform_real_distribution<double> u(0, 1);
    Cloud e;
    for(const Oriented_point& p : psc_test::ellipsoid(ctx.options.quick ? 40000 : 80000, a, b, c, unsigned(ctx.options.seed)))
      if(u(rng) * 4 < 1 + 3 * (p.first.x() / a + 1) / 2)
        e.push_back(p);
    Test_cloud t;
    t.points = e;
    t.sample_size = e.size();
    for(std::size_t i = 0; i < e.size(); ++i)
    {
      t.scored.push_back(std::uint32_t(i));
      t.truth.push_back(psc_test::ellipsoid_truth(e[i].first, a, b, c));
    }
    // about 58 neighbours on average
    double area = 0;
    {
      const double pp = 1.6075, ap = std::pow(a, pp), bp = std::pow(b, pp), cp = std::pow(c, pp);
      area = 4 * M_PI * std::pow((ap * bp + ap * cp + bp * cp) / 3, 1 / pp);
    }
    conditions.push_back({"ellipsoid i.i.d., ramp 1:4", t, std::sqrt(58.0 * area / (M_PI * double(e.size())))});
  }
  {
    goursat::Random random(ctx.options.seed * 43 + 7);
    Cloud flipped = g50;
    for(Oriented_point& p : flipped)
      if(random.uniform() < 0.3)
        p.second = -p.second;
    Test_cloud t = scored_everywhere(g50, false);
    t.points = flipped;
    conditions.push_back({"Goursat 50K, 30% normals flipped", t, 1.5});
  }
  {
    Test_cloud t = scored_everywhere(g50, false);
    t.points = rotated_normals(g50, 30, ctx.options.seed * 47 + 9);
    conditions.push_back({"Goursat 50K, normals rotated 30 deg", t, 1.5});
  }
  {
    goursat::Random random(ctx.options.seed * 53 + 11);
    Test_cloud t = scored_everywhere(g50, false);
    for(Oriented_point& p : t.points)
      p.first = Point(p.first.x() + 0.2 * random.gaussian(), p.first.y() + 0.2 * random.gaussian(),
                      p.first.z() + 0.2 * random.gaussian());
    conditions.push_back({"Goursat 50K, position noise sigma 0.2", t, 1.5});
  }
  if(ctx.options.quick)
    conditions.resize(3);  // CI: the three clean clouds

  ctx.report.text("Mean |H - H*| (x 1e-3) and, in parentheses, mean k_max error (x 1e-3), exact truth, "
                  "Parallel_tag. Variants are estimate_aso_curvatures() with aso_variant(PAPER) and the "
                  "options named; ROBUST is the package's default. 'matched width': P = 3 at r sqrt(3/2), "
                  "the kernel width of P = 2 at r. Radii: Goursat 1.5 (LiDAR 1.4), ellipsoid for 58 "
                  "neighbours on average.\n");
  Table t;
  t.header = {"variant"};
  for(const Condition& c : conditions)
    t.header.push_back(c.name + " (r = " + format(c.radius, 3) + ")");
  std::vector<Error_row> rows;
  Budget budget("variants", ctx.budget(120, 20));
  for(const Variant& v : variants)
  {
    std::vector<std::string> row = {v.name};
    for(const Condition& c : conditions)
    {
      const double r = c.radius * v.radius_factor;
      const double work = Budget::work(double(c.cloud.points.size()), 60);
      if(!budget.allow(v.name, work, c.name, ctx.skipped))
      {
        row.push_back("");
        continue;
      }
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Estimate> est = v.run(c.cloud.points, r);
      const double seconds = seconds_since(t0);
      budget.record(v.name, seconds, work);
      double h = 0, kmax = 0;
      std::size_t count = 0;
      for(std::size_t s = 0; s < c.cloud.scored.size(); ++s)
      {
        const Estimate& e = est[c.cloud.scored[s]];
        if(!e.is_valid())
          continue;
        h += std::abs(e.mean_curvature - c.cloud.truth[s].mean);
        kmax += std::isfinite(e.max_curvature) ? std::abs(e.max_curvature - c.cloud.truth[s].k_max) : 0;
        ++count;
      }
      const double valid = double(count) / double(c.cloud.scored.size());
      std::ostringstream cell;
      cell << format(1e3 * h / double(count), 3) << " (" << format(1e3 * kmax / double(count), 3) << ")";
      if(valid < 0.999)
        cell << ", " << format_fixed(100 * valid, 1) << "% valid";
      row.push_back(cell.str());
      Errors err;
      err.H = h / double(count);
      err.kmax = kmax / double(count);
      err.valid_fraction = valid;
      rows.push_back(Error_row{v.name, c.cloud.sample_size, r, c.name, err, seconds, c.cloud.points.size()});
      std::cerr << "  " << v.name << " on " << c.name << ": " << format(seconds) << " s\n";
    }
    t.rows.push_back(row);
  }
  write_error_csv(ctx.path("variants.csv"), rows);
  ctx.report.table(t);
  ctx.report.text(skipped_text(ctx, "variants"));
}

// --- experiment 5 -----------------------------------------------------------------------

double quantile_abs(std::vector<double> v, double q)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if(v.empty())
    return 1;
  for(double& x : v)
    x = std::abs(x);
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

double mean_nearest_distance(const Cloud& c)
{
  std::vector<double> xyz;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for(const Oriented_point& p : c)
    for(int i = 0; i < 3; ++i)
    {
      xyz.push_back(p.first[i]);
      lo[i] = std::min(lo[i], p.first[i]);
      hi[i] = std::max(hi[i], p.first[i]);
    }
  // cells of about 4 points on a surface filling the box
  double area = (hi[0] - lo[0]) * (hi[1] - lo[1]) + (hi[1] - lo[1]) * (hi[2] - lo[2]) + (hi[0] - lo[0]) * (hi[2] - lo[2]);
  const double cell = 2 * std::sqrt(2 * area / double(c.size()));
  const goursat::Hash_grid grid(xyz, cell);
  double sum = 0;
  std::size_t count = 0;
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    double best = cell * cell;
    grid.for_each_in_ball(&xyz[3 * i], cell, [&](std::uint32_t j, double d2) {
      if(j != i)
        best = std::min(best, d2);
    });
    if(best < cell * cell)
    {
      sum += std::sqrt(best);
      ++count;
    }
  }
  return count ? sum / double(count) : cell;
}

// Splat radius of every point: 0.8 x the distance to its 6th nearest neighbour, which
// closes the gaps between the scan lines of anisotropic clouds (bunny, LiDAR) that a
// radius from the nearest neighbour leaves open.
std::vector<double> splat_radii(const Cloud& c)
{
  const double cell = 4 * mean_nearest_distance(c);
  std::vector<double> xyz;
  for(const Oriented_point& p : c)
    for(int i = 0; i < 3; ++i)
      xyz.push_back(p.first[i]);
  const goursat::Hash_grid grid(xyz, cell);
  std::vector<double> radii(c.size());
  std::vector<double> d2s;
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    d2s.clear();
    grid.for_each_in_ball(&xyz[3 * i], cell, [&](std::uint32_t j, double d2) {
      if(j != i)
        d2s.push_back(d2);
    });
    const std::size_t k = 6;
    double d = cell;
    if(d2s.size() >= k)
    {
      std::nth_element(d2s.begin(), d2s.begin() + (k - 1), d2s.end());
      d = std::sqrt(d2s[k - 1]);
    }
    radii[i] = 0.8 * d;
  }
  return radii;
}

// Renders panels (one per quantity) and writes a gnuplot script assembling them.
struct Panel
{
  std::string title;
  std::vector<double> values;
};

void render_figure(Context& ctx, const std::string& name, const std::string& title, const Cloud& cloud,
                   const std::vector<std::vector<Panel> >& rows, const render::View& view, double range)
{
  const int size = 400;
  const std::vector<double> radii = splat_radii(cloud);
  std::vector<std::vector<std::string> > files(rows.size());
  for(std::size_t row = 0; row < rows.size(); ++row)
    for(std::size_t col = 0; col < rows[row].size(); ++col)
    {
      std::vector<render::Splat> splats(cloud.size());
      for(std::size_t i = 0; i < cloud.size(); ++i)
      {
        const Oriented_point& p = cloud[i];
        splats[i].position = {{p.first.x(), p.first.y(), p.first.z()}};
        splats[i].normal = {{p.second.x(), p.second.y(), p.second.z()}};
        splats[i].color = render::diverging_color(rows[row][col].values[i], range);
        splats[i].radius = radii[i];
      }
      const std::string file = "panel_" + name + "_" + std::to_string(row) + std::to_string(col) + ".png";
      render::render_splats(splats, view, size, size).write_png(ctx.path(file));
      files[row].push_back(file);
    }
  const std::size_t columns = rows.front().size();
  std::ofstream gp(ctx.path(name + ".gp"));
  const int w = int(columns) * 330 + 100, h = int(rows.size()) * 350 + 40;
  gp << "set terminal pngcairo size " << w << "," << h << " font ',11'\nset output '" << name << ".png'\n";
  gp << render::diverging_palette_gnuplot() << "\nset cbrange [" << -range << ":" << range << "]\n";
  gp << "unset key\nunset border\nunset xtics\nunset ytics\nset size ratio -1\n";
  gp << "set multiplot title " << gp_quote(title) << " font ',13'\n";
  const double cw = 330.0 / w, ch = 350.0 / h, top = 1 - 40.0 / h;
  for(std::size_t row = 0; row < rows.size(); ++row)
    for(std::size_t col = 0; col < columns; ++col)
    {
      gp << "set origin " << col * cw << "," << top - (row + 1) * ch << "\nset size " << cw << "," << ch << "\n";
      gp << "set title " << gp_quote(rows[row][col].title) << "\n";
      gp << "unset colorbox\n";
      gp << "plot '" << files[row][col] << "' binary filetype=png with rgbimage\n";
    }
  // colour bar: a palette plot of nothing, only its colorbox
  gp << "set origin " << columns * cw << "," << top - rows.size() * ch << "\nset size " << 100.0 / w << ","
     << rows.size() * ch << "\n";
  gp << "unset title\nset colorbox user origin " << (columns * cw + 0.01) << "," << (top - rows.size() * ch + 0.1 * ch)
     << " size 0.015," << (rows.size() * ch - 0.2 * ch) << "\nset cbtics font ',10'\nset cblabel 'curvature (1/length)'\n";
  gp << "unset size\nset size " << 100.0 / w << "," << rows.size() * ch << "\n";
  gp << "plot [0:1][0:1] '+' using (NaN):(NaN):(0) with points palette\n";
  gp << "unset multiplot\n";
}

void experiment_pictures(Context& ctx)
{
  ctx.report.section("Experiment 5: real data (Figures 1 and 7)");
  const Estimator& aso = find_estimator(ctx.estimators, "ASO");

  // Bunny
  {
    const Cloud bunny = psc_test::read_ascii_ply_xyz_normals(ctx.options.data + "/bunny.ply");
    const double r = 0.005;
    const std::vector<Estimate> est = aso.run(bunny, r, true);
    std::vector<Panel> panels(3);
    panels[0].title = "ASO mean curvature H";
    panels[1].title = "ASO k_{min}";
    panels[2].title = "ASO k_{max}";
    std::size_t invalid = 0;
    for(const Estimate& e : est)
    {
      panels[0].values.push_back(e.mean_curvature);
      panels[1].values.push_back(e.min_curvature);
      panels[2].values.push_back(e.max_curvature);
      invalid += e.is_valid() ? 0 : 1;
    }
    std::vector<double> pooled = panels[1].values;
    pooled.insert(pooled.end(), panels[2].values.begin(), panels[2].values.end());
    const double range = quantile_abs(pooled, 0.95);
    render_figure(ctx, "curvatures_bunny", "Stanford bunny (" + format_count(bunny.size()) + " points), ASO, r = " + format(r),
                  bunny, {panels}, render::View::looking_from({{0, 0, 1}}, {{0, 1, 0}}), range);
    ctx.report.text("- `curvatures_bunny.png`: bunny, ASO at r = " + format(r) + ", " + std::to_string(invalid) +
                    " invalid estimates (dark green); colour range ±" + format(range) +
                    " (95% quantile of |k|), blue negative, red positive.");
  }

  // Goursat LiDAR: estimates next to the analytic truth, and errors of every estimator.
  {
    const Cloud lidar = psc_test::read_xyz(ctx.options.data + "/goursat-lidar.xyz");
    const double r = 1.0;
    std::vector<Panel> est_panels(3), truth_panels(3);
    est_panels[0].title = "ASO H";
    est_panels[1].title = "ASO k_{min}";
    est_panels[2].title = "ASO k_{max}";
    truth_panels[0].title = "exact H";
    truth_panels[1].title = "exact k_{min}";
    truth_panels[2].title = "exact k_{max}";
    Test_cloud t;
    t.points = lidar;
    t.sample_size = lidar.size();
    for(std::size_t i = 0; i < lidar.size(); ++i)
    {
      // truth at the radial projection of the (noisy) point onto the surface
      const double v[3] = {lidar[i].first.x(), lidar[i].first.y(), lidar[i].first.z()};
      double p[3];
      goursat::project_radially(v, p);
      t.scored.push_back(std::uint32_t(i));
      t.truth.push_back(psc_test::goursat_truth(Point(p[0], p[1], p[2])));
      truth_panels[0].values.push_back(t.truth.back().mean);
      truth_panels[1].values.push_back(t.truth.back().k_min);
      truth_panels[2].values.push_back(t.truth.back().k_max);
    }
    const std::vector<Estimate> est = aso.run(lidar, r, true);
    for(const Estimate& e : est)
    {
      est_panels[0].values.push_back(e.mean_curvature);
      est_panels[1].values.push_back(e.min_curvature);
      est_panels[2].values.push_back(e.max_curvature);
    }
    std::vector<double> pooled = truth_panels[1].values;
    pooled.insert(pooled.end(), truth_panels[2].values.begin(), truth_panels[2].values.end());
    const double range = quantile_abs(pooled, 0.95);
    render_figure(ctx, "curvatures_goursat_lidar",
                  "Goursat surface, simulated LiDAR (" + std::to_string(lidar.size()) + " points), ASO r = " + format(r) +
                    " (top) and exact values (bottom)",
                  lidar, {est_panels, truth_panels}, render::View::looking_from({{0, 0, 1}}, {{0, 1, 0}}), range);
    ctx.report.text("- `curvatures_goursat_lidar.png`: simulated LiDAR scan of the Goursat surface (top face, anisotropic, "
                    "depth noise), ASO at r = " + format(r) + " above the exact values; colour range ±" + format(range) + ".\n");

    std::vector<Error_row> rows;
    for(const Estimator& e : ctx.estimators)
    {
      const auto t0 = std::chrono::steady_clock::now();
      const std::vector<Estimate> x = e.run(lidar, r, true);
      rows.push_back(Error_row{e.name, lidar.size(), r, "lidar", score(t, x, e.unsigned_curvatures), seconds_since(t0),
                               lidar.size()});
    }
    write_error_csv(ctx.path("lidar.csv"), rows);
    ctx.report.text("Errors on the LiDAR cloud against the analytic values at the radial projection of each point "
                    "(points near the scan border have one-sided neighbourhoods):\n");
    ctx.report.table(error_table(rows, false, false));
  }
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse_options(argc, argv);
    Context ctx(options);
    Budget::start() = std::chrono::steady_clock::now();
    Budget::deadline() = options.quick ? 100 : 960;
    const auto t0 = std::chrono::steady_clock::now();
    std::string names;
    for(const Estimator& e : ctx.estimators)
      names += (names.empty() ? "" : ", ") + e.name;
    ctx.report.add("# Paper experiments (Lejemble et al. 2021, Section 6), measured here\n\n");
    ctx.report.text(std::string("Mode: ") + (options.quick ? "--quick" : "full") + ", seed " +
                    std::to_string(options.seed) + ", " + std::to_string(std::thread::hardware_concurrency()) +
                    " hardware threads. Estimators found: " + names + ".");
    if(options.run("sampler"))
      experiment_sampler(ctx);
    if(options.run("convergence"))
      experiment_convergence(ctx);
    if(options.run("noise_position"))
      experiment_noise_position(ctx);
    if(options.run("noise_normals"))
      experiment_noise_normals(ctx);
    if(options.run("neighbors"))
      experiment_neighbors(ctx);
    if(options.run("variants"))
      experiment_variants(ctx);
    if(options.run("timings"))
      experiment_timings(ctx);
    if(options.run("pictures"))
      experiment_pictures(ctx);

    ctx.report.section("Goursat samples used");
    Table t;
    t.header = {"N", "Lloyd iterations", "sampling seconds", "max residual abs(F)/norm(grad F), over the diagonal"};
    for(const auto& s : ctx.samples.all())
      t.rows.push_back({format_count(s.first), std::to_string(goursat::Sampling_options().lloyd_iterations),
                        format(s.second.seconds), format(s.second.max_residual)});
    ctx.report.table(t);
    ctx.report.text("Total time of the program: " + format(seconds_since(t0)) + " s.");
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "paper_experiments: " << e.what() << "\n";
    return 1;
  }
}
