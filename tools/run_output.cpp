// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See run_output.h.

#include "run_output.h"

#include "interruption.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace psc_tool {

namespace {

// Diverging colour map centred on 0 (Moreland's cool-warm end points): blue for negative,
// near-white at zero, red for positive, saturated beyond +-range.
std::array<unsigned char, 3> diverging_color(double v, double range)
{
  static const double blue[3] = {59, 76, 192}, white[3] = {221, 221, 221}, red[3] = {180, 4, 38};
  if(!std::isfinite(v))
    return {128, 128, 128};
  const double t = range > 0 ? std::max(-1.0, std::min(1.0, v / range)) : 0.0;
  const double* end = t < 0 ? blue : red;
  const double a = std::abs(t);
  std::array<unsigned char, 3> c;
  for(int i = 0; i < 3; ++i)
    c[i] = static_cast<unsigned char>(std::lround((1 - a) * white[i] + a * end[i]));
  return c;
}

// The output's format, columns and header comments, with colours by `color_quantity` (-1:
// none) over +-color_range.
Output_layout output_layout(const Options& o, const Estimation_settings& scale,
                            const std::vector<Attribute>& attributes, int color_quantity, double color_range)
{
  Output_layout layout;
  layout.format = lower_extension(o.output) == ".csv" ? Output_layout::CSV
                  : o.ascii                           ? Output_layout::ASCII_PLY
                                                      : Output_layout::BINARY_PLY;
  layout.comments.push_back(
    cat("point_set_curvatures method ", method_label(o, scale), ", ", scale_description(scale)));
  layout.comments.push_back(cat("input ", o.input));
  if(color_quantity >= 0)
    layout.comments.push_back(
      cat("colors: ", o.color, ", blue -", color_range, " white 0 red +", color_range, ", grey invalid"));
  layout.fields = output_fields(o.fields, o.float32, color_quantity >= 0, attributes, scale.automatic_largest > 0);
  layout.attributes = &attributes;
  if(layout.format != Output_layout::CSV)
  {
    // The input's 16-bit colours (LAS, or a PLY's ushort red green blue) as PLY viewers read
    // colours, 8 bits: CloudCompare 2.11 shows ushort red green blue as black. The high byte, or
    // the value itself where no value of the file exceeds 255 (8-bit colours stored in 16-bit
    // fields, as some LAS writers do). CSV and LAS output keep the 16 bits, and so do the
    // input's colours renamed input_red ... when --color writes the estimates' colours.
    bool wide = false;
    std::vector<Output_field*> colours;
    for(Output_field& f : layout.fields)
      if(f.source >= Output_field::ATTRIBUTE && f.type == Scalar_type::UINT16 &&
         (f.name == "red" || f.name == "green" || f.name == "blue"))
      {
        colours.push_back(&f);
        // (a NaN largest, unknown, is taken as 16 bits)
        wide = wide || !(attributes[f.source - Output_field::ATTRIBUTE].largest <= 255);
      }
    for(Output_field* f : colours)
    {
      f->type = Scalar_type::UINT8;
      f->shift = wide ? 8 : 0;
    }
  }
  layout.scalar_prefix = o.ply_scalar_names;
  if(!attributes.empty())
  {
    std::string kept;
    for(const Attribute& a : attributes)
      kept += (kept.empty() ? "" : " ") + a.name;
    layout.comments.push_back(cat("input attributes: ", kept));
  }
  return layout;
}

// "binary PLY of 20000 points": the output, for messages.
std::string output_description(const Output_layout& layout, std::size_t n)
{
  return cat(layout.format == Output_layout::CSV         ? "CSV"
             : layout.format == Output_layout::ASCII_PLY ? "ASCII PLY"
                                                         : "binary PLY",
             " of ", plural(n, "point"), ", ", plural(layout.fields.size(), "field"));
}

}  // namespace

void estimate_row(const Point_set& ps, const Estimates& estimates, std::size_t i, Output_row& r)
{
  const Point& p = ps.point(*(ps.begin() + i));
  fill_row(p.x(), p.y(), p.z(), estimates[i], r);
}

void reserve_output(const Options& o, Temporary_output& output, const std::vector<Attribute>& attributes, std::size_t n,
                    const Las_output_options* las)
{
  if(las)
  {
    const std::vector<Output_field> fields =
      output_fields(o.fields, o.float32, false, attributes, o.scale.automatic_largest > 0);
    output.reserve(las_output_size(*las, fields, attributes, n),
                   cat("LAS of ", plural(n, "point"), ", ", plural(fields.size(), "field")));
    return;
  }
  const Output_layout layout =
    output_layout(o, o.scale, attributes, o.color.empty() ? -1 : color_quantities().at(o.color), 0.0);
  output.reserve(output_size_bound(layout, n) + 1024, output_description(layout, n));
}

void write_output(const Run_context& c, Temporary_output& output, const Estimation_settings& scale,
                  const std::vector<Attribute>& attributes, std::size_t n, const Row_summary& summary,
                  const Row_source& rows, const Las_output_options* las)
{
  const Options& o = c.o;
  if(las)
  {
    // LAS 1.4, the estimates as extra bytes (write_las.h); no colours (refused in run());
    // the temporary file is created now, when writing starts
    const std::vector<Output_field> fields =
      output_fields(o.fields, o.float32, false, attributes, o.scale.automatic_largest > 0);
    std::FILE* file = output.open(las_output_size(*las, fields, attributes, n),
                                  cat("LAS of ", plural(n, "point"), ", ", plural(fields.size(), "field")));
    const std::vector<std::string> w = write_las(file, *las, fields, attributes, n, rows, c.progress.phase("writing"));
    c.warnings.insert(c.warnings.end(), w.begin(), w.end());
    c.progress.finish();
    if(interrupted)
      throw Cancelled();
    output.commit();
    return;
  }
  int color_quantity = -1;
  double color_range = 0;
  if(!o.color.empty())
  {
    color_quantity = color_quantities().at(o.color);
    if(summary.count(color_quantity) == 0)
      c.warnings.push_back(cat("--color ", o.color, ": no valid value (not estimated by method ", o.method->name,
                               "?); every point is grey"));
    color_range = summary.color_range(color_quantity);
  }
  const Output_layout layout = output_layout(o, scale, attributes, color_quantity, color_range);
  // the temporary file is created now, when writing starts
  std::FILE* file = output.open(output_size_bound(layout, n), output_description(layout, n));
  const int color_value = color_quantity >= 0 ? summary_quantities::value_index[std::size_t(color_quantity)] : -1;
  write_point_cloud(
    file, layout, n,
    [&](std::size_t i, Output_row& r) {
      rows(i, r);
      if(color_value >= 0)
      {
        const std::array<unsigned char, 3> rgb =
          diverging_color(r.valid() ? r.value[color_value] : std::nan(""), color_range);
        std::copy(rgb.begin(), rgb.end(), r.color);
      }
    },
    c.progress.phase("writing"));
  c.progress.finish();
  if(interrupted)
    throw Cancelled();
  output.commit();
}

}  // namespace psc_tool
