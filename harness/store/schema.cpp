// The column tables and the migrations of the store (docs/store.md, "Schema"); the columns and
// the migrations themselves are the lines of store/schema.def.
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
#define RAYGATE_COLUMN(...) {__VA_ARGS__},
#define RAYGATE_MIGRATION(...)
#include "store/schema.def"
#undef RAYGATE_MIGRATION
#undef RAYGATE_COLUMN
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
#define RAYGATE_COLUMN(...)
#define RAYGATE_MIGRATION(...) {__VA_ARGS__},
#include "store/schema.def"
#undef RAYGATE_MIGRATION
#undef RAYGATE_COLUMN
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
