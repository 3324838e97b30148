// merge_base and first_parent_history on a small branchy history:
//
//   A - B - C ----- M - E    main
//        \         /
//         D1 - D2            dev
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

std::vector<std::string> shas(const std::vector<Revision>& revisions) {
  std::vector<std::string> out;
  for (const Revision& r : revisions) out.push_back(r.sha);
  return out;
}

class CheckoutHistory : public ::testing::Test {
 protected:
  CheckoutHistory() : repo_(dir_.path() / "tracer") {
    a_ = step("A");
    b_ = step("B");
    repo_.branch("dev");
    c_ = step("C");
    repo_.switch_to("dev");
    d1_ = step("D1");
    d2_ = step("D2");
    repo_.switch_to("main");
    repo_.write("merged", "dev");
    m_ = repo_.commit("M", {.merge_parents = {d2_}});
    e_ = step("E");
  }

  std::string step(const std::string& name) {
    repo_.write("history", name);
    return repo_.commit(name);
  }
  Repository open() const { return Repository::open(repo_.path().string(), dir_.path() / "cache"); }

  TempDir dir_{"raygate-history"};
  testing::GitFixture repo_;
  std::string a_, b_, c_, d1_, d2_, m_, e_;
};

TEST_F(CheckoutHistory, MergeBaseBeforeAndAfterTheMerge) {
  const Repository repo = open();
  const auto before = repo.merge_base(c_, d2_);
  ASSERT_TRUE(before.has_value());
  EXPECT_EQ(before->sha, b_);
  EXPECT_EQ(before->subject, "B");
  const auto after = repo.merge_base("main", "dev");
  ASSERT_TRUE(after.has_value());
  EXPECT_EQ(after->sha, d2_);
}

TEST_F(CheckoutHistory, UnrelatedHistoriesHaveNoMergeBase) {
  repo_.branch("orphan");
  repo_.switch_to("orphan");
  const std::string root = repo_.commit("unrelated", {.root = true});
  EXPECT_FALSE(open().merge_base(root, "main").has_value());
}

TEST_F(CheckoutHistory, FirstParentHistoryIsOldestFirstAndSkipsMergedBranches) {
  const auto history = open().first_parent_history(a_, "main");
  EXPECT_THAT(shas(history), ::testing::ElementsAre(b_, c_, m_, e_));
  EXPECT_EQ(history.back().subject, "E");
  EXPECT_EQ(history.front().revision, b_);
}

TEST_F(CheckoutHistory, GoodOnAMergedBranchExcludesEverythingItReaches) {
  EXPECT_THAT(shas(open().first_parent_history(d1_, e_)), ::testing::ElementsAre(c_, m_, e_));
}

TEST_F(CheckoutHistory, SameRevisionGivesAnEmptyRange) {
  EXPECT_TRUE(open().first_parent_history("main", e_).empty());
}

TEST_F(CheckoutHistory, GoodMustBeAnAncestorOfBad) {
  try {
    open().first_parent_history("main", a_);
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("is not an ancestor of"));
  }
  EXPECT_THROW(open().first_parent_history(c_, "dev"), UsageError);
}

// Sweep 17: a bisect in a shallow clone ended in libgit2's "object not found", exit 3. The clone
// is said to be shallow, with what to do: the user's checkout depth to change.
TEST_F(CheckoutHistory, AShallowCloneIsSaidToBeShallow) {
  const std::string origin = repo_.path().string();
  const std::string shallow = (dir_.path() / "shallow").string();
  ASSERT_EQ(std::system(("git -C '" + origin + "' tag old " + a_ + " && git clone -q --depth 2 " +
                         "--no-single-branch 'file://" + origin + "' '" + shallow + "'")
                            .c_str()),
            0);
  try {
    Repository::open(shallow, dir_.path() / "cache2").first_parent_history("old", "origin/main");
    FAIL() << "walked a shallow history";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(),
                ::testing::HasSubstr("is a shallow clone: bisect needs the whole history"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("git fetch --unshallow"));
  }
}

}  // namespace
}  // namespace raygate
