// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The LAS writer (see write_las.h), written from the ASPRS LAS 1.4 R15
// specification. Little-endian throughout.

#include "psc_io/write_las.h"

#include "las_format.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <set>
#include <string>

#include <sys/types.h>

namespace psc_tool {
namespace {

// The unsigned integer of a type's size.
template <std::size_t N>
struct Unsigned;
template <>
struct Unsigned<1>
{
  typedef std::uint8_t type;
};
template <>
struct Unsigned<2>
{
  typedef std::uint16_t type;
};
template <>
struct Unsigned<4>
{
  typedef std::uint32_t type;
};
template <>
struct Unsigned<8>
{
  typedef std::uint64_t type;
};

// `v` at `at`, little-endian whatever the machine's order.
template <class T>
void put(char* at, T v)
{
  typename Unsigned<sizeof(T)>::type u;
  std::memcpy(&u, &v, sizeof(T));
  for(std::size_t i = 0; i < sizeof(T); ++i)
    at[i] = char((std::uint64_t(u) >> (8 * i)) & 0xFF);
}

template <class T>
T get(const char* at)
{
  std::uint64_t u = 0;
  for(std::size_t i = 0; i < sizeof(T); ++i)
    u |= std::uint64_t(static_cast<unsigned char>(at[i])) << (8 * i);
  const typename Unsigned<sizeof(T)>::type x = static_cast<typename Unsigned<sizeof(T)>::type>(u);
  T v;
  std::memcpy(&v, &x, sizeof(T));
  return v;
}

using namespace las;  // format_size, extra_type_size, has_rgb, ... (las_format.h)

// Writes `v` (the data type's raw value) at `at`.
void put_extra(char* at, int data_type, double v)
{
  switch(data_type)
  {
    case 1: put(at, to_integer<std::uint8_t>(v)); break;
    case 2: put(at, to_integer<std::int8_t>(v)); break;
    case 3: put(at, to_integer<std::uint16_t>(v)); break;
    case 4: put(at, to_integer<std::int16_t>(v)); break;
    case 5: put(at, to_integer<std::uint32_t>(v)); break;
    case 6: put(at, to_integer<std::int32_t>(v)); break;
    case 7: put(at, to_integer<std::uint64_t>(v)); break;
    case 8: put(at, to_integer<std::int64_t>(v)); break;
    case 9: put(at, static_cast<float>(v)); break;
    default: put(at, v); break;
  }
}

int data_type_of(Scalar_type t)
{
  switch(t)
  {
    case Scalar_type::UINT8: return 1;
    case Scalar_type::INT8: return 2;
    case Scalar_type::UINT16: return 3;
    case Scalar_type::INT16: return 4;
    case Scalar_type::UINT32: return 5;
    case Scalar_type::INT32: return 6;
    case Scalar_type::FLOAT32: return 9;
    default: return 10;
  }
}

// What the descriptor of an estimate says of it (at most 31 characters: the table's).
const char* description_of(const std::string& name)
{
  const std::size_t row = CGAL::Point_set_curvatures::field_index(name);
  return row < CGAL::Point_set_curvatures::field_count ? CGAL::Point_set_curvatures::field_descriptions[row].description
                                                       : "input attribute";
}

// An extra-bytes field of the output.
struct Extra
{
  std::size_t field = 0;  // in the fields
  int data_type = 10;
  double scale = 1, shift = 0;  // raw = (value - shift) / scale
  std::size_t offset = 0;       // in the record
  std::string descriptor;       // 192 bytes
};

std::string padded(const std::string& s, std::size_t size)
{
  std::string p = s.substr(0, size);
  p.resize(size, '\0');
  return p;
}

// The day of the year (1-366) and the year of the file's creation: today (UTC), or the
// date of SOURCE_DATE_EPOCH (reproducible outputs).
void creation_date(int& day, int& year)
{
  std::time_t t = std::time(nullptr);
  if(const char* epoch = std::getenv("SOURCE_DATE_EPOCH"))
  {
    char* end = nullptr;
    const long long e = std::strtoll(epoch, &end, 10);
    if(end != epoch && *end == '\0' && e >= 0)
      t = std::time_t(e);
  }
  std::tm utc;
  gmtime_r(&t, &utc);
  day = utc.tm_yday + 1;
  year = utc.tm_year + 1900;
}

// The largest power of ten not above v (v > 0, finite).
double power_of_ten_below(double v) { return std::pow(10.0, std::floor(std::log10(v))); }

}  // namespace

namespace {

// What the records of the output are made of: the point format, the extra-bytes fields, the
// variable length records (computed before the estimation to reserve the output's size, and
// again to write it).
struct Las_layout
{
  int standard_source[LAS_FIELD_COUNT];  // the attribute of each standard field, or -1
  int format = 6;
  std::vector<Extra> extras;
  std::size_t record_length = 0;
  std::string vlrs;
  std::uint32_t vlr_count = 0;
  std::uint64_t point_offset = 375;
};

Las_layout las_layout(const Las_output_options& options, const std::vector<Output_field>& fields,
                      const std::vector<Attribute>& attributes, std::vector<std::string>& warnings)
{
  Las_layout l;
  const Las_source* source = options.source.get();
  // the standard fields: those of the input's format when its attributes carry them
  int* standard_source = l.standard_source;
  std::fill(standard_source, standard_source + LAS_FIELD_COUNT, -1);
  bool standard = false;
  for(std::size_t j = 0; j < attributes.size(); ++j)
    if(source && attributes[j].las_field >= 0 && attributes[j].las_field < LAS_FIELD_COUNT)
    {
      standard_source[attributes[j].las_field] = int(j);
      standard = true;
    }
  const int format = l.format = standard ? source->format : 6;

  // the extra-bytes fields, in the order of the fields
  std::vector<Extra>& extras = l.extras;
  std::size_t& record_length = l.record_length;
  record_length = format_size[format];
  std::set<std::string> used_names;
  for(std::size_t c = 0; c < fields.size(); ++c)
  {
    const Output_field& field = fields[c];
    const int s = field.source;
    Extra x;
    x.field = c;
    x.descriptor.assign(192, '\0');
    char* d = &x.descriptor[0];
    if(s < 3 || (s >= Output_field::COLOR && s < Output_field::ATTRIBUTE))
      continue;  // coordinates; colours (not written to LAS: refused by the tool)
    if(s >= Output_field::ATTRIBUTE)
    {
      const Attribute& a = attributes[std::size_t(s - Output_field::ATTRIBUTE)];
      if(a.las_field >= 0 && source)
        continue;  // a standard field
      if(options.drop_attributes)
        continue;
      if(a.las_descriptor.size() == 192)
      {
        x.descriptor = a.las_descriptor;
        d = &x.descriptor[0];
        x.data_type = static_cast<unsigned char>(d[2]);
        const int bits = static_cast<unsigned char>(d[3]);
        if(bits & 8)
          x.scale = get<double>(d + 112);
        if(bits & 16)
          x.shift = get<double>(d + 136);
        if(!(x.scale != 0) || !std::isfinite(x.scale))
          x.scale = 1;
        if(x.data_type < 1 || x.data_type > 10)
          continue;  // (read_las.cpp keeps types 1-10 only)
      }
      else
      {
        x.data_type = data_type_of(a.type);
        std::memcpy(d + 160, "input attribute", 15);
      }
    }
    else
    {
      // an estimate: double or float with no_data NaN; counts int32; flags uchar
      x.data_type = data_type_of(field.type);
      if(x.data_type >= 9)
      {
        d[3] = 1;  // no_data_bit
        put(d + 40, std::numeric_limits<double>::quiet_NaN());
      }
      const char* text = description_of(field.name);
      std::memcpy(d + 160, text, std::min<std::size_t>(32, std::strlen(text)));
    }
    d[2] = char(x.data_type);
    // 32 characters at most, unique: readers find the fields by name
    std::string name = field.name.substr(0, 32);
    for(int k = 2; used_names.count(name); ++k)
    {
      const std::string suffix = "~" + std::to_string(k);
      name = field.name.substr(0, 32 - suffix.size()) + suffix;
    }
    used_names.insert(name);
    std::memcpy(d + 4, padded(name, 32).data(), 32);
    x.offset = record_length;
    record_length += extra_type_size[x.data_type];
    extras.push_back(x);
  }
  if(record_length > 65535 || 192 * extras.size() > 65535)
    throw Error(cat("the output has ", extras.size(), " extra-bytes fields of ", record_length - format_size[format],
                    " bytes per point, more than a LAS record holds (65535 bytes, 341 fields): choose fewer with "
                    "--fields or --drop-attributes, or write .ply"));

  // the variable length records: the input's, its extra-bytes VLR replaced by the output's
  std::string& vlrs = l.vlrs;
  std::uint32_t& vlr_count = l.vlr_count;
  auto add_vlr = [&](const std::string& user_id, int record_id, const std::string& description,
                     const std::string& payload) {
    std::string h(54, '\0');
    std::memcpy(&h[2], padded(user_id, 16).data(), 16);
    put(&h[18], std::uint16_t(record_id));
    put(&h[20], std::uint16_t(payload.size()));
    std::memcpy(&h[22], padded(description, 32).data(), 32);
    vlrs += h + payload;
    ++vlr_count;
  };
  if(source)
    for(const Las_source::Vlr& v : source->vlrs)
      if(!(std::string(v.user_id.c_str()) == "LASF_Spec" && v.record_id == 4))
        add_vlr(v.user_id, v.record_id, v.description, v.payload);
  if(source && !source->vlrs_complete)
    warnings.push_back("the input's variable length records did not all parse: only those that did are in the "
                       "LAS output");
  if(!extras.empty())
  {
    std::string payload;
    for(const Extra& x : extras)
      payload += x.descriptor;
    add_vlr("LASF_Spec", 4, "point_set_curvatures estimates", payload);
  }
  l.point_offset = 375 + vlrs.size();
  return l;
}

}  // namespace

std::uint64_t las_output_size(const Las_output_options& options, const std::vector<Output_field>& fields,
                              const std::vector<Attribute>& attributes, std::size_t n)
{
  std::vector<std::string> warnings;
  const Las_layout l = las_layout(options, fields, attributes, warnings);
  std::uint64_t evlrs = 0;
  if(options.source)
    for(const auto& e : options.source->evlrs)
      evlrs += e.second;
  return l.point_offset + std::uint64_t(n) * l.record_length + evlrs;
}

namespace {

// The scale and offset of the output's coordinates: the input's, or chosen from the bounds
// (offset at the floor of the minimum, scale 0.001, finer for extents below 1000).
void las_scale_offset(const Las_output_options& options, double scale[3], double offset[3])
{
  const Las_source* source = options.source.get();
  for(int a = 0; a < 3; ++a)
  {
    if(source)
    {
      scale[a] = source->scale[a];
      offset[a] = source->offset[a];
      continue;
    }
    const bool finite = std::isfinite(options.lo[a]) && std::isfinite(options.hi[a]) && options.lo[a] <= options.hi[a];
    offset[a] = finite ? std::floor(options.lo[a]) : 0.0;
    double extent = finite ? options.hi[a] - offset[a] : 0.0;
    if(!std::isfinite(extent))
      extent = std::numeric_limits<double>::max();
    scale[a] = 0.001;
    if(extent > 0 && extent * 1e-6 < 0.001)
      scale[a] = std::max(1e-300, power_of_ten_below(extent * 1e-6));
    while(extent / scale[a] > 2e9)
      scale[a] *= 10;
  }
}

// The header as first written (the counts, bounds and extended records' place are written at
// the end, finish_las_header()): the input's identifiers, this program, the layout, the scale
// and offset; `global_encoding` the input's bits that stay valid (completed at the end).
std::string las_header_start(const Las_source* source, const Las_layout& l, const double scale[3],
                             const double offset[3], std::uint16_t& global_encoding)
{
  const int format = l.format;
  std::string header(375, '\0');
  std::memcpy(&header[0], "LASF", 4);
  global_encoding = 0;
  if(source)
  {
    std::memcpy(&header[4], source->header.data() + 4, 2);  // file source id
    global_encoding = get<std::uint16_t>(source->header.data() + 6);
    std::memcpy(&header[8], source->header.data() + 8, 16);    // project id
    std::memcpy(&header[26], source->header.data() + 26, 32);  // system identifier
    global_encoding &= 0x1F;
    if(!has_wave_packet(format))
      global_encoding &= ~std::uint16_t(6);
  }
  else
    std::memcpy(&header[26], "OTHER", 5);
  header[24] = 1;
  header[25] = 4;
  std::memcpy(&header[58], "point_set_curvatures", 20);
  int day = 1, year = 2026;
  creation_date(day, year);
  put(&header[90], std::uint16_t(day));
  put(&header[92], std::uint16_t(year));
  put(&header[94], std::uint16_t(375));
  put(&header[96], std::uint32_t(l.point_offset));
  put(&header[100], l.vlr_count);
  put(&header[104], std::uint8_t(format));
  put(&header[105], std::uint16_t(l.record_length));
  for(int a = 0; a < 3; ++a)
  {
    put(&header[131 + 8 * a], scale[a]);
    put(&header[155 + 8 * a], offset[a]);
  }
  return header;
}

// The standard fields of a point record `p` (point format `format`), each from `field(f,
// otherwise)`; `finite`: the point's coordinates are (else it is withheld). Counts the point
// by its return number in `by_return`.
template <class Field>
inline void encode_las_fields(char* p, int format, bool finite, const Field& field, std::uint64_t by_return[15])
{
  const bool extended = format >= 6;
  const double withheld = finite ? field(LAS_WITHHELD, 0) : 1;
  const unsigned return_number = to_integer<std::uint8_t>(field(LAS_RETURN_NUMBER, 1));
  put(p + 12, to_integer<std::uint16_t>(field(LAS_INTENSITY, 0)));
  const unsigned returns = to_integer<std::uint8_t>(field(LAS_NUMBER_OF_RETURNS, 1));
  const unsigned direction = to_integer<std::uint8_t>(field(LAS_SCAN_DIRECTION, 0)) & 1;
  const unsigned edge = to_integer<std::uint8_t>(field(LAS_EDGE, 0)) & 1;
  const unsigned synthetic = to_integer<std::uint8_t>(field(LAS_SYNTHETIC, 0)) & 1;
  const unsigned key = to_integer<std::uint8_t>(field(LAS_KEY_POINT, 0)) & 1;
  const unsigned held = to_integer<std::uint8_t>(withheld) & 1;
  const unsigned classification = to_integer<std::uint8_t>(field(LAS_CLASSIFICATION, 0));
  if(!extended)
  {
    p[14] = char((return_number & 7) | ((returns & 7) << 3) | (direction << 6) | (edge << 7));
    p[15] = char((classification & 31) | (synthetic << 5) | (key << 6) | (held << 7));
    put(p + 16, to_integer<std::int8_t>(field(LAS_SCAN_ANGLE, 0)));
    put(p + 17, to_integer<std::uint8_t>(field(LAS_USER_DATA, 0)));
    put(p + 18, to_integer<std::uint16_t>(field(LAS_POINT_SOURCE, 0)));
    if(has_gps_time(format))
      put(p + 20, field(LAS_GPS_TIME, 0));
    if(return_number >= 1 && (return_number & 7) <= 5)
      ++by_return[(return_number & 7) - 1];
  }
  else
  {
    const unsigned overlap = to_integer<std::uint8_t>(field(LAS_OVERLAP, 0)) & 1;
    const unsigned channel = to_integer<std::uint8_t>(field(LAS_SCANNER_CHANNEL, 0)) & 3;
    p[14] = char((return_number & 15) | ((returns & 15) << 4));
    p[15] =
      char(synthetic | (key << 1) | (held << 2) | (overlap << 3) | (channel << 4) | (direction << 6) | (edge << 7));
    p[16] = char(classification);
    put(p + 17, to_integer<std::uint8_t>(field(LAS_USER_DATA, 0)));
    put(p + 18, to_integer<std::int16_t>(field(LAS_SCAN_ANGLE, 0) / 0.006));
    put(p + 20, to_integer<std::uint16_t>(field(LAS_POINT_SOURCE, 0)));
    put(p + 22, field(LAS_GPS_TIME, 0));
    if((return_number & 15) >= 1)
      ++by_return[(return_number & 15) - 1];
  }
  if(has_rgb(format))
  {
    const std::size_t c = rgb_offset(format);
    put(p + c, to_integer<std::uint16_t>(field(LAS_RED, 0)));
    put(p + c + 2, to_integer<std::uint16_t>(field(LAS_GREEN, 0)));
    put(p + c + 4, to_integer<std::uint16_t>(field(LAS_BLUE, 0)));
    if(has_nir(format))
      put(p + c + 6, to_integer<std::uint16_t>(field(LAS_NIR, 0)));
  }
  if(has_wave_packet(format))
  {
    char* w = p + wave_offset(format);
    put(w, to_integer<std::uint8_t>(field(LAS_WAVE_DESCRIPTOR, 0)));
    put(w + 1, to_integer<std::uint64_t>(field(LAS_WAVE_OFFSET, 0)));
    put(w + 9, to_integer<std::uint32_t>(field(LAS_WAVE_SIZE, 0)));
    put(w + 13, static_cast<float>(field(LAS_WAVE_LOCATION, 0)));
    put(w + 17, static_cast<float>(field(LAS_WAVE_X_T, 0)));
    put(w + 21, static_cast<float>(field(LAS_WAVE_Y_T, 0)));
    put(w + 25, static_cast<float>(field(LAS_WAVE_Z_T, 0)));
  }
}

// The extended variable length records of the input (`source`), copied to `f` from byte `at`
// on (but the input's extra-bytes description: the output's VLR describes its own): where the
// first and the waveform records are, and their number. Returns the end of what was written.
std::uint64_t copy_las_evlrs(std::FILE* f, const Las_output_options& options, const Las_source* source,
                             std::uint64_t at, std::uint64_t& first_evlr, std::uint64_t& waveform_start,
                             std::uint32_t& evlr_count)
{
  if(source && !source->evlrs.empty())
  {
    std::FILE* in = std::fopen(options.input_path.c_str(), "rb");
    if(!in)
      throw Error(cat("cannot open input ", in_quotes(options.input_path),
                      " again to copy its extended variable length records"));
    std::vector<char> buffer(1 << 20);
    for(const auto& e : source->evlrs)
    {
      char h[60];
      if(std::fseek(in, long(e.first), SEEK_SET) != 0 || std::fread(h, 1, 60, in) != 60)
      {
        std::fclose(in);
        throw Error(cat("cannot read the extended variable length records of ", in_quotes(options.input_path),
                        " again (was the file changed?)"));
      }
      const std::string user(h + 2, strnlen(h + 2, 16));
      const int id = get<std::uint16_t>(h + 18);
      if(user == "LASF_Spec" && id == 4)
        continue;  // the input's extra bytes: the output's VLR describes them
      if(user == "LASF_Spec" && id == 65535)
        waveform_start = at;
      if(first_evlr == 0)
        first_evlr = at;
      ++evlr_count;
      std::fwrite(h, 1, 60, f);
      for(std::uint64_t left = e.second - 60; left > 0;)
      {
        const std::size_t m = std::size_t(std::min<std::uint64_t>(left, buffer.size()));
        if(std::fread(buffer.data(), 1, m, in) != m)
        {
          std::fclose(in);
          throw Error(cat("cannot read the extended variable length records of ", in_quotes(options.input_path),
                          " again (was the file changed?)"));
        }
        std::fwrite(buffer.data(), 1, m, f);
        left -= m;
      }
      at += e.second;
    }
    std::fclose(in);
  }
  return at;
}

// The header completed: the encoding, the point counts (by return), the bounds [lo, hi] and the
// extended records' place.
void finish_las_header(std::string& header, int format, std::size_t n, std::uint16_t global_encoding,
                       const std::uint64_t by_return[15], const double lo[3], const double hi[3],
                       std::uint64_t waveform_start, std::uint64_t first_evlr, std::uint32_t evlr_count)
{
  put(&header[6], global_encoding);
  const bool legacy = format <= 5 && n <= 0xFFFFFFFFu;
  put(&header[107], std::uint32_t(legacy ? n : 0));
  for(int k = 0; k < 5; ++k)
    put(&header[111 + 4 * k], std::uint32_t(legacy ? by_return[k] : 0));
  for(int a = 0; a < 3; ++a)
  {
    const bool any = lo[a] <= hi[a];
    put(&header[179 + 16 * a], any ? hi[a] : 0.0);
    put(&header[187 + 16 * a], any ? lo[a] : 0.0);
  }
  put(&header[227], waveform_start);
  put(&header[235], first_evlr);
  put(&header[243], evlr_count);
  put(&header[247], std::uint64_t(n));
  for(int k = 0; k < 15; ++k)
    put(&header[255 + 8 * k], by_return[k]);
}

}  // namespace

std::vector<std::string> write_las(std::FILE* f, const Las_output_options& options,
                                   const std::vector<Output_field>& fields, const std::vector<Attribute>& attributes,
                                   std::size_t n, const std::function<void(std::size_t, Output_row&)>& row,
                                   const Progress& progress)
{
  std::vector<std::string> warnings;
  const Las_source* source = options.source.get();
  const Las_layout l = las_layout(options, fields, attributes, warnings);
  const int* standard_source = l.standard_source;
  const int format = l.format;
  const std::vector<Extra>& extras = l.extras;
  const std::size_t record_length = l.record_length;
  const std::string& vlrs = l.vlrs;
  const std::uint64_t point_offset = l.point_offset;

  // scale and offset: the input's, or chosen from the bounds
  double scale[3], offset[3];
  las_scale_offset(options, scale, offset);

  // the header (written again at the end with the counts and bounds)
  std::uint16_t global_encoding = 0;
  std::string header = las_header_start(source, l, scale, offset, global_encoding);
  std::fwrite(header.data(), 1, header.size(), f);
  std::fwrite(vlrs.data(), 1, vlrs.size(), f);

  // the points
  std::uint64_t by_return[15] = {};
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  std::size_t not_finite = 0;
  const std::size_t step = std::max<std::size_t>(1, n / 100);
  std::vector<char> chunk;
  std::vector<char> record(record_length);
  Output_row r;
  for(std::size_t i = 0; i < n; ++i)
  {
    row(i, r);
    auto attribute = [&](std::size_t j) { return r.attributes ? r.attributes[j] : attributes[j].values[i]; };
    auto field = [&](int f, double otherwise) {
      return standard_source[f] >= 0 ? attribute(std::size_t(standard_source[f])) : otherwise;
    };
    std::fill(record.begin(), record.end(), '\0');
    char* p = record.data();
    const bool finite = std::isfinite(r.value[0]) && std::isfinite(r.value[1]) && std::isfinite(r.value[2]);
    if(finite)
      for(int a = 0; a < 3; ++a)
      {
        const std::int32_t X = to_integer<std::int32_t>((r.value[a] - offset[a]) / scale[a]);
        put(p + 4 * a, X);
        const double v = double(X) * scale[a] + offset[a];
        lo[a] = std::min(lo[a], v);
        hi[a] = std::max(hi[a], v);
      }
    else
      ++not_finite;
    encode_las_fields(p, format, finite, field, by_return);
    for(const Extra& x : extras)
    {
      const int s = fields[x.field].source;
      const double v = s < output_value_count ? r.value[s] : attribute(std::size_t(s - Output_field::ATTRIBUTE));
      put_extra(p + x.offset, x.data_type, (v - x.shift) / x.scale);
    }
    chunk.insert(chunk.end(), record.begin(), record.end());
    if(chunk.size() > (1u << 20))
    {
      std::fwrite(chunk.data(), 1, chunk.size(), f);
      chunk.clear();
    }
    if(progress && (i + 1) % step == 0 && !progress(double(i + 1) / double(n)))
      throw Cancelled();
  }
  if(!chunk.empty())
    std::fwrite(chunk.data(), 1, chunk.size(), f);
  if(not_finite > 0)
    warnings.push_back(cat(not_finite, " points with non-finite coordinates are written to the LAS output at its "
                                       "offset, withheld (LAS coordinates are integers)"));

  // the extended variable length records, copied from the input
  std::uint64_t first_evlr = 0, waveform_start = 0;
  std::uint32_t evlr_count = 0;
  const std::uint64_t at = copy_las_evlrs(f, options, source, point_offset + std::uint64_t(n) * record_length,
                                          first_evlr, waveform_start, evlr_count);
  if(waveform_start == 0)
    global_encoding &= ~std::uint16_t(2);  // no waveform data packets in the file

  // the header again, complete
  finish_las_header(header, format, n, global_encoding, by_return, lo, hi, waveform_start, first_evlr, evlr_count);
  if(std::fseek(f, 0, SEEK_SET) != 0)
    throw Error("cannot write the LAS header: the output is not seekable");
  std::fwrite(header.data(), 1, header.size(), f);
  // back to the end of what was written: the file may have been allocated longer (the
  // reservation counts an extra-bytes EVLR that is not copied), and is cut where it ends
  if(::fseeko(f, off_t(at), SEEK_SET) != 0)
    throw Error("cannot write the LAS output: the output is not seekable");
  return warnings;
}

}  // namespace psc_tool
