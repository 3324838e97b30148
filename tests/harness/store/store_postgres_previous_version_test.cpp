// A PostgreSQL team store written by the raygate before the SQL store was written once (main at
// 60ebc9f, with its own PostgreSQL schema and writer) opens with this one, reads back exactly
// what the SQLite store main wrote of the same documents, takes new documents after its own, and
// has the schema this raygate gives a new database. The fixture is `pg_dump --inserts` of a
// database into which main's binary imported the two documents of the SQLite fixture
// (store_previous_version_test.cpp).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/fs.h"
#include "postgres_server.h"
#include "store/document_files.h"
#include "store/store.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(RAYGATE_SOURCE_DIR) / "tests/harness/store/fixtures";

// Columns with their types, nullability and defaults, indexes and constraints, one per line.
constexpr const char* kDescribeSchema = R"sql(
SELECT string_agg(line, E'\n' ORDER BY part, k1 COLLATE "C", k2) FROM (
  SELECT 1 AS part, table_name || '.' || column_name || ' ' || data_type || ' ' ||
         is_nullable || coalesce(' DEFAULT ' || column_default, '') AS line,
         table_name::text AS k1, ordinal_position::int AS k2
  FROM information_schema.columns WHERE table_schema = current_schema()
  UNION ALL
  SELECT 2, indexdef, indexname::text, 0 FROM pg_indexes WHERE schemaname = current_schema()
  UNION ALL
  SELECT 3, conrelid::regclass::text || ' ' || conname || ' ' || pg_get_constraintdef(oid),
         conname::text, 0
  FROM pg_constraint WHERE connamespace = current_schema()::regnamespace
) AS schema)sql";

// Every field of a measurement but stored_at (when each store got it).
std::string row_text(const HistoryRow& r) {
  const auto number = [](const std::optional<double>& v) {
    return v ? fmt::format("{}", *v) : std::string("-");
  };
  return fmt::format(
      "{} {} {} {} {} {} {} [{}] {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {}",
      r.document_id, r.measured_at, r.complete, r.branch, r.role, r.sha, r.short_sha, r.subject,
      r.commit_time, r.commit_unix.value_or(-1), r.dirty, r.scene_id, r.status, number(r.ratio),
      number(r.ratio_lower), number(r.ratio_upper), number(r.baseline_median_seconds),
      r.image_verdict, number(r.image_max_error), number(r.image_rms_error), r.machine_hostname,
      r.machine_cpu_model, r.baseline_sha256, r.repository_key, r.adapter_name, r.suite,
      r.scene_settings, r.timing, r.baseline_accel, r.series_id);
}

std::vector<std::string> texts(const std::vector<HistoryRow>& rows) {
  std::vector<std::string> out;
  for (const HistoryRow& row : rows) out.push_back(row_text(row));
  return out;
}

class StorePostgresPreviousVersion : public ::testing::Test {
 protected:
  StorePostgresPreviousVersion() {
    EXPECT_TRUE(RawConnection(url).exec(read_file(kFixtures / "main-60ebc9f-postgres.sql")));
  }
  const std::string url = postgres_server().create_database();
};

TEST_F(StorePostgresPreviousVersion, ADatabaseMainWroteReadsBackAsItsSqliteStoreDoes) {
  const auto store = open_store(url, StoreOpen::must_exist);
  EXPECT_EQ(RawConnection(url).text("SELECT max(version) FROM schema_migrations"), "3");
  TempDir dir;
  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 2u);
  export_documents({stored[0]}, dir.path() / "compare.json");
  EXPECT_EQ(read_file(dir.path() / "compare.json"),
            read_file(kFixtures / "main-60ebc9f-compare.json"));

  fs::copy_file(kFixtures / "main-60ebc9f.db", dir.path() / "results.db");
  const auto sqlite = open_store((dir.path() / "results.db").string(), StoreOpen::must_exist);
  HistoryQuery any;
  any.role = "any";
  const std::vector<std::string> rows = texts(store->measurements(any));
  EXPECT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows, texts(sqlite->measurements(any)));
}

TEST_F(StorePostgresPreviousVersion, NewDocumentsFollowItsOwn) {
  const auto store = open_store(url, StoreOpen::must_exist);
  const ResultsDocument run = load_results_file(kFixtures / "main-60ebc9f-run.json");
  const AddOutcome again = store->add(run, "main");
  EXPECT_TRUE(again.duplicate);
  EXPECT_EQ(again.document_id, 1);
  ResultsDocument rerun = run;
  rerun.started_at = "2026-11-27T00:00:00Z";
  const AddOutcome added = store->add(rerun, "main");
  EXPECT_FALSE(added.duplicate);
  EXPECT_EQ(added.document_id, 3);
}

TEST_F(StorePostgresPreviousVersion, ANewDatabaseGetsTheSchemaMainGaveIt) {
  const std::string fresh = postgres_server().create_database();
  open_store(fresh);
  // The dump opened first: the migrations after main's (3, peak memory) bring it what a new
  // database has.
  open_store(url, StoreOpen::must_exist);
  const std::string expected = RawConnection(url).text(kDescribeSchema);
  EXPECT_NE(expected.find("scene_results.series_id text NO DEFAULT ''::text"), std::string::npos)
      << expected;
  EXPECT_NE(expected.find("scene_results.memory_verdict text NO DEFAULT ''::text"),
            std::string::npos)
      << expected;
  EXPECT_EQ(RawConnection(fresh).text(kDescribeSchema), expected);
}

}  // namespace
}  // namespace raygate::test
