// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Python bindings: running a C++ function in a worker thread with the GIL released, the
// progress reports forwarded to a Python callable on the calling thread, cancellation, the
// thread count.

#ifndef PSC_PYTHON_RUN_H
#define PSC_PYTHON_RUN_H

#include "common.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

namespace psc_py {

namespace py = pybind11;

// Raised (as point_set_curvatures.Cancelled) when the progress callable returned False.
struct Cancelled_error : std::runtime_error
{
  Cancelled_error() : std::runtime_error("cancelled by the progress callback") {}
};

// The thread count of a run: 0 (all cores) as it is, more than the cores TBB may use capped
// to them (the results do not depend on it; an arena larger than that would only make TBB
// print a warning on stderr). Negative values are refused.
inline long long checked_threads(long long threads)
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

}  // namespace psc_py

#endif
