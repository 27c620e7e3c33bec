// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Facts of the LAS point data record formats 0-10 (ASPRS LAS 1.4 R15) that the LAS
// reader (read_las.cpp) and writer (write_las.cpp) share.

#ifndef PSC_IO_LAS_FORMAT_H
#define PSC_IO_LAS_FORMAT_H

#include <cstddef>

namespace psc_tool {
namespace las {

// Size in bytes of the fields of each point data record format.
inline constexpr std::size_t format_size[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
// Size in bytes of an extra-bytes field of each data type 1-10 (0: undocumented).
inline constexpr std::size_t extra_type_size[11] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};

inline bool has_gps_time(int f) { return f != 0 && f != 2; }
inline bool has_rgb(int f) { return f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10; }
inline bool has_nir(int f) { return f == 8 || f == 10; }
// offset of red (formats 2, 3, 5: after the legacy fields or the GPS time; 7, 8, 10: after
// the 30 bytes of format 6)
inline std::size_t rgb_offset(int f) { return f == 2 ? 20 : f < 6 ? 28 : 30; }
inline bool has_wave_packet(int f) { return f == 4 || f == 5 || f == 9 || f == 10; }
// where the wave packet fields start: descriptor index (uchar), byte offset to the waveform
// (uint64), packet size (uint32), return point location (float, picoseconds), then the
// parametric line of the pulse x(t) y(t) z(t) (floats, coordinate units per picosecond)
inline std::size_t wave_offset(int f) { return f == 4 ? 28 : f == 5 ? 34 : f == 9 ? 30 : 38; }

}  // namespace las
}  // namespace psc_tool

#endif
