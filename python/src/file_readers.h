// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the package's file readers (io/: psc_io/read_point_cloud.h, the tool's), for
// point_set_curvatures.read_point_cloud() and the Dask driver's blocks of binary PLY and LAS files.
// Their errors (a malformed or unreadable file) are ValueErrors with the readers' message.

#ifndef POINT_SET_CURVATURES_PYTHON_FILE_READERS_H
#define POINT_SET_CURVATURES_PYTHON_FILE_READERS_H

#include "output_arrays.h"
#include "psc_io/read_point_cloud.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace psc_py {

namespace py = pybind11;

// The numpy type code of a reader's scalar type ("f8", "u1", ...).
inline const char* numpy_type_code(psc_tool::Scalar_type t)
{
  static const char* const codes[] = {"i1", "u1", "i2", "u2", "i4", "u4", "f4", "f8"};
  return codes[int(t)];
}

// Runs a reader, its Error a ValueError.
template <class F>
auto reading(const F& f) -> decltype(f())
{
  try
  {
    return f();
  }
  catch(const psc_tool::Error& e)
  {
    throw py::value_error(e.what());
  }
}

// The (n, 3) float64 array of the values `v` (3 per point).
inline py::array_t<double> n3_array(const std::vector<double>& v)
{
  py::array_t<double> a = array_n3(v.size() / 3);
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// The whole file: {"points", "normals" (None without), "normals_source", "attributes" (name
// -> array of the file's type), "warnings"}. The GIL is released while reading.
// `columns`: as the tool's --columns ("x,y,z,_,nx,ny,nz"; empty: automatic).
inline py::dict read_point_cloud_py(const std::string& path, const std::string& columns, bool keep_attributes,
                                    bool allow_truncated)
{
  psc_tool::Read_options options;
  if(!columns.empty())
    options.columns = reading([&] { return psc_tool::parse_columns(columns); });
  options.keep_attributes = keep_attributes;
  options.allow_truncated = allow_truncated;
  psc_tool::Point_cloud cloud;
  {
    py::gil_scoped_release release;
    cloud = reading([&] { return psc_tool::read_point_cloud(path, options); });
  }
  py::dict d;
  d["points"] = n3_array(cloud.xyz);
  d["normals"] = cloud.has_normals() ? py::object(n3_array(cloud.normals)) : py::object(py::none());
  d["normals_source"] = cloud.normals_source;
  py::dict attributes;
  for(const psc_tool::Attribute& a : cloud.attributes)
  {
    py::array values = py::array_t<double>(py::ssize_t(a.values.size()), a.values.data());
    attributes[py::str(a.name)] = values.attr("astype")(numpy_type_code(a.type));
  }
  d["attributes"] = attributes;
  d["warnings"] = py::cast(cloud.warnings);
  return d;
}

// Where the vertices of a binary PLY file lie: {"big_endian", "offset", "count",
// "record_size", "properties" [(name, numpy type code, offset)], "xyz" (the three properties
// of the coordinates), "normals" (those of the normals, or None)}.
inline py::dict ply_vertex_layout_py(const std::string& path)
{
  const psc_tool::Ply_vertex_layout layout = reading([&] { return psc_tool::ply_vertex_layout(path); });
  py::dict d;
  d["big_endian"] = layout.big_endian;
  d["offset"] = layout.offset;
  d["count"] = layout.count;
  d["record_size"] = layout.record_size;
  py::list properties;
  for(const auto& p : layout.properties)
    properties.append(py::make_tuple(p.name, numpy_type_code(p.type), p.offset));
  d["properties"] = properties;
  auto roles = [&properties](const int* role) -> py::object {
    if(role[0] < 0)
      return py::none();
    return py::make_tuple(properties[role[0]], properties[role[1]], properties[role[2]]);
  };
  d["xyz"] = roles(layout.xyz);
  d["normals"] = roles(layout.normal);
  return d;
}

// Where the point records of an uncompressed LAS file lie: {"offset", "count", "record_size",
// "scale" (3), "shift" (3)}; x = X * scale[0] + shift[0] for the int32 X at the record's start.
inline py::dict las_point_layout_py(const std::string& path)
{
  const psc_tool::Las_point_layout layout = reading([&] { return psc_tool::las_point_layout(path); });
  py::dict d;
  d["offset"] = layout.offset;
  d["count"] = layout.count;
  d["record_size"] = layout.record_size;
  d["scale"] = py::make_tuple(layout.scale[0], layout.scale[1], layout.scale[2]);
  d["shift"] = py::make_tuple(layout.shift[0], layout.shift[1], layout.shift[2]);
  return d;
}

}  // namespace psc_py

#endif
