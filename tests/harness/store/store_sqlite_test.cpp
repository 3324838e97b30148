// The SQLite store: documents kept whole and once, the schema versioned and migrated, one
// transaction per document (a failure halfway leaves nothing), and errors that say what failed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sqlite3.h>

#include "core/error.h"
#include "core/fs.h"
#include "../core/file_size_limit.h"
#include "results_fixture.h"
#include "store/migrate.h"
#include "store/sql_store.h"
#include "store/store.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

DocumentSpec two_scenes(int seed) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.scenes = {{"balls", 0.8}, {"gears", 1.2, 0.02, 2.0, 0.004, ImageVerdict::warn}};
  return spec;
}

// A query with one field set (designated initializers warn under -Wextra on GCC 12).
template <typename Set>
DocumentQuery query(Set set) {
  DocumentQuery q;
  set(q);
  return q;
}

// A raw connection for looking inside the file, or for sabotaging it.
struct Raw {
  explicit Raw(const std::filesystem::path& path) { sqlite3_open(path.c_str(), &db); }
  ~Raw() { sqlite3_close(db); }
  std::string text(const std::string& sql) const {
    sqlite3_stmt* s = nullptr;
    sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr);
    std::string out;
    if (sqlite3_step(s) == SQLITE_ROW && sqlite3_column_text(s, 0)) {
      out = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
    }
    sqlite3_finalize(s);
    return out;
  }
  int exec(const std::string& sql) const { return sqlite3_exec(db, sql.c_str(), 0, 0, 0); }
  sqlite3* db = nullptr;
};

TEST(StoreSqlite, StoresTheWholeDocumentAndReadsItBack) {
  TempDir dir;
  const auto store = open_store((dir.path() / "results.db").string());
  const ResultsDocument document = make_document(two_scenes(1));
  const AddOutcome added = store->add(document, "main");
  EXPECT_FALSE(added.duplicate);
  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].id, added.document_id);
  EXPECT_EQ(stored[0].branch, "main");
  EXPECT_EQ(stored[0].content_sha256.size(), 64u);
  // Export reproduces what write_results writes, byte for byte.
  EXPECT_EQ(stored[0].document.dump(1), to_json(document).dump(1));
  EXPECT_EQ(to_json(results_from_json(stored[0].document, "stored")), to_json(document));
}

TEST(StoreSqlite, TheSameDocumentTwiceIsStoredOnce) {
  TempDir dir;
  const auto store = open_store((dir.path() / "results.db").string());
  const ResultsDocument document = make_document(two_scenes(1));
  const AddOutcome first = store->add(document, "main");
  const AddOutcome again = store->add(document, "other-branch");
  EXPECT_TRUE(again.duplicate);
  EXPECT_EQ(again.document_id, first.document_id);
  EXPECT_FALSE(store->add(make_document(two_scenes(2)), "main").duplicate);
  EXPECT_EQ(store->documents({}).size(), 2u);
}

TEST(StoreSqlite, SchemaIsVersionedInWalModeAndMigratedOnce) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string());
  open_store(path.string());  // reopening applies nothing again
  Raw raw(path);
  EXPECT_EQ(raw.text("PRAGMA user_version"), "3");
  EXPECT_EQ(raw.text("PRAGMA journal_mode"), "wal");
  EXPECT_EQ(raw.text("SELECT count(*) FROM schema_migrations"), "3");
  EXPECT_EQ(raw.text("SELECT description FROM schema_migrations WHERE version = 1"),
            "documents, revisions, scene_results");
}

TEST(StoreSqlite, ASecondMigrationAppliesOnceOnTopOfTheFirst) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string());
  std::vector<Migration> migrations(store_migrations().begin(), store_migrations().end());
  migrations.push_back({4, "documents.note", "ALTER TABLE documents ADD COLUMN note TEXT"});
  SqliteDb db = SqliteDb::open(path, false);
  EXPECT_EQ(migrate(db, migrations), 4);
  EXPECT_EQ(migrate(db, migrations), 4);
  Raw raw(path);
  EXPECT_EQ(raw.text("SELECT count(*) FROM schema_migrations"), "4");
  EXPECT_EQ(raw.exec("SELECT note FROM documents"), SQLITE_OK);
}

TEST(StoreSqlite, AFailingMigrationLeavesTheVersionBefore) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string());
  std::vector<Migration> migrations(store_migrations().begin(), store_migrations().end());
  migrations.push_back(
      {4, "broken", "CREATE TABLE extra (x); INSERT INTO no_such_table VALUES (1)"});
  SqliteDb db = SqliteDb::open(path, false);
  EXPECT_THROW(migrate(db, migrations), InfraError);
  EXPECT_EQ(schema_version(db), 3);
  Raw raw(path);
  EXPECT_EQ(raw.text("SELECT count(*) FROM sqlite_master WHERE name = 'extra'"), "0");
}

TEST(StoreSqlite, AStoreFromANewerRaygateIsRefused) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string());
  Raw(path).exec("PRAGMA user_version = 99");
  try {
    open_store(path.string());
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("schema version 99 is newer"));
  }
}

TEST(StoreSqlite, AFailureHalfwayThroughADocumentStoresNothingOfIt) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  const auto store = open_store(path.string());
  DocumentSpec spec = two_scenes(1);
  spec.scenes.push_back({"balls", 0.9});  // the same scene twice: its second row cannot go in
  try {
    store->add(make_document(spec), "main");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(), HasSubstr("UNIQUE constraint failed: scene_results"));
    EXPECT_THAT(e.what(), HasSubstr("INSERT INTO scene_results"));
    EXPECT_THAT(e.what(), HasSubstr(path.string()));
  }
  Raw raw(path);
  EXPECT_EQ(raw.text("SELECT count(*) FROM documents"), "0");
  EXPECT_EQ(raw.text("SELECT count(*) FROM revisions"), "0");
  EXPECT_EQ(raw.text("SELECT count(*) FROM scene_results"), "0");
  EXPECT_FALSE(store->add(make_document(two_scenes(1)), "main").duplicate);  // still usable
}

TEST(StoreSqlite, AnInjectedFailureRollsBackAndKeepsEarlierDocuments) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  const auto store = open_store(path.string());
  store->add(make_document(two_scenes(1)), "main");
  Raw raw(path);
  ASSERT_EQ(raw.exec("CREATE TRIGGER boom BEFORE INSERT ON scene_results WHEN NEW.scene_id = "
                     "'gears' BEGIN SELECT RAISE(ABORT, 'injected failure'); END"),
            SQLITE_OK);
  EXPECT_THROW(store->add(make_document(two_scenes(2)), "main"), InfraError);
  EXPECT_EQ(raw.text("SELECT count(*) FROM documents"), "1");
  EXPECT_EQ(raw.text("SELECT count(*) FROM scene_results"), "2");
  ASSERT_EQ(raw.exec("DROP TRIGGER boom"), SQLITE_OK);
  EXPECT_FALSE(store->add(make_document(two_scenes(2)), "main").duplicate);
  EXPECT_EQ(store->documents({}).size(), 2u);
}

// The seventh sweep: a store whose -wal file is a symbolic link gave only SQLite's "unable to
// open database file"; the link is named now.
TEST(StoreSqlite, AWalFileThatIsALinkIsNamed) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string())->add(make_document(two_scenes(1)), "main");
  write_file_atomically(dir.path() / "elsewhere", "");
  std::filesystem::create_symlink(dir.path() / "elsewhere", path.string() + "-wal");
  try {
    open_store(path.string())->add(make_document(two_scenes(2)), "main");
    FAIL() << "a -wal link was opened";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("results.db-wal is a symbolic link, which SQLite does not open"));
  }
  EXPECT_EQ(read_file(dir.path() / "elsewhere"), "");
}

TEST(StoreSqlite, ALockedDatabaseIsAnInfrastructureError) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string());
  Raw holder(path);
  ASSERT_EQ(holder.exec("BEGIN IMMEDIATE"), SQLITE_OK);
  const auto store = open_sqlite_store(path, StoreOpen::must_exist, std::chrono::milliseconds(200));
  try {
    store->add(make_document(two_scenes(1)), "main");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(), HasSubstr("database is locked"));
    EXPECT_THAT(e.what(), HasSubstr("BEGIN IMMEDIATE"));
  }
  holder.exec("ROLLBACK");
}

TEST(StoreSqlite, AFileThatIsNotADatabaseIsAUsageError) {
  TempDir dir;
  write_file_atomically(dir.path() / "notes.db", std::string(4096, 'x'));
  EXPECT_THROW(open_store((dir.path() / "notes.db").string()), UsageError);
}

// The seventh sweep: `import` into a new store on a full disk exited 3 (right) and left a 0-byte
// file, which the next command took for a broken store. A store the open created and could not
// set up is removed; one that was there is left as it was.
TEST(StoreSqlite, ANewStoreThatCannotBeSetUpIsNotLeftBehind) {
  const TempDir dir;
  const std::filesystem::path path = dir.path() / "results.db";
  {
    const FileSizeLimit full_disk(0);
    EXPECT_THROW(open_store(path.string(), StoreOpen::create_if_missing), InfraError);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  open_store(path.string(), StoreOpen::create_if_missing)
      ->add(make_document(two_scenes(1)), "main");
  {
    const FileSizeLimit full_disk(0);
    try {
      open_store(path.string(), StoreOpen::create_if_missing)
          ->add(make_document(two_scenes(2)), "main");
    } catch (const Error&) {  // a full disk may stop the second document, never lose the first
    }
  }
  EXPECT_EQ(open_store(path.string(), StoreOpen::must_exist)->documents({}).size(), 1u);
}

TEST(StoreSqlite, AMissingStoreIsAnErrorWhenItMustExist) {
  TempDir dir;
  try {
    open_store((dir.path() / "none.db").string(), StoreOpen::must_exist);
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("does not exist"));
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "none.db"));
}

// Commands that only read do not turn a file into a store: an empty file (a user's notes) or
// another program's database was given raygate's tables (a sweep).
TEST(StoreSqlite, AFileThatIsNoStoreIsRefusedWhenItMustExistAndLeftUntouched) {
  TempDir dir;
  write_file_atomically(dir.path() / "empty.txt", "");
  try {
    open_store((dir.path() / "empty.txt").string(), StoreOpen::must_exist);
    FAIL() << "an empty file was taken for a store";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("is not a raygate store (an empty file)"));
  }
  EXPECT_EQ(std::filesystem::file_size(dir.path() / "empty.txt"), 0u);
  {
    Raw other(dir.path() / "other.db");
    other.exec("CREATE TABLE notes (x TEXT)");
  }
  EXPECT_THROW(open_store((dir.path() / "other.db").string(), StoreOpen::must_exist), UsageError);
  EXPECT_EQ(Raw(dir.path() / "other.db").text("SELECT count(*) FROM sqlite_master"), "1");
}

// Another program's SQLite database with a table of raygate's names is not made a store by a
// command that writes either (import stopped in SQL's words, "table documents already exists").
TEST(StoreSqlite, ADatabaseWithAnotherProgramsTablesIsNotMadeAStore) {
  TempDir dir;
  const auto path = dir.path() / "other.db";
  Raw(path).exec("CREATE TABLE documents (x TEXT)");
  try {
    open_store(path.string());
    FAIL() << "another program's database was made a store";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("not a raygate store: it has a table 'documents'"));
  }
  EXPECT_EQ(Raw(path).text("SELECT count(*) FROM sqlite_master"), "1");
  EXPECT_EQ(Raw(path).text("PRAGMA journal_mode"), "delete");  // not switched to WAL (a sweep)
  // Its own schema_migrations, or a user_version naming tables it lacks: refused the same way.
  for (const std::string& setup :
       {std::string("CREATE TABLE schema_migrations (x)"),
        std::string("CREATE TABLE documents (x); PRAGMA user_version = 3")}) {
    const auto other = dir.path() / "other2.db";
    std::filesystem::remove(other);
    Raw(other).exec(setup);
    for (StoreOpen mode : {StoreOpen::create_if_missing, StoreOpen::must_exist}) {
      try {
        open_store(other.string(), mode)->history({});
        ADD_FAILURE() << setup << ": taken for a store";
      } catch (const UsageError& e) {
        EXPECT_THAT(e.what(), HasSubstr("not a raygate store")) << setup;
      }
    }
    EXPECT_EQ(Raw(other).text("PRAGMA journal_mode"), "delete") << setup;
  }
}

// SQLite keeps what a hand edit gives a column: text or an impossible ratio read back would
// change what history and alert say (a ratio of 'abc' hid a +50% regression; a sweep).
TEST(StoreSqlite, NumbersEditedByHandAreADamagedStoreNotAnotherVerdict) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  open_store(path.string())->add(make_document(two_scenes(1)), "main");
  for (const char* value : {"'abc'", "0", "-1", "1e308"}) {
    Raw(path).exec(std::string("UPDATE scene_results SET normalized_ratio = ") + value +
                   " WHERE scene_id = 'gears'");
    try {
      open_store(path.string(), StoreOpen::must_exist)->history({});
      ADD_FAILURE() << value << " was read";
    } catch (const InfraError& e) {
      EXPECT_THAT(e.what(), HasSubstr("document 1"));
      EXPECT_THAT(e.what(), HasSubstr("normalized_ratio"));
      EXPECT_THAT(e.what(), HasSubstr("the store is damaged"));
    }
  }
  Raw(path).exec("UPDATE scene_results SET normalized_ratio = NULL WHERE scene_id = 'gears'");
  EXPECT_NO_THROW(open_store(path.string(), StoreOpen::must_exist)->history({}));
  // Words as numbers: `<script>` as the image verdict was shown by history as the verdict.
  for (const char* edit : {"UPDATE scene_results SET image_verdict = '<script>'",
                           "UPDATE scene_results SET status = 'fine'",
                           "UPDATE scene_results SET memory_verdict = 'GREAT'"}) {
    const auto fresh = dir.path() / "words.db";
    std::filesystem::remove(fresh);
    open_store(fresh.string())->add(make_document(two_scenes(1)), "main");
    Raw(fresh).exec(edit);
    try {
      open_store(fresh.string(), StoreOpen::must_exist)->history({});
      ADD_FAILURE() << edit << ": read";
    } catch (const InfraError& e) {
      EXPECT_THAT(e.what(), HasSubstr("a word no document holds; the store is damaged"));
    }
  }
}

// A document's text is what its content_sha256 was taken of: one document's text copied into
// another's row, or `{}`, was exported as if it were that document (a sweep).
TEST(StoreSqlite, ADocumentTextEditedByHandIsADamagedStoreNotAnExport) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  {
    const auto store = open_store(path.string());
    store->add(make_document(two_scenes(1)), "main");
    store->add(make_document(two_scenes(2)), "main");
  }
  EXPECT_EQ(open_store(path.string(), StoreOpen::must_exist)->documents({}).size(), 2u);
  for (const char* edit :
       {"UPDATE documents SET document_json = (SELECT document_json FROM documents WHERE id = 2) "
        "WHERE id = 1",
        "UPDATE documents SET document_json = '{}' WHERE id = 1"}) {
    Raw(path).exec(edit);
    try {
      open_store(path.string(), StoreOpen::must_exist)->documents({});
      ADD_FAILURE() << edit << ": exported";
    } catch (const InfraError& e) {
      EXPECT_THAT(e.what(), HasSubstr("document 1's text does not match its content_sha256"));
      EXPECT_THAT(e.what(), HasSubstr("the store is damaged"));
    }
  }
}

// postgresql:// URLs open the team store (store_postgres_test.cpp); other URLs are refused.
TEST(StoreSqlite, OtherUrlsAreRefusedWithoutEchoingThePassword) {
  try {
    open_store("mysql://ci:s3cret@db.example/raygate");
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown kind of URL"));
    EXPECT_THAT(e.what(), HasSubstr("mysql://ci@db.example/raygate"));
    EXPECT_THAT(e.what(), Not(HasSubstr("s3cret")));
  }
}

TEST(StoreSqlite, DocumentsFilterBySha) {
  TempDir dir;
  const auto store = open_store((dir.path() / "results.db").string());
  for (int seed = 1; seed <= 3; ++seed) store->add(make_document(two_scenes(seed)), "main");
  const auto by_sha =
      store->documents(query([](DocumentQuery& q) { q.sha_prefix = fake_sha(2).substr(0, 8); }));
  ASSERT_EQ(by_sha.size(), 1u);
  EXPECT_EQ(by_sha[0].document["revisions"][0]["worktree"]["sha"], fake_sha(2));
  const auto last_two = store->documents(query([](DocumentQuery& q) { q.last = 2; }));
  ASSERT_EQ(last_two.size(), 2u);
  EXPECT_GT(last_two[0].id, last_two[1].id);  // newest stored first
  EXPECT_TRUE(store->documents(query([](DocumentQuery& q) { q.branch = "nope"; })).empty());
}

TEST(StoreSqlite, BranchComesFromTheRevisionsRef) {
  ResultsDocument document = make_document(two_scenes(1));
  EXPECT_EQ(branch_of(document, "fallback"), "main");
  document.revisions[0].worktree.ref_name.clear();
  EXPECT_EQ(branch_of(document, "fallback"), "fallback");
}

}  // namespace
}  // namespace raygate::test
