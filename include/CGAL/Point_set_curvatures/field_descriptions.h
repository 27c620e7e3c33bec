// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The per-point fields that the front ends write (the tool's columns in PLY, CSV and LAS, the
// Python module's arrays, the Dask layouts), one row each: a field is added here and every
// writer, the summary, --color and Python find it by name.

#ifndef CGAL_POINT_SET_CURVATURES_FIELD_DESCRIPTIONS_H
#define CGAL_POINT_SET_CURVATURES_FIELD_DESCRIPTIONS_H

#include <CGAL/Curvature_estimate.h>
#include <CGAL/Point_set_curvatures/estimators.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <iterator>
#include <limits>
#include <string_view>

namespace CGAL {
namespace Point_set_curvatures {

/// \ingroup PkgPointSetCurvaturesRef
/// Where a field's value comes from in a `CGAL::Curvature_estimate` (`field_value()`).
enum class Field_source {
  NORMAL,                ///< `normal` (a component)
  MIN_CURVATURE,         ///< `min_curvature`
  MAX_CURVATURE,         ///< `max_curvature`
  MEAN_CURVATURE,        ///< `mean_curvature`
  GAUSSIAN_CURVATURE,    ///< `gaussian_curvature`
  MIN_DIRECTION,         ///< `min_direction` (a component)
  MAX_DIRECTION,         ///< `max_direction` (a component)
  NORMAL_COHERENCE,      ///< `normal_coherence`
  MEAN_CURVATURE_ERROR,  ///< `mean_curvature_error`
  NEIGHBOR_COUNT,        ///< `neighbor_count`
  VALID,                 ///< 1 for a valid estimate, 0 otherwise
  STATUS                 ///< `status`, as its integer value
};

/// \ingroup PkgPointSetCurvaturesRef
/// How a field is stored.
enum class Field_type {
  REAL,   ///< a double (a float with the tool's `--float`)
  COUNT,  ///< a count: a 32-bit integer in files, 64-bit in Python
  FLAG    ///< a small unsigned integer (8 bits)
};

/// \ingroup PkgPointSetCurvaturesRef
/// One per-point field of the front ends (`field_descriptions`).
struct Field_description
{
  /// The tool's name: `--fields`, the PLY property (with `--ply-names scalar`, `scalar_` prepended
  /// but to `nx ny nz`), the CSV column, the LAS extra bytes; null where the tool does not write it.
  const char* name;
  /// The `--fields` group of a vector's component (`normal`, `dmin`, `dmax`), or "".
  const char* group;
  /// The key of the Python module's result dictionary; null where Python does not return it.
  const char* python_key;
  /// The component of a vector (0 to 2: column of the (N, 3) array `python_key`), or -1.
  int component;
  /// What it is, in at most 31 characters (the LAS extra bytes' description).
  const char* description;
  /// Where its value comes from.
  Field_source source;
  /// How it is stored.
  Field_type type;
  /// The bit of `estimate_fields` of the estimators that fill it (0: every estimate has it).
  unsigned filled_by;
  /// Written only with the automatic scale (`parameters::automatic_scale`).
  bool automatic_scale_only;
  /// A curvature that the tool's summary reports and `--color` shows.
  bool summarised;
};

/// \ingroup PkgPointSetCurvaturesRef
/// The per-point fields, in the order the front ends write them (the tool after `x y z`).
inline constexpr Field_description field_descriptions[] = {
  {"nx", "normal", "normal", 0, "unit normal, x", Field_source::NORMAL, Field_type::REAL, estimate_fields::normal,
   false, false},
  {"ny", "normal", "normal", 1, "unit normal, y", Field_source::NORMAL, Field_type::REAL, estimate_fields::normal,
   false, false},
  {"nz", "normal", "normal", 2, "unit normal, z", Field_source::NORMAL, Field_type::REAL, estimate_fields::normal,
   false, false},
  {"k_min", "", "k_min", -1, "minimum principal curvature", Field_source::MIN_CURVATURE, Field_type::REAL,
   estimate_fields::principal_curvatures, false, true},
  {"k_max", "", "k_max", -1, "maximum principal curvature", Field_source::MAX_CURVATURE, Field_type::REAL,
   estimate_fields::principal_curvatures, false, true},
  {"mean", "", "mean", -1, "mean curvature (k_min+k_max)/2", Field_source::MEAN_CURVATURE, Field_type::REAL,
   estimate_fields::mean_curvature, false, true},
  {"gaussian", "", "gaussian", -1, "Gaussian curvature k_min*k_max", Field_source::GAUSSIAN_CURVATURE, Field_type::REAL,
   estimate_fields::gaussian_curvature, false, true},
  {"dmin_x", "dmin", "min_direction", 0, "direction of k_min, x", Field_source::MIN_DIRECTION, Field_type::REAL,
   estimate_fields::principal_directions, false, false},
  {"dmin_y", "dmin", "min_direction", 1, "direction of k_min, y", Field_source::MIN_DIRECTION, Field_type::REAL,
   estimate_fields::principal_directions, false, false},
  {"dmin_z", "dmin", "min_direction", 2, "direction of k_min, z", Field_source::MIN_DIRECTION, Field_type::REAL,
   estimate_fields::principal_directions, false, false},
  {"dmax_x", "dmax", "max_direction", 0, "direction of k_max, x", Field_source::MAX_DIRECTION, Field_type::REAL,
   estimate_fields::principal_directions, false, false},
  {"dmax_y", "dmax", "max_direction", 1, "direction of k_max, y", Field_source::MAX_DIRECTION, Field_type::REAL,
   estimate_fields::principal_directions, false, false},
  {"dmax_z", "dmax", "max_direction", 2, "direction of k_max, z", Field_source::MAX_DIRECTION, Field_type::REAL,
   estimate_fields::principal_directions, false, false},
  {"normal_coherence", "", "normal_coherence", -1, "agreement of the normals, 0-1", Field_source::NORMAL_COHERENCE,
   Field_type::REAL, estimate_fields::normal_coherence, false, false},
  {"mean_error", "", "mean_error", -1, "standard error of mean", Field_source::MEAN_CURVATURE_ERROR, Field_type::REAL,
   0, true, false},
  {"neighbors", "", "neighbors", -1, "neighbours of the estimate", Field_source::NEIGHBOR_COUNT, Field_type::COUNT, 0,
   false, false},
  {"valid", "", nullptr, -1, "1 valid estimate, 0 invalid", Field_source::VALID, Field_type::FLAG, 0, false, false},
  {nullptr, "", "status", -1, "the estimate's status", Field_source::STATUS, Field_type::FLAG, 0, false, false}};

/// \ingroup PkgPointSetCurvaturesRef
/// The number of rows of `field_descriptions`.
inline constexpr std::size_t field_count = std::size(field_descriptions);

/// \ingroup PkgPointSetCurvaturesRef
/// The row of `field_descriptions` whose tool name is `name`, or `field_count`.
inline constexpr std::size_t field_index(std::string_view name)
{
  for(std::size_t i = 0; i < field_count; ++i)
    if(field_descriptions[i].name && name == field_descriptions[i].name)
      return i;
  return field_count;
}

/// \cond SKIP_IN_MANUAL
namespace internal {
// The table's rules, checked at compile time: descriptions fit a LAS extra bytes' 32 characters
// (with the terminating zero), names a LAS extra bytes' 32 and are unique and not x y z, a
// vector's components follow one another, numbered 0 1 2, with one key and one source.
constexpr bool field_descriptions_hold()
{
  for(std::size_t i = 0; i < field_count; ++i)
  {
    const Field_description& f = field_descriptions[i];
    if(std::string_view(f.description).size() > 31)
      return false;
    if(f.name)
    {
      const std::string_view name(f.name);
      if(name.empty() || name.size() > 32 || name == "x" || name == "y" || name == "z" || field_index(name) != i)
        return false;
    }
    if(f.component > 0)
    {
      const Field_description& p = field_descriptions[i - 1];
      if(p.component != f.component - 1 ||
         std::string_view(p.python_key ? p.python_key : "") != std::string_view(f.python_key ? f.python_key : "") ||
         p.source != f.source)
        return false;
    }
    if(f.component == 0 && (i + 2 >= field_count || field_descriptions[i + 2].component != 2))
      return false;
  }
  return true;
}
static_assert(field_descriptions_hold(), "field_descriptions: a description longer than 31 characters, a name "
                                         "repeated, empty, longer than 32 or x y z, or a vector's components apart");
}  // namespace internal
/// \endcond

/// \ingroup PkgPointSetCurvaturesRef
/// The value of field `f` of the estimate `e`, as a double.
/// \tparam Kernel the kernel of the estimate
template <class Kernel>
double field_value(const Curvature_estimate<Kernel>& e, const Field_description& f)
{
  CGAL_precondition((f.source != Field_source::NORMAL && f.source != Field_source::MIN_DIRECTION &&
                     f.source != Field_source::MAX_DIRECTION) ||
                    (f.component >= 0 && f.component < 3));
  const auto component = [&f](const typename Kernel::Vector_3& v) { return CGAL::to_double(v[f.component]); };
  switch(f.source)
  {
    case Field_source::NORMAL: return component(e.normal);
    case Field_source::MIN_CURVATURE: return CGAL::to_double(e.min_curvature);
    case Field_source::MAX_CURVATURE: return CGAL::to_double(e.max_curvature);
    case Field_source::MEAN_CURVATURE: return CGAL::to_double(e.mean_curvature);
    case Field_source::GAUSSIAN_CURVATURE: return CGAL::to_double(e.gaussian_curvature);
    case Field_source::MIN_DIRECTION: return component(e.min_direction);
    case Field_source::MAX_DIRECTION: return component(e.max_direction);
    case Field_source::NORMAL_COHERENCE: return CGAL::to_double(e.normal_coherence);
    case Field_source::MEAN_CURVATURE_ERROR: return CGAL::to_double(e.mean_curvature_error);
    case Field_source::NEIGHBOR_COUNT: return double(e.neighbor_count);
    case Field_source::VALID: return e.is_valid() ? 1.0 : 0.0;
    case Field_source::STATUS: return double(static_cast<int>(e.status));
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace Point_set_curvatures
}  // namespace CGAL

#endif
