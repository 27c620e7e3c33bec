// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Writes a large oriented cloud for the tool's runs at any size (issue 12): N points of the
// terrain z = 2 sin(x / 9) cos(y / 13) + 0.5 sin(x / 3 + y / 5) over the square [0, L]^2
// with L = sqrt(N) (one point per unit of area), x and y uniform at random, with the exact
// unit normals (upward), as a binary little-endian PLY of doubles x y z nx ny nz (48 bytes a
// point: 4.8 GB for 100M points). The points come in strips of 16 units along y, in random
// order within a strip, as an airborne scan comes in flight lines. At --radius 3.5 a point
// has about 38 neighbours.
//
//   large_cloud N OUTPUT.ply

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if(argc != 3)
  {
    std::fprintf(stderr, "usage: large_cloud N OUTPUT.ply\n");
    return 2;
  }
  const double n_value = std::strtod(argv[1], nullptr);
  if(!(n_value >= 1) || n_value > 1e10)
  {
    std::fprintf(stderr, "large_cloud: N must be a count between 1 and 1e10\n");
    return 2;
  }
  const std::uint64_t n = std::uint64_t(n_value);
  std::FILE* f = std::fopen(argv[2], "wb");
  if(!f)
  {
    std::fprintf(stderr, "large_cloud: cannot write %s\n", argv[2]);
    return 2;
  }
  std::fprintf(f,
               "ply\nformat binary_little_endian 1.0\ncomment large_cloud %llu: terrain z = 2 sin(x/9) cos(y/13) + "
               "0.5 sin(x/3 + y/5)\nelement vertex %llu\nproperty double x\nproperty double y\nproperty double "
               "z\nproperty double nx\nproperty double ny\nproperty double nz\nend_header\n",
               (unsigned long long)n, (unsigned long long)n);
  const double side = std::sqrt(double(n)), strip = 16;
  const std::uint64_t strips = std::uint64_t(std::ceil(side / strip));
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> buffer;
  buffer.reserve(6 * 65536);
  std::uint64_t written = 0;
  for(std::uint64_t s = 0; s < strips; ++s)
  {
    // the points of strip s: those up to the strip's end, as a share of n
    const double y0 = double(s) * strip, y1 = std::min(side, y0 + strip);
    const std::uint64_t until = s + 1 == strips ? n : std::uint64_t(double(n) * (y1 / side));
    for(; written < until; ++written)
    {
      const double x = side * unit(random), y = y0 + (y1 - y0) * unit(random);
      const double z = 2 * std::sin(x / 9) * std::cos(y / 13) + 0.5 * std::sin(x / 3 + y / 5);
      const double zx = 2.0 / 9 * std::cos(x / 9) * std::cos(y / 13) + 0.5 / 3 * std::cos(x / 3 + y / 5);
      const double zy = -2.0 / 13 * std::sin(x / 9) * std::sin(y / 13) + 0.5 / 5 * std::cos(x / 3 + y / 5);
      const double l = std::sqrt(zx * zx + zy * zy + 1);
      const double p[6] = {x, y, z, -zx / l, -zy / l, 1 / l};
      buffer.insert(buffer.end(), p, p + 6);
      if(buffer.size() == buffer.capacity())
      {
        std::fwrite(buffer.data(), sizeof(double), buffer.size(), f);
        buffer.clear();
      }
    }
  }
  std::fwrite(buffer.data(), sizeof(double), buffer.size(), f);
  if(std::fclose(f) != 0)
  {
    std::fprintf(stderr, "large_cloud: cannot write %s\n", argv[2]);
    return 2;
  }
  std::printf("large_cloud: %llu points written to %s\n", (unsigned long long)n, argv[2]);
  return 0;
}
