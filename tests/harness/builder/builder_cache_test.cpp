// Successful builds and the cache: steps run in order with placeholders expanded, in {src}; a
// successful build is reused without running a step; any change of commit, adapter or compiler,
// and any dirty worktree, builds anew; leftovers of a dead run are never taken for output.
#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "builder/build_cache.h"
#include "builder_fixture.h"

namespace raygate::testing {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

BuildKeyInputs inputs_for(const Worktree& w, const Adapter& a, const BuildOptions& o) {
  return {
      w.sha,      w.dirty, a.name, build_inputs_hash(a, build_environment()), *o.compiler_identity,
      o.key_extra};
}

TEST(BuilderCache, RunsEveryStepWithPlaceholdersInSrc) {
  BuilderFixture f;
  fs::create_directories(f.tree() / "renderer");
  const Adapter a =
      toy_adapter({{"sh", "-c", "printf '%s\\n' \"$@\" > \"$1/placeholders.txt\"", "sh", "{build}",
                    "{src}", "{repo_root}", "{jobs}", "{raygate_source}"},
                   {"cp", "{build}/placeholders.txt", "{build}/tracer"},
                   {"sh", "-c", "pwd > \"$1/cwd.txt\"", "sh", "{build}"}},
                  {{"source_dir", "renderer"}});
  const BuildRecord r = build(f.worktree(), a, f.options());

  ASSERT_TRUE(r.success) << failure_message(r);
  EXPECT_FALSE(r.cached);
  ASSERT_EQ(r.steps.size(), 3u);
  const fs::path src = f.tree() / "renderer";
  EXPECT_EQ(read_text(r.build_dir / "tracer"), r.build_dir.string() + "\n" + src.string() + "\n" +
                                                   f.tree().string() + "\n3\n" +
                                                   (f.root() / "raygate-src").string() + "\n");
  EXPECT_EQ(read_text(r.build_dir / "cwd.txt"), src.string() + "\n");
  EXPECT_EQ(r.src_dir, src);
  EXPECT_EQ(r.steps[1].argv,
            (std::vector<std::string>{"cp", r.build_dir.string() + "/placeholders.txt",
                                      r.build_dir.string() + "/tracer"}));
  EXPECT_EQ(r.steps[0].outcome, "exited with status 0");
  EXPECT_EQ(r.steps[2].log, f.cache() / "builds" / r.key / "logs" / "step-3.log");
  EXPECT_EQ(r.build_dir, f.cache() / "builds" / r.key / "build");
  EXPECT_EQ(r.sha, kShaA);
  EXPECT_EQ(r.adapter_hash, build_inputs_hash(a, build_environment()));
  EXPECT_EQ(r.compiler, "test compiler 1.0");
}

TEST(BuilderCache, StepOutputGoesToItsLog) {
  BuilderFixture f;
  const Adapter a = toy_adapter({{"sh", "-c", "echo to-out; echo to-err >&2"}});
  const BuildRecord r = build(f.worktree(), a, f.options());
  ASSERT_TRUE(r.success);
  EXPECT_EQ(read_text(r.steps[0].log), "to-out\nto-err\n");
}

TEST(BuilderCache, HitReturnsTheRecordWithoutRunningSteps) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter()), {"touch", "{build}/tracer"}});
  const BuildRecord first = build(f.worktree(), a, f.options());
  const BuildRecord second = build(f.worktree(), a, f.options());

  ASSERT_TRUE(first.success);
  EXPECT_TRUE(second.success);
  EXPECT_TRUE(second.cached);
  EXPECT_EQ(lines_in(f.counter()), 1);
  EXPECT_EQ(second.build_dir, first.build_dir);
  BuildRecord expected = first;
  expected.cached = true;
  EXPECT_EQ(second, expected);  // build.json holds the whole record
}

TEST(BuilderCache, BuildJsonIsWrittenOnSuccess) {
  BuilderFixture f;
  const BuildRecord r = build(f.worktree(), toy_adapter({{"true"}}), f.options());
  const fs::path record = f.cache() / "builds" / r.key / "build.json";
  ASSERT_TRUE(fs::exists(record));
  EXPECT_EQ(build_record_from_json(nlohmann::json::parse(read_text(record))), r);
}

TEST(BuilderCache, OtherCommitAdapterOrCompilerBuildsAgain) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())});
  // Another build flag: the count step with one more argument, as a CMake -D would be.
  nlohmann::json flagged = count_step(f.counter());
  flagged.push_back("-DFAST=ON");
  const Adapter slower = toy_adapter({flagged});
  const BuildRecord base = build(f.worktree(kShaA), a, f.options());
  const BuildRecord other_sha = build(f.worktree(kShaB), a, f.options());
  const BuildRecord other_adapter = build(f.worktree(kShaA), slower, f.options());
  const BuildRecord other_compiler = build(f.worktree(kShaA), a, f.options("clang 99"));
  BuildOptions extra = f.options();
  extra.key_extra = "raygate 0.2";
  const BuildRecord other_extra = build(f.worktree(kShaA), a, extra);

  EXPECT_EQ(lines_in(f.counter()), 5);
  for (const BuildRecord* r : {&other_sha, &other_adapter, &other_compiler, &other_extra}) {
    EXPECT_FALSE(r->cached);
    EXPECT_NE(r->key, base.key);
    EXPECT_NE(r->build_dir, base.build_dir);
  }
  EXPECT_TRUE(build(f.worktree(kShaB), a, f.options()).cached);
}

// Fixing how the tracer is run (its path, its options, its timeouts) changes no file the build
// makes, so the build is reused (issue 26: a wrong run path cost a 35 s rebuild to fix).
TEST(BuilderCache, ARunOnlyChangeReusesTheBuild) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())});
  const Adapter fixed = toy_adapter({count_step(f.counter())},
                                    {{"run", {"{build}/bin/tracer", "{scene}", "-o", "{image}"}},
                                     {"timeout_s", {{"run", 9}}},
                                     {"env", {{"OMP_NUM_THREADS", "1"}}},
                                     {"description", "the run path fixed"}});
  const BuildRecord first = build(f.worktree(), a, f.options());
  const BuildRecord second = build(f.worktree(), fixed, f.options());
  ASSERT_TRUE(first.success);
  EXPECT_TRUE(second.cached);
  EXPECT_EQ(second.key, first.key);
  EXPECT_EQ(lines_in(f.counter()), 1);
  // The measurement is another one all the same: a history series of its own.
  EXPECT_NE(measurement_hash(fixed, second.adapter_hash), measurement_hash(a, first.adapter_hash));
}

// The build tools' environment is an input: CXXFLAGS set in the job changes the binary.
TEST(BuilderCacheKey, BuildEnvironmentIsAnInput) {
  const Adapter a = toy_adapter({{"true"}});
  EXPECT_NE(build_inputs_hash(a, {{"CXXFLAGS", "-O3"}}), build_inputs_hash(a, {}));
  EXPECT_NE(build_inputs_hash(a, {{"CXXFLAGS", "-O3"}}),
            build_inputs_hash(a, {{"CXXFLAGS", "-O2"}}));
  EXPECT_EQ(build_inputs_hash(a, {}),
            build_inputs_hash(toy_adapter({{"true"}}, {{"threads", 4}}), {}));
}

TEST(BuilderCache, DirtyWorktreeIsAlwaysRebuiltAndNeverRecorded) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())});
  const BuildRecord clean = build(f.worktree(kShaA), a, f.options());
  const BuildRecord dirty1 = build(f.worktree(kShaA, true), a, f.options());
  const BuildRecord dirty2 = build(f.worktree(kShaA, true), a, f.options());

  EXPECT_EQ(lines_in(f.counter()), 3);
  EXPECT_TRUE(dirty2.success);
  EXPECT_FALSE(dirty2.cached);
  EXPECT_TRUE(dirty2.dirty);
  EXPECT_NE(dirty1.key, clean.key);
  EXPECT_FALSE(fs::exists(f.cache() / "builds" / dirty2.key / "build.json"));
  EXPECT_TRUE(build(f.worktree(kShaA), a, f.options()).cached);  // the clean build survives
}

TEST(BuilderCache, LeftoverOfADeadRunIsRemovedBeforeBuilding) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())});
  const BuildOptions o = f.options();
  const BuildCacheEntry entry = cache_entry(f.cache(), build_key(inputs_for(f.worktree(), a, o)));
  fs::create_directories(entry.build_dir);
  std::ofstream(entry.build_dir / "tracer") << "stale";

  const BuildRecord r = build(f.worktree(), a, o);
  ASSERT_TRUE(r.success);
  EXPECT_EQ(r.build_dir, entry.build_dir);
  EXPECT_FALSE(fs::exists(entry.build_dir / "tracer"));
  EXPECT_EQ(lines_in(f.counter()), 1);
}

TEST(BuilderCache, UnreadableOrFailedRecordIsNotAHit) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())});
  const BuildRecord r = build(f.worktree(), a, f.options());
  const fs::path record = f.cache() / "builds" / r.key / "build.json";

  write_file_atomically(record, "{\"record_version\": 1, \"sha\"");
  EXPECT_FALSE(build(f.worktree(), a, f.options()).cached);
  nlohmann::json doc = nlohmann::json::parse(read_text(record));
  doc["success"] = false;
  write_file_atomically(record, doc.dump());
  EXPECT_FALSE(build(f.worktree(), a, f.options()).cached);
  EXPECT_EQ(lines_in(f.counter()), 3);
}

TEST(BuilderCache, TwoBuildsOfOneKeyAtOnceRunTheStepsOnce) {
  BuilderFixture f;
  const Adapter a =
      toy_adapter({{"sh", "-c", "echo ran >> \"$1\"; sleep 0.2", "sh", f.counter().string()},
                   {"touch", "{build}/tracer"}});
  BuildRecord first;
  BuildRecord second;
  std::thread other([&] { first = build(f.worktree(), a, f.options()); });
  second = build(f.worktree(), a, f.options());
  other.join();

  EXPECT_TRUE(first.success);
  EXPECT_TRUE(second.success);
  EXPECT_NE(first.cached, second.cached);
  EXPECT_EQ(lines_in(f.counter()), 1);
  EXPECT_TRUE(fs::exists(first.build_dir / "tracer"));
}

TEST(BuilderCache, NoStepsIsAnEmptySuccessfulBuild) {
  BuilderFixture f;
  const BuildRecord r = build(f.worktree(), toy_adapter({}), f.options());
  EXPECT_TRUE(r.success);
  EXPECT_TRUE(fs::is_directory(r.build_dir));
  EXPECT_TRUE(build(f.worktree(), toy_adapter({}), f.options()).cached);
}

TEST(BuilderCacheKey, ReadableAndSensitiveToEveryInput) {
  const BuildKeyInputs base{kShaA, false, "toy", "h1", "gcc 12", ""};
  const std::string key = build_key(base);
  EXPECT_EQ(key.rfind("toy-aaaaaaaaaaaa-", 0), 0u) << key;
  EXPECT_EQ(key.size(), std::string("toy-aaaaaaaaaaaa-").size() + 16);
  EXPECT_EQ(build_key(base), key);
  BuildKeyInputs dirty = base;
  dirty.dirty = true;
  EXPECT_NE(build_key(dirty).find("-dirty-"), std::string::npos);
  for (auto change : {+[](BuildKeyInputs& i) { i.sha = kShaB; },
                      +[](BuildKeyInputs& i) { i.adapter_hash = "h2"; },
                      +[](BuildKeyInputs& i) { i.compiler = "gcc 13"; },
                      +[](BuildKeyInputs& i) { i.extra = kShaB; },
                      +[](BuildKeyInputs& i) { i.adapter_name = "toy2"; }}) {
    BuildKeyInputs changed = base;
    change(changed);
    EXPECT_NE(build_key(changed), key);
  }
}

}  // namespace
}  // namespace raygate::testing
