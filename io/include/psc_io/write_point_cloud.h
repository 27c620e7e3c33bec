// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The writers (io/; the tool's PLY and CSV output): binary or ASCII PLY, or CSV with a
// header line, one row per input point in input order, with the columns chosen by
// output_fields(). The rows come from a callback; their fields are those of the package's
// table (field_descriptions.h).

#ifndef PSC_IO_WRITE_POINT_CLOUD_H
#define PSC_IO_WRITE_POINT_CLOUD_H

#include "psc_io/read_point_cloud.h"
#include "psc_io/support.h"

#include <CGAL/Point_set_curvatures/field_descriptions.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace psc_tool {

// A value converted to an integer type: rounded, clamped to the type's range, 0 for NaN.
template <class T>
T to_integer(double v)
{
  if(std::isnan(v))
    return 0;
  v = std::nearbyint(v);
  if(v <= double(std::numeric_limits<T>::min()))
    return std::numeric_limits<T>::min();
  if(v >= double(std::numeric_limits<T>::max()))
    return std::numeric_limits<T>::max();
  return static_cast<T>(v);
}

// Calls f(d) for every field d of the package's table that the tool writes
// (CGAL::Point_set_curvatures::field_descriptions, those with a name), in the table's order.
template <class F>
constexpr void for_each_tool_field(const F& f)
{
  for(const CGAL::Point_set_curvatures::Field_description& d : CGAL::Point_set_curvatures::field_descriptions)
    if(d.name)
      f(d);
}

// The values of a row, in order: x y z, then every field that the tool writes, as doubles
// (counts and flags too: exact), whatever the columns chosen; then, with colours, red green
// blue (uchar). A value is found by its field's name (output_value_index()), never by position.
namespace output_values {
constexpr int count_fields()
{
  int n = 0;
  for_each_tool_field([&n](const CGAL::Point_set_curvatures::Field_description&) { ++n; });
  return n;
}
}  // namespace output_values
constexpr int output_value_count = 3 + output_values::count_fields();

// The index in Output_row::value of the field named `name` ("x", "y", "z" 0 to 2), or -1.
constexpr int output_value_index(std::string_view name)
{
  const std::size_t row = CGAL::Point_set_curvatures::field_index(name);
  if(row == CGAL::Point_set_curvatures::field_count)
  {
    const std::string_view xyz[] = {"x", "y", "z"};
    for(int a = 0; a < 3; ++a)
      if(name == xyz[a])
        return a;
    return -1;
  }
  int index = 3;
  for(std::size_t i = 0; i < row; ++i)
    index += CGAL::Point_set_curvatures::field_descriptions[i].name ? 1 : 0;
  return index;
}

struct Output_row
{
  double value[output_value_count];
  unsigned char color[3] = {0, 0, 0};
  int status = 0;  // the estimate's status (CGAL::Curvature_estimate_status), for the summary
  // The row's attribute values in the order of Output_layout::attributes, or null: then
  // value i of each attribute is row i's (the tool's tiled runs give each row its own).
  const double* attributes = nullptr;

  bool valid() const
  {
    static constexpr int at = output_value_index("valid");
    return value[at] != 0;
  }
  std::int32_t neighbors() const
  {
    static constexpr int at = output_value_index("neighbors");
    return to_integer<std::int32_t>(value[at]);
  }
};

// Fills the values of row `r` with the point (x, y, z) and its estimate `e` (a
// CGAL::Curvature_estimate), every field of the table, and its status.
template <class Estimate>
void fill_row(double x, double y, double z, const Estimate& e, Output_row& r)
{
  r.value[0] = x;
  r.value[1] = y;
  r.value[2] = z;
  int v = 3;  // (the table's order: output_value_index())
  for_each_tool_field([&](const CGAL::Point_set_curvatures::Field_description& f) {
    r.value[v++] = CGAL::Point_set_curvatures::field_value(e, f);
  });
  r.status = static_cast<int>(e.status);
}

// One column of the output: its name, its type, and where its value comes from.
struct Output_field
{
  enum Source { VALUE = 0, COLOR = output_value_count, ATTRIBUTE = 100 };
  static_assert(COLOR + 3 <= ATTRIBUTE, "the values and colours of a row must stay below ATTRIBUTE");
  std::string name;
  Scalar_type type = Scalar_type::FLOAT64;
  int source = 0;  // VALUE + i: Output_row::value[i]; COLOR + c; ATTRIBUTE + j: attribute j
  // an attribute written as its value divided by 2^shift, rounded down (16-bit colours as 8)
  int shift = 0;
};

struct Output_layout
{
  enum Format { BINARY_PLY, ASCII_PLY, CSV } format = BINARY_PLY;
  std::vector<Output_field> fields;                    // the columns, in order (output_fields())
  const std::vector<Attribute>* attributes = nullptr;  // for Output_field::ATTRIBUTE + j
  std::vector<std::string> comments;                   // PLY header comments
  // --ply-names scalar: PLY properties other than x y z nx ny nz red green blue are named
  // scalar_NAME, the names CloudCompare loads as scalar fields NAME (ply_property_names()).
  bool scalar_prefix = false;
};

// The PLY property names of the layout's fields: their names, or with scalar_prefix each
// name but x y z nx ny nz red green blue as scalar_NAME (a name already beginning with
// scalar_, such as an attribute of a PLY written by CloudCompare, is kept unless another
// field has it); unique.
std::vector<std::string> ply_property_names(const Output_layout& layout);

// The names --fields accepts, for messages.
const char* selectable_fields();

// Parses a --fields value ("k_min,k_max,mean"): the estimator fields to write, each the name
// of a field or the group of a vector's components ("normal": nx ny nz, "dmin", "dmax").
// Throws Error for an unknown name.
std::vector<std::string> parse_fields(const std::string& text);

// The columns of the output: x y z (always, in double: coordinates near 1e6 need it), then the
// selected fields (all if `selected` is empty) in the order of the table, real ones as float32
// if `float32`, counts as int32 and flags as uchar (those of the automatic scale only with
// `automatic_scale`), red green blue with `color`, then the input's attributes in their own
// types (renamed input_NAME when NAME is one of the tool's fields, selected or not, or red green
// blue with `color`).
std::vector<Output_field> output_fields(const std::vector<std::string>& selected, bool float32, bool color,
                                        const std::vector<Attribute>& attributes, bool automatic_scale);

// The size of the file write_point_cloud() writes for `n` rows: exact for binary PLY, an
// upper bound for the text formats (every number at its widest: "-2.2250738585072014e-308").
std::uint64_t output_size_bound(const Output_layout& layout, std::size_t n);

// Writes `n` rows, row(i, r) filling row i. Progress: the fraction of rows written, about
// every 1%; false cancels (Cancelled). Write errors are left to the caller (ferror).
void write_point_cloud(std::FILE* f, const Output_layout& layout, std::size_t n,
                       const std::function<void(std::size_t, Output_row&)>& row, const Progress& progress);

}  // namespace psc_tool

#endif
