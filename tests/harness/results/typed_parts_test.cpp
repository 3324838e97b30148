// The typed settings and scaling of a results document (results/measurement_settings.h,
// results/scaling_record.h): a document written by an earlier raygate (the store's fixture from
// main 60ebc9f) reads into the typed fields and writes back the same JSON; fields a document
// lacks stay absent; keys this raygate does not know survive; a wrong value is a UsageError with
// its JSON path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"
#include "results/results.h"
#include "results/scaling_json.h"
#include "results/settings_json.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kFixtures = fs::path(RAYGATE_SOURCE_DIR) / "tests/harness/store/fixtures";

json old_document(const char* name) { return read_json_file(kFixtures / name); }

std::string usage_error(const json& document) {
  try {
    results_from_json(document, "doc.json");
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TypedSettings, ADocumentOfAnEarlierRaygateReadsIntoTheFields) {
  const json file = old_document("main-60ebc9f-compare.json");
  const ResultsDocument d = results_from_json(file, "compare.json");
  const MeasurementSettings& s = d.settings;
  EXPECT_EQ(s.schedule, ScheduleKind::alternate);
  EXPECT_EQ(s.warmup_runs, 0);
  EXPECT_EQ(s.pin_cpus, std::vector<int>{});
  EXPECT_EQ(s.round_cpus, (std::vector<int>{0, 1}));
  EXPECT_EQ(s.baseline_rounds, 3u);
  EXPECT_EQ(s.max_rounds, 3u);
  EXPECT_EQ(s.max_minutes, 8.0);
  EXPECT_EQ(s.timing_source, TimingSource::process);
  EXPECT_EQ(s.tracer_clock, "process-cpu");
  EXPECT_EQ(s.baseline_clock, "process-cpu");
  EXPECT_EQ(s.metric_by_threads, true);
  EXPECT_EQ(s.goldens, "none");
  EXPECT_EQ(s.max_slowdown, 0.03);
  EXPECT_EQ(s.family_significance, 0.01);
  EXPECT_FALSE(s.simulated());
  // Written before these were recorded: absent, not defaulted.
  EXPECT_FALSE(s.pinned_by.has_value());
  EXPECT_FALSE(s.repeats.has_value());
  EXPECT_FALSE(s.max_memory_increase.has_value());
  EXPECT_FALSE(s.shard.has_value());
  EXPECT_TRUE(s.unknown.is_null());
  EXPECT_FALSE(d.scaling.has_value());
}

TEST(TypedSettings, EarlierDocumentsWriteBackByteForByte) {
  for (const char* name : {"main-60ebc9f-run.json", "main-60ebc9f-compare.json"}) {
    const json file = old_document(name);
    const json written = to_json(results_from_json(file, name));
    EXPECT_EQ(written.at("settings").dump(), file.at("settings").dump()) << name;
    EXPECT_EQ(written.dump(), file.dump()) << name;
  }
}

TEST(TypedSettings, AbsentFieldsStayAbsentAndUnknownKeysAreKept) {
  json file = old_document("main-60ebc9f-run.json");
  file["settings"] = {{"schedule", "duet"},
                      {"from_a_newer_raygate", {{"knob", 3}, {"words", {"a", "b"}}}},
                      {"another", nullptr}};
  const ResultsDocument d = results_from_json(file, "newer.json");
  EXPECT_EQ(d.settings.schedule, ScheduleKind::duet);
  EXPECT_FALSE(d.settings.tracer_clock.has_value());
  EXPECT_EQ(d.settings.unknown.at("from_a_newer_raygate").at("knob"), 3);
  EXPECT_EQ(to_json(d).at("settings"), file.at("settings"));
  // A reader falls back to what applied when a field was not recorded.
  EXPECT_EQ(d.settings.max_slowdown.value_or(0.03), 0.03);
}

TEST(TypedSettings, NullSettingsReadAsNone) {
  json file = old_document("main-60ebc9f-run.json");
  file["settings"] = nullptr;
  const ResultsDocument d = results_from_json(file, "null.json");
  EXPECT_EQ(d.settings, MeasurementSettings{});
  EXPECT_EQ(to_json(d).at("settings"), json::object());
}

TEST(TypedSettings, AWrongValueNamesItsPath) {
  const json file = old_document("main-60ebc9f-run.json");
  const auto with = [&](const char* key, const json& value) {
    json bad = file;
    bad["settings"][key] = value;
    return usage_error(bad);
  };
  EXPECT_NE(with("threads", "four").find("doc.json: $.settings.threads: expected a whole number"),
            std::string::npos)
      << with("threads", "four");
  EXPECT_NE(with("schedule", "zigzag")
                .find("$.settings.schedule: unknown schedule \"zigzag\" (\"alternate\", \"duet\")"),
            std::string::npos)
      << with("schedule", "zigzag");
  EXPECT_NE(with("timing_source", "pmu").find("$.settings.timing_source: unknown timing source"),
            std::string::npos);
  EXPECT_NE(with("round_cpus", json::array({0, "x"})).find("$.settings.round_cpus[1]"),
            std::string::npos);
  EXPECT_NE(with("max_rounds", -1).find("$.settings.max_rounds"), std::string::npos);
  EXPECT_NE(with("shard", {{"index", 3}, {"count", 2}})
                .find("$.settings.shard: index 3 of count 2 is not a shard"),
            std::string::npos);
  EXPECT_NE(with("merged_shards", json::array({{{"index", 1}}}))
                .find("$.settings.merged_shards[0]: missing required key 'count'"),
            std::string::npos)
      << with("merged_shards", json::array({{{"index", 1}}}));
  json not_object = file;
  not_object["settings"] = 3;
  EXPECT_NE(usage_error(not_object).find("doc.json: $.settings: expected an object"),
            std::string::npos)
      << usage_error(not_object);
}

TEST(TypedSettings, IdleCpusAreWordsAndARefusalKeepsItsReason) {
  json file = old_document("main-60ebc9f-compare.json");
  EXPECT_FALSE(results_from_json(file, "c.json").settings.cpu_idle.has_value());
  file["settings"]["cpu_idle"] = "os";
  file["settings"]["cpu_idle_refused"] = "cannot open /dev/cpu_dma_latency: Permission denied";
  const ResultsDocument d = results_from_json(file, "c.json");
  EXPECT_EQ(d.settings.cpu_idle, CpuIdle::os);
  EXPECT_EQ(d.settings.cpu_idle_refused, "cannot open /dev/cpu_dma_latency: Permission denied");
  EXPECT_EQ(to_json(d).at("settings"), file.at("settings"));
  file["settings"]["cpu_idle"] = "poll";
  EXPECT_EQ(results_from_json(file, "c.json").settings.cpu_idle, CpuIdle::poll);
  file["settings"]["cpu_idle"] = "halt";
  EXPECT_NE(usage_error(file).find("$.settings.cpu_idle: unknown cpu idle \"halt\" (\"os\", "
                                   "\"poll\")"),
            std::string::npos)
      << usage_error(file);
}

TEST(TypedSettings, TheGateReadsTheRecordedLimits) {
  json file = old_document("main-60ebc9f-compare.json");
  file["settings"]["max_slowdown"] = 0.07;
  EXPECT_EQ(results_from_json(file, "c.json").settings.max_slowdown, 0.07);
  file["settings"]["timing_source"] = "simulated";
  EXPECT_TRUE(results_from_json(file, "c.json").settings.simulated());
}

PowerFit line_fit(double exponent) {
  PowerFit fit;
  fit.points = 4;
  fit.exponent = exponent;
  fit.exponent_interval = {exponent - 0.1, exponent + 0.1};
  fit.r_squared = 0.99;
  fit.quality = FitQuality::power_law;
  fit.growth_exponent = exponent;
  return fit;
}

ScalingAnalysis one_family() {
  FamilyScaling family;
  family.family = "balls";
  family.series_id = "0123456789abcdef";
  family.points = {{"balls-1",
                    1,
                    11,
                    0.01,
                    {{Role::base, 0.02}, {Role::head, 0.03}},
                    {{Role::base, 2.0}, {Role::head, 3.0}},
                    0.5,
                    Interval{0.4, 0.6}}};
  family.baseline = line_fit(1.0);
  family.roles[Role::base] = {line_fit(1.0), line_fit(0.0)};
  ExponentChange change;
  change.fit = line_fit(0.3);
  change.fit.r_squared = std::nan("");  // written null, read back as NaN
  change.verdict = ChangeVerdict::regressed;
  change.limit = 0.1;
  change.slowdown = 0.03;
  change.crossing = Projection{2, 91, 0.05};
  family.change = change;
  return {{family}, 0.1};
}

TEST(TypedScaling, ParsedOnceWithTheDocumentAndWrittenBackTheSame) {
  json file = old_document("main-60ebc9f-compare.json");
  file["scaling"] = to_json(one_family());
  const ResultsDocument d = results_from_json(file, "c.json");
  ASSERT_TRUE(d.scaling.has_value());
  ASSERT_EQ(d.scaling->families.size(), 1u);
  const FamilyScaling& balls = d.scaling->families[0];
  ASSERT_TRUE(balls.change.has_value());
  EXPECT_EQ(balls.change->verdict, ChangeVerdict::regressed);
  EXPECT_TRUE(std::isnan(balls.change->fit.r_squared));
  EXPECT_EQ(balls.points[0].ratios.at(Role::head), 3.0);
  EXPECT_EQ(to_json(d).at("scaling").dump(), file.at("scaling").dump());
}

TEST(TypedScaling, AWrongValueNamesItsPath) {
  json file = old_document("main-60ebc9f-compare.json");
  file["scaling"] = to_json(one_family());
  file["scaling"]["families"][0]["change"]["verdict"] = "WORSE";
  EXPECT_NE(usage_error(file).find("$.scaling.families[0].change.verdict: unknown verdict"),
            std::string::npos)
      << usage_error(file);
  file["scaling"] = {{"families", json::array()}};
  EXPECT_NE(usage_error(file).find("$.scaling: missing required key 'max_exponent_increase'"),
            std::string::npos)
      << usage_error(file);
}

}  // namespace
}  // namespace raygate
