// The column tables and the migrations of the store (docs/store.md, "Schema").
#include "store/schema.h"

namespace raygate {

namespace {

using D = DocumentRow;
using R = RevisionRow;
using S = SceneRow;
using H = HistoryRow;

// documents: one row per stored document, the document whole in document_json (canonical text:
// export gives it back byte for byte), after the generated id. revisions: one row per measured
// revision (role) of a document; scene_results: one per scene and revision; both after
// document_id.
constexpr Column kColumns[] = {
    {1, "content_sha256", &D::content_sha256},
    {1, "schema_version", &D::schema_version},
    {1, "kind", &D::kind},
    {1, "branch", &D::branch, &H::branch},
    {1, "suite", &D::suite, &H::suite},
    {1, "shard", &D::shard},
    {1, "complete", &D::complete, &H::complete},
    {1, "started_at", &D::started_at, &H::measured_at},
    {1, "finished_at", &D::finished_at},
    {1, "stored_at", &D::stored_at, &H::stored_at},
    {1, "raygate_version", &D::raygate_version},
    {1, "baseline_version", &D::baseline_version},
    {1, "baseline_sha256", &D::baseline_sha256, &H::baseline_sha256},
    {1, "machine_hostname", &D::machine_hostname, &H::machine_hostname},
    {1, "machine_cpu_model", &D::machine_cpu_model, &H::machine_cpu_model},
    {1, "document_json", &D::document_json},
    {2, "timing", &D::timing, &H::timing},
    {2, "baseline_accel", &D::baseline_accel, &H::baseline_accel},

    {1, "role", &R::role, &H::role},
    {1, "repository", &R::repository},
    {1, "sha", &R::sha, &H::sha},
    {1, "short_sha", &R::short_sha, &H::short_sha},
    {1, "subject", &R::subject, &H::subject},
    {1, "author", &R::author},
    {1, "ref_name", &R::ref_name},
    {1, "commit_time", &R::commit_time, &H::commit_time},
    {1, "commit_unix", &R::commit_unix, &H::commit_unix},
    {1, "dirty", &R::dirty, &H::dirty},
    {1, "adapter_name", &R::adapter_name, &H::adapter_name},
    {1, "adapter_hash", &R::adapter_hash},
    {2, "repository_key", &R::repository_key, &H::repository_key},

    {1, "scene_id", &S::scene_id, &H::scene_id},
    {1, "role", &S::role},
    {1, "status", &S::status, &H::status},
    {1, "rounds", &S::rounds},
    {1, "normalized_ratio", &S::ratio, &H::ratio},
    {1, "ratio_lower", &S::ratio_lower, &H::ratio_lower},
    {1, "ratio_upper", &S::ratio_upper, &H::ratio_upper},
    {1, "tracer_median_seconds", &S::tracer_median_seconds},
    {1, "baseline_median_seconds", &S::baseline_median_seconds, &H::baseline_median_seconds},
    {1, "image_verdict", &S::image_verdict, &H::image_verdict},
    {1, "image_max_error", &S::image_max_error, &H::image_max_error},
    {1, "image_rms_error", &S::image_rms_error, &H::image_rms_error},
    {1, "relative_change", &S::change},
    {1, "change_lower", &S::change_lower},
    {1, "change_upper", &S::change_upper},
    {1, "change_verdict", &S::change_verdict},
    {2, "scene_settings", &S::scene_settings, &H::scene_settings},
    {2, "series_id", &S::series_id, &H::series_id},
    {3, "peak_memory_kib", &S::peak_memory_kib, &H::peak_memory_kib},
    {3, "memory_change", &S::memory_change, &H::memory_change},
    {3, "memory_verdict", &S::memory_verdict, &H::memory_verdict},
};

// Migration 1's indexes, for history's filters and joins.
constexpr const char* kIndexes = R"sql(
CREATE INDEX documents_branch ON documents(branch, id);
CREATE INDEX documents_machine ON documents(machine_hostname, machine_cpu_model);
CREATE INDEX revisions_sha ON revisions(sha);
CREATE INDEX revisions_commit ON revisions(role, commit_unix);
CREATE INDEX scene_results_scene ON scene_results(scene_id, role);
)sql";

// Migration 2: the parts of each row's series (results/series.h) as columns, so history filters
// and groups by them; rows stored before are filled in from their documents.
constexpr const char* kSeriesIndexes = R"sql(
CREATE INDEX revisions_repository ON revisions(repository_key, adapter_name);
CREATE INDEX scene_results_series ON scene_results(series_id);
)sql";

const Migration kMigrations[] = {
    {1, "documents, revisions, scene_results", kIndexes},
    {2,
     "series columns: documents.timing, baseline_accel; revisions.repository_key; "
     "scene_results.scene_settings, series_id",
     kSeriesIndexes, true},
    // Migration 3 (issue 27): peak memory per scene and revision, for history, alert and the
    // trend; rows stored before get it from their documents' runs (none before raygate-meter).
    {3, "peak memory: scene_results.peak_memory_kib, memory_change, memory_verdict", "", true},
};

const TableShape kTables[] = {
    {StoreTable::documents, "documents", "d", false, {}, {"UNIQUE (content_sha256)"}},
    {StoreTable::revisions,
     "revisions",
     "r",
     true,
     {"role"},
     {"FOREIGN KEY (document_id) REFERENCES documents(id) ON DELETE CASCADE"}},
    {StoreTable::scene_results,
     "scene_results",
     "s",
     true,
     {"scene_id", "role"},
     {"FOREIGN KEY (document_id, role) REFERENCES revisions(document_id, role) ON DELETE CASCADE"}},
};

// The alternative of a field's type in FieldOf: text, flag, int32, int64, optional int64, real.
std::size_t type_index(const Column& column) {
  return std::visit([](const auto& field) { return field.index(); }, column.field);
}

}  // namespace

SqlType Column::type() const {
  constexpr SqlType kTypes[] = {SqlType::text,  SqlType::flag,  SqlType::int32,
                                SqlType::int64, SqlType::int64, SqlType::real};
  return kTypes[type_index(*this)];
}

bool Column::nullable() const { return type_index(*this) >= 4; }

std::span<const Column> store_columns() { return kColumns; }
std::span<const TableShape> store_tables() { return kTables; }
const TableShape& store_table(StoreTable table) { return kTables[static_cast<int>(table)]; }
std::span<const Migration> store_migrations() { return kMigrations; }

}  // namespace raygate
