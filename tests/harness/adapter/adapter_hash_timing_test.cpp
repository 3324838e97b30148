// The adapter hash (the build cache key) and reported-time parsing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "adapter/adapter.h"

namespace raygate {
namespace {

const char* kAdapter = R"({"name": "t", "scene_format": "nff",
  "run": ["t", "{scene}", "-o", "{image}"], "image": "{image}",
  "timeout_s": {"build": 100, "run": 10}})";

TEST(AdapterHash, IgnoresWhitespaceAndKeyOrder) {
  const std::string reordered = R"({
      "timeout_s": {"run": 10, "build": 100},
      "image":     "{image}",
      "run": [ "t", "{scene}", "-o", "{image}" ],
      "scene_format": "nff", "name": "t" })";
  const std::string hash = adapter_hash(parse_adapter(kAdapter, "a.json"));
  EXPECT_EQ(hash.size(), 64u);
  EXPECT_EQ(adapter_hash(parse_adapter(reordered, "b.json")), hash);
}

TEST(AdapterHash, ChangesWithAnyValue) {
  const std::string hash = adapter_hash(parse_adapter(kAdapter, "a.json"));
  std::string changed = kAdapter;
  changed.replace(changed.find("\"build\": 100"), 12, "\"build\": 101");
  EXPECT_NE(adapter_hash(parse_adapter(changed, "a.json")), hash);
  std::string reordered_argv = kAdapter;
  reordered_argv.replace(reordered_argv.find("\"-o\", \"{image}\""), 15, "\"{image}\", \"-o\"");
  EXPECT_NE(adapter_hash(parse_adapter(reordered_argv, "a.json")), hash);
}

Adapter reported(const std::string& regex, const std::string& unit) {
  return parse_adapter(R"({"name": "t", "scene_format": "nff", "run": ["t", "{scene}"],
    "image": "{workdir}/trace.ppm", "timing": {"source": "reported", "regex": )" +
                           nlohmann::json(regex).dump() + R"(, "unit": ")" + unit + R"("}})",
                       "r.json");
}

TEST(ReportedTime, Seconds) {
  const Adapter a = reported("render time: ([0-9.]+) s", "s");
  EXPECT_EQ(parse_reported_seconds(a, "loading\nrender time: 1.25 s\nbye\n"), 1.25);
}

TEST(ReportedTime, Milliseconds) {
  const Adapter a = reported("took ([0-9]+)ms", "ms");
  EXPECT_DOUBLE_EQ(*parse_reported_seconds(a, "parse took 12ms\r\ntrace took 2500ms\r\n"), 2.5);
}

TEST(ReportedTime, LastReportWins) {
  const Adapter a = reported("time: ([0-9.]+)", "s");
  EXPECT_EQ(parse_reported_seconds(a, "time: 1\ntime: 2\ntime: 3"), 3.0);
}

TEST(ReportedTime, NoMatchOrNoNumberIsNullopt) {
  const Adapter a = reported("render time: ([0-9.a-z]*) s", "s");
  EXPECT_EQ(parse_reported_seconds(a, "nothing here\n"), std::nullopt);
  EXPECT_EQ(parse_reported_seconds(a, ""), std::nullopt);
  EXPECT_EQ(parse_reported_seconds(a, "render time: abc s\n"), std::nullopt);
  EXPECT_EQ(parse_reported_seconds(a, "render time: 1.2.3 s\n"), std::nullopt);
  EXPECT_EQ(parse_reported_seconds(a, "render time:  s\n"), std::nullopt);
}

TEST(ReportedTime, PovRayExampleFromTheReadme) {
  const Adapter a = reported(R"(Trace Time:.*\(([0-9.]+) seconds\))", "s");
  const std::string povray_tail =
      "Render Time:\n  Photon Time:      No photons\n"
      "  Trace Time:       0 hours  0 minutes  2 seconds (2.153 seconds)\n"
      "              using 4 thread(s) with 8.339 CPU-seconds total\n";
  EXPECT_EQ(parse_reported_seconds(a, povray_tail), 2.153);
}

TEST(ReportedTime, ProcessTimingHasNoReport) {
  EXPECT_EQ(parse_reported_seconds(parse_adapter(kAdapter, "a.json"), "time: 1"), std::nullopt);
}

}  // namespace
}  // namespace raygate
