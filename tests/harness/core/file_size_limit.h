// A full disk, made in a test: while a FileSizeLimit lives, the process may write files of at most
// `bytes`, and a write past that fails with EFBIG as one on a full disk fails with ENOSPC (ctest
// runs each test in a process of its own, so the limit ends with the test).
#pragma once

#include <sys/resource.h>

#include <csignal>

namespace raygate::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = saved_;
    small.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &small);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_)(int) = nullptr;
};

}  // namespace raygate::test
