// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The LAS writer (io/; the tool's LAS output): LAS 1.4 (ASPRS LAS 1.4 R15), the estimates
// as extra-bytes fields.
//
// The header is 375 bytes. For a LAS input, the point data record format is the input's
// (every standard field written back from the attributes that read_las.cpp read, whose
// las_field says which), its scale and offset, file source id, global encoding, project id,
// system identifier and variable length records are kept (its extra-bytes VLR replaced by
// the output's), and its extended VLRs are copied from the input file after the points (the
// waveform data packet record's start pointing to its copy). Otherwise the format is 6
// (return 1 of 1, the other fields 0), the offset of each coordinate the floor of its
// smallest value, the scale 0.001, or finer (a power of ten) when the extent is below
// 1000 units (at least a million steps across it), or coarser when the extent would
// overflow the 32-bit integers. A point whose coordinates are not finite is written at the
// offset, withheld.
//
// After the standard fields, every field of output_fields() but x y z is an extra-bytes
// field, described by one extra-bytes VLR (LASF_Spec, record 4, a 192-byte descriptor each):
// the estimates as double (data type 10) or float (9, --float) with no_data NaN (options bit
// 0), neighbors as int32 (6), valid as uchar (1); the input's extra bytes with their own
// descriptor (type, scale, offset, no_data; the name renamed as in output_fields()); other
// input values (PLY properties, text columns) in their types. --drop-attributes drops the
// input's extra bytes and other values (a LAS input's standard fields are its records: kept).
// The counts of points (64-bit, by return) and the bounds come from the points written; the
// legacy 32-bit counts are set for formats 0-5 when they fit, 0 otherwise.

#ifndef PSC_IO_WRITE_LAS_H
#define PSC_IO_WRITE_LAS_H

#include "psc_io/write_point_cloud.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace psc_tool {

struct Las_output_options
{
  std::shared_ptr<const Las_source> source;     // a LAS input's header and records, else null
  std::string input_path;                       // where the extended VLRs are copied from
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // the bounds of the input's finite points
  bool drop_attributes = false;                 // --drop-attributes
};

// The size of write_las()'s output (an upper bound when the input has an extra-bytes EVLR,
// which is not copied), to reserve it before the estimation.
std::uint64_t las_output_size(const Las_output_options& options, const std::vector<Output_field>& fields,
                              const std::vector<Attribute>& attributes, std::size_t n);

// Writes the n rows of `row` (asked for in order) with the columns `fields` (output_fields()
// of `attributes`) to `f`, a seekable file (the header is written again at the end). Returns
// warnings (points with non-finite coordinates, extended VLRs not copied). Throws Error
// when the fields do not fit in a LAS record.
std::vector<std::string> write_las(std::FILE* f, const Las_output_options& options,
                                   const std::vector<Output_field>& fields, const std::vector<Attribute>& attributes,
                                   std::size_t n, const std::function<void(std::size_t, Output_row&)>& row,
                                   const Progress& progress);

}  // namespace psc_tool

#endif
