// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target of the readers (io/src/read_point_cloud.cpp, read_ply.cpp,
// read_las.cpp).
// The first byte of an input chooses the format (.las with bit 3, else .xyz, .ply, .off, .csv
// by its value mod 4) and, with bit 2, --columns x,y,z,_,nx,ny,nz; the rest is the file. A reader may refuse a
// file (psc_tool::Error) but must never crash, hang, allocate without bound, or return a
// cloud that breaks its invariants; read again in chunks of 3 points (Read_options::chunk, the
// tool's tiled runs), it must give the same points, normals and attributes, or the same
// refusal. Built and run by run_fuzzers.sh (clang, -fsanitize=fuzzer,address,undefined).

#include "psc_io/read_point_cloud.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  static const char* const extensions[4] = {".xyz", ".ply", ".off", ".csv"};
  const char* extension = data[0] & 8 ? ".las" : extensions[data[0] % 4];
  const std::string directory = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  const std::string path = directory + "/psc_fuzz_" + std::to_string(getpid()) + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if(!f)
    return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  psc_tool::Read_options options;
  if(data[0] & 4)
    options.columns = {"x", "y", "z", "_", "nx", "ny", "nz"};
  psc_tool::Point_cloud cloud;
  bool refused = false;
  try
  {
    cloud = psc_tool::read_point_cloud(path, options);
    // what every reader promises
    if(cloud.xyz.size() % 3 != 0 || cloud.size() == 0 ||
       (cloud.has_normals() && cloud.normals.size() != cloud.xyz.size()))
      std::abort();
    for(const psc_tool::Attribute& a : cloud.attributes)
      if(a.values.size() != cloud.size())
        std::abort();
  }
  catch(const psc_tool::Error&)
  {
    refused = true;  // a refused file: fine
  }
  // in chunks: the same points in the same order (bitwise), or a refusal
  psc_tool::Point_cloud joined;
  bool refused_in_chunks = false;
  options.chunk_points = 3;
  options.chunk = [&joined](const psc_tool::Point_cloud& c) {
    if(c.first != joined.size() || c.size() == 0 || (!c.normals.empty() && c.normals.size() != c.xyz.size()))
      std::abort();
    joined.xyz.insert(joined.xyz.end(), c.xyz.begin(), c.xyz.end());
    joined.normals.insert(joined.normals.end(), c.normals.begin(), c.normals.end());
    joined.attributes.resize(c.attributes.size());
    for(std::size_t a = 0; a < c.attributes.size(); ++a)
    {
      if(c.attributes[a].values.size() != c.size())
        std::abort();
      joined.attributes[a].values.insert(joined.attributes[a].values.end(), c.attributes[a].values.begin(),
                                         c.attributes[a].values.end());
    }
  };
  try
  {
    const psc_tool::Point_cloud rest = psc_tool::read_point_cloud(path, options);
    if(rest.size() != 0 || rest.total() != joined.size() || rest.has_normals() != cloud.has_normals())
      std::abort();
  }
  catch(const psc_tool::Error&)
  {
    refused_in_chunks = true;
  }
  if(refused != refused_in_chunks)
    std::abort();
  if(!refused)
  {
    auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
      return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
    };
    if(!same(cloud.xyz, joined.xyz) || !same(cloud.normals, joined.normals) ||
       cloud.attributes.size() != joined.attributes.size())
      std::abort();
    for(std::size_t a = 0; a < cloud.attributes.size(); ++a)
      if(!same(cloud.attributes[a].values, joined.attributes[a].values))
        std::abort();
  }
  std::remove(path.c_str());
  return 0;
}
