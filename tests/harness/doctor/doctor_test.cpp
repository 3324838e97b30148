// The doctor on a fake /proc and /sys tree in a temp dir (what it parses), on hand-made facts
// (its grading and advice), and the noise score's statistics on fixed rounds.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/fs.h"
#include "doctor/doctor_report.h"
#include "doctor/findings.h"
#include "doctor/noise.h"
#include "doctor/system_facts.h"

namespace raygate {
namespace {

using ::testing::HasSubstr;

class FakeRoot {
 public:
  void write(const std::string& path, const std::string& text) {
    write_file_atomically(dir.path() / path, text);
  }
  SystemFacts probe() const { return probe_system_facts({dir.path(), /*live=*/false}); }
  TempDir dir{"raygate-doctor-test"};
};

// A 4-CPU KVM guest in a Docker container, two cores with two threads each.
void fill_busy_vm(FakeRoot& root) {
  const char* governors[] = {"performance", "powersave", "powersave", "performance"};
  const char* siblings[] = {"0,2", "1,3", "0,2", "1,3"};
  for (int cpu = 0; cpu < 4; ++cpu) {
    const std::string dir = "sys/devices/system/cpu/cpu" + std::to_string(cpu);
    root.write(dir + "/cpufreq/scaling_governor", std::string(governors[cpu]) + "\n");
    root.write(dir + "/topology/thread_siblings_list", std::string(siblings[cpu]) + "\n");
  }
  root.write("sys/devices/system/cpu/online", "0-3\n");
  root.write("sys/devices/system/cpu/smt/active", "1\n");
  root.write("sys/devices/system/cpu/intel_pstate/no_turbo", "0\n");
  root.write("proc/loadavg", "3.20 2.10 1.00 3/250 4242\n");
  root.write("proc/sys/kernel/randomize_va_space", "2\n");
  root.write("proc/sys/kernel/perf_event_paranoid", "3\n");
  root.write("proc/meminfo",
             "MemTotal:  8000000 kB\nMemAvailable:  1000000 kB\n"
             "SwapTotal:  2097152 kB\nSwapFree:  1048576 kB\n");
  root.write("proc/self/cgroup", "0::/docker/abc\n");
  root.write("sys/fs/cgroup/docker/abc/cpu.max", "150000 100000\n");
  root.write("sys/fs/cgroup/docker/cpu.max", "max 100000\n");
  root.write("proc/1/cgroup", "0::/docker/abc\n");
  root.write(".dockerenv", "");
  root.write("sys/class/dmi/id/product_name", "KVM\n");
  root.write("sys/class/dmi/id/sys_vendor", "Red Hat\n");
  root.write("proc/cpuinfo",
             "processor\t: 0\nmodel name\t: Fake CPU\nflags\t\t: fpu sse hypervisor\n");
}

TEST(DoctorFacts, ReadsAFakeTree) {
  FakeRoot root;
  fill_busy_vm(root);
  const SystemFacts facts = root.probe();
  ASSERT_EQ(facts.governors.size(), 4u);
  EXPECT_EQ(facts.governors[1].cpu, 1);
  EXPECT_EQ(facts.governors[1].governor, "powersave");
  EXPECT_TRUE(facts.cpufreq_present);
  EXPECT_EQ(facts.smt_sibling_groups, (std::vector<std::vector<int>>{{0, 2}, {1, 3}}));
  EXPECT_EQ(facts.smt_active, true);
  EXPECT_EQ(facts.aslr, 2);
  ASSERT_TRUE(facts.swap.has_value());
  EXPECT_EQ(facts.swap->total_bytes, 2097152ull * 1024);
  EXPECT_EQ(facts.swap->used_bytes, 1048576ull * 1024);
  EXPECT_EQ(facts.swap->available_memory_bytes, 1000000ull * 1024);
  ASSERT_TRUE(facts.cpu_quota.has_value());
  EXPECT_DOUBLE_EQ(*facts.cpu_quota, 1.5);
  EXPECT_EQ(facts.virtualization.vm, "kvm");
  EXPECT_EQ(facts.virtualization.container, "docker");
  EXPECT_GE(facts.virtualization.evidence.size(), 3u);
  EXPECT_TRUE(facts.allowed_cpus.empty());  // not live
  // The machine context comes from the same tree.
  EXPECT_EQ(facts.machine.cpu_model, "Fake CPU");
  EXPECT_EQ(facts.machine.turbo_enabled, true);
  EXPECT_EQ(facts.machine.perf_event_paranoid, 3);
  ASSERT_TRUE(facts.machine.load_average.has_value());
  EXPECT_DOUBLE_EQ((*facts.machine.load_average)[0], 3.2);
}

TEST(DoctorFacts, EmptyTreeIsAllUnknown) {
  FakeRoot root;
  const SystemFacts facts = root.probe();
  EXPECT_TRUE(facts.governors.empty());
  EXPECT_FALSE(facts.cpufreq_present);
  EXPECT_TRUE(facts.smt_sibling_groups.empty());
  EXPECT_FALSE(facts.aslr.has_value());
  EXPECT_FALSE(facts.swap.has_value());
  EXPECT_FALSE(facts.cpu_quota.has_value());
  EXPECT_TRUE(facts.virtualization.vm.empty());
  EXPECT_TRUE(facts.virtualization.container.empty());
}

TEST(DoctorFacts, CgroupV1Quota) {
  FakeRoot root;
  root.write("proc/self/cgroup", "4:cpu,cpuacct:/ci/job\n0::/\n");
  root.write("sys/fs/cgroup/cpu/ci/job/cpu.cfs_quota_us", "50000\n");
  root.write("sys/fs/cgroup/cpu/ci/job/cpu.cfs_period_us", "100000\n");
  root.write("sys/fs/cgroup/cpu/cpu.cfs_quota_us", "-1\n");
  root.write("sys/fs/cgroup/cpu/cpu.cfs_period_us", "100000\n");
  const SystemFacts facts = root.probe();
  ASSERT_TRUE(facts.cpu_quota.has_value());
  EXPECT_DOUBLE_EQ(*facts.cpu_quota, 0.5);
}

TEST(DoctorFacts, ParsersOnFixedText) {
  EXPECT_EQ(parse_cpu_list("0-2,5\n"), (std::vector<int>{0, 1, 2, 5}));
  EXPECT_TRUE(parse_cpu_list("3-1").empty());
  EXPECT_TRUE(parse_cpu_list("x").empty());
  EXPECT_EQ(format_cpu_list({0, 1, 2, 5, 7, 8}), "0-2,5,7-8");
  EXPECT_EQ(format_cpu_list({}), "");
  EXPECT_FALSE(parse_swap("MemTotal: 1 kB\n").has_value());
  EXPECT_EQ(parse_swap("SwapTotal: 0 kB\nSwapFree: 0 kB\n")->used_bytes, 0u);
  EXPECT_DOUBLE_EQ(*parse_cpu_max("200000 100000\n"), 2.0);
  EXPECT_FALSE(parse_cpu_max("max 100000").has_value());
  EXPECT_FALSE(parse_cpu_max("garbage").has_value());
  const auto times = parse_cpu_times("cpu  100 0 50 800 10 0 5 35 0 0\ncpu0 1 2 3 4\n");
  ASSERT_TRUE(times.has_value());
  EXPECT_EQ(times->total, 1000u);
  EXPECT_EQ(times->steal, 35u);
  EXPECT_FALSE(parse_cpu_times("intr 1 2 3").has_value());
  EXPECT_EQ(vm_from_dmi("Standard PC (Q35 + ICH9, 2009)", "QEMU"), "qemu");
  EXPECT_EQ(vm_from_dmi("VMware Virtual Platform", "VMware, Inc."), "vmware");
  EXPECT_EQ(vm_from_dmi("Virtual Machine", "Microsoft Corporation"), "microsoft");
  EXPECT_EQ(vm_from_dmi("PowerEdge R640", "Dell Inc."), "");
  EXPECT_EQ(container_from_cgroup("12:cpu:/kubepods/burstable/pod1\n"), "kubernetes");
  EXPECT_EQ(container_from_cgroup("0::/init.scope\n"), "");
}

const Finding& find(const std::vector<Finding>& findings, const std::string& check) {
  for (const Finding& f : findings) {
    if (f.check == check) return f;
  }
  throw std::runtime_error("no finding " + check);
}

TEST(DoctorFindings, BusyVmGetsWarningsWithAdvice) {
  FakeRoot root;
  fill_busy_vm(root);
  SystemFacts facts = root.probe();
  facts.allowed_cpus = {0, 1, 2, 3};
  facts.machine.perf_instructions_available = false;
  facts.machine.perf_error = "Permission denied: not permitted";
  const std::vector<Finding> findings = diagnose(facts);

  const Finding& governor = find(findings, "governor");
  EXPECT_EQ(governor.level, FindingLevel::warn);
  EXPECT_THAT(governor.detail, HasSubstr("performance on cpu 0,3"));
  EXPECT_THAT(governor.detail, HasSubstr("powersave on cpu 1-2"));
  EXPECT_THAT(governor.advice, HasSubstr("cpupower frequency-set -g performance"));
  EXPECT_EQ(find(findings, "turbo").level, FindingLevel::warn);
  const Finding& load = find(findings, "load");
  EXPECT_EQ(load.level, FindingLevel::warn);
  EXPECT_THAT(load.advice, HasSubstr("load 3.2 on 4 CPU(s): stop other jobs"));
  const Finding& cpus = find(findings, "cpus");
  EXPECT_EQ(cpus.level, FindingLevel::warn);
  EXPECT_THAT(cpus.detail, HasSubstr("quota 1.50 CPUs"));
  const Finding& smt = find(findings, "smt");
  EXPECT_EQ(smt.level, FindingLevel::warn);
  EXPECT_THAT(smt.detail, HasSubstr("CPUs 0,2 are SMT siblings"));
  const Finding& perf = find(findings, "perf");
  EXPECT_EQ(perf.level, FindingLevel::warn);
  EXPECT_THAT(perf.advice, HasSubstr("kernel.perf_event_paranoid=1"));
  EXPECT_EQ(find(findings, "aslr").level, FindingLevel::ok);
  const Finding& swap = find(findings, "swap");
  EXPECT_EQ(swap.level, FindingLevel::warn);
  EXPECT_THAT(swap.detail, HasSubstr("1024 MiB of 2048 MiB swap in use"));
  const Finding& virt = find(findings, "virtualization");
  EXPECT_EQ(virt.level, FindingLevel::info);
  EXPECT_THAT(virt.detail, HasSubstr("virtual machine (kvm), container (docker)"));
}

TEST(DoctorFindings, QuietBareMetalIsAllOk) {
  SystemFacts facts;
  facts.machine.online_cpus = 4;
  facts.machine.load_average = std::array<double, 3>{0.1, 0.2, 0.3};
  facts.machine.turbo_enabled = false;
  facts.machine.perf_instructions_available = true;
  facts.machine.perf_event_paranoid = 1;
  facts.cpufreq_present = true;
  for (int cpu = 0; cpu < 4; ++cpu) facts.governors.push_back({cpu, "performance"});
  facts.allowed_cpus = {0, 1, 2, 3};
  facts.smt_sibling_groups = {{0, 2}};
  facts.aslr = 2;
  facts.swap = SwapUsage{0, 0, std::nullopt};
  facts.allowed_cpus = {0, 1, 3};  // CPU 2 (0's sibling) is not allowed
  DoctorReport report{facts, diagnose(facts), std::nullopt, "", ""};
  for (const Finding& f : report.findings) {
    EXPECT_NE(f.level, FindingLevel::warn) << f.check << ": " << f.detail;
  }
  EXPECT_EQ(find(report.findings, "smt").level, FindingLevel::info);
  EXPECT_EQ(report.warnings(), 0u);
}

TEST(DoctorFindings, IdleCpusThatCannotBeHeldPollingAreAWarningWithTheWay) {
  SystemFacts facts;
  EXPECT_EQ(find(diagnose(facts), "idle").level, FindingLevel::info);  // a fake root: not asked
  facts.idle_polling = IdlePolling{true, ""};
  EXPECT_EQ(find(diagnose(facts), "idle").level, FindingLevel::ok);
  facts.idle_polling = IdlePolling{false, "cannot open /dev/cpu_dma_latency: Permission denied"};
  const Finding refused = find(diagnose(facts), "idle");
  EXPECT_EQ(refused.level, FindingLevel::warn);
  EXPECT_THAT(refused.detail, HasSubstr("(cannot open /dev/cpu_dma_latency: Permission denied)"));
  EXPECT_THAT(refused.advice, HasSubstr("udev rule"));
}

TEST(DoctorFindings, VmWithoutCpufreqOrCountersSaysSo) {
  SystemFacts facts;
  facts.machine.online_cpus = 2;
  facts.virtualization.vm = "kvm";
  facts.machine.perf_error =
      "No such file or directory: no hardware instruction counter (virtual "
      "machine or unsupported PMU)";
  facts.machine.perf_event_paranoid = 2;
  const std::vector<Finding> findings = diagnose(facts);
  const Finding& governor = find(findings, "governor");
  EXPECT_EQ(governor.level, FindingLevel::info);
  EXPECT_THAT(governor.detail, HasSubstr("virtual machine"));
  EXPECT_EQ(find(findings, "perf").level, FindingLevel::info);
  EXPECT_THAT(find(findings, "turbo").detail, HasSubstr("the host decides"));
}

std::vector<NoiseRound> rounds(const std::vector<std::pair<double, double>>& seconds) {
  std::vector<NoiseRound> out;
  for (const auto& [a, b] : seconds) out.push_back({{a, a * 0.99}, {b, b * 0.99}});
  return out;
}

TEST(DoctorNoise, StatisticsOfFixedRounds) {
  // Ratios a/b: 1.0, 1.1, 0.9 -> mean 1.0, sample CV 0.1, spread 1.1/0.9.
  const NoiseScore score = summarize_noise(rounds({{1.0, 1.0}, {1.1, 1.0}, {0.9, 1.0}}));
  EXPECT_EQ(score.rounds, 3u);
  EXPECT_NEAR(score.ratio_cv, 0.1, 1e-12);
  EXPECT_NEAR(score.ratio_spread, 1.1 / 0.9, 1e-12);
  EXPECT_NEAR(score.aa_ratio, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(score.seconds.median, 1.0);
  EXPECT_NEAR(score.seconds.spread, 1.1 / 0.9, 1e-12);
  EXPECT_NEAR(score.cpu_seconds.median, 0.99, 1e-12);
  EXPECT_EQ(score.grade, NoiseGrade::noisy);
  EXPECT_THAT(score.advice(), HasSubstr("10.0%"));
  EXPECT_NEAR(score.waiting_fraction(), 0.01, 1e-12);  // CPU seconds are 99% of the time
}

TEST(DoctorNoise, Grades) {
  EXPECT_EQ(grade_noise(0.005), NoiseGrade::good);
  EXPECT_EQ(grade_noise(0.02), NoiseGrade::fair);
  EXPECT_EQ(grade_noise(0.05), NoiseGrade::noisy);
  const NoiseScore steady = summarize_noise(rounds({{1.0, 1.0}, {2.0, 2.0}, {1.5, 1.5}}));
  EXPECT_DOUBLE_EQ(steady.ratio_cv, 0.0);  // the machine's speed moved, the ratio did not
  EXPECT_GT(steady.seconds.cv, 0.2);
  EXPECT_EQ(steady.grade, NoiseGrade::good);
  EXPECT_THROW(summarize_noise(rounds({{1.0, 1.0}})), std::invalid_argument);
  EXPECT_THROW(summarize_noise(rounds({{1.0, 1.0}, {0.0, 1.0}})), std::invalid_argument);
}

TEST(DoctorReport, TextAndJsonCarryFindingsAndNoise) {
  SystemFacts facts;
  facts.machine.hostname = "runner-7";
  facts.machine.cpu_model = "Fake CPU";
  facts.governors = {{0, "powersave"}};
  DoctorReport report{facts, diagnose(facts), summarize_noise(rounds({{1.0, 1.0}, {1.0, 1.01}})),
                      "", "raygate-baseline 0.1.0"};
  const std::string text = doctor_text(report);
  EXPECT_THAT(text, HasSubstr("runner-7 (Fake CPU)"));
  EXPECT_THAT(text, HasSubstr("warn  governor"));
  EXPECT_THAT(text, HasSubstr("noise score  good"));
  const nlohmann::json json = doctor_json(report);
  EXPECT_EQ(json["noise"]["grade"], "good");
  EXPECT_EQ(json["system"]["governors"]["cpu0"], "powersave");
  EXPECT_EQ(json["checks"][0]["check"], "governor");
  EXPECT_GE(json["warnings"].get<int>(), 1);
  report.noise.reset();
  report.noise_error = "raygate-baseline not found";
  EXPECT_THAT(doctor_text(report), HasSubstr("noise: not measured: raygate-baseline not found"));
  EXPECT_TRUE(doctor_json(report)["noise"].is_null());
}

}  // namespace
}  // namespace raygate
