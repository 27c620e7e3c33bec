// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// An independent LAS 1.4 reader for the tests of the tool's LAS output (test_tool_las.cpp),
// written from the ASPRS LAS 1.4 R15 specification with its byte offsets, sharing no code
// with the tool (io/src/read_las.cpp, io/src/write_las.cpp): the public header block, the
// variable length records (54-byte headers), the extended ones (60-byte headers), the
// extra-bytes descriptors (LASF_Spec record 4, 192 bytes each) and the point records as
// bytes. Also what the tests need to write LAS inputs with VLRs, extra bytes and EVLRs.

#ifndef PSC_TEST_LAS_TEST_READER_H
#define PSC_TEST_LAS_TEST_READER_H

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace psc_las_test {

// A little-endian value at byte `at` of `s` (bounds checked: a short file fails the test
// with an exception rather than reading past it).
template <class T>
T le(const std::string& s, std::size_t at)
{
  if(at + sizeof(T) > s.size())
    throw std::out_of_range("LAS test reader: read past the end of the file");
  unsigned char b[sizeof(T)];
  for(std::size_t k = 0; k < sizeof(T); ++k)
    b[k] = static_cast<unsigned char>(s[at + k]);  // the test machines are little-endian, as LAS is
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

template <class T>
void set_le(std::string& s, std::size_t at, T v)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  for(std::size_t k = 0; k < sizeof(T); ++k)
    s[at + k] = char(b[k]);
}

// A NUL-padded text field.
inline std::string text(const std::string& s, std::size_t at, std::size_t size)
{
  const std::string t = s.substr(at, size);
  return t.substr(0, t.find('\0'));
}

struct Record
{
  std::string user_id;
  int record_id = 0;
  std::string description;
  std::string payload;
  std::uint64_t at = 0;  // where its header starts in the file
};

struct Descriptor
{
  int data_type = 0, options = 0;
  std::string name, description;
  std::string no_data;  // the 8 bytes
  double scale = 0, offset = 0;
  std::string bytes;  // all 192
};

struct Las
{
  std::string file;
  int major = 0, minor = 0, format = 0;
  std::uint16_t file_source_id = 0, global_encoding = 0, day = 0, year = 0, header_size = 0;
  std::uint32_t point_offset = 0, vlr_count = 0, legacy_count = 0, legacy_by_return[5] = {};
  std::uint16_t record_length = 0;
  std::string system_id, software;
  double scale[3] = {}, offset[3] = {}, max[3] = {}, min[3] = {};
  std::uint64_t waveform_start = 0, first_evlr = 0, count = 0, by_return[15] = {};
  std::uint32_t evlr_count = 0;
  std::vector<Record> vlrs, evlrs;
  std::vector<Descriptor> descriptors;

  // point record i's bytes
  std::string record(std::size_t i) const
  {
    return file.substr(point_offset + i * std::size_t(record_length), record_length);
  }
  std::size_t record_at(std::size_t i) const { return point_offset + i * std::size_t(record_length); }
  // coordinate a of point i
  double coordinate(std::size_t i, int a) const
  {
    return double(le<std::int32_t>(file, record_at(i) + 4 * std::size_t(a))) * scale[a] + offset[a];
  }
  // the extra-bytes descriptor named `name` and its offset in the records (after the standard fields)
  const Descriptor* extra(const std::string& name, std::size_t& at) const
  {
    static const std::size_t standard[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
    static const std::size_t size[11] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
    at = standard[format];
    for(const Descriptor& d : descriptors)
    {
      if(d.name == name)
        return &d;
      at += d.data_type == 0 ? std::size_t(d.options) : size[d.data_type];
    }
    return nullptr;
  }
};

// Parses a LAS 1.4 file from its bytes, with the offsets of the specification's tables.
inline Las read_las_1_4(const std::string& file)
{
  Las l;
  l.file = file;
  if(file.compare(0, 4, "LASF") != 0)
    throw std::runtime_error("LAS test reader: no LASF signature");
  l.file_source_id = le<std::uint16_t>(file, 4);
  l.global_encoding = le<std::uint16_t>(file, 6);
  l.major = le<std::uint8_t>(file, 24);
  l.minor = le<std::uint8_t>(file, 25);
  l.system_id = text(file, 26, 32);
  l.software = text(file, 58, 32);
  l.day = le<std::uint16_t>(file, 90);
  l.year = le<std::uint16_t>(file, 92);
  l.header_size = le<std::uint16_t>(file, 94);
  l.point_offset = le<std::uint32_t>(file, 96);
  l.vlr_count = le<std::uint32_t>(file, 100);
  l.format = le<std::uint8_t>(file, 104);
  l.record_length = le<std::uint16_t>(file, 105);
  l.legacy_count = le<std::uint32_t>(file, 107);
  for(int k = 0; k < 5; ++k)
    l.legacy_by_return[k] = le<std::uint32_t>(file, 111 + 4 * k);
  for(int a = 0; a < 3; ++a)
  {
    l.scale[a] = le<double>(file, 131 + 8 * a);
    l.offset[a] = le<double>(file, 155 + 8 * a);
    l.max[a] = le<double>(file, 179 + 16 * a);
    l.min[a] = le<double>(file, 187 + 16 * a);
  }
  l.waveform_start = le<std::uint64_t>(file, 227);
  l.first_evlr = le<std::uint64_t>(file, 235);
  l.evlr_count = le<std::uint32_t>(file, 243);
  l.count = le<std::uint64_t>(file, 247);
  for(int k = 0; k < 15; ++k)
    l.by_return[k] = le<std::uint64_t>(file, 255 + 8 * k);
  std::size_t at = l.header_size;
  for(std::uint32_t k = 0; k < l.vlr_count; ++k)
  {
    Record r;
    r.at = at;
    r.user_id = text(file, at + 2, 16);
    r.record_id = le<std::uint16_t>(file, at + 18);
    const std::size_t length = le<std::uint16_t>(file, at + 20);
    r.description = text(file, at + 22, 32);
    r.payload = file.substr(at + 54, length);
    at += 54 + length;
    l.vlrs.push_back(r);
  }
  if(at != l.point_offset)
    throw std::runtime_error("LAS test reader: the VLRs do not end at the point data");
  std::uint64_t e = l.first_evlr;
  for(std::uint32_t k = 0; k < l.evlr_count; ++k)
  {
    Record r;
    r.at = e;
    r.user_id = text(file, e + 2, 16);
    r.record_id = le<std::uint16_t>(file, e + 18);
    const std::uint64_t length = le<std::uint64_t>(file, e + 20);
    r.description = text(file, e + 28, 32);
    r.payload = file.substr(e + 60, length);
    e += 60 + length;
    l.evlrs.push_back(r);
  }
  for(const Record& r : l.vlrs)
    if(r.user_id == "LASF_Spec" && r.record_id == 4)
      for(std::size_t d = 0; d + 192 <= r.payload.size(); d += 192)
      {
        const std::string b = r.payload.substr(d, 192);
        Descriptor x;
        x.bytes = b;
        x.data_type = le<std::uint8_t>(b, 2);
        x.options = le<std::uint8_t>(b, 3);
        x.name = text(b, 4, 32);
        x.no_data = b.substr(40, 8);
        x.scale = le<double>(b, 112);
        x.offset = le<double>(b, 136);
        x.description = text(b, 160, 32);
        l.descriptors.push_back(x);
      }
  return l;
}

// A VLR's bytes (54-byte header and payload).
inline std::string vlr(const std::string& user_id, int record_id, const std::string& payload)
{
  std::string h(54, '\0');
  h.replace(2, user_id.size(), user_id);
  set_le<std::uint16_t>(h, 18, std::uint16_t(record_id));
  set_le<std::uint16_t>(h, 20, std::uint16_t(payload.size()));
  return h + payload;
}

// An EVLR's bytes (60-byte header and payload).
inline std::string evlr(const std::string& user_id, int record_id, const std::string& payload)
{
  std::string h(60, '\0');
  h.replace(2, user_id.size(), user_id);
  set_le<std::uint16_t>(h, 18, std::uint16_t(record_id));
  set_le<std::uint64_t>(h, 20, std::uint64_t(payload.size()));
  return h + payload;
}

// An extra-bytes descriptor.
inline std::string descriptor(int data_type, const std::string& name, int options = 0, double scale = 0,
                              double offset = 0, const std::string& description = "")
{
  std::string d(192, '\0');
  d[2] = char(data_type);
  d[3] = char(options);
  d.replace(4, name.size(), name);
  set_le<double>(d, 112, scale);
  set_le<double>(d, 136, offset);
  d.replace(160, description.size(), description);
  return d;
}

// The GeoKeyDirectory payload of one key: GTModelTypeGeoKey (1024) = model (1 projected, 2
// geographic).
inline std::string geokeys(int model)
{
  std::string p(16, '\0');
  const std::uint16_t v[8] = {1, 1, 0, 1, 1024, 0, 1, std::uint16_t(model)};
  for(int k = 0; k < 8; ++k)
    set_le<std::uint16_t>(p, 2 * std::size_t(k), v[k]);
  return p;
}

// `las` (a file without VLRs, its records' extra bytes last) with `vlrs` inserted between
// its header and its points (offset to the points and VLR count updated).
inline std::string with_vlrs(std::string las, const std::vector<std::string>& vlrs)
{
  const std::size_t header = le<std::uint16_t>(las, 94);
  std::string all;
  for(const std::string& v : vlrs)
    all += v;
  set_le<std::uint32_t>(las, 96, std::uint32_t(header + all.size()));
  set_le<std::uint32_t>(las, 100, std::uint32_t(vlrs.size()));
  return las.substr(0, header) + all + las.substr(header);
}

}  // namespace psc_las_test

#endif
