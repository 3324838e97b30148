// An SQLite store written before series existed (schema version 1) opens with this raygate:
// migration 2 adds the series columns and fills them from the stored documents, so old rows
// join the series of new ones, stored documents read back unchanged, and a document that no
// longer reads becomes a series of its own.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include "core/sha256.h"
#include "core/fs.h"
#include "results_fixture.h"
#include "store/history.h"
#include "results/series.h"
#include "store/migrate.h"
#include "store/sqlite_handle.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate::test {
namespace {

DocumentSpec balls(int seed, int day, double ratio) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.commit_time = "2026-07-0" + std::to_string(day) + "T10:00:00+00:00";
  spec.started_at = "2026-07-0" + std::to_string(day) + "T12:00:00Z";
  spec.scenes = {{"balls", ratio}, {"gears", 2 * ratio}};
  return spec;
}

// The rows of `rows` with schema version 1's columns, as raygate wrote them then; the stored
// text is `document_json` when given (a document this raygate cannot read).
void insert_v1(SqliteDb& db, const DocumentRows& rows, const std::string& document_json = "") {
  const DocumentRow& d = rows.document;
  SqliteStatement doc(db, R"sql(
INSERT INTO documents (content_sha256, schema_version, kind, branch, suite, shard, complete,
  started_at, finished_at, stored_at, raygate_version, baseline_version, baseline_sha256,
  machine_hostname, machine_cpu_model, document_json)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16))sql");
  // A text of its own has its own hash, as the raygate that stored it took it.
  const std::string& text = document_json.empty() ? d.document_json : document_json;
  doc.bind_text(1, sha256_hex(text)).bind_int(2, d.schema_version).bind_text(3, d.kind);
  doc.bind_text(4, d.branch).bind_text(5, d.suite).bind_text(6, d.shard).bind_flag(7, d.complete);
  doc.bind_text(8, d.started_at).bind_text(9, d.finished_at).bind_text(10, d.stored_at);
  doc.bind_text(11, d.raygate_version).bind_text(12, d.baseline_version);
  doc.bind_text(13, d.baseline_sha256).bind_text(14, d.machine_hostname);
  doc.bind_text(15, d.machine_cpu_model);
  doc.bind_text(16, text).run();
  const std::int64_t id = sqlite3_last_insert_rowid(db.get());
  for (const RevisionRow& r : rows.revisions) {
    SqliteStatement s(db, R"sql(
INSERT INTO revisions (document_id, role, repository, sha, short_sha, subject, author, ref_name,
  commit_time, commit_unix, dirty, adapter_name, adapter_hash)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13))sql");
    s.bind_int(1, id).bind_text(2, r.role).bind_text(3, r.repository).bind_text(4, r.sha);
    s.bind_text(5, r.short_sha).bind_text(6, r.subject).bind_text(7, r.author);
    s.bind_text(8, r.ref_name).bind_text(9, r.commit_time).bind_int(10, r.commit_unix);
    s.bind_flag(11, r.dirty).bind_text(12, r.adapter_name).bind_text(13, r.adapter_hash).run();
  }
  for (const SceneRow& r : rows.scenes) {
    SqliteStatement s(db, R"sql(
INSERT INTO scene_results (document_id, scene_id, role, status, rounds, normalized_ratio,
  ratio_lower, ratio_upper, tracer_median_seconds, baseline_median_seconds, image_verdict,
  image_max_error, image_rms_error, relative_change, change_lower, change_upper, change_verdict)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17))sql");
    s.bind_int(1, id).bind_text(2, r.scene_id).bind_text(3, r.role).bind_text(4, r.status);
    s.bind_int(5, r.rounds).bind_real(6, r.ratio).bind_real(7, r.ratio_lower);
    s.bind_real(8, r.ratio_upper).bind_real(9, r.tracer_median_seconds);
    s.bind_real(10, r.baseline_median_seconds).bind_text(11, r.image_verdict);
    s.bind_real(12, r.image_max_error).bind_real(13, r.image_rms_error).bind_real(14, r.change);
    s.bind_real(15, r.change_lower).bind_real(16, r.change_upper);
    s.bind_text(17, r.change_verdict).run();
  }
}

TEST(StoreMigration, AVersionOneStoreGetsItsSeriesFromItsDocumentsAndStaysReadable) {
  TempDir dir;
  const auto path = dir.path() / "old.db";
  const ResultsDocument first = make_document(balls(1, 1, 1.0));
  const ResultsDocument second = make_document(balls(2, 2, 1.1));
  {
    SqliteDb db = SqliteDb::open(path, true);
    // Migration 1 is released and never edited: its SQL is the version 1 schema.
    ASSERT_EQ(migrate(db, store_migrations().first(1)), 1);
    insert_v1(db, document_rows(first, "main", "2026-07-01T13:00:00Z"));
    insert_v1(db, document_rows(second, "main", "2026-07-02T13:00:00Z"));
    // A document this raygate cannot read back (from a newer schema, say).
    DocumentRows unreadable = document_rows(make_document(balls(3, 3, 9.0)), "main", "t");
    insert_v1(db, unreadable, R"({"schema_version": 99})");
  }

  const auto store = open_store(path.string(), StoreOpen::must_exist);
  {
    SqliteDb db = SqliteDb::open(path, false);
    EXPECT_EQ(schema_version(db), 3);
  }
  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 3u);
  EXPECT_EQ(stored[1].document, to_json(second));  // newest first
  EXPECT_EQ(stored[2].document, to_json(first));

  // Rows get exactly the series a fresh store gives them.
  const DocumentRows fresh = document_rows(first, "main", "t");
  for (const HistoryRow& row : store->measurements({})) {
    if (row.sha == fake_sha(3)) {
      EXPECT_EQ(row.series_id, unknown_series_id(row.document_id));
      EXPECT_EQ(row.repository_key, "unknown");
      continue;
    }
    EXPECT_EQ(row.repository_key, "path:/tmp/tracer-repo");
    EXPECT_EQ(row.adapter_name, "cmake-nff");
    EXPECT_EQ(row.timing, fresh.document.timing);
    EXPECT_EQ(row.baseline_accel, "none");
    const SceneRow& expected = fresh.scenes.at(row.scene_id == "balls" ? 0 : 1);
    EXPECT_EQ(row.series_id, expected.series_id) << row.scene_id;
    EXPECT_EQ(row.scene_settings, expected.scene_settings);
  }

  // Stored again, an old document is still the same content; a new one continues its series.
  EXPECT_TRUE(store->add(first, "main").duplicate);
  store->add(make_document(balls(4, 4, 1.2)), "main");
  HistoryQuery q;
  q.scenes = {"balls"};
  q.repository = "path:";
  const std::vector<HistoryRow> rows = store->history(q);
  const std::vector<SeriesColumn> columns = series_columns(rows);
  ASSERT_EQ(columns.size(), 1u);
  EXPECT_EQ(scene_trend(group_by_commit(rows), columns[0]).ratios,
            (std::vector<double>{1.0, 1.1, 1.2}));
}

// Migration 3 (issue 27): the peak memory of rows stored before it comes from their documents'
// runs: each role's median own peak, and on a compare's head row the change and the verdict
// under the limit the document was measured with; a document from before raygate-meter has none.
TEST(StoreMigration, RowsStoredBeforePeakMemoryGetItFromTheirDocuments) {
  TempDir dir;
  const auto path = dir.path() / "old.db";
  DocumentSpec compare = balls(1, 1, 1.0);
  compare.kind = DocumentKind::compare;
  compare.roles = {Role::base, Role::head};
  compare.with_change = true;
  compare.scenes = {{"balls", 1.0}, {"gears", 2.0}};
  compare.scenes[0].peak_kib = 8 * 1024;
  compare.scenes[0].head_peak_kib = 58 * 1024;  // +50 MiB
  compare.scenes[1].peak_kib = 4 * 1024;        // head the same
  const ResultsDocument with_peaks = make_document(compare);
  const ResultsDocument before_meter = make_document(balls(2, 2, 1.1));
  {
    SqliteDb db = SqliteDb::open(path, true);
    ASSERT_EQ(migrate(db, store_migrations().first(1)), 1);
    insert_v1(db, document_rows(with_peaks, "main", "2026-07-01T13:00:00Z"));
    insert_v1(db, document_rows(before_meter, "main", "2026-07-02T13:00:00Z"));
  }
  const auto store = open_store(path.string(), StoreOpen::must_exist);
  {
    SqliteDb db = SqliteDb::open(path, false);
    EXPECT_EQ(schema_version(db), 3);
  }
  HistoryQuery any;
  any.role = "any";
  std::size_t checked = 0;
  for (const HistoryRow& row : store->measurements(any)) {
    if (row.sha == fake_sha(2)) {
      EXPECT_FALSE(row.peak_memory_kib) << "raygate's own peak is not the tracer's";
      EXPECT_EQ(row.memory_verdict, "");
      continue;
    }
    const bool balls_row = row.scene_id == "balls";
    const double base_peak = balls_row ? 8 * 1024 : 4 * 1024;
    ASSERT_TRUE(row.peak_memory_kib) << row.scene_id << " " << row.role;
    if (row.role == "base") {
      EXPECT_DOUBLE_EQ(*row.peak_memory_kib, base_peak);
      EXPECT_EQ(row.memory_verdict, "");
    } else {
      EXPECT_DOUBLE_EQ(*row.peak_memory_kib, balls_row ? 58 * 1024 : base_peak);
      EXPECT_EQ(row.memory_verdict, balls_row ? "REGRESSED" : "UNCHANGED");
      ASSERT_TRUE(row.memory_change);
      EXPECT_NEAR(*row.memory_change, balls_row ? 50.0 / 8.0 : 0.0, 1e-9);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 4u);
  // A fresh store gives the same rows.
  const DocumentRows fresh = document_rows(with_peaks, "main", "t");
  EXPECT_EQ(fresh.scenes.at(1).memory_verdict, "REGRESSED");  // balls, head
}

}  // namespace
}  // namespace raygate::test
