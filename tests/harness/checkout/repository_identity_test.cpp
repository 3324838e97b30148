// A repository's identity for history series: the first-parent root commit, the same for a
// local path and a clone by URL and different for another tracer's history; the origin URL when
// the history is shallow; nothing when there is no repository; URLs in one spelling.
#include <gtest/gtest.h>

#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "checkout/repository_identity.h"
#include "core/fs.h"

namespace raygate {
namespace {

using testing::GitFixture;

TEST(RepositoryIdentity, TheFirstParentRootCommitForEveryCloneOfAHistory) {
  TempDir dir;
  GitFixture repo(dir.path() / "tracer");
  repo.write("a.txt", "a");
  const std::string root = repo.commit("first");
  repo.write("b.txt", "b");
  repo.commit("second");
  // An unrelated history merged in as a second parent does not change the mainline's root.
  repo.branch("other");
  repo.switch_to("other");
  repo.write("c.txt", "c");
  testing::CommitOptions unrelated;
  unrelated.root = true;
  const std::string other_root = repo.commit("other root", unrelated);
  repo.switch_to("main");
  testing::CommitOptions merge;
  merge.merge_parents = {other_root};
  const std::string head = repo.commit("merge", merge);

  const auto cache = dir.path() / "cache";
  EXPECT_EQ(repository_identity(repo.path().string(), head, cache), "root:" + root);
  const Repository clone = Repository::open(repo.url(), cache);  // a bare clone in the cache
  EXPECT_EQ(repository_identity(repo.url(), head, cache), "root:" + root);
  EXPECT_EQ(repository_identity(repo.path().string(), other_root, cache), "root:" + other_root);

  // Another tracer's history (the fixture's clock is fixed: the same first file, message and
  // time would be the same commit, as in a fork, which is the same history).
  GitFixture another(dir.path() / "another-tracer");
  another.write("main.c", "int main(void) { return 0; }\n");
  const std::string another_root = another.commit("first");
  EXPECT_NE(repository_identity(another.path().string(), another_root, cache), "root:" + root);
}

TEST(RepositoryIdentity, AShallowHistoryIsKnownByItsOriginUrl) {
  TempDir dir;
  GitFixture repo(dir.path() / "tracer");
  repo.write("a.txt", "a");
  const std::string sha = repo.commit("only");
  // What a depth-1 CI checkout leaves: the commit's parents are cut off.
  write_file_atomically(repo.path() / ".git" / "shallow", sha + "\n");
  EXPECT_EQ(repository_identity(repo.path().string(), sha, dir.path()), "");  // no origin
  git_remote* remote = nullptr;
  ASSERT_EQ(git_remote_create(&remote, repo.raw(), "origin", "git@GitHub.com:me/tracer.git"), 0);
  git_remote_free(remote);
  EXPECT_EQ(repository_identity(repo.path().string(), sha, dir.path()), "url:github.com/me/tracer");
}

TEST(RepositoryIdentity, NothingWhereThereIsNoRepositoryOrCommit) {
  TempDir dir;
  EXPECT_EQ(repository_identity(dir.path().string(), "uncommitted", dir.path()), "");
  GitFixture repo(dir.path() / "tracer");
  repo.write("a.txt", "a");
  repo.commit("first");
  EXPECT_EQ(repository_identity(repo.path().string(), "uncommitted", dir.path()), "");
  EXPECT_EQ(repository_identity(repo.path().string(), std::string(40, 'f'), dir.path()), "");
  EXPECT_EQ(
      repository_identity("https://example.invalid/none.git", std::string(40, 'f'), dir.path()),
      "");  // never fetched: no cached clone, no identity
}

TEST(RepositoryIdentity, RemoteUrlsInOneSpelling) {
  EXPECT_EQ(normalize_remote_url("https://GitHub.com/me/tracer.git"), "github.com/me/tracer");
  EXPECT_EQ(normalize_remote_url("git@github.com:me/tracer"), "github.com/me/tracer");
  EXPECT_EQ(normalize_remote_url("ssh://git@github.com/me/tracer.git/"), "github.com/me/tracer");
  EXPECT_EQ(normalize_remote_url("https://user:secret@host:8443/a/b"), "host:8443/a/b");
  EXPECT_EQ(normalize_remote_url("file:///srv/git/tracer.git"), "/srv/git/tracer");
  EXPECT_EQ(normalize_remote_url("/srv/git/tracer/"), "/srv/git/tracer");
}

}  // namespace
}  // namespace raygate
