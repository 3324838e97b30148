#include "runner/idle_poll.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <utility>

namespace raygate {
namespace {

std::string failed(const char* what, const std::filesystem::path& device, int error) {
  return std::string(what) + " " + device.string() + ": " + std::strerror(error);
}

// Why a latency request through the kernel's device would not hold idle CPUs polling: no
// cpuidle driver to honour it. "" when there is one.
std::string no_driver(const std::filesystem::path& driver_file) {
  std::ifstream in(driver_file);
  std::string driver;
  if (!(in >> driver)) return "no cpuidle driver (" + driver_file.string() + " unreadable)";
  if (driver != "none") return "";
  return "no cpuidle driver (" + driver_file.string() +
         ": none): idle CPUs halt whatever latency is asked";
}

}  // namespace

IdlePollHold::IdlePollHold(const std::filesystem::path& device,
                           const std::filesystem::path& cpuidle_driver) {
  const int fd = ::open(device.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) {
    why_not_ = failed("cannot open", device, errno);
    return;
  }
  struct stat status {};
  if (::fstat(fd, &status) == 0 && S_ISCHR(status.st_mode)) {
    why_not_ = no_driver(cpuidle_driver);
    if (!why_not_.empty()) {
      ::close(fd);
      return;
    }
  }
  // The request is a 32-bit latency in microseconds, as binary; 0 = never leave the poll state.
  const std::int32_t latency_us = 0;
  const ssize_t written = ::write(fd, &latency_us, sizeof latency_us);
  if (written != static_cast<ssize_t>(sizeof latency_us)) {
    why_not_ = failed("cannot write", device, written < 0 ? errno : EIO);
    ::close(fd);
    return;
  }
  fd_ = fd;
}

IdlePollHold::~IdlePollHold() {
  if (fd_ >= 0) ::close(fd_);
}

IdlePollHold::IdlePollHold(IdlePollHold&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), why_not_(std::move(other.why_not_)) {}

IdlePollHold& IdlePollHold::operator=(IdlePollHold&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    why_not_ = std::move(other.why_not_);
  }
  return *this;
}

}  // namespace raygate
