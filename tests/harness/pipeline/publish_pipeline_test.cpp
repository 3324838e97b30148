// The pipeline closed at both ends, without the command line: compare's revisions located
// (pipeline/revision_setup.h), measured with the fake executor and clock, then published
// (pipeline/publish.h): recorded in a store, gated, and reported in files.
#include "pipeline/publish.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <sstream>

#include "core/exit_codes.h"
#include "pipeline/compare_measurement.h"
#include "pipeline/revision_setup.h"
#include "pipeline_fixture.h"
#include "store/store.h"

namespace raygate::testing {
namespace {

// What publishing said, by channel.
class RecordingSink final : public PublishSink {
 public:
  void info(const std::string& text) const override { infos.push_back(text); }
  void warning(const std::string& text) const override { warnings.push_back(text); }
  void problem(const std::string& text) const override { problems.push_back(text); }

  mutable std::vector<std::string> infos;
  mutable std::vector<std::string> warnings;
  mutable std::vector<std::string> problems;
};

class PublishPipelineTest : public PipelineTest {
 protected:
  // compare base..head, then publish to the store and a json and a markdown report in dir_.
  int compare_and_publish(const std::string& base, const std::string& head) {
    const CompareTrees trees =
        locate_compare_trees(repo_.path().string(), base, "", head, context_.cache_dir);
    measured_ =
        measure_compare({context_, baseline_, trees.repository, trees.base, trees.head, {}}, io_);
    request_.document_path = measured_.path;
    request_.store = store_;
    request_.policy = context_.policy;
    // As parse_report_targets makes them, without its early check of the paths (a report that
    // fails when written must reach publish).
    request_.reports = {{ReportFormat::json, json_}, {ReportFormat::markdown, markdown_}};
    request_.table = &table_;
    return publish(measured_.document, request_, sink_, failures_);
  }

  nlohmann::json json_report() const { return nlohmann::json::parse(read_file(json_)); }

  std::filesystem::path store_ = dir_.path() / "results.db";
  std::filesystem::path json_ = dir_.path() / "reports" / "report.json";
  std::filesystem::path markdown_ = dir_.path() / "reports" / "report.md";
  MeasuredDocument measured_;
  PublishRequest request_;
  RecordingSink sink_;
  std::ostringstream table_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> said_{std::tmpfile(), &std::fclose};
  OutputFailures failures_{said_.get()};
};

TEST_F(PublishPipelineTest, ASlowerHeadIsStoredGatedAndReportedAsARegression) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.4", "head: 20% slower");
  EXPECT_EQ(compare_and_publish(base, head), to_int(ExitCode::regression));

  const auto store = open_store(store_.string(), StoreOpen::must_exist);
  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].document.at("kind"), "compare");
  EXPECT_EQ(stored[0].document.at("revisions").at(1).at("worktree").at("sha"), head);

  const nlohmann::json report = json_report();
  EXPECT_EQ(report.at("kind"), "compare");
  EXPECT_EQ(report.at("exit_code"), to_int(ExitCode::regression));
  EXPECT_EQ(report.at("counts").at("fail"), 2);
  EXPECT_FALSE(read_file(markdown_).empty());
  EXPECT_NE(table_.str().find("head"), std::string::npos) << table_.str();
  // Said where everything went, and nothing went wrong.
  ASSERT_GE(sink_.infos.size(), 4u);
  EXPECT_EQ(sink_.infos[0], "results: " + measured_.path.string());
  EXPECT_NE(sink_.infos[1].find("stored in "), std::string::npos) << sink_.infos[1];
  EXPECT_EQ(sink_.infos[2], "json report: " + json_.string());
  EXPECT_EQ(sink_.infos[3], "markdown report: " + markdown_.string());
  EXPECT_TRUE(sink_.problems.empty());
  EXPECT_FALSE(failures_.any());
}

TEST_F(PublishPipelineTest, AnEqualHeadPassesAndIsStoredOnce) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head: a comment");
  EXPECT_EQ(compare_and_publish(base, head), to_int(ExitCode::pass));
  EXPECT_EQ(json_report().at("exit_code"), 0);
  // Published again: the store already has it.
  EXPECT_EQ(publish(measured_.document, request_, sink_, failures_), 0);
  EXPECT_NE(sink_.infos.back().find("report: "), std::string::npos);
  bool already = false;
  for (const std::string& info : sink_.infos) {
    already = already || info.starts_with("already stored in");
  }
  EXPECT_TRUE(already);
  EXPECT_EQ(open_store(store_.string())->documents({}).size(), 1u);
}

// A store that cannot be written loses nothing else: the reports are written, the gate's code
// stands, and the message says how to import the kept document later.
TEST_F(PublishPipelineTest, AStoreThatCannotBeWrittenIsSaidAndTheReportsStillGoOut) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.4", "head: 20% slower");
  write_file_atomically(dir_.path() / "a-file", "not a folder\n");
  store_ = dir_.path() / "a-file" / "results.db";
  EXPECT_EQ(compare_and_publish(base, head), to_int(ExitCode::regression));
  ASSERT_EQ(sink_.problems.size(), 1u);
  EXPECT_TRUE(sink_.problems[0].starts_with("raygate: warning: results not stored: "));
  EXPECT_NE(sink_.problems[0].find("raygate import " + measured_.path.string()), std::string::npos)
      << sink_.problems[0];
  EXPECT_EQ(json_report().at("exit_code"), to_int(ExitCode::regression));
}

// Issue 40: a report that cannot be written makes raygate exit 3, and the table's closing line
// says so, with the problem, instead of "pass (...), exit 0".
TEST_F(PublishPipelineTest, AReportThatCannotBeWrittenEndsTheTableWithTheRealExitCode) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head: a comment");
  write_file_atomically(dir_.path() / "a-file", "not a folder\n");
  markdown_ = dir_.path() / "a-file" / "report.md";
  EXPECT_EQ(compare_and_publish(base, head), to_int(ExitCode::infrastructure));
  const std::string table = table_.str();
  EXPECT_NE(
      table.find("problem: 1 output could not be written (--report markdown:" + markdown_.string()),
      std::string::npos)
      << table;
  EXPECT_NE(table.find("), exit 3\n"), std::string::npos) << table;
  EXPECT_EQ(table.find("exit 0"), std::string::npos) << table;
  EXPECT_EQ(json_report().at("exit_code"), 0);  // written before the markdown failed
}

TEST_F(PublishPipelineTest, ABadReportSpecIsAUsageError) {
  EXPECT_THROW(parse_report_targets({"html"}), UsageError);
  EXPECT_THROW(parse_report_targets({"pdf:r.pdf"}), UsageError);
  EXPECT_THROW(parse_report_targets({"json:" + dir_.path().string()}), UsageError);
}

TEST_F(PublishPipelineTest, ABaseBranchThatDoesNotExistIsRefused) {
  commit_tracer("2.0", "main");
  EXPECT_THROW(
      locate_compare_trees(repo_.path().string(), "", "no-such-branch", "HEAD", context_.cache_dir),
      Error);
}

}  // namespace
}  // namespace raygate::testing
