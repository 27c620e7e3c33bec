// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's tiled runs (see tiled_run.h).

#include "tiled_run.h"

#include "tile_pass_progress.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <queue>
#include <utility>

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;

double bytes_per_point(std::size_t attributes, bool automatic_scale, bool spanning_tree)
{
  return 16.0 * double(attributes) + std::max(automatic_scale ? 500.0 : 300.0, spanning_tree ? 480.0 : 0.0);
}

namespace {

bool finite_point(const double* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// Appends point k of `from` to `to` (coordinates, normal, attribute values).
void append_point(const Point_cloud& from, std::size_t k, std::vector<double>& xyz, std::vector<double>& normals,
                  std::vector<std::vector<double>>& attributes)
{
  xyz.insert(xyz.end(), &from.xyz[3 * k], &from.xyz[3 * k] + 3);
  if(!from.normals.empty())
    normals.insert(normals.end(), &from.normals[3 * k], &from.normals[3 * k] + 3);
  attributes.resize(from.attributes.size());
  for(std::size_t a = 0; a < from.attributes.size(); ++a)
    attributes[a].push_back(from.attributes[a].values[k]);
}

// Counts of the finite points per cell of a grid of at most 128 cells per axis over the
// bounds, with prefix sums: the number of points in any box of cells in constant time. The
// arithmetic is on halved coordinates, so that bounds whose extent overflows a double (from
// -1e308 to 1e308) give finite cells.
class Density_grid
{
public:
  Density_grid(const double lo[3], const double hi[3])
  {
    double longest = 0;
    for(int a = 0; a < 3; ++a)
      longest = std::max(longest, hi[a] / 2 - lo[a] / 2);
    for(int a = 0; a < 3; ++a)
    {
      m_lo[a] = lo[a] / 2;
      const double extent = hi[a] / 2 - lo[a] / 2;
      m_dims[a] = extent > 0 && longest > 0
                    ? std::size_t(std::max(1.0, std::min(128.0, std::ceil(128.0 * (extent / longest)))))
                    : 1;
      m_cell[a] = extent > 0 ? extent / double(m_dims[a]) : 1.0;
    }
    m_count.assign(m_dims[0] * m_dims[1] * m_dims[2], 0);
  }

  void add(const double* p) { ++m_count[cell(0, p[0]) + m_dims[0] * (cell(1, p[1]) + m_dims[1] * cell(2, p[2]))]; }

  // after the last add()
  void finish()
  {
    const std::size_t d0 = m_dims[0] + 1, d1 = m_dims[1] + 1, d2 = m_dims[2] + 1;
    m_sum.assign(d0 * d1 * d2, 0);
    for(std::size_t k = 1; k < d2; ++k)
      for(std::size_t j = 1; j < d1; ++j)
        for(std::size_t i = 1; i < d0; ++i)
          m_sum[i + d0 * (j + d1 * k)] =
            m_count[(i - 1) + m_dims[0] * ((j - 1) + m_dims[1] * (k - 1))] + m_sum[(i - 1) + d0 * (j + d1 * k)] +
            m_sum[i + d0 * ((j - 1) + d1 * k)] + m_sum[i + d0 * (j + d1 * (k - 1))] -
            m_sum[(i - 1) + d0 * ((j - 1) + d1 * k)] - m_sum[(i - 1) + d0 * (j + d1 * (k - 1))] -
            m_sum[i + d0 * ((j - 1) + d1 * (k - 1))] + m_sum[(i - 1) + d0 * ((j - 1) + d1 * (k - 1))];
  }

  // An upper bound of the points in the box [lo, hi] (the cells it meets; every point for a
  // NaN bound).
  std::uint64_t at_most(const double lo[3], const double hi[3]) const
  {
    std::size_t b[3], e[3];
    for(int a = 0; a < 3; ++a)
    {
      if(std::isnan(lo[a]) || std::isnan(hi[a]))
      {
        b[a] = 0;
        e[a] = m_dims[a];
        continue;
      }
      if(hi[a] / 2 < m_lo[a] || lo[a] / 2 > m_lo[a] + m_cell[a] * double(m_dims[a]))
        return 0;
      b[a] = cell(a, lo[a]);
      e[a] = cell(a, hi[a]) + 1;
    }
    const std::size_t d0 = m_dims[0] + 1, d1 = m_dims[1] + 1;
    auto s = [&](std::size_t i, std::size_t j, std::size_t k) { return m_sum[i + d0 * (j + d1 * k)]; };
    return s(e[0], e[1], e[2]) - s(b[0], e[1], e[2]) - s(e[0], b[1], e[2]) - s(e[0], e[1], b[2]) + s(b[0], b[1], e[2]) +
           s(b[0], e[1], b[2]) + s(e[0], b[1], b[2]) - s(b[0], b[1], b[2]);
  }

  // The first halo of a tile by count: the smallest h of the ladder start, 1.25 start, ... such
  // that around every occupied cell of the box [b, e] (a tile's core, clamped to the bounds) the
  // cell grown by h meets cells holding at least `count` points. A guess, not a bound: at_most()
  // counts every cell the grown box meets, and a point's neighbourhood is a ball (see
  // tile_first_halo() for the margins).
  double halo_for_count(const double b[3], const double e[3], double count, double start) const
  {
    std::size_t cb[3], ce[3];
    for(int a = 0; a < 3; ++a)
    {
      cb[a] = cell(a, b[a]);
      ce[a] = cell(a, e[a]);
    }
    count = std::min(count, double(m_sum.back()));  // (at most every point: a halo over the grid)
    double halo = start;
    for(std::size_t z = cb[2]; z <= ce[2]; ++z)
      for(std::size_t y = cb[1]; y <= ce[1]; ++y)
        for(std::size_t x = cb[0]; x <= ce[0]; ++x)
        {
          if(m_count[x + m_dims[0] * (y + m_dims[1] * z)] == 0)
            continue;
          const std::size_t i[3] = {x, y, z};
          double l[3], h[3];
          for(int a = 0; a < 3; ++a)
          {
            l[a] = 2 * (m_lo[a] + m_cell[a] * double(i[a]));
            h[a] = 2 * (m_lo[a] + m_cell[a] * double(i[a] + 1));
          }
          // (the halo only grows: a cell that the current one serves costs one count)
          for(int step = 0; step < 200; ++step, halo *= 1.25)
          {
            double gl[3], gh[3];
            for(int a = 0; a < 3; ++a)
            {
              gl[a] = l[a] - halo;
              gh[a] = h[a] + halo;
            }
            if(double(at_most(gl, gh)) >= count || !std::isfinite(halo))
              break;
          }
        }
    return halo;
  }

private:
  // the cell of coordinate v along axis a, clamped (monotonic in v; v not NaN)
  std::size_t cell(int a, double v) const
  {
    const double c = std::floor((v / 2 - m_lo[a]) / m_cell[a]);
    return !(c > 0) ? 0 : c >= double(m_dims[a] - 1) ? m_dims[a] - 1 : std::size_t(c);
  }
  double m_lo[3], m_cell[3];  // halved: lo / 2 and the cell side / 2
  std::size_t m_dims[3];
  std::vector<std::uint64_t> m_count, m_sum;
};

// The box [b, e] where the points of tile t with its halo are counted in the density grid:
// the tile's core clamped to the box of the tiles [lo, hi] (the outer tiles are infinite),
// grown by the halo.
void tile_box(const PSC::Tile_grid& grid, std::size_t t, const double lo[3], const double hi[3], double halo,
              double b[3], double e[3])
{
  const PSC::Tile tile = grid.tile(t, halo);
  for(int a = 0; a < 3; ++a)
  {
    b[a] = std::max(tile.core.min(a), lo[a]) - halo;
    e[a] = std::min(tile.core.max(a), hi[a]) + halo;
  }
}

// How much more than the count k of a tiling by count a tile's first halo asks of the density
// grid around each occupied cell of its core, and the factor on the halo found
// (Density_grid::halo_for_count()): a neighbourhood is a ball where the grid counts boxes of
// whole cells (4 / pi as many points in a square as in its disc), and with sample weights the
// estimation needs the neighbours' own neighbours too. Against the halo of the cloud's mean
// density for every tile (--orient +z, 2 cores, two alternating runs each, 2026-12-01):
// lone-star.las (a terrestrial scan whose density varies a hundredfold) with --neighbors 40
// under 50M 13.7-16.6 s -> 10.4-12.8 s (tiles read again 69 -> 40), under 150M 9.6-10.2 ->
// 7.5-8.3 s (26 -> 9), the default scale under 50M 96.8 -> 87.1 s (336 -> 187, one run);
// hexbin-crop.las under 5M 11.2-12.7 -> 9.4-9.9 s (292 tiles, the largest range 6723 -> 3922
// points), under 20M within 2%; sample_c.las under 5M 2.9-3.1 -> 2.6-2.8 s; the same peaks
// within 5%. Every output bitwise the in-memory one, as before. Tried:
// count factor 8 (halo factor 1.15) cut lone-star's default re-reads to 38 (78 s) but made
// the small airborne files' halos 3 times the needed ones (hexbin-crop under 5M 13.4 s); 1.27
// left hexbin-crop 212 re-reads; halos grown from the previous tile's re-read made lone-star's
// ranges 142K points against 88K.
constexpr double first_halo_count_factor = 2;
constexpr double first_halo_factor = 1.3;

// The first halo of tile t of `grid` by count (`k` neighbours): first_halo_factor times the
// halo that Density_grid::halo_for_count() finds around the tile's core from `least` up. A
// tile asks for a larger halo when its estimation needs one (Halo_too_small), after work that
// a first halo large enough saves; any halo gives the same estimates.
double tile_first_halo(const PSC::Tile_grid& grid, std::size_t t, const Density_grid& density, const double lo[3],
                       const double hi[3], std::size_t k, double least)
{
  double b[3], e[3];
  tile_box(grid, t, lo, hi, 0.0, b, e);  // (the core, clamped to the tiles' box)
  return first_halo_factor * density.halo_for_count(b, e, first_halo_count_factor * double(k), least);
}

// The most points of one tile with its halo, bounded from the density grid.
std::uint64_t largest_tile(const PSC::Tile_grid& grid, const Density_grid& density, const double lo[3],
                           const double hi[3], double halo)
{
  std::uint64_t most = 0;
  for(std::size_t t = 0; t < grid.size(); ++t)
  {
    double b[3], e[3];
    tile_box(grid, t, lo, hi, halo, b, e);
    most = std::max(most, density.at_most(b, e));
  }
  return most;
}

// The tiles' rows in one temporary file, unlinked as soon as it is created (it disappears
// with the process, however the process ends): records (input index, row, attribute values),
// a segment per tile, each sorted by input index. One file and one write buffer whatever the
// number of tiles (a file per tile kept a 1 MB buffer each: 1500 points in 356 tiles took
// 373 MB, and thousands of tiles would exceed the open files allowed); the merge reads each
// segment through a buffer of its own (run_tiled() sizes them: half the limit shared, 16
// records each at least).
static_assert(sizeof(::off_t) >= 8, "temporary files beyond 2 GB need a 64-bit off_t");
class Row_store
{
public:
  Row_store(const std::string& prefix, std::size_t attributes)
      : m_attributes(attributes), m_record(sizeof(std::uint64_t) + sizeof(Output_row) + sizeof(double) * attributes)
  {
    std::string pattern = prefix + "XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = ::mkstemp(name.data());
    if(fd < 0)
      throw Error(cat("cannot create a temporary file ", in_quotes(pattern), ": ", std::strerror(errno)));
    ::unlink(name.data());
    m_name = name.data();
    m_file = ::fdopen(fd, "w+b");
    if(!m_file)
    {
      ::close(fd);
      throw Error(cat("cannot create a temporary file ", in_quotes(m_name), ": ", std::strerror(errno)));
    }
    m_buffer.reset(new char[1 << 20]);
    std::setvbuf(m_file, m_buffer.get(), _IOFBF, 1 << 20);
  }
  ~Row_store()
  {
    if(m_file)
      std::fclose(m_file);
  }
  Row_store(const Row_store&) = delete;
  Row_store& operator=(const Row_store&) = delete;

  // A new segment: the rows put from now on
  void begin_segment() { m_segments.push_back(Segment{m_records, m_records}); }

  void put(std::uint64_t index, const Output_row& row, const double* attributes)
  {
    Output_row r = row;
    r.attributes = nullptr;
    // (a full disk stops the run at the row that does not fit, not after the last tile)
    if(std::fwrite(&index, sizeof index, 1, m_file) != 1 || std::fwrite(&r, sizeof r, 1, m_file) != 1 ||
       (m_attributes && std::fwrite(attributes, sizeof(double), m_attributes, m_file) != m_attributes))
      throw Error(cat("cannot write the temporary file ", in_quotes(m_name), ": ", std::strerror(errno)));
    ++m_records;
    m_segments.back().end = m_records;
  }

  // after the last put()
  void finish()
  {
    if(std::fflush(m_file) != 0 || std::ferror(m_file))
      throw Error(cat("cannot write the temporary file ", in_quotes(m_name), ": ", std::strerror(errno)));
  }

  std::size_t segments() const { return m_segments.size(); }
  std::size_t record_bytes() const { return m_record; }

  // The records of one segment in order, read `buffered` at a time.
  class Cursor
  {
  public:
    Cursor(const Row_store& store, std::size_t segment, std::size_t buffered)
        : m_store(&store), m_next(store.m_segments[segment].begin), m_end(store.m_segments[segment].end),
          m_buffered(std::max<std::size_t>(1, buffered))
    {}

    // false at the end
    bool get(std::uint64_t& index, Output_row& row, std::vector<double>& attributes)
    {
      if(m_at == m_bytes.size())
      {
        if(m_next == m_end)
          return false;
        const std::size_t records = std::min<std::size_t>(m_buffered, m_end - m_next);
        m_bytes.resize(records * m_store->m_record);
        m_at = 0;
        std::size_t done = 0;
        while(done < m_bytes.size())
        {
          const ::ssize_t n = ::pread(::fileno(m_store->m_file), m_bytes.data() + done, m_bytes.size() - done,
                                      ::off_t(m_next * m_store->m_record + done));
          if(n <= 0)
          {
            if(n < 0 && errno == EINTR)
              continue;
            throw Error(cat("cannot read the temporary file ", in_quotes(m_store->m_name),
                            n < 0 ? cat(": ", std::strerror(errno)) : std::string()));
          }
          done += std::size_t(n);
        }
        m_next += records;
      }
      const char* at = m_bytes.data() + m_at;
      std::memcpy(&index, at, sizeof index);
      std::memcpy(&row, at + sizeof index, sizeof row);
      row.attributes = nullptr;
      attributes.resize(m_store->m_attributes);
      if(m_store->m_attributes)
        std::memcpy(attributes.data(), at + sizeof index + sizeof row, sizeof(double) * m_store->m_attributes);
      m_at += m_store->m_record;
      return true;
    }

  private:
    const Row_store* m_store;
    std::uint64_t m_next, m_end;  // records
    std::size_t m_buffered;
    std::vector<char> m_bytes;
    std::size_t m_at = 0;
  };

private:
  struct Segment
  {
    std::uint64_t begin, end;  // records
  };
  std::size_t m_attributes, m_record;
  std::string m_name;
  std::FILE* m_file = nullptr;
  std::unique_ptr<char[]> m_buffer;
  std::vector<Segment> m_segments;
  std::uint64_t m_records = 0;
};

// The box of the tiles: the library's rule (PSC::tile_grid_box(), the 0.1% and 99.9% quantiles
// of the sample on each axis), as Dask's.
void tile_box(const Scanned_input& input, double lo[3], double hi[3])
{
  const CGAL::Bbox_3 b = input.sample.box();
  for(int a = 0; a < 3; ++a)
  {
    lo[a] = b.min(a);
    hi[a] = b.max(a);
  }
}

}  // namespace

double density_halo(const Scanned_input& input, std::size_t k)
{
  double lo[3], hi[3];
  tile_box(input, lo, hi);
  return PSC::halo_guess_for_count(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), input.finite, k);
}

Scanned_input read_or_scan(const std::string& path, const Read_options& options, double memory_limit,
                           bool automatic_scale, bool spanning_tree)
{
  Scanned_input s;
  for(int a = 0; a < 3; ++a)
  {
    s.lo[a] = HUGE_VAL;
    s.hi[a] = -HUGE_VAL;
  }
  bool keeping = true;
  std::vector<double> xyz, normals;
  std::vector<std::vector<double>> attributes;
  std::vector<double> largest;  // per attribute, over every point
  Read_options o = options;
  o.chunk_points = 1 << 16;
  // The share of the file read (the readers' progress), for the points' storage reserved at
  // once for the count it predicts: grown chunk by chunk, reallocation and its first touch of
  // fresh memory (page faults) took two thirds of the read phase (1M points of .xyz with
  // normals: 0.93 s, the parsing 0.3 s).
  double fraction_read = 0;
  o.progress = [&fraction_read, &options](double f) {
    fraction_read = f;
    return !options.progress || options.progress(f);
  };
  const auto reserve_for = [&](std::size_t attribute_count, std::size_t with_normals) {
    if(!(fraction_read > 0))
      return;
    const double predicted = 1.1 * double(s.points) / std::min(1.0, fraction_read) + double(o.chunk_points);
    const double affordable =
      memory_limit / bytes_per_point(attribute_count, automatic_scale, spanning_tree && with_normals == 0);
    const std::size_t count = std::size_t(std::min(predicted, affordable));
    if(3 * count <= xyz.capacity())
      return;
    xyz.reserve(3 * count);
    normals.reserve(with_normals * 3 * count);
    for(std::vector<double>& a : attributes)
      a.reserve(count);
  };
  o.chunk = [&](const Point_cloud& c) {
    largest.resize(c.attributes.size(), -HUGE_VAL);
    for(std::size_t a = 0; a < c.attributes.size(); ++a)
      for(const double v : c.attributes[a].values)
        largest[a] = v > largest[a] ? v : largest[a];
    for(std::size_t k = 0; k < c.size(); ++k)
    {
      const double* p = &c.xyz[3 * k];
      if(!finite_point(p))
        continue;
      ++s.finite;
      for(int a = 0; a < 3; ++a)
      {
        s.lo[a] = std::min(s.lo[a], p[a]);
        s.hi[a] = std::max(s.hi[a], p[a]);
      }
      s.sample.add(p[0], p[1], p[2]);
    }
    s.points += c.size();
    if(!keeping)
      return;
    if(double(s.points) * bytes_per_point(c.attributes.size(), automatic_scale, spanning_tree && c.normals.empty()) >
       memory_limit)
    {
      keeping = false;
      std::vector<double>().swap(xyz);
      std::vector<double>().swap(normals);
      std::vector<std::vector<double>>().swap(attributes);
      return;
    }
    attributes.resize(c.attributes.size());
    if(xyz.size() + c.xyz.size() > xyz.capacity())
      reserve_for(c.attributes.size(), c.normals.empty() ? 0 : 1);
    xyz.insert(xyz.end(), c.xyz.begin(), c.xyz.end());
    normals.insert(normals.end(), c.normals.begin(), c.normals.end());
    for(std::size_t a = 0; a < c.attributes.size(); ++a)
      attributes[a].insert(attributes[a].end(), c.attributes[a].values.begin(), c.attributes[a].values.end());
  };
  s.cloud = read_point_cloud(path, o);
  s.fits = keeping;
  for(std::size_t a = 0; a < s.cloud.attributes.size(); ++a)
    s.cloud.attributes[a].largest = a < largest.size() ? largest[a] : -HUGE_VAL;
  if(keeping)
  {
    s.cloud.first = 0;
    s.cloud.xyz = std::move(xyz);
    s.cloud.normals = std::move(normals);
    for(std::size_t a = 0; a < s.cloud.attributes.size() && a < attributes.size(); ++a)
      s.cloud.attributes[a].values = std::move(attributes[a]);
  }
  return s;
}

namespace {

// The density pass: the finite points of the file counted in a grid over the box of the tiles
// [lo, hi].
Density_grid read_density(const std::string& path, const Read_options& options, const double lo[3], const double hi[3],
                          const Tiling& tiling)
{
  Density_grid density(lo, hi);
  Read_options o = options;
  o.chunk_points = 1 << 16;
  o.progress = tiling.phase("density");
  o.chunk = [&](const Point_cloud& c) {
    for(std::size_t k = 0; k < c.size(); ++k)
      if(finite_point(&c.xyz[3 * k]))
        density.add(&c.xyz[3 * k]);
  };
  read_point_cloud(path, o);
  density.finish();
  return density;
}

// The tiles: the largest whose points with their `halo` fit in `budget` points by the
// density; where no grid does, the coarsest within 10% of the lowest peak. Records in `report`
// the finest grid of few tiles.
PSC::Tile_grid choose_tile_grid(const Density_grid& density, const double lo[3], const double hi[3], double halo,
                                double budget, const Tiling& tiling, Tiled_report& report)
{
  const CGAL::Bbox_3 box(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  // halved extents: the extent of finite bounds may overflow (from -1e308 to 1e308)
  double half[3], longest = 0;
  for(int a = 0; a < 3; ++a)
  {
    half[a] = hi[a] / 2 - lo[a] / 2;
    longest = std::max(longest, half[a]);
  }
  PSC::Tile_grid grid(box, std::array<std::size_t, 3>{{1, 1, 1}});
  // The grids tried, coarsest first, with the most points a tile of each reads.
  std::vector<std::pair<PSC::Tile_grid, double>> tried;
  // (the tiles shrink by 0.8 a step: past 4096 tiles within 38 steps)
  for(double side = longest; side > 0;)
  {
    side *= 0.8;
    const double largest = largest_tile(grid, density, lo, hi, halo);
    tried.emplace_back(grid, largest);
    if(grid.size() <= Tiled_report::few_tiles)
    {
      // the finest grid of few tiles, for a --memory-limit to suggest when the limit makes many
      report.few_tiles_grid = grid.size();
      report.few_tiles_points = largest;
    }
    if(largest <= budget)
      break;
    std::array<double, 3> counts;
    for(int a = 0; a < 3; ++a)
      counts[a] = std::max(1.0, std::ceil(half[a] / side));  // (1 when the ratio underflows, or NaN)
    if(!(counts[0] * counts[1] * counts[2] <= 4096))
      break;  // the halos dominate: as good as it gets
    grid = PSC::Tile_grid(
      box, std::array<std::size_t, 3>{{std::size_t(counts[0]), std::size_t(counts[1]), std::size_t(counts[2])}});
    if(tiling.interrupted && tiling.interrupted())
      throw Cancelled();
  }
  if(!tried.empty() && tried.back().second > budget)
  {
    // No grid meets the limit: the halos hold more points than it allows. Smaller tiles then
    // barely lower the peak (not at all when a halo spans the whole cloud: 3000 points with
    // neighbourhoods of 640 made 641 tiles, each the whole cloud, 200 times as long as one)
    // while every tile reads the input again: the coarsest grid within 10% of the lowest peak.
    double least = HUGE_VAL;
    for(const auto& g : tried)
      least = std::min(least, g.second);
    for(const auto& g : tried)
      if(g.second <= 1.1 * least)
        return g.first;
  }
  return grid;
}

// A tile's range read from the file: its points (`own[k]`: point k is the tile's own, of
// which there are `own_count`).
struct Tile_read
{
  Tile_points points;
  std::vector<char> own;
  std::size_t own_count = 0;
};

// Reads the points of `tile`, tile `t` of `grid` with its halo, reserving from the density;
// `range` (of `tile`) takes them and learns the range's rules. The first tile also takes the
// non-finite points, as its own.
Tile_read read_tile(const std::string& path, const Read_options& options, const Scanned_input& input,
                    const Tiling& tiling, const PSC::Tile_grid& grid, std::size_t t, const PSC::Tile& tile,
                    const double lo[3], const double hi[3], const Density_grid& density, PSC::Tile_range& range,
                    const Progress& progress)
{
  const std::size_t attribute_count = options.keep_attributes ? input.cloud.attributes.size() : 0;
  const bool with_normals = input.cloud.has_normals() || tiling.normals;
  Tile_read r;
  // reserved from the density (an upper bound), the chunks small: the tile's points are most
  // of the memory
  double b[3], e[3];
  tile_box(grid, t, lo, hi, tile.halo, b, e);
  const std::size_t expected = std::size_t(density.at_most(b, e)) + (t == 0 ? input.points - input.finite : 0);
  r.points.xyz.reserve(3 * expected);
  if(with_normals)
    r.points.normals.reserve(3 * expected);
  r.points.index.reserve(expected);
  r.own.reserve(expected);
  r.points.attributes.resize(attribute_count);
  for(std::vector<double>& a : r.points.attributes)
    a.reserve(expected);
  Read_options o = options;
  o.chunk_points = 1 << 16;
  o.progress = progress;
  o.chunk = [&](const Point_cloud& c) {
    r.points.attributes.resize(c.attributes.size());
    for(std::size_t k = 0; k < c.size(); ++k)
    {
      const double* p = &c.xyz[3 * k];
      const bool finite = finite_point(p);
      if(!range.take(p[0], p[1], p[2]) && (finite || t != 0))
        continue;  // (the first tile takes the non-finite points, as its own)
      append_point(c, k, r.points.xyz, r.points.normals, r.points.attributes);
      if(tiling.normals)
        r.points.normals.insert(r.points.normals.end(), &(*tiling.normals)[3 * (c.first + k)],
                                &(*tiling.normals)[3 * (c.first + k)] + 3);
      r.points.index.push_back(c.first + k);
      const bool is_own = finite ? tile.owns(p[0], p[1], p[2]) : true;
      r.own.push_back(is_own ? 1 : 0);
      r.own_count += is_own;
    }
  };
  read_point_cloud(path, o);
  if(with_normals && r.points.normals.size() != r.points.xyz.size())
    throw Error(cat(in_quotes(path), ": internal error: normals missing in a tile"));
  return r;
}

}  // namespace

Tiled_report visit_tiles(const std::string& path, const Read_options& options, const Scanned_input& input,
                         const Tiling& tiling, const Tile_visitor& visit)
{
  Tiled_report report;
  const std::size_t attribute_count = options.keep_attributes ? input.cloud.attributes.size() : 0;
  double lo[3], hi[3];
  tile_box(input, lo, hi);
  double first_halo = tiling.neighbors > 0 ? density_halo(input, tiling.neighbors) : tiling.halo;
  if(std::isnan(first_halo))
    first_halo = HUGE_VAL;  // (the whole cloud: never wrong)

  // 1. The density, and the tiles: the largest tiles whose points with their halo fit.
  const auto density_start = std::chrono::steady_clock::now();
  const Density_grid density = read_density(path, options, lo, hi, tiling);
  report.density_seconds = seconds_since(density_start);
  const double budget =
    tiling.memory_limit / (tiling.point_bytes > 0 ? tiling.point_bytes : bytes_per_point(attribute_count));
  const PSC::Tile_grid grid = choose_tile_grid(density, lo, hi, first_halo, budget, tiling, report);

  // The tiles visited: those whose core holds a point by the density (and the first tile, which
  // also writes the rows of the non-finite points), with their own points by the density.
  std::vector<std::size_t> visited;
  std::vector<double> own_points;
  for(std::size_t t = 0; t < grid.size(); ++t)
  {
    double b[3], e[3];
    tile_box(grid, t, lo, hi, 0, b, e);
    const double own = double(density.at_most(b, e));
    if(t == 0 || own > 0)
    {
      visited.push_back(t);
      own_points.push_back(own);
    }
  }
  if(tiling.grid_chosen)
    tiling.grid_chosen(visited.size(), report.few_tiles_grid, report.few_tiles_points);

  // 2. The tiles, each read from the file with its halo and visited. Non-finite points are
  // nobody's own: the first tile takes them as its own. One progress line for the pass, its
  // fraction in proportion to the time expected (tile_pass_progress.h).
  Tile_pass_progress pass_progress(own_points, report.density_seconds);
  const Progress pass = tiling.phase(tiling.estimate_phase);
  const auto step = [&](const std::string& name) {
    if(tiling.step)
      tiling.step(name);
  };
  const Progress step_progress = pass ? Progress([&](double f) { return pass(pass_progress.at(f)); }) : Progress();
  for(std::size_t v = 0; v < visited.size(); ++v)
  {
    const std::size_t t = visited[v];
    const std::string name = cat("tile ", t + 1, "/", grid.size());
    // each tile grows its own (by count: an outlier needs a large one; the first from the
    // density around its core)
    double halo = tiling.neighbors > 0 && std::isfinite(first_halo)
                    ? tile_first_halo(grid, t, density, lo, hi, tiling.neighbors, first_halo / 8)
                    : first_halo;
    for(;;)
    {
      const PSC::Tile tile = grid.tile(t, halo);
      PSC::Tile_range gathered(tile);  // the range's rules (the library's, as Dask's)
      const auto read_start = std::chrono::steady_clock::now();
      pass_progress.begin_read(v);
      step(name + " read");
      Tile_read read = read_tile(path, options, input, tiling, grid, t, tile, lo, hi, density, gathered, step_progress);
      report.read_seconds += seconds_since(read_start);
      if(read.own_count == 0)
      {
        pass_progress.end_tile(false);
        break;
      }
      const auto estimate_start = std::chrono::steady_clock::now();
      const std::size_t range = read.points.size();
      // A range holding every finite point is the whole cloud, whatever the halo's value: an
      // infinite halo says so to the estimator.
      halo = gathered.halo(input.finite);
      const bool whole_cloud = std::isinf(halo);
      try
      {
        pass_progress.begin_estimation(v);
        step(name + " " + tiling.estimate_phase);
        visit(read.points, read.own, grid.tile(t, halo), step_progress);
      }
      catch(const PSC::Halo_too_small& e)
      {
        if(whole_cloud)
          throw;  // (the estimator broke its promise: an internal error)
        // At least to the nearest point left out, so that the range grows at every retry (a
        // required halo may not change the range: twice the halo when it holds fewer points
        // than a neighbourhood, or a sum of halos rounded down to this one).
        halo = gathered.retry_halo(e);
        ++report.halo_growths;
        report.estimate_seconds += seconds_since(estimate_start);
        if(tiling.interrupted && tiling.interrupted())
          throw Cancelled();
        continue;  // read the tile again with the larger halo
      }
      report.estimate_seconds += seconds_since(estimate_start);
      pass_progress.end_tile();
      report.largest_range = std::max(report.largest_range, range);
      report.halo = std::max(report.halo, halo);
      ++report.tiles;
      break;
    }
    if(tiling.interrupted && tiling.interrupted())
      throw Cancelled();
  }
  return report;
}

Tiled_report run_tiled(const std::string& path, const Read_options& options, const Scanned_input& input,
                       const Tiling& tiling, const Tile_estimator& estimate,
                       const std::function<void(std::size_t, const Output_row&)>& own_row,
                       const std::function<void(const Row_source&)>& write)
{
  // 1. The tiles, each estimated and its own rows written to a temporary file.
  const std::size_t attribute_count = input.cloud.attributes.size();
  Row_store store(tiling.temporary_prefix + "tiles-", attribute_count);
  double rows_seconds = 0;
  Tiled_report report = visit_tiles(
    path, options, input, tiling,
    [&](Tile_points& points, const std::vector<char>& own, const PSC::Tile& tile, const Progress& progress) {
      const Row_source rows = estimate(points, tile, progress);
      const auto rows_start = std::chrono::steady_clock::now();
      store.begin_segment();
      Output_row r;
      std::vector<double> values(attribute_count);
      for(std::size_t k = 0; k < points.size(); ++k)
      {
        if(!own[k])
          continue;
        if(k % 65536 == 65535 && tiling.interrupted && tiling.interrupted())
          throw Cancelled();
        rows(k, r);
        for(std::size_t a = 0; a < attribute_count; ++a)
          values[a] = points.attributes[a][k];
        store.put(points.index[k], r, values.data());
        own_row(points.index[k], r);
      }
      rows_seconds += seconds_since(rows_start);
    });
  report.rows_seconds = rows_seconds;
  report.estimate_seconds -= rows_seconds;

  // 2. The rows in input order: a merge of the tiles' segments, each sorted by input index,
  // read through buffers that share half the memory limit (1 MB each at most, 16 rows at least).
  store.finish();
  const std::size_t segments = store.segments();
  const double share = tiling.memory_limit / 2 / double(std::max<std::size_t>(1, segments));
  const std::size_t buffered =
    std::size_t(std::max(16.0, std::min(share, double(1 << 20)) / double(store.record_bytes())));
  struct Head
  {
    std::uint64_t index;
    std::size_t segment;
    bool operator<(const Head& h) const { return index > h.index; }  // smallest on top
  };
  std::priority_queue<Head> heads;
  std::vector<Row_store::Cursor> cursors;
  cursors.reserve(segments);
  std::vector<Output_row> head_row(segments);
  std::vector<std::vector<double>> head_values(segments);
  for(std::size_t f = 0; f < segments; ++f)
  {
    cursors.emplace_back(store, f, buffered);
    std::uint64_t index;
    if(cursors[f].get(index, head_row[f], head_values[f]))
      heads.push(Head{index, f});
  }
  std::vector<double> current_values(attribute_count);
  write([&](std::size_t i, Output_row& r) {
    if(heads.empty() || heads.top().index != i)
      throw Error(cat("internal error: row ", i, " is missing from the tiles"));
    const std::size_t f = heads.top().segment;
    heads.pop();
    r = head_row[f];
    current_values.swap(head_values[f]);
    r.attributes = current_values.data();
    std::uint64_t index;
    if(cursors[f].get(index, head_row[f], head_values[f]))
      heads.push(Head{index, f});
  });
  return report;
}

}  // namespace psc_tool
