// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_ALGEBRAIC_POINT_SET_SURFACE_H
#define CGAL_ALGEBRAIC_POINT_SET_SURFACE_H

#include <CGAL/estimate_algebraic_sphere_features.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere.h>
#include <CGAL/Point_set_curvatures/internal/algebraic_sphere_features.h>
#include <CGAL/Point_set_curvatures/internal/estimation_driver.h>
#include <CGAL/Point_set_curvatures/internal/position_index.h>
#include <CGAL/Point_set_curvatures/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace CGAL {

/// \ingroup PkgPointSetCurvaturesRef
/// Outcome of `CGAL::Algebraic_point_set_surface::project()`.
enum class Apss_projection_status : unsigned char {
  CONVERGED = 0,      ///< the last step moved the point by less than the tolerance
  NOT_CONVERGED,      ///< the iteration cap was reached first; the last iterate is returned
  TOO_FEW_NEIGHBORS,  ///< fewer than 3 points of the cloud at distance `< r` of an iterate
  DEGENERATE_FIT,     ///< the neighbours (nearly) coincide or their normals cancel out, or
                      ///< an iterate is the centre of its fitted sphere
  NON_FINITE_POINT    ///< the position to project has a NaN or infinite coordinate
};

/// \ingroup PkgPointSetCurvaturesRef
/// A short, stable name of a projection status (`"converged"`, `"not_converged"`, ...).
inline const char* to_string(Apss_projection_status s)
{
  switch(s)
  {
    case Apss_projection_status::CONVERGED: return "converged";
    case Apss_projection_status::NOT_CONVERGED: return "not_converged";
    case Apss_projection_status::TOO_FEW_NEIGHBORS: return "too_few_neighbors";
    case Apss_projection_status::DEGENERATE_FIT: return "degenerate_fit";
    case Apss_projection_status::NON_FINITE_POINT: return "non_finite_point";
  }
  return "unknown";
}

inline std::ostream& operator<<(std::ostream& os, Apss_projection_status s) { return os << to_string(s); }

/// \ingroup PkgPointSetCurvaturesRef
///
/// The APSS surface of an oriented point cloud (Guennebaud and Gross 2007; Lejemble et al.
/// 2021, Sections 3 and 4.5): the set of positions lying on the algebraic sphere fitted
/// around themselves. `project()` sends any 3-D position onto it by iterating the projection
/// onto the fitted sphere (Equation 20): fit at `x_k` (neighbours at distance `< radius`, the
/// kernel of `weight_kernel`), `x_{k+1}` = the closest point of that sphere (or plane, when
/// `u_q = 0`), until a step is shorter than the tolerance. `features()` evaluates the
/// algebraic sphere features at any position.
///
/// The cloud is copied (positions and unit normals, in double precision) into a spatial index
/// at construction; the input range may change afterwards. Unusable points (non-finite
/// coordinates, zero or non-finite normal) are left out. Queries are `const` and may run
/// concurrently.
///
/// \tparam GeomTraits a model of `Kernel` with a floating-point `FT`: the type of the query
/// and result points.
template <class GeomTraits>
class Algebraic_point_set_surface
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  /// The result of a projection.
  struct Projection
  {
    /// the projected position (last iterate); NaN unless `CONVERGED` or `NOT_CONVERGED`
    Point_3 point = Point_3(nan(), nan(), nan());
    /// unit normal of the last fitted sphere at `point`, oriented like the input normals
    Vector_3 normal = Vector_3(nan(), nan(), nan());
    /// number of fits (steps) performed
    std::size_t iterations = 0;
    /// number of cloud points at distance `< radius` from the last fitted position
    std::size_t neighbor_count = 0;
    /// outcome
    Apss_projection_status status = Apss_projection_status::NON_FINITE_POINT;

    /// `true` if and only if `status == Apss_projection_status::CONVERGED`
    bool is_valid() const { return status == Apss_projection_status::CONVERGED; }
  };

  /// Indexes `points` for projections with the kernel radius `radius` (in the unit of the
  /// coordinates).
  ///
  /// \param points oriented point cloud (a model of `ConstRange`)
  /// \param radius kernel radius `r`: positions farther than `r` from every point of the
  ///        cloud cannot be projected (`TOO_FEW_NEIGHBORS`)
  /// \param np named parameters: `point_map`, `normal_map` (required, except for
  ///        `CGAL::Point_set_3`), `Point_set_curvatures::parameters::weight_kernel`, as for
  ///        `CGAL::estimate_algebraic_sphere_features()`
  /// \throws std::invalid_argument if `radius` is not positive and finite.
  template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
  Algebraic_point_set_surface(const PointRange& points, double radius,
                              const NamedParameters& np = parameters::default_values())
  {
    typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
    static_assert(NP_helper::has_normal_map(),
                  "Error: no normal map. Pass CGAL::parameters::normal_map(...): the algebraic "
                  "sphere fit needs oriented normals.");
    Point_set_curvatures::internal::check_radius(radius, "Algebraic_point_set_surface");
    m_radius = radius;
    m_tolerance = 1e-10 * radius;
    m_kernel = Point_set_curvatures::internal::weight_kernel_parameter(np);
    const auto point_map = NP_helper::get_const_point_map(points, np);
    const auto normal_map = NP_helper::get_normal_map(points, np);
    std::vector<std::size_t> ids;
    std::size_t i = 0;
    for(auto it = points.begin(); it != points.end(); ++it, ++i)
    {
      const auto& p = get(point_map, *it);
      const auto& v = get(normal_map, *it);
      const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
      double n[3] = {CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())};
      const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
      if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]) || !(nn > 0) || !std::isfinite(nn))
        continue;
      const double inv = 1.0 / std::sqrt(nn);
      for(int a = 0; a < 3; ++a)
      {
        m_position.push_back(x[a]);
        m_normal.push_back(n[a] * inv);
      }
      ids.push_back(i);
    }
    m_index.build(m_position, m_normal, 3, ids, radius);
  }

  /// kernel radius `r`
  double radius() const { return m_radius; }
  /// number of usable points indexed
  std::size_t number_of_points() const { return m_position.size() / 3; }

  /// Sets the tolerance: the iteration stops when a step is shorter (in the unit of the
  /// coordinates; default `1e-10 * radius`). \throws std::invalid_argument unless
  /// non-negative and finite.
  void set_tolerance(double tolerance)
  {
    if(!(tolerance >= 0) || !std::isfinite(tolerance))
    {
      std::ostringstream msg;
      msg << "Algebraic_point_set_surface: parameter 'tolerance' must be non-negative and finite, got " << tolerance;
      throw std::invalid_argument(msg.str());
    }
    m_tolerance = tolerance;
  }
  double tolerance() const { return m_tolerance; }

  /// Sets the maximal number of steps of a projection (default 30).
  /// \throws std::invalid_argument if 0.
  void set_maximum_number_of_iterations(std::size_t n)
  {
    if(n == 0)
      throw std::invalid_argument(
        "Algebraic_point_set_surface: parameter 'maximum_number_of_iterations' must be at least 1");
    m_max_iterations = n;
  }
  std::size_t maximum_number_of_iterations() const { return m_max_iterations; }

  /// Projects `x` onto the APSS surface (iterated Equation 20, see the class description).
  /// On a cloud sampling a sphere exactly, one step lands on the sphere (the fit is exact).
  Projection project(const Point_3& x) const
  {
    Projection result;
    double y[3] = {CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
    if(!std::isfinite(y[0]) || !std::isfinite(y[1]) || !std::isfinite(y[2]))
      return result;
    const double r = m_radius;
    for(std::size_t it = 1; it <= m_max_iterations; ++it)
    {
      result.iterations = it;
      Point_set_curvatures::internal::Algebraic_sphere sphere;
      result.status = fit(y, sphere, result.neighbor_count);
      if(result.status != Apss_projection_status::CONVERGED)
        return invalid(result);
      const double origin[3] = {0, 0, 0};
      double step[3], n[3];
      if(!Point_set_curvatures::internal::project_on_sphere(sphere, origin, step, n))
      {
        result.status = Apss_projection_status::DEGENERATE_FIT;
        return invalid(result);
      }
      for(int a = 0; a < 3; ++a)
        y[a] += r * step[a];
      result.point = Point_3(FT(y[0]), FT(y[1]), FT(y[2]));
      result.normal = Vector_3(FT(n[0]), FT(n[1]), FT(n[2]));
      const double move = r * std::sqrt(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
      if(move <= m_tolerance)
        return result;  // CONVERGED
    }
    result.status = Apss_projection_status::NOT_CONVERGED;
    return result;
  }

  /// The algebraic sphere features of the fit at any position `x` (not necessarily a point of
  /// the cloud), with all cloud points at distance `< radius`: the same values as
  /// `CGAL::estimate_algebraic_sphere_features()` at a point of the cloud, up to the
  /// rounding of another summation order (bounded in test_sphere_features). Allocates a
  /// buffer for the neighbourhood at each call.
  Algebraic_sphere_features<GeomTraits> features(const Point_3& x) const
  {
    namespace PSCI = Point_set_curvatures::internal;
    const double y[3] = {CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
    if(!std::isfinite(y[0]) || !std::isfinite(y[1]) || !std::isfinite(y[2]))
    {
      Algebraic_sphere_features<GeomTraits> f;
      f.status = Curvature_estimate_status::NON_FINITE_POINT;
      return f;
    }
    // the neighbourhood in the scaled frame, for the shared feature code
    std::vector<double> buffer;
    m_index.for_each_neighbor(m_position.data(), y, [&](std::size_t k) {
      for(int a = 0; a < 3; ++a)
        buffer.push_back((m_position[3 * k + a] - y[a]) / m_radius);
      for(int a = 0; a < 3; ++a)
        buffer.push_back(m_normal[3 * k + a]);
    });
    const std::size_t n = buffer.size() / 6;
    std::vector<double> soa(6 * n);
    for(std::size_t i = 0; i < n; ++i)
      for(int a = 0; a < 6; ++a)
        soa[a * n + i] = buffer[6 * i + a];
    PSCI::Neighborhood nb;
    nb.size = n;
    nb.qx = soa.data();
    nb.qy = nb.qx + n;
    nb.qz = nb.qy + n;
    nb.nx = nb.qz + n;
    nb.ny = nb.nx + n;
    nb.nz = nb.ny + n;
    nb.radius = m_radius;
    for(int a = 0; a < 3; ++a)
      nb.center[a] = y[a];
    const PSCI::Local_sphere_features f =
      PSCI::with_weight_kernel(m_kernel, [&](auto k) { return PSCI::sphere_features<decltype(k)>(nb); });
    return PSCI::to_sphere_features<GeomTraits>(f, y);
  }

private:
  static FT nan() { return std::numeric_limits<FT>::quiet_NaN(); }

  static Projection invalid(Projection r)
  {
    r.point = Point_3(nan(), nan(), nan());
    r.normal = Vector_3(nan(), nan(), nan());
    return r;
  }

  // Sphere fitted at y (scaled frame of y); CONVERGED stands for "fitted".
  Apss_projection_status fit(const double y[3], Point_set_curvatures::internal::Algebraic_sphere& sphere,
                             std::size_t& count) const
  {
    return Point_set_curvatures::internal::with_weight_kernel(
      m_kernel, [&](auto k) { return fit<decltype(k)>(y, sphere, count); });
  }

  template <class WeightKernel>
  Apss_projection_status fit(const double y[3], Point_set_curvatures::internal::Algebraic_sphere& sphere,
                             std::size_t& count) const
  {
    namespace PSCI = Point_set_curvatures::internal;
    PSCI::Algebraic_sphere_sums<WeightKernel> sums;
    const double inv_r = 1.0 / m_radius;
    m_index.for_each_neighbor(m_position.data(), y, [&](std::size_t k) {
      const double* p = &m_position[3 * k];
      const double* n = &m_normal[3 * k];
      sums.add((p[0] - y[0]) * inv_r, (p[1] - y[1]) * inv_r, (p[2] - y[2]) * inv_r, n[0], n[1], n[2]);
    });
    count = sums.count;
    if(sums.count < PSCI::apss_min_neighbors)
      return Apss_projection_status::TOO_FEW_NEIGHBORS;
    sphere = PSCI::fit_algebraic_sphere(sums);
    return sphere.valid ? Apss_projection_status::CONVERGED : Apss_projection_status::DEGENERATE_FIT;
  }

  double m_radius = 1;
  double m_tolerance = 1e-10;
  std::size_t m_max_iterations = 30;
  Apss_weight_kernel m_kernel = Apss_weight_kernel::SMOOTH;
  std::vector<double> m_position, m_normal;  // usable points, in the index's order
  Point_set_curvatures::internal::Position_index m_index;
};

}  // namespace CGAL

#endif
