// The doctor's judgement of SystemFacts: one finding per check (governor, turbo, load, CPUs,
// SMT, perf counters, ASLR, swap, virtualization), each with what was seen and, when something
// should change, what to do. Pure: the same facts always give the same findings.
#pragma once

#include <string>
#include <vector>

#include "doctor/system_facts.h"

namespace raygate {

enum class FindingLevel {
  ok,    // fit to measure as it is
  info,  // worth knowing; nothing to change (or nothing that can be changed here)
  warn,  // adds noise or bias to measurements: change it if you can
};

std::string to_string(FindingLevel level);

struct Finding {
  std::string check;  // "governor", "turbo", "load", "cpus", "smt", "perf", "aslr", "swap",
                      // "virtualization", "idle"
  FindingLevel level = FindingLevel::ok;
  std::string detail;  // what was seen, one line
  std::string advice;  // what to do; empty when nothing
};

// A machine is busy when its 1-minute load per usable CPU exceeds this (load 1.0 on 2 CPUs
// leaves one CPU for raygate's runs, which is already borderline for a duet schedule).
inline constexpr double kBusyLoadPerCpu = 0.5;
// Swap in use beyond this suggests memory pressure that can page a tracer out mid-run.
inline constexpr double kSwapWarnBytes = 64.0 * 1024 * 1024;

std::vector<Finding> diagnose(const SystemFacts& facts);

}  // namespace raygate
