// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's writers (see write_point_cloud.h).

#include "write_point_cloud.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace psc_tool {

const char* const output_field_names[16] = {"x",      "y",      "z",      "nx",     "ny",     "nz",
                                            "k_min",  "k_max",  "mean",   "gaussian", "dmin_x", "dmin_y",
                                            "dmin_z", "dmax_x", "dmax_y", "dmax_z"};

namespace {

void put_text_double(std::FILE* f, double v)
{
  if(std::isnan(v))
    std::fputs("nan", f);
  else
    std::fprintf(f, "%.17g", v);
}

// One row of text output (ASCII PLY, CSV), values separated by `separator`.
void put_text_row(std::FILE* f, const Output_row& r, bool color, char separator)
{
  for(int a = 0; a < 16; ++a)
  {
    put_text_double(f, r.value[a]);
    std::fputc(separator, f);
  }
  std::fprintf(f, "%d%c%d", int(r.neighbors), separator, int(r.valid));
  if(color)
    std::fprintf(f, "%c%d%c%d%c%d", separator, int(r.color[0]), separator, int(r.color[1]), separator,
                 int(r.color[2]));
  std::fputc('\n', f);
}

bool little_endian_host()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <class T>
void put_binary(std::vector<char>& out, T v, bool swap)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  if(swap)
    std::reverse(bytes, bytes + sizeof(T));
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

void write_header(std::FILE* f, const Output_layout& layout, std::size_t n)
{
  if(layout.format == Output_layout::CSV)
  {
    for(const char* name : output_field_names)
      std::fprintf(f, "%s,", name);
    std::fputs(layout.color ? "neighbors,valid,red,green,blue\n" : "neighbors,valid\n", f);
    return;
  }
  std::fprintf(f, "ply\nformat %s 1.0\n", layout.format == Output_layout::ASCII_PLY ? "ascii" : "binary_little_endian");
  for(const std::string& c : layout.comments)
    std::fprintf(f, "comment %s\n", c.c_str());
  std::fprintf(f, "element vertex %zu\n", n);
  for(const char* name : output_field_names)
    std::fprintf(f, "property double %s\n", name);
  std::fputs("property int neighbors\nproperty uchar valid\n", f);
  if(layout.color)
    std::fputs("property uchar red\nproperty uchar green\nproperty uchar blue\n", f);
  std::fputs("end_header\n", f);
}

} // namespace

void write_point_cloud(std::FILE* f, const Output_layout& layout, std::size_t n,
                       const std::function<void(std::size_t, Output_row&)>& row, const Progress& progress)
{
  write_header(f, layout, n);
  const bool swap = !little_endian_host();
  const std::size_t step = std::max<std::size_t>(1, n / 100);
  std::vector<char> chunk;
  Output_row r;
  for(std::size_t i = 0; i < n; ++i)
  {
    row(i, r);
    if(layout.format == Output_layout::BINARY_PLY)
    {
      for(int a = 0; a < 16; ++a)
        put_binary(chunk, r.value[a], swap);
      put_binary(chunk, r.neighbors, swap);
      chunk.push_back(static_cast<char>(r.valid));
      if(layout.color)
        chunk.insert(chunk.end(), r.color, r.color + 3);
      if(chunk.size() > (1u << 20))
      {
        std::fwrite(chunk.data(), 1, chunk.size(), f);
        chunk.clear();
      }
    }
    else
      put_text_row(f, r, layout.color, layout.format == Output_layout::CSV ? ',' : ' ');
    if(progress && (i + 1) % step == 0 && !progress(double(i + 1) / double(n)))
      throw Cancelled();
  }
  if(!chunk.empty())
    std::fwrite(chunk.data(), 1, chunk.size(), f);
}

} // namespace psc_tool
