// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Two doubles computed side by side: the sums of the fits over a neighbourhood accumulate its
// points of even rank in one lane and those of odd rank in the other, and add the two lanes at
// the end. With GCC and Clang the pair is a vector of two doubles (one SSE2 or NEON register,
// one instruction for both lanes); elsewhere a struct of two doubles. Both do the same IEEE
// operations in the same order, so they give the same bits where the compiler does not fuse a
// product and a sum into one multiply-add: on x86-64 without -march flags (SSE2 has none), or
// with -ffp-contract=off (GCC contracts by default where the target has FMA: aarch64, or x86-64
// with -march=haswell). Either way the order of the sums is fixed by the neighbourhood's, so
// sequential and parallel runs, tiles and whole runs agree.

#ifndef CGAL_POINT_SET_CURVATURES_INTERNAL_LANE_PAIR_H
#define CGAL_POINT_SET_CURVATURES_INTERNAL_LANE_PAIR_H

#include <cstddef>
#include <cstring>

namespace CGAL {
namespace Point_set_curvatures {
namespace internal {

#if defined(__GNUC__) || defined(__clang__)

typedef double Lane_pair __attribute__((vector_size(2 * sizeof(double))));

inline Lane_pair lanes(double a, double b) { return Lane_pair{a, b}; }
inline double lane(const Lane_pair& x, int i) { return x[i]; }
// x where `keep` > 0, else 0, lane by lane
inline Lane_pair where_positive(const Lane_pair& keep, const Lane_pair& x)
{
  return keep > Lane_pair{0, 0} ? x : Lane_pair{0, 0};
}

#else

struct Lane_pair
{
  double v[2];
};
inline Lane_pair lanes(double a, double b) { return Lane_pair{{a, b}}; }
inline double lane(const Lane_pair& x, int i) { return x.v[i]; }
inline Lane_pair operator+(const Lane_pair& x, const Lane_pair& y) { return lanes(x.v[0] + y.v[0], x.v[1] + y.v[1]); }
inline Lane_pair operator-(const Lane_pair& x, const Lane_pair& y) { return lanes(x.v[0] - y.v[0], x.v[1] - y.v[1]); }
inline Lane_pair operator*(const Lane_pair& x, const Lane_pair& y) { return lanes(x.v[0] * y.v[0], x.v[1] * y.v[1]); }
inline Lane_pair& operator+=(Lane_pair& x, const Lane_pair& y) { return x = x + y; }
inline Lane_pair where_positive(const Lane_pair& keep, const Lane_pair& x)
{
  return lanes(keep.v[0] > 0 ? x.v[0] : 0.0, keep.v[1] > 0 ? x.v[1] : 0.0);
}

#endif

inline Lane_pair broadcast(double a) { return lanes(a, a); }
// The sum of the two lanes.
inline double fold(const Lane_pair& x) { return lane(x, 0) + lane(x, 1); }
// Two consecutive doubles, read or written.
inline Lane_pair load_lanes(const double* p)
{
  Lane_pair x;
  std::memcpy(&x, p, sizeof x);
  return x;
}
inline void store_lanes(double* p, const Lane_pair& x) { std::memcpy(p, &x, sizeof x); }
// Elements i and i + 1 of `values`, or element i and `pad` where i + 1 == size.
inline Lane_pair load_pair(const double* values, std::size_t i, std::size_t size, double pad)
{
  return lanes(values[i], i + 1 < size ? values[i + 1] : pad);
}

}  // namespace internal
}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
