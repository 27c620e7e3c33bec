// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The point_set_curvatures tool's progress bar: one line per phase on a terminal, and the
// progress callbacks that stop a phase once the run is interrupted (interruption.h).

#ifndef POINT_SET_CURVATURES_TOOL_PROGRESS_BAR_H
#define POINT_SET_CURVATURES_TOOL_PROGRESS_BAR_H

#include "interruption.h"
#include "progress_line.h"
#include "psc_io/support.h"

#include <CGAL/Point_set_curvatures/internal/work_rate.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace psc_tool {

// One line per phase on a terminal ("reading     [#######.....]  58%   1.2 s  ETA 1 s", the
// time left at the rate since the phase's first report; a
// pass over the tiles is one phase, its steps named after it: "... ETA 3 min 10 s  tile 2/9 read"),
// redrawn at every new percent and, from a timer thread, twice a second: the elapsed time and
// the ETA move on while a phase reports no progress for long (a radius covering the whole
// cloud). Nothing is drawn when stderr is not a terminal, and then no thread is started.
// The callbacks return false once Ctrl-C was pressed, which cancels the phase. CGAL's
// Parallel_tag functions call them from threads of their own: a mutex keeps one drawer at a
// time (the signal handler never draws).
class Progress_bar
{
public:
  explicit Progress_bar(bool enabled) : m_enabled(enabled)
  {
    if(m_enabled)
      m_timer = std::thread([this]() { redraw_periodically(); });
  }

  ~Progress_bar()
  {
    if(m_timer.joinable())
    {
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
      }
      m_wake.notify_all();
      m_timer.join();
    }
  }

  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  // Starts a phase (ending the previous one) and returns its callback.
  Progress phase(const std::string& name)
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      finish_locked();
      m_name = name;
      m_label.clear();
      m_label_width = 0;
      current_phase = name;
      m_start = std::chrono::steady_clock::now();
      m_rate.restart();
      m_fraction = 0;
      m_last = -1;
      m_active = true;
      draw_locked(true);
    }
    test_signal_at_phase_start(name);
    return [this](double fraction) {
      // (the lock only at a new percent: the line shows no finer fraction)
      if(m_enabled && percent_of(fraction) != m_last)
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        if(!m_rate.reported())
          m_rate.report(std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(),
                        std::isfinite(fraction) ? std::max(0.0, std::min(1.0, fraction)) : 0.0);
        m_fraction = fraction;
        draw_locked(false);
      }
      return !interrupted;
    };
  }

  // Names a step of the current phase (a tile's read or estimation in a pass over the tiles):
  // shown after the phase's line, named as the phase an interruption stopped, and a phase
  // for the test hook (interruption.h).
  void step(const std::string& label)
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_label = label;
      m_label_width = std::max(m_label_width, label.size());
      current_phase = label;
      draw_locked(true);
    }
    test_signal_at_phase_start(label);
  }

  // Prints `line` at once above the bar, which goes on below it; false (nothing printed)
  // when no bar is drawn (stderr not a terminal, --quiet): the warnings then wait for the end
  // of the run, so that a failure stays one line.
  bool note(const std::string& line)
  {
    if(!m_enabled)
      return false;
    std::lock_guard<std::mutex> lock(m_mutex);
    if(m_drawn)
      std::fputc('\n', stderr);
    std::fprintf(stderr, "%s\n", line.c_str());
    m_drawn = false;
    draw_locked(true);
    return true;
  }

  // Ends the current phase's line.
  void finish()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    finish_locked();
  }

private:
  void finish_locked()
  {
    if(m_drawn)
      std::fputc('\n', stderr);
    m_drawn = false;
    m_active = false;
  }

  // Draws the line at a new percent, or always with `force` (the timer's redraws).
  void draw_locked(bool force)
  {
    if(!m_enabled || !m_active)
      return;
    const double f = std::isfinite(m_fraction) ? std::max(0.0, std::min(1.0, m_fraction)) : 0.0;
    const int percent = percent_of(f);
    if(percent == m_last && !force)
      return;
    m_last = percent;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    // the time left at the rate since the first report (the set-up before it, a reader's or a
    // search's, tells nothing of what is left)
    const double rate = m_rate.own(seconds, f, -1);
    const double eta = rate >= 0 ? rate * (1 - f) : -1;
    std::fprintf(stderr, "\r%s", progress_line(m_name, f, seconds, m_label, m_label_width, eta).c_str());
    std::fflush(stderr);
    m_drawn = true;
  }

  static int percent_of(double fraction)
  {
    return std::isfinite(fraction) ? static_cast<int>(100 * std::max(0.0, std::min(1.0, fraction))) : 0;
  }

  void redraw_periodically()
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    while(!m_stop)
    {
      m_wake.wait_for(lock, std::chrono::milliseconds(500));
      if(!m_stop && m_active && !interrupted)
        draw_locked(true);
    }
  }

  const bool m_enabled;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::thread m_timer;
  bool m_stop = false;
  bool m_active = false;  // a phase is running (between phase() and finish())
  std::string m_name;
  std::string m_label;            // the step's (step()), shown after the line
  std::size_t m_label_width = 0;  // the longest label of the phase
  std::chrono::steady_clock::time_point m_start;
  double m_fraction = 0;
  CGAL::Point_set_curvatures::internal::Work_rate m_rate;  // the phase's, from its first report
  std::atomic<int> m_last{-1};  // the percent drawn last (read without the lock by the callbacks)
  bool m_drawn = false;
};

}  // namespace psc_tool

#endif
