// Several processes writing one PostgreSQL store at once, from a database with no tables yet
// (so they also race to create the schema), some adding the same documents at the same moment:
// every distinct document lands exactly once, exactly one writer is told it stored it, and the
// schema is migrated once.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <set>

#include "postgres_server.h"
#include "results_fixture.h"
#include "store/store.h"

namespace raygate::test {
namespace {

constexpr int kWriters = 6;
constexpr int kOwnDocuments = 8;
constexpr int kSharedDocuments = 4;  // every writer adds these too, first, all at once
constexpr int kFailed = 100;

ResultsDocument document(int seed) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.scenes = {{"balls", 0.5 + seed * 0.01}, {"gears", 1.0}, {"tetra", 2.0}};
  return make_document(spec);
}

// The child's whole life: wait for the start signal (the pipe closing), open, add, exit with
// the number of documents it stored itself. Never returns into the test framework.
[[noreturn]] void writer(const std::string& url, int index, int start_signal) {
  char byte = 0;
  while (::read(start_signal, &byte, 1) > 0) {
  }
  int stored = 0;
  try {
    const auto store = open_store(url);
    std::vector<int> seeds;
    for (int i = 0; i < kSharedDocuments; ++i) seeds.push_back(i);
    for (int i = 0; i < kOwnDocuments; ++i) seeds.push_back(100 * (index + 1) + i);
    for (int i = 0; i < kSharedDocuments; ++i) seeds.push_back(i);  // again: duplicates now
    for (const int seed : seeds) stored += store->add(document(seed), "main").duplicate ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "writer %d: %s\n", index, e.what());
    _exit(kFailed);
  }
  _exit(stored);
}

TEST(StorePostgresConcurrency, ParallelProcessesLoseAndDuplicateNothing) {
  const std::string url = postgres_server().create_database();
  int pipe_fds[2];
  ASSERT_EQ(::pipe(pipe_fds), 0);
  std::vector<pid_t> children;
  for (int i = 0; i < kWriters; ++i) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::close(pipe_fds[1]);
      writer(url, i, pipe_fds[0]);
    }
    children.push_back(pid);
  }
  ::close(pipe_fds[0]);
  ::close(pipe_fds[1]);  // go
  int stored_by_writers = 0;
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status)) << "writer " << pid << " crashed";
    ASSERT_NE(WEXITSTATUS(status), kFailed) << "writer " << pid << " failed (see stderr)";
    stored_by_writers += WEXITSTATUS(status);
  }
  const std::size_t distinct = kWriters * kOwnDocuments + kSharedDocuments;
  EXPECT_EQ(static_cast<std::size_t>(stored_by_writers), distinct);  // each told to one writer

  const auto store = open_store(url, StoreOpen::must_exist);
  const std::vector<StoredDocument> stored = store->documents({});
  EXPECT_EQ(stored.size(), distinct);
  std::set<std::string> hashes;
  std::set<std::string> shas;
  for (const StoredDocument& d : stored) {
    hashes.insert(d.content_sha256);
    shas.insert(d.document["revisions"][0]["worktree"]["sha"].get<std::string>());
  }
  EXPECT_EQ(hashes.size(), stored.size());
  for (int i = 0; i < kSharedDocuments; ++i) EXPECT_TRUE(shas.contains(fake_sha(i))) << i;
  for (int w = 0; w < kWriters; ++w) {
    for (int i = 0; i < kOwnDocuments; ++i) {
      EXPECT_TRUE(shas.contains(fake_sha(100 * (w + 1) + i))) << w << " " << i;
    }
  }
  EXPECT_EQ(store->measurements({}).size(), stored.size() * 3);
  RawConnection raw(url);
  EXPECT_EQ(raw.text("SELECT count(*) FROM schema_migrations"), "3");  // each migration once
  EXPECT_EQ(raw.text("SELECT count(*) FROM revisions"), std::to_string(distinct));
}

}  // namespace
}  // namespace raygate::test
