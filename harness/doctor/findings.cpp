#include "doctor/findings.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>

#include "core/enum_words.h"

namespace raygate {
namespace {

using Level = FindingLevel;

std::string mib(double bytes) { return fmt::format("{:.0f} MiB", bytes / (1024.0 * 1024.0)); }

// The CPUs raygate's runs may use: the affinity mask, else the context's count of it, else the
// online CPUs.
std::size_t usable_cpus(const SystemFacts& facts) {
  if (!facts.allowed_cpus.empty()) return facts.allowed_cpus.size();
  if (facts.machine.allowed_cpus) return static_cast<std::size_t>(*facts.machine.allowed_cpus);
  if (facts.machine.online_cpus) return static_cast<std::size_t>(*facts.machine.online_cpus);
  return static_cast<std::size_t>(facts.machine.logical_cores.value_or(1));
}

bool in_vm(const SystemFacts& facts) { return !facts.virtualization.vm.empty(); }

Finding governor(const SystemFacts& facts) {
  if (facts.governors.empty()) {
    if (in_vm(facts) || !facts.cpufreq_present) {
      return {"governor", Level::info,
              "no cpufreq in /sys: the frequency is not under this system's control (usual in a "
              "virtual machine or container: the host sets it)",
              in_vm(facts) ? ""
                           : "nothing to set here; if this is bare metal, load a cpufreq "
                             "driver (acpi-cpufreq, intel_pstate, amd-pstate)"};
    }
    return {"governor", Level::info, "cpufreq present but no scaling_governor readable", ""};
  }
  std::map<std::string, std::vector<int>> by_governor;
  for (const CpuGovernor& g : facts.governors) by_governor[g.governor].push_back(g.cpu);
  std::string detail;
  for (const auto& [name, cpus] : by_governor) {
    detail +=
        fmt::format("{}{} on cpu {}", detail.empty() ? "" : "; ", name, format_cpu_list(cpus));
  }
  if (by_governor.size() == 1 && by_governor.count("performance")) {
    return {"governor", Level::ok, detail, ""};
  }
  return {"governor", Level::warn,
          detail + ": the clock follows the load, so a run's speed depends on what ran before it",
          "set the governor to performance: `sudo cpupower frequency-set -g performance` "
          "(Debian package linux-cpupower)"};
}

Finding turbo(const SystemFacts& facts) {
  if (!facts.machine.turbo_enabled) {
    return {"turbo", Level::info,
            in_vm(facts) ? "turbo/boost not visible in a virtual machine (the host decides)"
                         : "turbo/boost state unknown (no intel_pstate/no_turbo or cpufreq/boost)",
            ""};
  }
  if (!*facts.machine.turbo_enabled) return {"turbo", Level::ok, "turbo/boost off", ""};
  return {"turbo", Level::warn,
          "turbo/boost on: the clock depends on temperature and on how many cores are busy; the "
          "ratio cancels a steady clock but not one that changes between a round's two runs",
          "turn it off while measuring: `echo 1 | sudo tee "
          "/sys/devices/system/cpu/intel_pstate/no_turbo` (intel_pstate) or `echo 0 | sudo tee "
          "/sys/devices/system/cpu/cpufreq/boost` (acpi-cpufreq, amd-pstate)"};
}

Finding load(const SystemFacts& facts) {
  if (!facts.machine.load_average) return {"load", Level::info, "load average unknown", ""};
  const double load1 = (*facts.machine.load_average)[0];
  const std::size_t cpus = usable_cpus(facts);
  const std::string detail = fmt::format("load {:.2f} (1 min), {:.2f} (5 min) on {} CPU(s)", load1,
                                         (*facts.machine.load_average)[1], cpus);
  if (load1 / static_cast<double>(cpus) <= kBusyLoadPerCpu) return {"load", Level::ok, detail, ""};
  return {"load", Level::warn, detail + ": other jobs compete for the CPUs",
          fmt::format("load {:.1f} on {} CPU(s): stop other jobs or measure on a dedicated runner "
                      "(paired rounds cancel steady load, not load that starts or stops between "
                      "a round's runs)",
                      load1, cpus)};
}

Finding cpus(const SystemFacts& facts) {
  const std::size_t usable = usable_cpus(facts);
  const std::string list =
      facts.allowed_cpus.empty() ? "" : " (" + format_cpu_list(facts.allowed_cpus) + ")";
  std::string detail = fmt::format("{} CPU(s) allowed{}", usable, list);
  if (facts.machine.online_cpus && static_cast<std::size_t>(*facts.machine.online_cpus) > usable) {
    detail += fmt::format(" of {} online (affinity from taskset, a CPU set or the container)",
                          *facts.machine.online_cpus);
  }
  if (facts.cpu_quota && *facts.cpu_quota < static_cast<double>(usable)) {
    return {"cpus", Level::warn,
            detail + fmt::format("; cgroup CPU quota {:.2f} CPUs: the kernel pauses the group "
                                 "whenever it uses more, which lands inside timed runs",
                                 *facts.cpu_quota),
            "raise or remove the quota (docker --cpus, Kubernetes CPU limits), or keep raygate's "
            "runs within it (one run at a time, --pin one CPU)"};
  }
  if (usable < 2) {
    return {"cpus", Level::warn, detail + ": the runs share their only CPU with everything else",
            "allow at least 2 CPUs (taskset, the container's CPU set) so the system runs beside "
            "the measurement, and for the duet schedule"};
  }
  return {"cpus", Level::ok, detail, ""};
}

Finding smt(const SystemFacts& facts) {
  if (facts.smt_sibling_groups.empty()) {
    return {"smt", Level::ok, "one thread per core (no SMT siblings)", ""};
  }
  const std::vector<int>& allowed = facts.allowed_cpus;
  for (const std::vector<int>& group : facts.smt_sibling_groups) {
    const auto shared = std::count_if(group.begin(), group.end(), [&](int cpu) {
      return allowed.empty() || std::find(allowed.begin(), allowed.end(), cpu) != allowed.end();
    });
    if (shared < 2) continue;
    return {"smt", Level::warn,
            fmt::format("CPUs {} are SMT siblings of one core: runs on them share its execution "
                        "units (a duet schedule, or a job on the sibling, slows the other)",
                        format_cpu_list(group)),
            "pin raygate to one thread per core (--pin, --duet-cpus with CPUs of different "
            "cores) or turn SMT off: `echo off | sudo tee /sys/devices/system/cpu/smt/control`"};
  }
  return {"smt", Level::info, "SMT on, but no two allowed CPUs share a core", ""};
}

Finding perf(const SystemFacts& facts) {
  const MachineContext& m = facts.machine;
  const std::string paranoid = m.perf_event_paranoid
                                   ? fmt::format("perf_event_paranoid {}", *m.perf_event_paranoid)
                                   : "perf_event_paranoid unknown";
  if (m.perf_instructions_available) {
    return {"perf", Level::ok, "instruction counter available (" + paranoid + ")", ""};
  }
  const std::string detail = "perf counters unavailable: " + m.perf_error + " (" + paranoid + ")";
  if (m.perf_error.find("no hardware instruction counter") != std::string::npos) {
    return {"perf", Level::info, detail,
            "instructions cannot be recorded on this machine (times still are); a VM host can "
            "expose a virtual PMU (libvirt: <pmu state='on'/>)"};
  }
  if (m.perf_event_paranoid && *m.perf_event_paranoid >= 2) {
    return {"perf", Level::warn, detail,
            "set kernel.perf_event_paranoid=1 to record instructions: `sudo sysctl -w "
            "kernel.perf_event_paranoid=1` (a file in /etc/sysctl.d/ keeps it)"};
  }
  return {"perf", Level::warn, detail,
          "perf_event_open is blocked although the kernel allows it: a container's seccomp "
          "profile or missing CAP_PERFMON (docker --cap-add PERFMON)"};
}

Finding aslr(const SystemFacts& facts) {
  if (!facts.aslr) return {"aslr", Level::info, "ASLR state unknown", ""};
  if (*facts.aslr == 0) {
    return {"aslr", Level::info,
            "ASLR off: every run gets the same memory layout, so a build that is lucky or "
            "unlucky with its layout stays so in every round",
            "fine for repeatable times; leave it on (2) to let rounds average over layouts"};
  }
  return {"aslr", Level::ok,
          fmt::format("ASLR on ({}): rounds average over memory layouts", *facts.aslr), ""};
}

Finding swap(const SystemFacts& facts) {
  if (!facts.swap) return {"swap", Level::info, "swap use unknown", ""};
  const SwapUsage& s = *facts.swap;
  if (s.total_bytes == 0) return {"swap", Level::ok, "no swap configured", ""};
  std::string detail = fmt::format("{} of {} swap in use", mib(static_cast<double>(s.used_bytes)),
                                   mib(static_cast<double>(s.total_bytes)));
  if (s.available_memory_bytes) {
    detail +=
        fmt::format(", {} memory available", mib(static_cast<double>(*s.available_memory_bytes)));
  }
  if (static_cast<double>(s.used_bytes) <= kSwapWarnBytes) return {"swap", Level::ok, detail, ""};
  return {"swap", Level::warn, detail + ": memory pressure can page a run out mid-measurement",
          "stop memory-hungry jobs; `sudo swapoff -a && sudo swapon -a` empties swap when enough "
          "memory is free"};
}

Finding virtualization(const SystemFacts& facts) {
  const Virtualization& v = facts.virtualization;
  std::string evidence;
  for (const std::string& e : v.evidence) evidence += (evidence.empty() ? " (" : "; ") + e;
  if (!evidence.empty()) evidence += ")";
  if (v.vm.empty() && v.container.empty()) {
    return {"virtualization", Level::ok, "no virtual machine or container detected", ""};
  }
  std::string detail;
  if (!v.vm.empty()) detail = "virtual machine (" + v.vm + ")";
  if (!v.container.empty())
    detail += (detail.empty() ? "" : ", ") + ("container (" + v.container + ")");
  return {"virtualization", Level::info, detail + evidence,
          v.vm.empty() ? "a container shares the host's CPUs: check the quota and load findings"
                       : "other guests on the host take CPU time (steal) and cache that no "
                         "setting here gets back; if the noise score is not good, gate on a "
                         "dedicated or bare-metal runner"};
}

// A CPU woken from an idle halt runs its first milliseconds slow; on this project's VM a tracer
// that sleeps during its run (POV-Ray) measured 35-50% slow in a third of its runs until idle
// CPUs were held polling (docs/statistics.md §6d).
Finding idle(const SystemFacts& facts) {
  if (!facts.idle_polling) return {"idle", Level::info, "idle CPU states not checked", ""};
  if (facts.idle_polling->holdable) {
    return {"idle", Level::ok,
            "idle CPUs can be held polling while raygate measures (/dev/cpu_dma_latency)", ""};
  }
  return {"idle", Level::warn,
          "idle CPUs cannot be held polling (" + facts.idle_polling->why_not +
              "): a CPU woken from sleep runs its first milliseconds slow, so runs that "
              "follow a pause, or a tracer that sleeps during its run, measure noisier",
          "let raygate write /dev/cpu_dma_latency: run it as root, or give its user the device "
          "(a udev rule: KERNEL==\"cpu_dma_latency\", GROUP=\"<group>\", MODE=\"0660\"; a "
          "container needs the device passed in)"};
}

// The levels' words, as the report prints them and its JSON writes them.
constexpr EnumWords<FindingLevel, 3> kLevelWords{
    {{FindingLevel::ok, "ok"}, {FindingLevel::info, "info"}, {FindingLevel::warn, "warn"}}};

}  // namespace

std::string to_string(FindingLevel level) { return std::string(word_of(kLevelWords, level, "?")); }

std::vector<Finding> diagnose(const SystemFacts& facts) {
  return {governor(facts), turbo(facts), load(facts), cpus(facts),           smt(facts),
          perf(facts),     aslr(facts),  swap(facts), virtualization(facts), idle(facts)};
}

}  // namespace raygate
