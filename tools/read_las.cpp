// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's LAS reader: LAS 1.0-1.4, uncompressed, point data record formats 0-10, written
// from the ASPRS LAS specification (public). Little-endian throughout.
//
// The public header block gives the version, the offset of the point records, the record
// format and length, the point count (32 bits before 1.4, 64 bits in 1.4), the scale and the
// offset of each coordinate and the bounds. A coordinate is an int32 X, stored; its value is
// X * scale + offset, computed in double. The variable length records between the header and
// the points, and what may follow the points (waveforms, extended records), are skipped.
// A record longer than its format's fields holds "extra bytes", skipped as well.
//
// Checked before anything is allocated: the signature, a known version and format, the
// header size for the version, a record length at least the format's, non-zero finite
// scales, and that the records declared fit in the file. After reading: the points against
// the header's bounds (a mismatch is a warning: some writers round the bounds).
//
// The point fields other than the coordinates become attributes (names in lower case):
// intensity, return_number, number_of_returns, scan_direction_flag, edge_of_flight_line,
// classification, synthetic, key_point, withheld, [overlap, scanner_channel (formats 6-10)],
// scan_angle (degrees), user_data, point_source_id, [gps_time], [red, green, blue], [nir].

#include "input_bytes.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace psc_tool {
namespace input {
namespace {

template <class T>
T little(const char* p)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  // assemble from little-endian bytes, whatever the machine's order
  std::uint64_t u = 0;
  for(std::size_t i = 0; i < sizeof(T); ++i)
    u |= std::uint64_t(b[i]) << (8 * i);
  T v;
  if constexpr(sizeof(T) == 1)
  {
    const std::uint8_t x = std::uint8_t(u);
    std::memcpy(&v, &x, 1);
  }
  else if constexpr(sizeof(T) == 2)
  {
    const std::uint16_t x = std::uint16_t(u);
    std::memcpy(&v, &x, 2);
  }
  else if constexpr(sizeof(T) == 4)
  {
    const std::uint32_t x = std::uint32_t(u);
    std::memcpy(&v, &x, 4);
  }
  else
    std::memcpy(&v, &u, 8);
  return v;
}

// Size in bytes of the fields of each point data record format.
const std::size_t format_size[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

bool has_gps_time(int f) { return f != 0 && f != 2; }
bool has_rgb(int f) { return f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10; }
bool has_nir(int f) { return f == 8 || f == 10; }
// offset of red (formats 2, 3, 5: after the legacy fields or the GPS time; 7, 8, 10: after
// the 30 bytes of format 6)
std::size_t rgb_offset(int f) { return f == 2 ? 20 : f < 6 ? 28 : 30; }
bool has_wave_packet(int f) { return f == 4 || f == 5 || f == 9 || f == 10; }
// where the wave packet fields start: descriptor index (uchar), byte offset to the waveform
// (uint64), packet size (uint32), return point location (float, picoseconds), then the
// parametric line of the pulse x(t) y(t) z(t) (floats, coordinate units per picosecond)
std::size_t wave_offset(int f) { return f == 4 ? 28 : f == 5 ? 34 : f == 9 ? 30 : 38; }

} // namespace

Point_cloud read_las(Byte_source& bytes, const std::string& path, const Read_options& options)
{
  const bool keep_attributes = options.keep_attributes;
  auto fail = [&](const std::string& what) { throw Error(cat(in_quotes(path), ": ", what)); };
  const std::uint64_t file_size = bytes.remaining();
  if(bytes.fill(227) < 227)
    fail("not a LAS file (shorter than a LAS header)");
  const char* h = bytes.data();
  if(std::memcmp(h, "LASF", 4) != 0)
    fail("not a LAS file (no 'LASF' signature)");
  const int major = little<std::uint8_t>(h + 24), minor = little<std::uint8_t>(h + 25);
  if(major != 1 || minor > 4)
    fail(cat("LAS version ", major, ".", minor, " is not supported (1.0 to 1.4 are)"));
  const std::size_t header_size = little<std::uint16_t>(h + 94);
  const std::uint64_t point_offset = little<std::uint32_t>(h + 96);
  const int format_byte = little<std::uint8_t>(h + 104);
  const std::size_t record_length = little<std::uint16_t>(h + 105);
  const std::size_t required_header = minor >= 4 ? 375 : minor == 3 ? 235 : 227;
  if(format_byte & 0xC0)
    fail("compressed LAS (LAZ) data: decompress it first, for example with 'laszip -i FILE -o FILE.las'");
  const int format = format_byte;
  if(format > 10 || (format > 5 && minor < 4) || (format > 3 && minor < 3))
    fail(cat("point data record format ", format, " is not valid in LAS 1.", minor));
  if(header_size < required_header)
    fail(cat("header size ", header_size, " is smaller than the ", required_header, " bytes of a LAS 1.", minor,
             " header"));
  if(point_offset < header_size || point_offset > file_size)
    fail(cat("offset to the point data ", point_offset, " is outside the file (header ", header_size,
             " bytes, file ", file_size, " bytes)"));
  if(record_length < format_size[format])
    fail(cat("point record length ", record_length, " is smaller than the ", format_size[format],
             " bytes of point format ", format));
  double scale[3], offset[3], max_bound[3], min_bound[3];
  for(int a = 0; a < 3; ++a)
  {
    scale[a] = little<double>(h + 131 + 8 * a);
    offset[a] = little<double>(h + 155 + 8 * a);
    max_bound[a] = little<double>(h + 179 + 16 * a);
    min_bound[a] = little<double>(h + 187 + 16 * a);
    if(!(scale[a] != 0) || !std::isfinite(scale[a]) || !std::isfinite(offset[a]))
      fail(cat("invalid ", "XYZ"[a], " scale factor ", scale[a], " or offset ", offset[a]));
  }
  std::uint64_t count = little<std::uint32_t>(h + 107);
  if(minor >= 4)
  {
    if(bytes.fill(header_size) < 375)
      fail("truncated LAS 1.4 header");
    h = bytes.data();
    const std::uint64_t count64 = little<std::uint64_t>(h + 247);
    if(count != 0 && count != count64)
      fail(cat("the header's point counts disagree (", count, " and ", count64, ")"));
    count = count64;
  }
  // the records declared must be in the file (what follows them is allowed: waveforms,
  // extended variable length records)
  if((long double)count * record_length > (long double)(file_size - point_offset))
    fail(cat("truncated: the header declares ", count, " points of ", record_length, " bytes from byte ",
             point_offset, ", the file has ", file_size, " bytes"));

  // skip the rest of the header and the variable length records
  for(std::uint64_t left = point_offset; left > 0;)
  {
    const std::size_t chunk = std::size_t(std::min<std::uint64_t>(left, 1u << 20));
    if(bytes.fill(chunk) < chunk)
      fail("truncated before the point data");
    bytes.advance(chunk);
    left -= chunk;
  }

  Point_cloud cloud;
  const std::size_t n = std::size_t(count);
  // the attributes of the format, in the order above
  enum Field
  {
    INTENSITY, RETURN_NUMBER, NUMBER_OF_RETURNS, SCAN_DIRECTION, EDGE, CLASSIFICATION, SYNTHETIC, KEY_POINT,
    WITHHELD, OVERLAP, SCANNER_CHANNEL, SCAN_ANGLE, USER_DATA, POINT_SOURCE, GPS_TIME, RED, GREEN, BLUE, NIR,
    WAVE_DESCRIPTOR, WAVE_SIZE, WAVE_LOCATION, WAVE_X_T, WAVE_Y_T, WAVE_Z_T, FIELD_COUNT
  };
  static const char* const names[FIELD_COUNT] = {
    "intensity", "return_number", "number_of_returns", "scan_direction_flag", "edge_of_flight_line",
    "classification", "synthetic", "key_point", "withheld", "overlap", "scanner_channel", "scan_angle",
    "user_data", "point_source_id", "gps_time", "red", "green", "blue", "nir", "wave_descriptor",
    "wave_packet_size", "wave_return_location", "wave_x_t", "wave_y_t", "wave_z_t"};
  static const Scalar_type types[FIELD_COUNT] = {
    Scalar_type::UINT16, Scalar_type::UINT8, Scalar_type::UINT8, Scalar_type::UINT8, Scalar_type::UINT8,
    Scalar_type::UINT8, Scalar_type::UINT8, Scalar_type::UINT8, Scalar_type::UINT8, Scalar_type::UINT8,
    Scalar_type::UINT8, Scalar_type::FLOAT32, Scalar_type::UINT8, Scalar_type::UINT16, Scalar_type::FLOAT64,
    Scalar_type::UINT16, Scalar_type::UINT16, Scalar_type::UINT16, Scalar_type::UINT16, Scalar_type::UINT8,
    Scalar_type::UINT32, Scalar_type::FLOAT32, Scalar_type::FLOAT32, Scalar_type::FLOAT32, Scalar_type::FLOAT32};
  const bool extended = format >= 6;
  bool present[FIELD_COUNT];
  for(int f = 0; f < FIELD_COUNT; ++f)
    present[f] = keep_attributes;
  if(keep_attributes)
  {
    present[OVERLAP] = present[SCANNER_CHANNEL] = extended;
    present[GPS_TIME] = has_gps_time(format);
    present[RED] = present[GREEN] = present[BLUE] = has_rgb(format);
    present[NIR] = has_nir(format);
    for(int f = WAVE_DESCRIPTOR; f <= WAVE_Z_T; ++f)
      present[f] = has_wave_packet(format);
  }
  for(int f = 0; f < FIELD_COUNT; ++f)
    if(present[f])
      cloud.attributes.push_back(Attribute{names[f], types[f], {}});
  // the points held: all of them, or a chunk at a time (Read_options::chunk)
  const std::size_t held = options.chunk ? std::min(n, options.chunk_points) : n;
  cloud.xyz.reserve(3 * held);
  for(Attribute& a : cloud.attributes)
    a.values.reserve(held);

  const std::size_t block = std::max<std::size_t>(1, (1u << 20) / record_length);
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  const std::size_t rgb = rgb_offset(format);
  double* column[FIELD_COUNT] = {};
  for(std::size_t first = 0; first < n;)
  {
    const std::size_t m = std::min(block, n - first);
    if(bytes.fill(m * record_length) < m * record_length)
      fail(cat("truncated: the file ends in point ", first + 1, " of the ", count, " declared in the header"));
    // the block's points are held from index `local` on
    const std::size_t local = cloud.size();
    cloud.xyz.resize(3 * (local + m));
    {
      std::size_t a = 0;
      for(int f = 0; f < FIELD_COUNT; ++f)
        if(present[f])
        {
          cloud.attributes[a].values.resize(local + m);
          column[f] = cloud.attributes[a++].values.data();
        }
    }
    const char* r = bytes.data();
    for(std::size_t i = local; i < local + m; ++i, r += record_length)
    {
      for(int a = 0; a < 3; ++a)
      {
        const double v = double(little<std::int32_t>(r + 4 * a)) * scale[a] + offset[a];
        cloud.xyz[3 * i + a] = v;
        lo[a] = std::min(lo[a], v);
        hi[a] = std::max(hi[a], v);
      }
      if(!keep_attributes)
        continue;
      const unsigned b14 = little<std::uint8_t>(r + 14), b15 = little<std::uint8_t>(r + 15);
      column[INTENSITY][i] = little<std::uint16_t>(r + 12);
      if(!extended)
      {
        column[RETURN_NUMBER][i] = b14 & 7;
        column[NUMBER_OF_RETURNS][i] = (b14 >> 3) & 7;
        column[SCAN_DIRECTION][i] = (b14 >> 6) & 1;
        column[EDGE][i] = (b14 >> 7) & 1;
        column[CLASSIFICATION][i] = b15 & 31;
        column[SYNTHETIC][i] = (b15 >> 5) & 1;
        column[KEY_POINT][i] = (b15 >> 6) & 1;
        column[WITHHELD][i] = (b15 >> 7) & 1;
        column[SCAN_ANGLE][i] = little<std::int8_t>(r + 16);  // degrees
        column[USER_DATA][i] = little<std::uint8_t>(r + 17);
        column[POINT_SOURCE][i] = little<std::uint16_t>(r + 18);
        if(present[GPS_TIME])
          column[GPS_TIME][i] = little<double>(r + 20);
      }
      else
      {
        column[RETURN_NUMBER][i] = b14 & 15;
        column[NUMBER_OF_RETURNS][i] = (b14 >> 4) & 15;
        column[SYNTHETIC][i] = b15 & 1;
        column[KEY_POINT][i] = (b15 >> 1) & 1;
        column[WITHHELD][i] = (b15 >> 2) & 1;
        column[OVERLAP][i] = (b15 >> 3) & 1;
        column[SCANNER_CHANNEL][i] = (b15 >> 4) & 3;
        column[SCAN_DIRECTION][i] = (b15 >> 6) & 1;
        column[EDGE][i] = (b15 >> 7) & 1;
        column[CLASSIFICATION][i] = little<std::uint8_t>(r + 16);
        column[USER_DATA][i] = little<std::uint8_t>(r + 17);
        column[SCAN_ANGLE][i] = float(little<std::int16_t>(r + 18) * 0.006);  // degrees
        column[POINT_SOURCE][i] = little<std::uint16_t>(r + 20);
        column[GPS_TIME][i] = little<double>(r + 22);
      }
      if(present[RED])
      {
        column[RED][i] = little<std::uint16_t>(r + rgb);
        column[GREEN][i] = little<std::uint16_t>(r + rgb + 2);
        column[BLUE][i] = little<std::uint16_t>(r + rgb + 4);
      }
      if(present[NIR])
        column[NIR][i] = little<std::uint16_t>(r + rgb + 6);
      if(present[WAVE_DESCRIPTOR])
      {
        const char* w = r + wave_offset(format);
        column[WAVE_DESCRIPTOR][i] = little<std::uint8_t>(w);
        column[WAVE_SIZE][i] = little<std::uint32_t>(w + 9);
        column[WAVE_LOCATION][i] = little<float>(w + 13);
        column[WAVE_X_T][i] = little<float>(w + 17);
        column[WAVE_Y_T][i] = little<float>(w + 21);
        column[WAVE_Z_T][i] = little<float>(w + 25);
      }
    }
    bytes.advance(m * record_length);
    first += m;
    hand_over(cloud, options);
  }
  // the header's bounds against the data, to half a unit of the scale (rounding)
  for(int a = 0; a < 3 && n > 0; ++a)
  {
    const double slack = 0.5 * std::abs(scale[a]) + 1e-9 * std::max(std::abs(lo[a]), std::abs(hi[a]));
    if(!(lo[a] >= min_bound[a] - slack && hi[a] <= max_bound[a] + slack))
      cloud.warnings.push_back(cat(in_quotes(path), ": the points' ", "xyz"[a], " range [", exact_number(lo[a]), ", ",
                                   exact_number(hi[a]), "] is not within the header's bounds [",
                                   exact_number(min_bound[a]), ", ", exact_number(max_bound[a]),
                                   "] (a corrupted header, or a writer that did not update it)"));
  }
  hand_over(cloud, options, true);
  return cloud;  // the rest of the file (waveforms, extended records) is not read
}

} // namespace input
} // namespace psc_tool
