// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// point_set_curvatures INPUT OUTPUT [options]
//
// Command-line front end of the package: reads a point cloud (.xyz/.pwn/.txt/.csv/.asc, .ply, .off, .las),
// estimates normals if the file has none, estimates curvatures at every point and writes them
// (.ply, .csv or .las), every input point in input order. The options are parsed in
// command_line.cpp, the estimators run from methods.cpp, the files are read and written in
// read_*.cpp and write_point_cloud.cpp, and inputs larger than memory go through tiled_run.cpp.
// Run with --help for the options. Exit status: 0 on success, 2 on invalid arguments or
// unreadable/malformed/unwritable files (one line on stderr, no output file left behind), 3
// when no point got a valid estimate (the output written, the reason on stderr), 130 when
// interrupted by Ctrl-C (SIGINT), 143 by SIGTERM, 1 on unexpected failures.

#include <CGAL/Point_set_curvatures/Tile.h>
#include <CGAL/Point_set_curvatures/internal/knn_neighborhoods.h>
#include <CGAL/Point_set_curvatures/parameters.h>
#include <CGAL/estimate_oriented_normals.h>

#include <tbb/global_control.h>

#include "command_line.h"
#include "methods.h"
#include "progress_line.h"
#include "read_point_cloud.h"
#include "run_summary.h"
#include "tiled_run.h"
#include "tool_support.h"
#include "write_las.h"
#include "write_point_cloud.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace psc_tool;
namespace PSC = CGAL::Point_set_curvatures;

// ---------------------------------------------------------------------------------------
// --orient scanner

// The attributes holding the pulse directions x(t) y(t) z(t) of LAS wave packets (read_las.cpp).
std::array<int, 3> pulse_attributes(const std::vector<Attribute>& attributes)
{
  std::array<int, 3> found = {{-1, -1, -1}};
  for(std::size_t j = 0; j < attributes.size(); ++j)
    for(int a = 0; a < 3; ++a)
      if(attributes[j].name == std::string("wave_") + "xyz"[a] + "_t")
        found[a] = int(j);
  return found;
}

// Turns each normal towards the origin of its point's pulse: against the pulse's direction
// (x(t), y(t), z(t): from the scanner to the point). Points without a direction (zero or not
// finite) keep the +z orientation; returns their number.
template <class Normal_of, class Pulse_of>
std::size_t orient_towards_scanner(std::size_t n, const Normal_of& normal, const Pulse_of& pulse)
{
  std::size_t without = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3> d = pulse(i);
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if(!(dd > 0) || !std::isfinite(dd))
    {
      ++without;
      continue;
    }
    Vector& v = normal(i);
    if(v.x() * d[0] + v.y() * d[1] + v.z() * d[2] > 0)
      v = -v;
  }
  return without;
}

// ---------------------------------------------------------------------------------------
// Progress and interruption

volatile std::sig_atomic_t interrupted = 0;
// The signal that interrupted the run (SIGINT or SIGTERM): the exit status is 128 + it.
volatile std::sig_atomic_t interrupt_signal = SIGINT;
// The temporary output file, removed by a second Ctrl-C (a fixed buffer: the handler may only
// call async-signal-safe functions). Empty when there is none.
char temporary_output_path[4096] = "";

// The phase running (its name in the progress bar), named in the message of an interrupted
// run: the phase that stopped.
std::string current_phase = "startup";

// Test hook (test_tool): PSC_TOOL_TEST_SIGNAL=INT@NAME, TERM@NAME or KILL@NAME raises SIGINT,
// SIGTERM or SIGKILL when the first phase whose name starts with NAME begins ('*' in NAME: any
// text, as in "tile *curvatures"; NAME#N: the N-th such phase), so that a test can check that
// every phase stops at the signal (within a progress report: about 1% of its work, 0.25 s),
// and what a run killed in a phase leaves behind.
void test_signal_at_phase_start(const std::string& phase)
{
  static const char* const hook = std::getenv("PSC_TOOL_TEST_SIGNAL");
  static int seen = 0;
  if(!hook || seen < 0)
    return;
  const std::string h = hook;
  const std::size_t at = h.find('@'), hash = h.find('#');
  if(at == std::string::npos)
    return;
  const std::string name = h.substr(at + 1, hash == std::string::npos ? std::string::npos : hash - at - 1);
  const int nth = hash == std::string::npos ? 1 : std::atoi(h.c_str() + hash + 1);
  const std::size_t star = name.find('*');
  const std::string head = name.substr(0, star), tail = star == std::string::npos ? "" : name.substr(star + 1);
  if(phase.compare(0, head.size(), head) != 0 ||
     (star != std::string::npos &&
      (phase.size() < head.size() + tail.size() || phase.compare(phase.size() - tail.size(), tail.size(), tail) != 0)))
    return;
  if(++seen < nth)
    return;
  seen = -1;  // once
  const std::string signal = h.substr(0, at);
  std::raise(signal == "TERM" ? SIGTERM : signal == "KILL" ? SIGKILL : SIGINT);
}

// The first Ctrl-C (or SIGTERM) cancels the current phase at its next progress report; a
// second one removes the temporary output and exits at once. Exit status 128 + the signal,
// as a shell reports a process the signal killed: 130 for SIGINT, 143 for SIGTERM.
extern "C" void on_interrupt(int signal)
{
  if(interrupted)
  {
    if(temporary_output_path[0] != '\0')
      ::unlink(temporary_output_path);
    ::_exit(128 + signal);
  }
  interrupt_signal = signal;
  interrupted = 1;
}

// ---------------------------------------------------------------------------------------
// Normals

bool is_finite(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

std::vector<Point_set::Index> finite_points(const Point_set& ps)
{
  std::vector<Point_set::Index> indices;
  indices.reserve(ps.size());
  for(Point_set::Index i : ps)
    if(is_finite(ps.point(i)))
      indices.push_back(i);
  return indices;
}

// The average spacing of --radius Nx, as CGAL::compute_average_spacing() computes it with 6
// neighbours: the mean, over the finite points, of the mean distance from a point to its 7
// nearest points, itself included (CGAL 5.5 searches k + 1 points and divides by k + 1). Computed on the package's k-nearest driver: faster than
// CGAL's k-d tree, and CGAL 5.5's function keeps a reference to a destroyed temporary of its
// callback (AddressSanitizer: stack-use-after-scope). Every finite point counts, with or without
// a normal (a constant normal is given to the driver).
double average_spacing(const Point_set& ps, const Progress& progress)
{
  namespace PSI = CGAL::Point_set_curvatures::internal;
  const std::size_t k = 7;
  PSI::Neighborhood_options options;
  options.function_name = "--radius Nx (average spacing)";
  options.callback = progress;
  options.check_normal_length = false;
  std::vector<double> spacing(ps.size(), -1.0);
  const CGAL::Constant_property_map<Point_set::Index, Vector> any_normal(Vector(0, 0, 1));
  PSI::for_each_neighborhood_knn<CGAL::Parallel_tag>(
    ps, ps.point_map(), any_normal, k, options, [&spacing, k](std::size_t i, const PSI::Neighborhood& nb) {
      // nb holds the k nearest and any point tied with the k-th: the k smallest distances
      thread_local std::vector<double> d;
      d.clear();
      for(std::size_t j = 0; j < nb.size; ++j)
        d.push_back(std::sqrt(nb.qx[j] * nb.qx[j] + nb.qy[j] * nb.qy[j] + nb.qz[j] * nb.qz[j]) * nb.radius);
      const std::size_t used = std::min(k, d.size());
      if(used == 0)
        return;
      std::nth_element(d.begin(), d.begin() + (used - 1), d.end());
      double sum = 0;
      for(std::size_t j = 0; j < used; ++j)
        sum += d[j];
      spacing[i] = sum / double(used);
    });
  double sum = 0;
  std::size_t count = 0;
  for(double s : spacing)
    if(s >= 0)
    {
      sum += s;
      ++count;
    }
  return count ? sum / double(count) : 0;
}

// How the estimated normals are oriented: --orient, or for "auto" (the default) what suits
// the input (LAS files are airborne or mobile scans, seen from above, unless they hold pulse
// directions), and why, for the summary.
struct Orientation_choice
{
  CGAL::Normal_orientation orientation;
  bool scanner = false;  // then each normal is turned towards its pulse's origin afterwards
  std::string text;      // what the summary says
};

Orientation_choice choose_orientation(const Options& o, bool las, bool has_pulses)
{
  Orientation_choice c;
  c.orientation = o.orientation;
  c.scanner = o.orient_scanner;
  if(o.orientation_text != "auto")
  {
    c.text = cat(o.orientation_text, " (--orient)");
    return c;
  }
  if(las && has_pulses)
  {
    c.orientation = CGAL::Normal_orientation::along_vector(0, 0, 1);
    c.scanner = true;
    c.text = "towards the scanner (LAS pulse directions; --orient auto)";
  }
  else if(las)
    c.orientation = CGAL::Normal_orientation::automatic();  // text once the normals are known
  else
  {
    c.orientation = CGAL::Normal_orientation::minimum_spanning_tree();
    c.text = "mst: along a minimum spanning tree, closed parts outward, open parts up (--orient auto)";
  }
  return c;
}

// Estimates the normals of the point set as the options say, oriented as `choice` says (its
// text completed for the automatic orientation). Returns the number of points left without a
// normal.
std::size_t estimate_normals(Point_set& ps, const Options& o, Orientation_choice& choice, const Progress& progress)
{
  ps.add_normal_map();
  const std::size_t without = CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
    ps, PSC::parameters::neighbor_count(
          normal_neighbor_count(o),
          PSC::parameters::automatic_scale(
            normal_automatic_largest(o),
            PSC::parameters::normal_fit(o.normal_fit, PSC::parameters::normal_orientation(
                                                        choice.orientation, CGAL::parameters::callback(progress))))));
  if(interrupted)
    throw Cancelled();
  if(choice.orientation.kind == CGAL::Normal_orientation::AUTOMATIC)
  {
    std::size_t usable = 0, vertical = 0;
    for(Point_set::Index i : ps)
    {
      const Vector& n = ps.normal(i);
      usable += n == CGAL::NULL_VECTOR ? 0 : 1;
      vertical += PSC::is_near_vertical(n.x(), n.y(), n.z()) ? 1 : 0;
    }
    const double share = usable ? std::round(1000.0 * double(vertical) / double(usable)) / 10 : 0.0;
    choice.text = PSC::is_two_and_a_half_d(vertical, usable)
                    ? cat("+z (LAS file, 2.5-D: ", share, "% of the normals within 60 degrees of the vertical; "
                          "closed parts outward; --orient auto)")
                    : cat("mst (LAS file, not 2.5-D: ", share, "% of the normals within 60 degrees of the "
                          "vertical; closed parts outward, open parts up; --orient auto)");
  }
  return without;
}

// One line per phase on a terminal ("reading     [#######.....]  58%   1.2 s  ETA 1 s"),
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
      current_phase = name;
      m_start = std::chrono::steady_clock::now();
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
        m_fraction = fraction;
        draw_locked(false);
      }
      return !interrupted;
    };
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
    std::fprintf(stderr, "\r%s", progress_line(m_name, f, seconds).c_str());
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
  std::chrono::steady_clock::time_point m_start;
  double m_fraction = 0;
  std::atomic<int> m_last{-1};  // the percent drawn last (read without the lock by the callbacks)
  bool m_drawn = false;
};

// ---------------------------------------------------------------------------------------
// Output

// "120.3 MB": a size for messages.
std::string size_text(double bytes)
{
  char text[64];
  if(bytes < 1024)
    std::snprintf(text, sizeof text, "%.0f bytes", bytes);
  else if(bytes < 1024.0 * 1024)
    std::snprintf(text, sizeof text, "%.1f KB", bytes / 1024);
  else if(bytes < 1024.0 * 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f MB", bytes / (1024.0 * 1024));
  else if(bytes < 1024.0 * 1024 * 1024 * 1024)
    std::snprintf(text, sizeof text, "%.1f GB", bytes / (1024.0 * 1024 * 1024));
  else
    std::snprintf(text, sizeof text, "%.1f TB", bytes / (1024.0 * 1024 * 1024 * 1024));
  return text;
}

// The folder of a path ("." for a bare name) and its name in it.
std::string folder_of(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

// The temporary files of OUTPUT are named ".NAME.tmp-PID-" and six characters of mkstemp
// (the output while it is written) or "tileN-" and six (the rows of a tiled run's tiles,
// unlinked at once): the PID tells the files of a killed run (its process is gone) from
// those of a run still going.
std::string temporary_prefix(const std::string& output)
{
  return hidden_sibling(output, cat(".tmp-", ::getpid(), "-"));
}

// Refuses, before any computation, an OUTPUT that cannot be written: a directory, a folder
// that does not exist, is not a directory or is not writable.
void check_output_path(const std::string& output)
{
  struct stat st;
  if(::stat(output.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw Error(cat("the output ", in_quotes(output), " is a directory: give a file name, such as ",
                    in_quotes(output + "/curvatures" + lower_extension(output))));
  const std::string folder = folder_of(output);
  if(::stat(folder.c_str(), &st) != 0)
    throw Error(cat("cannot write output ", in_quotes(output), ": its folder ", in_quotes(folder), " ",
                    errno == ENOENT ? "does not exist (create it with mkdir -p, or choose another OUTPUT)"
                                    : cat("cannot be read (", std::strerror(errno), "); choose another OUTPUT")));
  if(!S_ISDIR(st.st_mode))
    throw Error(cat("cannot write output ", in_quotes(output), ": ", in_quotes(folder),
                    " is not a directory; choose another OUTPUT"));
  if(::access(folder.c_str(), W_OK | X_OK) != 0)
    throw Error(cat("cannot write output ", in_quotes(output), ": its folder ", in_quotes(folder),
                    " is not writable (", std::strerror(errno), "); choose another OUTPUT or change its permissions"));
}

// Removes the temporary files that runs writing `output` left when they were killed (SIGKILL,
// a power cut): ".NAME.tmp-PID-..." whose process is gone, and ".NAME.tmp-XXXXXX" of the
// tool's earlier versions. Returns their number.
std::size_t remove_stale_temporaries(const std::string& output)
{
  const std::size_t slash = output.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : output.substr(0, slash + 1);
  const std::string head = hidden_sibling(output, ".tmp-").substr(folder.size());
  if(head.size() <= 5)
    return 0;
  std::size_t removed = 0;
  DIR* d = ::opendir(folder.empty() ? "." : folder.c_str());
  if(!d)
    return 0;
  while(const dirent* e = ::readdir(d))
  {
    const std::string name = e->d_name;
    if(name.compare(0, head.size(), head) != 0)
      continue;
    const std::string rest = name.substr(head.size());
    const std::size_t dash = rest.find('-');
    bool stale = false;
    if(dash == std::string::npos)
      stale = rest.size() == 6;  // ".NAME.tmp-XXXXXX": an earlier version's
    else if(dash > 0 && dash < 10 && rest.find_first_not_of("0123456789") == dash)
    {
      const long pid = std::strtol(rest.c_str(), nullptr, 10);
      stale = pid > 0 && pid != long(::getpid()) && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH;
    }
    struct stat st;
    const std::string path = folder + name;
    if(stale && ::lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::unlink(path.c_str()) == 0)
      ++removed;
  }
  ::closedir(d);
  return removed;
}

// Allocates `bytes` to the file: 0, or the error (ENOSPC for a full disk, EDQUOT, EFBIG for a
// file size limit). A file system without fallocate is checked for its free space instead.
int allocate(int fd, std::uint64_t bytes)
{
  if(bytes == 0)
    return 0;
#ifdef __linux__
  for(;;)
  {
    if(::fallocate(fd, 0, 0, off_t(bytes)) == 0)
      return 0;
    if(errno != EINTR || interrupted)
      break;
  }
  if(errno != EOPNOTSUPP && errno != ENOSYS)
    return errno;
  struct statvfs v;
  if(::fstatvfs(fd, &v) == 0 && double(v.f_bavail) * double(v.f_frsize) < double(bytes))
    return ENOSPC;
  return 0;
#else
  return ::posix_fallocate(fd, 0, off_t(bytes));
#endif
}

// The output file. Its size is reserved on its file system before the estimation (reserve()),
// so that a full disk, a quota or a file size limit fails in the first second, not after the
// computation; the space is held by a temporary file unlinked at once, so that a killed run
// leaves nothing. When writing starts (open()), the output is written under a temporary name
// in the same folder (the reservation passing to it), and renamed when complete (commit()):
// a failure or an interruption never leaves a partial OUTPUT.
class Temporary_output
{
public:
  explicit Temporary_output(const std::string& output) : m_output(output) {}

  ~Temporary_output()
  {
    discard();
    release();
  }

  // Reserves `bytes` (the output's size, or an upper bound) for the output; `what` describes
  // it for the message.
  void reserve(std::uint64_t bytes, const std::string& what)
  {
    std::string path;
    const int fd = create(path);
    ::unlink(path.c_str());
    temporary_output_path[0] = '\0';
    const int e = allocate(fd, bytes);
    if(e != 0)
    {
      ::close(fd);
      if(interrupted)
        throw Cancelled();
      throw reservation_error(e, bytes, what);
    }
    release();
    m_reserved = fd;
  }

  // Creates the temporary file, `bytes` allocated to it, and returns it for writing.
  std::FILE* open(std::uint64_t bytes, const std::string& what)
  {
    const int fd = create(m_path);
    release();  // the space reserved passes to the file
    const int e = allocate(fd, bytes);
    if(e != 0)
    {
      ::close(fd);
      discard();
      if(interrupted)
        throw Cancelled();
      throw reservation_error(e, bytes, what);
    }
    m_file = ::fdopen(fd, "wb");
    if(!m_file)
    {
      ::close(fd);
      discard();
      throw Error(cat("cannot write output ", in_quotes(m_output), ": ", std::strerror(errno)));
    }
    static char buffer_space[1 << 16];
    std::setvbuf(m_file, buffer_space, _IOFBF, sizeof(buffer_space));
    return m_file;
  }

  std::FILE* file() { return m_file; }

  void commit()
  {
    // the allocation may exceed what was written (text formats): cut the file where it ends
    bool written = std::fflush(m_file) == 0 && !std::ferror(m_file);
    const off_t end = ::ftello(m_file);
    written = written && end >= 0 && ::ftruncate(::fileno(m_file), end) == 0;
    const int error = errno;
    const bool closed = std::fclose(m_file) == 0;
    m_file = nullptr;
    if(!written || !closed)
      throw Error(cat("cannot write output ", in_quotes(m_output), ": ", std::strerror(written ? errno : error)));
    temporary_output_path[0] = '\0';
    if(std::rename(m_path.c_str(), m_output.c_str()) != 0)
      throw Error(cat("cannot write output ", in_quotes(m_output), ": ", std::strerror(errno)));
    m_path.clear();
  }

  void discard()
  {
    if(m_file)
      std::fclose(m_file);
    m_file = nullptr;
    temporary_output_path[0] = '\0';
    if(!m_path.empty())
      std::remove(m_path.c_str());
    m_path.clear();
  }

private:
  // A new temporary file ".NAME.tmp-PID-XXXXXX" with the usual permissions; its name in `path`
  // and in temporary_output_path (removed by a second Ctrl-C).
  int create(std::string& path)
  {
    const std::string pattern = temporary_prefix(m_output) + "XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int fd = ::mkstemp(buffer.data());
    if(fd < 0)
      throw Error(cat("cannot write output ", in_quotes(m_output), ": ", std::strerror(errno)));
    path = buffer.data();
    if(path.size() < sizeof(temporary_output_path))
      std::memcpy(temporary_output_path, path.c_str(), path.size() + 1);
    // mkstemp creates the file readable by its owner only: give it the usual permissions
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    return fd;
  }

  void release()
  {
    if(m_reserved >= 0)
      ::close(m_reserved);
    m_reserved = -1;
  }

  Error reservation_error(int e, std::uint64_t bytes, const std::string& what) const
  {
    const std::string needs = cat(size_text(double(bytes)), " (", what, ")");
    if(e == ENOSPC)
    {
      struct statvfs v;
      const std::string free_space = ::statvfs(folder_of(m_output).c_str(), &v) == 0
                                       ? cat(", the file system holding it has ", size_text(double(v.f_bavail) * double(v.f_frsize)), " free")
                                       : std::string();
      return Error(cat("not enough space for output ", in_quotes(m_output), ": it needs up to ", needs, free_space,
                       "; free some space or write OUTPUT elsewhere"));
    }
    if(e == EDQUOT)
      return Error(cat("output ", in_quotes(m_output), " needs up to ", needs, ", beyond your disk quota; free some "
                       "space or write OUTPUT elsewhere"));
    if(e == EFBIG)
      return Error(cat("output ", in_quotes(m_output), " needs up to ", needs, ", more than the largest file allowed "
                       "(the shell's file size limit, ulimit -f, or the file system's); raise the limit or write "
                       "OUTPUT elsewhere"));
    return Error(cat("cannot reserve ", needs, " for output ", in_quotes(m_output), ": ", std::strerror(e)));
  }

  std::string m_output, m_path;
  std::FILE* m_file = nullptr;
  int m_reserved = -1;  // the unlinked file holding the space reserved, until open()
};

// Diverging colour map centred on 0 (Moreland's cool-warm end points): blue for negative,
// near-white at zero, red for positive, saturated beyond +-range.
std::array<unsigned char, 3> diverging_color(double v, double range)
{
  static const double blue[3] = {59, 76, 192}, white[3] = {221, 221, 221}, red[3] = {180, 4, 38};
  if(!std::isfinite(v))
    return {128, 128, 128};
  const double t = range > 0 ? std::max(-1.0, std::min(1.0, v / range)) : 0.0;
  const double* end = t < 0 ? blue : red;
  const double a = std::abs(t);
  std::array<unsigned char, 3> c;
  for(int i = 0; i < 3; ++i)
    c[i] = static_cast<unsigned char>(std::lround((1 - a) * white[i] + a * end[i]));
  return c;
}

// ---------------------------------------------------------------------------------------
// Summary

std::string min_median_max(const Row_summary& s, int q)
{
  if(s.count(q) == 0)
    return s.valid() ? "n/a (not estimated by this method)" : "n/a (no valid estimate)";
  return cat("min ", s.min(q), "  median ", percentile(s.sample(q), 0.5), "  max ", s.max(q));
}

// "1.234": seconds in the report
std::string s3(double seconds)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

std::string scale_description(const Scale& s)
{
  if(s.by_count && s.automatic_largest > 0)
    return cat("automatic scale: ", s.neighbors, " to ", s.automatic_largest,
               " nearest neighbours, the count chosen per point (field neighbors)");
  if(s.by_count)
    return cat(s.neighbors, " nearest neighbours per point (itself included)");
  if(s.spacing_multiple > 0)
    return cat("radius ", s.radius, " (", s.spacing_multiple, " x average spacing ", s.spacing, ")");
  return cat("radius ", s.radius);
}

// The points that can be anyone's neighbour: finite, with a usable normal.
std::size_t usable_points(const Row_summary& summary)
{
  std::size_t n = summary.valid();
  for(const auto& s : summary.invalid())
    if(s.first != int(CGAL::Curvature_estimate_status::NON_FINITE_POINT) &&
       s.first != int(CGAL::Curvature_estimate_status::INVALID_NORMAL))
      n += s.second;
  return n;
}

// "fewer than 12 neighbours": the least count of a valid estimate, when the tool knows it
// (--min-neighbors below a fit's own least count, 3 or 6 points, is raised to it).
std::string fewer_than_least(const Method& m, const Scale& scale)
{
  const std::size_t least = scale.min_neighbors ? scale.min_neighbors : m.min_neighbors;
  return least >= 6 ? cat("fewer than ", least, " neighbours") : std::string("too few neighbours for a fit");
}

// When the input holds fewer usable points than the method's `good_neighbors`, no scale
// helps: what to say instead of a suggested scale ("" otherwise).
std::string too_small_input(const Method& m, const std::string& input, const Row_summary& summary)
{
  const std::size_t usable = usable_points(summary);
  if(usable >= m.good_neighbors)
    return "";
  return cat(in_quotes(input), " is too small for ", m.name, ": it holds ", plural(usable, "usable point"),
             " (finite, with a normal), fewer than the ", m.good_neighbors, " neighbours from which ", m.name,
             "'s errors stay within twice those at 40 (measured, see the manual), whatever --radius or --neighbors");
}

// The scale to try for about 40 neighbours, from the median count (counts grow like the
// radius squared on a surface).
std::string suggested_scale(const Method& m, const Scale& scale, double median)
{
  if(scale.by_count)
    return cat("--neighbors ", std::max<std::size_t>(40, m.good_neighbors));
  const double factor = std::sqrt(40.0 / std::max(median, 1.0));
  return scale.spacing_multiple > 0 ? cat("--radius ", scale.spacing_multiple * factor, "x")
                                    : cat("--radius ", scale.radius * factor);
}

// The warning when neighbourhoods are small: empty if the median count of the estimated
// points reaches the method's measured `good_neighbors`.
std::string small_neighborhood_warning(const Method& m, const Scale& scale, const Row_summary& summary,
                                       const std::string& input)
{
  if(summary.neighbor_sample().empty())
    return "";
  const double median = percentile(summary.neighbor_sample(), 0.5);
  if(median >= double(m.good_neighbors))
    return "";
  const std::string invalid = summary.too_few() == 0 ? std::string()
                              : cat("; ", plural(summary.too_few(), "point"), summary.too_few() == 1 ? " has " : " have ",
                                    fewer_than_least(m, scale), " and ", summary.too_few() == 1 ? "is" : "are",
                                    " invalid (too_few_neighbors)");
  const std::string too_small = too_small_input(m, input, summary);
  if(!too_small.empty())
    return too_small + invalid;
  return cat("the median neighbourhood holds ", plural(std::size_t(median), "point"), ", fewer than the ", m.good_neighbors,
             " from which ", m.name, "'s errors stay within twice those at 40 neighbours (measured, see the "
             "manual)", invalid, ". For about 40 neighbours, try ", suggested_scale(m, scale, median));
}

// Why no point got a valid estimate (exit status 3): the most frequent status, what causes
// it, and what to try.
std::string no_valid_estimate_reason(const Method& m, const Scale& scale, const Row_summary& summary,
                                     const std::string& input, bool normals_estimated)
{
  typedef CGAL::Curvature_estimate_status Status;
  int status = -1;
  std::size_t count = 0, n = 0;
  for(const auto& s : summary.invalid())
  {
    n += s.second;
    if(s.second > count)
    {
      status = s.first;
      count = s.second;
    }
  }
  const std::string what = cat(count == n ? (n == 1 ? std::string("the only point is ") : cat("all ", n, " points are "))
                                          : cat(count, " of the ", n, count == 1 ? " points is " : " points are "),
                               CGAL::to_string(static_cast<Status>(status)));
  std::string why;
  switch(static_cast<Status>(status))
  {
    case Status::TOO_FEW_NEIGHBORS:
    {
      const std::string too_small = too_small_input(m, input, summary);
      if(!too_small.empty())
        why = too_small + " (--min-neighbors lowers the least count of a valid estimate, at a cost in accuracy)";
      else if(!summary.neighbor_sample().empty())
      {
        const double median = percentile(summary.neighbor_sample(), 0.5);
        why = cat("the median neighbourhood holds ", plural(std::size_t(median), "point"), ": ",
                  fewer_than_least(m, scale), ", the least count of a valid ", m.name,
                  " estimate; for about 40 neighbours, try ", suggested_scale(m, scale, median));
      }
      break;
    }
    case Status::DEGENERATE_FIT:
      why = "coincident neighbours, neighbours along one line (a single scan line), or a radius far larger than "
            "the cloud; --radius 3.5x gives about 40 neighbours";
      break;
    case Status::NON_FINITE_POINT:
      why = "NaN or infinite coordinates";
      break;
    case Status::INVALID_NORMAL:
      why = normals_estimated ? "no normal could be estimated (too few points, coincident points, or points along "
                                "one line: try a larger --normal-neighbors)"
                              : "the normals are zero, not finite or far from unit length (are the columns right? "
                                "see --columns)";
      break;
    case Status::TWO_SHEETS:
      why = "two layers with opposite normals in every neighbourhood (a thin plate, or neighbourhoods reaching "
            "across the object): try a smaller --radius or --neighbors";
      break;
    default:
      break;
  }
  return cat("no valid estimate: ", what, why.empty() ? std::string() : ": " + why);
}

// Row i of the output from the point set and its estimates (without colour).
void estimate_row(const Point_set& ps, const Estimates& estimates, std::size_t i, Output_row& r)
{
  const Point& p = ps.point(*(ps.begin() + i));
  const Estimate& e = estimates[i];
  const double v[output_value_count] = {p.x(), p.y(), p.z(), e.normal.x(), e.normal.y(), e.normal.z(),
                                        e.min_curvature, e.max_curvature, e.mean_curvature, e.gaussian_curvature,
                                        e.min_direction.x(), e.min_direction.y(), e.min_direction.z(),
                                        e.max_direction.x(), e.max_direction.y(), e.max_direction.z(),
                                        e.normal_coherence, e.mean_curvature_error};
  std::copy(v, v + output_value_count, r.value);
  r.neighbors = static_cast<std::int32_t>(std::min<std::size_t>(e.neighbor_count, INT32_MAX));
  r.valid = e.is_valid() ? 1 : 0;
  r.status = static_cast<int>(e.status);
}

// A point set of the given points and normals (none if `normals` is empty).
void fill_point_set(Point_set& ps, const std::vector<double>& xyz, const std::vector<double>& normals)
{
  const std::size_t n = xyz.size() / 3;
  ps.reserve(n);
  if(!normals.empty())
    ps.add_normal_map();
  for(std::size_t i = 0; i < n; ++i)
  {
    const double* p = &xyz[3 * i];
    const auto it = ps.insert(Point(p[0], p[1], p[2]));
    if(!normals.empty())
    {
      const double* nv = &normals[3 * i];
      ps.normal(*it) = Vector(nv[0], nv[1], nv[2]);
    }
  }
}

// What the writing and the report share between in-memory and tiled runs.
struct Run_context
{
  const Options& o;
  Progress_bar& progress;
  std::vector<std::string>& warnings;
  std::chrono::steady_clock::time_point start;
};

// "aso (robust variant)": the method and its options, for the summary and the output's header.
std::string method_label(const Options& o, const Scale& scale)
{
  if(std::string(o.method->name) != "aso")
    return o.method->name;
  return cat("aso (", scale.variant == CGAL::Aso_variant::PAPER ? "paper's variant" : "robust variant",
             scale.position_fit_blend > 0 ? cat(", blended with a position fit, weight ", scale.position_fit_blend)
                                          : std::string(),
             ")");
}

// The scale and estimator options of the run: the command line's, with the position fit
// blended into the robust ASO by default when the normals are estimated (--position-blend;
// --variant paper stays the paper's estimator unless asked).
Scale estimation_scale(const Options& o, bool normals_estimated)
{
  Scale s = o.scale;
  const bool robust = s.variant == CGAL::Aso_variant::ROBUST;
  s.position_fit_blend = o.position_blend >= 0 ? o.position_blend : normals_estimated && robust ? 0.5 : 0.0;
  return s;
}

// The output's format, columns and header comments, with colours by `color_quantity` (-1:
// none) over +-color_range.
Output_layout output_layout(const Options& o, const Scale& scale, const std::vector<Attribute>& attributes,
                            int color_quantity, double color_range)
{
  Output_layout layout;
  layout.format = lower_extension(o.output) == ".csv" ? Output_layout::CSV
                  : o.ascii                           ? Output_layout::ASCII_PLY
                                                      : Output_layout::BINARY_PLY;
  layout.comments.push_back(cat("point_set_curvatures method ", method_label(o, scale), ", ", scale_description(scale)));
  layout.comments.push_back(cat("input ", o.input));
  if(color_quantity >= 0)
    layout.comments.push_back(
      cat("colors: ", o.color, ", blue -", color_range, " white 0 red +", color_range, ", grey invalid"));
  layout.fields = output_fields(o.fields, o.float32, color_quantity >= 0, attributes, scale.automatic_largest > 0);
  layout.attributes = &attributes;
  layout.scalar_prefix = o.ply_scalar_names;
  if(!attributes.empty())
  {
    std::string kept;
    for(const Attribute& a : attributes)
      kept += (kept.empty() ? "" : " ") + a.name;
    layout.comments.push_back(cat("input attributes: ", kept));
  }
  return layout;
}

// "binary PLY of 20000 points": the output, for messages.
std::string output_description(const Output_layout& layout, std::size_t n)
{
  return cat(layout.format == Output_layout::CSV ? "CSV" : layout.format == Output_layout::ASCII_PLY ? "ASCII PLY" : "binary PLY",
             " of ", plural(n, "point"), ", ", plural(layout.fields.size(), "field"));
}

// Reserves the output's size before the estimation (Temporary_output::reserve): the layout of
// write_output() with the scale and colour range still unknown (a margin for the header
// comments that hold them).
// A LAS output (`las` not null) has its size from write_las.h.
void reserve_output(const Options& o, Temporary_output& output, const std::vector<Attribute>& attributes,
                    std::size_t n, const Las_output_options* las)
{
  if(las)
  {
    const std::vector<Output_field> fields = output_fields(o.fields, o.float32, false, attributes, o.scale.automatic_largest > 0);
    output.reserve(las_output_size(*las, fields, attributes, n),
                   cat("LAS of ", plural(n, "point"), ", ", plural(fields.size(), "field")));
    return;
  }
  const Output_layout layout =
    output_layout(o, o.scale, attributes, o.color.empty() ? -1 : color_quantities().at(o.color), 0.0);
  output.reserve(output_size_bound(layout, n) + 1024, output_description(layout, n));
}

// Writes the n rows of `rows` (asked for in input order), coloured from the summary; a LAS
// output when `las` is not null.
void write_output(const Run_context& c, Temporary_output& output, const Scale& scale,
                  const std::vector<Attribute>& attributes, std::size_t n, const Row_summary& summary,
                  const Row_source& rows, const Las_output_options* las)
{
  const Options& o = c.o;
  if(las)
  {
    // LAS 1.4, the estimates as extra bytes (write_las.h); no colours (refused in run());
    // the temporary file is created now, when writing starts
    const std::vector<Output_field> fields = output_fields(o.fields, o.float32, false, attributes, o.scale.automatic_largest > 0);
    std::FILE* file = output.open(las_output_size(*las, fields, attributes, n),
                                  cat("LAS of ", plural(n, "point"), ", ", plural(fields.size(), "field")));
    const std::vector<std::string> w = write_las(file, *las, fields, attributes, n, rows, c.progress.phase("writing"));
    c.warnings.insert(c.warnings.end(), w.begin(), w.end());
    c.progress.finish();
    if(interrupted)
      throw Cancelled();
    output.commit();
    return;
  }
  int color_quantity = -1;
  double color_range = 0;
  if(!o.color.empty())
  {
    color_quantity = color_quantities().at(o.color);
    if(summary.count(color_quantity) == 0)
      c.warnings.push_back(cat("--color ", o.color, ": no valid value (not estimated by method ", o.method->name,
                               "?); every point is grey"));
    color_range = summary.color_range(color_quantity);
  }
  const Output_layout layout = output_layout(o, scale, attributes, color_quantity, color_range);
  // the temporary file is created now, when writing starts
  std::FILE* file = output.open(output_size_bound(layout, n), output_description(layout, n));
  write_point_cloud(file, layout, n, [&](std::size_t i, Output_row& r) {
    rows(i, r);
    if(color_quantity >= 0)
    {
      const std::array<unsigned char, 3> rgb =
        diverging_color(r.valid ? r.value[6 + color_quantity] : std::nan(""), color_range);
      std::copy(rgb.begin(), rgb.end(), r.color);
    }
  }, c.progress.phase("writing"));
  c.progress.finish();
  if(interrupted)
    throw Cancelled();
  output.commit();
}

// The warnings and the summary (not with --quiet).
void print_summary(const Run_context& c, const Scale& scale, std::size_t n, const std::string& estimated_normals,
                   const Row_summary& summary, const std::string& times, const std::string& tiles)
{
  const Options& o = c.o;
  if(o.quiet)
    return;
  for(const std::string& w : c.warnings)
    std::fprintf(stderr, "%s: warning: %s\n", program, w.c_str());
  std::string why;
  for(const auto& s : summary.invalid())
    why += cat(why.empty() ? "; " : ", ", s.second, " ",
               CGAL::to_string(static_cast<CGAL::Curvature_estimate_status>(s.first)));
  const std::size_t valid = summary.valid();
  std::printf("%s: %s -> %s\n", program, o.input.c_str(), o.output.c_str());
  std::printf("  method      %s: %s\n", method_label(o, scale).c_str(), o.method->description);
  std::printf("  scale       %s\n", scale_description(scale).c_str());
  std::printf("  points      %zu%s\n", n, estimated_normals.empty() ? "" : " (normals estimated)");
  if(!estimated_normals.empty())
    std::printf("  normals     %s\n", estimated_normals.c_str());
  if(!tiles.empty())
    std::printf("  tiles       %s\n", tiles.c_str());
  std::printf("  valid       %zu (%.2f %%)%s\n", valid, 100.0 * double(valid) / double(n), why.c_str());
  std::printf("  neighbours  %.2f on average (valid estimates)\n",
              valid ? double(summary.neighbors()) / double(valid) : 0.0);
  std::printf("  time        %s s: %s\n", s3(seconds_since(c.start)).c_str(), times.c_str());
  std::printf("  H (mean)    %s\n", min_median_max(summary, 2).c_str());
  std::printf("  K (Gauss)   %s\n", min_median_max(summary, 3).c_str());
}

// The report on standard output, and the warnings (after the output is written, so that a
// failure prints one line only). Throws No_valid_estimate, after them, when no point got a
// valid estimate (exit status 3).
void print_report(const Run_context& c, const Scale& scale, std::size_t n, const std::string& estimated_normals,
                  const Row_summary& summary, const std::string& times, const std::string& tiles)
{
  const Options& o = c.o;
  const bool none_valid = n > 0 && summary.valid() == 0;
  const std::string small = none_valid ? std::string() : small_neighborhood_warning(*o.method, scale, summary, o.input);
  if(!small.empty())
    c.warnings.push_back(small);
  print_summary(c, scale, n, estimated_normals, summary, times, tiles);
  if(none_valid)
    throw No_valid_estimate(cat(no_valid_estimate_reason(*o.method, scale, summary, o.input, !estimated_normals.empty()),
                                "; ", in_quotes(o.output), " was written, every row invalid"));
}

// The physical memory of the machine, in bytes (0 if unknown).
double physical_memory()
{
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

// More tiles than this: the memory limit is said to be too small (--memory-limit 1K on 1000
// points: 570 tiles, 14 times as long as 8 tiles at 200K).
const std::size_t many_tiles = 500;

// "190K": a --memory-limit of at least `bytes`, two significant digits.
std::string memory_argument(double bytes)
{
  const char* units = "KMGT";
  double v = bytes / 1024;
  int u = 0;
  while(v >= 1000 && u < 3)
  {
    v /= 1024;
    ++u;
  }
  const double step = v >= 100 ? 10 : v >= 10 ? 1 : 0.1;
  v = std::ceil(v / step - 1e-9) * step;
  char text[64];
  std::snprintf(text, sizeof text, step < 1 ? "%.1f%c" : "%.0f%c", std::max(v, 0.1), units[u]);
  return text;
}

// The run on an input that does not fit in the memory limit: estimated in tiles
// (tiled_run.h), bitwise as in memory.
int run_tiled_input(const Run_context& c, Temporary_output& output, const Read_options& read_options,
                    const Scanned_input& input, double memory_limit, const Orientation_choice& orientation,
                    const Las_output_options* las)
{
  const double count_seconds = seconds_since(c.start);
  const Options& o = c.o;
  const std::size_t n = std::size_t(input.points);
  const std::string too_large = cat(in_quotes(o.input), " holds ", n, " points, more than fit in the memory limit (",
                                    memory_limit / (1 << 20), " MB, --memory-limit)");
  // Without normals, each tile estimates those of the points its curvatures need: the points
  // within the curvature halo H of its core, whose own neighbours lie within H + normal_halo.
  const bool with_normals = input.cloud.has_normals();
  if(!with_normals)
  {
    if(o.require_normals)
      throw Error(cat(in_quotes(o.input), " has no normals (nx ny nz) and --require-normals was given"));
    if(orientation.orientation.kind == CGAL::Normal_orientation::MINIMUM_SPANNING_TREE ||
       orientation.orientation.kind == CGAL::Normal_orientation::AUTOMATIC)
      throw Error(cat(too_large, " and has no normals: they are estimated tile by tile, which needs a local "
                      "orientation, --orient +z (airborne scans), another axis, or viewpoint:X,Y,Z (a spanning "
                      "tree, which --orient auto uses here, spans the whole cloud); or raise --memory-limit"));
    c.warnings.push_back(cat(in_quotes(o.input), " has no normals: estimating them (", normal_fit_description(o),
                             ", oriented ", orientation.text, "); a wrong orientation flips the sign of the "
                             "curvatures"));
  }
  if(!o.scale.by_count && o.scale.spacing_multiple > 0)
    throw Error(cat(too_large, ": --radius ", o.scale.spacing_multiple, "x needs the whole cloud for the average "
                    "spacing; give the radius as a length, or raise --memory-limit"));
  if(std::string(o.method->name) == "vcm")
    throw Error(cat(too_large, ": --method vcm needs the whole cloud (its Voronoi cells come from the Delaunay "
                    "triangulation of every point); raise --memory-limit"));
  const Scale scale = estimation_scale(o, !with_normals);
  reserve_output(o, output, o.drop_attributes && !las ? std::vector<Attribute>() : input.cloud.attributes, n, las);
  Tiling tiling;
  tiling.memory_limit = memory_limit;
  if(scale.by_count)
    tiling.neighbors = scale.reach_neighbors();
  else
    tiling.halo = 2 * scale.radius;  // the reach of the sample weights' areas
  tiling.temporary_prefix = temporary_prefix(o.output);
  tiling.phase = [&c](const std::string& name) { return c.progress.phase(name); };
  tiling.interrupted = []() { return interrupted != 0; };
  // a limit making many tiles is said at once on a terminal (the run may be long), else with
  // the other warnings at the end
  const auto slow_tiling = [&](const char* makes, std::size_t tiles, std::size_t few_grid, double few_points) {
    return cat("--memory-limit ", size_text(memory_limit), makes, tiles, " tiles, each read again from the input "
               "with its halo: slow; --memory-limit ",
               memory_argument(few_points * bytes_per_point(input.cloud.attributes.size())), " gives at most ",
               plural(few_grid, "tile"));
  };
  bool slow_tiling_said = false;
  tiling.grid_chosen = [&](std::size_t tiles, std::size_t few_grid, double few_points) {
    if(tiles > many_tiles)
      slow_tiling_said =
        c.progress.note(cat(program, ": warning: ", slow_tiling(" makes up to ", tiles, few_grid, few_points),
                            " (Ctrl-C to stop)"));
  };
  // Without normals, a tile's halo H is shared by two needs: the curvatures of its own points
  // read the points within the curvature halo h of its core (guessed from the density by
  // count, then grown to what the estimator asks for), and their normals are those of the
  // "normal tile" whose core is the core grown by h on every side, whose own points need
  // their neighbours within the normal halo of that box. The tiles are read with a halo along
  // each axis (Tiling::box_halo), which holds both when H >= h + normal halo: the normals are
  // given H - h (the largest the range supports), and when they need more, H grows to h plus
  // what they need. Sums are rounded up and differences down, so that a halo said to
  // suffice does.
  const double inf = std::numeric_limits<double>::infinity();
  auto normal_share = [inf](double H, double h) { return std::nextafter(H - h, -inf); };
  auto total_halo = [inf](double h, double normal) { return std::nextafter(h + normal, inf); };
  const double normal_halo_guess = with_normals ? 0.0 : density_halo(input, normal_reach_neighbors(o));
  const double curvature_halo_guess = scale.by_count ? density_halo(input, scale.reach_neighbors()) : tiling.halo;
  tiling.extra_halo = normal_halo_guess;
  tiling.box_halo = !with_normals;
  // the current tile's curvature halo (grown over the retries of a tile)
  double curvature_halo = curvature_halo_guess;
  CGAL::Bbox_3 last_core;

  const Tile_estimator estimate = [&](Tile_points& points, const PSC::Tile& tile,
                                      const Progress& progress) -> Row_source {
    auto ps = std::make_shared<Point_set>();
    fill_point_set(*ps, points.xyz, points.normals);
    std::vector<double>().swap(points.xyz);
    std::vector<double>().swap(points.normals);
    std::shared_ptr<Estimates> estimates;
    if(!(tile.core == last_core))
      curvature_halo = curvature_halo_guess;  // a new tile
    last_core = tile.core;
    const double H = tile.halo;  // infinite: the range is the whole cloud
    if(with_normals || H == inf)
      curvature_halo = H;
    for(;;)
    {
      if(!with_normals)
      {
        // the normals of the points within the curvature halo of the core
        const double h = curvature_halo, normal_halo = H == inf ? inf : normal_share(H, h);
        if(!(normal_halo >= 0))
          throw PSC::Halo_too_small(total_halo(h, normal_halo_guess), H);
        const CGAL::Bbox_3& b = tile.core;
        const PSC::Tile normal_tile(CGAL::Bbox_3(b.xmin() - h, b.ymin() - h, b.zmin() - h, b.xmax() + h,
                                                 b.ymax() + h, b.zmax() + h),
                                    normal_halo);
        if(!ps->has_normal_map())
          ps->add_normal_map();
        try
        {
          CGAL::estimate_oriented_normals<CGAL::Parallel_tag>(
            *ps, PSC::parameters::neighbor_count(
                   normal_neighbor_count(o),
                   PSC::parameters::automatic_scale(normal_automatic_largest(o), PSC::parameters::normal_fit(
                     o.normal_fit, PSC::parameters::normal_orientation(
                                     orientation.orientation,
                                     PSC::parameters::tile(normal_tile, CGAL::parameters::callback(progress)))))));
        }
        catch(const PSC::Halo_too_small& e)
        {
          throw PSC::Halo_too_small(total_halo(h, e.required_halo()), H);
        }
        if(interrupted)
          throw Cancelled();
        if(orientation.scanner)
        {
          const std::array<int, 3> pulse = pulse_attributes(input.cloud.attributes);
          orient_towards_scanner(
            ps->size(), [&ps](std::size_t i) -> Vector& { return ps->normal(*(ps->begin() + i)); },
            [&](std::size_t i) {
              return std::array<double, 3>{{points.attributes[pulse[0]][i], points.attributes[pulse[1]][i],
                                            points.attributes[pulse[2]][i]}};
            });
        }
      }
      try
      {
        estimates = std::make_shared<Estimates>(
          o.method->run(*ps, scale, progress, PSC::Tile(tile.core, curvature_halo)));
        break;
      }
      catch(const PSC::Halo_too_small& e)
      {
        if(with_normals)
          throw;
        const double normal_halo = normal_share(H, curvature_halo);
        curvature_halo = e.required_halo();
        // the range may hold the larger curvature halo and the normals' share: estimate again
        if(total_halo(curvature_halo, normal_halo_guess) <= H)
          continue;
        throw PSC::Halo_too_small(total_halo(curvature_halo, std::max(normal_halo, normal_halo_guess)), H);
      }
      catch(const std::invalid_argument& e)
      {
        throw Error(cat(e.what(), " (", too_large, ", so it is estimated in tiles: give --radius, or raise "
                        "--memory-limit)"));
      }
    }
    if(interrupted)
      throw Cancelled();
    return [ps, estimates](std::size_t k, Output_row& r) { estimate_row(*ps, *estimates, k, r); };
  };
  Row_summary summary(n, static_cast<int>(CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS));
  double write_seconds = 0;
  const Tiled_report report = run_tiled(
    o.input, read_options, input, tiling, estimate,
    [&summary](std::size_t i, const Output_row& r) { summary.add(i, r); },
    [&](const Row_source& rows) {
      const auto write_start = std::chrono::steady_clock::now();
      write_output(c, output, scale,
                   o.drop_attributes && !las ? std::vector<Attribute>() : input.cloud.attributes, n, summary, rows,
                   las);
      write_seconds = seconds_since(write_start);
    });
  if(!with_normals)
  {
    std::size_t without = 0;
    for(const auto& s : summary.invalid())
      if(s.first == int(CGAL::Curvature_estimate_status::INVALID_NORMAL) ||
         s.first == int(CGAL::Curvature_estimate_status::NON_FINITE_POINT))
        without += s.second;
    if(without > 0)
      c.warnings.push_back(cat(without, " points got no normal (coincident neighbours, neighbours along one line "
                               "such as a single scan line: try a larger --normal-neighbors; non-finite "
                               "coordinates) and are invalid_normal"));
  }
  if(report.tiles > many_tiles && !slow_tiling_said)
    c.warnings.push_back(slow_tiling(" makes ", report.tiles, report.few_tiles_grid, report.few_tiles_points));
  print_report(c, scale, n,
               with_normals ? std::string() : cat(normal_fit_description(o), ", oriented ", orientation.text), summary,
               cat("count ", s3(count_seconds), ", density ", s3(report.density_seconds), ", tile reads ",
                   s3(report.read_seconds), ", curvatures ", s3(report.estimate_seconds), ", tile rows ",
                   s3(report.rows_seconds),
                   ", merge and write ", s3(write_seconds)),
               cat(report.tiles, " (memory limit ", memory_limit / (1 << 20), " MB; at most ", report.largest_range,
                   " points with a halo of ", report.halo, report.halo_growths
                     ? cat("; ", report.halo_growths, " tiles read again with a larger halo") : std::string(), ")"));
  return 0;
}

int run(const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const std::string out_ext = lower_extension(o.output);
  if(out_ext != ".ply" && out_ext != ".csv" && out_ext != ".las")
    throw Error(cat("unsupported output format ", in_quotes(out_ext.empty() ? o.output : out_ext),
                    " for ", in_quotes(o.output), " (expected .ply, .csv or .las)"));
  const bool las_output = out_ext == ".las";
  if(las_output && !o.color.empty())
    throw Error(cat("--color ", o.color, ": a .las output holds no colours of the estimates (LAS viewers colour by "
                    "a field: choose ", o.color, "); drop --color, or write .ply"));
  if(las_output && o.ascii)
    throw Error("--ascii: a .las output is binary; drop --ascii, or write .ply or .csv");
  {
    struct stat in, out;
    if(::stat(o.input.c_str(), &in) == 0 && ::stat(o.output.c_str(), &out) == 0 && in.st_dev == out.st_dev &&
       in.st_ino == out.st_ino)
      throw Error(cat("the output ", in_quotes(o.output), " is the input file: choose another output"));
  }

  std::unique_ptr<tbb::global_control> threads;
  if(o.threads > 0)
    threads.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                          static_cast<std::size_t>(o.threads)));

  // An unwritable OUTPUT fails before any long computation; its size is reserved once the
  // input is read, and its file created when writing starts.
  check_output_path(o.output);
  Temporary_output output(o.output);
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  // beyond a file size limit (ulimit -f), a write or a reservation fails with EFBIG, which
  // is reported, instead of killing the process
  std::signal(SIGXFSZ, SIG_IGN);
  if(const std::size_t stale = remove_stale_temporaries(o.output))
    if(!o.quiet)
      std::fprintf(stderr, "%s: note: removed %s of earlier runs writing %s that were killed (%s*)\n", program,
                   plural(stale, "temporary file").c_str(), in_quotes(o.output).c_str(),
                   hidden_sibling(o.output, ".tmp-").c_str());
  Progress_bar progress(!o.quiet && ::isatty(STDERR_FILENO));
  auto check_interrupted = [&]() {
    if(interrupted)
      throw Cancelled();
  };
  // Warnings are printed once the output is written, so that a failure prints one line only.
  std::vector<std::string> warnings;
  auto warn = [&](const std::string& message) { warnings.push_back(message); };
  const Run_context context{o, progress, warnings, start};

  // 1. Read, or count the points of a file too large for the memory limit.
  const double memory_limit = o.memory_limit > 0 ? o.memory_limit : 0.25 * physical_memory();
  if(o.memory_limit > physical_memory() && physical_memory() > 0)
    warn(cat("--memory-limit ", size_text(o.memory_limit), " exceeds this machine's memory (", size_text(physical_memory()),
             " of RAM): inputs up to that size are read whole and may be swapped out; give at most the RAM, or "
             "omit --memory-limit for a quarter of it"));
  Read_options read_options;
  read_options.columns = o.columns;
  const bool las = lower_extension(o.input) == ".las";
  // the pulses of --orient scanner, or of --orient auto on a LAS file
  read_options.keep_attributes =
    !o.drop_attributes || o.orient_scanner || (las && o.orientation_text == "auto") || las_output;
  read_options.allow_truncated = o.allow_truncated;
  read_options.progress = progress.phase("reading");
  Scanned_input input = read_or_scan(o.input, read_options, memory_limit > 0 ? memory_limit : HUGE_VAL);
  for(const std::string& w : input.cloud.warnings)
    warn(w);
  const std::array<int, 3> pulse = pulse_attributes(input.cloud.attributes);
  if(o.orient_scanner && !input.cloud.has_normals() && *std::min_element(pulse.begin(), pulse.end()) < 0)
    throw Error(cat("--orient scanner: ", in_quotes(o.input), " holds no pulse directions (the wave packets of LAS point "
                    "formats 4, 5, 9 and 10); use --orient +z (airborne scans) or viewpoint:X,Y,Z"));
  const bool has_pulses = *std::min_element(pulse.begin(), pulse.end()) >= 0;
  Orientation_choice orientation = choose_orientation(o, las, has_pulses);
  // a LAS output: the input's LAS header and records, the bounds of its points (the same in
  // tiles as in memory)
  Las_output_options las_options;
  las_options.source = input.cloud.las;
  las_options.input_path = o.input;
  las_options.drop_attributes = o.drop_attributes;
  for(int a = 0; a < 3; ++a)
  {
    las_options.lo[a] = input.lo[a];
    las_options.hi[a] = input.hi[a];
  }
  const Las_output_options* las_out = las_output ? &las_options : nullptr;
  if(!input.fits)
  {
    read_options.progress = Progress();
    return run_tiled_input(context, output, read_options, input, memory_limit, orientation, las_out);
  }
  Point_set ps;
  const std::vector<Attribute> attributes = std::move(input.cloud.attributes);  // written after the estimates
  const std::vector<Attribute> no_attributes;
  const bool had_normals = input.cloud.has_normals();
  fill_point_set(ps, input.cloud.xyz, input.cloud.normals);
  input.cloud = Point_cloud();
  reserve_output(o, output, o.drop_attributes && !las_output ? no_attributes : attributes, ps.size(), las_out);
  const double read_seconds = seconds_since(start);
  check_interrupted();

  // 2. Normals, if the file has none.
  if(!had_normals)
  {
    if(o.require_normals)
      throw Error(cat(in_quotes(o.input), " has no normals (nx ny nz) and --require-normals was given"));
    const std::size_t without = estimate_normals(ps, o, orientation, progress.phase("normals"));
    progress.finish();
    warn(cat(in_quotes(o.input), " has no normals: estimating them (", normal_fit_description(o), ", oriented ",
             orientation.text, "); a wrong orientation flips the sign of the curvatures"));
    if(without > 0)
      warn(cat(without, " points got no normal (coincident neighbours, neighbours along one line such as a single "
               "scan line: try a larger --normal-neighbors; non-finite coordinates) and are invalid_normal"));
    if(orientation.scanner)
    {
      const std::size_t undirected = orient_towards_scanner(
        ps.size(), [&ps](std::size_t i) -> Vector& { return ps.normal(*(ps.begin() + i)); },
        [&](std::size_t i) {
          return std::array<double, 3>{{attributes[pulse[0]].values[i], attributes[pulse[1]].values[i],
                                        attributes[pulse[2]].values[i]}};
        });
      if(undirected > 0)
        warn(cat("--orient scanner: ", undirected, " points have no pulse direction and keep normals oriented to +z"));
    }
  }
  const double normals_seconds = seconds_since(start) - read_seconds;
  check_interrupted();

  // 3. Average spacing, for --radius Nx.
  Scale scale = estimation_scale(o, !had_normals);
  const auto spacing_start = std::chrono::steady_clock::now();
  if(!scale.by_count && scale.spacing_multiple > 0)
  {
    const std::vector<Point_set::Index> indices = finite_points(ps);
    if(indices.size() < 7)
      throw Error(cat("--radius ", scale.spacing_multiple, "x: ", in_quotes(o.input),
                      " has fewer than 7 points, too few for an average spacing"));
    scale.spacing = average_spacing(ps, progress.phase("spacing"));
    check_interrupted();
    scale.radius = scale.spacing_multiple * scale.spacing;
    if(!(scale.radius > 0) || !std::isfinite(scale.radius))
      throw Error(cat("--radius ", scale.spacing_multiple, "x: the average spacing of ",
                      in_quotes(o.input), " is ", scale.spacing, " (coincident points?)"));
  }
  const double spacing_seconds = seconds_since(spacing_start);

  // 4. Curvatures.
  const auto estimation_start = std::chrono::steady_clock::now();
  const Estimates estimates = o.method->run(ps, scale, progress.phase("curvatures"), PSC::Tile::whole_space());
  const double estimation_seconds = seconds_since(estimation_start);
  check_interrupted();

  // 5. Write.
  const auto write_start = std::chrono::steady_clock::now();
  Row_summary summary(ps.size(), static_cast<int>(CGAL::Curvature_estimate_status::TOO_FEW_NEIGHBORS));
  {
    Output_row r;
    for(std::size_t i = 0; i < ps.size(); ++i)
    {
      estimate_row(ps, estimates, i, r);
      summary.add(i, r);
    }
  }
  write_output(context, output, scale, o.drop_attributes && !las_output ? no_attributes : attributes, ps.size(),
               summary, [&](std::size_t i, Output_row& r) { estimate_row(ps, estimates, i, r); }, las_out);
  const double write_seconds = seconds_since(write_start);
  print_report(context, scale, ps.size(),
               had_normals ? std::string() : cat(normal_fit_description(o), ", oriented ", orientation.text), summary,
               cat("read ", s3(read_seconds), ", normals ", s3(normals_seconds), ", spacing ", s3(spacing_seconds),
                   ", curvatures ", s3(estimation_seconds), ", write ", s3(write_seconds)),
               "");
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse_command_line(argc, argv);
    if(options.help)
    {
      print_usage(std::cout);
      return 0;
    }
    return run(options);
  }
  catch(const Cancelled&)
  {
    // the temporary output was removed when the stack unwound
    std::fprintf(stderr, "\n%s: interrupted (%s), nothing written\n", program, current_phase.c_str());
    return 128 + interrupt_signal;  // 130 for SIGINT, 143 for SIGTERM
  }
  catch(const Error& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  }
  catch(const No_valid_estimate& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 3;
  }
  catch(const std::invalid_argument& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return 2;
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "%s: internal error: %s\n", program, e.what());
    return 1;
  }
}
