// Repositories git refuses or cannot fully answer for: one owned by another user names git's
// ownership check and the safe.directory remedy (not "not in a git repository"), and a revision
// missing from a shallow clone says the clone is shallow.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "checkout/git_fixture.h"
#include "checkout/repository.h"
#include "checkout/safe_directory.h"
#include "core/error.h"
#include "core/fs.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

std::string open_error(const fs::path& repo, const fs::path& cache) {
  try {
    Repository::open(repo.string(), cache);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "opened";
}

// libgit2 reads the global and system git config for safe.directory: point it at an empty
// folder so the machine's own config cannot decide the test, and at `dir`/.gitconfig when set.
void use_config_dir(const fs::path& dir) {
  for (const int level : {GIT_CONFIG_LEVEL_GLOBAL, GIT_CONFIG_LEVEL_XDG, GIT_CONFIG_LEVEL_SYSTEM,
                          GIT_CONFIG_LEVEL_PROGRAMDATA}) {
    ASSERT_EQ(git_libgit2_opts(GIT_OPT_SET_SEARCH_PATH, level, dir.c_str()), 0);
  }
}

// A repository of one commit at `path`, given to `nobody` (uid 65534), as a CI checkout made by
// another user than the job's.
void commit_and_give_to_nobody(const fs::path& path) {
  {
    testing::GitFixture repo(path);
    repo.write("a.txt", "a\n");
    repo.commit("first");
  }
  const uid_t nobody = 65534;
  ASSERT_EQ(::lchown(path.c_str(), nobody, nobody), 0);
  for (const auto& entry : fs::recursive_directory_iterator(path)) {
    ASSERT_EQ(::lchown(entry.path().c_str(), nobody, nobody), 0) << entry.path();
  }
}

TEST(CheckoutRefusal, RepositoryOwnedByAnotherUserNamesTheOwnershipCheck) {
  if (::getuid() != 0) GTEST_SKIP() << "needs root to give a repository to another user";
  TempDir dir("raygate-owner");
  const fs::path path = dir.path() / "theirs";
  commit_and_give_to_nobody(path);
  git::Library library;  // keeps the search paths set below for the opens in this test
  const fs::path config = dir.path() / "config";
  fs::create_directories(config);
  use_config_dir(config);

  const std::string refused = open_error(path, dir.path() / "cache");
  EXPECT_NE(refused.find("git refuses the repository " + path.string()), std::string::npos)
      << refused;
  EXPECT_NE(refused.find("owned by uid 65534"), std::string::npos) << refused;
  EXPECT_NE(refused.find("git config --global --add safe.directory " + path.string()),
            std::string::npos)
      << refused;
  EXPECT_EQ(refused.find("not in a git repository"), std::string::npos) << refused;

  // The remedy the message names works: libgit2 honours safe.directory from git config.
  write_file_atomically(config / ".gitconfig", "[safe]\n\tdirectory = " + path.string() + "\n");
  EXPECT_EQ(open_error(path, dir.path() / "cache"), "opened");

  // A folder in no repository at all still says so.
  fs::create_directories(dir.path() / "plain");
  EXPECT_NE(open_error(dir.path() / "plain", dir.path() / "cache").find("not in a git repository"),
            std::string::npos);
}

// The rules git applies to safe.directory values, which libgit2 1.5 applies only in part.
TEST(CheckoutRefusal, SafeDirectoryValuesFollowGitsRules) {
  EXPECT_FALSE(safe_directory_trusts({}, "/w/repo"));
  EXPECT_TRUE(safe_directory_trusts({"/w/repo"}, "/w/repo"));
  EXPECT_TRUE(safe_directory_trusts({"/w/repo/"}, "/w/repo"));
  EXPECT_TRUE(safe_directory_trusts({"*"}, "/w/repo"));
  EXPECT_FALSE(safe_directory_trusts({"/w/other", "/w/rep"}, "/w/repo"));
  EXPECT_FALSE(safe_directory_trusts({"*", ""}, "/w/repo")) << "an empty value resets the list";
  EXPECT_TRUE(safe_directory_trusts({"", "*"}, "/w/repo"));
}

// `git config --global --add safe.directory '*'`, what CI containers commonly run, is honoured by
// git and, since libgit2 1.5 ignores it, by raygate's own reading of the config.
TEST(CheckoutRefusal, WildcardSafeDirectoryTrustsAForeignRepositoryLikeGit) {
  if (::getuid() != 0) GTEST_SKIP() << "needs root to give a repository to another user";
  TempDir dir("raygate-owner-wildcard");
  const fs::path path = dir.path() / "theirs";
  commit_and_give_to_nobody(path);
  git::Library library;
  const fs::path config = dir.path() / "config";
  fs::create_directories(config);
  use_config_dir(config);

  write_file_atomically(config / ".gitconfig", "[safe]\n\tdirectory = *\n");
  EXPECT_EQ(open_error(path, dir.path() / "cache"), "opened");

  // An empty value after it forgets it, as in git: refused again, with the remedy.
  write_file_atomically(config / ".gitconfig", "[safe]\n\tdirectory = *\n\tdirectory =\n");
  EXPECT_NE(open_error(path, dir.path() / "cache").find("git config --global --add safe.directory"),
            std::string::npos);
}

// libgit2 writes loose objects: removing one is what a shallow clone lacks.
void remove_object(const fs::path& repo, const std::string& sha) {
  ASSERT_TRUE(fs::remove(repo / ".git" / "objects" / sha.substr(0, 2) / sha.substr(2)));
}

TEST(CheckoutRefusal, RevisionMissingFromAShallowCloneSaysTheCloneIsShallow) {
  TempDir dir("raygate-shallow");
  testing::GitFixture repo(dir.path() / "clone");
  repo.write("a.txt", "1\n");
  const std::string old = repo.commit("old");
  repo.write("a.txt", "2\n");
  const std::string recent = repo.commit("recent");
  remove_object(repo.path(), old);
  write_file_atomically(repo.path() / ".git" / "shallow", recent + "\n");

  const Repository opened = Repository::open(repo.path().string(), dir.path() / "cache");
  EXPECT_EQ(opened.resolve("HEAD").sha, recent);
  for (const std::string& missing : {old, std::string("HEAD~1")}) {
    try {
      opened.resolve(missing);
      ADD_FAILURE() << missing << " resolved";
    } catch (const UsageError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("the clone is shallow"), std::string::npos) << what;
      EXPECT_NE(what.find("git fetch --unshallow"), std::string::npos) << what;
    }
  }

  // Without the shallow marker the same missing commit is just unknown.
  fs::remove(repo.path() / ".git" / "shallow");
  const Repository full = Repository::open(repo.path().string(), dir.path() / "cache");
  try {
    full.resolve(old);
    ADD_FAILURE() << "resolved";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find("the clone is shallow"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raygate
