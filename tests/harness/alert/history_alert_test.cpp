// Alerts from history rows made by hand: a series that got 10% slower at its 9th commit is in
// alert with the range 8..9, a flat one and one that got faster are not, the scene's policy
// limit decides what counts, and the action decides the exit code.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/core.h>

#include "alert/history_alert.h"
#include "core/error.h"

namespace raygate {
namespace {

using ::testing::HasSubstr;

// Commits 1..n of one series, newest first as ResultsStore::history gives them; ratio(i).
std::vector<HistoryRow> rows_of(const std::string& scene, std::size_t n,
                                double (*ratio)(std::size_t)) {
  std::vector<HistoryRow> rows;
  for (std::size_t i = n; i >= 1; --i) {
    HistoryRow row;
    row.sha = fmt::format("{:040}", i);
    row.short_sha = fmt::format("c{:02}", i);
    row.subject = fmt::format("commit {}", i);
    row.scene_id = scene;
    row.series_id = "series-" + scene;
    row.repository_key = "root:abc";
    row.adapter_name = "cmake-nff";
    row.suite = "ci";
    row.ratio = ratio(i);
    rows.push_back(row);
  }
  return rows;
}

double wobble(std::size_t i) { return 0.01 * std::sin(1.7 * static_cast<double>(i)); }
double flat(std::size_t i) { return 0.8 * (1 + wobble(i)); }
double slower_at_9(std::size_t i) { return (i >= 9 ? 0.88 : 0.8) * (1 + wobble(i)); }
double faster_at_9(std::size_t i) { return (i >= 9 ? 0.72 : 0.8) * (1 + wobble(i)); }
double two_percent_at_9(std::size_t i) { return (i >= 9 ? 0.816 : 0.8) * (1 + 0.002 * wobble(i)); }

std::vector<HistoryRow> join(std::vector<HistoryRow> a, const std::vector<HistoryRow>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(HistoryAlert, RegressionAtCommitNineNamesRangeEightToNine) {
  const AlertJudgement j =
      judge_history(join(rows_of("balls", 15, slower_at_9), rows_of("gears", 15, flat)),
                    GatePolicy{}, {}, AlertAction::fail);
  ASSERT_EQ(j.series.size(), 2u);
  EXPECT_EQ(j.alerts(), 1u);
  EXPECT_EQ(j.exit_code(), 1);
  const SeriesJudgement& balls = j.series[0];
  ASSERT_EQ(balls.column.scene_id, "balls");
  ASSERT_TRUE(balls.alert);
  EXPECT_EQ(balls.alert->last_before.short_sha, "c08");
  EXPECT_EQ(balls.alert->first_after.short_sha, "c09");
  EXPECT_EQ(balls.alert->commits_after, 7u);
  EXPECT_NEAR(balls.alert->change.relative_change(), 0.10, 0.01);
  EXPECT_EQ(balls.points, 15u);
  EXPECT_FALSE(j.series[1].alert);
  EXPECT_TRUE(j.series[1].changes.empty());

  const std::string text = alert_text(j);
  EXPECT_THAT(text, HasSubstr("REGRESSED  balls"));
  EXPECT_THAT(text, HasSubstr("c08..c09"));
  EXPECT_THAT(text, HasSubstr("alert: FAIL: 2 series, 1 in alert"));
  const nlohmann::json json = alert_json(j, {});
  EXPECT_EQ(json["alerts"], 1);
  EXPECT_EQ(json["series"][0]["alert"]["first_after"]["short_sha"], "c09");
  EXPECT_TRUE(json["series"][1]["alert"].is_null());
}

TEST(HistoryAlert, AnnotateReportsButDoesNotFail) {
  const AlertJudgement j =
      judge_history(rows_of("balls", 15, slower_at_9), GatePolicy{}, {}, AlertAction::annotate);
  EXPECT_EQ(j.alerts(), 1u);
  EXPECT_EQ(j.exit_code(), 0);
  EXPECT_THAT(alert_text(j), HasSubstr("ANNOTATE"));
}

TEST(HistoryAlert, FlatHistoryAndImprovementRaiseNothing) {
  const AlertJudgement flat_j =
      judge_history(rows_of("balls", 15, flat), GatePolicy{}, {}, AlertAction::fail);
  EXPECT_EQ(flat_j.alerts(), 0u);
  EXPECT_EQ(flat_j.exit_code(), 0);
  EXPECT_THAT(alert_text(flat_j), HasSubstr("alert: OK: 1 series, 0 in alert, 0 change points\n"));
  // The sweep of 2026-11-29: one measurement said only "OK".
  const AlertJudgement one =
      judge_history(rows_of("balls", 1, flat), GatePolicy{}, {}, AlertAction::fail);
  EXPECT_THAT(alert_text(one), HasSubstr("; 1 too short to show a change (fewer than 6 points)"));
  const AlertJudgement faster =
      judge_history(rows_of("balls", 15, faster_at_9), GatePolicy{}, {}, AlertAction::fail);
  ASSERT_EQ(faster.series[0].changes.size(), 1u);  // found, but it is good news
  EXPECT_EQ(faster.alerts(), 0u);
}

TEST(HistoryAlert, ChangeBelowTheScenesLimitIsNoAlert) {
  const std::vector<HistoryRow> rows = rows_of("balls", 15, two_percent_at_9);
  const AlertJudgement loose = judge_history(rows, GatePolicy{}, {}, AlertAction::fail);
  ASSERT_EQ(loose.series[0].changes.size(), 1u);  // a real +2% step
  EXPECT_EQ(loose.alerts(), 0u);                  // under the default 3% limit
  GatePolicy strict;
  strict.scenes["balls"].max_slowdown = 0.01;
  EXPECT_EQ(judge_history(rows, strict, {}, AlertAction::fail).alerts(), 1u);
}

TEST(HistoryAlert, UnmeasuredPointsAreLeftOut) {
  std::vector<HistoryRow> rows = rows_of("balls", 16, slower_at_9);
  rows.front().ratio.reset();  // commit 16 failed to measure
  const AlertJudgement j = judge_history(rows, GatePolicy{}, {}, AlertAction::fail);
  EXPECT_EQ(j.series[0].points, 15u);
  ASSERT_TRUE(j.series[0].alert);
  EXPECT_EQ(j.series[0].alert->first_after.short_sha, "c09");
}

// Peak memory (issue 27): the same rows with the tracer's own peak, KiB, per commit.
std::vector<HistoryRow> with_peaks(std::vector<HistoryRow> rows, double (*peak_kib)(std::size_t)) {
  for (std::size_t k = 0; k < rows.size(); ++k) rows[k].peak_memory_kib = peak_kib(rows.size() - k);
  return rows;
}

double jitter_kib(std::size_t i) { return 100.0 * std::sin(1.7 * static_cast<double>(i)); }
double eight_mib(std::size_t i) { return 8192.0 + jitter_kib(i); }
double fifty_more_at_9(std::size_t i) { return (i >= 9 ? 58.0 : 8.0) * 1024 + jitter_kib(i); }
double small_tracer_at_9(std::size_t i) { return (i >= 9 ? 4600.0 : 4000.0) + jitter_kib(i) / 10; }
double five_percent_at_9(std::size_t i) { return (i >= 9 ? 105.0 : 100.0) * 1024 + jitter_kib(i); }

TEST(HistoryAlert, AMemoryStepPutsTheSeriesInAlertWithItsRange) {
  const AlertJudgement j =
      judge_history(join(with_peaks(rows_of("balls", 15, flat), fifty_more_at_9),
                         with_peaks(rows_of("gears", 15, flat), eight_mib)),
                    GatePolicy{}, {}, AlertAction::fail);
  ASSERT_EQ(j.series.size(), 2u);
  EXPECT_EQ(j.alerts(), 1u);
  EXPECT_EQ(j.exit_code(), 1);
  const SeriesJudgement& balls = j.series[0];
  EXPECT_FALSE(balls.alert);  // its time did not change
  ASSERT_TRUE(balls.memory);
  EXPECT_EQ(balls.memory->points, 15u);
  EXPECT_DOUBLE_EQ(balls.memory->limit, 0.10);
  ASSERT_TRUE(balls.memory->alert);
  EXPECT_EQ(balls.memory->alert->last_before.short_sha, "c08");
  EXPECT_EQ(balls.memory->alert->first_after.short_sha, "c09");
  EXPECT_NEAR(balls.memory->alert->change.relative_change(), 50.0 / 8.0, 0.05);
  ASSERT_TRUE(j.series[1].memory);
  EXPECT_FALSE(j.series[1].memory->alert);

  const std::string text = alert_text(j);
  EXPECT_THAT(text, HasSubstr("REGRESSED  balls      memory +6"));
  EXPECT_THAT(text, HasSubstr("(8.0 MiB -> 58.0 MiB, limit +10%"));
  EXPECT_THAT(text, HasSubstr("c08..c09"));
  EXPECT_THAT(text, HasSubstr("alert: FAIL: 2 series, 1 in alert"));
  const nlohmann::json json = alert_json(j, {});
  EXPECT_TRUE(json["series"][0]["alert"].is_null());
  EXPECT_EQ(json["series"][0]["memory"]["alert"]["first_after"]["short_sha"], "c09");
  EXPECT_EQ(json["series"][0]["memory"]["max_memory_increase"], 0.10);
  EXPECT_TRUE(json["series"][1]["memory"]["alert"].is_null());
}

TEST(HistoryAlert, AMemoryStepUnderTheFloorOrTheLimitIsNoAlert) {
  // +15%, but 600 KiB: page-level jitter of a small tracer, never a verdict.
  const AlertJudgement small =
      judge_history(with_peaks(rows_of("balls", 15, flat), small_tracer_at_9), GatePolicy{}, {},
                    AlertAction::fail);
  ASSERT_TRUE(small.series[0].memory);
  EXPECT_EQ(small.series[0].memory->changes.size(), 1u);
  EXPECT_EQ(small.alerts(), 0u);
  // +5 MiB of 100 MiB: over the floor, under the default 10% limit; a stricter scene flags it.
  const std::vector<HistoryRow> rows = with_peaks(rows_of("balls", 15, flat), five_percent_at_9);
  EXPECT_EQ(judge_history(rows, GatePolicy{}, {}, AlertAction::fail).alerts(), 0u);
  GatePolicy strict;
  strict.scenes["balls"].max_memory_increase = 0.02;
  EXPECT_EQ(judge_history(rows, strict, {}, AlertAction::fail).alerts(), 1u);
}

TEST(HistoryAlert, ASeriesWithoutPeaksHasNoMemoryTrack) {
  const AlertJudgement j =
      judge_history(rows_of("balls", 15, flat), GatePolicy{}, {}, AlertAction::fail);
  EXPECT_FALSE(j.series[0].memory);
  EXPECT_TRUE(alert_json(j, {})["series"][0]["memory"].is_null());
}

TEST(HistoryAlert, ActionNames) {
  EXPECT_EQ(parse_alert_action("annotate"), AlertAction::annotate);
  EXPECT_EQ(to_string(AlertAction::fail), "fail");
  EXPECT_THROW(parse_alert_action("warn"), UsageError);
}

}  // namespace
}  // namespace raygate
