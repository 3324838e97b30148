#include "core/fs.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace raygate {
namespace {

std::string system_reason() { return std::strerror(errno); }

// Writes all of `content` to fd, retrying short writes; false with errno set on failure.
bool write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t n = ::write(fd, content.data(), content.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    content.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  // A symbolic link at `path` is replaced by the file, never followed: a link planted in a
  // repository or a shared folder cannot send raygate's write anywhere else. Outputs a user
  // names are refused up front when they are links (pipeline/output_failures.h).
  std::error_code ec;
  const std::filesystem::file_status existing = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(existing)) throw WriteError(path, "it is a directory");
  if (std::filesystem::exists(existing) && !std::filesystem::is_regular_file(existing)) {
    throw WriteError(path, "not a regular file (a device, FIFO or socket is never replaced)");
  }
  const std::filesystem::path parent = path.parent_path().empty() ? "." : path.parent_path();
  std::filesystem::create_directories(parent, ec);
  if (ec) {
    throw WriteError(path, "cannot create directory " + parent.string() + ": " + ec.message());
  }

  // A name of 244 bytes or more would make the temporary's too long for the file system (255):
  // that file is written beside it under a short name instead.
  std::string temp_name = ".";
  temp_name += path.filename().string();
  temp_name += ".tmp-XXXXXX";
  if (temp_name.size() > 255) temp_name = ".raygate.tmp-XXXXXX";
  std::string temp = (parent / temp_name).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw WriteError(path, system_reason());
  const bool written = write_all(fd, content) && ::fsync(fd) == 0;
  const std::string reason = written ? "" : system_reason();
  ::close(fd);
  if (!written) {
    ::unlink(temp.c_str());
    throw WriteError(path, reason);
  }
  ::chmod(temp.c_str(), 0644);
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string rename_reason = system_reason();
    ::unlink(temp.c_str());
    throw WriteError(path, "cannot replace it: " + rename_reason);
  }
}

std::optional<FileStamp> file_stamp(const std::filesystem::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  const auto ns = [](const timespec& t) { return t.tv_sec * 1'000'000'000LL + t.tv_nsec; };
  return FileStamp{static_cast<unsigned long long>(info.st_ino),
                   static_cast<long long>(info.st_size), ns(info.st_mtim), ns(info.st_ctim)};
}

std::string symbolic_link_problem(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_symlink(std::filesystem::symlink_status(path, error))) return "";
  const std::filesystem::path target = std::filesystem::read_symlink(path, error);
  return path.string() + " is a symbolic link (to " + target.string() +
         "): raygate writes a file whole and would replace the link; name the file itself";
}

void sync_directory(const std::filesystem::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw WriteError(folder, "cannot open the folder to sync it: " + system_reason());
  const bool synced = ::fsync(fd) == 0;
  const std::string reason = synced ? "" : system_reason();
  ::close(fd);
  if (!synced) throw WriteError(folder, "cannot sync the folder: " + reason);
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_type type = std::filesystem::status(path, ec).type();
  if (type == std::filesystem::file_type::directory) {
    throw UsageError(path.string() + ": is a directory, expected a file");
  }
  // A FIFO with no writer blocks the open forever, a device may never end: only regular files
  // (issue 25, class 12). A missing file falls through to the open's own message.
  const bool special =
      type == std::filesystem::file_type::fifo || type == std::filesystem::file_type::socket ||
      type == std::filesystem::file_type::block || type == std::filesystem::file_type::character;
  if (special) {
    throw UsageError(
        path.string() + ": is a " +
        (type == std::filesystem::file_type::fifo ? "FIFO (named pipe)" : "device or socket") +
        ", expected a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path.string() + ": cannot open: " + system_reason());
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw UsageError(path.string() + ": read failed");
  return buffer.str();
}

TempDir::TempDir(std::string_view prefix) {
  // The system's words for a TMPDIR that is no folder were "temp_directory_path: No such file
  // or directory", naming neither the variable nor its value.
  std::error_code error;
  const std::filesystem::path folder = std::filesystem::temp_directory_path(error);
  if (error) {
    const char* tmpdir = std::getenv("TMPDIR");
    throw UsageError("TMPDIR=" + std::string(tmpdir ? tmpdir : "") +
                     " is not a folder that can be used (" + error.message() +
                     "): raygate's temporary files go there; name a folder, or unset it");
  }
  std::string pattern = (folder / (std::string(prefix) + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    // A TMPDIR the user named that takes no folder (/proc, a read-only one) is the user's to
    // change, as one that is missing is; a full disk is not.
    const int reason = errno;
    const char* tmpdir = std::getenv("TMPDIR");
    const bool setting = reason == EACCES || reason == EPERM || reason == EROFS ||
                         reason == ENOENT || reason == ENOTDIR;
    const std::string message =
        "cannot create a temporary folder in " + folder.string() + ": " + system_reason();
    if (setting && tmpdir != nullptr && *tmpdir != '\0') {
      throw UsageError("TMPDIR=" + std::string(tmpdir) + ": " + message +
                       "; raygate's temporary files go there: name a writable folder, or unset it");
    }
    throw InfraError(message);
  }
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::optional<std::string> read_pseudo_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream out;
  out << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return out.str();
}

}  // namespace raygate
