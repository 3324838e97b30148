// File helpers with the guarantees raygate's results need: a write either lands whole or not at
// all (temp file, fsync, rename), and failures name the path and the system's reason.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace raygate {

// One write that failed: the file and the system's reason.
struct FailedWrite {
  std::filesystem::path path;
  std::string reason;
};

// A file that could not be written: which one, and the system's reason ("No space left on
// device"). Kept apart from other infrastructure failures so a command that writes several
// outputs can keep going after one of them failed and say which (cli/output_failures.h).
class WriteError : public InfraError {
 public:
  WriteError(std::filesystem::path path, std::string reason)
      : InfraError("cannot write " + path.string() + ": " + reason),
        path_(std::move(path)),
        reason_(std::move(reason)) {}
  const std::filesystem::path& path() const { return path_; }
  const std::string& reason() const { return reason_; }
  FailedWrite failure() const { return {path_, reason_}; }

 private:
  std::filesystem::path path_;
  std::string reason_;
};

// Replaces `path` atomically with `content`; creates parent directories. On any failure
// (including a full disk) the old file is untouched and a WriteError names the path and why.
// Only a regular file (or nothing) is replaced: a device, FIFO or socket at `path` (/dev/full,
// /dev/stdout) is refused, since renaming over it would replace the node, not write through it.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// Why a file the user named must not be written whole at `path`: it is a symbolic link, which the
// write would replace (and a link planted in a repository must not send a write elsewhere). The
// text names the path and the link's target; "" when `path` is no link.
std::string symbolic_link_problem(const std::filesystem::path& path);

// What one stat says of a file's identity and last change: its inode, size, and modification and
// status-change times in nanoseconds. Any write moves the status-change time, which a process
// cannot set back (utimensat sets only the others), and a replacement has another inode: equal
// stamps mean the file was not touched, at the cost of one stat (hashing a 300 KB scene took 3 ms,
// a tenth of a fast tracer's run). nullopt when the file cannot be stat'ed.
struct FileStamp {
  unsigned long long inode = 0;
  long long size = 0;
  long long modified_ns = 0;
  long long changed_ns = 0;
  bool operator==(const FileStamp&) const = default;
};
std::optional<FileStamp> file_stamp(const std::filesystem::path& path);

// Flushes a directory's entries to disk (after files were created or renamed in it), so a
// rename that was reported done survives a crash. A WriteError names the folder on failure.
void sync_directory(const std::filesystem::path& folder);

// Whole file as bytes; throws UsageError (missing or unreadable input is the user's to fix, and so
// is a FIFO, device or socket, which could block or never end).
std::string read_file(const std::filesystem::path& path);

// The whole of a /proc or /sys file (they report size 0, so it is read to EOF); nullopt when it
// cannot be read, which for such files means "unknown", not an error.
std::optional<std::string> read_pseudo_file(const std::filesystem::path& path);

// A fresh, empty directory under the system temp dir, removed by the destructor. A TMPDIR that
// is no folder is a UsageError naming it; a folder that cannot be made in, an InfraError.
class TempDir {
 public:
  explicit TempDir(std::string_view prefix = "raygate");
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace raygate
