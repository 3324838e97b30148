// Telling URLs from paths, the cache key of a URL, and git's rules for relative submodule URLs.
#include <gtest/gtest.h>

#include "checkout/remote_cache.h"
#include "core/error.h"

namespace raygate {
namespace {

TEST(CheckoutIsUrl, SchemesAndScpLikeAreUrlsPathsAreNot) {
  EXPECT_TRUE(is_url("https://github.com/a/b.git"));
  EXPECT_TRUE(is_url("file:///srv/git/tracer"));
  EXPECT_TRUE(is_url("ssh://git@host/a.git"));
  EXPECT_TRUE(is_url("git@github.com:a/b.git"));
  EXPECT_FALSE(is_url("/home/me/tracer"));
  EXPECT_FALSE(is_url("../tracer"));
  EXPECT_FALSE(is_url("."));
  EXPECT_FALSE(is_url("./odd:name"));
}

TEST(CheckoutClonePath, OneDirectoryPerUrlUnderRepos) {
  const auto a = clone_cache_path("/c", "file:///srv/a");
  EXPECT_EQ(a.parent_path(), "/c/repos");
  EXPECT_EQ(a.filename().string().size(), 16u);
  EXPECT_EQ(a, clone_cache_path("/c", "file:///srv/a"));
  EXPECT_NE(a, clone_cache_path("/c", "file:///srv/b"));
}

TEST(CheckoutRelativeUrl, ResolvesLikeGit) {
  EXPECT_EQ(resolve_relative_url("../sub.git", "https://host/org/super.git"),
            "https://host/org/sub.git");
  EXPECT_EQ(resolve_relative_url("./sub", "https://host/org/super"), "https://host/org/super/sub");
  EXPECT_EQ(resolve_relative_url("../../x/y", "https://host/org/super/"), "https://host/x/y");
  EXPECT_EQ(resolve_relative_url("../sub", "/srv/git/super"), "/srv/git/sub");
  EXPECT_EQ(resolve_relative_url("../sub", "file:///super"), "file:///sub");
  EXPECT_EQ(resolve_relative_url("../sub.git", "git@host:org/super.git"), "git@host:org/sub.git");
  EXPECT_EQ(resolve_relative_url("../sub.git", "git@host:super.git"), "git@host:sub.git");
  EXPECT_EQ(resolve_relative_url("https://other/abs.git", "/srv/super"), "https://other/abs.git");
}

TEST(CheckoutRelativeUrl, ClimbingAboveTheHostIsAnError) {
  EXPECT_THROW(resolve_relative_url("../../../x", "https://host/super"), UsageError);
  EXPECT_THROW(resolve_relative_url("../../x", "file:///super"), UsageError);
}

}  // namespace
}  // namespace raygate
