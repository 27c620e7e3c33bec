// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the tool's report and its --color need from the output rows, gathered row by row in
// any order (the tiles of a tiled run come in no particular order): exact counts and
// extrema, and the values of a fixed sample of the points (every step-th input index, at
// most 2^20 points) for the medians and the colour range. The sample depends only on the
// point count, so a tiled run and an in-memory run report and colour alike; clouds of at
// most 2^20 points are sampled completely.

#ifndef POINT_SET_CURVATURES_TOOL_RUN_SUMMARY_H
#define POINT_SET_CURVATURES_TOOL_RUN_SUMMARY_H

#include "psc_io/write_point_cloud.h"

#include <CGAL/Point_set_curvatures/vertical_normals.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace psc_tool {

// Value at fraction q of the values (nearest rank); values must not be empty.
inline double percentile(std::vector<double> values, double q)
{
  const std::size_t i = std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + i, values.end());
  return values[i];
}

// The quantities summarised, those of the table marked `summarised` (k_min, k_max, mean,
// gaussian), numbered q in the table's order: their number, their names (name[q]; also what
// --color shows), the q of the field named `name` (-1 if it is not summarised), and quantity
// q's index in Output_row::value (value_index[q]).
namespace summary_quantities {
constexpr int count()
{
  int n = 0;
  for(const CGAL::Point_set_curvatures::Field_description& f : CGAL::Point_set_curvatures::field_descriptions)
    n += f.name && f.summarised ? 1 : 0;
  return n;
}
constexpr std::array<std::string_view, count()> names()
{
  std::array<std::string_view, count()> at{};
  int q = 0;
  for(const CGAL::Point_set_curvatures::Field_description& f : CGAL::Point_set_curvatures::field_descriptions)
    if(f.name && f.summarised)
      at[q++] = f.name;
  return at;
}
inline constexpr std::array<std::string_view, count()> name = names();
constexpr int of(std::string_view field)
{
  for(int q = 0; q < count(); ++q)
    if(name[q] == field)
      return q;
  return -1;
}
constexpr std::array<int, count()> value_indices()
{
  std::array<int, count()> at{};
  for(int q = 0; q < count(); ++q)
    at[q] = output_value_index(name[q]);
  return at;
}
inline constexpr std::array<int, count()> value_index = value_indices();
}  // namespace summary_quantities

class Row_summary
{
public:
  // The estimated quantities summarised (summary_quantities).
  static constexpr int quantities = summary_quantities::count();

  // `points`: the rows to come; `too_few_status`: the status whose rows still count in the
  // neighbour counts (too few neighbours).
  Row_summary(std::size_t points, int too_few_status)
      : m_step(std::max<std::size_t>(1, (points + (std::size_t(1) << 20) - 1) >> 20)), m_too_few_status(too_few_status)
  {
    for(int q = 0; q < quantities; ++q)
    {
      m_min[q] = HUGE_VAL;
      m_max[q] = -HUGE_VAL;
      m_count[q] = 0;
    }
  }

  void add(std::size_t index, const Output_row& r)
  {
    const bool sampled = index % m_step == 0;
    if(r.valid())
    {
      ++m_valid;
      static constexpr int x = output_value_index("nx"), y = output_value_index("ny"), z = output_value_index("nz");
      const double nx = r.value[x], ny = r.value[y], nz = r.value[z];
      if(CGAL::Point_set_curvatures::is_near_vertical(nx, ny, nz))
      {
        ++m_near_vertical;
        m_near_vertical_up += nz > 0 ? 1 : 0;
      }
      m_neighbors += std::uint64_t(std::max(0, r.neighbors()));
      for(int q = 0; q < quantities; ++q)
      {
        const double v = r.value[summary_quantities::value_index[q]];
        if(!std::isfinite(v))
          continue;
        ++m_count[q];
        m_min[q] = std::min(m_min[q], v);
        m_max[q] = std::max(m_max[q], v);
        if(sampled)
          m_sample[q].push_back(v);
      }
    }
    else
      ++m_invalid[r.status];
    if(r.valid() || r.status == m_too_few_status)
    {
      m_too_few += !r.valid();
      if(sampled)
        m_neighbor_sample.push_back(double(r.neighbors()));
    }
  }

  std::size_t valid() const { return m_valid; }
  // valid rows whose output normal lies within 60 degrees of the vertical, and those of them
  // that point up (what the output holds, which the report states)
  std::size_t near_vertical() const { return m_near_vertical; }
  std::size_t near_vertical_up() const { return m_near_vertical_up; }
  std::uint64_t neighbors() const { return m_neighbors; }
  // invalid rows per status
  const std::map<int, std::size_t>& invalid() const { return m_invalid; }
  // rows with too few neighbours
  std::size_t too_few() const { return m_too_few; }
  // neighbour counts of the sampled valid or too-few rows
  const std::vector<double>& neighbor_sample() const { return m_neighbor_sample; }

  // number of finite values of quantity q, their extrema, and the sample
  std::size_t count(int q) const { return m_count[q]; }
  double min(int q) const { return m_min[q]; }
  double max(int q) const { return m_max[q]; }
  const std::vector<double>& sample(int q) const { return m_sample[q]; }

  // The symmetric colour range of quantity q: the larger magnitude of the 2nd and 98th
  // percentiles of the sample; 0 without values.
  double color_range(int q) const
  {
    if(m_sample[q].empty())
      return 0;
    return std::max(std::abs(percentile(m_sample[q], 0.02)), std::abs(percentile(m_sample[q], 0.98)));
  }

private:
  std::size_t m_step;
  int m_too_few_status;
  std::size_t m_valid = 0, m_too_few = 0, m_near_vertical = 0, m_near_vertical_up = 0;
  std::uint64_t m_neighbors = 0;
  std::map<int, std::size_t> m_invalid;
  std::size_t m_count[quantities];
  double m_min[quantities], m_max[quantities];
  std::vector<double> m_sample[quantities], m_neighbor_sample;
};

}  // namespace psc_tool

#endif
