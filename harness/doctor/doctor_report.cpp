#include "doctor/doctor_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/format.h"

namespace raygate {
namespace {

using nlohmann::json;

std::string machine_line(const SystemFacts& facts) {
  const MachineContext& m = facts.machine;
  return fmt::format("{} ({}), {} CPU(s) online, kernel {}", m.hostname.empty() ? "?" : m.hostname,
                     m.cpu_model.empty() ? "unknown CPU" : m.cpu_model,
                     m.online_cpus ? std::to_string(*m.online_cpus) : "?", m.kernel);
}

void noise_text(const DoctorReport& report, std::string& out) {
  if (!report.noise) {
    out += "\nnoise: not measured: " + report.noise_error + "\n";
    return;
  }
  const NoiseScore& n = *report.noise;
  out += fmt::format("\nnoise: {} rounds of two raygate-baseline runs on {}\n", n.rounds, n.scene);
  out += fmt::format("  run time     median {:.4f} s  CV {}  spread (max/min) {:.3f}x\n",
                     n.seconds.median, percent(n.seconds.cv, 2), n.seconds.spread);
  out += fmt::format("  CPU time     median {:.4f} s  CV {}  spread (max/min) {:.3f}x\n",
                     n.cpu_seconds.median, percent(n.cpu_seconds.cv, 2), n.cpu_seconds.spread);
  out += fmt::format("  A/A ratio    {:.4f}  CV {}  spread (max/min) {:.3f}x\n", n.aa_ratio,
                     percent(n.ratio_cv, 2), n.ratio_spread);
  if (n.waiting_fraction() > kWaitingWarnFraction) {
    out += fmt::format(
        "  waiting      {:.0f}% of a run's time went by without it on a CPU: other "
        "processes hold the CPUs\n",
        100.0 * n.waiting_fraction());
  }
  if (n.steal_fraction) {
    out += fmt::format("  steal        {} of CPU time went to other guests while measuring\n",
                       percent(*n.steal_fraction, 2));
  }
  out += fmt::format("  noise score  {} (CV of the A/A ratio {}; good < {:.0f}%, fair < {:.0f}%)\n",
                     to_string(n.grade), percent(n.ratio_cv, 2), 100.0 * kNoiseGoodCv,
                     100.0 * kNoiseFairCv);
  out += "  -> " + n.advice() + "\n";
}

json noise_json(const DoctorReport& report) {
  if (!report.noise) return nullptr;
  const NoiseScore& n = *report.noise;
  auto spread = [](const TimeSpread& t) {
    return json{{"median", t.median}, {"cv", t.cv}, {"spread", t.spread}};
  };
  return {{"scene", n.scene},
          {"rounds", n.rounds},
          {"seconds", spread(n.seconds)},
          {"cpu_seconds", spread(n.cpu_seconds)},
          {"aa_ratio", n.aa_ratio},
          {"ratio_cv", n.ratio_cv},
          {"ratio_spread", n.ratio_spread},
          {"waiting_fraction", n.waiting_fraction()},
          {"steal_fraction", n.steal_fraction ? json(*n.steal_fraction) : json(nullptr)},
          {"grade", to_string(n.grade)},
          {"advice", n.advice()}};
}

}  // namespace

std::size_t DoctorReport::warnings() const {
  return static_cast<std::size_t>(
      std::count_if(findings.begin(), findings.end(),
                    [](const Finding& f) { return f.level == FindingLevel::warn; }));
}

std::string doctor_text(const DoctorReport& report) {
  std::string out = "raygate doctor: is this machine fit to measure?\n";
  out += "machine: " + machine_line(report.facts) + "\n";
  if (!report.baseline_version.empty()) out += "baseline: " + report.baseline_version + "\n";
  out += "\n";
  for (const Finding& f : report.findings) {
    out += fmt::format("  {:<4}  {:<14}  {}\n", to_string(f.level), f.check, f.detail);
    if (!f.advice.empty()) out += fmt::format("  {:<4}  {:<14}  -> {}\n", "", "", f.advice);
  }
  noise_text(report, out);
  const std::string grade = report.noise ? to_string(report.noise->grade) : "not measured";
  out += fmt::format("\nverdict: {} warning(s); noise score {}\n", report.warnings(), grade);
  return out;
}

json doctor_json(const DoctorReport& report) {
  json checks = json::array();
  for (const Finding& f : report.findings) {
    checks.push_back({{"check", f.check},
                      {"level", to_string(f.level)},
                      {"detail", f.detail},
                      {"advice", f.advice.empty() ? json(nullptr) : json(f.advice)}});
  }
  json governors = json::object();
  for (const CpuGovernor& g : report.facts.governors)
    governors["cpu" + std::to_string(g.cpu)] = g.governor;
  const SystemFacts& f = report.facts;
  return {
      {"machine", f.machine},
      {"baseline", report.baseline_version.empty() ? json(nullptr) : json(report.baseline_version)},
      {"system",
       {{"governors", governors},
        {"cpufreq_present", f.cpufreq_present},
        {"allowed_cpus", f.allowed_cpus},
        {"smt_sibling_groups", f.smt_sibling_groups},
        {"aslr", f.aslr ? json(*f.aslr) : json(nullptr)},
        {"swap_used_bytes", f.swap ? json(f.swap->used_bytes) : json(nullptr)},
        {"cpu_quota", f.cpu_quota ? json(*f.cpu_quota) : json(nullptr)},
        {"vm", f.virtualization.vm.empty() ? json(nullptr) : json(f.virtualization.vm)},
        {"container",
         f.virtualization.container.empty() ? json(nullptr) : json(f.virtualization.container)}}},
      {"checks", checks},
      {"warnings", report.warnings()},
      {"noise", noise_json(report)},
      {"noise_error", report.noise_error.empty() ? json(nullptr) : json(report.noise_error)}};
}

}  // namespace raygate
