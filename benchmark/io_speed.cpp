// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Speed of the tool's readers and writer (issue 12), linked from tools/: N points of a unit
// sphere with normals written as .xyz (x y z nx ny nz, 9 significant digits, as scanners
// export), binary PLY (6 doubles) and LAS 1.2 point format 3 (34 bytes, no normals); each file
// read with read_point_cloud() (best of 3, one thread: the readers are sequential) and the
// default output (binary PLY: x y z and the fields of the table, field_descriptions.h)
// written with write_point_cloud().
// Then the share of reading and writing in a whole run as the tool does it on the binary PLY:
// read + write against the default ASO by count (--neighbors 40, Parallel_tag), measured in
// this process. Prints MB/s and the ratios; asserts nothing.
//
// usage: io_speed [number_of_points=1000000] [folder=/tmp]

#include "bench_support.h"

#include "psc_io/read_point_cloud.h"
#include "psc_io/write_point_cloud.h"

#include <CGAL/estimate_aso_curvatures.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

double best_of_3(const std::function<void()>& f)
{
  double best = 1e300;
  for(int i = 0; i < 3; ++i)
  {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, psc_bench::seconds_since(t0));
  }
  return best;
}

double file_megabytes(const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if(!f)
    return 0;
  std::fseek(f, 0, SEEK_END);
  const double size = double(std::ftell(f));
  std::fclose(f);
  return size / 1e6;
}

}  // namespace

int main(int argc, char** argv)
{
  using namespace psc_test;
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
  const std::string folder = argc > 2 ? argv[2] : "/tmp";
  const std::vector<Oriented_point> pts = sphere(n, 1.0);

  const std::string xyz = folder + "/psc_io_speed.xyz", ply = folder + "/psc_io_speed.ply",
                    las = folder + "/psc_io_speed.las", out = folder + "/psc_io_speed_out.ply";
  {
    std::FILE* f = std::fopen(xyz.c_str(), "wb");
    for(const Oriented_point& p : pts)
      std::fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g\n", p.first.x(), p.first.y(), p.first.z(), p.second.x(),
                   p.second.y(), p.second.z());
    std::fclose(f);
    f = std::fopen(ply.c_str(), "wb");
    std::fprintf(f,
                 "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty double x\nproperty double y\n"
                 "property double z\nproperty double nx\nproperty double ny\nproperty double nz\nend_header\n",
                 n);
    for(const Oriented_point& p : pts)
    {
      const double v[6] = {p.first.x(), p.first.y(), p.first.z(), p.second.x(), p.second.y(), p.second.z()};
      std::fwrite(v, sizeof(double), 6, f);
    }
    std::fclose(f);
    const double offset[3] = {0, 0, 0};
    const std::string bytes = las_file(pts, 3, 2, 1e-6, offset);
    f = std::fopen(las.c_str(), "wb");
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
  }

  std::printf("%zu points on a unit sphere, one thread\n\n| file | MB | read (s) | MB/s |\n|---|---|---|---|\n", n);
  psc_tool::Point_cloud cloud;
  double ply_read = 0;
  for(const std::string& path : {xyz, ply, las})
  {
    const double s = best_of_3([&]() { cloud = psc_tool::read_point_cloud(path, psc_tool::Read_options()); });
    if(path == ply)
      ply_read = s;
    std::printf("| %s | %.1f | %.3f | %.0f |\n", path.substr(path.size() - 4).c_str(), file_megabytes(path), s,
                file_megabytes(path) / s);
  }

  // the tool's default output, rows from a precomputed estimate
  cloud = psc_tool::read_point_cloud(ply, psc_tool::Read_options());
  const auto t0 = std::chrono::steady_clock::now();
  const auto estimates = CGAL::estimate_aso_curvatures<CGAL::Parallel_tag>(
    pts, CGAL::Point_set_curvatures::parameters::neighbor_count(
           40, CGAL::parameters::point_map(Point_map()).normal_map(Normal_map())));
  const double estimate_seconds = psc_bench::seconds_since(t0);
  psc_tool::Output_layout layout;
  layout.fields = psc_tool::output_fields({}, false, false, cloud.attributes, false);
  layout.attributes = &cloud.attributes;
  const double write_seconds = best_of_3([&]() {
    std::FILE* f = std::fopen(out.c_str(), "wb");
    psc_tool::write_point_cloud(
      f, layout, n,
      [&](std::size_t i, psc_tool::Output_row& r) {
        psc_tool::fill_row(pts[i].first.x(), pts[i].first.y(), pts[i].first.z(), estimates[i], r);
      },
      psc_tool::Progress());
    std::fclose(f);
  });
  std::printf("| write binary PLY (17 doubles, int, uchar) | %.1f | %.3f | %.0f |\n", file_megabytes(out),
              write_seconds, file_megabytes(out) / write_seconds);
  const double io = ply_read + write_seconds;
  std::printf("\nbinary PLY in and out: read %.3f s + write %.3f s against ASO (--neighbors 40, Parallel_tag) "
              "%.3f s: reading and writing are %.1f%% of the total\n",
              ply_read, write_seconds, estimate_seconds, 100 * io / (io + estimate_seconds));
  for(const std::string& path : {xyz, ply, las, out})
    std::remove(path.c_str());
  return 0;
}
