#include "image/file_output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace raygate {
namespace {

// Writes all of `bytes` to `fd`, retrying short writes and EINTR; false with errno set.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::string failure(const std::string& path, const std::string& reason) {
  return "cannot write '" + path + "': " + reason;
}

// A device or FIFO named as the output: written through, as a shell redirection would.
bool write_through(const std::string& path, std::string_view bytes, std::string& error) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) {
    error = failure(path, std::strerror(errno));
    return false;
  }
  const bool written = write_all(fd, bytes);
  const int saved = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    error = failure(path, std::strerror(written ? errno : saved));
    return false;
  }
  return true;
}

// "<folder>/.<name>.tmp" for "<folder>/<name>", or with "-<pid>" appended (`with_pid`).
std::string temporary_for(const std::string& path, bool with_pid) {
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return folder + "." + name + ".tmp" + (with_pid ? "-" + std::to_string(::getpid()) : "");
}

// Creates the temporary, exclusively: the fixed name first, so every run executes the same
// instructions (sim mode counts them, and a pid's digits would make two runs differ by a few
// dozen), then a pid-named one if another writer or a crashed run left the fixed one behind.
int open_temporary(const std::string& path, std::string& temporary) {
  for (const bool with_pid : {false, true}) {
    temporary = temporary_for(path, with_pid);
    // 0666 less the umask, as a plain open(O_CREAT) would make it.
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

}  // namespace

bool write_file_replacing(const std::string& path, std::string_view bytes, std::string& error) {
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode)) {
    if (S_ISDIR(existing.st_mode)) {
      error = failure(path, "it is a directory");
      return false;
    }
    return write_through(path, bytes, error);
  }
  std::string temporary;
  const int fd = open_temporary(path, temporary);
  if (fd < 0) {
    error = failure(path, std::strerror(errno));
    return false;
  }
  const bool written = write_all(fd, bytes);
  const int saved = errno;
  const bool closed = ::close(fd) == 0;  // some file systems report a full disk only here
  if (!written || !closed) {
    error = failure(path, std::strerror(written ? errno : saved));
    ::unlink(temporary.c_str());
    return false;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    error = failure(path, std::strerror(errno));
    ::unlink(temporary.c_str());
    return false;
  }
  return true;
}

}  // namespace raygate
