// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See tiled_normals.h.

#include "tiled_normals.h"

#include "interruption.h"

#include <CGAL/estimate_oriented_normals.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace psc_tool {

namespace PSC = CGAL::Point_set_curvatures;
typedef PSC::internal::Normal_record Normal_record;

namespace {

// The bytes per point of the file that the gathered arrays take while the tiles are estimated,
// and at their peak: with a spanning tree, the records and coordinates, then at the orientation
// also the oriented normals and the tree's graph (offsets, 24 neighbours of 4 bytes, the bucket
// queue's edges, arrays of a byte to 4 bytes per point: by_height, visited, piece, part; and
// the parity check's 29: its grid of at most 8 bytes a point, a part's scales and their sorted
// copy, the points it turns, the votes); otherwise the normals only.
double gathered_bytes(bool global) { return global ? double(sizeof(Normal_record)) + 24 : gathered_normal_bytes; }
double peak_bytes(bool global)
{
  return global ? gathered_bytes(true) + gathered_normal_bytes + 8 + 96 + 64 + 17 + 29 : gathered_normal_bytes;
}

}  // namespace

double least_memory_for_tiled_normals(double points, bool global)
{
  // with a spanning tree, the tiles have at least a fifth of the limit beside the gathered
  // arrays; the normals alone do not refuse a limit (the tiles then are as small as they get)
  return global ? 1.25 * points * peak_bytes(true) : 0;
}

Tiled_normals estimate_tiled_normals(const std::string& path, const Read_options& read_options,
                                     const Scanned_input& input, const Options& o, Orientation_choice& choice,
                                     Tiling tiling)
{
  const std::size_t n = std::size_t(input.points);
  const bool global = PSC::internal::is_global(choice.orientation);
  if(tiling.memory_limit < least_memory_for_tiled_normals(double(n), global))
    throw std::logic_error("estimate_tiled_normals: the memory limit is below least_memory_for_tiled_normals()");
  if(global && input.points > std::numeric_limits<std::uint32_t>::max())
    throw Error(cat("a spanning tree orients at most ", std::numeric_limits<std::uint32_t>::max(), " points (",
                    in_quotes(path), " holds ", input.points,
                    "): orient them locally, --orient +z (airborne scans), another axis, or viewpoint:X,Y,Z"));
  Tiled_normals result;
  std::vector<Normal_record> records(global ? n : 0);
  std::vector<double> xyz(global ? 3 * n : 0, std::numeric_limits<double>::quiet_NaN());
  if(!global)
    result.normals.assign(3 * n, 0.0);
  const std::array<int, 3> pulse = pulse_attributes(input.cloud.attributes);
  std::size_t gathered = 0;  // own points (every point once, the non-finite ones in the first tile)
  {
    // 1. Tile by tile, the normals of the tile's own points (their records with a spanning
    // tree): the tiles have what the gathered arrays leave of the limit; no attribute is read
    // but the pulse directions of --orient scanner.
    Read_options read = read_options;
    read.keep_attributes = choice.scanner;
    tiling.memory_limit = std::max(0.0, tiling.memory_limit - double(n) * gathered_bytes(global));
    tiling.point_bytes =
      bytes_per_point(choice.scanner ? input.cloud.attributes.size() : 0, normal_automatic_largest(o) > 0);
    tiling.neighbors = normal_largest_count(o);
    tiling.halo = 0;
    tiling.normals = nullptr;
    tiling.estimate_phase = "normals";
    tiling.grid_chosen = nullptr;
    result.report = visit_tiles(
      path, read, input, tiling,
      [&](Tile_points& points, const std::vector<char>& own, const PSC::Tile& tile, const Progress& progress) {
        Point_set ps;
        fill_point_set(ps, points.xyz, std::vector<double>());
        if(global)
        {
          const std::vector<Normal_record> tile_records = estimate_normal_records(ps, o, progress, tile);
          for(std::size_t k = 0; k < points.size(); ++k)
          {
            if(!own[k])
              continue;
            const std::size_t i = std::size_t(points.index[k]);
            ++gathered;  // (once the tile's estimate succeeded: a tile may be read again)
            std::copy(&points.xyz[3 * k], &points.xyz[3 * k] + 3, &xyz[3 * i]);
            Normal_record& r = records[i];
            r = tile_records[k];
            // the neighbours' indices in the file (they are within the tile's range)
            for(std::size_t e = 0; e < r.degree; ++e)
              r.neighbor[e] = static_cast<std::uint32_t>(points.index[r.neighbor[e]]);
          }
          return;
        }
        estimate_normals(ps, o, choice, progress, tile);
        if(choice.scanner)
          result.undirected += orient_towards_scanner(
            ps.size(), [&ps](std::size_t k) -> Vector& { return ps.normal(*(ps.begin() + k)); },
            [&](std::size_t k) {
              return std::array<double, 3>{
                {points.attributes[pulse[0]][k], points.attributes[pulse[1]][k], points.attributes[pulse[2]][k]}};
            },
            [&](std::size_t k) { return own[k] && ps.normal(*(ps.begin() + k)) != CGAL::NULL_VECTOR; });
        for(std::size_t k = 0; k < points.size(); ++k)
          if(own[k])
          {
            ++gathered;
            const Vector& v = ps.normal(*(ps.begin() + k));
            double* to = &result.normals[3 * std::size_t(points.index[k])];
            to[0] = v.x();
            to[1] = v.y();
            to[2] = v.z();
          }
      });
  }
  if(gathered != n)
    throw std::logic_error(cat("estimate_tiled_normals: ", gathered, " of the ", n, " points were in a tile"));
  if(!global)
    return result;

  // 2. Their orientation, as the library orients a whole cloud.
  const auto start = std::chrono::steady_clock::now();
  const Progress progress = tiling.phase("orientation");
  const bool oriented =
    PSC::internal::orient_normal_records(records, xyz, choice.orientation, result.normals,
                                         [&progress](double f) { return !interrupted && (!progress || progress(f)); });
  if(!oriented || interrupted)
    throw Cancelled();
  if(choice.orientation.kind == CGAL::Normal_orientation::AUTOMATIC)
  {
    Vertical_count count;
    for(std::size_t i = 0; i < n; ++i)
      count.add(result.normals[3 * i], result.normals[3 * i + 1], result.normals[3 * i + 2]);
    choice.text = automatic_orientation_text(count);
  }
  result.orientation_seconds = seconds_since(start);
  return result;
}

}  // namespace psc_tool
