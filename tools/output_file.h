// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The point_set_curvatures tool's output file: checked before the estimation, its size
// reserved on its file system, written under a temporary name and renamed when complete, and
// the temporary files of killed runs removed.

#ifndef POINT_SET_CURVATURES_TOOL_OUTPUT_FILE_H
#define POINT_SET_CURVATURES_TOOL_OUTPUT_FILE_H

#include "psc_io/support.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace psc_tool {

// "120.3 MB": a size for messages.
std::string size_text(double bytes);

// The temporary files of OUTPUT are named ".NAME.tmp-PID-" and six characters of mkstemp
// (the output while it is written) or "tiles-" and six (the rows of a tiled run's tiles,
// unlinked at once): the PID tells the files of a killed run (its process is gone) from
// those of a run still going.
std::string temporary_prefix(const std::string& output);

// Refuses, before any computation, an OUTPUT that cannot be written: a directory, a folder
// that does not exist, is not a directory or is not writable.
void check_output_path(const std::string& output);

// Removes the temporary files that runs writing `output` left when they were killed (SIGKILL,
// a power cut): ".NAME.tmp-PID-..." whose process is gone, and ".NAME.tmp-XXXXXX" of the
// tool's earlier versions. Returns their number.
std::size_t remove_stale_temporaries(const std::string& output);

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

  ~Temporary_output();

  // Reserves `bytes` (the output's size, or an upper bound) for the output; `what` describes
  // it for the message.
  void reserve(std::uint64_t bytes, const std::string& what);

  // Creates the temporary file, `bytes` allocated to it, and returns it for writing.
  std::FILE* open(std::uint64_t bytes, const std::string& what);

  std::FILE* file() { return m_file; }

  // Flushes the file, cuts it where it ends and renames it to OUTPUT.
  void commit();

  // Closes and removes the temporary file, if any.
  void discard();

private:
  // A new temporary file ".NAME.tmp-PID-XXXXXX" with the usual permissions; its name in `path`
  // and in temporary_output_path (removed by a second Ctrl-C).
  int create(std::string& path);

  void release();

  Error reservation_error(int e, std::uint64_t bytes, const std::string& what) const;

  std::string m_output, m_path;
  std::FILE* m_file = nullptr;
  int m_reserved = -1;  // the unlinked file holding the space reserved, until open()
};

}  // namespace psc_tool

#endif
