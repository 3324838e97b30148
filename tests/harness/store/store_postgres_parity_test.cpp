// The two backends answer alike: the same documents added to an SQLite file and to a
// PostgreSQL database give the same ids and duplicates, the same documents for every filter,
// the same measurement rows in the same order, and the same history.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "core/fs.h"
#include "postgres_server.h"
#include "results_fixture.h"
#include "store/store.h"

namespace raygate::test {
namespace {

DocumentSpec commit(int seed, int day, double ratio, const std::string& branch = "main") {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed) + " — naïve";
  spec.commit_time = fmt::format("2026-03-{:02}T10:00:00+02:00", day);
  spec.started_at = fmt::format("2026-03-{:02}T12:00:00Z", day);
  spec.ref_name = "refs/heads/" + branch;
  // Upper and lower case, so a locale's collation would order them differently than bytes.
  spec.scenes = {{"balls", ratio},
                 {"Gears", ratio * 2, 0.02, 2.0, 0.004, ImageVerdict::warn},
                 {"gears", ratio * 3},
                 {"tetra", ratio / 3, 0.01, 0.5, 0.0, ImageVerdict::pass, SceneStatus::failed}};
  return spec;
}

// Runs, re-runs, shards, a compare, a dirty tree, an uncommitted tree, another branch and
// machine, an incomplete document, and duplicates.
std::vector<DocumentSpec> documents() {
  std::vector<DocumentSpec> specs = {commit(1, 10, 1.0), commit(2, 12, 0.9), commit(3, 14, 0.8)};
  DocumentSpec rerun = commit(2, 12, 0.95);
  rerun.started_at = "2026-03-20T00:00:00Z";
  specs.push_back(rerun);
  specs.push_back(commit(4, 14, 0.7));  // ties commit 3 on commit and start time
  for (const char* shard : {"1/2", "2/2"}) {
    DocumentSpec part = commit(5, 16, 0.6);
    part.shard = shard;
    part.scenes = {part.scenes[std::string(shard) == "1/2" ? 0 : 1]};
    specs.push_back(part);
  }
  DocumentSpec compare = commit(6, 17, 1.1);
  compare.kind = DocumentKind::compare;
  compare.roles = {Role::base, Role::head};
  specs.push_back(compare);
  DocumentSpec dirty = commit(3, 14, 0.5);
  dirty.dirty = true;
  dirty.started_at = "2026-03-21T08:00:00Z";
  specs.push_back(dirty);
  DocumentSpec uncommitted = commit(7, 18, 0.4);
  uncommitted.commit_time.clear();
  specs.push_back(uncommitted);
  DocumentSpec feature = commit(8, 19, 1.3, "feature");
  feature.hostname = "laptop";
  feature.cpu_model = "Other CPU";
  feature.complete = false;
  specs.push_back(feature);
  specs.push_back(commit(1, 10, 1.0));  // a duplicate
  return specs;
}

std::string row_text(const HistoryRow& r) {  // every field but stored_at (the clock's)
  auto number = [](const std::optional<double>& v) { return v ? fmt::format("{}", *v) : "-"; };
  return fmt::format("{} {} {} {} {} {} {} [{}] {} {} {} {} {} {} {} {} {} {} {} {} {} {} {}",
                     r.document_id, r.measured_at, r.complete, r.branch, r.role, r.sha, r.short_sha,
                     r.subject, r.commit_time, r.commit_unix ? std::to_string(*r.commit_unix) : "-",
                     r.dirty, r.scene_id, r.status, number(r.ratio), number(r.ratio_lower),
                     number(r.ratio_upper), number(r.baseline_median_seconds), r.image_verdict,
                     number(r.image_max_error), number(r.image_rms_error), r.machine_hostname,
                     r.machine_cpu_model, r.baseline_sha256);
}

std::vector<std::string> texts(const std::vector<HistoryRow>& rows) {
  std::vector<std::string> out;
  for (const HistoryRow& row : rows) out.push_back(row_text(row));
  return out;
}

std::vector<std::string> texts(const std::vector<StoredDocument>& documents) {
  std::vector<std::string> out;
  for (const StoredDocument& d : documents) {
    out.push_back(fmt::format("{} {} {} {}", d.id, d.branch, d.content_sha256, d.document.dump()));
  }
  return out;
}

template <typename Set>
HistoryQuery history_query(Set set) {
  HistoryQuery q;
  set(q);
  return q;
}

template <typename Set>
DocumentQuery document_query(Set set) {
  DocumentQuery q;
  set(q);
  return q;
}

class StoreParity : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const DocumentSpec& spec : documents()) {
      const ResultsDocument document = make_document(spec);
      const std::string branch = branch_of(document, "");
      const AddOutcome in_sqlite = sqlite->add(document, branch);
      const AddOutcome in_postgres = postgres->add(document, branch);
      EXPECT_EQ(in_sqlite.document_id, in_postgres.document_id) << spec.sha;
      EXPECT_EQ(in_sqlite.duplicate, in_postgres.duplicate) << spec.sha;
    }
  }
  TempDir dir;
  std::unique_ptr<ResultsStore> sqlite = open_store((dir.path() / "results.db").string());
  std::unique_ptr<ResultsStore> postgres = open_store(postgres_server().create_database());
};

TEST_F(StoreParity, DocumentsMatchForEveryFilter) {
  const std::vector<DocumentQuery> queries = {
      {},
      document_query([](DocumentQuery& q) { q.branch = "main"; }),
      document_query([](DocumentQuery& q) { q.branch = "feature"; }),
      document_query([](DocumentQuery& q) { q.sha_prefix = fake_sha(2).substr(0, 6); }),
      document_query([](DocumentQuery& q) { q.sha_prefix = fake_sha(3); }),
      document_query([](DocumentQuery& q) { q.sha_prefix = "0000000"; }),
      document_query([](DocumentQuery& q) { q.last = 3; }),
      document_query([](DocumentQuery& q) {
        q.last = 1;
        q.branch = "main";
      }),
  };
  ASSERT_EQ(sqlite->documents({}).size(), 11u);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(texts(sqlite->documents(queries[i])), texts(postgres->documents(queries[i])))
        << "query " << i;
  }
}

TEST_F(StoreParity, MeasurementsAndHistoryMatchRowForRow) {
  const std::vector<HistoryQuery> queries = {
      {},
      history_query([](HistoryQuery& q) { q.include_dirty = true; }),
      history_query([](HistoryQuery& q) { q.branch = "feature"; }),
      history_query([](HistoryQuery& q) { q.role = "head"; }),
      history_query([](HistoryQuery& q) { q.role = "base"; }),
      history_query([](HistoryQuery& q) {
        q.scenes = {"gears", "Gears"};
      }),
      history_query([](HistoryQuery& q) {
        q.scenes = {"balls"};
        q.last_commits = 2;
        q.include_dirty = true;
      }),
  };
  ASSERT_GT(sqlite->measurements({}).size(), 20u);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    EXPECT_EQ(texts(sqlite->measurements(queries[i])), texts(postgres->measurements(queries[i])))
        << "query " << i;
    EXPECT_EQ(texts(sqlite->history(queries[i])), texts(postgres->history(queries[i])))
        << "query " << i;
  }
}

// With role "any" a compare's base and head rows tie on every ordering key, so neither backend
// promises their order: the same rows, in any order.
TEST_F(StoreParity, EveryRoleGivesTheSameRows) {
  const HistoryQuery any = history_query([](HistoryQuery& q) {
    q.role = "any";
    q.include_dirty = true;
  });
  std::vector<std::string> in_sqlite = texts(sqlite->measurements(any));
  std::vector<std::string> in_postgres = texts(postgres->measurements(any));
  std::sort(in_sqlite.begin(), in_sqlite.end());
  std::sort(in_postgres.begin(), in_postgres.end());
  EXPECT_EQ(in_sqlite, in_postgres);
  const HistoryQuery tracer = history_query([](HistoryQuery& q) { q.include_dirty = true; });
  // Beyond the tracer rows: the compare's base and head rows, four scenes each.
  EXPECT_EQ(in_sqlite.size(), sqlite->measurements(tracer).size() + 8u);
}

}  // namespace
}  // namespace raygate::test
