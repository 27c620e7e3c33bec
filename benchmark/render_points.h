// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A small point renderer for the benchmark's pictures (issue 5, experiment 5): every
// oriented point is drawn as a disc in its tangent plane (surface splatting with a depth
// buffer, orthographic camera, Lambert shading), coloured by a scalar through a diverging
// colour map, and the image is written as PNG by a minimal encoder (zlib stored blocks: no
// compression, no dependency). gnuplot then assembles the panels with titles and a colour
// bar (compressed PNG).

#ifndef PSC_BENCHMARK_RENDER_POINTS_H
#define PSC_BENCHMARK_RENDER_POINTS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace render {

struct Rgb
{
  double r = 0, g = 0, b = 0;
};

class Image
{
public:
  Image(int width, int height, Rgb background = Rgb{1, 1, 1})
      : m_width(width), m_height(height), m_rgb(std::size_t(3) * width * height)
  {
    for(int y = 0; y < height; ++y)
      for(int x = 0; x < width; ++x)
        set(x, y, background);
  }
  int width() const { return m_width; }
  int height() const { return m_height; }
  // (0, 0) is the top-left pixel.
  void set(int x, int y, const Rgb& c)
  {
    unsigned char* p = &m_rgb[3 * (std::size_t(y) * m_width + x)];
    p[0] = to_byte(c.r);
    p[1] = to_byte(c.g);
    p[2] = to_byte(c.b);
  }
  const std::vector<unsigned char>& bytes() const { return m_rgb; }

  // 8-bit RGB PNG, filter 0 on every row, deflate stored blocks.
  void write_png(const std::string& file) const
  {
    std::vector<unsigned char> raw;
    raw.reserve(m_rgb.size() + m_height);
    for(int y = 0; y < m_height; ++y)
    {
      raw.push_back(0);
      raw.insert(raw.end(), m_rgb.begin() + 3 * std::size_t(y) * m_width,
                 m_rgb.begin() + 3 * std::size_t(y + 1) * m_width);
    }
    std::vector<unsigned char> z = {0x78, 0x01};  // zlib header: deflate, 32K window, no dict
    for(std::size_t pos = 0; pos < raw.size() || raw.empty();)
    {
      const std::size_t len = std::min<std::size_t>(65535, raw.size() - pos);
      const bool last = pos + len == raw.size();
      z.push_back(last ? 1 : 0);  // BFINAL, BTYPE = 00 (stored)
      z.push_back(len & 0xff);
      z.push_back(len >> 8);
      z.push_back(~len & 0xff);
      z.push_back((~len >> 8) & 0xff);
      z.insert(z.end(), raw.begin() + pos, raw.begin() + pos + len);
      pos += len;
      if(last)
        break;
    }
    std::uint32_t a = 1, b = 0;  // Adler-32 of the uncompressed data
    for(unsigned char c : raw)
    {
      a = (a + c) % 65521;
      b = (b + a) % 65521;
    }
    put32(z, (b << 16) | a);

    std::vector<unsigned char> ihdr;
    put32(ihdr, std::uint32_t(m_width));
    put32(ihdr, std::uint32_t(m_height));
    ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, filter 0, no interlace

    std::ofstream out(file, std::ios::binary);
    if(!out)
      throw std::runtime_error("cannot write " + file);
    const unsigned char signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    out.write(reinterpret_cast<const char*>(signature), 8);
    write_chunk(out, "IHDR", ihdr);
    write_chunk(out, "IDAT", z);
    write_chunk(out, "IEND", {});
  }

private:
  static unsigned char to_byte(double v)
  {
    return static_cast<unsigned char>(std::lround(255 * std::min(1.0, std::max(0.0, v))));
  }
  static void put32(std::vector<unsigned char>& v, std::uint32_t x)
  {
    for(int s = 24; s >= 0; s -= 8)
      v.push_back((x >> s) & 0xff);
  }
  static std::uint32_t crc32(const unsigned char* data, std::size_t n, std::uint32_t crc)
  {
    static const std::array<std::uint32_t, 256> table = [] {
      std::array<std::uint32_t, 256> t{};
      for(std::uint32_t i = 0; i < 256; ++i)
      {
        std::uint32_t c = i;
        for(int k = 0; k < 8; ++k)
          c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
        t[i] = c;
      }
      return t;
    }();
    for(std::size_t i = 0; i < n; ++i)
      crc = table[(crc ^ data[i]) & 0xff] ^ (crc >> 8);
    return crc;
  }
  static void write_chunk(std::ofstream& out, const char* type, const std::vector<unsigned char>& data)
  {
    std::vector<unsigned char> head;
    put32(head, std::uint32_t(data.size()));
    out.write(reinterpret_cast<const char*>(head.data()), 4);
    out.write(type, 4);
    out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
    std::uint32_t crc = crc32(reinterpret_cast<const unsigned char*>(type), 4, 0xffffffffu);
    crc = crc32(data.data(), data.size(), crc) ^ 0xffffffffu;
    std::vector<unsigned char> tail;
    put32(tail, crc);
    out.write(reinterpret_cast<const char*>(tail.data()), 4);
  }

  int m_width, m_height;
  std::vector<unsigned char> m_rgb;
};

// Diverging map blue - light grey - red for signed curvature in [-range, range] (values
// beyond are clamped). The same anchors are given to gnuplot for the colour bar
// (diverging_palette_gnuplot). NaN (no estimate) is dark green, visible on both sides.
inline Rgb diverging_color(double v, double range)
{
  if(!std::isfinite(v))
    return Rgb{0.1, 0.45, 0.1};
  static const Rgb lo{0.23, 0.30, 0.75}, mid{0.87, 0.87, 0.87}, hi{0.71, 0.02, 0.15};
  const double t = std::max(-1.0, std::min(1.0, v / range));
  const Rgb& end = t < 0 ? lo : hi;
  const double s = std::abs(t);
  return Rgb{mid.r + s * (end.r - mid.r), mid.g + s * (end.g - mid.g), mid.b + s * (end.b - mid.b)};
}

inline const char* diverging_palette_gnuplot()
{
  return "set palette defined (-1 '#3b4cbf', 0 '#dddddd', 1 '#b50526')";
}

// Orthographic camera: `right`, `up` and `toward_viewer` form an orthonormal frame.
struct View
{
  std::array<double, 3> right{{1, 0, 0}}, up{{0, 1, 0}}, toward_viewer{{0, 0, 1}};

  // Camera looking along -toward_viewer with `up_hint` projected as the vertical.
  static View looking_from(std::array<double, 3> toward, std::array<double, 3> up_hint)
  {
    View v;
    normalize(toward);
    const double d = dot(up_hint, toward);
    for(int i = 0; i < 3; ++i)
      up_hint[i] -= d * toward[i];
    normalize(up_hint);
    v.toward_viewer = toward;
    v.up = up_hint;
    v.right = {{up_hint[1] * toward[2] - up_hint[2] * toward[1], up_hint[2] * toward[0] - up_hint[0] * toward[2],
                up_hint[0] * toward[1] - up_hint[1] * toward[0]}};
    return v;
  }
  static double dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  static void normalize(std::array<double, 3>& a)
  {
    const double l = std::sqrt(dot(a, a));
    for(double& x : a)
      x /= l;
  }
};

struct Splat
{
  std::array<double, 3> position, normal;
  Rgb color;
  double radius = 0;  // world units
};

// Draws every splat as a disc of its radius (world units) in the plane through
// its position orthogonal to its normal; nearest surface wins (depth buffer). Splats whose
// normal faces away from the viewer are skipped (back faces). The cloud is scaled to fill
// the image with a small margin. Shading: 0.35 ambient + 0.65 Lambert, light from the
// upper left of the viewer.
inline Image render_splats(const std::vector<Splat>& splats, const View& view, int width, int height)
{
  Image image(width, height);
  if(splats.empty())
    return image;
  struct Projected
  {
    double x, y, z, nx, ny, nz;
  };
  std::vector<Projected> proj(splats.size());
  double lo[2] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  double hi[2] = {-lo[0], -lo[1]};
  for(std::size_t i = 0; i < splats.size(); ++i)
  {
    const Splat& s = splats[i];
    Projected& p = proj[i];
    p.x = View::dot(s.position, view.right);
    p.y = View::dot(s.position, view.up);
    p.z = View::dot(s.position, view.toward_viewer);
    p.nx = View::dot(s.normal, view.right);
    p.ny = View::dot(s.normal, view.up);
    p.nz = View::dot(s.normal, view.toward_viewer);
    lo[0] = std::min(lo[0], p.x);
    hi[0] = std::max(hi[0], p.x);
    lo[1] = std::min(lo[1], p.y);
    hi[1] = std::max(hi[1], p.y);
  }
  const double margin = 0.04;
  const double scale = std::min(width * (1 - 2 * margin) / std::max(1e-300, hi[0] - lo[0]),
                                height * (1 - 2 * margin) / std::max(1e-300, hi[1] - lo[1]));
  const double ox = 0.5 * (width - scale * (hi[0] - lo[0])), oy = 0.5 * (height - scale * (hi[1] - lo[1]));
  std::vector<double> depth(std::size_t(width) * height, -std::numeric_limits<double>::max());
  std::array<double, 3> light{{-0.35, 0.45, 1}};
  View::normalize(light);
  for(std::size_t i = 0; i < splats.size(); ++i)
  {
    const Projected& p = proj[i];
    const double R = splats[i].radius * scale;  // in pixels
    const double nl = std::sqrt(p.nx * p.nx + p.ny * p.ny + p.nz * p.nz);
    if(!(nl > 0) || p.nz <= 0)
      continue;
    const double nx = p.nx / nl, ny = p.ny / nl, nz = std::max(0.25, p.nz / nl);
    const double shade = 0.35 + 0.65 * std::max(0.0, nx * light[0] + ny * light[1] + (p.nz / nl) * light[2]);
    const Rgb c{splats[i].color.r * shade, splats[i].color.g * shade, splats[i].color.b * shade};
    const double cx = ox + scale * (p.x - lo[0]), cy = height - (oy + scale * (p.y - lo[1]));
    const int x0 = std::max(0, int(std::floor(cx - R))), x1 = std::min(width - 1, int(std::ceil(cx + R)));
    const int y0 = std::max(0, int(std::floor(cy - R))), y1 = std::min(height - 1, int(std::ceil(cy + R)));
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x)
      {
        // pixel centre in the splat's plane, in pixel units relative to the centre
        const double dx = x + 0.5 - cx, dy = -(y + 0.5 - cy);
        const double dz = -(nx * dx + ny * dy) / nz;
        if(dx * dx + dy * dy + dz * dz > R * R)
          continue;
        const double z = p.z * scale + dz;
        double& d = depth[std::size_t(y) * width + x];
        if(z > d)
        {
          d = z;
          image.set(x, y, c);
        }
      }
  }
  return image;
}

}  // namespace render

#endif
