// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the readers share: the file read in blocks with progress (Byte_source), text
// lines on it (Line_source), and the parsing of words, numbers and counts. Internal to the
// readers (read_point_cloud.cpp, read_ply.cpp).

#ifndef PSC_IO_INPUT_BYTES_H
#define PSC_IO_INPUT_BYTES_H

#include "psc_io/read_point_cloud.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace psc_tool {
namespace input {

// ---------------------------------------------------------------------------------------
// Bytes and lines

// The file, read in blocks into a buffer that holds at least what the parser asks for.
// Progress: the fraction of the file consumed, reported at least every 1% and every 16 MB.
class Byte_source
{
public:
  Byte_source(const std::string& path, std::uint64_t size, const Progress& progress)
      : m_size(size), m_progress(progress)
  {
    m_file = std::fopen(path.c_str(), "rb");
    if(!m_file)
      throw Error(cat("cannot open input ", in_quotes(path), ": ", std::strerror(errno)));
    m_step = std::max<std::uint64_t>(1, std::min<std::uint64_t>(size / 100, 16u << 20));
    m_next_report = m_step;
    // 1 MB blocks, or the whole file if smaller (the buffer grows when a line needs more)
    m_buffer.resize(std::size_t(std::min<std::uint64_t>(1u << 20, std::max<std::uint64_t>(size + 1, 4096))));
  }
  ~Byte_source() { std::fclose(m_file); }
  Byte_source(const Byte_source&) = delete;
  Byte_source& operator=(const Byte_source&) = delete;

  // Buffers at least `n` bytes from the current position if the file has them; returns the
  // number of bytes buffered (fewer than n only at the end of the file).
  std::size_t fill(std::size_t n)
  {
    if(m_end - m_pos >= n || m_eof)
      return m_end - m_pos;
    std::memmove(m_buffer.data(), m_buffer.data() + m_pos, m_end - m_pos);
    m_end -= m_pos;
    m_pos = 0;
    if(m_buffer.size() < n)
      m_buffer.resize(std::max(n, 2 * m_buffer.size()));
    while(m_end < n && !m_eof)
    {
      const std::size_t got = std::fread(m_buffer.data() + m_end, 1, m_buffer.size() - m_end, m_file);
      m_end += got;
      if(got == 0)
      {
        if(std::ferror(m_file))
          throw Error(cat("cannot read input: ", std::strerror(errno)));
        m_eof = true;
      }
    }
    return m_end - m_pos;
  }
  std::size_t buffered() const { return m_end - m_pos; }
  const char* data() const { return m_buffer.data() + m_pos; }
  void advance(std::size_t n)
  {
    m_pos += n;
    m_consumed += n;
    if(m_consumed >= m_next_report)
    {
      m_next_report = m_consumed + m_step;
      if(m_progress && !m_progress(std::min(1.0, double(m_consumed) / double(std::max<std::uint64_t>(m_size, 1)))))
        throw Cancelled();
    }
  }
  // Bytes consumed since the start of the file.
  std::uint64_t consumed() const { return m_consumed; }
  // Bytes of the file after the current position (from its size when opened).
  std::uint64_t remaining() const { return m_size > m_consumed ? m_size - m_consumed : 0; }
  bool at_end() { return fill(1) == 0; }

private:
  std::FILE* m_file = nullptr;
  std::vector<char> m_buffer;
  std::size_t m_pos = 0, m_end = 0;
  bool m_eof = false;
  std::uint64_t m_size = 0, m_consumed = 0, m_step = 1, m_next_report = 1;
  Progress m_progress;
};

// Lines of a Byte_source, without their end of line ("\n" or "\r\n"). A line is valid until
// the next call.
class Line_source
{
public:
  explicit Line_source(Byte_source& bytes) : m_bytes(bytes) {}

  bool next(std::string_view& line)
  {
    std::size_t scanned = 0;
    for(;;)
    {
      const std::size_t available = m_bytes.buffered();
      const char* begin = m_bytes.data();
      const void* nl = std::memchr(begin + scanned, '\n', available - scanned);
      if(nl)
        return take(line, std::size_t(static_cast<const char*>(nl) - begin), 1);
      scanned = available;
      if(m_bytes.fill(available + (1 << 20)) == available)  // end of the file
        return available > 0 && take(line, available, 0);
    }
  }
  std::size_t line_number() const { return m_line_number; }

private:
  // The first `length` buffered bytes are the line, followed by `end` bytes of end of line.
  bool take(std::string_view& line, std::size_t length, std::size_t end)
  {
    line = std::string_view(m_bytes.data(), length);
    if(!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    ++m_line_number;
    m_bytes.advance(length + end);
    return true;
  }

  Byte_source& m_bytes;
  std::size_t m_line_number = 0;
};

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

inline std::string_view trim(std::string_view s)
{
  while(!s.empty() && is_space(s.front()))
    s.remove_prefix(1);
  while(!s.empty() && is_space(s.back()))
    s.remove_suffix(1);
  return s;
}

// Words of a line separated by white space.
inline void split_spaces(std::string_view line, std::vector<std::string_view>& words)
{
  words.clear();
  std::size_t i = 0;
  while(i < line.size())
  {
    while(i < line.size() && is_space(line[i]))
      ++i;
    const std::size_t b = i;
    while(i < line.size() && !is_space(line[i]))
      ++i;
    if(i > b)
      words.push_back(line.substr(b, i - b));
  }
}

// Values of a line of a text point file: separated by commas if the line has one (an empty
// field is kept, as an empty value), else by white space.
inline void split(std::string_view line, std::vector<std::string_view>& values)
{
  if(line.find(',') == std::string_view::npos)
    return split_spaces(line, values);
  values.clear();
  for(;;)
  {
    const std::size_t comma = line.find(',');
    values.push_back(trim(line.substr(0, comma)));
    if(comma == std::string_view::npos)
      return;
    line.remove_prefix(comma + 1);
  }
}

// A decimal number, the whole token (a leading '+' allowed; nan and inf are numbers: such
// points get the status non_finite_point).
inline bool parse_number(std::string_view t, double& v)
{
  const char* b = t.data();
  const char* e = b + t.size();
  if(b != e && *b == '+')
  {
    ++b;
    if(b != e && (*b == '+' || *b == '-'))
      return false;  // "+-1"
  }
  if(b == e)
    return false;
  const std::from_chars_result r = std::from_chars(b, e, v);
  if(r.ptr != e)
    return false;
  if(r.ec == std::errc::result_out_of_range)
  {
    // beyond the range of doubles: 1e400 is infinite (a non-finite point), 1e-400 is 0, as
    // strtod rounds them
    const std::string copy(b, e);
    v = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return r.ec == std::errc();
}

// A count: decimal digits only, below 2^63.
inline bool parse_count(std::string_view t, std::uint64_t& v)
{
  if(t.empty() || t.size() > 18 || t.find_first_not_of("0123456789") != std::string_view::npos)
    return false;
  std::from_chars(t.data(), t.data() + t.size(), v);
  return true;
}

inline std::string quoted(std::string_view t) { return in_quotes(std::string(t.substr(0, 60))); }

// Chunked reading (Read_options::chunk): hands the points held over once there are
// chunk_points of them, or at the end, and keeps the cloud's description.
inline void hand_over(Point_cloud& cloud, const Read_options& options, bool at_end = false)
{
  if(!options.chunk || cloud.size() == 0 || (!at_end && cloud.size() < options.chunk_points))
    return;
  options.chunk(cloud);
  cloud.first += cloud.size();
  cloud.xyz.clear();
  cloud.normals.clear();
  for(Attribute& a : cloud.attributes)
    a.values.clear();
}

// The size of `path`, a regular file; throws Error naming what it is otherwise (missing,
// unreadable, a directory, a pipe or a device).
std::uint64_t regular_file_size(const std::string& path);

// The PLY reader (read_ply.cpp): the file after its first byte.
Point_cloud read_ply(Byte_source& bytes, const std::string& path, const Read_options& options);

// The LAS reader (read_las.cpp).
Point_cloud read_las(Byte_source& bytes, const std::string& path, const Read_options& options);

}  // namespace input
}  // namespace psc_tool

#endif
