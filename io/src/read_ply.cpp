// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The PLY reader: ASCII and binary (both byte orders), any property order and scalar
// type, normals named nx ny nz or normal_x normal_y normal_z, other elements and properties
// skipped. Header counts are never trusted: what is reserved is bounded by the file's size,
// and a count beyond the data ends in a "truncated" error when the data runs out.

#include "input_bytes.h"

#include <cmath>
#include <limits>

namespace psc_tool {
namespace input {
namespace {

typedef Scalar_type Ply_type;

bool ply_type(std::string_view name, Ply_type& t)
{
  static const std::pair<const char*, Ply_type> names[] = {
    {"char", Ply_type::INT8},      {"int8", Ply_type::INT8},       {"uchar", Ply_type::UINT8},
    {"uint8", Ply_type::UINT8},    {"short", Ply_type::INT16},     {"int16", Ply_type::INT16},
    {"ushort", Ply_type::UINT16},  {"uint16", Ply_type::UINT16},   {"int", Ply_type::INT32},
    {"int32", Ply_type::INT32},    {"uint", Ply_type::UINT32},     {"uint32", Ply_type::UINT32},
    {"float", Ply_type::FLOAT32},  {"float32", Ply_type::FLOAT32}, {"double", Ply_type::FLOAT64},
    {"float64", Ply_type::FLOAT64}};
  for(const auto& n : names)
    if(name == n.first)
    {
      t = n.second;
      return true;
    }
  return false;
}

std::size_t type_size(Ply_type t)
{
  switch(t)
  {
    case Ply_type::INT8:
    case Ply_type::UINT8: return 1;
    case Ply_type::INT16:
    case Ply_type::UINT16: return 2;
    case Ply_type::INT32:
    case Ply_type::UINT32:
    case Ply_type::FLOAT32: return 4;
    default: return 8;
  }
}

bool is_integer(Ply_type t) { return t != Ply_type::FLOAT32 && t != Ply_type::FLOAT64; }

// A binary scalar as a double; `swap`: the file's byte order differs from the machine's.
double binary_value(const char* p, Ply_type t, bool swap)
{
  char b[8];
  const std::size_t n = type_size(t);
  std::memcpy(b, p, n);
  if(swap)
    std::reverse(b, b + n);
  switch(t)
  {
    case Ply_type::INT8: {
      std::int8_t v;
      std::memcpy(&v, b, 1);
      return v;
    }
    case Ply_type::UINT8: {
      std::uint8_t v;
      std::memcpy(&v, b, 1);
      return v;
    }
    case Ply_type::INT16: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Ply_type::UINT16: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case Ply_type::INT32: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Ply_type::UINT32: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case Ply_type::FLOAT32: {
      float v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default: {
      double v;
      std::memcpy(&v, b, 8);
      return v;
    }
  }
}

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::FLOAT32;  // of the items for a list
  bool list = false;
  Ply_type count_type = Ply_type::UINT8;
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;

  // bytes of one item in binary when its lists are empty; whether it has lists
  std::size_t least_binary_size() const
  {
    std::size_t s = 0;
    for(const Ply_property& p : properties)
      s += p.list ? type_size(p.count_type) : type_size(p.type);
    return s;
  }
  bool has_lists() const
  {
    return std::any_of(properties.begin(), properties.end(), [](const Ply_property& p) { return p.list; });
  }
};

enum class Ply_format { ASCII, BINARY_LITTLE_ENDIAN, BINARY_BIG_ENDIAN };

struct Ply_header
{
  Ply_format format = Ply_format::ASCII;
  std::vector<Ply_element> elements;
  std::size_t vertex = 0;  // index of the vertex element
  int role_property[6];    // per role (x y z nx ny nz), the vertex property, or -1
  // per vertex property, its attribute in Point_cloud::attributes, or -1 (roles, lists,
  // attributes not kept)
  std::vector<int> attribute_of;
};

Ply_header read_ply_header(Line_source& lines, const std::string& path)
{
  Ply_header h;
  std::string_view line;
  std::vector<std::string_view> w;
  auto fail = [&](const std::string& what) {
    throw Error(cat(in_quotes(path), " PLY header line ", lines.line_number(), ": ", what));
  };
  if(lines.next(line) && line.size() >= 3 && line.substr(0, 3) == "\xEF\xBB\xBF")
    line.remove_prefix(3);  // UTF-8 byte order mark
  if(lines.line_number() == 0 || trim(line) != "ply")
    throw Error(cat(in_quotes(path), ": not a PLY file (no 'ply' on its first line)"));
  bool format = false, end = false;
  while(!end && lines.next(line))
  {
    split_spaces(line, w);
    if(w.empty())
      continue;
    if(w[0] == "end_header")
      end = true;
    else if(w[0] == "comment" || w[0] == "obj_info")
      continue;
    else if(w[0] == "format")
    {
      if(w.size() != 3)
        fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if(w[1] == "ascii")
        h.format = Ply_format::ASCII;
      else if(w[1] == "binary_little_endian")
        h.format = Ply_format::BINARY_LITTLE_ENDIAN;
      else if(w[1] == "binary_big_endian")
        h.format = Ply_format::BINARY_BIG_ENDIAN;
      else
        throw Error(cat(in_quotes(path), ": unknown PLY format ", quoted(w[1])));
      format = true;
    }
    else if(w[0] == "element")
    {
      std::uint64_t count = 0;
      if(w.size() != 3)
        fail("expected 'element NAME COUNT'");
      if(!parse_count(w[2], count))
        throw Error(cat(in_quotes(path), ": invalid PLY element count ", quoted(w[2])));
      h.elements.push_back(Ply_element{std::string(w[1]), count, {}});
    }
    else if(w[0] == "property")
    {
      if(h.elements.empty())
        fail("a property before any element");
      Ply_property p;
      const bool list = w.size() >= 2 && w[1] == "list";
      if(list ? w.size() != 5 : w.size() != 3)
        fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
      if(list && (!ply_type(w[2], p.count_type) || !is_integer(p.count_type)))
        fail(cat("invalid list count type ", quoted(w[2])));
      if(!ply_type(w[list ? 3 : 1], p.type))
        fail(cat("unknown property type ", quoted(w[list ? 3 : 1])));
      p.list = list;
      p.name = std::string(w[list ? 4 : 2]);
      h.elements.back().properties.push_back(p);
    }
    else
      fail(cat("unexpected ", quoted(line)));
  }
  if(!end)
    throw Error(cat(in_quotes(path), ": truncated PLY header (no end_header)"));
  if(!format)
    throw Error(cat(in_quotes(path), ": PLY header without a format line"));

  h.vertex = h.elements.size();
  for(std::size_t e = 0; e < h.elements.size() && h.vertex == h.elements.size(); ++e)
    if(h.elements[e].name == "vertex" || h.elements[e].name == "vertices")
      h.vertex = e;
  if(h.vertex == h.elements.size())
    throw Error(cat(in_quotes(path), ": the PLY header declares no vertex element"));
  // x y z, and the normals under either name (the first complete set of names wins)
  const Ply_element& v = h.elements[h.vertex];
  auto find = [&](const char* name) {
    for(std::size_t i = 0; i < v.properties.size(); ++i)
      if(v.properties[i].name == name)
        return v.properties[i].list ? -2 : int(i);
    return -1;
  };
  const char* const coordinates[3] = {"x", "y", "z"};
  for(int r = 0; r < 3; ++r)
  {
    h.role_property[r] = find(coordinates[r]);
    if(h.role_property[r] < 0)
      throw Error(cat(in_quotes(path), ": the PLY vertex element has no scalar property ", coordinates[r]));
  }
  const char* const normal_names[2][3] = {{"nx", "ny", "nz"}, {"normal_x", "normal_y", "normal_z"}};
  h.role_property[3] = h.role_property[4] = h.role_property[5] = -1;
  for(const auto& names : normal_names)
  {
    int found[3], present = 0;
    for(int a = 0; a < 3; ++a)
    {
      found[a] = find(names[a]);
      present += found[a] >= 0;
      if(found[a] == -2)
        throw Error(cat(in_quotes(path), ": the PLY vertex property ", names[a], " is a list"));
    }
    if(present == 3 && h.role_property[3] < 0)
      for(int a = 0; a < 3; ++a)
        h.role_property[3 + a] = found[a];
    else if(present != 0 && present != 3)
      throw Error(
        cat(in_quotes(path), ": the PLY vertex element has only some of ", names[0], " ", names[1], " ", names[2]));
  }
  return h;
}

// The vertex properties that are neither coordinates nor normals nor lists become attributes.
void add_attributes(Ply_header& h, Point_cloud& cloud, bool keep, std::size_t reserved)
{
  const Ply_element& v = h.elements[h.vertex];
  h.attribute_of.assign(v.properties.size(), -1);
  if(!keep)
    return;
  for(std::size_t i = 0; i < v.properties.size(); ++i)
  {
    const Ply_property& p = v.properties[i];
    if(p.list || std::find(h.role_property, h.role_property + 6, int(i)) != h.role_property + 6)
      continue;
    h.attribute_of[i] = int(cloud.attributes.size());
    cloud.attributes.push_back(Attribute(p.name, p.type));
    cloud.attributes.back().values.reserve(reserved);
  }
}

std::string item_text(const Ply_element& e, std::uint64_t item)
{
  return cat(e.name, " ", item + 1, " of the ", e.count, " declared in the header");
}

void read_ply_binary(Byte_source& bytes, const Ply_header& h, Point_cloud& cloud, const std::string& path,
                     const Read_options& options)
{
  const std::uint16_t one = 1;
  unsigned char first_byte;
  std::memcpy(&first_byte, &one, 1);
  const bool little_host = first_byte == 1;
  const bool swap = (h.format == Ply_format::BINARY_LITTLE_ENDIAN) != little_host;
  const bool normals = h.role_property[3] >= 0;
  for(std::size_t ei = 0; ei < h.elements.size(); ++ei)
  {
    const Ply_element& e = h.elements[ei];
    const bool is_vertex = ei == h.vertex;
    // byte offset of each property in an item without lists
    std::vector<std::size_t> offset;
    std::size_t size = 0;
    for(const Ply_property& p : e.properties)
    {
      offset.push_back(size);
      size += p.list ? type_size(p.count_type) : type_size(p.type);
    }
    auto truncated = [&](std::uint64_t item) {
      throw Error(cat(in_quotes(path), ": truncated: the file ends in ", item_text(e, item)));
    };
    if(size == 0)
      continue;  // an element without properties holds no bytes
    if(!e.has_lists())
    {
      // fixed-size items, decoded a block at a time
      const std::size_t block = std::max<std::size_t>(1, (1u << 20) / size);
      for(std::uint64_t item = 0; item < e.count;)
      {
        const std::size_t n = std::size_t(std::min<std::uint64_t>(block, e.count - item));
        const std::size_t got = bytes.fill(n * size);
        if(got < n * size)
          truncated(item + got / size);
        if(is_vertex)
        {
          const char* base = bytes.data();
          for(std::size_t i = 0; i < n; ++i, base += size)
          {
            for(int r = 0; r < 3; ++r)
              cloud.xyz.push_back(
                binary_value(base + offset[h.role_property[r]], e.properties[h.role_property[r]].type, swap));
            if(normals)
              for(int r = 3; r < 6; ++r)
                cloud.normals.push_back(
                  binary_value(base + offset[h.role_property[r]], e.properties[h.role_property[r]].type, swap));
            for(std::size_t pi = 0; pi < e.properties.size(); ++pi)
              if(h.attribute_of[pi] >= 0)
                cloud.attributes[h.attribute_of[pi]].values.push_back(
                  binary_value(base + offset[pi], e.properties[pi].type, swap));
          }
        }
        bytes.advance(n * size);
        item += n;
        if(is_vertex)
          hand_over(cloud, options);
      }
      continue;
    }
    // items with lists, property by property
    double values[6] = {0, 0, 0, 0, 0, 0};
    for(std::uint64_t item = 0; item < e.count; ++item)
    {
      for(std::size_t pi = 0; pi < e.properties.size(); ++pi)
      {
        const Ply_property& p = e.properties[pi];
        if(!p.list)
        {
          if(bytes.fill(type_size(p.type)) < type_size(p.type))
            truncated(item);
          if(is_vertex)
          {
            for(int r = 0; r < 6; ++r)
              if(h.role_property[r] == int(pi))
                values[r] = binary_value(bytes.data(), p.type, swap);
            if(h.attribute_of[pi] >= 0)
              cloud.attributes[h.attribute_of[pi]].values.push_back(binary_value(bytes.data(), p.type, swap));
          }
          bytes.advance(type_size(p.type));
          continue;
        }
        if(bytes.fill(type_size(p.count_type)) < type_size(p.count_type))
          truncated(item);
        const double count = binary_value(bytes.data(), p.count_type, swap);
        bytes.advance(type_size(p.count_type));
        if(count < 0)
          throw Error(cat(in_quotes(path), ": negative list length ", count, " in ", item_text(e, item)));
        const long double list_bytes = (long double)count * type_size(p.type);
        if(list_bytes > (long double)bytes.remaining())
          truncated(item);
        for(std::uint64_t left = std::uint64_t(list_bytes); left > 0;)
        {
          const std::size_t chunk = std::size_t(std::min<std::uint64_t>(left, 1u << 20));
          if(bytes.fill(chunk) < chunk)
            truncated(item);
          bytes.advance(chunk);
          left -= chunk;
        }
      }
      if(is_vertex)
      {
        cloud.xyz.insert(cloud.xyz.end(), values, values + 3);
        if(normals)
          cloud.normals.insert(cloud.normals.end(), values + 3, values + 6);
        hand_over(cloud, options);
      }
    }
  }
}

// Values of an ASCII PLY body, across lines.
class Ascii_values
{
public:
  explicit Ascii_values(Line_source& lines) : m_lines(lines) {}
  bool next(std::string_view& value)
  {
    while(m_next == m_values.size())
    {
      std::string_view line;
      if(!m_lines.next(line))
        return false;
      // the words point into the line: valid until the next line is read, after they are used
      split_spaces(line, m_values);
      m_next = 0;
    }
    value = m_values[m_next++];
    return true;
  }
  std::size_t line_number() const { return m_lines.line_number(); }
  // every value of the current line was read
  bool at_line_end() const { return m_next == m_values.size(); }

private:
  Line_source& m_lines;
  std::vector<std::string_view> m_values;
  std::size_t m_next = 0;
};

void read_ply_ascii(Line_source& lines, const Ply_header& h, Point_cloud& cloud, const std::string& path,
                    const Read_options& options)
{
  Ascii_values values(lines);
  const bool normals = h.role_property[3] >= 0;
  for(std::size_t ei = 0; ei < h.elements.size(); ++ei)
  {
    const Ply_element& e = h.elements[ei];
    const bool is_vertex = ei == h.vertex;
    if(e.properties.empty())
      continue;  // an element without properties holds no values
    double point[6] = {0, 0, 0, 0, 0, 0};
    for(std::uint64_t item = 0; item < e.count; ++item)
    {
      // each element is one line (PLY): its values may not run over to the next line, nor
      // share theirs with the next element
      std::size_t item_line = 0;
      auto number = [&](double& v) {
        std::string_view t;
        if(!values.next(t))
          throw Error(cat(in_quotes(path), ": truncated: the file ends in ", item_text(e, item)));
        if(item_line == 0)
          item_line = values.line_number();
        else if(values.line_number() != item_line)
          throw Error(cat(in_quotes(path), ": line ", item_line, ": fewer values than the properties of ",
                          item_text(e, item), " (each element is one line; wrong properties in the header?)"));
        if(!parse_number(t, v))
          throw Error(cat(in_quotes(path), ": line ", values.line_number(), ": ", quoted(t), " is not a number (",
                          item_text(e, item), ")"));
      };
      for(std::size_t pi = 0; pi < e.properties.size(); ++pi)
      {
        const Ply_property& p = e.properties[pi];
        double v = 0;
        number(v);
        if(!p.list)
        {
          if(is_vertex)
          {
            for(int r = 0; r < 6; ++r)
              if(h.role_property[r] == int(pi))
                point[r] = v;
            if(h.attribute_of[pi] >= 0)
              cloud.attributes[h.attribute_of[pi]].values.push_back(v);
          }
          continue;
        }
        if(!(v >= 0) || v != std::floor(v) || v > 1e15)
          throw Error(cat(in_quotes(path), ": line ", values.line_number(), ": invalid list length ", v, " (",
                          item_text(e, item), ")"));
        for(double c = v; c > 0; --c)
          number(v);
      }
      if(!values.at_line_end())
        throw Error(cat(in_quotes(path), ": line ", item_line, ": more values than the properties of ",
                        item_text(e, item), " (each element is one line; wrong properties in the header?)"));
      if(is_vertex)
      {
        cloud.xyz.insert(cloud.xyz.end(), point, point + 3);
        if(normals)
          cloud.normals.insert(cloud.normals.end(), point + 3, point + 6);
        hand_over(cloud, options);
      }
    }
  }
  std::string_view extra;
  if(values.next(extra))
  {
    const Ply_element& v = h.elements[h.vertex];
    throw Error(cat(in_quotes(path), ": line ", values.line_number(), ": more data than the ", v.count, " vertices",
                    h.elements.size() > 1 ? " and other elements" : "",
                    " declared in the header (wrong vertex count?)"));
  }
}

}  // namespace

Point_cloud read_ply(Byte_source& bytes, const std::string& path, const Read_options& options)
{
  Line_source lines(bytes);
  Ply_header h = read_ply_header(lines, path);
  Point_cloud cloud;
  const Ply_element& v = h.elements[h.vertex];
  // Counts are not trusted: a vertex takes at least 3 bytes (binary) or 6 (ASCII), so the
  // file's size bounds what is reserved; a count beyond what the file holds ends in a
  // "truncated" error when the data runs out.
  const std::uint64_t most = bytes.remaining() / (h.format == Ply_format::ASCII ? 6 : 3);
  std::uint64_t reserved = std::min(v.count, most);
  if(options.chunk)
    reserved = std::min<std::uint64_t>(reserved, options.chunk_points + (1u << 20) / 3);
  cloud.xyz.reserve(3 * reserved);
  add_attributes(h, cloud, options.keep_attributes, std::size_t(reserved));
  if(h.role_property[3] >= 0)
  {
    cloud.normals.reserve(3 * reserved);
    cloud.normals_source = cat("the PLY properties ", v.properties[h.role_property[3]].name, " ",
                               v.properties[h.role_property[4]].name, " ", v.properties[h.role_property[5]].name);
  }
  if(h.format == Ply_format::ASCII)
    read_ply_ascii(lines, h, cloud, path, options);
  else
  {
    read_ply_binary(bytes, h, cloud, path, options);
    // a line break some writers append after the data is not data
    for(int i = 0; i < 2 && bytes.fill(1) == 1 && (*bytes.data() == '\n' || *bytes.data() == '\r'); ++i)
      bytes.advance(1);
    if(!bytes.at_end())
      throw Error(cat(in_quotes(path), ": more data than the ", v.count, " vertices",
                      h.elements.size() > 1 ? " and other elements" : "",
                      " declared in the header (wrong vertex count?)"));
  }
  hand_over(cloud, options, true);
  return cloud;
}

}  // namespace input

Ply_vertex_layout ply_vertex_layout(const std::string& path)
{
  using namespace input;
  const std::uint64_t size = regular_file_size(path);
  Byte_source bytes(path, size, Progress());
  Line_source lines(bytes);
  const Ply_header h = read_ply_header(lines, path);
  if(h.format == Ply_format::ASCII)
    throw Error(cat(in_quotes(path),
                    ": an ASCII PLY file cannot be read in place: only binary PLY files are "
                    "(convert it, for example with the point_set_curvatures tool, or save the points as .npy)"));
  Ply_vertex_layout layout;
  layout.big_endian = h.format == Ply_format::BINARY_BIG_ENDIAN;
  layout.offset = bytes.consumed();
  const std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
  for(std::size_t e = 0; e <= h.vertex; ++e)
    if(h.elements[e].has_lists())
      throw Error(cat(in_quotes(path), ": the PLY element ", quoted(h.elements[e].name), " has list properties ",
                      e == h.vertex ? "" : "before the vertices ",
                      "(records of varying size cannot be read in place)"));
  for(std::size_t e = 0; e < h.vertex; ++e)
  {
    const Ply_element& element = h.elements[e];
    const std::size_t record = element.least_binary_size();
    if(record > 0 && element.count > (most - layout.offset) / record)
      throw Error(cat(in_quotes(path), ": truncated (the PLY element ", quoted(element.name), " of ", element.count,
                      " items is larger than any file)"));
    layout.offset += element.count * record;
  }
  const Ply_element& v = h.elements[h.vertex];
  layout.count = v.count;
  for(const Ply_property& p : v.properties)
  {
    layout.properties.push_back(Ply_vertex_layout::Property{p.name, p.type, layout.record_size});
    layout.record_size += type_size(p.type);
  }
  for(int a = 0; a < 3; ++a)
  {
    layout.xyz[a] = h.role_property[a];
    layout.normal[a] = h.role_property[3 + a];
  }
  if(layout.offset > size || v.count > (size - layout.offset) / layout.record_size)
    throw Error(cat(in_quotes(path), ": truncated (", size, " bytes, the PLY header announces ", v.count,
                    " vertices of ", layout.record_size, " bytes from byte ", layout.offset, ")"));
  return layout;
}

}  // namespace psc_tool
