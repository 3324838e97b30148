// A store written by the raygate before the SQL store was written once (main at 60ebc9f, with
// its own SQLite schema and writer) opens with this one, reads back exactly, keeps its documents'
// identity and series, takes new documents, and has the very schema this raygate gives a new
// store. The fixture (fixtures/main-60ebc9f.db) was made by that binary: `raygate run` of the
// fixture tracer on two tiny scenes, then `raygate compare` of it against a commit that renders
// twice; the two JSON files are what those commands wrote with --out.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/fs.h"
#include "results/results.h"
#include "store/document_files.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(RAYGATE_SOURCE_DIR) / "tests/harness/store/fixtures";

// Every row of a query, its columns joined by '|', for comparing schemas.
std::vector<std::string> rows_of(const fs::path& path, const std::string& sql) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_stmt* statement = nullptr;
  sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr);
  std::vector<std::string> rows;
  while (sqlite3_step(statement) == SQLITE_ROW) {
    std::string row;
    for (int c = 0; c < sqlite3_column_count(statement); ++c) {
      const unsigned char* text = sqlite3_column_text(statement, c);
      if (c > 0) row += "|";
      row += text ? reinterpret_cast<const char*>(text) : "NULL";
    }
    rows.push_back(row);
  }
  sqlite3_finalize(statement);
  sqlite3_close(db);
  return rows;
}

// The columns (name, type, not null, default, key position) and indexes (with their columns) of
// every table, as SQLite describes them.
std::vector<std::string> schema_of(const fs::path& path) {
  std::vector<std::string> out;
  for (const char* table : {"documents", "revisions", "scene_results", "schema_migrations"}) {
    const std::string info = std::string(
                                 "SELECT name, type, \"notnull\", dflt_value, pk FROM "
                                 "pragma_table_info('") +
                             table + "')";
    for (const std::string& c : rows_of(path, info)) out.push_back(table + (" " + c));
    for (const std::string& index :
         rows_of(path, std::string("SELECT name FROM pragma_index_list('") + table +
                           "') ORDER BY name")) {
      const std::vector<std::string> columns =
          rows_of(path, "SELECT group_concat(name) FROM pragma_index_info('" + index + "')");
      out.push_back(std::string(table) + " index " + index + " on " + columns.at(0));
    }
  }
  for (const std::string& fk : rows_of(path, "SELECT * FROM pragma_foreign_key_list('revisions')"))
    out.push_back("revisions fk " + fk);
  for (const std::string& fk :
       rows_of(path, "SELECT * FROM pragma_foreign_key_list('scene_results')"))
    out.push_back("scene_results fk " + fk);
  return out;
}

// The fixture copied into `dir` (opening a store writes to it: its WAL, a migration).
fs::path copy_of_fixture(const TempDir& dir) {
  const fs::path path = dir.path() / "results.db";
  fs::copy_file(kFixtures / "main-60ebc9f.db", path);
  return path;
}

// `raygate import`'s way in.
ResultsDocument fixture_document(const std::string& name) {
  return load_results_file(kFixtures / name);
}

TEST(StorePreviousVersion, AStoreMainWroteOpensAtTheSameVersionAndExportsItsFilesByteForByte) {
  TempDir dir;
  const fs::path path = copy_of_fixture(dir);
  const auto store = open_store(path.string(), StoreOpen::must_exist);
  EXPECT_EQ(rows_of(path, "PRAGMA user_version"), std::vector<std::string>{"3"});
  EXPECT_EQ(rows_of(path, "SELECT version, description FROM schema_migrations ORDER BY version"),
            (std::vector<std::string>{
                "1|documents, revisions, scene_results",
                "2|series columns: documents.timing, baseline_accel; revisions.repository_key; "
                "scene_results.scene_settings, series_id",
                "3|peak memory: scene_results.peak_memory_kib, memory_change, memory_verdict"}));

  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 2u);  // newest first
  // `raygate export`'s way out.
  export_documents({stored[0]}, dir.path() / "compare.json");
  export_documents({stored[1]}, dir.path() / "run.json");
  EXPECT_EQ(read_file(dir.path() / "compare.json"),
            read_file(kFixtures / "main-60ebc9f-compare.json"));
  EXPECT_EQ(read_file(dir.path() / "run.json"), read_file(kFixtures / "main-60ebc9f-run.json"));
  EXPECT_EQ(stored[1].branch, "main");
}

TEST(StorePreviousVersion, ItsRowsReadBackAsThisRaygateWouldWriteThem) {
  TempDir dir;
  const auto store = open_store(copy_of_fixture(dir).string(), StoreOpen::must_exist);
  const ResultsDocument run = fixture_document("main-60ebc9f-run.json");
  const ResultsDocument compare = fixture_document("main-60ebc9f-compare.json");
  const DocumentRows run_rows = document_rows(run, "main", "t");
  const DocumentRows compare_rows = document_rows(compare, "main", "t");

  HistoryQuery any;
  any.role = "any";
  const std::vector<HistoryRow> rows = store->measurements(any);
  ASSERT_EQ(rows.size(), run_rows.scenes.size() + compare_rows.scenes.size());  // 2 + 2 x 2
  for (const HistoryRow& row : rows) {
    const bool from_run = row.document_id == 1;
    const DocumentRows& expected = from_run ? run_rows : compare_rows;
    const auto scene =
        std::find_if(expected.scenes.begin(), expected.scenes.end(), [&row](const SceneRow& s) {
          return s.scene_id == row.scene_id && s.role == row.role;
        });
    ASSERT_NE(scene, expected.scenes.end()) << row.scene_id << " " << row.role;
    // A series continues across the upgrade: the stored id is the one computed today.
    EXPECT_EQ(row.series_id, scene->series_id);
    EXPECT_EQ(row.scene_settings, scene->scene_settings);
    EXPECT_EQ(row.ratio, scene->ratio);  // bit for bit
    EXPECT_EQ(row.ratio_lower, scene->ratio_lower);
    EXPECT_EQ(row.baseline_median_seconds, scene->baseline_median_seconds);
    EXPECT_EQ(row.status, scene->status);
    EXPECT_EQ(row.image_verdict, scene->image_verdict);
    EXPECT_EQ(row.timing, expected.document.timing);
    EXPECT_EQ(row.measured_at, expected.document.started_at);
    EXPECT_EQ(row.complete, expected.document.complete);
    EXPECT_EQ(row.machine_cpu_model, expected.document.machine_cpu_model);
    const auto revision = std::find_if(expected.revisions.begin(), expected.revisions.end(),
                                       [&row](const RevisionRow& r) { return r.role == row.role; });
    ASSERT_NE(revision, expected.revisions.end());
    EXPECT_EQ(row.sha, revision->sha);
    EXPECT_EQ(row.commit_unix, revision->commit_unix);
    EXPECT_EQ(row.repository_key, revision->repository_key);
    EXPECT_EQ(row.adapter_name, "make-nff");
    EXPECT_FALSE(row.dirty);
  }
  EXPECT_EQ(store->history({}).size(), 2u);  // the run's tracer, one commit x two series
}

TEST(StorePreviousVersion, ItsDocumentsKeepTheirIdentityAndNewOnesFollowThem) {
  TempDir dir;
  const auto store = open_store(copy_of_fixture(dir).string(), StoreOpen::must_exist);
  const ResultsDocument run = fixture_document("main-60ebc9f-run.json");
  const AddOutcome again = store->add(run, "main");
  EXPECT_TRUE(again.duplicate);
  EXPECT_EQ(again.document_id, 1);
  EXPECT_TRUE(store->add(fixture_document("main-60ebc9f-compare.json"), "main").duplicate);

  ResultsDocument rerun = run;
  rerun.started_at = "2026-11-27T00:00:00Z";
  const AddOutcome added = store->add(rerun, "main");
  EXPECT_FALSE(added.duplicate);
  EXPECT_EQ(added.document_id, 3);
  const std::vector<HistoryRow> latest = store->history({});
  ASSERT_EQ(latest.size(), 2u);  // the re-run supersedes the run in both series
  for (const HistoryRow& row : latest) EXPECT_EQ(row.document_id, 3);
}

TEST(StorePreviousVersion, ANewStoreHasTheSchemaMainGaveItsStores) {
  TempDir dir;
  const fs::path fresh = dir.path() / "fresh.db";
  open_store(fresh.string());
  // Read from a copy: even a read-only connection leaves WAL files beside the database. Opened
  // first: the migrations after main's (3, peak memory) bring it what a new store has.
  const fs::path old = copy_of_fixture(dir);
  open_store(old.string(), StoreOpen::must_exist);
  const std::vector<std::string> expected = schema_of(old);
  ASSERT_GT(expected.size(), 50u);
  EXPECT_EQ(schema_of(fresh), expected);
}

// A store main wrote after raygate-meter (bc71eee, schema version 2): `raygate import` of
// bench/report-pictures' run and its compare (examples/nff-tracer, four scenes, each run's own
// peak). Opened here, migration 3 fills every row's peak memory from its document, as a fresh
// store would, and the compare's head rows get their memory verdicts.
TEST(StorePreviousVersion, AStoreMainWroteWithOwnPeaksGetsThemInHistory) {
  TempDir dir;
  const fs::path path = dir.path() / "results.db";
  fs::copy_file(kFixtures / "main-bc71eee-memory.db", path);
  EXPECT_EQ(rows_of(path, "PRAGMA user_version"), std::vector<std::string>{"2"});
  const auto store = open_store(path.string(), StoreOpen::must_exist);
  EXPECT_EQ(rows_of(path, "PRAGMA user_version"), std::vector<std::string>{"3"});
  std::map<std::pair<std::string, std::string>, SceneRow> expected;  // by (sha, scene)
  for (const StoredDocument& stored : store->documents({})) {
    const ResultsDocument d = results_from_json(stored.document, "stored");
    for (const SceneRow& row : document_rows(d, "", "").scenes) {
      const std::string& sha = d.revision(*parse_role(row.role))->worktree.sha;
      expected[{sha + row.role, row.scene_id}] = row;
    }
  }
  HistoryQuery any;
  any.role = "any";
  const std::vector<HistoryRow> rows = store->measurements(any);
  ASSERT_EQ(rows.size(), 12u);  // 4 scenes: the run's tracer, the compare's base and head
  std::size_t verdicts = 0;
  for (const HistoryRow& row : rows) {
    const SceneRow& want = expected.at({row.sha + row.role, row.scene_id});
    ASSERT_TRUE(row.peak_memory_kib) << row.scene_id << " " << row.role;
    EXPECT_EQ(row.peak_memory_kib, want.peak_memory_kib);
    EXPECT_GT(*row.peak_memory_kib, 1024.0);  // the tracer's few MiB, not raygate's ~130
    EXPECT_LT(*row.peak_memory_kib, 30 * 1024.0);
    EXPECT_EQ(row.memory_verdict, want.memory_verdict);
    if (row.role == "head") {
      EXPECT_EQ(row.memory_verdict, "UNCHANGED");
      ++verdicts;
    }
  }
  EXPECT_EQ(verdicts, 4u);
}

}  // namespace
}  // namespace raygate::test
