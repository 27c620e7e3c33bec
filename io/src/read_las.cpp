// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The LAS reader: LAS 1.0-1.4, uncompressed, point data record formats 0-10, written
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
// scan_angle (degrees), user_data, point_source_id, [gps_time], [red, green, blue], [nir],
// [wave_descriptor, wave_data_offset, wave_packet_size, wave_return_location, wave_x_t,
// wave_y_t, wave_z_t], each with its Las_field. The extra bytes described by an extra-bytes
// VLR (LASF_Spec 4, LAS 1.4 R15: 192-byte descriptors) of data types 1-10 follow, named as
// in the file (characters other than letters, digits, '_' and '-' replaced by '_'; extra_NAME
// on a clash), in their type, or as doubles when the descriptor gives a scale or an offset
// (the value is then raw * scale + offset); the deprecated arrays (11-30) and undocumented
// bytes are skipped with a warning. The header, the VLRs and where the extended VLRs are
// go to Point_cloud::las (for the LAS output, write_las.cpp). A geographic CRS (GeoTIFF
// GTModelTypeGeoKey 2, or an OGC WKT GEOGCS / GEOGCRS), or x and y that look like degrees,
// gets a warning. With Read_options::allow_truncated, a file whose last records are
// missing is read to its last complete record, with a warning.

#include "input_bytes.h"
#include "las_format.h"

#include <cctype>
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

using namespace las;  // format_size, has_rgb, ... (las_format.h)

// The user id of a VLR is `id` (16 characters, NUL-padded).
bool user_id_is(const std::string& user_id, const char* id) { return std::string(user_id.c_str()) == id; }

// A field name usable as a PLY property, a CSV column and a LAS extra-bytes name.
std::string field_name(const char* p, std::size_t size)
{
  std::string name(p, strnlen(p, size));
  for(char& c : name)
    if(!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-')
      c = '_';
  return name;
}

// Why the CRS of the VLRs is geographic, or "".
std::string geographic_crs(const Las_source::Vlr& v)
{
  if(!user_id_is(v.user_id, "LASF_Projection"))
    return "";
  if(v.record_id == 34735)  // GeoKeyDirectoryTag: 4 shorts, then 4 shorts per key
  {
    const std::size_t shorts = v.payload.size() / 2;
    if(shorts < 4)
      return "";
    const std::size_t keys = little<std::uint16_t>(v.payload.data() + 6);
    for(std::size_t k = 0; k < keys && 4 * (k + 2) <= shorts; ++k)
    {
      const char* key = v.payload.data() + 8 * (k + 1);
      if(little<std::uint16_t>(key) == 1024 && little<std::uint16_t>(key + 2) == 0 &&
         little<std::uint16_t>(key + 6) == 2)
        return "the CRS is geographic (GeoTIFF GTModelTypeGeoKey 1024 = 2, latitude/longitude)";
    }
    return "";
  }
  if(v.record_id == 2112)  // OGC WKT: the first CRS keyword, inside a compound CRS
  {
    std::string wkt(v.payload.c_str());
    for(char& c : wkt)
      c = char(std::toupper(static_cast<unsigned char>(c)));
    std::size_t b = wkt.find_first_not_of(" \t\r\n");
    for(const char* compound : {"COMPD_CS[", "COMPOUNDCRS["})
      if(b != std::string::npos && wkt.compare(b, std::strlen(compound), compound) == 0)
      {
        // skip the compound CRS's name: the next keyword is its horizontal CRS
        const std::size_t comma = wkt.find(',', b);
        b = comma == std::string::npos ? comma : wkt.find_first_not_of(" \t\r\n", comma + 1);
      }
    for(const char* geographic : {"GEOGCS[", "GEOGCRS[", "GEOGRAPHICCRS["})
      if(b != std::string::npos && wkt.compare(b, std::strlen(geographic), geographic) == 0)
        return cat("the CRS is geographic (WKT ", std::string(geographic, std::strlen(geographic) - 1),
                   ", latitude/longitude)");
  }
  return "";
}

// The extra-bytes field of a descriptor: its place in the record, how to read it.
struct Extra_field
{
  std::size_t offset = 0;  // in the record
  int data_type = 0;       // 1-10
  double scale = 1, shift = 0;
  std::size_t attribute = 0;
};

double extra_value(const char* p, int data_type)
{
  switch(data_type)
  {
    case 1: return little<std::uint8_t>(p);
    case 2: return little<std::int8_t>(p);
    case 3: return little<std::uint16_t>(p);
    case 4: return little<std::int16_t>(p);
    case 5: return little<std::uint32_t>(p);
    case 6: return little<std::int32_t>(p);
    case 7: return double(little<std::uint64_t>(p));
    case 8: return double(little<std::int64_t>(p));
    case 9: return little<float>(p);
    default: return little<double>(p);
  }
}

}  // namespace

namespace {

// The fields of a LAS header that locate and decode the point records, checked.
struct Las_header
{
  int minor = 0, format = 0;
  std::size_t header_size = 0, record_length = 0;
  std::uint64_t point_offset = 0, count = 0, file_size = 0;
  std::uint32_t vlr_count = 0;
  double scale[3] = {1, 1, 1}, offset[3] = {0, 0, 0}, min_bound[3] = {0, 0, 0}, max_bound[3] = {0, 0, 0};
};

// Reads the header at the start of `bytes` (which it leaves there) and checks it; throws Error
// for what read_las() refuses. The point records are not checked to be in the file.
Las_header read_las_header(Byte_source& bytes, const std::string& path)
{
  auto fail = [&](const std::string& what) { throw Error(cat(in_quotes(path), ": ", what)); };
  Las_header l;
  l.file_size = bytes.remaining();
  if(bytes.fill(227) < 227)
    fail("not a LAS file (shorter than a LAS header)");
  const char* h = bytes.data();
  if(std::memcmp(h, "LASF", 4) != 0)
    fail("not a LAS file (no 'LASF' signature)");
  const int major = little<std::uint8_t>(h + 24), minor = little<std::uint8_t>(h + 25);
  if(major != 1 || minor > 4)
    fail(cat("LAS version ", major, ".", minor, " is not supported (1.0 to 1.4 are)"));
  l.minor = minor;
  l.header_size = little<std::uint16_t>(h + 94);
  l.point_offset = little<std::uint32_t>(h + 96);
  l.vlr_count = little<std::uint32_t>(h + 100);
  const int format_byte = little<std::uint8_t>(h + 104);
  l.record_length = little<std::uint16_t>(h + 105);
  const std::size_t required_header = minor >= 4 ? 375 : minor == 3 ? 235 : 227;
  if(format_byte & 0xC0)
    fail("compressed LAS (LAZ) data: decompress it first, for example with 'laszip -i FILE -o FILE.las'");
  const int format = l.format = format_byte;
  if(format > 10 || (format > 5 && minor < 4) || (format > 3 && minor < 3))
    fail(cat("point data record format ", format, " is not valid in LAS 1.", minor));
  if(l.header_size < required_header)
    fail(cat("header size ", l.header_size, " is smaller than the ", required_header, " bytes of a LAS 1.", minor,
             " header"));
  if(l.point_offset < l.header_size || l.point_offset > l.file_size)
    fail(cat("offset to the point data ", l.point_offset, " is outside the file (header ", l.header_size,
             " bytes, file ", l.file_size, " bytes)"));
  if(l.record_length < format_size[format])
    fail(cat("point record length ", l.record_length, " is smaller than the ", format_size[format],
             " bytes of point format ", format));
  for(int a = 0; a < 3; ++a)
  {
    l.scale[a] = little<double>(h + 131 + 8 * a);
    l.offset[a] = little<double>(h + 155 + 8 * a);
    l.max_bound[a] = little<double>(h + 179 + 16 * a);
    l.min_bound[a] = little<double>(h + 187 + 16 * a);
    if(!(l.scale[a] != 0) || !std::isfinite(l.scale[a]) || !std::isfinite(l.offset[a]))
      fail(cat("invalid ", "XYZ"[a], " scale factor ", l.scale[a], " or offset ", l.offset[a]));
  }
  l.count = little<std::uint32_t>(h + 107);
  if(minor >= 4)
  {
    if(bytes.fill(l.header_size) < 375)
      fail("truncated LAS 1.4 header");
    h = bytes.data();
    const std::uint64_t count64 = little<std::uint64_t>(h + 247);
    if(l.count != 0 && l.count != count64)
      fail(cat("the header's point counts disagree (", l.count, " and ", count64, ")"));
    l.count = count64;
  }
  return l;
}

// The records declared that are in the file (what follows them is allowed: waveforms,
// extended variable length records).
std::uint64_t complete_records(const Las_header& l) { return (l.file_size - l.point_offset) / l.record_length; }

// The message of a file that holds fewer records than its header declares, up to the count of
// the complete ones (each reader ends it as it treats the file).
std::string truncated_text(const std::string& path, const Las_header& l)
{
  return cat(in_quotes(path), ": truncated: the header declares ", l.count, " points of ", l.record_length,
             " bytes from byte ", l.point_offset, ", the file has ", l.file_size, " bytes (", complete_records(l),
             " complete records");
}

// Skips the rest of the header and reads the variable length records into `source` (kept
// unless they are larger than 16 MB: no LAS file has such; they are then skipped).
void read_vlrs(Byte_source& bytes, const Las_header& l, const std::string& path, Las_source& source,
               std::vector<std::string>& warnings)
{
  auto fail = [&](const std::string& what) { throw Error(cat(in_quotes(path), ": ", what)); };
  const std::size_t header_size = l.header_size;
  const std::uint64_t point_offset = l.point_offset;
  const std::uint32_t vlr_count = l.vlr_count;
  for(std::uint64_t left = header_size; left > 0;)
  {
    const std::size_t chunk = std::size_t(std::min<std::uint64_t>(left, 1u << 20));
    if(bytes.fill(chunk) < chunk)
      fail("truncated before the point data");
    bytes.advance(chunk);
    left -= chunk;
  }
  const std::uint64_t vlr_bytes = point_offset - header_size;
  if(vlr_bytes <= (16u << 20))
  {
    const std::size_t size = std::size_t(vlr_bytes);
    if(bytes.fill(size) < size)
      fail("truncated before the point data");
    const std::string region(bytes.data(), size);
    bytes.advance(size);
    std::size_t at = 0;
    for(std::uint32_t k = 0; k < vlr_count; ++k)
    {
      if(size - at < 54 || size - at - 54 < little<std::uint16_t>(region.data() + at + 20))
      {
        source.vlrs_complete = false;
        warnings.push_back(cat(in_quotes(path), ": the header declares ", vlr_count, " variable length records, ", k,
                               " fit before the point data: the others are not read"));
        break;
      }
      Las_source::Vlr v;
      v.user_id.assign(region.data() + at + 2, 16);
      v.record_id = little<std::uint16_t>(region.data() + at + 18);
      const std::size_t length = little<std::uint16_t>(region.data() + at + 20);
      v.description.assign(region.data() + at + 22, 32);
      v.payload.assign(region.data() + at + 54, length);
      source.vlrs.push_back(std::move(v));
      at += 54 + length;
    }
  }
  else
  {
    source.vlrs_complete = false;
    for(std::uint64_t left = vlr_bytes; left > 0;)
    {
      const std::size_t chunk = std::size_t(std::min<std::uint64_t>(left, 1u << 20));
      if(bytes.fill(chunk) < chunk)
        fail("truncated before the point data");
      bytes.advance(chunk);
      left -= chunk;
    }
  }
}

// The extended variable length records: where they are in `source` (their bytes are copied by
// a LAS output); returns those of the CRS.
std::vector<Las_source::Vlr> read_evlrs(const std::string& path, const Las_header& l, Las_source& source,
                                        std::vector<std::string>& warnings)
{
  const int minor = l.minor;
  const std::uint64_t file_size = l.file_size;
  std::vector<Las_source::Vlr> crs_records;
  std::uint64_t at = 0, number = 0;
  if(minor >= 4)
  {
    at = little<std::uint64_t>(source.header.data() + 235);
    number = at == 0 ? 0 : little<std::uint32_t>(source.header.data() + 243);
  }
  else if(minor == 3 && source.waveform_start != 0)
  {
    at = source.waveform_start;
    number = 1;
  }
  std::FILE* f = number == 0 ? nullptr : std::fopen(path.c_str(), "rb");
  for(std::uint64_t k = 0; f && k < number; ++k)
  {
    char e[60];
    if(at > file_size || file_size - at < 60 || std::fseek(f, long(at), SEEK_SET) != 0 ||
       std::fread(e, 1, 60, f) != 60 || little<std::uint64_t>(e + 20) > file_size - at - 60)
    {
      warnings.push_back(cat(in_quotes(path), ": the extended variable length record ", k + 1, " of ", number,
                             " is not within the file: it and those after it are not read"));
      break;
    }
    const std::uint64_t length = little<std::uint64_t>(e + 20);
    source.evlrs.emplace_back(at, 60 + length);
    Las_source::Vlr v;
    v.user_id.assign(e + 2, 16);
    v.record_id = little<std::uint16_t>(e + 18);
    if(user_id_is(v.user_id, "LASF_Projection") && (v.record_id == 2112 || v.record_id == 34735) && length < (1u << 20))
    {
      v.payload.resize(std::size_t(length));
      if(std::fread(&v.payload[0], 1, v.payload.size(), f) == v.payload.size())
        crs_records.push_back(std::move(v));
    }
    at += 60 + length;
  }
  if(f)
    std::fclose(f);
  return crs_records;
}

// The extra bytes of the records: the fields the extra-bytes VLR of `source` describes, as
// attributes of `cloud` where `keep_attributes` (their warnings too), or undocumented.
std::vector<Extra_field> extra_fields(const Las_source& source, const Las_header& l, const std::string& path,
                                      bool keep_attributes, Point_cloud& cloud)
{
  const int format = l.format;
  const std::size_t record_length = l.record_length;
  std::vector<Extra_field> extras;
  std::size_t at = format_size[format];
  const Las_source::Vlr* described = nullptr;
  for(const Las_source::Vlr& v : source.vlrs)
    if(user_id_is(v.user_id, "LASF_Spec") && v.record_id == 4)
      described = &v;
  std::vector<std::string> skipped;
  for(std::size_t d = 0; described && d + 192 <= described->payload.size(); d += 192)
  {
    const char* e = described->payload.data() + d;
    const int data_type = little<std::uint8_t>(e + 2), options_bits = little<std::uint8_t>(e + 3);
    std::string name = field_name(e + 4, 32);
    std::size_t size = 0;
    if(data_type == 0)
      size = std::size_t(options_bits);
    else if(data_type <= 10)
      size = extra_type_size[data_type];
    else if(data_type <= 30)
      size = extra_type_size[(data_type - 11) % 10 + 1] * (data_type <= 20 ? 2 : 3);
    else
    {
      cloud.warnings.push_back(cat(in_quotes(path), ": extra bytes field ", in_quotes(name),
                                   " has the reserved data type ", data_type,
                                   ": it and the extra bytes after it are not read"));
      break;
    }
    if(size > record_length - at)
    {
      cloud.warnings.push_back(cat(in_quotes(path), ": the extra-bytes VLR describes more bytes than the ",
                                   record_length - format_size[format], " extra bytes of the records: from field ",
                                   in_quotes(name), " on, they are not read"));
      break;
    }
    if(data_type >= 1 && data_type <= 10 && keep_attributes)
    {
      Extra_field x;
      x.offset = at;
      x.data_type = data_type;
      if(options_bits & 8)
        x.scale = little<double>(e + 112);
      if(options_bits & 16)
        x.shift = little<double>(e + 136);
      if(name.empty())
        name = cat("extra_", extras.size() + 1);
      for(bool taken = true; taken;)
      {
        taken = false;
        for(const Attribute& a : cloud.attributes)
          taken = taken || a.name == name;
        if(taken)
          name = "extra_" + name;
      }
      static const Scalar_type raw_type[11] = {Scalar_type::FLOAT64, Scalar_type::UINT8,   Scalar_type::INT8,
                                               Scalar_type::UINT16,  Scalar_type::INT16,   Scalar_type::UINT32,
                                               Scalar_type::INT32,   Scalar_type::FLOAT64, Scalar_type::FLOAT64,
                                               Scalar_type::FLOAT32, Scalar_type::FLOAT64};
      x.attribute = cloud.attributes.size();
      cloud.attributes.push_back(Attribute(name, (options_bits & 24) ? Scalar_type::FLOAT64 : raw_type[data_type]));
      cloud.attributes.back().las_descriptor.assign(e, 192);
      extras.push_back(x);
    }
    else if(data_type != 0 || size > 0)
      skipped.push_back(
        cat(in_quotes(name.empty() ? "?" : name), data_type == 0 ? " (undocumented)" : " (deprecated array type)"));
    at += size;
  }
  if(!skipped.empty() && keep_attributes)
  {
    std::string list;
    for(const std::string& s : skipped)
      list += (list.empty() ? "" : ", ") + s;
    cloud.warnings.push_back(cat(in_quotes(path), ": extra bytes fields not read: ", list));
  }
  if(at < record_length && keep_attributes)
    cloud.warnings.push_back(
      cat(in_quotes(path), ": ", record_length - at, " extra bytes per point record ",
          described ? "beyond those the extra-bytes VLR describes" : "without an extra-bytes VLR describing them",
          " are not read"));
  return extras;
}

// Warns where the points' range [lo, hi] leaves the header's bounds, and where the coordinates
// are in degrees (`geographic`: what the CRS says, if it is geographic; else from the range).
void warn_of_bounds_and_degrees(const std::string& path, const Las_header& l, std::size_t n, const double lo[3],
                                const double hi[3], std::string geographic, std::vector<std::string>& warnings)
{
  const double* const scale = l.scale;
  const double* const min_bound = l.min_bound;
  const double* const max_bound = l.max_bound;
  // the header's bounds against the data, to half a unit of the scale (rounding)
  for(int a = 0; a < 3 && n > 0; ++a)
  {
    const double slack = 0.5 * std::abs(scale[a]) + 1e-9 * std::max(std::abs(lo[a]), std::abs(hi[a]));
    if(!(lo[a] >= min_bound[a] - slack && hi[a] <= max_bound[a] + slack))
      warnings.push_back(cat(in_quotes(path), ": the points' ", "xyz"[a], " range [", exact_number(lo[a]), ", ",
                             exact_number(hi[a]), "] is not within the header's bounds [", exact_number(min_bound[a]),
                             ", ", exact_number(max_bound[a]),
                             "] (a corrupted header, or a writer that did not update it)"));
  }
  // coordinates in degrees: from the CRS, or x and y within longitudes and latitudes spanning
  // less than a degree while z spans 20 times more (metres)
  if(geographic.empty() && n > 0 && lo[0] >= -180 && hi[0] <= 180 && lo[1] >= -90 && hi[1] <= 90)
  {
    const double xy = std::max(hi[0] - lo[0], hi[1] - lo[1]), z = hi[2] - lo[2];
    if(xy < 1 && z > 20 * xy)
      geographic = cat("x and y look like longitude and latitude (x in [", lo[0], ", ", hi[0], "], y in [", lo[1], ", ",
                       hi[1], "], while z spans ", z, ")");
  }
  if(!geographic.empty())
    warnings.push_back(cat(in_quotes(path), ": ", geographic,
                           ": curvatures in 1/degree are meaningless; "
                           "reproject to a projected CRS in metres first, for example 'pdal translate IN.las "
                           "OUT.las reprojection --filters.reprojection.out_srs=EPSG:326xx' (UTM zone xx "
                           "north), or give --radius in degrees"));
}

// The standard fields of point record `r` (point format `format`) into row `i` of the columns
// of the fields `present`.
inline void decode_las_fields(const char* r, int format, const bool present[LAS_FIELD_COUNT],
                              double* const column[LAS_FIELD_COUNT], std::size_t i)
{
  const bool extended = format >= 6;
  const std::size_t rgb = rgb_offset(format);
  const unsigned b14 = little<std::uint8_t>(r + 14), b15 = little<std::uint8_t>(r + 15);
  column[LAS_INTENSITY][i] = little<std::uint16_t>(r + 12);
  if(!extended)
  {
    column[LAS_RETURN_NUMBER][i] = b14 & 7;
    column[LAS_NUMBER_OF_RETURNS][i] = (b14 >> 3) & 7;
    column[LAS_SCAN_DIRECTION][i] = (b14 >> 6) & 1;
    column[LAS_EDGE][i] = (b14 >> 7) & 1;
    column[LAS_CLASSIFICATION][i] = b15 & 31;
    column[LAS_SYNTHETIC][i] = (b15 >> 5) & 1;
    column[LAS_KEY_POINT][i] = (b15 >> 6) & 1;
    column[LAS_WITHHELD][i] = (b15 >> 7) & 1;
    column[LAS_SCAN_ANGLE][i] = little<std::int8_t>(r + 16);  // degrees
    column[LAS_USER_DATA][i] = little<std::uint8_t>(r + 17);
    column[LAS_POINT_SOURCE][i] = little<std::uint16_t>(r + 18);
    if(present[LAS_GPS_TIME])
      column[LAS_GPS_TIME][i] = little<double>(r + 20);
  }
  else
  {
    column[LAS_RETURN_NUMBER][i] = b14 & 15;
    column[LAS_NUMBER_OF_RETURNS][i] = (b14 >> 4) & 15;
    column[LAS_SYNTHETIC][i] = b15 & 1;
    column[LAS_KEY_POINT][i] = (b15 >> 1) & 1;
    column[LAS_WITHHELD][i] = (b15 >> 2) & 1;
    column[LAS_OVERLAP][i] = (b15 >> 3) & 1;
    column[LAS_SCANNER_CHANNEL][i] = (b15 >> 4) & 3;
    column[LAS_SCAN_DIRECTION][i] = (b15 >> 6) & 1;
    column[LAS_EDGE][i] = (b15 >> 7) & 1;
    column[LAS_CLASSIFICATION][i] = little<std::uint8_t>(r + 16);
    column[LAS_USER_DATA][i] = little<std::uint8_t>(r + 17);
    column[LAS_SCAN_ANGLE][i] = float(little<std::int16_t>(r + 18) * 0.006);  // degrees
    column[LAS_POINT_SOURCE][i] = little<std::uint16_t>(r + 20);
    column[LAS_GPS_TIME][i] = little<double>(r + 22);
  }
  if(present[LAS_RED])
  {
    column[LAS_RED][i] = little<std::uint16_t>(r + rgb);
    column[LAS_GREEN][i] = little<std::uint16_t>(r + rgb + 2);
    column[LAS_BLUE][i] = little<std::uint16_t>(r + rgb + 4);
  }
  if(present[LAS_NIR])
    column[LAS_NIR][i] = little<std::uint16_t>(r + rgb + 6);
  if(present[LAS_WAVE_DESCRIPTOR])
  {
    const char* w = r + wave_offset(format);
    column[LAS_WAVE_DESCRIPTOR][i] = little<std::uint8_t>(w);
    column[LAS_WAVE_OFFSET][i] = double(little<std::uint64_t>(w + 1));
    column[LAS_WAVE_SIZE][i] = little<std::uint32_t>(w + 9);
    column[LAS_WAVE_LOCATION][i] = little<float>(w + 13);
    column[LAS_WAVE_X_T][i] = little<float>(w + 17);
    column[LAS_WAVE_Y_T][i] = little<float>(w + 21);
    column[LAS_WAVE_Z_T][i] = little<float>(w + 25);
  }
}

// The header as read (its first 375 bytes, zero-padded), for a LAS output.
std::shared_ptr<Las_source> header_source(Byte_source& bytes, const Las_header& l)
{
  auto source = std::make_shared<Las_source>();
  {
    const std::size_t kept = std::min<std::size_t>(l.header_size, 375);
    bytes.fill(kept);
    source->header.assign(bytes.data(), kept);
    source->header.resize(375, '\0');
  }
  source->minor = l.minor;
  source->format = l.format;
  for(int a = 0; a < 3; ++a)
  {
    source->scale[a] = l.scale[a];
    source->offset[a] = l.offset[a];
  }
  if(l.minor >= 3)
    source->waveform_start = little<std::uint64_t>(source->header.data() + 227);
  return source;
}

// The standard fields of point format `format` as attributes of `cloud`, in the order of
// Las_field, where `keep_attributes`: `present[f]` whether field f is read, `column_of[f]` its
// attribute (-1 if not).
void add_las_fields(int format, bool keep_attributes, Point_cloud& cloud, bool present[LAS_FIELD_COUNT],
                    int column_of[LAS_FIELD_COUNT])
{
  // clang-format off
  static const char* const names[LAS_FIELD_COUNT] = {
    "intensity", "return_number", "number_of_returns", "scan_direction_flag", "edge_of_flight_line",
    "classification", "synthetic", "key_point", "withheld", "overlap", "scanner_channel", "scan_angle",
    "user_data", "point_source_id", "gps_time", "red", "green", "blue", "nir", "wave_descriptor",
    "wave_data_offset", "wave_packet_size", "wave_return_location", "wave_x_t", "wave_y_t", "wave_z_t"};
  // clang-format on
  static const Scalar_type types[LAS_FIELD_COUNT] = {
    Scalar_type::UINT16,  Scalar_type::UINT8,   Scalar_type::UINT8,   Scalar_type::UINT8,   Scalar_type::UINT8,
    Scalar_type::UINT8,   Scalar_type::UINT8,   Scalar_type::UINT8,   Scalar_type::UINT8,   Scalar_type::UINT8,
    Scalar_type::UINT8,   Scalar_type::FLOAT32, Scalar_type::UINT8,   Scalar_type::UINT16,  Scalar_type::FLOAT64,
    Scalar_type::UINT16,  Scalar_type::UINT16,  Scalar_type::UINT16,  Scalar_type::UINT16,  Scalar_type::UINT8,
    Scalar_type::FLOAT64, Scalar_type::UINT32,  Scalar_type::FLOAT32, Scalar_type::FLOAT32, Scalar_type::FLOAT32,
    Scalar_type::FLOAT32};
  const bool extended = format >= 6;
  for(int f = 0; f < LAS_FIELD_COUNT; ++f)
    present[f] = keep_attributes;
  if(keep_attributes)
  {
    present[LAS_OVERLAP] = present[LAS_SCANNER_CHANNEL] = extended;
    present[LAS_GPS_TIME] = has_gps_time(format);
    present[LAS_RED] = present[LAS_GREEN] = present[LAS_BLUE] = has_rgb(format);
    present[LAS_NIR] = has_nir(format);
    for(int f = LAS_WAVE_DESCRIPTOR; f <= LAS_WAVE_Z_T; ++f)
      present[f] = has_wave_packet(format);
  }
  for(int f = 0; f < LAS_FIELD_COUNT; ++f)
  {
    column_of[f] = present[f] ? int(cloud.attributes.size()) : -1;
    if(present[f])
    {
      cloud.attributes.push_back(Attribute(names[f], types[f]));
      cloud.attributes.back().las_field = f;
    }
  }
}

}  // namespace

Point_cloud read_las(Byte_source& bytes, const std::string& path, const Read_options& options)
{
  const bool keep_attributes = options.keep_attributes;
  auto fail = [&](const std::string& what) { throw Error(cat(in_quotes(path), ": ", what)); };
  const Las_header l = read_las_header(bytes, path);
  const std::size_t record_length = l.record_length;
  const int format = l.format;
  const double* const scale = l.scale;
  const double* const offset = l.offset;
  std::uint64_t count = l.count;
  Point_cloud cloud;
  if(count > complete_records(l))
  {
    const std::uint64_t complete = complete_records(l);
    if(!options.allow_truncated)
      throw Error(truncated_text(path, l) + ": --allow-truncated reads them)");
    cloud.warnings.push_back(cat(in_quotes(path), ": truncated: read the ", complete, " complete points of the ", count,
                                 " the header declares (--allow-truncated)"));
    count = complete;
  }

  // the header as read, for a LAS output
  const std::shared_ptr<Las_source> source = header_source(bytes, l);
  read_vlrs(bytes, l, path, *source, cloud.warnings);
  const std::vector<Las_source::Vlr> crs_records = read_evlrs(path, l, *source, cloud.warnings);
  std::string geographic;
  for(const Las_source::Vlr& v : source->vlrs)
    if(geographic.empty())
      geographic = geographic_crs(v);
  for(const Las_source::Vlr& v : crs_records)
    if(geographic.empty())
      geographic = geographic_crs(v);

  const std::size_t n = std::size_t(count);
  // the attributes of the format, in the order of Las_field
  bool present[LAS_FIELD_COUNT];
  int column_of[LAS_FIELD_COUNT];
  add_las_fields(format, keep_attributes, cloud, present, column_of);
  // the extra bytes: described by the extra-bytes VLR, or undocumented
  const std::vector<Extra_field> extras = extra_fields(*source, l, path, keep_attributes, cloud);
  cloud.las = source;
  // the points held: all of them, or a chunk at a time (Read_options::chunk)
  const std::size_t held = options.chunk ? std::min(n, options.chunk_points) : n;
  cloud.xyz.reserve(3 * held);
  for(Attribute& a : cloud.attributes)
    a.values.reserve(held);

  const std::size_t block = std::max<std::size_t>(1, (1u << 20) / record_length);
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  double* column[LAS_FIELD_COUNT] = {};
  std::vector<double*> extra_column(extras.size());
  for(std::size_t first = 0; first < n;)
  {
    const std::size_t m = std::min(block, n - first);
    if(bytes.fill(m * record_length) < m * record_length)
      fail(cat("truncated: the file ends in point ", first + 1, " of the ", count, " declared in the header"));
    // the block's points are held from index `local` on
    const std::size_t local = cloud.size();
    cloud.xyz.resize(3 * (local + m));
    for(Attribute& a : cloud.attributes)
      a.values.resize(local + m);
    for(int f = 0; f < LAS_FIELD_COUNT; ++f)
      if(present[f])
        column[f] = cloud.attributes[column_of[f]].values.data();
    for(std::size_t x = 0; x < extras.size(); ++x)
      extra_column[x] = cloud.attributes[extras[x].attribute].values.data();
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
      decode_las_fields(r, format, present, column, i);
      for(std::size_t x = 0; x < extras.size(); ++x)
        extra_column[x][i] = extra_value(r + extras[x].offset, extras[x].data_type) * extras[x].scale + extras[x].shift;
    }
    bytes.advance(m * record_length);
    first += m;
    hand_over(cloud, options);
  }
  warn_of_bounds_and_degrees(path, l, n, lo, hi, geographic, cloud.warnings);
  hand_over(cloud, options, true);
  return cloud;  // the rest of the file (waveforms, extended records) is not read
}

}  // namespace input

Las_point_layout las_point_layout(const std::string& path)
{
  using namespace input;
  Byte_source bytes(path, regular_file_size(path), Progress());
  const Las_header l = read_las_header(bytes, path);
  if(l.count > complete_records(l))
    throw Error(truncated_text(path, l) + ")");
  Las_point_layout layout;
  layout.offset = l.point_offset;
  layout.count = l.count;
  layout.record_size = l.record_length;
  for(int a = 0; a < 3; ++a)
  {
    layout.scale[a] = l.scale[a];
    layout.shift[a] = l.offset[a];
  }
  return layout;
}

}  // namespace psc_tool
