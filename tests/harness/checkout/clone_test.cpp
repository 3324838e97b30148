// Repositories named by URL (cloned bare into the cache, offline over file://) and submodules
// at their recorded pins, recursively, cloned into the cache and reused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "checkout/git_fixture.h"
#include "checkout/remote_cache.h"
#include "checkout/repository.h"
#include "core/error.h"
#include "core/fs.h"

namespace fs = std::filesystem;

// libgit2 1.5 leaks a PCRE2 match block on every regex match it runs over config keys (fixed
// upstream after 1.5: libgit2 PR #6382), and every remote lookup runs some. LeakSanitizer
// reads this hook in sanitizer builds; ordinary builds never call it.
extern "C" const char* __lsan_default_suppressions() { return "leak:libpcre2-8.so\n"; }

namespace raygate {
namespace {

using ::testing::HasSubstr;

class CheckoutClone : public ::testing::Test {
 protected:
  CheckoutClone() : upstream_(dir_.path() / "upstream") {
    upstream_.write("tracer.cpp", "// one\n");
    upstream_.write("bin/trace", "#!/bin/sh\n", true);
    first_ = upstream_.commit("first");
    upstream_.tag("v1");
    upstream_.write("tracer.cpp", "// two\n");
    second_ = upstream_.commit("second");
    upstream_.annotated_tag("v2", "second release");
    upstream_.branch("dev", first_);
  }
  fs::path cache() const { return dir_.path() / "cache"; }
  Repository open() const { return Repository::open(upstream_.url(), cache()); }

  TempDir dir_{"raygate-clone"};
  testing::GitFixture upstream_;
  std::string first_, second_;
};

TEST_F(CheckoutClone, FileUrlIsClonedBareIntoTheCache) {
  const Repository repo = open();
  const fs::path clone = clone_cache_path(cache(), upstream_.url());
  EXPECT_TRUE(fs::exists(clone / "HEAD"));
  EXPECT_TRUE(fs::exists(clone / "objects"));
  EXPECT_FALSE(fs::exists(clone / ".git"));
  EXPECT_EQ(repo.location(), upstream_.url());
}

TEST_F(CheckoutClone, ResolvesRemoteTrackingBranchesTagsAndHead) {
  const Repository repo = open();
  EXPECT_EQ(repo.resolve("origin/main").sha, second_);
  EXPECT_EQ(repo.resolve("origin/main").ref_name, "refs/remotes/origin/main");
  EXPECT_EQ(repo.resolve("main").sha, second_);  // a plain branch name finds origin/<name>
  EXPECT_EQ(repo.resolve("dev").sha, first_);
  EXPECT_EQ(repo.resolve("HEAD").sha, second_);
  EXPECT_EQ(repo.resolve("HEAD~1").sha, first_);
  EXPECT_EQ(repo.resolve("v1").sha, first_);
  EXPECT_EQ(repo.resolve("v2").sha, second_);
  EXPECT_EQ(repo.resolve(first_.substr(0, 10)).sha, first_);
}

TEST_F(CheckoutClone, UnknownRevisionNamesTheUrlAndRemoteBranches) {
  try {
    open().resolve("nope");
    FAIL() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown revision 'nope' in " + upstream_.url()));
    EXPECT_THAT(e.what(), HasSubstr("branches: origin/dev, origin/main;"));
    EXPECT_THAT(e.what(), HasSubstr("tags: v1, v2"));
  }
}

TEST_F(CheckoutClone, ALaterOpenFetchesNewCommitsAndDeletedBranches) {
  open();
  upstream_.write("tracer.cpp", "// three\n");
  const std::string third = upstream_.commit("third");
  upstream_.tag("v3");
  git_reference* dev = nullptr;
  ASSERT_EQ(git_branch_lookup(&dev, upstream_.raw(), "dev", GIT_BRANCH_LOCAL), 0);
  ASSERT_EQ(git_branch_delete(dev), 0);
  git_reference_free(dev);

  const Repository repo = open();
  EXPECT_EQ(repo.resolve("main").sha, third);
  EXPECT_EQ(repo.resolve("v3").sha, third);
  EXPECT_THROW(repo.resolve("origin/dev"), UsageError);
}

TEST_F(CheckoutClone, WorktreeFromAClone) {
  const Worktree tree = open().checkout("v1");
  EXPECT_EQ(tree.path, cache() / "worktrees" / first_);
  EXPECT_EQ(read_file(tree.path / "tracer.cpp"), "// one\n");
  EXPECT_TRUE((fs::status(tree.path / "bin/trace").permissions() & fs::perms::owner_exec) !=
              fs::perms::none);
}

TEST(CheckoutCloneErrors, AnUnreachableUrlIsAnInfraErrorNamingIt) {
  TempDir dir("raygate-clone-error");
  const std::string url = "file://" + (dir.path() / "no-such-repo").string();
  try {
    Repository::open(url, dir.path() / "cache");
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(), HasSubstr("fetching " + url));
  }
  // The failed clone leaves nothing that a later run could mistake for a clone.
  EXPECT_FALSE(fs::exists(clone_cache_path(dir.path() / "cache", url)));
}

// Sweeps 10 and 11: `--repo ext::sh -c ...` and an unknown scheme exited 3, "could not measure";
// libgit2 has no transport for them, so they are the user's to fix, said before any fetch.
TEST(CheckoutCloneErrors, AUrlNoTransportTakesIsAUsageError) {
  TempDir dir("raygate-clone-error");
  for (const std::string url : {"ext::sh -c touch% /tmp/x", "fd::17", "gopher://host/tracer"}) {
    try {
      Repository::open(url, dir.path() / "cache");
      ADD_FAILURE() << "accepted " << url;
    } catch (const UsageError& e) {
      EXPECT_THAT(e.what(), HasSubstr("repository " + url + ": ")) << e.what();
    }
  }
  EXPECT_FALSE(fs::exists(dir.path() / "cache" / "repos"));
}

// A superproject with a submodule "lib" (relative URL ../lib) that itself has a submodule
// "deep" (absolute URL). Two superproject commits pin "lib" at different commits.
class CheckoutSubmodule : public ::testing::Test {
 protected:
  CheckoutSubmodule()
      : deep_(dir_.path() / "deep"), lib_(dir_.path() / "lib"), super_(dir_.path() / "super") {
    deep_.write("deep.h", "// deep\n");
    const std::string deep_pin = deep_.commit("deep");

    lib_.write("lib.h", "// lib v1\n");
    lib_.set_submodule("third_party/deep", deep_.url(), deep_pin);
    lib_v1_ = lib_.commit("lib v1");
    lib_.write("lib.h", "// lib v2\n");
    lib_.write("tool.sh", "#!/bin/sh\n", true);
    lib_v2_ = lib_.commit("lib v2");

    super_.write("main.cpp", "int main() {}\n");
    super_.set_submodule("ext/lib", "../lib", lib_v1_);
    super_v1_ = super_.commit("pin lib v1");
    super_.set_submodule("ext/lib", "../lib", lib_v2_);
    super_v2_ = super_.commit("pin lib v2");
  }
  fs::path cache() const { return dir_.path() / "cache"; }

  TempDir dir_{"raygate-submodules"};
  testing::GitFixture deep_, lib_, super_;
  std::string lib_v1_, lib_v2_, super_v1_, super_v2_;
};

TEST_F(CheckoutSubmodule, EachWorktreeGetsItsOwnPinnedContentRecursively) {
  const Repository repo = Repository::open(super_.path().string(), cache());
  const Worktree v1 = repo.checkout(super_v1_);
  const Worktree v2 = repo.checkout(super_v2_);
  EXPECT_EQ(read_file(v1.path / "ext/lib/lib.h"), "// lib v1\n");
  EXPECT_FALSE(fs::exists(v1.path / "ext/lib/tool.sh"));
  EXPECT_EQ(read_file(v2.path / "ext/lib/lib.h"), "// lib v2\n");
  EXPECT_TRUE((fs::status(v2.path / "ext/lib/tool.sh").permissions() & fs::perms::owner_exec) !=
              fs::perms::none);
  EXPECT_EQ(read_file(v1.path / "ext/lib/third_party/deep/deep.h"), "// deep\n");
  EXPECT_EQ(read_file(v2.path / "ext/lib/third_party/deep/deep.h"), "// deep\n");
  EXPECT_EQ(read_file(v1.path / "main.cpp"), "int main() {}\n");
  // "../lib" was resolved against the superproject's directory and cloned once into the cache.
  EXPECT_TRUE(fs::exists(clone_cache_path(cache(), lib_.path().string()) / "objects"));
  EXPECT_TRUE(fs::exists(clone_cache_path(cache(), deep_.url()) / "objects"));
}

TEST_F(CheckoutSubmodule, RelativeUrlsResolveAgainstASuperprojectUrl) {
  const Repository repo = Repository::open(super_.url(), cache());
  const Worktree v2 = repo.checkout("main");
  EXPECT_EQ(v2.sha, super_v2_);
  EXPECT_EQ(read_file(v2.path / "ext/lib/lib.h"), "// lib v2\n");
  EXPECT_TRUE(fs::exists(clone_cache_path(cache(), "file://" + lib_.path().string()) / "objects"));
}

TEST_F(CheckoutSubmodule, ANewPinFetchesTheCachedSubmoduleClone) {
  const Repository repo = Repository::open(super_.path().string(), cache());
  repo.checkout(super_v1_);
  lib_.write("lib.h", "// lib v3\n");
  const std::string lib_v3 = lib_.commit("lib v3");
  super_.set_submodule("ext/lib", "../lib", lib_v3);
  const std::string super_v3 = super_.commit("pin lib v3");
  EXPECT_EQ(read_file(repo.checkout(super_v3).path / "ext/lib/lib.h"), "// lib v3\n");
}

TEST_F(CheckoutSubmodule, APinTheSubmoduleDoesNotHaveIsAnInfraError) {
  super_.set_submodule("ext/lib", "../lib", deep_.sha("HEAD"));  // a commit lib never had
  const std::string broken = super_.commit("bad pin");
  const Repository repo = Repository::open(super_.path().string(), cache());
  try {
    repo.checkout(broken);
    FAIL() << "expected InfraError";
  } catch (const InfraError& e) {
    EXPECT_THAT(e.what(), HasSubstr("submodule 'ext/lib'"));
    EXPECT_THAT(e.what(), HasSubstr(deep_.sha("HEAD")));
  }
  EXPECT_FALSE(fs::exists(repo.worktree_path(broken)));
}

}  // namespace
}  // namespace raygate
