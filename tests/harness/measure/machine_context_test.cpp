// Machine context: filled on this machine, tolerant of a machine without /proc or /sys (a fake
// root), and written to JSON with every field present.
#include "measure/machine_context.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/fs.h"

namespace raygate {
namespace {

const char* const kFields[] = {"cpu_model",
                               "logical_cores",
                               "online_cpus",
                               "allowed_cpus",
                               "scaling_governors",
                               "turbo_enabled",
                               "kernel",
                               "compiler",
                               "load_average",
                               "total_memory_bytes",
                               "perf_instructions_available",
                               "perf_error",
                               "perf_event_paranoid",
                               "hostname",
                               "ci"};

TEST(MeasureMachineContext, FilledOnThisMachine) {
  const MachineContext context = probe_machine_context();
  EXPECT_FALSE(context.cpu_model.empty());
  ASSERT_TRUE(context.logical_cores.has_value());
  EXPECT_GE(*context.logical_cores, 1);
  ASSERT_TRUE(context.online_cpus.has_value());
  EXPECT_GE(*context.online_cpus, 1);
  EXPECT_NE(context.kernel.find("Linux"), std::string::npos);
  EXPECT_FALSE(context.compiler.empty());
  EXPECT_FALSE(context.hostname.empty());
  EXPECT_TRUE(context.load_average.has_value());
  ASSERT_TRUE(context.total_memory_bytes.has_value());
  EXPECT_GT(*context.total_memory_bytes, 0u);
  // Either way the probe says which: a refusal carries the kernel's reason.
  EXPECT_EQ(context.perf_instructions_available, context.perf_error.empty());
}

TEST(MeasureMachineContext, JsonHasEveryField) {
  const nlohmann::json json = probe_machine_context();
  for (const char* field : kFields) EXPECT_TRUE(json.contains(field)) << field;
  EXPECT_EQ(json.size(), std::size(kFields));
  EXPECT_TRUE(json["cpu_model"].is_string());
  EXPECT_TRUE(json["scaling_governors"].is_array());
}

TEST(MeasureMachineContext, MissingFilesLeaveFieldsUnknown) {
  TempDir empty_root("raygate-measure");
  const MachineContext context = probe_machine_context(empty_root.path());
  EXPECT_TRUE(context.cpu_model.empty());
  EXPECT_FALSE(context.logical_cores.has_value());
  EXPECT_FALSE(context.online_cpus.has_value());
  EXPECT_TRUE(context.scaling_governors.empty());
  EXPECT_FALSE(context.turbo_enabled.has_value());
  EXPECT_FALSE(context.load_average.has_value());
  EXPECT_FALSE(context.total_memory_bytes.has_value());
  const nlohmann::json json = context;
  EXPECT_TRUE(json["cpu_model"].is_null());
  EXPECT_TRUE(json["turbo_enabled"].is_null());
  EXPECT_EQ(json.size(), std::size(kFields));
}

TEST(MeasureMachineContext, FakeSysTree) {
  TempDir root("raygate-measure");
  const auto cpu = root.path() / "sys/devices/system/cpu";
  write_file_atomically(root.path() / "proc/cpuinfo",
                        "processor\t: 0\nmodel name\t: Test CPU @ 3.00GHz\n\n"
                        "processor\t: 1\nmodel name\t: Test CPU @ 3.00GHz\n");
  write_file_atomically(cpu / "online", "0-1\n");
  write_file_atomically(cpu / "cpu0/cpufreq/scaling_governor", "performance\n");
  write_file_atomically(cpu / "cpu1/cpufreq/scaling_governor", "powersave\n");
  write_file_atomically(cpu / "cpufreq/boost", "1\n");          // not a cpuN directory
  write_file_atomically(cpu / "intel_pstate/no_turbo", "1\n");  // wins over boost
  const MachineContext context = probe_machine_context(root.path());
  EXPECT_EQ(context.cpu_model, "Test CPU @ 3.00GHz");
  EXPECT_EQ(context.logical_cores, 2);
  EXPECT_EQ(context.online_cpus, 2);
  EXPECT_EQ(context.scaling_governors, (std::vector<std::string>{"performance", "powersave"}));
  EXPECT_EQ(context.turbo_enabled, false);
}

TEST(MeasureMachineContext, BoostWithoutIntelPstate) {
  TempDir root("raygate-measure");
  write_file_atomically(root.path() / "sys/devices/system/cpu/cpufreq/boost", "1\n");
  EXPECT_EQ(probe_machine_context(root.path()).turbo_enabled, true);
}

TEST(MeasureMachineContext, Parsers) {
  EXPECT_EQ(count_cpu_list("0-3,6,8-9\n"), 7);
  EXPECT_EQ(count_cpu_list("0"), 1);
  EXPECT_FALSE(count_cpu_list("").has_value());
  EXPECT_FALSE(count_cpu_list("3-1").has_value());
  EXPECT_FALSE(count_cpu_list("abc").has_value());
  EXPECT_EQ(parse_mem_total_bytes("MemTotal:       16318480 kB\nMemFree: 1 kB\n"),
            16318480ull * 1024);
  EXPECT_FALSE(parse_mem_total_bytes("MemFree: 1 kB\n").has_value());
  const auto load = parse_load_average("0.52 0.40 0.33 1/123 4567\n");
  ASSERT_TRUE(load.has_value());
  EXPECT_DOUBLE_EQ((*load)[2], 0.33);
  EXPECT_FALSE(parse_load_average("").has_value());
  EXPECT_EQ(parse_cpu_model("processor : 0\nProcessor : ARMv7 rev 4 (v7l)\n"), "ARMv7 rev 4 (v7l)");
  EXPECT_EQ(parse_cpu_model(""), "");
  EXPECT_TRUE(is_ci_value("true"));
  EXPECT_TRUE(is_ci_value("TRUE"));
  EXPECT_TRUE(is_ci_value("1"));
  EXPECT_FALSE(is_ci_value("false"));
  EXPECT_FALSE(is_ci_value(nullptr));
}

}  // namespace
}  // namespace raygate
