// The machine-drift rule: the baseline's seconds moved on most scenes against this machine's
// earlier documents while the ratios held -> a note about the machine; anything else -> none.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "store/drift.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;

struct Measured {
  std::int64_t document;
  std::string scene;
  double ratio;
  double baseline_seconds;
  std::string host = "runner-1";
};

std::vector<HistoryRow> rows_of(const std::vector<Measured>& measured) {
  std::vector<HistoryRow> rows;
  for (const Measured& m : measured) {
    HistoryRow row;
    row.document_id = m.document;
    row.measured_at = "2026-04-0" + std::to_string(m.document) + "T00:00:00Z";
    row.role = "tracer";
    row.short_sha = "abc000" + std::to_string(m.document);
    row.scene_id = m.scene;
    row.ratio = m.ratio;
    row.ratio_lower = m.ratio * 0.99;
    row.ratio_upper = m.ratio * 1.01;
    row.baseline_median_seconds = m.baseline_seconds;
    row.machine_hostname = m.host;
    row.machine_cpu_model = "Test CPU";
    row.baseline_sha256 = std::string(64, 'b');
    rows.push_back(row);
  }
  return rows;
}

// Two earlier documents at 1 s per scene, then a latest one at `latest_seconds` with `ratio`.
std::vector<Measured> history_then(double latest_seconds, double ratio, int moved_scenes = 3) {
  std::vector<Measured> m;
  const char* scenes[] = {"balls", "gears", "tetra"};
  for (int doc = 1; doc <= 2; ++doc) {
    for (const char* scene : scenes) m.push_back({doc, scene, 0.5, 1.0});
  }
  for (int i = 0; i < 3; ++i)
    m.push_back({3, scenes[i], ratio, i < moved_scenes ? latest_seconds : 1.0});
  return m;
}

TEST(MachineDrift, BaselineFasterWhileRatiosHeldIsTheMachine) {
  const auto drift = detect_machine_drift(rows_of(history_then(0.85, 0.505)));
  ASSERT_TRUE(drift);
  EXPECT_TRUE(drift->faster());
  EXPECT_EQ(drift->scenes_compared, 3u);
  EXPECT_EQ(drift->scenes_drifted, 3u);
  EXPECT_NEAR(drift->median_baseline_change, -0.15, 1e-12);
  EXPECT_EQ(drift->document_id, 3);
  const std::string note = describe_drift(*drift);
  EXPECT_THAT(note, HasSubstr("runner-1 (Test CPU)"));
  EXPECT_THAT(note, HasSubstr("15.0% less time"));
  EXPECT_THAT(note, HasSubstr("on 3 of 3 scenes"));
  EXPECT_THAT(note, HasSubstr("the machine got faster, not the code"));
}

TEST(MachineDrift, BaselineSlowerIsTheMachineGettingSlower) {
  const auto drift = detect_machine_drift(rows_of(history_then(1.2, 0.5)));
  ASSERT_TRUE(drift);
  EXPECT_FALSE(drift->faster());
  EXPECT_THAT(describe_drift(*drift), HasSubstr("the machine got slower"));
}

TEST(MachineDrift, RatiosThatMovedTooAreNotBlamedOnTheMachine) {
  EXPECT_FALSE(detect_machine_drift(rows_of(history_then(0.85, 0.6))));
}

TEST(MachineDrift, SmallOrFewMovesAreNoDrift) {
  EXPECT_FALSE(detect_machine_drift(rows_of(history_then(0.97, 0.5))));    // within 5%
  EXPECT_FALSE(detect_machine_drift(rows_of(history_then(0.8, 0.5, 1))));  // 1 of 3 scenes
  EXPECT_TRUE(detect_machine_drift(rows_of(history_then(0.8, 0.5, 2))));   // 2 of 3: most
}

TEST(MachineDrift, OnlyThisMachinesHistoryCounts) {
  std::vector<Measured> m = history_then(0.85, 0.5);
  for (Measured& row : m) {
    if (row.document < 3) row.host = "other-machine";
  }
  EXPECT_FALSE(detect_machine_drift(rows_of(m)));
  EXPECT_FALSE(detect_machine_drift({}));
}

TEST(MachineDrift, TheLatestDocumentIsTheOneJudged) {
  // The fast machine state was earlier; the latest document is back at the usual seconds.
  std::vector<Measured> m = history_then(0.85, 0.5);
  for (const char* scene : {"balls", "gears", "tetra"}) m.push_back({4, scene, 0.5, 1.0});
  EXPECT_FALSE(detect_machine_drift(rows_of(m)));
}

}  // namespace
}  // namespace raygate::test
