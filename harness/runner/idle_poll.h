// Keeps idle CPUs polling while raygate measures, so a CPU that idled does not run the next
// run slow. On a VM an idle vCPU halts and its host thread sleeps; the first tens of
// milliseconds after it wakes run up to 60% slower (cold caches, a host core that lowered its
// clock or went to another guest). A tracer that sleeps inside its own run (Debian's POV-Ray
// waits about 0.6 s polling its console) then renders at a speed set by the host: its CPU time
// for one ci scene split into a fast mode and one 35-50% slower. With idle CPUs polling, the
// kernel's idle loop spins instead of halting, and the slow mode is gone (docs/statistics.md
// §6d). The means is PM QoS: writing a CPU wake-up latency of 0 to /dev/cpu_dma_latency holds
// every CPU in its shallowest idle state (poll) for as long as the file stays open; the kernel
// drops the request when it is closed, also when the process dies, so nothing outlives raygate.
// The request is honoured only by a cpuidle driver: with none (current_driver "none", as on
// many VMs) an idle CPU halts whatever latency is asked, so the hold is not taken and the
// record says "os" with the reason (issue 40: "poll" was recorded on such a VM).
#pragma once

#include <filesystem>
#include <string>

namespace raygate {

// The kernel's PM QoS request file for the CPUs' wake-up latency.
inline constexpr const char* kCpuLatencyDevice = "/dev/cpu_dma_latency";
// The kernel's cpuidle driver; "none" when idle CPUs only halt.
inline constexpr const char* kCpuIdleDriverFile = "/sys/devices/system/cpu/cpuidle/current_driver";

class IdlePollHold {
 public:
  // Asks for idle CPUs to poll through `device` (kCpuLatencyDevice outside tests). Never
  // throws: a machine that does not allow it (no such file, not root, a container) still
  // measures, and held() / why_not() say so. When `device` is a character device (the kernel's),
  // `cpuidle_driver` must name a driver; a regular file standing in for it (tests) has no idle
  // states to check.
  explicit IdlePollHold(const std::filesystem::path& device,
                        const std::filesystem::path& cpuidle_driver = kCpuIdleDriverFile);
  ~IdlePollHold();
  IdlePollHold(IdlePollHold&& other) noexcept;
  IdlePollHold& operator=(IdlePollHold&& other) noexcept;
  IdlePollHold(const IdlePollHold&) = delete;
  IdlePollHold& operator=(const IdlePollHold&) = delete;

  bool held() const { return fd_ >= 0; }
  // Why it is not held: "cannot open /dev/cpu_dma_latency: Permission denied"; "" when held.
  const std::string& why_not() const { return why_not_; }

 private:
  int fd_ = -1;
  std::string why_not_;
};

}  // namespace raygate
