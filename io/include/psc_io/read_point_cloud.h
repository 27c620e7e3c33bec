// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The package's readers (io/: the tool, Python, the benchmarks): one validating pass over
// the file, no third-party reader. A file is either read completely and exactly as its
// header or columns say, or refused with an Error whose message names the file, the line or
// element, and what is wrong; nothing is read from a count in a header before it is checked
// against the bytes the file holds.
//
//   .xyz .pwn .txt .csv   one point per line, values separated by white space or by commas
//   .asc                  (.asc: CloudCompare's ASCII export, read alike);
//                         '#' comments; an optional point count alone on the first line; an
//                         optional header line of column names (x y z nx ny nz, normal_x...).
//                         Without names or --columns: 3 values (x y z) or 6 (x y z nx ny nz),
//                         the latter refused when its last three columns are not unit vectors
//                         (colours, say), with a message naming --columns.
//   .ply                  ASCII and binary (both endiannesses), any property order and scalar
//                         type, other elements and properties skipped; normals named nx ny nz
//                         or normal_x normal_y normal_z.
//   .off                  OFF or NOFF (normals), faces checked and ignored.
//   .las                  LAS 1.0-1.4, uncompressed, point data formats 0-10 (read_las.cpp);
//                         .laz is refused with a message. Extra-bytes fields described by
//                         an extra-bytes VLR (data types 1-10) are attributes too.
//
// With Read_options::keep_attributes, the values that are neither coordinates nor normals
// are kept as attributes: PLY vertex properties (lists skipped), text columns named by a
// header line or by --columns (except "_"), the LAS point fields.

#ifndef PSC_IO_READ_POINT_CLOUD_H
#define PSC_IO_READ_POINT_CLOUD_H

#include "psc_io/support.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace psc_tool {

// The scalar types of the attributes (those of PLY).
enum class Scalar_type { INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

// "char", "uchar", ..., "double": the PLY name of a type.
const char* ply_type_name(Scalar_type t);

// A per-point value of the input other than the coordinates and the normal (intensity,
// classification, colour, GPS time...), carried to the output. The values are held as
// doubles, which represent every value of every type exactly.
struct Attribute
{
  Attribute() = default;
  Attribute(std::string name_, Scalar_type type_) : name(std::move(name_)), type(type_) {}

  std::string name;
  Scalar_type type = Scalar_type::FLOAT64;
  std::vector<double> values;  // one per point
  // From a LAS file: the standard field of the point record it is (Las_field), or -1;
  // an extra-bytes field: its 192-byte descriptor as read (LAS 1.4 R15), else empty.
  int las_field = -1;
  std::string las_descriptor;
  // The largest value over every point of the file (set by the tool's first read,
  // read_or_scan(), in memory and in tiles alike; -inf without points, NaN until then).
  double largest = std::numeric_limits<double>::quiet_NaN();
};

// The standard fields of LAS point records, as read_las.cpp names them (the attributes'
// las_field).
enum Las_field {
  LAS_INTENSITY,
  LAS_RETURN_NUMBER,
  LAS_NUMBER_OF_RETURNS,
  LAS_SCAN_DIRECTION,
  LAS_EDGE,
  LAS_CLASSIFICATION,
  LAS_SYNTHETIC,
  LAS_KEY_POINT,
  LAS_WITHHELD,
  LAS_OVERLAP,
  LAS_SCANNER_CHANNEL,
  LAS_SCAN_ANGLE,
  LAS_USER_DATA,
  LAS_POINT_SOURCE,
  LAS_GPS_TIME,
  LAS_RED,
  LAS_GREEN,
  LAS_BLUE,
  LAS_NIR,
  LAS_WAVE_DESCRIPTOR,
  LAS_WAVE_OFFSET,
  LAS_WAVE_SIZE,
  LAS_WAVE_LOCATION,
  LAS_WAVE_X_T,
  LAS_WAVE_Y_T,
  LAS_WAVE_Z_T,
  LAS_FIELD_COUNT
};

// What a LAS input's output in LAS needs besides the points (write_las.cpp): the header,
// the variable length records, where the extended ones are.
struct Las_source
{
  std::string header;         // the public header block as read (its header size, at most 375 bytes kept)
  int minor = 0, format = 0;  // version 1.minor, point data record format
  double scale[3] = {1, 1, 1}, offset[3] = {0, 0, 0};
  struct Vlr
  {
    std::string user_id;  // 16 characters, NUL-padded
    int record_id = 0;
    std::string description;  // 32 characters, NUL-padded
    std::string payload;
  };
  std::vector<Vlr> vlrs;      // in file order (every one, the extra bytes' included)
  bool vlrs_complete = true;  // false: the records between the header and the points did not parse
  // the extended variable length records (LAS 1.4; the waveform record of LAS 1.3), as
  // (offset, size with their 60-byte header) in the input file
  std::vector<std::pair<std::uint64_t, std::uint64_t>> evlrs;
  std::uint64_t waveform_start = 0;  // the header's start of the waveform data packet record
};

struct Point_cloud
{
  std::vector<double> xyz;                // 3 per point, in file order
  std::vector<double> normals;            // 3 per point, or empty when the file has none
  std::string normals_source;             // where the normals came from, for messages
  std::vector<Attribute> attributes;      // empty unless Read_options::keep_attributes
  std::vector<std::string> warnings;      // file problems that do not prevent reading it
  std::shared_ptr<const Las_source> las;  // a LAS input's header and records, else null
  // With Read_options::chunk: the input index of the first point held (the points before it
  // were handed over); 0 otherwise.
  std::size_t first = 0;

  // the points held
  std::size_t size() const { return xyz.size() / 3; }
  // the points read so far: those handed over in chunks and those held
  std::size_t total() const { return first + size(); }
  bool has_normals() const { return !normals_source.empty(); }
};

struct Read_options
{
  // --columns: one name per value of a text line: x, y, z, nx, ny, nz (or normal_x, ...),
  // anything else (for example _ or r) for a value that is skipped. Empty: automatic.
  std::vector<std::string> columns;
  // Keep the other values of each point (PLY properties, named text columns, LAS fields).
  bool keep_attributes = true;
  // Called with the fraction of the file read, about every 1%; false cancels (Cancelled).
  Progress progress;
  // Reading in chunks (the tool's tiles, for files larger than memory): when set, the points
  // are handed to `chunk` in input order, `chunk_points` at a time or more (the last chunk
  // fewer), and removed from the cloud; the cloud that read_point_cloud() returns then holds
  // no points but the file's description (normals_source, attribute names and types,
  // warnings; total() is the point count). The file is still checked completely: an Error
  // may come after chunks were handed over. .off files come in one chunk.
  std::function<void(const Point_cloud&)> chunk;
  std::size_t chunk_points = std::size_t(1) << 20;
  // --allow-truncated: a LAS file whose last records are missing is read up to its last
  // complete record, with a warning (refused otherwise).
  bool allow_truncated = false;
};

// The formats read_point_cloud() understands, for messages: ".xyz, .pwn, .txt, .csv, .ply, .off or .las".
const char* readable_formats();

// Parses a --columns value ("x,y,z,_,_,_,nx,ny,nz"); throws Error if it lacks x, y or z,
// names a coordinate twice, or names only some of nx, ny, nz.
std::vector<std::string> parse_columns(const std::string& text);

// Reads `path` (a regular file) by its extension. Throws Error for anything malformed,
// Cancelled if the progress callback returned false.
Point_cloud read_point_cloud(const std::string& path, const Read_options& options);

// Where the vertices of a binary PLY file lie, to read them in place (the Dask driver's
// workers map blocks of vertices, python/point_set_curvatures/dask.py): one record per vertex.
struct Ply_vertex_layout
{
  bool big_endian = false;
  std::uint64_t offset = 0;     // of the first vertex, in bytes from the start of the file
  std::uint64_t count = 0;      // vertices
  std::size_t record_size = 0;  // bytes of one vertex
  struct Property
  {
    std::string name;
    Scalar_type type;
    std::size_t offset;  // in the record
  };
  std::vector<Property> properties;  // in record order
  // the properties of x y z and of the normals (nx ny nz or normal_x normal_y normal_z; -1
  // without normals), as read_point_cloud() chooses them
  int xyz[3] = {-1, -1, -1}, normal[3] = {-1, -1, -1};
};

// The layout of the vertices of the binary PLY file `path`, from its header as
// read_point_cloud() reads it; the data is not read, but the file must hold every vertex.
// Throws Error for what read_point_cloud() refuses in the header, an ASCII PLY file, list
// properties in or before the vertices (records of varying size), or a file too short.
Ply_vertex_layout ply_vertex_layout(const std::string& path);

// Where the point records of an uncompressed LAS file lie: record i at offset + i *
// record_size, its coordinates the little-endian int32 X Y Z at its start, x = X * scale[0] +
// shift[0] (as read_point_cloud() computes them), and so on.
struct Las_point_layout
{
  std::uint64_t offset = 0, count = 0, record_size = 0;
  double scale[3] = {1, 1, 1}, shift[3] = {0, 0, 0};
};

// The layout of the point records of the LAS file `path`, from its header as
// read_point_cloud() reads it; the records are not read, but the file must hold every one.
// Throws Error for what read_point_cloud() refuses in the header, or a file too short.
Las_point_layout las_point_layout(const std::string& path);

}  // namespace psc_tool

#endif
