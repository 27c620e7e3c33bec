// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The automatic scale (named parameter automatic_scale): for each point, the neighbour count
// among a ladder k0, 2 k0, 4 k0, ... up to the largest one, chosen by the rule of the
// intersection of confidence intervals (Goldenshluger and Nemirovski 1997; Katkovnik 1999),
// a Lepski-type rule.
//
// The driver hands the estimator the neighbourhood of the largest count. On each rung j, the
// k_j nearest of it (with the driver's rule for ties: every point closer than
// (1 + 2^-20) d_{k_j}; taken from the cloud's positions as the driver takes them, so that a
// rung is bit for bit the neighbourhood the driver gives for its count k_j) are fitted with the
// weighted quadric of positions of quadric_fit.h (without its anisotropy penalty), which gives
// the statistic the rungs are compared by (the mean curvature H_j for curvatures; for normals,
// the normal's two components in the first rung's tangent frame) and, by the sandwich formula
// of weighted least squares, its variance per unit of noise variance.
//
// The noise. A fit's residual variance is the position noise's plus the surface's own
// third-order terms, which grow as r⁶; the first two rungs separate the two. Where the noise
// is less than half of the first rung's residual variance (smooth surfaces without noise),
// the first rung is kept: its estimate is the one of the fixed count k. A first test, on the
// first rung alone (its nearest half against all of it), keeps it where the noise is clearly
// absent, and a second one where a cubic leaves little of the quadric's residuals (they are the
// surface's third-order terms), so that most points of a clean cloud never need the
// neighbourhood of 2 k.
//
// Rungs along one line. A rung whose neighbourhood, weighted by the fits' kernel, spreads along
// one line (weighted_line_spread_ratio of quadric_fit.h: a scan line through the query, the next
// ones at the kernel's rim) tells little across the line, and under noise its fit is poor: it is
// passed over, the first rung that spreads in two directions being the smallest (the top rung of
// a pass is kept, so that a pass always ends with a choice, and so is the last line rung where the
// pass's top rung cannot be fitted: below it, a rung that cannot be fitted is passed over too; in a
// pass that is not the last, with automatic_scale above 640, such a point does not climb on), and
// the first pass sends such a
// point on, as it does where the nearest half of the first rung is such a line (its residuals
// tell nothing of the noise across the line) and the cubic of the whole first rung does not keep
// it (gate_cubic_least_pivot). (The normals' first pass sends a point on where the
// weights leave one line and the points do not.) For the mean curvature, a rung whose fit can
// hardly tell it (two scan lines: ill_conditioned_curvature_factor) counts as such a line rung,
// the nearest half of the first rung too; above a rung already chosen, one ends the climb, unless
// the rung chosen is the first kept and was itself that ill-conditioned, kept only because a
// quadric nearly interpolated its few lines (residuals too small for the error's bound), and the
// line rung is below the pass's top: where, with the line rung's residuals for the noise, its
// error exceeds the bound, it is passed over too. Nor does the first pass keep a first rung
// whose error, its own residuals taken for the noise, is beyond that bound; and where such a first
// rung's interval misses the second rung's, the first is given up and the intervals start again
// from the second (a first rung is trusted as unbiased only where it can tell the curvature).
// The normals likewise: the first pass does not keep a first rung whose slope's error, its own
// residuals taken for the noise, is beyond that of a clean rung (clean_normal_slope_error); a
// first rung that can hardly tell the slope (ill_conditioned_normal_factor) is given up where
// it reads as noiseless or its interval misses the second's, if the second and third rungs say
// the data are noisy (a clean scan line's first rung is its best one).
//
// The rule. Each rung's interval is its statistic plus or minus kappa standard errors; the
// rule keeps the largest rung whose interval meets those of every smaller rung. Under noise
// the standard error falls as the scale grows (about k^-1.5) and the rungs agree until the
// surface's variation (bias) shows.
//
// The estimates at the chosen rungs, the passes and the curvatures' choices made by the
// normals' passes: automatic_scale_estimation.h.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_AUTOMATIC_SCALE_H

#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/internal/local_estimate.h>
#include <CGAL/Point_set_curvatures/internal/pca_plane.h>
#include <CGAL/Point_set_curvatures/internal/quadric_fit.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

// The half-width of the confidence intervals, in standard errors (see the header comment).
constexpr double automatic_scale_kappa = 3.0;
// Above the first rung the APSS sphere's mean curvature replaces the wrapped estimator's only
// where the two differ by at most this many standard errors (those of the rung's quadric's H),
// unless the wrapped estimator's H is poorly told: the neighbours' normals, which it
// differentiates, agree less than automatic_scale_sphere_coherence (its normal_coherence), or
// the standard error of H times the rung's radius exceeds automatic_scale_sphere_told (noise a
// large share of the neighbourhood; at most 0.019 on the simulated scans, 0.10 on a real ground
// point among vegetation). See automatic_scale_estimation.h.
constexpr double automatic_scale_sphere_agreement = 4.0;
// Where the rule climbed for noise, the sphere is not taken and the wrapped estimator's mean
// curvature lies more than this many standard errors from the rung's quadric's, the curvatures
// are the quadric's (automatic_scale_estimation.h). On the simulated scans (benchmark/README.md,
// section 8) the points beyond it are the first and last profiles of a mobile scan, one-sided
// neighbourhoods where the ASO reads H = -0.57 (estimated normals; clean scans with exact
// normals too) where the truth is 0.003 and the quadric says 0.005: 1-2% of its points, most of
// its error. Elsewhere the ASO lies within 15-22 standard errors of the quadric (99th
// percentiles) and is the better estimate; at 20 points of other patterns moved too (wobbly
// lines 8:1 under noise 0.3: +1.3%), at 40 fewer of the mobile scan's edge (3.9e-3 against
// 3.3e-3 at 30).
constexpr double automatic_scale_quadric_agreement = 30.0;
constexpr double automatic_scale_sphere_coherence = 0.95;
constexpr double automatic_scale_sphere_told = 0.05;
// The least share of the smallest scale's residual variance that must be noise for a larger
// scale to be considered (see the header comment).
constexpr double automatic_scale_noise_share = 0.5;
// The first pass's test (Scale_ladder::gate, its nearest half against the whole first rung) keeps
// the smallest rung where the noise it sees is less than this share of the rung's residual
// variance: the fit of half the rung (about 10 effective points for 20) estimates the noise poorly,
// so only its clear absence is trusted (chosen on the simulated scans: benchmark/README.md,
// "Automatic scale"); the second test (automatic_scale_gate_cubic_share) keeps it too.
constexpr double automatic_scale_gate_share = 0.05;
// How much larger the neighbourhood of each pass after the first is than the previous one's
// (a power of 2: the rungs double). A point that stops on rung j of the whole ladder has to see
// rung j + 1 first, so it pays the search of every pass up to the one holding rung j + 1: with
// 2, a point kept at 320 or 640 searched 40 + 80 + 160 + 320 + 640 neighbours and fitted the
// lower rungs in every pass; with 4, 40 + 160 + 640 (the tool's default on data/real/
// sample_c.las, 78% of its points at 640: 6.8 s against 5.1 s, the same choices, estimates
// equal to 1e-15); with 16, 40 + 640, one pass of 640 after the first for the points its test
// sends on. Measured again once the fits and the search had become cheaper (2026-11-29; the
// tool's default, 2 threads, one pair of runs each): 16 against 4, sample_c 1.14 s against
// 1.30 s, warsaw_small 0.23 against 0.25, hexbin-crop (9% end at 40, 42% at 80 or 160) 2.50
// against 2.74; on clean terrains within the run-to-run noise (about 10%): a 1M terrain with
// normals 11.7 against 12.4, without 22.4 against 22.9, a 200K terrain 4.4 against 4.2 (97%
// at 40). The same choices, estimates equal to 1e-15. (With the fits of the time, 16 made a
// clean terrain 2.2 times as long.)
constexpr std::size_t automatic_scale_pass_growth = 16;
// The first pass's second test (Scale_ladder::gate): the first rung is kept where a cubic fitted
// to it, with the quadric's weights in the quadric's frame, leaves less than this share of the
// quadric's residual variance (the third-order terms, not noise, made them), provided the cubic's
// monomials are well told apart (relative pivots of at least gate_cubic_least_pivot: over two or
// three scan lines a cubic follows the noise across them, and its residuals would read as no
// noise). A point climbs only where both tests see noise; the cubic is fitted only where the first
// test can be (half the smallest rung at least gate_least_half). On clean random terrains of
// benchmark/large_cloud (1M points; a 200K crop) the first test alone sends 40% of the points on
// for the curvatures and 12% for the normals, both tests 6.6% and 2.6%; on the clean scans of
// scan_experiments, for the curvatures, the torus 73% -> 4.5%, merged scans 59% -> 1.8%, lines
// 2:1 95% -> 2.8%, terrestrial 60% -> 1.2%, zigzag3 63% -> 38%, a mobile profiler 88% -> 75%
// (where line rungs route points on, unchanged: airborne 5:1 23%, lines 10:1 99%); the same
// estimates (to three digits) under range noise of 0.1 and 0.3 spacings, and a noise of 0.01
// spacings on the terrain still sends 98% on (benchmark/README.md, "Automatic scale").
constexpr double automatic_scale_gate_cubic_share = 0.2;
// The least relative pivot of the second test's cubic (Cubic_height_fit::residual_variance()):
// about 0.1-0.2 for the weakest cubic monomial where the points spread over a disc, near 0 where
// they lie on two or three lines. At 0.01 noisy lines 10 times farther apart than their spacing
// kept a few points too many (0.0116 against 0.0115); at 1e-10, 33% of them (0.0140), and the
// test "a rung of two noisy scan lines is passed over" fails.
constexpr double gate_cubic_least_pivot = 0.03;

// The same share for the normals' test in a shared frame (Scale_ladder::choose_in_shared_frame()):
// chosen on the clean and noisy scans and the real tiles of benchmark/README.md, "Automatic scale"
// (without the cubic's test: at 0.05 it sends 25% of a clean terrain's points on, at 0.15 10%, at
// 0.2 7%, with the same accuracy under noise).
constexpr double automatic_scale_shared_frame_gate_share = 0.15;
// The least size of the half of the smallest rung that the first pass's test fits (a quadric
// has 6 coefficients); below it neither test runs and every point goes on to the next pass.
constexpr std::size_t gate_least_half = 12;

// A rung whose mean curvature its fit can hardly tell is passed over as a rung along one line
// is: its variance factor of H per unit of noise variance, times its point count (scale-free:
// 100 to 700 where the points spread in two directions), above
// ill_conditioned_curvature_factor, and its standard error, with the rung's residual variance
// taken for noise, above ill_conditioned_curvature_error / r (an uncertainty of the size of a
// curvature whose radius is ten times the rung's). That is a rung of two scan lines, at a
// scan's edge or where lines lie far apart: a quadric through two noisy lines bends across them
// as their noise says, the nearer half of the rung (one line and a few points of the next)
// leaves residuals smaller still, and the comparison reads as no noise at all, keeping an
// estimate in error by several times the surface's curvature (benchmark/scan_experiments, range
// noise 0.3 spacings: `mobile` 0.0170 -> 0.0075, `airborne10` 0.0295 -> 0.0140; the factor
// alone, without the error's bound, also moved clean scans' edges to larger one-sided rungs,
// `wobbly8` 0.00198 -> 0.00211). The bound reads the rung's own residuals, which a quadric
// through one or two noisy lines makes small: at the edge of a noisy mobile scan (test_core) a
// first rung kept that way gave H 2.83 (truth 0.03); where the rung above it is a line rung, its
// residuals are taken for the noise too (Scale_ladder::choose()), and the point climbs (H 0.24
// off there; on the clean scans of benchmark/scan_experiments 14 edge points of `airborne10` and
// `mobile` climb too, `airborne10` 3.07e-3 -> 3.09e-3; its noisy scans and the real tiles do not
// change).
constexpr double ill_conditioned_curvature_factor = 1e4;
constexpr double ill_conditioned_curvature_error = 0.1;

// The normals' counterparts. A first rung whose slope its fit can hardly tell: the larger of
// the two slopes' variance factors per unit of noise variance (in the rung's units), times its
// point count, above ill_conditioned_normal_factor (4 to 30 where the points spread in two
// directions; one or two scan lines, or one line whose range noise lies in the plane of the
// line and the beams, above 100). Under noise a quadric through them follows the noise across the
// lines: its residuals read as no noise, or its interval misses the next rung's, and the ladder
// kept it with normals 5 to 15 degrees off (benchmark/scan_experiments `rings` at range noise 0.3
// spacings: 4,961 points kept at 40 that way by the second pass, median error 12.6 degrees).
// Such a rung is given up in those two cases (Scale_ladder::choose()) where the next two rungs
// say that the data are noisy (their residuals do not grow as r⁶: separated_noise() leaves at
// least automatic_scale_noise_share of the next rung's residual variance to noise); on clean
// scan lines such a rung is the best one (clean `airborne10` without that look ahead: the
// normals of the 453 points concerned 1.1 -> 3.7 degrees, the mean of all 0.36 -> 0.73). And the first pass's test does not keep a first rung as clean where
// the standard error of its slope, its own residuals taken for the noise, exceeds
// clean_normal_slope_error (0.3 degrees): a clean rung's is below 0.07 degrees at the 99th
// percentile on the fourteen simulated scans, noisy `rings` gate rungs above 1 degree erred by 25.
constexpr double ill_conditioned_normal_factor = 100;
constexpr double clean_normal_slope_error = 0.0052360;  // tan(0.3 degrees)

// How much faster than r⁶ the residual variance may grow from the smaller fit to the larger one
// for separated_noise() to tell the noise (see there).
constexpr double separated_noise_misfit_factor = 8;

// The noise variance from the fits of a point's nearest neighbours at two radii
// (r_small < r_large; residual variances in input units): the residuals are the noise plus
// the surface's third-order terms, which grow as r⁶, so the two separate them. NaN where the
// radii are too close for the growth to tell (within 0.17%), and where the larger residual
// exceeds separated_noise_misfit_factor times the growth of the smaller: the smaller fit then
// followed its points more closely than the noise allows (a quadric through the nearest points
// of one or two noisy scan lines nearly interpolates them), and the model that separates the
// two does not hold; the difference would read as no noise at all. (With 2, the noisy airborne
// lines 10 times farther apart than the spacing along them, benchmark/scan_experiments
// `airborne10` at range noise 0.3 spacings: the normals' mean error 3.25 -> 1.73 degrees, but
// 5.5% of a clean random terrain's points climbed past the first rung instead of 2.6%; with 4
// and 8 the same normals, and 3.1% and 2.7% climbed.)
inline double separated_noise(double residual_small, double radius_small, double residual_large, double radius_large)
{
  const double growth = std::pow(radius_large / radius_small, 6);
  if(!(growth > 1.01) || residual_large > separated_noise_misfit_factor * growth * residual_small)
    return std::numeric_limits<double>::quiet_NaN();
  return std::clamp((growth * residual_small - residual_large) / (growth - 1), 0.0, residual_small);
}

// The offsets of a neighbourhood's points from the query (p - x) and their squared distances, in
// its order. In input units (`unit` 1) from the cloud's positions where the driver gave them
// (Neighborhood::position), with the driver's arithmetic, so that a rung taken from them
// (Sub_neighborhood::take()) is bit for bit the neighbourhood the driver gives for the rung's
// count: the same points, in the same order, with the same scaled positions and radius. Else (a
// neighbourhood built by hand, or offsets whose squares overflow a double) its scaled positions
// (`unit` its radius). `limit`: the neighbourhood's radius in the offsets' unit.
struct Neighbor_offsets
{
  std::vector<double> x, y, z, d2;
  double unit = 1, limit = 1;

  void assign(const Neighborhood& whole)
  {
    const std::size_t n = whole.size;
    for(auto* v : {&x, &y, &z, &d2})
      v->resize(n);
    bool finite = whole.position && whole.index && std::isfinite(whole.radius);
    if(finite)
    {
      for(std::size_t i = 0; i < n; ++i)
      {
        const double* p = whole.position + 3 * std::size_t(whole.index[i]);
        x[i] = p[0] - whole.center[0];
        y[i] = p[1] - whole.center[1];
        z[i] = p[2] - whole.center[2];
        d2[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
      }
      for(std::size_t i = 0; i < n; ++i)
        finite = finite && std::isfinite(d2[i]);
    }
    unit = finite ? 1.0 : whole.radius;
    limit = finite ? whole.radius : 1.0;
    if(!finite)
      for(std::size_t i = 0; i < n; ++i)
      {
        x[i] = whole.qx[i];
        y[i] = whole.qy[i];
        z[i] = whole.qz[i];
        d2[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
      }
  }
};

// A neighbourhood of the first points of another, in its own scaled frame: the positions for
// the rungs' fits, the other fields only for the neighbourhood that an estimator reads.
struct Sub_neighborhood
{
  std::vector<double> qx, qy, qz, nx, ny, nz, weight;
  std::vector<std::uint32_t> index;
  std::vector<std::uint32_t> taken;  // the positions in `whole` of the points of take()
  std::vector<double> frame;         // the fit's frame cache (Quadric_fit::frame_cache)
  Neighborhood nb;

  // The points of `whole` closer than `radius` (the unit of `offsets`, whole's, assigned), in
  // whole's order, their positions scaled by 1 / radius as the driver scales a neighbourhood of
  // that radius; nb's other per-point fields are null until take_attributes(). The points inside
  // are listed without branches (every index written at the place of the next one inside, which
  // overwrites it where it lies outside), then only they are copied.
  void take(const Neighborhood& whole, double radius, const Neighbor_offsets& offsets)
  {
    const double r2 = radius * radius, inverse = 1.0 / radius;
    const double* d2 = offsets.d2.data();
    taken.resize(whole.size);
    std::size_t n = 0;  // (at most i: the writes stay within whole.size)
    for(std::size_t i = 0; i < whole.size; ++i)
    {
      taken[n] = static_cast<std::uint32_t>(i);
      n += d2[i] < r2 ? 1 : 0;
    }
    for(auto* v : {&qx, &qy, &qz})
      v->resize(n);
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::uint32_t i = taken[j];
      qx[j] = offsets.x[i] * inverse;
      qy[j] = offsets.y[i] * inverse;
      qz[j] = offsets.z[i] * inverse;
    }
    taken.resize(n);
    nb = whole;
    nb.size = n;
    nb.qx = qx.data();
    nb.qy = qy.data();
    nb.qz = qz.data();
    nb.nx = nb.ny = nb.nz = nullptr;
    nb.sample_weight = nullptr;
    nb.index = nullptr;
    nb.plain_quadric = nullptr;
    nb.radius = offsets.unit == 1 ? radius : offsets.unit * radius;
  }

  // After take(whole, radius): the normals, sample weights and indices of the same points.
  void take_attributes(const Neighborhood& whole)
  {
    const std::size_t n = taken.size();
    for(auto* v : {&nx, &ny, &nz})
      v->resize(n);
    for(std::size_t j = 0; j < n; ++j)
    {
      nx[j] = whole.nx[taken[j]];
      ny[j] = whole.ny[taken[j]];
      nz[j] = whole.nz[taken[j]];
    }
    weight.clear();
    if(whole.sample_weight)
      for(std::uint32_t i : taken)
        weight.push_back(whole.sample_weight[i]);
    index.clear();
    if(whole.index)
      for(std::uint32_t i : taken)
        index.push_back(whole.index[i]);
    nb.nx = nx.data();
    nb.ny = ny.data();
    nb.nz = nz.data();
    nb.sample_weight = whole.sample_weight ? weight.data() : nullptr;
    nb.index = whole.index ? index.data() : nullptr;
  }
};

// The k-th smallest squared distance of a neighbourhood's points to the query for the rungs'
// counts k: the values, times `scale` (below 1 but for rounding), bucketed once into equal
// intervals of [0, 1) by a counting sort, then each k-th selected within its bucket alone (about
// 10 values of 640 on a surface, where a selection among all the values above the previous rung's
// for each rung was 10% of a run of the automatic scale). The same values as nth_element's.
struct Distance_ranks
{
  static constexpr int bins = 64;
  std::vector<double> values;  // by bucket
  std::uint32_t start[bins + 1] = {};

  // (NaN, from extents that overflow a double, in the last bucket)
  static int bucket(double d2)
  {
    const double x = d2 * bins;
    return x >= 0 && x < bins ? static_cast<int>(x) : (x < 0 ? 0 : bins - 1);
  }

  void assign(const std::vector<double>& d2, double scale = 1.0)
  {
    std::uint32_t count[bins] = {};
    for(double v : d2)
      ++count[bucket(v * scale)];
    start[0] = 0;
    for(int b = 0; b < bins; ++b)
      start[b + 1] = start[b] + count[b];
    std::uint32_t next[bins];
    std::copy(start, start + bins, next);
    values.resize(d2.size());
    for(double v : d2)
      values[next[bucket(v * scale)]++] = v;
  }

  // The k-th smallest, 1 <= k <= the count of values.
  double kth(std::size_t k)
  {
    const std::size_t rank = k - 1;
    const int b = static_cast<int>(std::upper_bound(start, start + bins + 1, rank) - start) - 1;
    std::nth_element(values.begin() + start[b], values.begin() + rank, values.begin() + start[b + 1]);
    return values[rank];
  }
};

// The rungs' fits of one neighbourhood, kept by a pass of the normals' automatic scale so that
// the curvatures' rule, run on the same neighbourhood (curvature_scale_record()), fits each rung
// once: a rung's fit depends on the statistic by its variance factors only (all three are kept)
// and on the reference by its side only (Quadric_fit::orient_like_reference()).
struct Rung_cache
{
  struct Entry
  {
    std::size_t k = 0;
    bool fitted = false;  // compute() and variance_factors() succeeded
    Quadric_fit fit;
    double factor[3] = {0, 0, 0};  // those of H and of the normal's two slopes (scaled frame)
    double sigma2 = 0;             // the residual variance (scaled frame)
    std::size_t size = 0;          // the rung's point count
    std::vector<double> frame;     // its frame cache where kept (the smallest rung: the gate's cubic)
  };
  std::vector<Entry> entries;
  std::size_t used = 0;

  void clear() { used = 0; }
  Entry* find(std::size_t k)
  {
    for(std::size_t i = 0; i < used; ++i)
      if(entries[i].k == k)
        return &entries[i];
    return nullptr;
  }
  Entry& add()
  {
    if(used == entries.size())
      entries.emplace_back();
    return entries[used++];
  }
};

// One thread's scratch of Scale_ladder::choose(); the chosen rung's neighbourhood is left in
// `chosen`.
struct Ladder_scratch
{
  Rung_cache* cache = nullptr;  // the rungs' fits to keep and reuse (null: none)
  // The neighbourhood is the previous call's: `offsets` and `ranks` are its already.
  bool same_neighborhood = false;
  Neighbor_offsets offsets;
  Distance_ranks ranks;
  Sub_neighborhood chosen, trial;
  Sub_neighborhood ahead;          // Scale_ladder::choose(): the rung fitted to look ahead
  std::vector<double> gate_frame;  // Scale_ladder::choose_in_shared_frame(): u, v, h, inner
  // The chosen rung's plain quadric (Scale_ladder::fit_rung()), where choose() fitted it:
  // `chosen.nb.plain_quadric` points to it then, for the estimate at that rung.
  Quadric_fit chosen_fit;
};

// The chosen rung (its neighbourhood is left in the scratch's `chosen`): its rank on the ladder,
// its neighbour count, the standard error of H there (input units).
struct Scale_choice
{
  std::size_t rung = 0;
  std::size_t count = 0;
  double mean_error = std::numeric_limits<double>::quiet_NaN();
  double mean = 0;  // the quadric's H at the chosen rung (mean curvature statistic)
  bool found = false;
  // A rung above the smallest one fitted, kept by the rule because noise dominates the smallest
  // one's residuals (not a rung reached past rungs along one line only).
  bool noise_climb = false;
  // Not found because the first rung's quadric could not be fitted (too few points, or all
  // along one line): no fit tells the noise, so the first rung is estimated as it is, as with
  // a fixed count (its neighbourhood is in `chosen`, mean_error NaN). (A first rung at the
  // query, copies of it, gives no rung at all: DEGENERATE_FIT, as before.)
  bool as_first_rung = false;
  // With Scale_ladder::gate: noise may dominate, the next pass decides (`count` is then twice
  // the smallest count, the neighbourhood that pass gives).
  bool climb = false;
  // Kept by the normals' first test (choose_in_shared_frame()): the first rung's residuals are
  // the surface's third-order terms, not noise.
  bool clean = false;
  // The chosen rung (found or as_first_rung): the neighbour count that gives its neighbourhood
  // and that neighbourhood's radius (input units); the query normal its fit was oriented by
  // (`reference`: the neighbourhood's own where `reference_is_start`, else a lower rung's n0),
  // and the n0 of the first rung kept (`anchor`), which tells the side of `mean`.
  std::size_t k = 0;
  double radius = 0;
  double reference[3] = {0, 0, 0}, anchor[3] = {0, 0, 0};
  bool reference_is_start = true;
};

// The ladder's settings: the smallest and the largest neighbour count.
struct Scale_ladder
{
  std::size_t smallest = 40;
  std::size_t largest = 640;

  std::size_t rungs() const
  {
    std::size_t n = 1;
    for(std::size_t k = smallest; 2 * k <= largest; k *= 2)
      ++n;
    return n;
  }

  // What the rungs are compared by: the mean curvature (for curvatures), or the normal's two
  // tangent components in the smallest rung's frame (for normals, whose bias shows at smaller
  // scales than the curvature's).
  enum class Statistic { MEAN_CURVATURE, NORMAL };
  Statistic statistic = Statistic::MEAN_CURVATURE;

  // The first pass's test, on the smallest rung alone (largest == smallest): the noise from the
  // growth of the residuals between the nearest half of it and all of it, as between two rungs;
  // where it is less than automatic_scale_gate_share of the rung's residual variance the rung is
  // kept (smooth surfaces without noise: most points pay the neighbourhood of the smallest count
  // only); it is also kept where a cubic leaves less than automatic_scale_gate_cubic_share of the
  // quadric's residual variance (cubic_residual()); elsewhere the choice climbs
  // (Scale_choice::climb) and the next pass, on rungs k, 2 k, ..., applies the rule itself.
  bool gate = false;

  // How the first pass's test fits the nearest half and the whole smallest rung. For the mean
  // curvature, each as a rung (the weighted quadric, each in the frame of its own covariance). For
  // the normals, both unweighted, in the frame of the whole rung, in one pass over its points
  // (choose_in_shared_frame()), with its own share (automatic_scale_shared_frame_gate_share). On
  // random (Poisson-like) sampling of a clean terrain, without the cubic's test, the separate fits
  // send 39% of the points on, the shared frame 25% at the same share and 10% at its own; on the
  // clean scans of scan_experiments 0.3-6.4% against 19-72% (a mobile profiler: 47% against 67%),
  // with the same accuracy of the normals under noise. The mean curvature keeps the separate fits:
  // with the shared frame its first pass keeps points whose H is still noisy at the first rung
  // (range noise 0.3 spacings: torus 0.0295 against 0.0283; benchmark/README.md, "Automatic
  // scale").

  // False for the passes before the last (automatic_scale_passes): a point keeping the top
  // rung there climbs to the next pass, which replaces its estimate, so none is computed; its
  // choice is thus the ladder's whatever the estimator would have said at that rung (an
  // invalid estimate there, two_sheets, used to stop it).
  bool final_pass = true;

  // Only the choice, without the neighbourhood for an estimate (curvature_scale_record()).
  bool record_only = false;

  // The least chosen count that goes on to the next pass (automatic_scale_passes()): the
  // gate's points ask for the next rung, the others kept the top rung of their pass.
  std::size_t climb_count() const { return gate ? 2 * largest : largest; }
  bool climbs(const Scale_choice& c) const { return c.found && !final_pass && c.count >= climb_count(); }
  // Counts the points the pass sends on, as it goes (the passes' progress,
  // automatic_scale_progress.h); null: not counted. Results do not depend on it.
  std::atomic<std::size_t>* sent_on = nullptr;
  void count_sent_on() const
  {
    if(sent_on)
      sent_on->fetch_add(1, std::memory_order_relaxed);
  }
  // The first pass's test sends the point on to the next pass (its count, 2 smallest, marks it;
  // that pass's neighbourhood is automatic_scale_pass_growth times the smallest).
  void send_on(Scale_choice& c) const
  {
    c.found = true;
    c.climb = true;
    c.count = 2 * smallest;
  }

  // The fit of one rung: the plain quadric (the penalty of the normals' fit adds a bias that
  // does not grow as r³), the variance factors of the statistic's coefficients `g` (m of
  // them; scaled frame) and the residual variance (input units) at the rung's radius.
  struct Rung_fit
  {
    enum Outcome { NO_RUNG, FAILED, FITTED, LINE } outcome = FAILED;
    Quadric_fit fit;
    double factor[2] = {0, 0}, residual = 0, radius = 0;
    // for the mean curvature, a fitted rung ill-conditioned for H (curvature_ill_conditioned()),
    // a line rung where its error is also beyond the bound (curvature_error_beyond_bound())
    bool ill_conditioned = false;
    // for the normal, a fitted rung that can hardly tell its slope (ill_conditioned_normal_factor)
    bool normal_ill_conditioned = false;
  };

  // A rung's fit can hardly tell the mean curvature (ill_conditioned_curvature_factor) where it
  // is ill-conditioned for H, its variance factor of H in the rung's units (radius 1) times its
  // count n above the factor's limit, and its error beyond the bound, the variance of H in the
  // rung's units (that factor times a residual variance, also in the rung's units) above
  // ill_conditioned_curvature_error squared: fit_rung() reads both on the rung's own residuals,
  // choose() the bound again on a larger rung's.
  static bool curvature_ill_conditioned(double factor, std::size_t n)
  {
    return factor * double(n) > ill_conditioned_curvature_factor;
  }
  static bool curvature_error_beyond_bound(double variance)
  {
    return variance > ill_conditioned_curvature_error * ill_conditioned_curvature_error;
  }

  // A statistic's coefficient combinations, m rows g of the quadric's six coefficients: a3 + a5
  // (H = -(a3 + a5) / r), or the normal's slopes a1, a2.
  struct Combinations
  {
    const double (*g)[6];
    int m;
  };
  static Combinations combinations(Statistic statistic)
  {
    static constexpr double mean[1][6] = {{0, 0, 0, 1, 0, 1}};
    static constexpr double normal[2][6] = {{0, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}};
    return statistic == Statistic::NORMAL ? Combinations{normal, 2} : Combinations{mean, 1};
  }

  // The radius of the driver's neighbourhood whose k-th nearest point lies at squared distance
  // `d2_k` > 0, within the whole's (in the unit of `offsets`).
  static double rung_radius(const Neighbor_offsets& offsets, double d2_k)
  {
    return std::min(knn_radius_factor * std::sqrt(d2_k), offsets.limit);
  }

  // Fits the k nearest of `whole` (`offsets`: whole's, assigned) with the driver's radius rule
  // (the k nearest and those tied with the k-th: the k-th smallest of `ranks`, its squared
  // distances) in `target`, the fit oriented by `reference`,
  // with the variance factors of `statistic` (its coefficient combinations: combinations()).
  // NO_RUNG where the k-th nearest is at the query (copies of it); LINE where the rung's points
  // lie along one line, or, for the mean curvature, where its fit can hardly tell it
  // (curvature_ill_conditioned() and curvature_error_beyond_bound() on its residuals).
  static Rung_fit fit_rung(const Neighborhood& whole, const Neighbor_offsets& offsets, Distance_ranks& ranks,
                           std::size_t k, const double reference[3], Statistic statistic, Sub_neighborhood& target,
                           Rung_cache* cache = nullptr, bool keep_frame = false)
  {
    Rung_fit rung;
    const double r2 = ranks.kth(k);
    if(r2 == 0)
    {
      rung.outcome = Rung_fit::NO_RUNG;
      return rung;
    }
    const double radius = rung_radius(offsets, r2);
    // the mean curvature's combination, then the normal's two (a cache keeps all three)
    static constexpr double all[3][6] = {{0, 0, 0, 1, 0, 1}, {0, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}};
    double factor[3] = {0, 0, 0}, sigma2 = 0;
    bool fitted = false;
    Rung_cache::Entry* kept = cache ? cache->find(k) : nullptr;
    if(kept)
    {
      // (its points are not taken again: a record reads their count only)
      rung.fit = kept->fit;
      target.frame = kept->frame;
      if(rung.fit.orient_like_reference(reference))
        for(std::size_t b = 0; b + 7 < target.frame.size(); b += 8)
        {
          target.frame[b + 6] = -target.frame[b + 6];
          target.frame[b + 7] = -target.frame[b + 7];
        }
      target.nb.size = kept->size;
      target.nb.radius = offsets.unit == 1 ? radius : offsets.unit * radius;  // (as take() sets it)
      std::copy(reference, reference + 3, target.nb.query_normal);
      fitted = kept->fitted;
      std::copy(kept->factor, kept->factor + 3, factor);
      sigma2 = kept->sigma2;
    }
    else
    {
      target.take(whole, radius, offsets);
      std::copy(reference, reference + 3, target.nb.query_normal);
      rung.fit.anisotropy_penalty = 0;
      rung.fit.frame_cache = &target.frame;
      const Combinations c = cache ? Combinations{all, 3} : combinations(statistic);
      double* out = cache || statistic == Statistic::MEAN_CURVATURE ? factor : factor + 1;
      fitted = rung.fit.compute(target.nb) && rung.fit.variance_factors(target.nb, c.g, c.m, out, sigma2);
      if(cache)
      {
        Rung_cache::Entry& e = cache->add();
        e.k = k;
        e.fitted = fitted;
        e.fit = rung.fit;
        e.fit.frame_cache = nullptr;
        std::copy(factor, factor + 3, e.factor);
        e.sigma2 = sigma2;
        e.size = target.nb.size;
        if(keep_frame)
          e.frame = target.frame;
        else
          e.frame.clear();
      }
    }
    rung.fit.frame_cache = &target.frame;
    if(fitted)
    {
      if(statistic == Statistic::MEAN_CURVATURE)
        rung.factor[0] = factor[0];
      else
      {
        rung.factor[0] = factor[1];
        rung.factor[1] = factor[2];
      }
      rung.ill_conditioned =
        statistic == Statistic::MEAN_CURVATURE && curvature_ill_conditioned(rung.factor[0], target.nb.size);
      rung.normal_ill_conditioned =
        statistic == Statistic::NORMAL &&
        std::max(rung.factor[0], rung.factor[1]) * double(target.nb.size) > ill_conditioned_normal_factor;
      const bool line =
        rung.fit.weighted_line || (rung.ill_conditioned && curvature_error_beyond_bound(rung.factor[0] * sigma2));
      rung.outcome = line ? Rung_fit::LINE : Rung_fit::FITTED;
      rung.radius = target.nb.radius;
      rung.residual = sigma2 * (rung.radius * rung.radius);
    }
    return rung;
  }

  // The residual variance (input units) of the weighted cubic over the points of a quadric's fit,
  // in its frame and with its weights (its frame cache, Quadric_fit::frame_cache, of a
  // neighbourhood of that radius); NaN where the cubic's monomials are not well told apart
  // (gate_cubic_least_pivot) or too few points weigh.
  static double cubic_residual(const std::vector<double>& frame, double radius)
  {
    double sigma2;
    if(!cubic_over_frame_cache(frame).residual_variance(gate_cubic_least_pivot, sigma2))
      return std::numeric_limits<double>::quiet_NaN();
    return sigma2 * radius * radius;
  }

  // The normals' first pass's test (gate, largest == smallest): on the k nearest of `whole`
  // (the driver's rule for ties), unweighted quadrics of all of them and of the nearest half,
  // over the frame of their covariance; the noise from the growth of the residuals as in
  // separated_noise(), and where that sees noise, the second test's cubic, unweighted as these
  // fits. Leaves the rung's neighbourhood in `scratch.chosen` where it is kept.
  // As with the separate fits, a rung whose quadric cannot be fitted is estimated as it is
  // (as_first_rung); here the test of its spread is the unweighted covariance's. The choice
  // has no mean_error (the normals do not read it).
  Scale_choice choose_in_shared_frame(const Neighborhood& whole, Ladder_scratch& scratch) const
  {
    Neighbor_offsets& offsets = scratch.offsets;
    Sub_neighborhood& chosen = scratch.chosen;
    Scale_choice c;
    const std::size_t k = std::min(smallest, whole.size);
    if(k == 0)
      return c;
    Distance_ranks& ranks = scratch.ranks;
    if(!scratch.same_neighborhood)
    {
      offsets.assign(whole);
      ranks.assign(offsets.d2, 1.0 / (offsets.limit * offsets.limit));
    }
    const double rung2 = ranks.kth(k);
    if(rung2 == 0)
      return c;  // (the k nearest at the query: no rung)
    const double radius = rung_radius(offsets, rung2);
    // the nearest half's radius (input units) and its ratio to the rung's (0: none)
    const std::size_t half = smallest / 2;
    double half_radius = 0;
    if(half >= gate_least_half && half <= k)
    {
      const double half2 = ranks.kth(half);
      if(half2 > 0)
        half_radius = rung_radius(offsets, half2);
    }
    const double half_ratio = half_radius / radius;
    chosen.take(whole, radius, offsets);
    const Neighborhood& nb = chosen.nb;
    const std::size_t n = nb.size;
    const auto as_first_rung = [&]() {
      c.as_first_rung = true;
      c.count = n;
      chosen.take_attributes(whole);
      return c;
    };
    // the frame: the covariance of the positions about their centroid
    Neighborhood_pca pca;
    if(n <= quadratic_height_coefficients || !pca.compute(nb) || !spreads_in_two_directions(pca.values))
      return as_first_rung();
    // (the normals' test: a line for the weights, not for the points, as where
    // Quadric_fit::compute() takes the unweighted frame)
    Weighted_covariance weighted;
    if(!final_pass && !spreads_along_one_line(pca.values) && weighted.compute(nb) &&
       spreads_along_one_line(weighted.values))
    {
      send_on(c);
      return c;
    }
    const double* centroid = pca.centroid;
    const double(*axes)[3] = pca.vectors;
    // the heights over it, fitted on all points and on the nearest half
    Quadratic_height_fit all, inner;
    std::vector<double>& frame = scratch.gate_frame;
    frame.resize(4 * n);
    const double inner2 = half_radius * half_radius;
    std::size_t n_inner = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double q[3] = {nb.qx[i], nb.qy[i], nb.qz[i]};
      const double p[3] = {q[0] - centroid[0], q[1] - centroid[1], q[2] - centroid[2]};
      double* f = &frame[4 * i];
      f[0] = axes[2][0] * p[0] + axes[2][1] * p[1] + axes[2][2] * p[2];
      f[1] = axes[1][0] * p[0] + axes[1][1] * p[1] + axes[1][2] * p[2];
      f[2] = axes[0][0] * p[0] + axes[0][1] * p[1] + axes[0][2] * p[2];
      f[3] = offsets.d2[chosen.taken[i]] < inner2 ? 1.0 : 0.0;
      all.add(f[0], f[1], f[2], 1.0);
      if(f[3] > 0)
      {
        inner.add(f[0], f[1], f[2], 1.0);
        ++n_inner;
      }
    }
    double a_all[6], a_inner[6] = {0, 0, 0, 0, 0, 0};
    if(!all.solve(a_all))
      return as_first_rung();
    const bool inner_fitted = n_inner > quadratic_height_coefficients && inner.solve(a_inner);
    double ss_all = 0, ss_inner = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double* f = &frame[4 * i];
      const double m[6] = {1.0, f[0], f[1], f[0] * f[0], f[0] * f[1], f[1] * f[1]};
      double e = f[2], e_inner = f[2];
      for(int j = 0; j < 6; ++j)
      {
        e -= a_all[j] * m[j];
        e_inner -= a_inner[j] * m[j];
      }
      ss_all += e * e;
      if(inner_fitted && f[3] > 0)
        ss_inner += e_inner * e_inner;
    }
    // residual variances in input units (both fits are in the frame scaled by nb.radius)
    const double r = nb.radius;
    const double residual = ss_all / double(n - quadratic_height_coefficients) * r * r;
    const double noise2 = inner_fitted
                            ? separated_noise(ss_inner / double(n_inner - quadratic_height_coefficients) * r * r,
                                              half_ratio * r, residual, r)
                            : std::numeric_limits<double>::quiet_NaN();
    c.found = true;
    c.count = n;
    bool kept = noise2 < automatic_scale_shared_frame_gate_share * residual;  // (NaN: not kept)
    if(!kept && half_ratio > 0)
    {
      // the second test, as the mean curvature's (cubic_residual()), unweighted as these fits
      Cubic_height_fit cubic;
      for(std::size_t i = 0; i < n; i += 2)
      {
        // (by pairs; a weight of 0 for the one past the last)
        const double* f = &frame[4 * i];
        const bool pair = i + 1 < n;
        cubic.add(lanes(f[0], pair ? f[4] : 0.0), lanes(f[1], pair ? f[5] : 0.0), lanes(f[2], pair ? f[6] : 0.0),
                  lanes(1.0, pair ? 1.0 : 0.0));
      }
      double sigma2;
      kept = cubic.residual_variance(gate_cubic_least_pivot, sigma2) &&
             sigma2 * r * r < automatic_scale_gate_cubic_share * residual;
    }
    // (nor where the slope's own standard error, its residuals taken for the noise, is beyond
    // that of a clean rung: clean_normal_slope_error; both fits are in the scaled frame, where a
    // slope is a ratio of lengths)
    if(kept && !(all.slope_variance_factor() * ss_all / double(n - quadratic_height_coefficients) <=
                 clean_normal_slope_error * clean_normal_slope_error))
      kept = false;
    if(kept)
      chosen.take_attributes(whole);
    else
      send_on(c);
    c.clean = kept;
    return c;
  }

  // Chooses the rung of `whole` (the neighbourhood of `largest`, scaled by its radius) and
  // leaves its neighbourhood, every field, in `scratch.chosen`.
  Scale_choice choose(const Neighborhood& whole, Ladder_scratch& scratch) const
  {
    if(gate && statistic == Statistic::NORMAL)
      return choose_in_shared_frame(whole, scratch);
    Neighbor_offsets& offsets = scratch.offsets;
    Sub_neighborhood &chosen = scratch.chosen, &trial = scratch.trial;
    constexpr double inf = std::numeric_limits<double>::infinity();
    Scale_choice c;
    Distance_ranks& ranks = scratch.ranks;
    if(!scratch.same_neighborhood)
    {
      offsets.assign(whole);
      ranks.assign(offsets.d2, 1.0 / (offsets.limit * offsets.limit));
    }
    const bool by_normal = statistic == Statistic::NORMAL;
    const int m = combinations(statistic).m;
    double lo[2] = {-inf, -inf}, hi[2] = {inf, inf};
    bool compared = false;  // intervals started (second rung reached)
    double reference[3] = {whole.query_normal[0], whole.query_normal[1], whole.query_normal[2]};
    double axis[2][3] = {};  // the smallest rung's tangent frame (normals)
    // the smallest rung's values, variance factors and residual variance (input units), kept
    // until the second rung tells the noise
    double v0[2] = {0, 0}, factor0[2] = {0, 0}, residual0 = 0, radius0 = 0, noise2 = 0;
    // the last rung passed over for lying along one line (LINE; its neighbourhood kept in `trial`):
    // a larger rung may spread in two directions; taken where no rung above it is fitted up to
    // the top one, which cannot be (a lone noisy line, whose longer neighbourhoods are thinner)
    Rung_fit passed;
    std::size_t passed_rank = 0, passed_k = 0;
    bool fitted = false;    // scratch.chosen_fit is the chosen rung's
    bool kept_one = false;  // a rung was kept: `reference` is no longer the neighbourhood's
    bool first_ill_conditioned = false;
    bool first_normal_ill_conditioned = false;
    // Whether rung j (count k, radius r, residual variance sigma2 in input units) and the next
    // one of this pass say that the data are noisy: the residuals do not grow as r⁶ from one to
    // the other, at least automatic_scale_noise_share of rung j's being noise (separated_noise()).
    const auto noisy_from = [&](std::size_t j, std::size_t k, double r, double sigma2) {
      if(2 * k > whole.size || j + 1 >= rungs())
        return false;
      const Rung_fit next = fit_rung(whole, offsets, ranks, 2 * k, reference, statistic, scratch.ahead);
      if(next.outcome != Rung_fit::FITTED && next.outcome != Rung_fit::LINE)
        return false;
      return separated_noise(sigma2, r, next.residual, next.radius) >= automatic_scale_noise_share * sigma2;
    };
    // (a cloud of fewer points than the smallest count: every point, as with neighbor_count)
    std::size_t k = std::min(smallest, whole.size);
    for(std::size_t j = 0; k > 0 && k <= whole.size && j < rungs(); ++j, k *= 2)
    {
      Rung_fit rung =
        fit_rung(whole, offsets, ranks, k, reference, statistic, c.found ? trial : chosen, scratch.cache, j == 0);
      if(rung.outcome == Rung_fit::NO_RUNG)
        continue;
      const bool top = 2 * k > whole.size || j + 1 == rungs();
      if(rung.outcome == Rung_fit::LINE)
      {
        // Above the first rung kept, a line rung ends the climb; but where that rung was kept
        // only because its residuals were too small for the error's bound (ill-conditioned: one
        // or two scan lines that a quadric nearly interpolates), this line rung is not the pass's
        // top, and with its residuals taken for the noise the kept rung's standard error would
        // exceed that bound, the kept rung is given up: both are passed over as line rungs and
        // the climb goes on, on the side of the given-up rung's normal
        // (ill_conditioned_curvature_factor).
        if(c.found)
        {
          if(!first_ill_conditioned || compared || gate || top ||
             !curvature_error_beyond_bound(factor0[0] * std::max(residual0, rung.residual) * radius0 * radius0))
            break;
          const Scale_choice given_up = c;
          c = Scale_choice();
          std::copy(given_up.anchor, given_up.anchor + 3, c.anchor);  // (the side kept_one keeps)
          fitted = false;
          passed = rung;  // (fitted in `trial`, where a passed rung is kept)
          passed_rank = j;
          passed_k = k;
          continue;
        }
        // (the first pass's rung is its top one, passed over too: the point climbs)
        if(gate || !top)
        {
          passed = rung;
          passed_rank = j;
          passed_k = k;
          std::swap(chosen, trial);
          continue;
        }
      }
      std::size_t rank = j;
      bool fallback = false;
      double v[2] = {0, 0}, n[3];
      if((rung.outcome != Rung_fit::FITTED && rung.outcome != Rung_fit::LINE) || !rung.fit.normal(n))
      {
        // above a rung passed over as one line, one that cannot be fitted (the line and a few
        // points off it) is passed over too; the line is taken only where the top one cannot be
        if(!c.found && passed.outcome == Rung_fit::LINE && !top)
          continue;
        if(c.found || passed.outcome != Rung_fit::LINE || !passed.fit.normal(n))
        {
          if(!c.found && j == 0)
          {
            c.as_first_rung = true;
            c.count = chosen.nb.size;
            c.k = k;
            c.radius = chosen.nb.radius;
          }
          break;
        }
        rung = passed;
        rank = passed_rank;
        fallback = true;
        std::swap(chosen, trial);
      }
      const Quadric_fit& fit = rung.fit;
      double* factor = rung.factor;
      // to input units (the residual variance already is): H = -(a3 + a5) / r, its variance
      // factor over r⁴; a slope is a ratio of lengths, its variance factor over r²
      const double r = rung.radius, sigma2 = rung.residual;
      if(!c.found && by_normal)
        for(int a = 0; a < 3; ++a)
        {
          axis[0][a] = fit.t1[a];
          axis[1][a] = fit.t2[a];
        }
      for(int i = 0; i < m; ++i)
      {
        if(by_normal)
        {
          v[i] = n[0] * axis[i][0] + n[1] * axis[i][1] + n[2] * axis[i][2];
          factor[i] /= r * r;
        }
        else
        {
          v[i] = -(fit.a[3] + fit.a[5]) / r;
          factor[i] /= r * r * r * r;
        }
      }
      if(!c.found)
      {
        first_ill_conditioned = rung.ill_conditioned;
        first_normal_ill_conditioned = rung.normal_ill_conditioned;
        std::copy(v, v + 2, v0);
        std::copy(factor, factor + 2, factor0);
        residual0 = sigma2;
        radius0 = r;
        noise2 = sigma2;  // (an upper bound while no other rung tells)
      }
      else
      {
        const bool first_comparison = !compared;
        // A first rung that can hardly tell the normal (ill_conditioned_normal_factor) is given
        // up where its residuals read as no noise or its interval misses this rung's, provided
        // this rung and the next one say that the data are noisy.
        const bool first_untrusted = first_comparison && first_normal_ill_conditioned && noisy_from(j, k, r, sigma2);
        bool first_reads_no_noise = false;
        if(!compared)
        {
          // The residuals' variance is the noise's plus the surface's third-order terms,
          // which grow as r⁶: two rungs separate them.
          compared = true;
          noise2 = separated_noise(residual0, radius0, sigma2, r);
          if(std::isnan(noise2))
            noise2 = residual0;
          for(int i = 0; i < m; ++i)
          {
            const double s0 = std::sqrt(noise2 * factor0[i]);
            lo[i] = v0[i] - automatic_scale_kappa * s0;
            hi[i] = v0[i] + automatic_scale_kappa * s0;
          }
          c.mean_error = std::sqrt(noise2 * factor0[0]);
          // Without noise dominating the smallest scale's residuals, its fit is the best one
          // (the estimate of the noise, from about 20 effective points, is itself noisy).
          if(noise2 < automatic_scale_noise_share * residual0)
          {
            if(!first_untrusted)
              break;
            first_reads_no_noise = true;
          }
        }
        bool meet = true;
        for(int i = 0; i < m; ++i)
        {
          const double s = std::sqrt(noise2 * factor[i]);
          lo[i] = std::max(lo[i], v[i] - automatic_scale_kappa * s);
          hi[i] = std::min(hi[i], v[i] + automatic_scale_kappa * s);
          meet = meet && lo[i] <= hi[i];
        }
        // The intervals assume the first rung unbiased; where its own error is beyond the bound
        // of a rung that can hardly tell the mean curvature (curvature_error_beyond_bound(), with
        // the noise just separated), a disagreement says more of its estimate than of the larger
        // rung's bias: the first rung is given up and the climb starts again from this one
        // (benchmark/scan_experiments `rings` under noise: first rungs of two scan lines kept with
        // H errors of 5 to 20 times the surface's curvature). So is a first rung that cannot tell
        // the normal on noisy data (first_untrusted).
        if((first_untrusted && (!meet || first_reads_no_noise)) ||
           (!meet && first_comparison && statistic == Statistic::MEAN_CURVATURE &&
            curvature_error_beyond_bound(factor0[0] * noise2 * radius0 * radius0)))
        {
          std::copy(v, v + 2, v0);
          std::copy(factor, factor + 2, factor0);
          residual0 = sigma2;
          radius0 = r;
          noise2 = sigma2;
          first_ill_conditioned = rung.ill_conditioned;
          first_normal_ill_conditioned = rung.normal_ill_conditioned;
          compared = false;
          std::fill(lo, lo + 2, -inf);
          std::fill(hi, hi + 2, inf);
          meet = true;
        }
        if(!meet)
          break;
        std::swap(chosen, trial);
        c.noise_climb = true;
      }
      c.mean_error = std::sqrt(noise2 * factor[0]);
      c.found = true;
      c.rung = rank;
      c.mean = v[0];
      c.count = chosen.nb.size;  // (after the swap: target is the rung given up)
      c.k = fallback ? passed_k : k;
      c.radius = r;
      std::copy(reference, reference + 3, c.reference);
      c.reference_is_start = !kept_one;
      if(!kept_one)
        std::copy(fit.n0, fit.n0 + 3, c.anchor);
      kept_one = true;
      scratch.chosen_fit = fit;
      scratch.chosen_fit.frame_cache = nullptr;  // (a cache of `trial`'s or `chosen`'s)
      fitted = true;
      std::copy(fit.n0, fit.n0 + 3, reference);  // one side for every rung
      if(fallback)
        break;  // (the pass's top rung could not be fitted)
    }
    const std::size_t half = smallest / 2;
    if(gate && c.found && half >= gate_least_half && half <= whole.size)
    {
      // The cubic first, on the first rung's fit (`chosen`: the gate's pass has one rung, kept
      // only where fitted); where it does not keep the rung, the nearest half of it (NaN without
      // its fit, or where the growth cannot tell: the point climbs). `kept_noise2` is what the
      // test that keeps the rung takes for the noise's variance.
      CGAL_assertion(largest == smallest);
      double kept_noise2 = cubic_residual(chosen.frame, radius0);
      bool kept = kept_noise2 < automatic_scale_gate_cubic_share * residual0;
      if(!kept)
      {
        const Rung_fit rung = fit_rung(whole, offsets, ranks, half, reference, statistic, trial, scratch.cache);
        // (along one line, or where it can hardly tell the curvature, it tells nothing of the noise)
        kept_noise2 = rung.outcome == Rung_fit::FITTED ? separated_noise(rung.residual, rung.radius, residual0, radius0)
                                                       : std::numeric_limits<double>::quiet_NaN();
        kept = kept_noise2 < automatic_scale_gate_share * residual0;
      }
      // (nor where the rung's own residuals, taken for noise, put its error beyond the bound: the
      // tests read no noise where a cubic, or the nearest half along one scan line, fits the
      // noise itself; benchmark/scan_experiments `rings`)
      if(kept && statistic == Statistic::MEAN_CURVATURE &&
         curvature_error_beyond_bound(factor0[0] * residual0 * radius0 * radius0))
        kept = false;
      if(kept)
        c.mean_error = std::sqrt(kept_noise2 * factor0[0]);
      else
        send_on(c);
    }
    else if(gate && c.found)
      send_on(c);  // (too few points for either test)
    if(gate && !c.found && !c.as_first_rung && passed.outcome == Rung_fit::LINE && !final_pass)
      send_on(c);
    if((c.found || c.as_first_rung) && !climbs(c) && !record_only)
    {
      chosen.take_attributes(whole);
      chosen.nb.plain_quadric = fitted && !c.climb ? &scratch.chosen_fit : nullptr;
    }
    return c;
  }
};

// The largest count of the named parameter automatic_scale, 0 without it. Throws
// std::invalid_argument with a radius, or below the count of neighbor_count.
template <class NamedParameters>
std::size_t automatic_scale_parameter(const NamedParameters& np, bool radius_given, const char* function_name)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::size_t largest = choose_parameter(get_parameter(np, internal_np::automatic_scale), std::size_t(0));
  if(largest == 0)
    return 0;
  const std::size_t k = choose_parameter(get_parameter(np, internal_np::neighbor_count), std::size_t(0));
  std::ostringstream msg;
  msg << function_name << ": parameter 'automatic_scale' ";
  if(radius_given)
    msg << "chooses among neighbour counts: use the overload without a radius, with neighbor_count";
  else if(k > 0 && largest < k)
    msg << "(" << largest << ") must be at least neighbor_count (" << k << ")";
  else
    return largest;
  throw std::invalid_argument(msg.str());
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
