// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the readers and writers (io/) and the point_set_curvatures tool share: the error a
// user can fix (exit status 2, one line on stderr), a run without any valid estimate (exit
// status 3), the cancellation of a long phase (exit status 130 for SIGINT, 143 for SIGTERM),
// string helpers and the progress callback type. (io/ keeps the tool's namespace psc_tool:
// its readers and writers were the tool's, and the tool names them unqualified.)

#ifndef PSC_IO_SUPPORT_H
#define PSC_IO_SUPPORT_H

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace psc_tool {

// Every failure the user can fix (arguments, files): one line on stderr, exit status 2.
struct Error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A phase stopped because its progress callback returned false (Ctrl-C or SIGTERM): exit
// status 130 or 143.
struct Cancelled : std::runtime_error
{
  Cancelled() : std::runtime_error("cancelled") {}
};

// A run that wrote its output but where no point got a valid estimate: exit status 3, the
// reason and what to try on stderr (a pipeline must not take it for a success).
struct No_valid_estimate : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Fraction done in [0, 1]; returning false cancels the phase.
typedef std::function<bool(double)> Progress;

template <class... T>
std::string cat(const T&... t)
{
  std::ostringstream s;
  (s << ... << t);
  return s.str();
}

// "1 point", "2 points": a count and its noun.
inline std::string plural(std::size_t n, const std::string& noun) { return cat(n, " ", noun, n == 1 ? "" : "s"); }

// part / all in percent to one decimal ("98.7"), never "100" unless part == all and never "0"
// unless part == 0; "0" when all is 0.
inline std::string percent_text(std::size_t part, std::size_t all)
{
  if(all == 0)
    return "0";
  const double p = std::round(1000.0 * double(part) / double(all)) / 10;
  return cat(part == all ? 100.0 : part == 0 ? 0.0 : std::max(0.1, std::min(p, 99.9)));
}

// The shortest decimal text that reads back as `v` exactly: "1000004.9995" where the stream's
// six digits print "1e+06" (for numbers compared in a message, which must differ in print
// when they differ).
inline std::string exact_number(double v)
{
  char text[40];
  for(int digits = 1; digits <= 17; ++digits)
  {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if(std::strtod(text, nullptr) == v)
      break;
  }
  return text;
}

// (not named quoted: std::quoted would win by ADL for non-const strings)
inline std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

inline std::string lower_case(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Seconds elapsed since `t`.
inline double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The hidden name of a temporary file beside `path`: "a/.b.ply" + suffix for "a/b.ply" (an
// empty file name gives an empty result).
inline std::string hidden_sibling(const std::string& path, const std::string& suffix)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.empty() ? std::string() : folder + "." + name + suffix;
}

// ".ply" for "a/b.PLY", "" without an extension.
inline std::string lower_extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  return lower_case(path.substr(dot));
}

}  // namespace psc_tool

#endif
