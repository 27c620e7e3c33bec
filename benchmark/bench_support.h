// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the benchmark programs: the clouds and readers of the test suite
// (test/test_support.h), a timer and the area of an ellipsoid.

#ifndef PSC_BENCH_SUPPORT_H
#define PSC_BENCH_SUPPORT_H

#include "../test/test_support.h"

#include <chrono>
#include <cmath>

namespace psc_bench {

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Surface area of the ellipsoid with semi-axes a, b, c (Knud Thomsen's formula, 1% accurate).
inline double ellipsoid_area(double a, double b, double c)
{
  const double p = 1.6075;
  return 4 * M_PI * std::pow((std::pow(a * b, p) + std::pow(a * c, p) + std::pow(b * c, p)) / 3, 1 / p);
}

} // namespace psc_bench

#endif
