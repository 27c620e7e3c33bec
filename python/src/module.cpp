// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: the compiled part `point_set_curvatures._core`: its functions and their
// declaration to Python. The public API, its argument checks and its docstrings are in
// point_set_curvatures/__init__.py. Arguments are read in input_arrays.h, the C++ functions
// run in a worker thread with the GIL released and the progress forwarded to Python
// (run.h), results converted to numpy arrays (output_arrays.h); the classes are in
// surface.h and tile_grid.h, the estimators' description in descriptions.h, the file readers
// in file_readers.h, the calls of the estimators in curvatures_*.cpp and features.cpp (one
// translation unit each).

#include "common.h"
#include "descriptions.h"
#include "features.h"
#include "file_readers.h"
#include "input_arrays.h"
#include "normal_records.h"
#include "output_arrays.h"
#include "run.h"
#include "surface.h"
#include "tile_grid.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <tbb/info.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;

namespace psc_py {

// ---- The functions of _core ----

// The per-point sample weights given as an array (None: none): N float values, in a copy.
// Their values (finite, non-negative) are checked by the C++ functions.
std::vector<double> read_weights(const py::object& weights, std::size_t n)
{
  std::vector<double> w;
  if(weights.is_none())
    return w;
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(weights);
  if(!a || a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
    throw py::value_error("sample_weights: expected one weight per point, an array of shape (" + std::to_string(n) +
                          ",), or one of 'uniform', 'tangent_voronoi_area'");
  w.assign(a.data(), a.data() + n);
  return w;
}

// `options` with the per-point weights of `weights` (None: `options` as they are), read into
// `storage`, which must outlive the copy returned.
Options options_with_weights(const Options& options, const py::object& weights, std::size_t n,
                             std::vector<double>& storage)
{
  Options o = options;
  storage = read_weights(weights, n);
  if(!weights.is_none())
    o.given_weights = &storage;
  return o;
}

py::dict estimate_curvatures(const std::string& method, const py::handle& points, const py::handle& normals,
                             const py::object& radius, const py::object& neighbors, long long threads,
                             const py::object& progress, const Options& options, const py::object& tile,
                             const py::object& weights)
{
  const CGAL::Point_set_curvatures::Estimator_description* described =
    CGAL::Point_set_curvatures::find_estimator(method);
  if(!described)
    throw py::value_error("unknown method '" + method + "'");
  const Scale scale = read_scale(radius, neighbors, described->supports_automatic_scale);
  const Tile_arg t = read_tile(tile);
  const Cloud cloud = read_cloud(points, normals);
  std::vector<double> given;
  const Options o = options_with_weights(options, weights, cloud.size(), given);
  // each described estimator's call (python/src/curvatures_*.cpp)
  std::function<std::vector<Estimate>(bool, const Callback&)> call;
  if(method == "aso")
    call = [&](bool parallel, const Callback& cb) { return estimate_aso(cloud, scale, o, t, parallel, cb); };
  else if(method == "apss")
    call = [&](bool parallel, const Callback& cb) { return estimate_apss(cloud, scale, o, t, parallel, cb); };
  else if(method == "barycenter" || method == "pca_plane")
    call = [&](bool parallel, const Callback& cb) { return estimate_simple(method, cloud, scale, o, t, parallel, cb); };
  else if(method == "pss" || method == "wavejet")
    call = [&](bool parallel, const Callback& cb) {
      return estimate_pss_wavejet(method, cloud, scale, o, t, parallel, cb);
    };
  else if(method == "jet")
    call = [&](bool parallel, const Callback& cb) { return estimate_jet(cloud, scale, o, t, parallel, cb); };
  else if(method == "vcm")
    call = [&](bool parallel, const Callback& cb) { return estimate_vcm(cloud, scale, o, t, parallel, cb); };
  else
    throw std::logic_error("method '" + method + "' is described (estimators.h) but has no binding");
  std::vector<Estimate> result;
  run([&](bool parallel, const Callback& cb) { result = call(parallel, cb); }, progress, threads);
  return estimates_to_dict(result, scale.automatic_largest > 0);
}

py::dict sphere_features_py(const py::handle& points, const py::handle& normals, const py::object& radius,
                            const py::object& neighbors, long long threads, const py::object& progress,
                            const Options& options, const py::object& tile, const py::object& weights)
{
  const Scale scale = read_scale(radius, neighbors);
  const Tile_arg t = read_tile(tile);
  const Cloud cloud = read_cloud(points, normals);
  std::vector<double> given;
  const Options o = options_with_weights(options, weights, cloud.size(), given);
  std::vector<Features> result;
  run([&](bool parallel, const Callback& cb) { result = sphere_features(cloud, scale, o, t, parallel, cb); }, progress,
      threads);
  return features_to_dict({&result}, true);
}

py::array_t<double> tangent_voronoi_areas_py(const py::handle& points, const py::handle& normals,
                                             const py::object& radius, const py::object& neighbors, long long threads,
                                             const py::object& progress, bool accept_unnormalized_normals)
{
  const Scale scale = read_scale(radius, neighbors);
  Cloud cloud = read_cloud(points, normals);
  std::vector<double> areas;
  run(
    [&](bool parallel, const Callback& cb) {
      if(!tangent_voronoi_areas(cloud, scale, accept_unnormalized_normals, parallel, cb, areas))
        throw Cancelled_error();
    },
    progress, threads);
  auto out = array_1<double>(areas.size());
  std::copy(areas.begin(), areas.end(), out.mutable_data());
  return out;
}

py::dict multiscale_features_py(const py::handle& points, const py::handle& normals, const std::vector<double>& radii,
                                long long threads, const py::object& progress, const Options& options)
{
  const Cloud cloud = read_cloud(points, normals);
  std::vector<std::vector<Features> > result;
  run([&](bool parallel,
          const Callback& cb) { result = multiscale_sphere_features(cloud, radii, options, parallel, cb); },
      progress, threads);
  std::vector<const std::vector<Features>*> scales;
  for(const auto& r : result)
    scales.push_back(&r);
  if(scales.empty())  // not reached: the C++ function refuses an empty list
    return py::dict();
  return features_to_dict(scales, false);
}

py::dict smooth_py(const py::handle& points, const py::handle& normals, double radius, long long iterations,
                   bool update_normals, long long threads, const py::object& progress, const Options& options)
{
  Cloud cloud = read_cloud(points, normals);
  std::vector<CGAL::Curvature_estimate_status> status;
  run(
    [&](bool parallel, const Callback& cb) {
      status = smooth_point_set(cloud, radius, iterations, update_normals, options, parallel, cb);
    },
    progress, threads);
  const std::size_t n = cloud.size();
  auto p = array_n3(n), v = array_n3(n);
  auto s = array_1<std::uint8_t>(n);
  double *pp = p.mutable_data(), *pv = v.mutable_data();
  std::uint8_t* ps = s.mutable_data();
  for(std::size_t i = 0; i < n; ++i)
  {
    put3(pp, i, cloud[i].first);
    put3(pv, i, cloud[i].second);
    ps[i] = static_cast<std::uint8_t>(status[i]);
  }
  py::dict d;
  d["points"] = p;
  d["normals"] = v;
  d["status"] = s;
  return d;
}

py::tuple normals_py(const py::handle& points, const py::object& radius, const py::object& neighbors, int orientation,
                     const std::vector<double>& target, int fit, long long threads, const py::object& progress)
{
  const Scale scale = read_scale(radius, neighbors, true);
  if(target.size() != 3)
    throw py::value_error("the orientation target must have 3 coordinates");
  Cloud cloud = read_cloud(points, py::none());
  std::size_t without = 0;
  run(
    [&](bool parallel, const Callback& cb) {
      without = oriented_normals(cloud, scale, orientation, target.data(), fit, parallel, cb);
    },
    progress, threads);
  auto v = array_n3(cloud.size());
  double* pv = v.mutable_data();
  for(std::size_t i = 0; i < cloud.size(); ++i)
    put3(pv, i, cloud[i].second);
  return py::make_tuple(v, without);
}

}  // namespace psc_py

PYBIND11_MODULE(_core, m)
{
  using namespace psc_py;
  m.doc() = "Compiled part of point_set_curvatures (use the functions of the package, not these).";
  // The CMake project's version (CMakeLists.txt), which setup.py gives the pip package too.
  m.attr("__version__") = PSC_PYTHON_VERSION;
  m.attr("MAX_THREADS") = std::max(1, tbb::info::default_concurrency());

  py::register_exception<Cancelled_error>(m, "Cancelled", PyExc_RuntimeError);
  // HaloTooSmall carries required_halo; the type lives as long as the interpreter.
  static PyObject* halo_type =
    PyErr_NewException("point_set_curvatures._core.HaloTooSmall", PyExc_RuntimeError, nullptr);
  m.attr("HaloTooSmall") = py::handle(halo_type);
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const CGAL::Point_set_curvatures::Halo_too_small& e)
    {
      py::object instance = py::handle(halo_type)(e.what());
      instance.attr("required_halo") = e.required_halo();
      PyErr_SetObject(halo_type, instance.ptr());
    }
  });

  py::class_<Options>(m, "_Options", "Every option of the C++ estimators as plain values (-1: default).")
    .def(py::init<>())
    .def_readwrite("min_neighbors", &Options::min_neighbors)
    .def_readwrite("accept_unnormalized_normals", &Options::accept_unnormalized_normals)
    .def_readwrite("aso_variant", &Options::aso_variant)
    .def_readwrite("weight_kernel", &Options::weight_kernel)
    .def_readwrite("sample_weights", &Options::sample_weights)
    .def_readwrite("robust_orientation", &Options::robust_orientation)
    .def_readwrite("normal_field_blend", &Options::normal_field_blend)
    .def_readwrite("normal_refinement", &Options::normal_refinement)
    .def_readwrite("position_fit_blend", &Options::position_fit_blend)
    .def_readwrite("aso_projection", &Options::aso_projection)
    .def_readwrite("degree_fitting", &Options::degree_fitting)
    .def_readwrite("degree_monge", &Options::degree_monge)
    .def_readwrite("vcm_offset_radius", &Options::vcm_offset_radius);

  // The library's description of its estimators (estimators.h): the package derives its
  // method and option lists and the names of the enumerations' values from it.
  py::list estimators;
  for(const CGAL::Point_set_curvatures::Estimator_description& e : CGAL::Point_set_curvatures::estimators)
    estimators.append(estimator_to_dict(e));
  m.attr("ESTIMATORS") = py::tuple(estimators);
  export_enums(m);
  m.attr("AUTOMATIC_NEIGHBORS") = py::make_tuple(CGAL::Point_set_curvatures::automatic_scale_ladder::smallest,
                                                 CGAL::Point_set_curvatures::automatic_scale_ladder::largest);
  // The front ends' defaults (estimators.h), which the tool uses too: the scale of a run given
  // none, the position blend of a run on estimated normals.
  namespace defaults = CGAL::Point_set_curvatures::front_end_defaults;
  m.attr("DEFAULT_NEIGHBORS") = defaults::neighbor_count;
  // estimate_normals' default counts (quadric, plane)
  m.attr("DEFAULT_NORMAL_NEIGHBORS") = py::make_tuple(default_normal_neighbors(1), default_normal_neighbors(0));
  m.def(
    "automatic_scale_by_default",
    [](const std::string& method, int variant) {
      const auto* e = CGAL::Point_set_curvatures::find_estimator(method);
      return e != nullptr && defaults::automatic_scale(*e, CGAL::Aso_variant(variant));
    },
    py::arg("method"), py::arg("aso_variant"));
  m.def(
    "default_position_fit_blend",
    [](int variant, bool normals_estimated) {
      return defaults::position_fit_blend(CGAL::Aso_variant(variant), normals_estimated);
    },
    py::arg("aso_variant"), py::arg("normals_estimated"));

  // The per-point fields of the results (field_descriptions.h), for the Dask layouts.
  m.def("fields", &fields_to_tuple);

  // Status names and values, checked against the Python enums at import.
  py::dict status;
  for(int s = 0; s <= int(CGAL::Curvature_estimate_status::TWO_SHEETS); ++s)
    status[py::str(CGAL::to_string(CGAL::Curvature_estimate_status(s)))] = s;
  m.attr("STATUS_VALUES") = status;
  py::dict projection_status;
  for(int s = 0; s <= int(CGAL::Apss_projection_status::NON_FINITE_POINT); ++s)
    projection_status[py::str(CGAL::to_string(CGAL::Apss_projection_status(s)))] = s;
  m.attr("PROJECTION_STATUS_VALUES") = projection_status;

  // The rules of tiles (Tile.h: the halo, the box, a tile's range and own points), for the Dask driver.
  m.def("halo_for_radius", &CGAL::Point_set_curvatures::halo_for_radius, py::arg("radius"));
  m.def(
    "halo_guess_for_count",
    [](const std::array<double, 3>& lo, const std::array<double, 3>& hi, std::size_t n, std::size_t k) {
      return CGAL::Point_set_curvatures::halo_guess_for_count(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), n,
                                                              k);
    },
    py::arg("box_min"), py::arg("box_max"), py::arg("points"), py::arg("neighbors"));
  m.def("next_halo", &CGAL::Point_set_curvatures::next_halo, py::arg("required"), py::arg("at_least"));
  m.def("halo_of_range", &CGAL::Point_set_curvatures::halo_of_range, py::arg("halo"), py::arg("finite_in_range"),
        py::arg("finite_in_cloud"));
  m.def("tile_grid_box", &tile_grid_box_py, py::arg("points"));
  m.attr("TILE_BOX_SAMPLE_POINTS") = CGAL::Point_set_curvatures::Tile_box_sample::default_max_points;
  m.def("tile_range", &tile_range_py, py::arg("core_min"), py::arg("core_max"), py::arg("halo"), py::arg("points"));
  m.def("tile_owns", &tile_owns_py, py::arg("core_min"), py::arg("core_max"), py::arg("points"));
  m.def("estimate_curvatures", &estimate_curvatures, py::arg("method"), py::arg("points"), py::arg("normals"),
        py::arg("radius"), py::arg("neighbors"), py::arg("threads"), py::arg("progress"), py::arg("options"),
        py::arg("tile"), py::arg("weights"));
  m.def("sphere_features", &sphere_features_py, py::arg("points"), py::arg("normals"), py::arg("radius"),
        py::arg("neighbors"), py::arg("threads"), py::arg("progress"), py::arg("options"), py::arg("tile"),
        py::arg("weights"));
  m.def("tangent_voronoi_areas", &tangent_voronoi_areas_py, py::arg("points"), py::arg("normals"), py::arg("radius"),
        py::arg("neighbors"), py::arg("threads"), py::arg("progress"), py::arg("accept_unnormalized_normals"));
  m.def("multiscale_sphere_features", &multiscale_features_py, py::arg("points"), py::arg("normals"), py::arg("radii"),
        py::arg("threads"), py::arg("progress"), py::arg("options"));
  m.def("smooth_point_set", &smooth_py, py::arg("points"), py::arg("normals"), py::arg("radius"), py::arg("iterations"),
        py::arg("update_normals"), py::arg("threads"), py::arg("progress"), py::arg("options"));
  m.def("estimate_normals", &normals_py, py::arg("points"), py::arg("radius"), py::arg("neighbors"),
        py::arg("orientation"), py::arg("target"), py::arg("fit"), py::arg("threads"), py::arg("progress"));
  m.attr("NORMAL_RECORD_DEGREE") = record_degree;
  m.def("normal_records", &normal_records_py, py::arg("points"), py::arg("radius"), py::arg("neighbors"),
        py::arg("fit"), py::arg("tile"), py::arg("threads"), py::arg("progress"));
  m.def("orient_normal_records", &orient_normal_records_py, py::arg("normal"), py::arg("neighbor"), py::arg("degree"),
        py::arg("status"), py::arg("xyz"), py::arg("orientation"), py::arg("target"), py::arg("threads"),
        py::arg("progress"));

  // The package's file readers (the tool's), for read_point_cloud() and the Dask driver.
  m.def("read_point_cloud", &read_point_cloud_py, py::arg("path"), py::arg("columns"), py::arg("attributes"),
        py::arg("allow_truncated"));
  m.def("ply_vertex_layout", &ply_vertex_layout_py, py::arg("path"));
  m.def("las_point_layout", &las_point_layout_py, py::arg("path"));

  py::class_<Surface>(m, "_Surface")
    .def(py::init<const py::handle&, const py::handle&, double, int>(), py::arg("points"), py::arg("normals"),
         py::arg("radius"), py::arg("weight_kernel"))
    .def_property_readonly("radius", &Surface::radius)
    .def_property_readonly("number_of_points", &Surface::number_of_points)
    .def_property("tolerance", &Surface::tolerance, &Surface::set_tolerance)
    .def_property("max_iterations", &Surface::max_iterations, &Surface::set_max_iterations)
    .def("project", &Surface::project, py::arg("queries"), py::arg("threads"))
    .def("features", &Surface::features, py::arg("queries"), py::arg("threads"));

  py::class_<Tile_grid_py>(m, "_TileGrid")
    .def(py::init<const std::vector<double>&, const std::vector<double>&, const py::object&, const py::object&>(),
         py::arg("box_min"), py::arg("box_max"), py::arg("tile_side"), py::arg("counts"))
    .def("__len__", &Tile_grid_py::size)
    .def_property_readonly("counts", &Tile_grid_py::counts)
    .def("core", &Tile_grid_py::core, py::arg("index"))
    .def("tile_of", &Tile_grid_py::tile_of, py::arg("points"))
    .def("tiles_near", &Tile_grid_py::tiles_near, py::arg("points"), py::arg("halo"));
}
