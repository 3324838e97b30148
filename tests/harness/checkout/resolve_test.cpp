// Revision resolution in a local repository: every revspec form, the recorded fields, and the
// errors a user sees for unknown or unsuitable revisions.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "checkout/git_fixture.h"
#include "checkout/git_handle.h"
#include "checkout/repository.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

class CheckoutResolve : public ::testing::Test {
 protected:
  CheckoutResolve() : repo_(dir_.path() / "tracer") {
    repo_.write("README", "one\n");
    c1_ = repo_.commit("first commit\n\nwith a body", {.time = 1700000000, .offset_minutes = 60});
    repo_.write("README", "two\n");
    c2_ = repo_.commit("second", {.author = "Grace Hopper"});
    repo_.tag("v1");
    repo_.write("README", "three\n");
    c3_ = repo_.commit("third");
    repo_.annotated_tag("v2", "release two");
    repo_.write("README", "four\n");
    c4_ = repo_.commit("fourth");
    repo_.branch("dev", c2_);
    repo_.branch("feature/x", c3_);
  }

  Repository open() const { return Repository::open(repo_.path().string(), dir_.path() / "cache"); }

  TempDir dir_{"raygate-resolve"};
  testing::GitFixture repo_;
  std::string c1_, c2_, c3_, c4_;
};

TEST_F(CheckoutResolve, BranchRecordsEveryField) {
  const Revision main = open().resolve("main");
  EXPECT_EQ(main.sha, c4_);
  EXPECT_EQ(main.revision, "main");
  EXPECT_EQ(main.ref_name, "refs/heads/main");
  EXPECT_EQ(main.subject, "fourth");
  EXPECT_EQ(main.author, "Ada Tester");
  EXPECT_GE(main.short_sha.size(), 7u);
  EXPECT_THAT(c4_, StartsWith(main.short_sha));
}

TEST_F(CheckoutResolve, SubjectAndIsoTimeWithOffset) {
  const Revision first = open().resolve(c1_);
  EXPECT_EQ(first.subject, "first commit");
  // 1700000000 is 2023-11-14T22:13:20Z; shown at the committer's +01:00.
  EXPECT_EQ(first.commit_time, "2023-11-14T23:13:20+01:00");
  EXPECT_EQ(first.ref_name, "");
}

TEST_F(CheckoutResolve, BranchWithSlashAndOtherBranch) {
  const Repository repo = open();
  EXPECT_EQ(repo.resolve("feature/x").sha, c3_);
  EXPECT_EQ(repo.resolve("dev").sha, c2_);
  EXPECT_EQ(repo.resolve("dev").author, "Grace Hopper");
}

TEST_F(CheckoutResolve, LightweightAndAnnotatedTagsPeelToCommits) {
  const Repository repo = open();
  const Revision v1 = repo.resolve("v1");
  EXPECT_EQ(v1.sha, c2_);
  EXPECT_EQ(v1.ref_name, "refs/tags/v1");
  const Revision v2 = repo.resolve("v2");
  EXPECT_EQ(v2.sha, c3_);
  EXPECT_EQ(v2.subject, "third");
}

TEST_F(CheckoutResolve, FullAndShortShas) {
  const Repository repo = open();
  EXPECT_EQ(repo.resolve(c2_).sha, c2_);
  EXPECT_EQ(repo.resolve(c2_.substr(0, 8)).sha, c2_);
}

TEST_F(CheckoutResolve, AncestryExpressions) {
  const Repository repo = open();
  EXPECT_EQ(repo.resolve("HEAD~3").sha, c1_);
  EXPECT_EQ(repo.resolve("main^").sha, c3_);
  EXPECT_EQ(repo.resolve("HEAD").sha, c4_);
}

TEST_F(CheckoutResolve, UnknownRevisionListsBranchesAndTags) {
  try {
    open().resolve("nope");
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_THAT(message, HasSubstr("unknown revision 'nope' in " + repo_.path().string()));
    EXPECT_THAT(message, HasSubstr("branches: dev, feature/x, main"));
    EXPECT_THAT(message, HasSubstr("tags: v1, v2"));
    EXPECT_EQ(e.code(), ExitCode::usage);
  }
}

TEST_F(CheckoutResolve, HistoryTooShortAndEmptyAreUnknown) {
  const Repository repo = open();
  EXPECT_THROW(repo.resolve("HEAD~10"), UsageError);
  EXPECT_THROW(repo.resolve(""), UsageError);
  EXPECT_THROW(repo.resolve("main..dev"), UsageError);
}

TEST_F(CheckoutResolve, ATreeIsNotACommit) {
  try {
    open().resolve("main^{tree}");
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("names a tree, not a commit"));
  }
}

TEST_F(CheckoutResolve, OpensFromASubdirectory) {
  repo_.write("src/a.cpp", "int a;\n");
  repo_.commit("src");
  const Repository repo = Repository::open((repo_.path() / "src").string(), dir_.path() / "cache");
  EXPECT_EQ(repo.location(), repo_.path().string());
}

TEST(CheckoutOpen, MissingPathAndNonRepositoryAreUsageErrors) {
  TempDir dir("raygate-open");
  EXPECT_THROW(Repository::open((dir.path() / "absent").string(), dir.path() / "cache"),
               UsageError);
  try {
    Repository::open(dir.path().string(), dir.path() / "cache");
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("is not in a git repository"));
  }
}

TEST(CheckoutGitCheck, FailureCarriesContextAndLibgit2Message) {
  git::Library library;
  git::RepositoryPtr repo;
  try {
    git::check(git_repository_open(repo.out(), "/nonexistent/raygate/repo"),
               "opening /nonexistent/raygate/repo");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    const std::string message = e.what();
    EXPECT_THAT(message, StartsWith("opening /nonexistent/raygate/repo: "));
    EXPECT_GT(message.size(), std::string("opening /nonexistent/raygate/repo: ").size());
  }
  git_error_clear();  // git_error_last() is NULL now: the message must still be sensible
  try {
    git::check(-1, "doing nothing");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_STREQ(e.what(), "doing nothing: unknown libgit2 error");
  }
  EXPECT_EQ(git::check(0, "fine"), 0);
}

TEST(CheckoutGitHandle, MovesAndReleasesOwnership) {
  git::Library library;
  TempDir dir("raygate-handle");
  testing::GitFixture fixture(dir.path() / "r");
  fixture.write("f", "x");
  const std::string sha = fixture.commit("c");
  git::ObjectPtr object;
  ASSERT_EQ(git_revparse_single(object.out(), fixture.raw(), sha.c_str()), 0);
  git::ObjectPtr moved = std::move(object);
  EXPECT_FALSE(object);  // NOLINT(bugprone-use-after-move): checking the moved-from state
  ASSERT_TRUE(moved);
  git::CommitPtr commit(reinterpret_cast<git_commit*>(moved.release()));
  EXPECT_FALSE(moved);
  EXPECT_EQ(git::to_hex(*git_commit_id(commit.get())), sha);
}

}  // namespace
}  // namespace raygate
