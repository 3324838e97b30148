// pipeline/publish_options: where a published document's record and reports go, as a front end's
// options say: the default store beside the cache, none with no_store, the console table only
// for a console that may speak, and bad report specs or outputs refused before measuring.
#include <gtest/gtest.h>

#include <iostream>

#include "core/error.h"
#include "core/fs.h"
#include "pipeline/publish_options.h"

namespace raygate {
namespace {

const Console kQuietConsole(ColourChoice::never, true, nullptr);
const Console kChattyConsole(ColourChoice::always, false, nullptr);

TEST(PublishOptions, TheStoreDefaultsToTheCacheDirsResultsDb) {
  PublishOptions options;
  options.branch = "main";
  const PublishRequest request =
      publish_request(options, "/runs/r/results.json", "/cache", {}, kQuietConsole);
  EXPECT_EQ(request.document_path.string(), "/runs/r/results.json");
  EXPECT_EQ(request.store.string(), "/cache/results.db");
  EXPECT_EQ(request.branch, "main");
  EXPECT_TRUE(request.reports.empty());
}

TEST(PublishOptions, ANamedStoreWinsAndNoStoreRecordsNothing) {
  PublishOptions named;
  named.store = "postgresql://ci@db/raygate";
  EXPECT_EQ(publish_request(named, "d.json", "/cache", {}, kQuietConsole).store.string(),
            "postgresql://ci@db/raygate");
  PublishOptions refused;
  refused.no_store = true;
  EXPECT_TRUE(publish_request(refused, "d.json", "/cache", {}, kQuietConsole).store.empty());
}

TEST(PublishOptions, TheTableIsForAConsoleThatMaySpeak) {
  const PublishRequest quiet = publish_request({}, "d.json", "/cache", {}, kQuietConsole);
  EXPECT_EQ(quiet.table, nullptr);
  EXPECT_FALSE(quiet.table_colour);
  EXPECT_FALSE(quiet.report_colour);
  const PublishRequest chatty = publish_request({}, "d.json", "/cache", {}, kChattyConsole);
  EXPECT_EQ(chatty.table, &std::cerr);  // chatter goes to standard error, never standard output
  EXPECT_TRUE(chatty.table_colour);
  EXPECT_TRUE(chatty.report_colour);
}

TEST(PublishOptions, ReportsAndThePolicyAreCarried) {
  PublishOptions options;
  options.reports = {"json:-", "markdown:summary.md"};
  GatePolicy policy;
  policy.fail_on_inconclusive = true;
  const PublishRequest request =
      publish_request(options, "d.json", "/cache", policy, kQuietConsole);
  ASSERT_EQ(request.reports.size(), 2u);
  EXPECT_EQ(request.reports[0].format, ReportFormat::json);
  EXPECT_EQ(request.reports[1].format, ReportFormat::markdown);
  EXPECT_EQ(request.reports[1].path.string(), "summary.md");
  EXPECT_TRUE(request.policy.fail_on_inconclusive);
}

TEST(PublishOptions, BadTargetsAreRefusedBeforeMeasuring) {
  PublishOptions unknown_format;
  unknown_format.reports = {"pdf:r.pdf"};
  EXPECT_THROW(check_publish_targets(unknown_format, "", "--output"), UsageError);
  TempDir dir;
  // A folder where the document should go: named by the option that gave it.
  try {
    check_publish_targets({}, dir.path().string(), "--output");
    ADD_FAILURE() << "a directory was accepted as the document's path";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--output"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_publish_targets({}, "", "--output"));  // the default place
  EXPECT_NO_THROW(check_publish_targets({}, (dir.path() / "r.json").string(), "--output"));
}

// Hostile sweep O1: run and compare measured everything and then only warned about a --store
// URL that import, history and alert refuse.
TEST(PublishOptions, AMalformedStoreUrlIsRefusedBeforeMeasuring) {
  for (const std::string url :
       {"postgresql://u@h:99999/db", "postgresql://u@localhost/db?sslmode=bogus"}) {
    SCOPED_TRACE(url);
    PublishOptions options;
    options.store = url;
    try {
      check_publish_targets(options, "", "--output");
      ADD_FAILURE() << "a malformed URL was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--store " + url + ": not a valid PostgreSQL URL"),
                std::string::npos)
          << e.what();
    }
    options.no_store = true;  // not used: nothing to refuse
    EXPECT_NO_THROW(check_publish_targets(options, "", "--output"));
  }
  // A well-formed URL is not connected to here: a server that cannot be reached is a warning
  // after measuring (docs/ci.md).
  PublishOptions unreachable;
  unreachable.store = "postgresql://ci@127.0.0.1:1/raygate";
  EXPECT_NO_THROW(check_publish_targets(unreachable, "", "--output"));
}

TEST(PublishOptions, MergeWantsAnOutputBeforeReadingAnyShard) {
  MergeRequest request;
  request.documents = {"/no/such/shard.json"};
  try {
    merge_and_publish(request, {}, "/cache", kQuietConsole);
    ADD_FAILURE() << "a merge without --output went ahead";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--output is required"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raygate
