// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: results as numpy arrays (estimates, sphere features).

#ifndef PSC_PYTHON_OUTPUT_ARRAYS_H
#define PSC_PYTHON_OUTPUT_ARRAYS_H

#include "common.h"
#include "features.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

namespace psc_py {

namespace py = pybind11;

template <class T>
py::array_t<T> array_1(std::size_t n)
{
  return py::array_t<T>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)});
}

inline py::array_t<double> array_n3(std::size_t n)
{
  return py::array_t<double>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), 3});
}

template <class V>
void put3(double* out, std::size_t i, const V& v)
{
  out[3 * i] = CGAL::to_double(v.x());
  out[3 * i + 1] = CGAL::to_double(v.y());
  out[3 * i + 2] = CGAL::to_double(v.z());
}

inline py::dict estimates_to_dict(const std::vector<Estimate>& e, bool with_mean_error)
{
  const std::size_t n = e.size();
  auto normal = array_n3(n), dmin = array_n3(n), dmax = array_n3(n);
  auto kmin = array_1<double>(n), kmax = array_1<double>(n), mean = array_1<double>(n), gauss = array_1<double>(n);
  auto count = array_1<std::int64_t>(n);
  auto status = array_1<std::uint8_t>(n);
  double *pn = normal.mutable_data(), *pdmin = dmin.mutable_data(), *pdmax = dmax.mutable_data();
  auto coherence = array_1<double>(n);
  double *pkmin = kmin.mutable_data(), *pkmax = kmax.mutable_data(), *pmean = mean.mutable_data(),
         *pgauss = gauss.mutable_data(), *pcoherence = coherence.mutable_data();
  std::int64_t* pc = count.mutable_data();
  std::uint8_t* ps = status.mutable_data();
  {
    py::gil_scoped_release release;
    for(std::size_t i = 0; i < n; ++i)
    {
      put3(pn, i, e[i].normal);
      put3(pdmin, i, e[i].min_direction);
      put3(pdmax, i, e[i].max_direction);
      pkmin[i] = e[i].min_curvature;
      pkmax[i] = e[i].max_curvature;
      pmean[i] = e[i].mean_curvature;
      pgauss[i] = e[i].gaussian_curvature;
      pcoherence[i] = e[i].normal_coherence;
      pc[i] = static_cast<std::int64_t>(e[i].neighbor_count);
      ps[i] = static_cast<std::uint8_t>(e[i].status);
    }
  }
  py::dict d;
  d["normal"] = normal;
  d["k_min"] = kmin;
  d["k_max"] = kmax;
  d["mean"] = mean;
  d["gaussian"] = gauss;
  d["normal_coherence"] = coherence;
  d["min_direction"] = dmin;
  d["max_direction"] = dmax;
  d["neighbors"] = count;
  d["status"] = status;
  if(with_mean_error)
  {
    auto error = array_1<double>(n);
    double* pe = error.mutable_data();
    for(std::size_t i = 0; i < n; ++i)
      pe[i] = e[i].mean_curvature_error;
    d["mean_error"] = error;
  }
  return d;
}

// Features of `scales` x `n` points: arrays of shape (n, ...) if `flat`, else (scales, n, ...).
inline py::dict features_to_dict(const std::vector<const std::vector<Features>*>& scales, bool flat)
{
  const std::size_t s = scales.size(), n = scales.empty() ? 0 : scales[0]->size();
  auto shape = [&](bool vec) {
    std::vector<py::ssize_t> sh;
    if(!flat)
      sh.push_back(static_cast<py::ssize_t>(s));
    sh.push_back(static_cast<py::ssize_t>(n));
    if(vec)
      sh.push_back(3);
    return sh;
  };
  py::dict d;
  auto scalar = [&](const char* name, auto get) {
    py::array_t<double> a(shape(false));
    double* p = a.mutable_data();
    for(std::size_t k = 0; k < s; ++k)
      for(std::size_t i = 0; i < n; ++i)
        p[k * n + i] = CGAL::to_double(get((*scales[k])[i]));
    d[name] = a;
  };
  auto vector = [&](const char* name, auto get) {
    py::array_t<double> a(shape(true));
    double* p = a.mutable_data();
    for(std::size_t k = 0; k < s; ++k)
      for(std::size_t i = 0; i < n; ++i)
        put3(p + 3 * k * n, i, get((*scales[k])[i]));
    d[name] = a;
  };
  scalar("u_c", [](const Features& f) { return f.u_c; });
  vector("u_l", [](const Features& f) { return f.u_l; });
  scalar("u_q", [](const Features& f) { return f.u_q; });
  scalar("pratt_norm", [](const Features& f) { return f.pratt_norm; });
  scalar("anisotropy", [](const Features& f) { return f.anisotropy; });
  vector("normal", [](const Features& f) { return f.normal; });
  scalar("mean", [](const Features& f) { return f.mean_curvature; });
  scalar("geometric_variation", [](const Features& f) { return f.geometric_variation; });
  scalar("d_u_c_dr", [](const Features& f) { return f.d_u_c_dr; });
  vector("d_normal_dr", [](const Features& f) { return f.d_normal_dr; });
  scalar("d_mean_dr", [](const Features& f) { return f.d_mean_curvature_dr; });
  vector("center", [](const Features& f) { return f.center; });
  scalar("sphere_radius", [](const Features& f) { return f.sphere_radius; });
  vector("projection", [](const Features& f) { return f.projection; });
  scalar("kernel_radius", [](const Features& f) { return f.kernel_radius; });
  py::array_t<bool> plane(shape(false));
  py::array_t<std::int64_t> count(shape(false));
  py::array_t<std::uint8_t> status(shape(false));
  bool* pp = plane.mutable_data();
  std::int64_t* pc = count.mutable_data();
  std::uint8_t* ps = status.mutable_data();
  for(std::size_t k = 0; k < s; ++k)
    for(std::size_t i = 0; i < n; ++i)
    {
      const Features& f = (*scales[k])[i];
      pp[k * n + i] = f.is_plane;
      pc[k * n + i] = static_cast<std::int64_t>(f.neighbor_count);
      ps[k * n + i] = static_cast<std::uint8_t>(f.status);
    }
  d["is_plane"] = plane;
  d["neighbors"] = count;
  d["status"] = status;
  return d;
}

} // namespace psc_py

#endif
