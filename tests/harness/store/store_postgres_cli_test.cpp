// The raygate binary with --store postgresql://...: import, history and export against the
// test server, the exit codes of a store that is empty or not there, and no password printed.
#include <fmt/core.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "../cli/cli_support.h"
#include "postgres_server.h"
#include "results_fixture.h"
#include "store/postgres_url.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

DocumentSpec commit(int seed, int day, double balls_ratio) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit number " + std::to_string(seed);
  spec.commit_time = fmt::format("2026-05-{:02}T09:00:00+00:00", day);
  spec.started_at = fmt::format("2026-05-{:02}T10:00:00Z", day);
  spec.scenes = {{"balls", balls_ratio}, {"gears", 1.5, 0.02, 2.0, 0.0123, ImageVerdict::warn}};
  return spec;
}

class StorePostgresCli : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const DocumentSpec& spec) {
    write_results(make_document(spec), dir.path() / "docs" / name);
    return "docs/" + name;
  }
  TempDir dir;
  std::string url = postgres_server().create_database();
};

TEST_F(StorePostgresCli, ImportHistoryAndExportThroughTheBinary) {
  const std::vector<std::string> files = {write("c1.json", commit(1, 1, 0.80)),
                                          write("c2.json", commit(2, 2, 0.80)),
                                          write("c3.json", commit(3, 3, 0.88))};
  std::vector<std::string> args = {"import", "--store", url};
  args.insert(args.end(), files.begin(), files.end());
  const CliRun imported = run_raygate(args, dir);
  ASSERT_EQ(imported.exit_code, 0) << imported.out;
  EXPECT_THAT(imported.out,
              HasSubstr("imported 3 of 3 documents into " + redact_postgresql_url(url)));
  const CliRun again = run_raygate({"import", "--store", url, files[0]}, dir);
  ASSERT_EQ(again.exit_code, 0) << again.out;
  EXPECT_THAT(again.out, HasSubstr("already stored as document 1"));

  const CliRun history = run_raygate({"history", "--store", url}, dir);
  ASSERT_EQ(history.exit_code, 0) << history.out;
  for (int seed : {1, 2, 3}) EXPECT_THAT(history.out, HasSubstr(fake_sha(seed).substr(0, 7)));
  EXPECT_THAT(history.out, HasSubstr("0.880 ±1.0%"));
  EXPECT_THAT(history.out, HasSubstr("+10.0% ↑ vs " + fake_sha(2).substr(0, 7)));
  const CliRun json = run_raygate({"history", "--store", url, "--format", "json"}, dir);
  ASSERT_EQ(json.exit_code, 0) << json.out;
  EXPECT_EQ(nlohmann::json::parse(json.out)["tables"].at(0)["commits"].size(), 3u) << json.out;

  const CliRun exported = run_raygate({"export", "--store", url, "-o", "out"}, dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.out;
  std::set<std::string> out_files;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "out")) {
    out_files.insert(read_file(entry.path()));
  }
  std::set<std::string> in_files;
  for (const std::string& file : files) in_files.insert(read_file(dir.path() / file));
  EXPECT_EQ(out_files, in_files);  // byte for byte

  for (const CliRun* run : {&imported, &again, &history, &exported}) {
    EXPECT_THAT(run->out, Not(HasSubstr(PostgresServer::kPassword)));
  }
}

TEST_F(StorePostgresCli, EmptyDatabaseBadUrlAndNoServerExitCodes) {
  const CliRun empty = run_raygate({"history", "--store", url}, dir);
  EXPECT_EQ(empty.exit_code, 2) << empty.out;
  EXPECT_THAT(empty.out, HasSubstr("no raygate tables yet"));
  const CliRun bad = run_raygate({"history", "--store", "postgresql://ci:s3cret@[::1/x"}, dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_THAT(bad.out, HasSubstr("not a valid PostgreSQL URL"));
  const CliRun down =
      run_raygate({"history", "--store", "postgresql://ci:s3cret@127.0.0.1:1/x"}, dir);
  EXPECT_EQ(down.exit_code, 3) << down.out;
  EXPECT_THAT(down.out, HasSubstr("postgresql://ci@127.0.0.1:1/x"));
  for (const CliRun* run : {&empty, &bad, &down}) {
    EXPECT_THAT(run->out, Not(HasSubstr("s3cret")));
    EXPECT_THAT(run->out, Not(HasSubstr(PostgresServer::kPassword)));
  }
}

}  // namespace
}  // namespace raygate::test
