// Copyright (c) 2026 The Point_set_curvatures authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// See output_file.h.

#include "output_file.h"

#include "interruption.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace psc_tool {

namespace {

// The folder of a path ("." for a bare name).
std::string folder_of(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
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

}  // namespace

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

std::string temporary_prefix(const std::string& output)
{
  return hidden_sibling(output, cat(".tmp-", ::getpid(), "-"));
}

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
    throw Error(cat("cannot write output ", in_quotes(output), ": its folder ", in_quotes(folder), " is not writable (",
                    std::strerror(errno), "); choose another OUTPUT or change its permissions"));
}

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

Temporary_output::~Temporary_output()
{
  discard();
  release();
}

void Temporary_output::reserve(std::uint64_t bytes, const std::string& what)
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

std::FILE* Temporary_output::open(std::uint64_t bytes, const std::string& what)
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

void Temporary_output::commit()
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

void Temporary_output::discard()
{
  if(m_file)
    std::fclose(m_file);
  m_file = nullptr;
  temporary_output_path[0] = '\0';
  if(!m_path.empty())
    std::remove(m_path.c_str());
  m_path.clear();
}

int Temporary_output::create(std::string& path)
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

void Temporary_output::release()
{
  if(m_reserved >= 0)
    ::close(m_reserved);
  m_reserved = -1;
}

Error Temporary_output::reservation_error(int e, std::uint64_t bytes, const std::string& what) const
{
  const std::string needs = cat(size_text(double(bytes)), " (", what, ")");
  if(e == ENOSPC)
  {
    struct statvfs v;
    const std::string free_space =
      ::statvfs(folder_of(m_output).c_str(), &v) == 0
        ? cat(", the file system holding it has ", size_text(double(v.f_bavail) * double(v.f_frsize)), " free")
        : std::string();
    return Error(cat("not enough space for output ", in_quotes(m_output), ": it needs up to ", needs, free_space,
                     "; free some space or write OUTPUT elsewhere"));
  }
  if(e == EDQUOT)
    return Error(cat("output ", in_quotes(m_output), " needs up to ", needs,
                     ", beyond your disk quota; free some space or write OUTPUT elsewhere"));
  if(e == EFBIG)
    return Error(cat("output ", in_quotes(m_output), " needs up to ", needs,
                     ", more than the largest file allowed "
                     "(the shell's file size limit, ulimit -f, or the file system's); raise the limit or write "
                     "OUTPUT elsewhere"));
  return Error(cat("cannot reserve ", needs, " for output ", in_quotes(m_output), ": ", std::strerror(e)));
}

}  // namespace psc_tool
