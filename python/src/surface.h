// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: point_set_curvatures.AlgebraicPointSetSurface, the APSS projection on an
// indexed cloud, queried from Python.

#ifndef PSC_PYTHON_SURFACE_H
#define PSC_PYTHON_SURFACE_H

#include "input_arrays.h"
#include "output_arrays.h"
#include "run.h"

#include <CGAL/Algebraic_point_set_surface.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace psc_py {

namespace py = pybind11;

// The projection: an indexed cloud, queried from Python.
class Surface
{
public:
  typedef CGAL::Algebraic_point_set_surface<K> APSS;

  Surface(const py::handle& points, const py::handle& normals, double radius, int weight_kernel)
  {
    const Cloud cloud = read_cloud(points, normals);
    const CGAL::Apss_weight_kernel kernel =
      weight_kernel >= 0 ? CGAL::Apss_weight_kernel(weight_kernel) : CGAL::Apss_weight_kernel::SMOOTH;
    py::gil_scoped_release release;
    m_surface =
      std::make_unique<APSS>(cloud, radius,
                             CGAL::Point_set_curvatures::parameters::weight_kernel(
                               kernel, CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Oriented>())
                                         .normal_map(CGAL::Second_of_pair_property_map<Oriented>())));
  }

  double radius() const { return m_surface->radius(); }
  std::size_t number_of_points() const { return m_surface->number_of_points(); }
  double tolerance() const { return m_surface->tolerance(); }
  void set_tolerance(double t) { m_surface->set_tolerance(t); }
  std::size_t max_iterations() const { return m_surface->maximum_number_of_iterations(); }
  void set_max_iterations(long long n)
  {
    if(n < 0)
      throw py::value_error("max_iterations must be at least 1, got " + std::to_string(n));
    m_surface->set_maximum_number_of_iterations(static_cast<std::size_t>(n));
  }

  py::dict project(const py::handle& queries, long long threads) const
  {
    const std::vector<K::Point_3> q = read_queries(queries);
    std::vector<APSS::Projection> r(q.size());
    for_all(q.size(), threads, [&](std::size_t i) { r[i] = m_surface->project(q[i]); });
    const std::size_t n = q.size();
    auto p = array_n3(n), v = array_n3(n);
    auto it = array_1<std::int64_t>(n), c = array_1<std::int64_t>(n);
    auto s = array_1<std::uint8_t>(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      put3(p.mutable_data(), i, r[i].point);
      put3(v.mutable_data(), i, r[i].normal);
      it.mutable_data()[i] = static_cast<std::int64_t>(r[i].iterations);
      c.mutable_data()[i] = static_cast<std::int64_t>(r[i].neighbor_count);
      s.mutable_data()[i] = static_cast<std::uint8_t>(r[i].status);
    }
    py::dict d;
    d["point"] = p;
    d["normal"] = v;
    d["iterations"] = it;
    d["neighbors"] = c;
    d["status"] = s;
    return d;
  }

  py::dict features(const py::handle& queries, long long threads) const
  {
    const std::vector<K::Point_3> q = read_queries(queries);
    std::vector<Features> r(q.size());
    for_all(q.size(), threads, [&](std::size_t i) { r[i] = m_surface->features(q[i]); });
    return features_to_dict({&r}, true);
  }

private:
  static std::vector<K::Point_3> read_queries(const py::handle& queries)
  {
    checked_rows(queries, "queries");
    const py::array a = py::reinterpret_borrow<py::array>(queries);
    std::vector<K::Point_3> q(static_cast<std::size_t>(a.shape(0)));
    for_each_row(a, [&q](py::ssize_t i, const double* x) { q[i] = K::Point_3(x[0], x[1], x[2]); });
    return q;
  }

  template <class F>
  static void for_all(std::size_t n, long long threads, const F& f)
  {
    threads = checked_threads(threads);
    py::gil_scoped_release release;
    auto parallel = [&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
        for(std::size_t i = r.begin(); i != r.end(); ++i)
          f(i);
      });
    };
    if(threads == 1)
      for(std::size_t i = 0; i < n; ++i)
        f(i);
    else if(threads > 1)
    {
      tbb::task_arena arena(static_cast<int>(threads));
      arena.execute(parallel);
    }
    else
      parallel();
  }

  std::unique_ptr<APSS> m_surface;
};

}  // namespace psc_py

#endif
