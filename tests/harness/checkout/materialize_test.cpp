// Worktrees in the cache: content and modes, the user's checkout left byte-for-byte alone,
// reuse without rewriting, and leftovers of a killed run never used.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <map>
#include <vector>

#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "checkout/tree_stamp.h"
#include "core/error.h"
#include "core/fs.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

// Every regular file and symlink under `root` (the .git directory included) with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string key = fs::relative(entry.path(), root).string();
    if (entry.is_symlink()) {
      files[key] = "-> " + fs::read_symlink(entry.path()).string();
    } else if (entry.is_regular_file()) {
      files[key] = read_file(entry.path());
    }
  }
  return files;
}

struct stat stat_of(const fs::path& path) {
  struct stat info {};
  EXPECT_EQ(::lstat(path.c_str(), &info), 0) << path;
  return info;
}

class CheckoutMaterialize : public ::testing::Test {
 protected:
  CheckoutMaterialize() : repo_(dir_.path() / "tracer") {
    repo_.write("CMakeLists.txt", "project(t)\n");
    repo_.write("src/render.cpp", "// v1\n");
    repo_.write("tools/run.sh", "#!/bin/sh\necho hi\n", true);
    first_ = repo_.commit("first");
    repo_.write("src/render.cpp", "// v2\n");
    repo_.remove("tools/run.sh");
    second_ = repo_.commit("second");
    repo_.branch("dev", first_);
  }

  Repository open() const { return Repository::open(repo_.path().string(), cache()); }
  fs::path cache() const { return dir_.path() / "cache"; }

  TempDir dir_{"raygate-materialize"};
  testing::GitFixture repo_;
  std::string first_, second_;
};

TEST_F(CheckoutMaterialize, WritesTheCommitsFilesWithExecutableBits) {
  const Worktree tree = open().checkout("dev");
  EXPECT_EQ(tree.path, cache() / "worktrees" / first_);
  EXPECT_EQ(tree.sha, first_);
  EXPECT_EQ(tree.subject, "first");
  EXPECT_EQ(tree.revision, "dev");
  EXPECT_EQ(tree.ref_name, "refs/heads/dev");
  EXPECT_FALSE(tree.dirty);
  EXPECT_EQ(read_file(tree.path / "src/render.cpp"), "// v1\n");
  EXPECT_EQ(read_file(tree.path / "tools/run.sh"), "#!/bin/sh\necho hi\n");
  EXPECT_NE(stat_of(tree.path / "tools/run.sh").st_mode & S_IXUSR, 0u);
  EXPECT_EQ(stat_of(tree.path / "CMakeLists.txt").st_mode & S_IXUSR, 0u);
  EXPECT_FALSE(fs::exists(tree.path / ".git"));
}

TEST_F(CheckoutMaterialize, EachCommitGetsItsOwnTree) {
  const Repository repo = open();
  const Worktree older = repo.checkout(first_);
  const Worktree newer = repo.checkout("main");
  EXPECT_NE(older.path, newer.path);
  EXPECT_EQ(read_file(newer.path / "src/render.cpp"), "// v2\n");
  EXPECT_FALSE(fs::exists(newer.path / "tools/run.sh"));
  EXPECT_EQ(read_file(older.path / "src/render.cpp"), "// v1\n");
}

TEST_F(CheckoutMaterialize, SymlinksStaySymlinks) {
  repo_.write("data/scene.nff", "v 0 0 0\n");
  fs::create_symlink("data/scene.nff", repo_.path() / "scene.nff");
  repo_.commit("link");
  const Worktree tree = open().checkout("main");
  ASSERT_TRUE(fs::is_symlink(tree.path / "scene.nff"));
  EXPECT_EQ(fs::read_symlink(tree.path / "scene.nff"), "data/scene.nff");
}

TEST_F(CheckoutMaterialize, LeavesTheUsersCheckoutUntouched) {
  // The user is mid-edit: a modified tracked file, a new untracked one.
  repo_.write("src/render.cpp", "// work in progress\n");
  repo_.write("notes.txt", "todo\n");
  const auto before = snapshot(repo_.path());
  ASSERT_TRUE(before.count(".git/index"));
  ASSERT_TRUE(before.count(".git/HEAD"));
  {
    const Repository repo = open();
    repo.checkout("dev");
    repo.checkout("HEAD~1");
    repo.checkout("main");
    repo.first_parent_history(first_, "main");
  }
  EXPECT_EQ(snapshot(repo_.path()), before);
  EXPECT_EQ(read_file(repo_.path() / ".git/HEAD"), "ref: refs/heads/main\n");
}

TEST_F(CheckoutMaterialize, ACompleteWorktreeIsReusedNotRewritten) {
  const Repository repo = open();
  const Worktree first = repo.checkout("main");
  const struct stat file_before = stat_of(first.path / "src/render.cpp");
  const struct stat dir_before = stat_of(first.path);
  const Worktree again = repo.checkout(second_);
  EXPECT_EQ(again.path, first.path);
  const struct stat file_after = stat_of(again.path / "src/render.cpp");
  EXPECT_EQ(file_after.st_ino, file_before.st_ino);
  EXPECT_EQ(file_after.st_mtim.tv_nsec, file_before.st_mtim.tv_nsec);
  EXPECT_EQ(file_after.st_mtim.tv_sec, file_before.st_mtim.tv_sec);
  EXPECT_EQ(stat_of(again.path).st_ino, dir_before.st_ino);
  // A second Repository (a later raygate run) reuses it too.
  EXPECT_EQ(stat_of(open().checkout("main").path / "src/render.cpp").st_ino, file_before.st_ino);
}

TEST_F(CheckoutMaterialize, AKilledRunsHalfWrittenTreeIsIgnoredAndCleaned) {
  const fs::path worktrees = cache() / "worktrees";
  const fs::path stale = worktrees / ("." + second_ + ".tmp-dead01");
  fs::create_directories(stale / "src");
  write_file_atomically(stale / "src/render.cpp", "// half");
  write_file_atomically(stale / "HALF_WRITTEN", "");
  const fs::path other = worktrees / ("." + first_ + ".tmp-alive1");  // another commit's: kept
  fs::create_directories(other);

  const Worktree tree = open().checkout("main");
  EXPECT_EQ(tree.path, worktrees / second_);
  EXPECT_EQ(read_file(tree.path / "src/render.cpp"), "// v2\n");
  EXPECT_FALSE(fs::exists(tree.path / "HALF_WRITTEN"));
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(other));
  std::vector<std::string> temporaries;
  for (const auto& entry : fs::directory_iterator(worktrees)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos) temporaries.push_back(name);
  }
  EXPECT_THAT(temporaries, ::testing::ElementsAre(other.filename().string()));
}

// A cached tree is verified before reuse (checkout/tree_stamp.h): what was edited, removed or
// emptied since it was checked out is recreated, so the clean commit's record never measures
// other code.
TEST_F(CheckoutMaterialize, AnEditedTreeIsRecreatedBeforeReuse) {
  const fs::path path = open().checkout("main").path;
  write_file_atomically(path / "src/render.cpp", "// v9\n");  // same size, new mtime
  EXPECT_EQ(read_file(open().checkout("main").path / "src/render.cpp"), "// v2\n");

  ::chmod((path / "CMakeLists.txt").c_str(), 0755);
  open().checkout("main");
  EXPECT_EQ(stat_of(path / "CMakeLists.txt").st_mode & S_IXUSR, 0u);

  fs::remove(path / "CMakeLists.txt");
  EXPECT_EQ(read_file(open().checkout("main").path / "CMakeLists.txt"), "project(t)\n");
}

TEST_F(CheckoutMaterialize, AnEmptiedOrDeletedTreeIsRecreated) {
  const fs::path path = open().checkout("main").path;
  for (const auto& entry : fs::directory_iterator(path)) fs::remove_all(entry.path());
  EXPECT_EQ(read_file(open().checkout("main").path / "src/render.cpp"), "// v2\n");
  fs::remove_all(path);
  EXPECT_EQ(read_file(open().checkout("main").path / "src/render.cpp"), "// v2\n");
}

// make-nff builds in {src}: its outputs appear in the tree and must not count as an edit, or
// every run would throw the build's tree away.
TEST_F(CheckoutMaterialize, FilesAddedByAnInTreeBuildDoNotCountAsChanges) {
  const fs::path path = open().checkout("main").path;
  const struct stat before = stat_of(path / "src/render.cpp");
  write_file_atomically(path / "src/render.o", "object");
  write_file_atomically(path / "tracer", "binary");
  open().checkout("main");
  EXPECT_EQ(stat_of(path / "src/render.cpp").st_ino, before.st_ino);
  EXPECT_TRUE(fs::exists(path / "tracer"));
  // The stamp lives beside the tree, never in it.
  EXPECT_TRUE(fs::exists(cache() / "worktrees" / ("." + second_ + ".stamp")));
  EXPECT_EQ(std::distance(fs::directory_iterator(path), fs::directory_iterator()), 3);
}

// A tree cached by a raygate that wrote no stamp cannot be vouched for: recreated once, then
// reused.
TEST_F(CheckoutMaterialize, ATreeWithoutAStampIsRecreatedOnceThenReused) {
  const fs::path path = open().checkout("main").path;
  fs::remove(cache() / "worktrees" / ("." + second_ + ".stamp"));
  write_file_atomically(path / "src/render.cpp", "// v9\n");
  EXPECT_EQ(read_file(open().checkout("main").path / "src/render.cpp"), "// v2\n");
  const struct stat recreated = stat_of(path / "src/render.cpp");
  open().checkout("main");
  EXPECT_EQ(stat_of(path / "src/render.cpp").st_ino, recreated.st_ino);
}

// Any path git allows survives the stamp's text form; a damaged stamp is never trusted.
TEST(TreeStamp, RoundTripsOddPathsAndRefusesDamagedStamps) {
  TempDir dir;
  write_file_atomically(dir.path() / "a b" / "line\nbreak.txt", "x");
  write_file_atomically(dir.path() / "12 34:5", "y");
  fs::create_symlink("12 34:5", dir.path() / "link");
  const std::string stamp = tree_stamp(dir.path());
  EXPECT_EQ(stamp_difference(dir.path(), stamp), std::nullopt);
  EXPECT_EQ(stamp_difference(dir.path(), stamp.substr(0, stamp.size() - 3)),
            "its stamp is unreadable");
  EXPECT_EQ(stamp_difference(dir.path(), "raygate tree stamp 0\n"), "its stamp is unreadable");
  fs::remove(dir.path() / "link");
  fs::create_symlink("elsewhere", dir.path() / "link");
  EXPECT_EQ(stamp_difference(dir.path(), stamp), "link was modified");
  const std::string relinked = tree_stamp(dir.path());
  fs::remove(dir.path() / "a b" / "line\nbreak.txt");
  EXPECT_EQ(stamp_difference(dir.path(), relinked), "a b/line\nbreak.txt is missing");
}

TEST_F(CheckoutMaterialize, MaterializeTakesAResolvedRevision) {
  const Repository repo = open();
  const Revision revision = repo.resolve("main");
  const Worktree tree = repo.materialize(revision);
  EXPECT_EQ(tree, worktree_of(cache() / "worktrees" / second_, revision));
  Revision bogus = revision;
  bogus.sha = "not-a-sha";
  EXPECT_THROW(repo.materialize(bogus), UsageError);
}

}  // namespace
}  // namespace raygate
