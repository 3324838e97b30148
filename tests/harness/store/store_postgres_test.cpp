// The PostgreSQL team store on a real server: documents kept whole and once, the schema
// versioned and migrated, one transaction per document (a constraint failure or a connection
// killed halfway leaves nothing), and errors that name the server without the password.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "postgres_server.h"
#include "results_fixture.h"
#include "store/migrate.h"
#include "store/postgres_handle.h"
#include "store/postgres_url.h"
#include "store/store.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

DocumentSpec two_scenes(int seed) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.scenes = {{"balls", 0.8}, {"gears", 1.2, 0.02, 2.0, 0.004, ImageVerdict::warn}};
  return spec;
}

template <typename Set>
DocumentQuery query(Set set) {
  DocumentQuery q;
  set(q);
  return q;
}

class StorePostgres : public ::testing::Test {
 protected:
  std::string url = postgres_server().create_database();
};

TEST_F(StorePostgres, StoresTheWholeDocumentAndExportsItByteForByte) {
  const auto store = open_store(url);
  DocumentSpec spec = two_scenes(1);
  spec.subject = "naïve BVH → 2× faster \"quoted\" \\ back";  // UTF-8 and escapes survive
  spec.scenes[0].ratio = 0.1 + 0.2;                           // a double with 17 digits
  const ResultsDocument document = make_document(spec);
  const AddOutcome added = store->add(document, "main");
  EXPECT_FALSE(added.duplicate);
  const std::vector<StoredDocument> stored = store->documents({});
  ASSERT_EQ(stored.size(), 1u);
  EXPECT_EQ(stored[0].id, added.document_id);
  EXPECT_EQ(stored[0].branch, "main");
  EXPECT_EQ(stored[0].content_sha256.size(), 64u);
  EXPECT_EQ(stored[0].document.dump(1), to_json(document).dump(1));  // what export writes
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT document_json FROM documents"), to_json(document).dump());
  const std::vector<HistoryRow> rows = store->measurements({});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(*rows[0].ratio, 0.1 + 0.2);  // exactly, not to 15 digits
  EXPECT_EQ(rows[0].subject, spec.subject);
}

TEST_F(StorePostgres, TheSameDocumentTwiceIsStoredOnce) {
  const auto store = open_store(url);
  const ResultsDocument document = make_document(two_scenes(1));
  const AddOutcome first = store->add(document, "main");
  const AddOutcome again = store->add(document, "other-branch");
  EXPECT_TRUE(again.duplicate);
  EXPECT_EQ(again.document_id, first.document_id);
  const AddOutcome second = open_store(url)->add(make_document(two_scenes(2)), "main");
  EXPECT_FALSE(second.duplicate);
  EXPECT_EQ(second.document_id, first.document_id + 1);  // a duplicate used up no id
  EXPECT_EQ(store->documents({}).size(), 2u);
  EXPECT_EQ(store->documents({})[1].branch, "main");  // the branch first recorded
}

TEST_F(StorePostgres, SchemaIsVersionedAndMigratedOnce) {
  open_store(url);
  open_store(url);  // reopening applies nothing again
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT count(*) FROM schema_migrations"), "3");
  EXPECT_EQ(raw.text("SELECT description FROM schema_migrations WHERE version = 1"),
            "documents, revisions, scene_results");
  EXPECT_EQ(raw.text("SELECT description FROM schema_migrations WHERE version = 2"),
            "series columns: documents.timing, baseline_accel; revisions.repository_key; "
            "scene_results.scene_settings, series_id");
  EXPECT_EQ(raw.text("SELECT description FROM schema_migrations WHERE version = 3"),
            "peak memory: scene_results.peak_memory_kib, memory_change, memory_verdict");
  EXPECT_EQ(raw.text("SELECT data_type FROM information_schema.columns WHERE table_name = "
                     "'scene_results' AND column_name = 'normalized_ratio'"),
            "double precision");
  EXPECT_EQ(raw.text("SELECT count(*) FROM pg_indexes WHERE indexname IN ('documents_branch', "
                     "'documents_machine', 'revisions_sha', 'revisions_commit', "
                     "'scene_results_scene', 'revisions_repository', 'scene_results_series')"),
            "7");
}

TEST_F(StorePostgres, ASecondMigrationAppliesOnceOnTopOfTheFirst) {
  open_store(url);
  std::vector<Migration> migrations(store_migrations().begin(), store_migrations().end());
  migrations.push_back({4, "documents.note", "ALTER TABLE documents ADD COLUMN note TEXT"});
  PgConnection db = PgConnection::connect(url);
  EXPECT_EQ(migrate(db, migrations), 4);
  EXPECT_EQ(migrate(db, migrations), 4);
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT count(*) FROM schema_migrations"), "4");
  EXPECT_TRUE(raw.exec("SELECT note FROM documents"));
}

TEST_F(StorePostgres, AFailingMigrationLeavesTheVersionBefore) {
  open_store(url);
  std::vector<Migration> migrations(store_migrations().begin(), store_migrations().end());
  migrations.push_back(
      {4, "broken", "CREATE TABLE extra (x INTEGER); INSERT INTO nope VALUES (1)"});
  PgConnection db = PgConnection::connect(url);
  EXPECT_THROW(migrate(db, migrations), InfraError);
  EXPECT_EQ(schema_version(db), 3);
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT to_regclass('extra') IS NULL"), "t");
}

TEST_F(StorePostgres, AStoreFromANewerRaygateIsRefused) {
  open_store(url);
  RawConnection(url).text(
      "INSERT INTO schema_migrations VALUES (99, 'from the future', '2030-01-01T00:00:00Z')");
  try {
    open_store(url);
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("schema version 99 is newer"));
  }
}

TEST_F(StorePostgres, AConstraintFailureHalfwayStoresNothingOfTheDocument) {
  const auto store = open_store(url);
  DocumentSpec spec = two_scenes(1);
  spec.scenes.push_back({"balls", 0.9});  // the same scene twice: its second row cannot go in
  try {
    store->add(make_document(spec), "main");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(), HasSubstr("23505"));  // unique_violation
    EXPECT_THAT(e.what(), HasSubstr("scene_results_pkey"));
    EXPECT_THAT(e.what(), HasSubstr("INSERT INTO scene_results"));
    EXPECT_THAT(e.what(), HasSubstr(redact_postgresql_url(url)));
    EXPECT_THAT(e.what(), Not(HasSubstr(PostgresServer::kPassword)));
  }
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT count(*) FROM documents"), "0");
  EXPECT_EQ(raw.text("SELECT count(*) FROM revisions"), "0");
  EXPECT_EQ(raw.text("SELECT count(*) FROM scene_results"), "0");
  EXPECT_FALSE(store->add(make_document(two_scenes(1)), "main").duplicate);  // still usable
}

// The server process serving the store is killed while it writes the document's scene rows.
TEST_F(StorePostgres, AConnectionKilledHalfwayStoresNothingOfTheDocument) {
  const auto store = open_store(url);
  store->add(make_document(two_scenes(1)), "main");
  RawConnection raw(url);
  ASSERT_TRUE(raw.exec(R"sql(
    CREATE FUNCTION die() RETURNS trigger LANGUAGE plpgsql AS $$
    BEGIN
      IF NEW.scene_id = 'gears' AND NEW.document_id > 1 THEN
        PERFORM pg_terminate_backend(pg_backend_pid());
        PERFORM pg_sleep(10);
      END IF;
      RETURN NEW;
    END $$;
    CREATE TRIGGER die BEFORE INSERT ON scene_results FOR EACH ROW EXECUTE FUNCTION die())sql"));
  try {
    store->add(make_document(two_scenes(2)), "main");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(), HasSubstr("lost the connection"));
    EXPECT_THAT(e.what(), HasSubstr("retry"));
    EXPECT_THAT(e.what(), HasSubstr("127.0.0.1:" + std::to_string(postgres_server().port())));
    EXPECT_THAT(e.what(), Not(HasSubstr(PostgresServer::kPassword)));
  }
  EXPECT_THROW(store->add(make_document(two_scenes(3)), "main"), InfraError);  // still dead
  EXPECT_EQ(raw.text("SELECT count(*) FROM documents"), "1");
  EXPECT_EQ(raw.text("SELECT count(*) FROM revisions"), "1");
  EXPECT_EQ(raw.text("SELECT count(*) FROM scene_results"), "2");
  ASSERT_TRUE(raw.exec("DROP TRIGGER die ON scene_results"));
  EXPECT_FALSE(open_store(url)->add(make_document(two_scenes(2)), "main").duplicate);
}

TEST_F(StorePostgres, DocumentsFilterByShaBranchAndCount) {
  const auto store = open_store(url);
  for (int seed = 1; seed <= 3; ++seed) store->add(make_document(two_scenes(seed)), "main");
  const auto by_sha =
      store->documents(query([](DocumentQuery& q) { q.sha_prefix = fake_sha(2).substr(0, 8); }));
  ASSERT_EQ(by_sha.size(), 1u);
  EXPECT_EQ(by_sha[0].document["revisions"][0]["worktree"]["sha"], fake_sha(2));
  const auto last_two = store->documents(query([](DocumentQuery& q) { q.last = 2; }));
  ASSERT_EQ(last_two.size(), 2u);
  EXPECT_GT(last_two[0].id, last_two[1].id);  // newest stored first
  EXPECT_TRUE(store->documents(query([](DocumentQuery& q) { q.branch = "nope"; })).empty());
  // A prefix with LIKE's wildcards matches literally, as in SQLite.
  EXPECT_TRUE(store->documents(query([](DocumentQuery& q) { q.sha_prefix = "%"; })).empty());
}

TEST_F(StorePostgres, AnEmptyDatabaseIsAUsageErrorWhenTheStoreMustExist) {
  try {
    open_store(url, StoreOpen::must_exist);
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no raygate tables yet"));
    EXPECT_THAT(e.what(), HasSubstr("raygate import"));
    EXPECT_THAT(e.what(), Not(HasSubstr(PostgresServer::kPassword)));
  }
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT to_regclass('documents') IS NULL"), "t");  // nothing created
}

// A sweep: a database holding another program's tables of raygate's names gave SQL's words
// ("COALESCE types text and integer cannot be matched", "relation documents already exists"),
// exit 3. It is the user's to fix: a UsageError, and nothing is written.
TEST_F(StorePostgres, ADatabaseWithAnotherProgramsTablesIsNotAStore) {
  RawConnection(url).text("CREATE TABLE documents (x int)");
  for (StoreOpen mode : {StoreOpen::create_if_missing, StoreOpen::must_exist}) {
    try {
      open_store(url, mode);
      ADD_FAILURE() << "another program's database was taken for a store";
    } catch (const UsageError& e) {
      EXPECT_THAT(e.what(), HasSubstr("not a raygate store"));
      EXPECT_THAT(e.what(), Not(HasSubstr(PostgresServer::kPassword)));
    }
  }
  RawConnection(url).text("CREATE TABLE schema_migrations (version text)");
  try {
    open_store(url);
    ADD_FAILURE() << "another program's schema_migrations was read as raygate's";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("its table schema_migrations is another program's"));
  }
  EXPECT_EQ(RawConnection(url).text("SELECT to_regclass('scene_results') IS NULL"), "t");
}

TEST(StorePostgresErrors, AMalformedUrlIsAUsageErrorWithoutThePassword) {
  for (const std::string bad :
       {"postgresql://ci:s3cret@[::1/raygate", "postgresql://ci:s3cret@db/raygate?no_such_option=1",
        "postgres://ci:s3cret@db/ray%zzgate",
        "postgresql://ci:s3cret@127.0.0.1:notaport/raygate"}) {
    try {
      open_store(bad);
      ADD_FAILURE() << "expected UsageError for " << bad;
    } catch (const UsageError& e) {
      EXPECT_THAT(e.what(), HasSubstr("not a valid PostgreSQL URL")) << bad;
      EXPECT_THAT(e.what(), HasSubstr("postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE"));
      EXPECT_THAT(e.what(), Not(HasSubstr("s3cret"))) << e.what();
    }
  }
}

TEST(StorePostgresErrors, APasswordWithSlashOrAtIsNotPrinted) {
  // Generated passwords often hold '/' (base64); written unencoded they break the URL, and the
  // error that says so must not print them. Nor may an unencoded '@' leave part of one behind.
  const std::vector<std::pair<std::string, std::string>> cases{
      {"postgresql://ci:ab/cd9q@127.0.0.1:1/raygate", "ab/cd9q"},
      {"postgresql://ci:1234/x9q@127.0.0.1:1/raygate", "1234/x9q"},
      {"postgresql://ci:p@ss9q@127.0.0.1:1/raygate", "ss9q"}};
  for (const auto& [url, secret] : cases) {
    try {
      open_store(url);
      ADD_FAILURE() << "expected an error for " << url;
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), Not(HasSubstr(secret))) << e.what();
      EXPECT_THAT(e.what(), HasSubstr("127.0.0.1")) << e.what();  // still says where
    }
  }
}

TEST(StorePostgresErrors, AServerThatIsNotThereIsAnInfrastructureErrorNamingHostAndPort) {
  try {
    open_store("postgresql://ci:s3cret@127.0.0.1:1/raygate?password=other-secret");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_EQ(e.code(), ExitCode::infrastructure);
    EXPECT_THAT(e.what(), HasSubstr("results store postgresql://ci@127.0.0.1:1/raygate:"));
    EXPECT_THAT(e.what(), HasSubstr("cannot connect"));
    EXPECT_THAT(e.what(), HasSubstr("Connection refused"));  // libpq's own words
    EXPECT_THAT(e.what(), HasSubstr("check that the PostgreSQL server is running"));
    EXPECT_THAT(e.what(), Not(HasSubstr("s3cret")));
    EXPECT_THAT(e.what(), Not(HasSubstr("other-secret")));
  }
}

TEST(StorePostgresErrors, LocationsArePrintedWithoutPasswords) {
  EXPECT_EQ(redact_postgresql_url("postgresql://ci:s3cret@db:5432/raygate"),
            "postgresql://ci@db:5432/raygate");
  EXPECT_EQ(redact_postgresql_url("postgres://ci@db/raygate?password=x&sslmode=require"),
            "postgres://ci@db/raygate?sslmode=require");
  EXPECT_EQ(redact_postgresql_url("postgresql://db/raygate?passwor%64=x"),
            "postgresql://db/raygate");
  EXPECT_EQ(redact_postgresql_url("postgresql:///raygate"), "postgresql:///raygate");
  EXPECT_EQ(redact_postgresql_url(".raygate/results.db"), ".raygate/results.db");
  const auto store = open_store(postgres_server().create_database());
  EXPECT_THAT(store->location(),
              StartsWith("postgresql://raygate@127.0.0.1:" +
                         std::to_string(postgres_server().port()) + "/raygate_test_"));
  EXPECT_THAT(store->location(), Not(HasSubstr(PostgresServer::kPassword)));
}

}  // namespace
}  // namespace raygate::test
