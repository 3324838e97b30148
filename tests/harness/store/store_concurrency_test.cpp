// Several processes writing one SQLite store at once, from a file that does not exist yet (so
// they also race to create and migrate it): every document lands exactly once.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <set>

#include "core/fs.h"
#include "results_fixture.h"
#include "store/store.h"

namespace raygate::test {
namespace {

constexpr int kWriters = 6;
constexpr int kOwnDocuments = 8;
constexpr int kSharedDocuments = 3;  // every writer adds these too

ResultsDocument document(int seed) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.scenes = {{"balls", 0.5 + seed * 0.01}, {"gears", 1.0}, {"tetra", 2.0}};
  return make_document(spec);
}

// The child's whole life: open, add, exit. Never returns into the test framework.
[[noreturn]] void writer(const std::filesystem::path& path, int index) {
  int status = 0;
  try {
    const auto store = open_store(path.string());
    for (int i = 0; i < kOwnDocuments; ++i) store->add(document(100 * (index + 1) + i), "main");
    for (int i = 0; i < kSharedDocuments; ++i) store->add(document(i), "main");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "writer %d: %s\n", index, e.what());
    status = 1;
  }
  _exit(status);
}

TEST(StoreConcurrency, ParallelWritersLoseAndDuplicateNothing) {
  TempDir dir;
  const std::filesystem::path path = dir.path() / "results.db";
  std::vector<pid_t> children;
  for (int i = 0; i < kWriters; ++i) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) writer(path, i);
    children.push_back(pid);
  }
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer " << pid << " failed";
  }
  const auto store = open_store(path.string(), StoreOpen::must_exist);
  const std::vector<StoredDocument> stored = store->documents({});
  EXPECT_EQ(stored.size(), static_cast<std::size_t>(kWriters * kOwnDocuments + kSharedDocuments));
  std::set<std::string> hashes;
  for (const StoredDocument& d : stored) hashes.insert(d.content_sha256);
  EXPECT_EQ(hashes.size(), stored.size());
  EXPECT_EQ(store->measurements({}).size(), stored.size() * 3);
  sqlite3* raw = nullptr;
  sqlite3_open(path.c_str(), &raw);
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(raw, "SELECT count(*) FROM schema_migrations", -1, &s, nullptr);
  ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(s, 0), 3);  // each migration once, whoever won
  sqlite3_finalize(s);
  sqlite3_close(raw);
}

}  // namespace
}  // namespace raygate::test
