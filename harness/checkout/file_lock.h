// An exclusive lock between raygate processes sharing one cache (two CI jobs on one runner).
// flock(2) on a lock file: the kernel drops it when the holder dies, so a killed run never
// leaves a cache entry locked, and whoever holds it may delete a dead run's leftovers.
#pragma once

#include <filesystem>

namespace raygate {

class FileLock {
 public:
  // Creates the file and its parent directories; blocks until the lock is ours.
  explicit FileLock(const std::filesystem::path& path);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace raygate
