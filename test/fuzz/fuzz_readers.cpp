// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target of the tool's readers (tools/read_point_cloud.cpp, read_ply.cpp,
// read_las.cpp).
// The first byte of an input chooses the format (.las with bit 3, else .xyz, .ply, .off, .csv
// by its value mod 4) and, with bit 2, --columns x,y,z,_,nx,ny,nz; the rest is the file. A reader may refuse a
// file (psc_tool::Error) but must never crash, hang, allocate without bound, or return a
// cloud that breaks its invariants. Built and run by run_fuzzers.sh (clang, -fsanitize=
// fuzzer,address,undefined).

#include "../../tools/read_point_cloud.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  static const char* const extensions[4] = {".xyz", ".ply", ".off", ".csv"};
  const char* extension = data[0] & 8 ? ".las" : extensions[data[0] % 4];
  const std::string directory = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  const std::string path =
    directory + "/psc_fuzz_" + std::to_string(getpid()) + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if(!f)
    return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  psc_tool::Read_options options;
  if(data[0] & 4)
    options.columns = {"x", "y", "z", "_", "nx", "ny", "nz"};
  try
  {
    const psc_tool::Point_cloud cloud = psc_tool::read_point_cloud(path, options);
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
    // a refused file: fine
  }
  std::remove(path.c_str());
  return 0;
}
