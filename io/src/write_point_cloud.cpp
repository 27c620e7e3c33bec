// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The writers (see write_point_cloud.h).

#include "psc_io/write_point_cloud.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>

namespace psc_tool {

namespace {

namespace PSC = CGAL::Point_set_curvatures;

}  // namespace

const char* selectable_fields()
{
  static const std::string text = [] {
    std::string t;
    for_each_tool_field([&t](const PSC::Field_description& d) {
      t += t.empty() ? "" : ", ";
      t += d.name;
      if(d.component == 2 && *d.group)
        t += cat(" (or ", d.group, ")");
      if(d.automatic_scale_only)
        t += " (with --neighbors auto)";
    });
    return t;
  }();
  return text.c_str();
}

std::vector<std::string> parse_fields(const std::string& text)
{
  std::vector<std::string> names;
  std::size_t b = 0;
  for(;;)
  {
    const std::size_t comma = text.find(',', b);
    std::string name = text.substr(b, comma == std::string::npos ? std::string::npos : comma - b);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    bool known = false;
    for_each_tool_field([&](const PSC::Field_description& d) {
      if(!name.empty() && (name == d.name || (*d.group && name == d.group)))
      {
        names.push_back(d.name);
        known = true;
      }
    });
    if(!known)
      throw Error(cat("--fields: unknown field ", in_quotes(name), " (x y z are always written; choose among ",
                      selectable_fields(), ")"));
    if(comma == std::string::npos)
      break;
    b = comma + 1;
  }
  return names;
}

std::vector<Output_field> output_fields(const std::vector<std::string>& selected, bool float32, bool color,
                                        const std::vector<Attribute>& attributes, bool automatic_scale)
{
  auto chosen = [&](const std::string& name) {
    return selected.empty() || std::find(selected.begin(), selected.end(), name) != selected.end();
  };
  std::vector<Output_field> fields;
  for(const char* xyz : {"x", "y", "z"})
    fields.push_back(Output_field{xyz, Scalar_type::FLOAT64, Output_field::VALUE + output_value_index(xyz)});
  // the tool's names, selected or not, are never an input's: no file where k_min could be
  // an older run's value
  std::set<std::string> taken = {"x", "y", "z"};
  for_each_tool_field([&](const PSC::Field_description& d) {
    taken.insert(d.name);
    if(!chosen(d.name) || (d.automatic_scale_only && !automatic_scale))
      return;
    const Scalar_type type = d.type == PSC::Field_type::COUNT  ? Scalar_type::INT32
                             : d.type == PSC::Field_type::FLAG ? Scalar_type::UINT8
                             : float32                         ? Scalar_type::FLOAT32
                                                               : Scalar_type::FLOAT64;
    fields.push_back(Output_field{d.name, type, Output_field::VALUE + output_value_index(d.name)});
  });
  if(color)
    for(int c = 0; c < 3; ++c)
      fields.push_back(Output_field{c == 0   ? "red"
                                    : c == 1 ? "green"
                                             : "blue",
                                    Scalar_type::UINT8, Output_field::COLOR + c});
  for(const Output_field& f : fields)
    taken.insert(f.name);
  for(std::size_t j = 0; j < attributes.size(); ++j)
  {
    std::string name = attributes[j].name;
    while(taken.count(name))
      name = "input_" + name;
    taken.insert(name);
    fields.push_back(Output_field{name, attributes[j].type, Output_field::ATTRIBUTE + int(j)});
  }
  return fields;
}

std::vector<std::string> ply_property_names(const Output_layout& layout)
{
  // A PLY header splits its lines on white space: a name that holds some (a text column
  // "Scalar field") gets '_' for it, and '_' appended while it equals another name.
  const auto unfit = [](char c) { return static_cast<unsigned char>(c) <= ' ' || c == 127; };
  std::vector<std::string> names;
  std::set<std::string> used;
  for(const Output_field& f : layout.fields)
    if(!f.name.empty() && std::none_of(f.name.begin(), f.name.end(), unfit))
      used.insert(f.name);
  for(const Output_field& f : layout.fields)
  {
    std::string name = f.name;
    if(name.empty() || std::any_of(name.begin(), name.end(), unfit))
    {
      std::replace_if(name.begin(), name.end(), unfit, '_');
      while(name.empty() || used.count(name))
        name += '_';
      used.insert(name);
    }
    names.push_back(name);
  }
  if(!layout.scalar_prefix)
    return names;
  // CloudCompare 2.11 loads x y z, nx ny nz and red green blue as what they are, and a
  // property scalar_NAME as the scalar field NAME; other properties (mean, k_min, ...) it
  // leaves out without a word.
  static const std::set<std::string> kept = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};
  const std::string prefix = "scalar_";
  std::set<std::string> taken;
  for(std::string& name : names)
  {
    if(!kept.count(name))
    {
      if(name.compare(0, prefix.size(), prefix) != 0 || taken.count(name))
        name = prefix + name;
      while(taken.count(name))
        name = prefix + name;
    }
    taken.insert(name);
  }
  return names;
}

namespace {

bool little_endian_host()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <class T>
void put_binary(std::vector<char>& out, T v, bool swap)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  if(swap)
    std::reverse(bytes, bytes + sizeof(T));
  out.insert(out.end(), bytes, bytes + sizeof(T));
}

void put_binary_value(std::vector<char>& out, Scalar_type t, double v, bool swap)
{
  switch(t)
  {
    case Scalar_type::INT8: put_binary(out, to_integer<std::int8_t>(v), swap); break;
    case Scalar_type::UINT8: put_binary(out, to_integer<std::uint8_t>(v), swap); break;
    case Scalar_type::INT16: put_binary(out, to_integer<std::int16_t>(v), swap); break;
    case Scalar_type::UINT16: put_binary(out, to_integer<std::uint16_t>(v), swap); break;
    case Scalar_type::INT32: put_binary(out, to_integer<std::int32_t>(v), swap); break;
    case Scalar_type::UINT32: put_binary(out, to_integer<std::uint32_t>(v), swap); break;
    case Scalar_type::FLOAT32: put_binary(out, static_cast<float>(v), swap); break;
    default: put_binary(out, v, swap); break;
  }
}

void put_text_value(std::FILE* f, Scalar_type t, double v)
{
  switch(t)
  {
    case Scalar_type::INT8: std::fprintf(f, "%d", int(to_integer<std::int8_t>(v))); break;
    case Scalar_type::UINT8: std::fprintf(f, "%u", unsigned(to_integer<std::uint8_t>(v))); break;
    case Scalar_type::INT16: std::fprintf(f, "%d", int(to_integer<std::int16_t>(v))); break;
    case Scalar_type::UINT16: std::fprintf(f, "%u", unsigned(to_integer<std::uint16_t>(v))); break;
    case Scalar_type::INT32: std::fprintf(f, "%ld", long(to_integer<std::int32_t>(v))); break;
    case Scalar_type::UINT32: std::fprintf(f, "%lu", (unsigned long)(to_integer<std::uint32_t>(v))); break;
    default:
      if(std::isnan(v))
        std::fputs("nan", f);
      else if(t == Scalar_type::FLOAT32)
        std::fprintf(f, "%.9g", double(static_cast<float>(v)));
      else
        std::fprintf(f, "%.17g", v);
  }
}

void write_header(std::FILE* f, const Output_layout& layout, std::size_t n)
{
  if(layout.format == Output_layout::CSV)
  {
    for(std::size_t i = 0; i < layout.fields.size(); ++i)
      std::fprintf(f, "%s%c", layout.fields[i].name.c_str(), i + 1 == layout.fields.size() ? '\n' : ',');
    return;
  }
  std::fprintf(f, "ply\nformat %s 1.0\n", layout.format == Output_layout::ASCII_PLY ? "ascii" : "binary_little_endian");
  for(const std::string& c : layout.comments)
    std::fprintf(f, "comment %s\n", c.c_str());
  std::fprintf(f, "element vertex %zu\n", n);
  const std::vector<std::string> names = ply_property_names(layout);
  for(std::size_t i = 0; i < layout.fields.size(); ++i)
    std::fprintf(f, "property %s %s\n", ply_type_name(layout.fields[i].type), names[i].c_str());
  std::fputs("end_header\n", f);
}

// The bytes of a value in binary PLY, and the most characters it takes as text.
std::size_t binary_size(Scalar_type t)
{
  switch(t)
  {
    case Scalar_type::INT8:
    case Scalar_type::UINT8: return 1;
    case Scalar_type::INT16:
    case Scalar_type::UINT16: return 2;
    case Scalar_type::INT32:
    case Scalar_type::UINT32:
    case Scalar_type::FLOAT32: return 4;
    default: return 8;
  }
}

std::size_t text_width(Scalar_type t)
{
  switch(t)
  {
    case Scalar_type::INT8: return 4;      // -128
    case Scalar_type::UINT8: return 3;     // 255
    case Scalar_type::INT16: return 6;     // -32768
    case Scalar_type::UINT16: return 5;    // 65535
    case Scalar_type::INT32: return 11;    // -2147483648
    case Scalar_type::UINT32: return 10;   // 4294967295
    case Scalar_type::FLOAT32: return 15;  // -1.17549435e-38 (%.9g)
    default: return 24;                    // -2.2250738585072014e-308 (%.17g)
  }
}

}  // namespace

std::uint64_t output_size_bound(const Output_layout& layout, std::size_t n)
{
  // the header, written to memory
  char* text = nullptr;
  std::size_t header = 0;
  if(std::FILE* m = ::open_memstream(&text, &header))
  {
    write_header(m, layout, n);
    std::fclose(m);
  }
  std::free(text);
  std::uint64_t row = 0;
  for(const Output_field& field : layout.fields)
    row += layout.format == Output_layout::BINARY_PLY ? binary_size(field.type) : text_width(field.type) + 1;
  return std::uint64_t(header) + row * std::uint64_t(n);
}

void write_point_cloud(std::FILE* f, const Output_layout& layout, std::size_t n,
                       const std::function<void(std::size_t, Output_row&)>& row, const Progress& progress)
{
  write_header(f, layout, n);
  const bool swap = !little_endian_host();
  const std::size_t step = std::max<std::size_t>(1, n / 100);
  const char separator = layout.format == Output_layout::CSV ? ',' : ' ';
  std::vector<char> chunk;
  Output_row r;
  for(std::size_t i = 0; i < n; ++i)
  {
    row(i, r);
    for(std::size_t c = 0; c < layout.fields.size(); ++c)
    {
      const Output_field& field = layout.fields[c];
      const int s = field.source;
      double v = s < output_value_count        ? r.value[s]
                 : s < Output_field::ATTRIBUTE ? double(r.color[s - Output_field::COLOR])
                 : r.attributes                ? r.attributes[s - Output_field::ATTRIBUTE]
                                               : (*layout.attributes)[s - Output_field::ATTRIBUTE].values[i];
      if(field.shift)
        v = std::floor(v / double(1 << field.shift));
      if(layout.format == Output_layout::BINARY_PLY)
        put_binary_value(chunk, field.type, v, swap);
      else
      {
        if(c > 0)
          std::fputc(separator, f);
        put_text_value(f, field.type, v);
      }
    }
    if(layout.format == Output_layout::BINARY_PLY)
    {
      if(chunk.size() > (1u << 20))
      {
        std::fwrite(chunk.data(), 1, chunk.size(), f);
        chunk.clear();
      }
    }
    else
      std::fputc('\n', f);
    if(progress && (i + 1) % step == 0 && !progress(double(i + 1) / double(n)))
      throw Cancelled();
  }
  if(!chunk.empty())
    std::fwrite(chunk.data(), 1, chunk.size(), f);
}

}  // namespace psc_tool
