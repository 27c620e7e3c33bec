// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's writers: binary or ASCII PLY, or CSV with a header line, one row per input
// point in input order, with the columns chosen by output_fields(). The rows come from a
// callback, so this file knows nothing of the estimators.

#ifndef POINT_SET_CURVATURES_TOOL_WRITE_POINT_CLOUD_H
#define POINT_SET_CURVATURES_TOOL_WRITE_POINT_CLOUD_H

#include "read_point_cloud.h"
#include "tool_support.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
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

// The doubles of a row, in order: x y z nx ny nz k_min k_max mean gaussian dmin_x dmin_y
// dmin_z dmax_x dmax_y dmax_z normal_coherence mean_error (written with the automatic scale
// only); then neighbors (int), valid (uchar) and, with colours, red green blue (uchar).
constexpr int output_value_count = 18;
constexpr int mean_error_value = 17;
extern const char* const output_field_names[output_value_count];

struct Output_row
{
  double value[output_value_count];
  std::int32_t neighbors = 0;
  unsigned char valid = 0;
  unsigned char color[3] = {0, 0, 0};
  int status = 0;  // the estimate's status (CGAL::Curvature_estimate_status), for the summary
  // The row's attribute values in the order of Output_layout::attributes, or null: then
  // value i of each attribute is row i's (the tool's tiled runs give each row its own).
  const double* attributes = nullptr;
};

// One column of the output: its name, its type, and where its value comes from.
struct Output_field
{
  enum Source { VALUE = 0, NEIGHBORS = output_value_count, VALID, COLOR, ATTRIBUTE = 100 };
  std::string name;
  Scalar_type type = Scalar_type::FLOAT64;
  int source = 0;  // VALUE + i: Output_row::value[i]; COLOR + c; ATTRIBUTE + j: attribute j
  // an attribute written as its value divided by 2^shift, rounded down (16-bit colours as 8)
  int shift = 0;
};

struct Output_layout
{
  enum Format { BINARY_PLY, ASCII_PLY, CSV } format = BINARY_PLY;
  std::vector<Output_field> fields;                  // the columns, in order (output_fields())
  const std::vector<Attribute>* attributes = nullptr;  // for Output_field::ATTRIBUTE + j
  std::vector<std::string> comments;                 // PLY header comments
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

// Parses a --fields value ("k_min,k_max,mean"): the estimator fields to write, each a name of
// output_field_names, "neighbors", "valid", or a group: "normal" (nx ny nz), "dmin", "dmax"
// (the three components). Throws Error for an unknown name.
std::vector<std::string> parse_fields(const std::string& text);

// The columns of the output: x y z (always, in double: coordinates near 1e6 need it), then the
// selected estimator fields (all if `selected` is empty) in the order of output_field_names,
// as float32 if `float32` (mean_error only with `automatic_scale`), neighbors and valid if
// selected, red green blue with `color`, then the input's attributes in their own types
// (renamed input_NAME when NAME is one of the tool's fields, selected or not, or red green
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

} // namespace psc_tool

#endif
