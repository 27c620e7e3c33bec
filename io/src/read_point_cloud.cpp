// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The readers (see read_point_cloud.h): the text formats (.xyz family, .off) and the
// dispatch by extension. Bytes, lines and number parsing: input_bytes.h; PLY: read_ply.cpp.

#include "psc_io/read_point_cloud.h"
#include "input_bytes.h"

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

using namespace input;

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

// Normals read from unnamed values: refused when they are not unit vectors (median length
// outside [0.5, 2]: colours, intensities), never silently used as normals. Streaming: the
// decision comes from counts (the median is below 0.5 when more than half the lengths are,
// above 2 when at least the other half are), the same whether the points come in one piece
// or in chunks; the message quotes the median of the first 65536 lengths.
class Unit_normal_check
{
public:
  void add(const Point_cloud& cloud)
  {
    for(std::size_t i = 0; i < cloud.size(); ++i)
    {
      const double* n = &cloud.normals[3 * i];
      const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if(!std::isfinite(l))
        continue;
      ++m_count;
      m_below += l < 0.5;
      m_above += l > 2;
      if(m_sample.size() < 65536)
        m_sample.push_back(l);
    }
  }
  void check(const std::string& path, const char* what) const
  {
    if(m_count > 0 && m_below <= m_count / 2 && m_above < m_count - m_count / 2)
      return;
    throw Error(cat(in_quotes(path), ": ", what, " are not unit normals (median length ", median(m_sample),
                    "): if they are colours or other values, give --columns to name the columns, for "
                    "example --columns x,y,z,r,g,b (normals are then estimated), or --columns "
                    "x,y,z,nx,ny,nz to use them as normals"));
  }

private:
  std::uint64_t m_count = 0, m_below = 0, m_above = 0;
  std::vector<double> m_sample;
};

void check_unit_normals(const Point_cloud& cloud, const std::string& path, const char* what)
{
  Unit_normal_check check;
  check.add(cloud);
  check.check(path, what);
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
  bool has_count = false, first_content = true, header_allowed = true;
  std::string_view line;
  // per column, its attribute in cloud.attributes or -1: the named columns that are neither
  // coordinates nor normals, except "_"
  std::vector<int> attribute_of;
  auto name_attributes = [&](const std::vector<std::string>& names) {
    attribute_of.assign(names.size(), -1);
    if(!options.keep_attributes)
      return;
    for(std::size_t c = 0; c < names.size(); ++c)
      if(roles[c] < 0 && names[c] != "_")
      {
        attribute_of[c] = int(cloud.attributes.size());
        cloud.attributes.push_back(Attribute(names[c], Scalar_type::FLOAT64));
      }
  };
  if(explicit_columns)
  {
    roles = roles_of(options.columns);
    layout_origin = "--columns";
    name_attributes(options.columns);
  }
  auto fail = [&](const std::string& what) {
    throw Error(cat(in_quotes(path), " line ", lines.line_number(), ": ", what));
  };
  // Names the normals' source and counts the lengths of unnamed normals before the points are
  // handed over; they are checked at the end (an Error after chunks were handed over is
  // allowed).
  Unit_normal_check unit_normals;
  auto hand_over_checked = [&](bool at_end) {
    if(std::count(roles.begin(), roles.end(), 3) == 1)
      cloud.normals_source = automatic_six ? "columns 4-6" : cat("the columns named by ", layout_origin);
    if(automatic_six)
      unit_normals.add(cloud);
    if(at_end && automatic_six && cloud.total() > 0)
      unit_normals.check(path, "its columns 4-6");
    hand_over(cloud, options, at_end);
  };
  while(lines.next(line))
  {
    if(lines.line_number() == 1 && line.size() >= 3 && line.substr(0, 3) == "\xEF\xBB\xBF")
      line.remove_prefix(3);                      // UTF-8 byte order mark
    line = trim(line.substr(0, line.find('#')));  // '#' starts a comment, anywhere
    if(line.empty())
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
        continue;  // a header line may follow
      }
    }
    if(header_allowed)
    {
      header_allowed = false;
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
            fail(cat("the header line ", problem,
                     ": give --columns to name the columns (for example --columns x,y,z,nx,ny,nz)"));
          layout_origin = "the header line";
          name_attributes(header);
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
      attribute_of.assign(roles.size(), -1);
      automatic_six = values.size() == 6;
      layout_origin = "the previous lines";
    }
    if(values.size() != roles.size())
      fail(cat(values.size(), " values where ", layout_origin,
               layout_origin == "the previous lines" ? " have " : " names ", roles.size()));
    double p[6] = {0, 0, 0, 0, 0, 0};
    for(std::size_t c = 0; c < values.size(); ++c)
    {
      double v = 0;
      if(roles[c] < 0 && attribute_of[c] < 0)
        continue;
      if(!parse_number(values[c], v))
        fail(values[c].empty() ? cat("empty value in column ", c + 1) : cat(quoted(values[c]), " is not a number"));
      if(roles[c] >= 0)
        p[roles[c]] = v;
      else
        cloud.attributes[attribute_of[c]].values.push_back(v);
    }
    cloud.xyz.insert(cloud.xyz.end(), p, p + 3);
    if(roles.size() >= 6 && std::count(roles.begin(), roles.end(), 3) == 1)
      cloud.normals.insert(cloud.normals.end(), p + 3, p + 6);
    if(options.chunk && cloud.size() >= options.chunk_points)
      hand_over_checked(false);
  }
  if(has_count && declared != cloud.total())
    throw Error(cat(in_quotes(path), ": its first line declares ", declared, " points but it has ", cloud.total()));
  hand_over_checked(true);
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
      if(w.empty() || (w[0] != "OFF" && w[0] != "NOFF"))
        fail("expected the header OFF or NOFF (binary and coloured OFF are not supported)");
      signature = std::string(w[0]);
      stage = 1;
      if(w.size() == 1)
        continue;
      w.erase(w.begin());  // the counts on the same line: "OFF 8 6 12"
    }
    if(stage == 1)
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
    throw Error(
      cat(in_quotes(path), ": the header declares ", declared_vertices, " vertices but the file has ", cloud.size()));
  if(faces != declared_faces)
    throw Error(cat(in_quotes(path), ": the header declares ", declared_faces, " faces but the file has ", faces));
  if(!cloud.normals.empty())
  {
    cloud.normals_source = "the vertex lines (x y z nx ny nz)";
    check_unit_normals(cloud, path, "the 4th to 6th values of its vertex lines");
  }
  return cloud;
}

}  // namespace

const char* readable_formats() { return ".xyz, .pwn, .txt, .csv, .asc, .ply, .off or .las"; }

const char* ply_type_name(Scalar_type t)
{
  static const char* const names[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  return names[int(t)];
}

std::vector<std::string> parse_columns(const std::string& text)
{
  std::vector<std::string> names;
  std::size_t b = 0;
  for(;;)
  {
    const std::size_t comma = text.find(',', b);
    names.push_back(
      std::string(trim(std::string_view(text).substr(b, comma == std::string::npos ? std::string::npos : comma - b))));
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

namespace input {

std::uint64_t regular_file_size(const std::string& path)
{
  struct stat st;
  if(::stat(path.c_str(), &st) != 0)
    throw Error(cat("cannot open input ", in_quotes(path), ": ", std::strerror(errno)));
  if(S_ISDIR(st.st_mode))
    throw Error(cat("cannot read input ", in_quotes(path), ": it is a directory"));
  if(!S_ISREG(st.st_mode))
    throw Error(cat("cannot read input ", in_quotes(path), ": not a regular file (a pipe or a device?)"));
  return std::uint64_t(st.st_size);
}

}  // namespace input

Point_cloud read_point_cloud(const std::string& path, const Read_options& options)
{
  const std::uint64_t size = regular_file_size(path);
  const std::string ext = lower_extension(path);
  // .asc: CloudCompare's ASCII export (values separated by spaces or commas, an optional
  // header line such as //X Y Z Nx Ny Nz), read like .txt
  const bool text = ext == ".xyz" || ext == ".pwn" || ext == ".txt" || ext == ".csv" || ext == ".asc";
  if(ext == ".laz")
    throw Error(cat(in_quotes(path), ": compressed LAS (.laz) is not read; decompress it first, for example "
                                     "with 'laszip -i FILE.laz -o FILE.las' or 'pdal translate FILE.laz FILE.las'"));
  if(!text && ext != ".ply" && ext != ".off" && ext != ".las")
    throw Error(cat("unsupported input format ", in_quotes(ext.empty() ? path : ext), " for ", in_quotes(path),
                    " (expected ", readable_formats(), ")"));
  if(!options.columns.empty() && !text)
    throw Error(cat("--columns applies to text point files (.xyz, .pwn, .txt, .csv, .asc), not to ", in_quotes(path)));
  Byte_source bytes(path, size, options.progress);
  Point_cloud cloud = text            ? read_xyz(bytes, path, options)
                      : ext == ".ply" ? read_ply(bytes, path, options)
                      : ext == ".las" ? read_las(bytes, path, options)
                                      : read_off(bytes, path);
  if(ext == ".off")
    hand_over(cloud, options, true);
  if(cloud.total() == 0)
    throw Error(cat(in_quotes(path), " contains no points"));
  if(options.progress && !options.progress(1.0))
    throw Cancelled();
  return cloud;
}

}  // namespace psc_tool
