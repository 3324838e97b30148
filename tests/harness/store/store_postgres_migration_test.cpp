// A PostgreSQL team store written before series existed (schema version 1) opens with this
// raygate: migration 2 adds the series columns and fills them from the stored documents, the
// same way the SQLite store does (store_migration_test.cpp), and the documents read back.
#include <gtest/gtest.h>

#include "core/sha256.h"
#include "postgres_server.h"
#include "results_fixture.h"
#include "store/history.h"
#include "store/migrate.h"
#include "store/postgres_handle.h"
#include "results/series.h"
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

// The rows with schema version 1's columns, as raygate wrote them then.
void insert_v1(PgConnection& db, const DocumentRows& rows, const std::string& document_json = "") {
  const DocumentRow& d = rows.document;
  PgParams p;
  // A text of its own has its own hash, as the raygate that stored it took it.
  const std::string& text = document_json.empty() ? d.document_json : document_json;
  p.text(sha256_hex(text)).integer(d.schema_version).text(d.kind).text(d.branch).text(d.suite);
  p.text(d.shard).flag(d.complete).text(d.started_at).text(d.finished_at).text(d.stored_at);
  p.text(d.raygate_version).text(d.baseline_version).text(d.baseline_sha256);
  p.text(d.machine_hostname).text(d.machine_cpu_model);
  p.text(text);
  const std::int64_t id = db.exec(R"sql(
INSERT INTO documents (content_sha256, schema_version, kind, branch, suite, shard, complete,
  started_at, finished_at, stored_at, raygate_version, baseline_version, baseline_sha256,
  machine_hostname, machine_cpu_model, document_json)
VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16) RETURNING id)sql",
                                  p)
                              .integer(0, 0);
  for (const RevisionRow& r : rows.revisions) {
    PgParams q;
    q.integer(id).text(r.role).text(r.repository).text(r.sha).text(r.short_sha).text(r.subject);
    q.text(r.author).text(r.ref_name).text(r.commit_time).integer(r.commit_unix).flag(r.dirty);
    q.text(r.adapter_name).text(r.adapter_hash);
    db.exec(R"sql(
INSERT INTO revisions (document_id, role, repository, sha, short_sha, subject, author, ref_name,
  commit_time, commit_unix, dirty, adapter_name, adapter_hash)
VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13))sql",
            q);
  }
  for (const SceneRow& r : rows.scenes) {
    PgParams q;
    q.integer(id).text(r.scene_id).text(r.role).text(r.status).integer(r.rounds).real(r.ratio);
    q.real(r.ratio_lower).real(r.ratio_upper).real(r.tracer_median_seconds);
    q.real(r.baseline_median_seconds).text(r.image_verdict).real(r.image_max_error);
    q.real(r.image_rms_error).real(r.change).real(r.change_lower).real(r.change_upper);
    q.text(r.change_verdict);
    db.exec(R"sql(
INSERT INTO scene_results (document_id, scene_id, role, status, rounds, normalized_ratio,
  ratio_lower, ratio_upper, tracer_median_seconds, baseline_median_seconds, image_verdict,
  image_max_error, image_rms_error, relative_change, change_lower, change_upper, change_verdict)
VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16, $17))sql",
            q);
  }
}

TEST(StorePostgresMigration, AVersionOneStoreGetsItsSeriesFromItsDocumentsAndStaysReadable) {
  const std::string url = postgres_server().create_database();
  const ResultsDocument first = make_document(balls(1, 1, 1.0));
  const ResultsDocument second = make_document(balls(2, 2, 1.1));
  {
    PgConnection db = PgConnection::connect(url);
    // Migration 1 is released and never edited: its SQL is the version 1 schema.
    ASSERT_EQ(migrate(db, store_migrations().first(1)), 1);
    insert_v1(db, document_rows(first, "main", "2026-07-01T13:00:00Z"));
    insert_v1(db, document_rows(second, "main", "2026-07-02T13:00:00Z"));
    insert_v1(db, document_rows(make_document(balls(3, 3, 9.0)), "main", "t"),
              R"({"schema_version": 99})");
  }

  const auto store = open_store(url, StoreOpen::must_exist);
  {
    PgConnection db = PgConnection::connect(url);
    EXPECT_EQ(schema_version(db), 3);
  }
  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 3u);
  EXPECT_EQ(stored[1].document, to_json(second));
  EXPECT_EQ(stored[2].document, to_json(first));

  const DocumentRows fresh = document_rows(first, "main", "t");
  for (const HistoryRow& row : store->measurements({})) {
    if (row.sha == fake_sha(3)) {
      EXPECT_EQ(row.series_id, unknown_series_id(row.document_id));
      EXPECT_EQ(row.repository_key, "unknown");
      continue;
    }
    EXPECT_EQ(row.repository_key, "path:/tmp/tracer-repo");
    EXPECT_EQ(row.timing, fresh.document.timing);
    const SceneRow& expected = fresh.scenes.at(row.scene_id == "balls" ? 0 : 1);
    EXPECT_EQ(row.series_id, expected.series_id) << row.scene_id;
    EXPECT_EQ(row.scene_settings, expected.scene_settings);
  }

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

}  // namespace
}  // namespace raygate::test
