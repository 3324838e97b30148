// What `raygate doctor` knows about this machine before it measures anything: the results
// document's machine context (measure/machine_context.h) plus what only matters when judging
// whether the machine is fit to measure: the governor of each CPU, SMT siblings, ASLR, swap use,
// a cgroup CPU quota, and whether this is a virtual machine or a container. Everything under
// /proc and /sys is read below a root directory, so tests feed a fake tree; nothing is global.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "measure/machine_context.h"

namespace raygate {

struct CpuGovernor {
  int cpu = 0;
  std::string governor;
};

struct SwapUsage {
  std::uint64_t total_bytes = 0;
  std::uint64_t used_bytes = 0;                         // SwapTotal - SwapFree
  std::optional<std::uint64_t> available_memory_bytes;  // MemAvailable
};

struct Virtualization {
  std::string vm;                     // "kvm", "vmware", ... ; empty when none was detected
  std::string container;              // "docker", "podman", ... ; empty when none was detected
  std::vector<std::string> evidence;  // where each finding came from, for the report
};

struct CpuTimes {  // the "cpu" line of /proc/stat, in clock ticks
  std::uint64_t total = 0;
  std::uint64_t steal = 0;  // time a hypervisor gave this VM's CPUs to someone else
};

// Whether raygate can hold idle CPUs polling while it measures (runner/idle_poll.h).
struct IdlePolling {
  bool holdable = false;
  std::string why_not;  // when not: "cannot open /dev/cpu_dma_latency: Permission denied"
};

struct SystemFacts {
  MachineContext machine;
  bool cpufreq_present = false;                      // some cpuN/cpufreq directory exists
  std::vector<CpuGovernor> governors;                // per CPU, ascending
  std::vector<int> allowed_cpus;                     // this process's affinity mask
  std::vector<std::vector<int>> smt_sibling_groups;  // cores with more than one thread
  std::optional<bool> smt_active;                    // /sys/devices/system/cpu/smt/active
  std::optional<int> aslr;  // /proc/sys/kernel/randomize_va_space: 0, 1 or 2
  std::optional<SwapUsage> swap;
  std::optional<double> cpu_quota;  // cgroup v2 cpu.max as CPUs; nullopt: no quota
  Virtualization virtualization;
  std::optional<IdlePolling> idle_polling;  // asked of the live system only
};

struct ProbeOptions {
  std::filesystem::path root = "/";  // prefixes every /proc and /sys path
  // Also ask the live system what no file under `root` says: the affinity mask and
  // systemd-detect-virt. Tests with a fake root turn it off.
  bool live = true;
};

SystemFacts probe_system_facts(const ProbeOptions& options = {});

// Reads the "cpu" line of <root>/proc/stat; nullopt when unreadable.
std::optional<CpuTimes> read_cpu_times(const std::filesystem::path& root = "/");

// Pure pieces of the probe, tested on fixed text.
std::vector<int> parse_cpu_list(std::string_view list);     // "0-2,5" -> {0,1,2,5}; bad -> {}
std::string format_cpu_list(const std::vector<int>& cpus);  // {0,1,2,5} -> "0-2,5"
std::optional<SwapUsage> parse_swap(std::string_view meminfo);
std::optional<double> parse_cpu_max(std::string_view cpu_max);  // "200000 100000" -> 2.0
std::optional<CpuTimes> parse_cpu_times(std::string_view proc_stat);
// DMI product name and vendor of a virtual machine -> "kvm", "vmware", ...; empty otherwise.
std::string vm_from_dmi(std::string_view product_name, std::string_view sys_vendor);
// /proc/1/cgroup of a container -> "docker", "kubernetes", "lxc", ...; empty otherwise.
std::string container_from_cgroup(std::string_view cgroup);

}  // namespace raygate
