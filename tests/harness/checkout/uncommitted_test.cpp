// describe_uncommitted_worktree: the record for a --worktree the user may have edited.
#include <gtest/gtest.h>

#include "checkout/git_fixture.h"
#include "checkout/worktree.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

class CheckoutUncommitted : public ::testing::Test {
 protected:
  CheckoutUncommitted() : repo_(dir_.path() / "tracer") {
    repo_.write("main.cpp", "int main() {}\n");
    head_ = repo_.commit("only commit");
  }
  TempDir dir_{"raygate-uncommitted"};
  testing::GitFixture repo_;
  std::string head_;
};

TEST_F(CheckoutUncommitted, CleanTreeIsHeadAndNotDirty) {
  const Worktree tree = describe_uncommitted_worktree(repo_.path());
  EXPECT_EQ(tree.sha, head_);
  EXPECT_EQ(tree.subject, "only commit");
  EXPECT_EQ(tree.path, repo_.path());
  EXPECT_FALSE(tree.dirty);
}

TEST_F(CheckoutUncommitted, ModifiedOrUntrackedFilesMakeItDirty) {
  repo_.write("main.cpp", "int main() { return 1; }\n");
  const std::string index_before = read_file(repo_.path() / ".git/index");
  EXPECT_TRUE(describe_uncommitted_worktree(repo_.path()).dirty);
  EXPECT_EQ(read_file(repo_.path() / ".git/index"), index_before);  // looking never writes

  repo_.write("main.cpp", "int main() {}\n");
  repo_.write("new.cpp", "\n");
  EXPECT_TRUE(describe_uncommitted_worktree(repo_.path()).dirty);
}

TEST_F(CheckoutUncommitted, ASubdirectoryReportsItsRepository) {
  repo_.write("src/a.cpp", "\n");
  repo_.commit("src");
  const Worktree tree = describe_uncommitted_worktree(repo_.path() / "src");
  EXPECT_EQ(tree.sha, repo_.sha("HEAD"));
  EXPECT_EQ(tree.path, repo_.path() / "src");
}

TEST(CheckoutUncommittedPlain, OutsideAnyRepositoryItIsUncommitted) {
  TempDir dir("raygate-plain");
  const Worktree tree = describe_uncommitted_worktree(dir.path());
  EXPECT_EQ(tree.sha, "uncommitted");
  EXPECT_TRUE(tree.dirty);
  EXPECT_THROW(describe_uncommitted_worktree(dir.path() / "absent"), UsageError);
}

TEST(CheckoutUncommittedPlain, AnUnbornHeadIsUncommitted) {
  TempDir dir("raygate-unborn");
  testing::GitFixture repo(dir.path() / "fresh");
  repo.write("a", "b");
  const Worktree tree = describe_uncommitted_worktree(repo.path());
  EXPECT_EQ(tree.sha, "uncommitted");
  EXPECT_TRUE(tree.dirty);
}

}  // namespace
}  // namespace raygate
