// `raygate alert` on a store holding 15 commits of a tracer's main branch: when commit 9 made
// balls 10% slower, the alert names the range 8..9 and fails (or only annotates); when commit 9
// made it keep 50 MiB more (issue 27), the same range is flagged for memory; a flat history
// raises nothing; the JSON on standard output is the whole of it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>

#include "cli_support.h"
#include "results_fixture.h"
#include "store/sqlite_handle.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class AlertCli : public ::testing::Test {
 protected:
  // Commits 1..15 on consecutive days; balls' ratio `slower` times 0.8 from commit `from` on,
  // gears flat; ±1% of fixed noise on both, as a quiet runner gives.
  // With `memory_from`, every run has its own peak: 8 MiB, and 58 MiB from that commit on.
  void record_history(double slower, int from, int memory_from = 0) {
    std::vector<std::string> args{"import", "--store", "store.db"};
    for (int i = 1; i <= 15; ++i) {
      const double noise = 1.0 + 0.01 * std::sin(2.3 * i);
      DocumentSpec spec;
      spec.sha = fake_sha(i);
      spec.subject = fmt::format("commit {}", i);
      spec.commit_time = fmt::format("2026-06-{:02}T09:00:00+00:00", i);
      spec.started_at = fmt::format("2026-06-{:02}T10:00:00Z", i);
      spec.repository_id = "root:0123456789abcdef0123456789abcdef01234567";
      spec.scenes = {{"balls", 0.8 * (i >= from ? slower : 1.0) * noise},
                     {"gears", 1.5 * (1.0 + 0.01 * std::cos(1.9 * i))}};
      if (memory_from > 0) {
        const long jitter_kib = std::lround(60 * std::sin(2.3 * i));
        spec.scenes[0].peak_kib = (i >= memory_from ? 58 : 8) * 1024 + jitter_kib;
        spec.scenes[1].peak_kib = 12 * 1024 + jitter_kib;
      }
      const std::string name = fmt::format("docs/c{:02}.json", i);
      write_results(make_document(spec), dir.path() / name);
      args.push_back(name);
    }
    const CliRun imported = run_raygate(args, dir);
    ASSERT_EQ(imported.exit_code, 0) << imported.out;
  }
  std::string short_sha(int seed) { return fake_sha(seed).substr(0, 7); }
  TempDir dir;
};

TEST_F(AlertCli, RegressionAtCommitNineIsFlaggedAsRangeEightToNine) {
  record_history(1.10, 9);
  const CliStreams r =
      run_raygate_streams({"alert", "--store", "store.db", "--branch", "main"}, dir);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("REGRESSED  balls"));
  EXPECT_THAT(r.out, HasSubstr(short_sha(8) + ".." + short_sha(9)));
  EXPECT_THAT(r.out, HasSubstr("\"commit 9\""));
  EXPECT_THAT(r.out, Not(HasSubstr("REGRESSED  gears")));
  EXPECT_THAT(r.out, HasSubstr("alert: FAIL: 2 series, 1 in alert"));
  EXPECT_THAT(r.err, HasSubstr("judging the last 30 commits of branch main"));

  const CliStreams annotate =
      run_raygate_streams({"alert", "--store", "store.db", "--on-regression", "annotate"}, dir);
  EXPECT_EQ(annotate.exit_code, 0) << annotate.out << annotate.err;
  EXPECT_THAT(annotate.out, HasSubstr(short_sha(8) + ".." + short_sha(9)));
}

TEST_F(AlertCli, JsonOnStandardOutputNamesTheRange) {
  record_history(1.10, 9);
  const CliStreams r =
      run_raygate_streams({"alert", "--store", "store.db", "--format", "json"}, dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // nothing but the JSON
  EXPECT_EQ(j["alerts"], 1);
  EXPECT_EQ(j["method"], "e-divisive means");
  bool found = false;
  for (const nlohmann::json& s : j["series"]) {
    if (s["scene"] != "balls") continue;
    found = true;
    EXPECT_EQ(s["points"], 15);
    EXPECT_EQ(s["alert"]["last_before"]["sha"], fake_sha(8));
    EXPECT_EQ(s["alert"]["first_after"]["sha"], fake_sha(9));
    EXPECT_NEAR(s["alert"]["relative_change"].get<double>(), 0.10, 0.01);
  }
  EXPECT_TRUE(found) << r.out;
}

// Subjects in the store that are not UTF-8 and carry an ESC sequence: the JSON still parses
// (it once failed with type_error.316, exit 3) and the text shows the ESC instead of obeying it.
TEST_F(AlertCli, TextThatIsNotUtf8InTheStoreIsRepairedOnTheWayOut) {
  record_history(1.10, 9);
  {
    SqliteDb db = SqliteDb::open(dir.path() / "store.db", false);
    db.exec(
        "UPDATE revisions SET subject = subject || ' caf' || CAST(X'E9' AS TEXT) || "
        "CAST(X'1B' AS TEXT) || '[2J'");
  }
  const CliStreams j = run_raygate_streams(
      {"alert", "--store", "store.db", "--branch", "main", "--format", "json"}, dir);
  EXPECT_EQ(j.exit_code, 1) << j.err;
  ASSERT_TRUE(nlohmann::json::accept(j.out)) << j.out;
  EXPECT_THAT(j.out, HasSubstr("commit 9 caf\xEF\xBF\xBD"));

  const CliStreams t =
      run_raygate_streams({"alert", "--store", "store.db", "--branch", "main"}, dir);
  EXPECT_EQ(t.exit_code, 1) << t.err;
  EXPECT_THAT(t.out, HasSubstr("commit 9 caf\xEF\xBF\xBD\\x1b[2J"));
  EXPECT_THAT(t.out + t.err, Not(HasSubstr("\x1b[2J")));
}

TEST_F(AlertCli, FiftyMoreMebibytesAtCommitNineAreFlaggedForMemory) {
  record_history(1.0, 9, 9);
  const CliStreams r = run_raygate_streams({"alert", "--store", "store.db"}, dir);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("REGRESSED  balls      memory +"));
  EXPECT_THAT(r.out, HasSubstr("(8.0 MiB -> 58.0 MiB, limit +10%"));
  EXPECT_THAT(r.out, HasSubstr(short_sha(8) + ".." + short_sha(9)));
  EXPECT_THAT(r.out, Not(HasSubstr("REGRESSED  gears")));
  EXPECT_THAT(r.out, HasSubstr("alert: FAIL: 2 series, 1 in alert"));
  const CliStreams j =
      run_raygate_streams({"alert", "--store", "store.db", "--format", "json"}, dir);
  const nlohmann::json json = nlohmann::json::parse(j.out);
  for (const nlohmann::json& s : json["series"]) {
    EXPECT_EQ(s["memory"]["points"], 15);
    EXPECT_EQ(s["memory"]["alert"].is_null(), s["scene"] != "balls") << s.dump();
  }
}

TEST_F(AlertCli, FlatHistoryRaisesNothing) {
  record_history(1.0, 9);
  const CliStreams r = run_raygate_streams({"alert", "--store", "store.db"}, dir);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, Not(HasSubstr("REGRESSED")));
  EXPECT_THAT(r.out, HasSubstr("alert: OK: 2 series, 0 in alert, 0 change points"));
}

TEST_F(AlertCli, PolicyLimitAndUnknownBranch) {
  record_history(1.02, 9);  // +2%: under the default 3% limit
  EXPECT_EQ(run_raygate_streams({"alert", "--store", "store.db"}, dir).exit_code, 0);
  write_file_atomically(dir.path() / "strict.json", R"({"max_slowdown": 0.01})");
  const CliStreams strict =
      run_raygate_streams({"alert", "--store", "store.db", "--policy", "strict.json"}, dir);
  EXPECT_EQ(strict.exit_code, 1) << strict.out << strict.err;
  const CliStreams none =
      run_raygate_streams({"alert", "--store", "store.db", "--branch", "release"}, dir);
  EXPECT_EQ(none.exit_code, 2) << none.out << none.err;
  EXPECT_THAT(none.err, HasSubstr("no measured commits"));
}

TEST_F(AlertCli, ASegmentLongerThanTheHistoryKeptIsRefusedNotPassed) {
  record_history(1.10, 9);
  const CliStreams r = run_raygate_streams(
      {"alert", "--store", "store.db", "--last", "10", "--min-segment", "6"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("--min-segment 6 needs 12 commits, more than --last 10 keeps"));
  EXPECT_THAT(r.out, Not(HasSubstr("OK")));
}

}  // namespace
}  // namespace raygate::test
