// What machine a measurement ran on (DESIGN.md §8): stored with every result so that a ratio
// that moved can be checked against a governor, turbo, load or kernel that changed. Probing
// never throws: a container without /sys or a kernel that forbids perf leaves a field unknown
// (empty string, empty list, or std::nullopt, written to JSON as null).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace raygate {

struct MachineContext {
  std::string cpu_model;                       // "model name" from /proc/cpuinfo
  std::optional<int> logical_cores;            // "processor" entries in /proc/cpuinfo
  std::optional<int> online_cpus;              // /sys/devices/system/cpu/online
  std::optional<int> allowed_cpus;             // this process's affinity mask (containers, taskset)
  std::vector<std::string> scaling_governors;  // distinct values over all CPUs, sorted
  std::optional<bool> turbo_enabled;           // intel_pstate/no_turbo, else cpufreq/boost
  std::string kernel;                          // uname: sysname release version machine
  std::string compiler;                        // the compiler that built raygate
  std::optional<std::array<double, 3>> load_average;  // 1, 5, 15 minutes
  std::optional<std::uint64_t> total_memory_bytes;    // MemTotal in /proc/meminfo
  bool perf_instructions_available = false;  // perf_event_open(HW_INSTRUCTIONS) on self works
  std::string perf_error;                    // why not, when not
  std::optional<int> perf_event_paranoid;    // /proc/sys/kernel/perf_event_paranoid
  std::string hostname;
  bool ci = false;  // environment variable CI is "true" (GitHub, GitLab and others set it)
};

// Probes this machine. `root` prefixes /proc and /sys paths (tests point it at a fake tree);
// uname, hostname, affinity, perf and the environment always come from the live system.
MachineContext probe_machine_context(const std::filesystem::path& root = "/");

// The scaling governor of each CPU that has one (<root>/sys/devices/system/cpu/cpuN/cpufreq), by
// CPU number: the one probe behind a document's scaling_governors and the doctor's check.
std::map<int, std::string> cpu_governors(const std::filesystem::path& root);

// Pieces of the probe, pure so they are tested on fixed text.
std::string parse_cpu_model(std::string_view cpuinfo);
std::optional<int> count_processors(std::string_view cpuinfo);
std::optional<int> count_cpu_list(std::string_view list);  // "0-3,6,8-9" -> 7
std::optional<std::uint64_t> parse_mem_total_bytes(std::string_view meminfo);
std::optional<std::array<double, 3>> parse_load_average(std::string_view loadavg);
bool is_ci_value(const char* value);  // getenv("CI"): "true" in any case, or "1"
std::string compiler_description();

void to_json(nlohmann::json& json, const MachineContext& context);

}  // namespace raygate
