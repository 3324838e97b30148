#include "runner/idle_poll.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <utility>

namespace raygate {
namespace {

std::string failed(const char* what, const std::filesystem::path& device, int error) {
  return std::string(what) + " " + device.string() + ": " + std::strerror(error);
}

}  // namespace

IdlePollHold::IdlePollHold(const std::filesystem::path& device) {
  const int fd = ::open(device.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) {
    why_not_ = failed("cannot open", device, errno);
    return;
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
