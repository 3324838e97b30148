// The compiler identity in the cache key, and the builder fed by the real checkout stage.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>

#include "builder/compiler_identity.h"
#include "builder_fixture.h"
#include "checkout/git_fixture.h"
#include "checkout/repository.h"

namespace raygate::testing {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for one test and puts the old value back.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value != nullptr) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(BuilderCompiler, FindsTheCompilerOnPath) {
  const ScopedEnv cxx("CXX", nullptr);
  const CompilerInfo info = detect_compiler("CXX", "c++");
  EXPECT_EQ(info.command, "c++");
  EXPECT_TRUE(fs::path(info.path).is_absolute()) << info.path;
  EXPECT_FALSE(info.version.empty());
  EXPECT_EQ(describe(info), "CXX=c++ (" + info.path + "): " + info.version);
}

TEST(BuilderCompiler, CxxVariableWins) {
  const ScopedEnv cxx("CXX", "raygate-no-such-compiler");
  const CompilerInfo info = detect_compiler("CXX", "c++");
  EXPECT_EQ(describe(info), "CXX=raygate-no-such-compiler (not found): version unknown");
  EXPECT_EQ(detect_compiler_identity().rfind(describe(info) + "\nCC=", 0), 0u);
}

TEST(BuilderCompiler, IdentityIsUsedWhenNotGiven) {
  BuilderFixture f;
  BuildOptions options = f.options();
  options.compiler_identity.reset();
  const BuildRecord r = build(f.worktree(), toy_adapter({}), options);
  EXPECT_EQ(r.compiler, detect_compiler_identity());
}

TEST(BuilderCheckout, BuildsACheckedOutCommit) {
  BuilderFixture f;
  GitFixture repo(f.root() / "repo");
  repo.write("renderer/tracer.sh", "echo v1\n", true);
  const std::string v1 = repo.commit("v1");
  repo.write("renderer/tracer.sh", "echo v2\n", true);
  const std::string v2 = repo.commit("v2");
  const Adapter a =
      toy_adapter({{"cp", "{src}/tracer.sh", "{build}/tracer"}}, {{"source_dir", "renderer"}});
  const Repository repository = Repository::open(repo.path().string(), f.cache());

  const BuildRecord first = build(repository.checkout(v1), a, f.options());
  const BuildRecord second = build(repository.checkout("main"), a, f.options());
  ASSERT_TRUE(first.success) << failure_message(first);
  ASSERT_TRUE(second.success) << failure_message(second);
  EXPECT_EQ(first.sha, v1);
  EXPECT_EQ(second.sha, v2);
  std::ifstream in(second.build_dir / "tracer");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "echo v2");
  EXPECT_TRUE(build(repository.checkout("main~1"), a, f.options()).cached);
}

}  // namespace
}  // namespace raygate::testing
