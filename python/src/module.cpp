// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings (issue 13): the compiled part `point_set_curvatures._core`. The public
// API, its argument checks and its docstrings are in point_set_curvatures/__init__.py; this
// module converts arrays, runs the C++ functions in a worker thread with the GIL released,
// forwards the progress reports to a Python callable on the calling thread, and converts
// the results to numpy arrays.

#include "common.h"
#include "features.h"

#include <CGAL/Algebraic_point_set_surface.h>
#include <CGAL/Point_set_curvatures/estimators.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

namespace py = pybind11;

namespace psc_py {

// ---- Exceptions ----

// Raised (as point_set_curvatures.Cancelled) when the progress callable returned False.
struct Cancelled_error : std::runtime_error
{
  Cancelled_error() : std::runtime_error("cancelled by the progress callback") {}
};

// ---- Input arrays ----

// The number of rows of an (N, 3) float32 or float64 array; throws a ValueError / TypeError
// naming `what` otherwise.
py::ssize_t checked_rows(const py::handle& h, const char* what)
{
  if(!py::isinstance<py::array>(h))
    throw py::type_error(std::string(what) + ": expected a numpy array of shape (N, 3)");
  const py::array a = py::reinterpret_borrow<py::array>(h);
  if(!py::isinstance<py::array_t<double> >(a) && !py::isinstance<py::array_t<float> >(a))
    throw py::type_error(std::string(what) + ": expected dtype float64 or float32 (native byte order), got " +
                         std::string(py::str(a.dtype())));
  if(a.ndim() != 2 || a.shape(1) != 3)
  {
    std::string shape = "(";
    for(py::ssize_t d = 0; d < a.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(what) + ": expected shape (N, 3), got " + shape);
  }
  return a.shape(0);
}

// Reads row i of an (N, 3) array of T with any strides (C, Fortran, non-contiguous views).
template <class T>
struct Row_reader
{
  const char* data;
  py::ssize_t s0, s1;
  explicit Row_reader(const py::array& a)
    : data(static_cast<const char*>(a.data())), s0(a.strides(0)), s1(a.strides(1))
  {}
  void operator()(py::ssize_t i, double out[3]) const
  {
    for(int c = 0; c < 3; ++c)
    {
      T v;
      std::memcpy(&v, data + i * s0 + c * s1, sizeof(T));
      out[c] = static_cast<double>(v);
    }
  }
};

template <class F>
void for_each_row(const py::array& a, const F& f)
{
  const py::ssize_t n = a.shape(0);
  if(py::isinstance<py::array_t<double> >(a))
  {
    const Row_reader<double> r(a);
    double x[3];
    for(py::ssize_t i = 0; i < n; ++i) { r(i, x); f(i, x); }
  }
  else
  {
    const Row_reader<float> r(a);
    double x[3];
    for(py::ssize_t i = 0; i < n; ++i) { r(i, x); f(i, x); }
  }
}

// The one copy of the input: positions and normals (zero normals if `normals` is None).
Cloud read_cloud(const py::handle& points, const py::handle& normals)
{
  const py::ssize_t n = checked_rows(points, "points");
  Cloud cloud(static_cast<std::size_t>(n), Oriented(K::Point_3(0, 0, 0), K::Vector_3(0, 0, 0)));
  for_each_row(py::reinterpret_borrow<py::array>(points),
               [&cloud](py::ssize_t i, const double* x) { cloud[i].first = K::Point_3(x[0], x[1], x[2]); });
  if(!normals.is_none())
  {
    const py::ssize_t m = checked_rows(normals, "normals");
    if(m != n)
      throw py::value_error("points and normals must have the same number of rows, got " + std::to_string(n) +
                            " and " + std::to_string(m));
    for_each_row(py::reinterpret_borrow<py::array>(normals),
                 [&cloud](py::ssize_t i, const double* x) { cloud[i].second = K::Vector_3(x[0], x[1], x[2]); });
  }
  return cloud;
}

Scale read_scale(const py::object& radius, const py::object& neighbors, bool automatic = false)
{
  Scale s;
  if(!radius.is_none() && !neighbors.is_none())
    throw py::value_error("give either radius or neighbors, not both");
  if(radius.is_none() && neighbors.is_none())
    throw py::value_error("give radius or neighbors");
  if(!radius.is_none())
    s.radius = radius.cast<double>();  // checked by the C++ function (positive and finite)
  else if(py::isinstance<py::str>(neighbors))
  {
    // "auto" (where `automatic`): the library's ladder, that of the tool's --neighbors auto
    if(!automatic || neighbors.cast<std::string>() != "auto")
      throw py::value_error("neighbors: expected a count" + std::string(automatic ? " or 'auto'" : ""));
    s.by_count = true;
    s.k = CGAL::Point_set_curvatures::automatic_scale_ladder::smallest;
    s.automatic_largest = CGAL::Point_set_curvatures::automatic_scale_ladder::largest;
  }
  else
  {
    const long long k = neighbors.cast<long long>();
    if(k < 1)
      throw py::value_error("neighbors must be at least 1, got " + std::to_string(k));
    s.by_count = true;
    s.k = static_cast<std::size_t>(k);
  }
  return s;
}

Tile_arg read_tile(const py::object& tile)
{
  Tile_arg t;
  if(tile.is_none())
    return t;
  const py::tuple tu = tile.cast<py::tuple>();
  if(tu.size() != 3)
    throw py::value_error("tile: expected (core_min, core_max, halo)");
  const auto lo = tu[0].cast<std::vector<double> >(), hi = tu[1].cast<std::vector<double> >();
  if(lo.size() != 3 || hi.size() != 3)
    throw py::value_error("tile: core_min and core_max must have 3 coordinates");
  t.has = true;
  t.tile = CGAL::Point_set_curvatures::Tile(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]),
                                            tu[2].cast<double>());
  return t;
}

// ---- Running: worker thread, progress on the calling thread, threads ----

// The thread count of a run: 0 (all cores) as it is, more than the cores TBB may use capped
// to them (the results do not depend on it; an arena larger than that would only make TBB
// print a warning on stderr). Negative values are refused.
long long checked_threads(long long threads)
{
  if(threads < 0)
    throw py::value_error("threads must be None or at least 1, got " + std::to_string(threads));
  const long long cores = std::max(1, tbb::info::default_concurrency());
  return std::min(threads, cores);
}

// Runs f(parallel, callback) in a worker thread while the calling thread, with the GIL
// released, waits for progress reports and calls `progress(fraction)` with the GIL: the
// worker waits for its answer, so that False stops the run at that report exactly as the
// C++ callback would. Ctrl-C (a pending signal) cancels too. threads: 0 = all cores
// (Parallel_tag), 1 = Sequential_tag, n = Parallel_tag in a TBB arena of n threads.
template <class F>
void run(const F& f, const py::object& progress, long long threads)
{
  threads = checked_threads(threads);
  struct State
  {
    std::mutex m;
    std::condition_variable cv;
    bool request = false, answered = false, answer = true, done = false;
    double fraction = 0;
    std::atomic<bool> cancel{false};
    bool has_progress = false;
  } st;
  st.has_progress = !progress.is_none();
  const Callback callback = [&st](double fraction) -> bool {
    if(st.cancel.load())
      return false;
    if(!st.has_progress)
      return true;
    std::unique_lock<std::mutex> lock(st.m);
    st.fraction = fraction;
    st.request = true;
    st.answered = false;
    st.cv.notify_all();
    st.cv.wait(lock, [&st] { return st.answered; });
    return st.answer;
  };

  std::exception_ptr error;
  std::optional<py::error_already_set> python_error;  // destroyed with the GIL held
  bool cancelled = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try
      {
        if(threads == 1)
          f(false, callback);
        else if(threads > 1)
        {
          tbb::task_arena arena(static_cast<int>(threads));
          arena.execute([&] { f(true, callback); });
        }
        else
          f(true, callback);
      }
      catch(...)
      {
        error = std::current_exception();
      }
      {
        std::lock_guard<std::mutex> lock(st.m);
        st.done = true;
      }
      st.cv.notify_all();
    });
    std::unique_lock<std::mutex> lock(st.m);
    for(;;)
    {
      st.cv.wait_for(lock, std::chrono::milliseconds(50), [&st] { return st.request || st.done; });
      if(st.request)
      {
        const double fraction = st.fraction;
        st.request = false;
        bool go_on = !st.cancel.load();
        if(go_on)
        {
          lock.unlock();
          {
            py::gil_scoped_acquire acquire;
            try
            {
              const py::object r = progress(fraction);
              const int truth = r.is_none() ? 1 : PyObject_IsTrue(r.ptr());
              if(truth < 0)
                throw py::error_already_set();
              go_on = truth == 1;
              cancelled = cancelled || !go_on;
            }
            catch(py::error_already_set& e)
            {
              python_error = e;
              go_on = false;
            }
          }
          lock.lock();
          if(!go_on)
            st.cancel = true;
        }
        st.answer = go_on;
        st.answered = true;
        st.cv.notify_all();
      }
      else if(st.done)
        break;
      else
      {
        // No report for 50 ms: let Python handle Ctrl-C (KeyboardInterrupt cancels).
        lock.unlock();
        {
          py::gil_scoped_acquire acquire;
          if(PyErr_CheckSignals() != 0)
          {
            python_error = py::error_already_set();
            st.cancel = true;
          }
        }
        lock.lock();
      }
    }
    lock.unlock();
    worker.join();
  }
  if(python_error)
    throw *python_error;
  if(cancelled)
    throw Cancelled_error();
  if(error)
    std::rethrow_exception(error);
}

// ---- Output arrays ----

template <class T>
py::array_t<T> array_1(std::size_t n)
{
  return py::array_t<T>(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n)});
}

py::array_t<double> array_n3(std::size_t n)
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

py::dict estimates_to_dict(const std::vector<Estimate>& e, bool with_mean_error)
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
py::dict features_to_dict(const std::vector<const std::vector<Features>*>& scales, bool flat)
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
  const Scale scale = read_scale(radius, neighbors, method == "aso");
  const Tile_arg t = read_tile(tile);
  if(!CGAL::Point_set_curvatures::find_estimator(method))
    throw py::value_error("unknown method '" + method + "'");
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
  run([&](bool parallel, const Callback& cb) { result = sphere_features(cloud, scale, o, t, parallel, cb); },
      progress, threads);
  return features_to_dict({&result}, true);
}

py::array_t<double> tangent_voronoi_areas_py(const py::handle& points, const py::handle& normals,
                                             const py::object& radius, const py::object& neighbors, long long threads,
                                             const py::object& progress, bool accept_unnormalized_normals)
{
  const Scale scale = read_scale(radius, neighbors);
  Cloud cloud = read_cloud(points, normals);
  std::vector<double> areas;
  run([&](bool parallel, const Callback& cb) {
        if(!tangent_voronoi_areas(cloud, scale, accept_unnormalized_normals, parallel, cb, areas))
          throw Cancelled_error();
      },
      progress, threads);
  auto out = array_1<double>(areas.size());
  std::copy(areas.begin(), areas.end(), out.mutable_data());
  return out;
}

py::dict multiscale_features_py(const py::handle& points, const py::handle& normals,
                                const std::vector<double>& radii, long long threads, const py::object& progress,
                                const Options& options)
{
  const Cloud cloud = read_cloud(points, normals);
  std::vector<std::vector<Features> > result;
  run([&](bool parallel, const Callback& cb) {
        result = multiscale_sphere_features(cloud, radii, options, parallel, cb);
      },
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
  run([&](bool parallel, const Callback& cb) {
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

py::tuple normals_py(const py::handle& points, const py::object& radius, const py::object& neighbors,
                     int orientation, const std::vector<double>& target, int fit, long long threads,
                     const py::object& progress)
{
  const Scale scale = read_scale(radius, neighbors, true);
  if(target.size() != 3)
    throw py::value_error("the orientation target must have 3 coordinates");
  Cloud cloud = read_cloud(points, py::none());
  std::size_t without = 0;
  run([&](bool parallel, const Callback& cb) {
        without = oriented_normals(cloud, scale, orientation, target.data(), fit, parallel, cb);
      },
      progress, threads);
  auto v = array_n3(cloud.size());
  double* pv = v.mutable_data();
  for(std::size_t i = 0; i < cloud.size(); ++i)
    put3(pv, i, cloud[i].second);
  return py::make_tuple(v, without);
}

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
    m_surface = std::make_unique<APSS>(
      cloud, radius,
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

// The library's tiling (Tile.h), for splitting a cloud across processes.
class Tile_grid_py
{
public:
  Tile_grid_py(const std::vector<double>& lo, const std::vector<double>& hi, const py::object& side,
               const py::object& counts)
  {
    if(lo.size() != 3 || hi.size() != 3)
      throw py::value_error("TileGrid: box_min and box_max must have 3 coordinates");
    const CGAL::Bbox_3 box(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    if(side.is_none() == counts.is_none())
      throw py::value_error("TileGrid: give either tile_side or counts");
    if(!side.is_none())
      m_grid = CGAL::Point_set_curvatures::Tile_grid(box, side.cast<double>());
    else
    {
      const auto c = counts.cast<std::vector<long long> >();
      if(c.size() != 3 || c[0] < 1 || c[1] < 1 || c[2] < 1)
        throw py::value_error("TileGrid: counts must be 3 positive integers");
      m_grid = CGAL::Point_set_curvatures::Tile_grid(
        box, std::array<std::size_t, 3>{std::size_t(c[0]), std::size_t(c[1]), std::size_t(c[2])});
    }
  }

  std::size_t size() const { return m_grid.size(); }
  py::tuple counts() const { return py::make_tuple(m_grid.count(0), m_grid.count(1), m_grid.count(2)); }

  py::tuple core(std::size_t i) const
  {
    if(i >= m_grid.size())
      throw py::index_error("TileGrid: tile index out of range");
    const CGAL::Bbox_3 b = m_grid.tile(i, 0).core;
    return py::make_tuple(py::make_tuple(b.xmin(), b.ymin(), b.zmin()), py::make_tuple(b.xmax(), b.ymax(), b.zmax()));
  }

  py::array_t<std::int64_t> tile_of(const py::handle& points) const
  {
    checked_rows(points, "points");
    const py::array a = py::reinterpret_borrow<py::array>(points);
    auto out = array_1<std::int64_t>(static_cast<std::size_t>(a.shape(0)));
    std::int64_t* p = out.mutable_data();
    for_each_row(a, [&](py::ssize_t i, const double* x) {
      p[i] = static_cast<std::int64_t>(m_grid.tile_of(x[0], x[1], x[2]));
    });
    return out;
  }

  // For each point, the tiles whose halo holds it: (point indices, tile indices), sorted by
  // tile then point (so that each tile's points are in input order).
  py::tuple tiles_near(const py::handle& points, double halo) const
  {
    checked_rows(points, "points");
    const py::array a = py::reinterpret_borrow<py::array>(points);
    std::vector<std::pair<std::int64_t, std::int64_t> > pairs;  // (tile, point)
    for_each_row(a, [&](py::ssize_t i, const double* x) {
      m_grid.for_each_tile_near(x[0], x[1], x[2], halo, [&](std::size_t t) { pairs.emplace_back(t, i); });
    });
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const auto& u, const auto& v) { return u.first < v.first; });
    auto pi = array_1<std::int64_t>(pairs.size()), ti = array_1<std::int64_t>(pairs.size());
    for(std::size_t j = 0; j < pairs.size(); ++j)
    {
      ti.mutable_data()[j] = pairs[j].first;
      pi.mutable_data()[j] = pairs[j].second;
    }
    return py::make_tuple(pi, ti);
  }

private:
  CGAL::Point_set_curvatures::Tile_grid m_grid;
};

} // namespace psc_py

namespace psc_py {

// An estimator's description as a dict: name, function, summary, fields (a tuple of the
// result's keys it fills), min_neighbors, good_neighbors, paper_variant_good_neighbors,
// options (dicts: name, values, default, choices).
py::dict estimator_to_dict(const CGAL::Point_set_curvatures::Estimator_description& e)
{
  namespace F = CGAL::Point_set_curvatures::estimate_fields;
  const std::pair<unsigned, const char*> keys[] = {
    {F::normal, "normal"}, {F::principal_curvatures, "k_min"}, {F::principal_curvatures, "k_max"},
    {F::mean_curvature, "mean"}, {F::gaussian_curvature, "gaussian"}, {F::normal_coherence, "normal_coherence"},
    {F::principal_directions, "min_direction"}, {F::principal_directions, "max_direction"}};
  py::list fields, options;
  for(const auto& k : keys)
    if(e.fields & k.first)
      fields.append(k.second);
  for(const CGAL::Point_set_curvatures::Estimator_option& o : e)
  {
    py::list choices;
    for(const char* c : o.choices)
      choices.append(c);
    py::dict d;
    d["name"] = o.name;
    d["values"] = o.values;
    d["default"] = o.default_value;
    d["choices"] = py::tuple(choices);
    options.append(d);
  }
  py::dict d;
  d["name"] = e.name;
  d["function"] = e.function;
  d["summary"] = e.summary;
  d["fields"] = py::tuple(fields);
  d["min_neighbors"] = e.min_neighbors;
  d["good_neighbors"] = e.good_neighbors;
  d["paper_variant_good_neighbors"] = e.paper_variant_good_neighbors;
  d["options"] = py::tuple(options);
  return d;
}

} // namespace psc_py

PYBIND11_MODULE(_core, m)
{
  using namespace psc_py;
  m.doc() = "Compiled part of point_set_curvatures (use the functions of the package, not these).";
  // The CMake project's version (CMakeLists.txt), which setup.py gives the pip package too.
  m.attr("__version__") = PSC_PYTHON_VERSION;
  m.attr("MAX_THREADS") = std::max(1, tbb::info::default_concurrency());

  py::register_exception<Cancelled_error>(m, "Cancelled", PyExc_RuntimeError);
  // HaloTooSmall carries required_halo; the type lives as long as the interpreter.
  static PyObject* halo_type = PyErr_NewException("point_set_curvatures._core.HaloTooSmall", PyExc_RuntimeError, nullptr);
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
  {
    namespace PSC = CGAL::Point_set_curvatures;
    auto names = [](const auto& array) {
      py::list l;
      for(const char* n : array)
        l.append(n);
      return py::tuple(l);
    };
    py::dict enums;  // option -> the names of its values, indexed by the C++ enumerator's value
    enums["aso_variant"] = names(PSC::aso_variant_names);
    enums["weight_kernel"] = names(PSC::weight_kernel_names);
    enums["sample_weights"] = names(PSC::sample_weights_names);
    enums["aso_projection"] = names(PSC::aso_projection_names);
    m.attr("ENUM_NAMES") = enums;
  }
  m.attr("AUTOMATIC_NEIGHBORS") = py::make_tuple(CGAL::Point_set_curvatures::automatic_scale_ladder::smallest,
                                                 CGAL::Point_set_curvatures::automatic_scale_ladder::largest);

  // Status names and values, checked against the Python enums at import.
  py::dict status;
  for(int s = 0; s <= int(CGAL::Curvature_estimate_status::TWO_SHEETS); ++s)
    status[py::str(CGAL::to_string(CGAL::Curvature_estimate_status(s)))] = s;
  m.attr("STATUS_VALUES") = status;
  py::dict projection_status;
  for(int s = 0; s <= int(CGAL::Apss_projection_status::NON_FINITE_POINT); ++s)
    projection_status[py::str(CGAL::to_string(CGAL::Apss_projection_status(s)))] = s;
  m.attr("PROJECTION_STATUS_VALUES") = projection_status;

  // The halo rule of tiles (Tile.h), for the Dask driver.
  m.def("halo_for_radius", &CGAL::Point_set_curvatures::halo_for_radius, py::arg("radius"));
  m.def(
    "halo_guess_for_count",
    [](const std::array<double, 3>& lo, const std::array<double, 3>& hi, std::size_t n, std::size_t k) {
      return CGAL::Point_set_curvatures::halo_guess_for_count(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]),
                                                              n, k);
    },
    py::arg("box_min"), py::arg("box_max"), py::arg("points"), py::arg("neighbors"));
  m.def(
    "next_halo",
    [](double halo, double required, double at_least) {
      return CGAL::Point_set_curvatures::next_halo(CGAL::Point_set_curvatures::Halo_too_small(required, halo), at_least);
    },
    py::arg("halo"), py::arg("required"), py::arg("at_least"));
  m.def("estimate_curvatures", &estimate_curvatures, py::arg("method"), py::arg("points"), py::arg("normals"),
        py::arg("radius"), py::arg("neighbors"), py::arg("threads"), py::arg("progress"), py::arg("options"),
        py::arg("tile"), py::arg("weights"));
  m.def("sphere_features", &sphere_features_py, py::arg("points"), py::arg("normals"), py::arg("radius"),
        py::arg("neighbors"), py::arg("threads"), py::arg("progress"), py::arg("options"), py::arg("tile"),
        py::arg("weights"));
  m.def("tangent_voronoi_areas", &tangent_voronoi_areas_py, py::arg("points"), py::arg("normals"),
        py::arg("radius"), py::arg("neighbors"), py::arg("threads"), py::arg("progress"),
        py::arg("accept_unnormalized_normals"));
  m.def("multiscale_sphere_features", &multiscale_features_py, py::arg("points"), py::arg("normals"),
        py::arg("radii"), py::arg("threads"), py::arg("progress"), py::arg("options"));
  m.def("smooth_point_set", &smooth_py, py::arg("points"), py::arg("normals"), py::arg("radius"),
        py::arg("iterations"), py::arg("update_normals"), py::arg("threads"), py::arg("progress"),
        py::arg("options"));
  m.def("estimate_normals", &normals_py, py::arg("points"), py::arg("radius"), py::arg("neighbors"),
        py::arg("orientation"), py::arg("target"), py::arg("fit"), py::arg("threads"), py::arg("progress"));

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
