// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's readers (see read_point_cloud.h). Layers, bottom up: Byte_source (the file in
// blocks, progress by bytes consumed), Line_source (text lines on it), the text formats
// (.xyz family, .off), then PLY (header, then ASCII or binary records).

#include "read_point_cloud.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string_view>

namespace psc_tool {
namespace {

// ---------------------------------------------------------------------------------------
// Bytes and lines

// The file, read in blocks into a buffer that holds at least what the parser asks for.
// Progress: the fraction of the file consumed, reported at least every 1% and every 16 MB.
class Byte_source
{
public:
  Byte_source(const std::string& path, std::uint64_t size, const Progress& progress)
    : m_size(size), m_progress(progress)
  {
    m_file = std::fopen(path.c_str(), "rb");
    if(!m_file)
      throw Error(cat("cannot open input ", in_quotes(path), ": ", std::strerror(errno)));
    m_step = std::max<std::uint64_t>(1, std::min<std::uint64_t>(size / 100, 16u << 20));
    m_next_report = m_step;
    m_buffer.resize(1 << 20);
  }
  ~Byte_source() { std::fclose(m_file); }
  Byte_source(const Byte_source&) = delete;
  Byte_source& operator=(const Byte_source&) = delete;

  // Buffers at least `n` bytes from the current position if the file has them; returns the
  // number of bytes buffered (fewer than n only at the end of the file).
  std::size_t fill(std::size_t n)
  {
    if(m_end - m_pos >= n || m_eof)
      return m_end - m_pos;
    std::memmove(m_buffer.data(), m_buffer.data() + m_pos, m_end - m_pos);
    m_end -= m_pos;
    m_pos = 0;
    if(m_buffer.size() < n)
      m_buffer.resize(std::max(n, 2 * m_buffer.size()));
    while(m_end < n && !m_eof)
    {
      const std::size_t got = std::fread(m_buffer.data() + m_end, 1, m_buffer.size() - m_end, m_file);
      m_end += got;
      if(got == 0)
      {
        if(std::ferror(m_file))
          throw Error(cat("cannot read input: ", std::strerror(errno)));
        m_eof = true;
      }
    }
    return m_end - m_pos;
  }
  std::size_t buffered() const { return m_end - m_pos; }
  const char* data() const { return m_buffer.data() + m_pos; }
  void advance(std::size_t n)
  {
    m_pos += n;
    m_consumed += n;
    if(m_consumed >= m_next_report)
    {
      m_next_report = m_consumed + m_step;
      if(m_progress && !m_progress(std::min(1.0, double(m_consumed) / double(std::max<std::uint64_t>(m_size, 1)))))
        throw Cancelled();
    }
  }
  // Bytes of the file after the current position (from its size when opened).
  std::uint64_t remaining() const { return m_size > m_consumed ? m_size - m_consumed : 0; }
  bool at_end() { return fill(1) == 0; }

private:
  std::FILE* m_file = nullptr;
  std::vector<char> m_buffer;
  std::size_t m_pos = 0, m_end = 0;
  bool m_eof = false;
  std::uint64_t m_size = 0, m_consumed = 0, m_step = 1, m_next_report = 1;
  Progress m_progress;
};

// Lines of a Byte_source, without their end of line ("\n" or "\r\n"). A line is valid until
// the next call.
class Line_source
{
public:
  explicit Line_source(Byte_source& bytes) : m_bytes(bytes) {}

  bool next(std::string_view& line)
  {
    std::size_t scanned = 0;
    for(;;)
    {
      const std::size_t available = m_bytes.buffered();
      const char* begin = m_bytes.data();
      const void* nl = std::memchr(begin + scanned, '\n', available - scanned);
      if(nl)
        return take(line, std::size_t(static_cast<const char*>(nl) - begin), 1);
      scanned = available;
      if(m_bytes.fill(available + (1 << 20)) == available)  // end of the file
        return available > 0 && take(line, available, 0);
    }
  }
  std::size_t line_number() const { return m_line_number; }

private:
  // The first `length` buffered bytes are the line, followed by `end` bytes of end of line.
  bool take(std::string_view& line, std::size_t length, std::size_t end)
  {
    line = std::string_view(m_bytes.data(), length);
    if(!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    ++m_line_number;
    m_bytes.advance(length + end);
    return true;
  }

  Byte_source& m_bytes;
  std::size_t m_line_number = 0;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s)
{
  while(!s.empty() && is_space(s.front()))
    s.remove_prefix(1);
  while(!s.empty() && is_space(s.back()))
    s.remove_suffix(1);
  return s;
}

// Words of a line separated by white space.
void split_spaces(std::string_view line, std::vector<std::string_view>& words)
{
  words.clear();
  std::size_t i = 0;
  while(i < line.size())
  {
    while(i < line.size() && is_space(line[i]))
      ++i;
    const std::size_t b = i;
    while(i < line.size() && !is_space(line[i]))
      ++i;
    if(i > b)
      words.push_back(line.substr(b, i - b));
  }
}

// Values of a line of a text point file: separated by commas if the line has one (an empty
// field is kept, as an empty value), else by white space.
void split(std::string_view line, std::vector<std::string_view>& values)
{
  if(line.find(',') == std::string_view::npos)
    return split_spaces(line, values);
  values.clear();
  for(;;)
  {
    const std::size_t comma = line.find(',');
    values.push_back(trim(line.substr(0, comma)));
    if(comma == std::string_view::npos)
      return;
    line.remove_prefix(comma + 1);
  }
}

// A decimal number, the whole token (a leading '+' allowed; nan and inf are numbers: such
// points get the status non_finite_point).
bool parse_number(std::string_view t, double& v)
{
  const char* b = t.data();
  const char* e = b + t.size();
  if(b != e && *b == '+')
    ++b;
  if(b == e)
    return false;
  const std::from_chars_result r = std::from_chars(b, e, v);
  return r.ec == std::errc() && r.ptr == e;
}

// A count: decimal digits only, below 2^63.
bool parse_count(std::string_view t, std::uint64_t& v)
{
  if(t.empty() || t.size() > 18 || t.find_first_not_of("0123456789") != std::string_view::npos)
    return false;
  std::from_chars(t.data(), t.data() + t.size(), v);
  return true;
}

std::string quoted(std::string_view t) { return in_quotes(std::string(t.substr(0, 60))); }

// Role of a named column or property: 0-2 for x y z, 3-5 for the normal, -1 for anything
// else. Names are compared in lower case, without the leading '/' of CloudCompare's "//X".
int role_of(std::string name)
{
  name = lower_case(name);
  name.erase(0, name.find_first_not_of('/'));
  static const char* const names[6][3] = {{"x", "", ""},
                                          {"y", "", ""},
                                          {"z", "", ""},
                                          {"nx", "normal_x", "normalx"},
                                          {"ny", "normal_y", "normaly"},
                                          {"nz", "normal_z", "normalz"}};
  for(int r = 0; r < 6; ++r)
    for(const char* n : names[r])
      if(*n && name == n)
        return r;
  return -1;
}

// Checks a layout of roles (one per column); describes the problem, or returns "".
std::string layout_problem(const std::vector<int>& roles)
{
  int count[6] = {0, 0, 0, 0, 0, 0};
  for(int r : roles)
    if(r >= 0)
      ++count[r];
  static const char* const names[6] = {"x", "y", "z", "nx", "ny", "nz"};
  for(int r = 0; r < 6; ++r)
    if(count[r] > 1)
      return cat("names ", names[r], " twice");
  if(!count[0] || !count[1] || !count[2])
    return "does not name all of x, y, z";
  const int normals = count[3] + count[4] + count[5];
  if(normals != 0 && normals != 3)
    return "names only some of nx, ny, nz";
  return "";
}

std::vector<int> roles_of(const std::vector<std::string>& names)
{
  std::vector<int> roles;
  for(const std::string& n : names)
    roles.push_back(role_of(n));
  return roles;
}

double median(std::vector<double> v)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// ---------------------------------------------------------------------------------------
// .xyz, .pwn, .txt, .csv

Point_cloud read_xyz(Byte_source& bytes, const std::string& path, const Read_options& options)
{
  Line_source lines(bytes);
  Point_cloud cloud;
  std::vector<std::string_view> values;
  std::vector<int> roles;  // per column; empty until the first line of values
  bool automatic_six = false, explicit_columns = !options.columns.empty();
  std::string layout_origin;
  std::uint64_t declared = 0;
  bool has_count = false, first_content = true;
  std::string_view line;
  if(explicit_columns)
  {
    roles = roles_of(options.columns);
    layout_origin = "--columns";
  }
  auto fail = [&](const std::string& what) {
    throw Error(cat(in_quotes(path), " line ", lines.line_number(), ": ", what));
  };
  while(lines.next(line))
  {
    if(lines.line_number() == 1 && line.size() >= 3 && line.substr(0, 3) == "\xEF\xBB\xBF")
      line.remove_prefix(3);  // UTF-8 byte order mark
    line = trim(line);
    if(line.empty() || line[0] == '#')
      continue;
    split(line, values);
    if(first_content)
    {
      first_content = false;
      std::uint64_t count = 0;
      if(lines.line_number() == 1 && values.size() == 1 && parse_count(values[0], count))
      {
        has_count = true;
        declared = count;
        continue;
      }
      // a header line of names: no value is a number
      bool names = true;
      for(std::string_view v : values)
      {
        double x;
        names = names && !v.empty() && !parse_number(v, x) &&
                (std::isalpha(static_cast<unsigned char>(v[0])) || v[0] == '_' || v[0] == '/');
      }
      if(names)
      {
        if(!explicit_columns)
        {
          std::vector<std::string> header(values.begin(), values.end());
          roles = roles_of(header);
          const std::string problem = layout_problem(roles);
          if(!problem.empty())
            fail(cat("the header line ", problem, ": give --columns to name the columns (for example "
                     "--columns x,y,z,nx,ny,nz)"));
          layout_origin = "the header line";
        }
        continue;
      }
    }
    if(roles.empty())
    {
      if(values.size() != 3 && values.size() != 6)
        fail(cat("expected 3 (x y z) or 6 (x y z nx ny nz) values, found ", values.size(),
                 "; give --columns to name them (for example --columns x,y,z,intensity)"));
      roles = values.size() == 3 ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 1, 2, 3, 4, 5};
      automatic_six = values.size() == 6;
      layout_origin = "the previous lines";
    }
    if(values.size() != roles.size())
      fail(cat(values.size(), " values where ", layout_origin,
               layout_origin == "the previous lines" ? " have " : " names ", roles.size()));
    double p[6] = {0, 0, 0, 0, 0, 0};
    for(std::size_t c = 0; c < values.size(); ++c)
    {
      if(roles[c] < 0)
        continue;
      if(!parse_number(values[c], p[roles[c]]))
        fail(values[c].empty() ? cat("empty value in column ", c + 1) : cat(quoted(values[c]), " is not a number"));
    }
    cloud.xyz.insert(cloud.xyz.end(), p, p + 3);
    cloud.normals.insert(cloud.normals.end(), p + 3, p + 6);
  }
  if(has_count && declared != cloud.size())
    throw Error(cat(in_quotes(path), ": its first line declares ", declared, " points but it has ", cloud.size()));
  const bool with_normals = std::count(roles.begin(), roles.end(), 3) == 1;
  if(!with_normals)
    cloud.normals.clear();
  else
    cloud.normals_source = automatic_six ? "columns 4-6" : cat("the columns named by ", layout_origin);
  if(automatic_six && cloud.size() > 0)
  {
    std::vector<double> lengths;
    for(std::size_t i = 0; i < cloud.size(); ++i)
    {
      const double* n = &cloud.normals[3 * i];
      const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if(std::isfinite(l))
        lengths.push_back(l);
    }
    const double m = median(lengths);
    if(!(m >= 0.5 && m <= 2))
      throw Error(cat(in_quotes(path), ": its columns 4-6 are not unit normals (median length ", m,
                      "): if they are colours or other values, give --columns to name the columns, for "
                      "example --columns x,y,z,r,g,b (normals are then estimated), or --columns "
                      "x,y,z,nx,ny,nz to use them as normals"));
  }
  return cloud;
}

// ---------------------------------------------------------------------------------------
// .off

Point_cloud read_off(Byte_source& bytes, const std::string& path)
{
  Line_source lines(bytes);
  Point_cloud cloud;
  std::vector<std::string_view> w;
  std::string_view line;
  std::string signature;
  std::uint64_t declared_vertices = 0, declared_faces = 0, faces = 0, dummy = 0;
  std::size_t columns = 0;
  int stage = 0;  // 0 signature, 1 counts, 2 vertices, 3 faces
  auto fail = [&](const std::string& what) {
    throw Error(cat(in_quotes(path), " line ", lines.line_number(), ": ", what));
  };
  while(lines.next(line))
  {
    line = trim(line);
    if(line.empty() || line[0] == '#')
      continue;
    split_spaces(line, w);
    if(stage == 0)
    {
      if(w.size() != 1 || (w[0] != "OFF" && w[0] != "NOFF"))
        fail("expected the header OFF or NOFF (binary and coloured OFF are not supported)");
      signature = std::string(w[0]);
      stage = 1;
    }
    else if(stage == 1)
    {
      if(w.size() != 3 || !parse_count(w[0], declared_vertices) || !parse_count(w[1], declared_faces) ||
         !parse_count(w[2], dummy))
        fail("expected the counts 'vertices faces edges'");
      stage = declared_vertices > 0 ? 2 : 3;
    }
    else if(stage == 2)
    {
      const std::size_t expected = signature == "NOFF" ? 6 : (columns ? columns : w.size());
      double p[6] = {0, 0, 0, 0, 0, 0};
      for(std::size_t c = 0; c < w.size() && c < 6; ++c)
        if(!parse_number(w[c], p[c]))
          fail(cat(quoted(w[c]), " is not a number"));
      if((w.size() != 3 && w.size() != 6) || w.size() != expected)
        fail(cat("expected ", signature == "NOFF" ? "6 (x y z nx ny nz)" : "3 (x y z) or 6 (x y z nx ny nz)",
                 " values like the other vertices, found ", w.size(), " (wrong vertex count in the header?)"));
      columns = w.size();
      cloud.xyz.insert(cloud.xyz.end(), p, p + 3);
      if(columns == 6)
        cloud.normals.insert(cloud.normals.end(), p + 3, p + 6);
      if(cloud.size() == declared_vertices)
        stage = 3;
    }
    else
    {
      std::uint64_t corners = 0, index = 0;
      if(!parse_count(w[0], corners) || corners + 1 > w.size() || faces >= declared_faces)
        fail(cat("unexpected line after the ", cloud.size(), " vertices and ", faces,
                 " faces declared (wrong vertex or face count?)"));
      for(std::size_t c = 1; c <= corners; ++c)
        if(!parse_count(w[c], index) || index >= declared_vertices)
          fail(cat("face with an invalid vertex index ", quoted(w[c])));
      ++faces;
    }
  }
  if(stage < 2)
    throw Error(cat(in_quotes(path), ": not an OFF file (missing header or counts)"));
  if(cloud.size() != declared_vertices)
    throw Error(cat(in_quotes(path), ": the header declares ", declared_vertices, " vertices but the file has ",
                    cloud.size()));
  if(faces != declared_faces)
    throw Error(cat(in_quotes(path), ": the header declares ", declared_faces, " faces but the file has ", faces));
  if(cloud.has_normals())
    cloud.normals_source = "the vertex lines (x y z nx ny nz)";
  return cloud;
}

// ---------------------------------------------------------------------------------------
// PLY

enum class Ply_type { INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

bool ply_type(std::string_view name, Ply_type& t)
{
  static const std::pair<const char*, Ply_type> names[] = {
    {"char", Ply_type::INT8},     {"int8", Ply_type::INT8},       {"uchar", Ply_type::UINT8},
    {"uint8", Ply_type::UINT8},   {"short", Ply_type::INT16},     {"int16", Ply_type::INT16},
    {"ushort", Ply_type::UINT16}, {"uint16", Ply_type::UINT16},   {"int", Ply_type::INT32},
    {"int32", Ply_type::INT32},   {"uint", Ply_type::UINT32},     {"uint32", Ply_type::UINT32},
    {"float", Ply_type::FLOAT32}, {"float32", Ply_type::FLOAT32}, {"double", Ply_type::FLOAT64},
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
    case Ply_type::INT8: case Ply_type::UINT8: return 1;
    case Ply_type::INT16: case Ply_type::UINT16: return 2;
    case Ply_type::INT32: case Ply_type::UINT32: case Ply_type::FLOAT32: return 4;
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
    case Ply_type::INT8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
    case Ply_type::UINT8: { std::uint8_t v; std::memcpy(&v, b, 1); return v; }
    case Ply_type::INT16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
    case Ply_type::UINT16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
    case Ply_type::INT32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::UINT32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::FLOAT32: { float v; std::memcpy(&v, b, 4); return v; }
    default: { double v; std::memcpy(&v, b, 8); return v; }
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
  std::size_t vertex = 0;        // index of the vertex element
  int role_property[6];          // per role (x y z nx ny nz), the vertex property, or -1
};

Ply_header read_ply_header(Line_source& lines, const std::string& path)
{
  Ply_header h;
  std::string_view line;
  std::vector<std::string_view> w;
  auto fail = [&](const std::string& what) {
    throw Error(cat(in_quotes(path), " PLY header line ", lines.line_number(), ": ", what));
  };
  if(!lines.next(line) || trim(line) != "ply")
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
      throw Error(cat(in_quotes(path), ": the PLY vertex element has only some of ", names[0], " ", names[1],
                      " ", names[2]));
  }
  return h;
}

std::string item_text(const Ply_element& e, std::uint64_t item)
{
  return cat(e.name, " ", item + 1, " of the ", e.count, " declared in the header");
}

void read_ply_binary(Byte_source& bytes, const Ply_header& h, Point_cloud& cloud, const std::string& path)
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
              cloud.xyz.push_back(binary_value(base + offset[h.role_property[r]],
                                               e.properties[h.role_property[r]].type, swap));
            if(normals)
              for(int r = 3; r < 6; ++r)
                cloud.normals.push_back(binary_value(base + offset[h.role_property[r]],
                                                     e.properties[h.role_property[r]].type, swap));
          }
        }
        bytes.advance(n * size);
        item += n;
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
            for(int r = 0; r < 6; ++r)
              if(h.role_property[r] == int(pi))
                values[r] = binary_value(bytes.data(), p.type, swap);
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

private:
  Line_source& m_lines;
  std::vector<std::string_view> m_values;
  std::size_t m_next = 0;
};

void read_ply_ascii(Line_source& lines, const Ply_header& h, Point_cloud& cloud, const std::string& path)
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
      auto number = [&](double& v) {
        std::string_view t;
        if(!values.next(t))
          throw Error(cat(in_quotes(path), ": truncated: the file ends in ", item_text(e, item)));
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
            for(int r = 0; r < 6; ++r)
              if(h.role_property[r] == int(pi))
                point[r] = v;
          continue;
        }
        if(!(v >= 0) || v != std::floor(v) || v > 1e15)
          throw Error(cat(in_quotes(path), ": line ", values.line_number(), ": invalid list length ", v, " (",
                          item_text(e, item), ")"));
        for(double c = v; c > 0; --c)
          number(v);
      }
      if(is_vertex)
      {
        cloud.xyz.insert(cloud.xyz.end(), point, point + 3);
        if(normals)
          cloud.normals.insert(cloud.normals.end(), point + 3, point + 6);
      }
    }
  }
  std::string_view extra;
  if(values.next(extra))
  {
    const Ply_element& v = h.elements[h.vertex];
    throw Error(cat(in_quotes(path), ": line ", values.line_number(), ": more data than the ", v.count,
                    " vertices", h.elements.size() > 1 ? " and other elements" : "",
                    " declared in the header (wrong vertex count?)"));
  }
}

Point_cloud read_ply(Byte_source& bytes, const std::string& path)
{
  Line_source lines(bytes);
  const Ply_header h = read_ply_header(lines, path);
  Point_cloud cloud;
  const Ply_element& v = h.elements[h.vertex];
  // Counts are not trusted: a vertex takes at least 3 bytes (binary) or 6 (ASCII), so the
  // file's size bounds what is reserved; a count beyond what the file holds ends in a
  // "truncated" error when the data runs out.
  const std::uint64_t most = bytes.remaining() / (h.format == Ply_format::ASCII ? 6 : 3);
  const std::size_t reserved = std::size_t(std::min(v.count, most));
  cloud.xyz.reserve(3 * reserved);
  if(h.role_property[3] >= 0)
  {
    cloud.normals.reserve(3 * reserved);
    cloud.normals_source = cat("the PLY properties ", v.properties[h.role_property[3]].name, " ",
                               v.properties[h.role_property[4]].name, " ", v.properties[h.role_property[5]].name);
  }
  if(h.format == Ply_format::ASCII)
    read_ply_ascii(lines, h, cloud, path);
  else
  {
    read_ply_binary(bytes, h, cloud, path);
    if(!bytes.at_end())
      throw Error(cat(in_quotes(path), ": more data than the ", v.count, " vertices",
                      h.elements.size() > 1 ? " and other elements" : "",
                      " declared in the header (wrong vertex count?)"));
  }
  return cloud;
}

} // namespace

const char* readable_formats() { return ".xyz, .pwn, .txt, .csv, .ply or .off"; }

std::vector<std::string> parse_columns(const std::string& text)
{
  std::vector<std::string> names;
  std::size_t b = 0;
  for(;;)
  {
    const std::size_t comma = text.find(',', b);
    names.push_back(std::string(trim(std::string_view(text).substr(b, comma == std::string::npos ? std::string::npos : comma - b))));
    if(comma == std::string::npos)
      break;
    b = comma + 1;
  }
  for(const std::string& n : names)
    if(n.empty())
      throw Error(cat("--columns: empty column name in ", in_quotes(text),
                      " (use _ for a column to skip, for example x,y,z,_,nx,ny,nz)"));
  const std::string problem = layout_problem(roles_of(names));
  if(!problem.empty())
    throw Error(cat("--columns ", in_quotes(text), " ", problem, " (for example x,y,z,nx,ny,nz or x,y,z,r,g,b)"));
  return names;
}

Point_cloud read_point_cloud(const std::string& path, const Read_options& options)
{
  struct stat st;
  if(::stat(path.c_str(), &st) != 0)
    throw Error(cat("cannot open input ", in_quotes(path), ": ", std::strerror(errno)));
  if(S_ISDIR(st.st_mode))
    throw Error(cat("cannot read input ", in_quotes(path), ": it is a directory"));
  if(!S_ISREG(st.st_mode))
    throw Error(cat("cannot read input ", in_quotes(path), ": not a regular file (a pipe or a device?)"));
  const std::string ext = lower_extension(path);
  const bool text = ext == ".xyz" || ext == ".pwn" || ext == ".txt" || ext == ".csv";
  if(!text && ext != ".ply" && ext != ".off")
    throw Error(cat("unsupported input format ", in_quotes(ext.empty() ? path : ext), " for ", in_quotes(path),
                    " (expected ", readable_formats(), ")"));
  if(!options.columns.empty() && !text)
    throw Error(cat("--columns applies to text point files (.xyz, .pwn, .txt, .csv), not to ", in_quotes(path)));
  Byte_source bytes(path, std::uint64_t(st.st_size), options.progress);
  Point_cloud cloud = text ? read_xyz(bytes, path, options) : ext == ".ply" ? read_ply(bytes, path) : read_off(bytes, path);
  if(cloud.size() == 0)
    throw Error(cat(in_quotes(path), " contains no points"));
  if(options.progress && !options.progress(1.0))
    throw Cancelled();
  return cloud;
}

} // namespace psc_tool
