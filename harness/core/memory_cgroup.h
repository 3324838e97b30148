// A memory cgroup of its own for one metered run (issue 40): the peak of the tracer's whole
// process tree at once, not of one process at a time. wait4's ru_maxrss is per process, so a
// tracer that runs four workers of 100 MiB side by side reports ~100 MiB; the kernel's cgroup
// counter sees all four together.
//
// Where: cgroup v2 (memory.peak, kernel 5.19+) when its hierarchy has the memory controller,
// else a cgroup v1 memory hierarchy (memory.max_usage_in_bytes). Creating either needs write
// access to the cgroup tree (root in CI). Where neither can be made, the run falls back to the
// peak of its largest single process (raygate-meter's wait4), and the record says so
// (PeakMethod::largest_process).
//
// Cleanup on every path: the destructor kills whatever is still in the cgroup and removes it;
// a cgroup left by a raygate that was SIGKILLed (its pid is in the name) is removed by the next
// raygate that creates one in the same place.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace raygate {

// How a run's peak memory was measured.
enum class PeakMethod {
  raygate_process,  // not metered: raygate's own peak seen through fork (not judged)
  largest_process,  // raygate-meter's wait4: the largest single process of the tree
  cgroup_v1,        // the tree at once: cgroup v1 memory.max_usage_in_bytes
  cgroup_v2,        // the tree at once: cgroup v2 memory.peak
};

std::string_view to_string(PeakMethod method);
std::optional<PeakMethod> parse_peak_method(std::string_view word);
// "the whole process tree (cgroup v2 memory.peak)", for reports.
std::string describe_peak_method(PeakMethod method);
void to_json(nlohmann::json&, PeakMethod) = delete;  // the words, not a number
void from_json(const nlohmann::json&, PeakMethod&) = delete;

class MemoryCgroup {
 public:
  // A new, empty cgroup with a memory counter, or nullopt (then `why_not` says why, for the
  // curious: doctor and tests). Never throws.
  static std::optional<MemoryCgroup> create(std::string* why_not = nullptr);

  MemoryCgroup(MemoryCgroup&& other) noexcept;
  MemoryCgroup& operator=(MemoryCgroup&& other) noexcept;
  MemoryCgroup(const MemoryCgroup&) = delete;
  ~MemoryCgroup();  // kills what is left in it, then removes it

  // The file a process writes its pid to, to join (raygate-meter does, before it starts the
  // program, so the program and all it starts are inside).
  std::filesystem::path procs_file() const { return directory_ / "cgroup.procs"; }
  PeakMethod method() const { return method_; }
  // The peak (KiB) since the cgroup was made; nullopt if it cannot be read.
  std::optional<long> peak_kib() const;
  const std::filesystem::path& directory() const { return directory_; }

 private:
  MemoryCgroup(std::filesystem::path directory, PeakMethod method)
      : directory_(std::move(directory)), method_(method) {}

  std::filesystem::path directory_;  // empty once moved from
  PeakMethod method_ = PeakMethod::cgroup_v2;
};

}  // namespace raygate
