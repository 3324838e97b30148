// File helpers with the guarantees raygate's results need: a write either lands whole or not at
// all (temp file, fsync, rename), and failures name the path and the system's reason.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace raygate {

// Replaces `path` atomically with `content`; creates parent directories. On any failure
// (including a full disk) the old file is untouched and an InfraError names the path and why.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// Whole file as bytes; throws UsageError (missing or unreadable input is the user's to fix).
std::string read_file(const std::filesystem::path& path);

// The whole of a /proc or /sys file (they report size 0, so it is read to EOF); nullopt when it
// cannot be read, which for such files means "unknown", not an error.
std::optional<std::string> read_pseudo_file(const std::filesystem::path& path);

// A fresh, empty directory under the system temp dir, removed by the destructor.
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
