// The adapter hash (the build cache key) and reported-time parsing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "adapter/adapter.h"
#include "core/fs.h"

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

// A progress bar redrawn with \r and never ended is one line of megabytes: the matcher, which
// recurses a frame per character, sees only its end, where the report is.
TEST(ReportedTime, AMegabyteLineIsSearchedAtItsEnd) {
  const Adapter a = reported("render time: ([0-9.]+) s", "s");
  const std::string line = std::string(4 << 20, '#') + " render time: 1.5 s";
  EXPECT_EQ(parse_reported_seconds(a, line), 1.5);
  EXPECT_EQ(parse_reported_seconds(a, std::string(4 << 20, '.')), std::nullopt);
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

// "h:m:s": a clock time, as Blender prints its render time.
TEST(ReportedTime, ClockTime) {
  const Adapter a = reported("^Took ([0-9:.]+)$", "h:m:s");
  EXPECT_DOUBLE_EQ(*parse_reported_seconds(a, "Took 00:01.23\n"), 1.23);
  EXPECT_DOUBLE_EQ(*parse_reported_seconds(a, "Took 2.5\n"), 2.5);
  EXPECT_DOUBLE_EQ(*parse_reported_seconds(a, "Took 01:02:03.5\n"), 3723.5);
  for (const char* bad : {"Took 1:2:3:4\n", "Took 1.5:00\n", "Took 00:\n", "Took :01\n",
                          "Took 00::01\n", "Took ..\n"}) {
    EXPECT_EQ(parse_reported_seconds(a, bad), std::nullopt) << bad;
  }
}

// The shipped Cycles adapter reads Blender's own render time from the line Blender 3.4 prints
// after the frame (the tail of a real log, 48x48, 16 spp), not the progress lines' "Time:".
TEST(ReportedTime, ShippedBlenderAdapterReadsTheFramesTime) {
  const std::filesystem::path file =
      std::filesystem::path(RAYGATE_SOURCE_DIR) / "adapters" / "blender-cycles.json";
  const Adapter blender = parse_adapter(read_file(file), file.string());
  ASSERT_EQ(blender.timing.source, TimingSource::reported);
  const std::string tail =
      "Fra:1 Mem:10.94M (Peak 11.16M) | Time:00:00.40 | Remaining:00:00.18 | Mem:0.85M, "
      "Peak:0.85M | Scene, ViewLayer | Sample 1/16\n"
      "Fra:1 Mem:10.98M (Peak 11.16M) | Time:00:00.51 | Mem:0.85M, Peak:0.85M | Scene, "
      "ViewLayer | Finished\n"
      "Saved: '/tmp/run/work/image.exr'\n"
      " Time: 00:00.52 (Saving: 00:00.00)\n"
      "\n\nBlender quit\n";
  EXPECT_DOUBLE_EQ(*parse_reported_seconds(blender, tail), 0.52);
  EXPECT_DOUBLE_EQ(*parse_reported_seconds(blender, " Time: 01:05.25 (Saving: 00:00.01)\n"), 65.25);
  // A log cut before the frame finished has no render time: the run fails, not a wrong one.
  EXPECT_EQ(parse_reported_seconds(blender, tail.substr(0, tail.find("Saved"))), std::nullopt);
}

TEST(ReportedTime, ProcessTimingHasNoReport) {
  EXPECT_EQ(parse_reported_seconds(parse_adapter(kAdapter, "a.json"), "time: 1"), std::nullopt);
}

}  // namespace
}  // namespace raygate
