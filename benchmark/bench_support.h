// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the benchmark programs: the clouds and readers of the test suite
// (test/test_support.h), a timer, the area of an ellipsoid and the reading of options.

#ifndef PSC_BENCH_SUPPORT_H
#define PSC_BENCH_SUPPORT_H

#include "test_support.h"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

// The command line of a benchmark program, option by option:
//   Arguments args(argc, argv);
//   for(std::string a; args.next(a);)
//     if(a == "--out") out = args.value(); else if(a == "--only") only = args.list(); ...
// value() and list() throw std::invalid_argument when the option has no value.
class Arguments
{
public:
  Arguments(int argc, char** argv) : m_argc(argc), m_argv(argv) {}

  // The next option, false after the last.
  bool next(std::string& option)
  {
    if(m_i + 1 >= m_argc)
      return false;
    m_option = option = m_argv[++m_i];
    return true;
  }
  // The current option's value.
  std::string value()
  {
    if(m_i + 1 >= m_argc)
      throw std::invalid_argument(m_option + " needs a value");
    return m_argv[++m_i];
  }
  // The current option's value split at commas ("a,b,c").
  std::vector<std::string> list()
  {
    std::vector<std::string> parts;
    std::stringstream s(value());
    for(std::string part; std::getline(s, part, ',');)
      parts.push_back(part);
    return parts;
  }

private:
  int m_argc;
  char** m_argv;
  int m_i = 0;
  std::string m_option;
};

}  // namespace psc_bench

#endif
