// `raygate run` end to end: a throwaway git repository holding a small real NFF tracer
// (tests/fixtures/nff_tracer) built through the shipped make-nff adapter, measured on a tiny
// suite. A complete document; a slower commit's higher ratio; the build cache; the user's tree
// and HEAD untouched; concurrent runs apart; a crash, a missing image and a hang recorded per
// scene (exit 3); an unreadable image failed (exit 1); usage errors (exit 2); goldens compared
// only when made from the same scene settings (an image unlike its golden: exit 1).
#include <gtest/gtest.h>

#include <chrono>

#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "tracer_fixture.h"
#include "results/results.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class RunCli : public ::testing::Test {
 protected:
  RunCli() : repo_(dir_.path() / "tracer-repo") {
    write_file_atomically(suite_, kTinySuite);
    fs::create_directories(no_goldens_);
  }

  std::string commit(const std::string& source, const std::string& message) {
    repo_.write("tracer.cpp", source);
    repo_.write("Makefile", read_file(kFixture / "Makefile"));
    return repo_.commit(message);
  }

  struct Options {
    std::string adapter = "make-nff";
    std::vector<std::string> scenes{"tetra", "balls"};
    std::string max_rounds = "3";
    std::string warmup = "1";
    std::string golden_dir = "no-goldens";
    std::vector<std::string> extra;  // more options
  };

  // The arguments of raygate run of `rev` on the tiny suite.
  std::vector<std::string> arguments(const std::string& rev, const Options& options) const {
    std::vector<std::string> args{"run",
                                  "--repo",
                                  repo_.path().string(),
                                  "--rev",
                                  rev,
                                  "--adapter",
                                  options.adapter,
                                  "--suite",
                                  suite_.string(),
                                  "--cache-dir",
                                  cache_.string(),
                                  "--golden-dir",
                                  options.golden_dir,
                                  "--max-rounds",
                                  options.max_rounds,
                                  "--warmup",
                                  options.warmup};
    for (const std::string& id : options.scenes) args.insert(args.end(), {"--scene", id});
    args.insert(args.end(), options.extra.begin(), options.extra.end());
    return args;
  }

  CliRun run(const std::string& rev, const fs::path& out, const Options& options) {
    std::vector<std::string> args = arguments(rev, options);
    args.insert(args.end(), {"--out", out.string()});
    return run_raygate(args, dir_);
  }
  CliRun run(const std::string& rev, const fs::path& out) { return run(rev, out, Options{}); }

  // One round of one scene, no warm-up: for what does not need numbers.
  static Options quick() {
    return Options{.scenes = {"tetra"}, .max_rounds = "1", .warmup = "0", .extra = {}};
  }

  // The shipped make-nff adapter with a 1 s run timeout, as a file in the temp dir.
  fs::path short_timeout_adapter() const {
    json adapter = json::parse(read_file(kSource / "adapters" / "make-nff.json"));
    adapter["name"] = "make-nff-1s";
    adapter["timeout_s"]["run"] = 1;
    const fs::path path = dir_.path() / "make-nff-1s.json";
    write_file_atomically(path, adapter.dump(2));
    return path;
  }

  TempDir dir_;
  testing::GitFixture repo_;
  TracerSources sources_;
  fs::path suite_ = dir_.path() / "tiny.json";
  fs::path no_goldens_ = dir_.path() / "no-goldens";
  fs::path cache_ = dir_.path() / ".raygate";
};

const SceneResult& scene(const ResultsDocument& document, const std::string& id) {
  for (const SceneResult& s : document.scenes) {
    if (s.entry.id == id) return s;
  }
  throw std::runtime_error("no scene " + id + " in the document");
}

double ratio(const ResultsDocument& document, const std::string& id) {
  const RatioSummary* r = scene(document, id).ratio(Role::tracer);
  return r == nullptr ? 0.0 : r->ratio;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Every run of a measured scene: successful, timed, with its log and image on disk.
void expect_measured(const SceneResult& s) {
  SCOPED_TRACE("scene " + s.entry.id);
  EXPECT_EQ(s.status, SceneStatus::measured);
  EXPECT_FALSE(s.runs.failed());
  ASSERT_EQ(s.runs.rounds.size(), 3u);  // --max-rounds 3 (min_rounds shrinks to 3 as well)
  EXPECT_EQ(s.scene_sha256.size(), 64u);
  EXPECT_EQ(s.runs.warmup.at("tracer").size(), 1u);
  for (const Round& round : s.runs.rounds) {
    for (const std::string role : {"baseline", "tracer"}) {
      const RunRecord& run = round.runs.at(role);
      EXPECT_TRUE(run.ok) << role << ": " << run.failure;
      EXPECT_GT(run.seconds, 0.0) << role;
      EXPECT_GT(run.wall_seconds, 0.0) << role;
      EXPECT_TRUE(fs::exists(run.log)) << run.log;
      EXPECT_TRUE(fs::exists(run.image)) << run.image;
    }
    EXPECT_TRUE(round.runs.at("baseline").reported_seconds);  // in-process time from --stats
  }
  const RatioSummary* r = s.ratio(Role::tracer);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->rounds, 3u);
  EXPECT_GT(r->ratio, 0.0);
  EXPECT_LE(r->ratio_interval.lower, r->ratio);
  EXPECT_GE(r->ratio_interval.upper, r->ratio);
}

// --- a good revision ---------------------------------------------------------------------------

TEST_F(RunCli, MeasuresARevisionIntoACompleteDocument) {
  const std::string sha = commit(sources_.fast, "tracer");
  repo_.tag("v1");
  const CliRun r = run("v1", dir_.path() / "r.json");
  ASSERT_EQ(r.exit_code, 0) << r.out;

  const ResultsDocument d = read_results(dir_.path() / "r.json");
  EXPECT_TRUE(d.complete);
  EXPECT_EQ(d.kind, DocumentKind::run);
  EXPECT_EQ(d.suite, "tiny");
  EXPECT_FALSE(d.finished_at.empty());
  EXPECT_TRUE(has(d.baseline.version, "raygate-baseline")) << d.baseline.version;
  EXPECT_FALSE(d.machine.empty());
  EXPECT_EQ(d.settings.schedule, ScheduleKind::alternate);
  ASSERT_EQ(d.revisions.size(), 1u);
  const RevisionRecord& tracer = d.revisions[0];
  EXPECT_EQ(tracer.worktree.sha, sha);
  EXPECT_EQ(tracer.worktree.revision, "v1");
  EXPECT_FALSE(tracer.worktree.dirty);
  EXPECT_EQ(tracer.adapter_name, "make-nff");
  EXPECT_EQ(tracer.adapter_hash,
            adapter_hash(load_adapter(kSource / "adapters" / "make-nff.json")));
  EXPECT_TRUE(tracer.build.success);
  EXPECT_FALSE(tracer.build.cached);
  for (const BuildStepRecord& step : tracer.build.steps) EXPECT_TRUE(fs::exists(step.log));

  ASSERT_EQ(d.scenes.size(), 2u);
  EXPECT_EQ(d.scenes[0].entry.id, "tetra");  // in the order asked for
  for (const SceneResult& s : d.scenes) {
    expect_measured(s);
    ASSERT_EQ(s.images.size(), 1u);
    // An empty golden dir: reported, not failed.
    EXPECT_EQ(s.images[0].verdict, ImageVerdict::missing);
  }
  ASSERT_TRUE(d.scores.contains(Role::tracer));
  EXPECT_EQ(d.scores.at(Role::tracer).scenes, 2u);
  EXPECT_TRUE(has(r.out, "tetra")) << r.out;
  EXPECT_TRUE(has(r.out, "results: " + (dir_.path() / "r.json").string())) << r.out;
}

TEST_F(RunCli, SlowerCommitHasAClearlyHigherRatio) {
  const std::string fast = commit(sources_.fast, "tracer");
  const std::string slow = commit(sources_.slow, "trace every pixel four times");
  ASSERT_EQ(run(fast, dir_.path() / "fast.json").exit_code, 0);
  const CliRun r = run(slow, dir_.path() / "slow.json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const ResultsDocument before = read_results(dir_.path() / "fast.json");
  const ResultsDocument after = read_results(dir_.path() / "slow.json");
  EXPECT_EQ(after.revisions[0].worktree.sha, slow);
  for (const std::string id : {"tetra", "balls"}) {
    EXPECT_GT(ratio(after, id), 1.8 * ratio(before, id))
        << id << ": fast " << ratio(before, id) << ", slow " << ratio(after, id);
  }
}

TEST_F(RunCli, SecondRunReusesTheBuildAndTheUsersTreeIsUntouched) {
  const std::string sha = commit(sources_.fast, "tracer");
  // The user's own checkout: HEAD, a local edit and an untracked file, which raygate only reads.
  repo_.write("tracer.cpp", "// half-written local change\n");
  repo_.write("notes.txt", "untracked\n");
  const std::string index = read_file(repo_.path() / ".git" / "index");

  ASSERT_EQ(run("HEAD", dir_.path() / "first.json", quick()).exit_code, 0);
  const CliRun again = run("main", dir_.path() / "second.json", quick());
  ASSERT_EQ(again.exit_code, 0) << again.out;
  EXPECT_TRUE(has(again.out, "cached build")) << again.out;
  const BuildRecord first = read_results(dir_.path() / "first.json").revisions[0].build;
  const BuildRecord second = read_results(dir_.path() / "second.json").revisions[0].build;
  EXPECT_TRUE(second.cached);
  EXPECT_EQ(second.build_dir, first.build_dir);

  EXPECT_EQ(repo_.sha("HEAD"), sha);
  EXPECT_EQ(read_file(repo_.path() / "tracer.cpp"), "// half-written local change\n");
  EXPECT_EQ(read_file(repo_.path() / "notes.txt"), "untracked\n");
  EXPECT_EQ(read_file(repo_.path() / ".git" / "index"), index);
  EXPECT_FALSE(fs::exists(repo_.path() / "tracer"));  // built in the worktree cache, not here
}

// Without --out the document goes into the run's own directory, which must be its own even when
// two runs of one commit start in the same second (CI shards sharing a machine and cache).
TEST_F(RunCli, RunsStartedTogetherKeepTheirOwnRunDirectories) {
  commit(sources_.fast, "tracer");
  ASSERT_EQ(run("HEAD", dir_.path() / "warm.json", quick()).exit_code, 0);  // builds it once
  std::vector<Process> processes;
  for (const std::string name : {"a.log", "b.log"}) {
    ProcessSpec spec;
    spec.argv = arguments("HEAD", quick());
    spec.argv.insert(spec.argv.begin(), RAYGATE_EXE);
    spec.stdout_path = dir_.path() / name;
    spec.stderr_path = spec.stdout_path;
    spec.timeout = std::chrono::minutes(2);
    processes.push_back(Process::start(spec));
  }
  std::vector<fs::path> documents;
  for (Process& process : processes) EXPECT_TRUE(process.wait().succeeded());
  for (const std::string name : {"a.log", "b.log"}) {
    const std::string log = read_file(dir_.path() / name);
    const std::size_t at = log.find("results: ");
    ASSERT_NE(at, std::string::npos) << log;
    documents.emplace_back(log.substr(at + 9, log.find('\n', at) - at - 9));
  }
  EXPECT_NE(documents[0], documents[1]);
  EXPECT_NE(documents[0].parent_path(), documents[1].parent_path());
  for (const fs::path& document : documents) {
    EXPECT_EQ(read_results(document).scenes.at(0).status, SceneStatus::measured) << document;
  }
}

// --- tracers that fail -------------------------------------------------------------------------

TEST_F(RunCli, CrashIsRecordedForItsSceneAndTheOtherSceneIsMeasured) {
  commit(sources_.crashing, "abort on spheres");
  const CliRun r = run("HEAD", dir_.path() / "r.json");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  EXPECT_TRUE(d.complete);
  expect_measured(scene(d, "tetra"));
  const SceneResult& balls = scene(d, "balls");
  EXPECT_EQ(balls.status, SceneStatus::failed);
  ASSERT_TRUE(balls.runs.failed());
  EXPECT_EQ(balls.runs.failed_role, Role::tracer);
  EXPECT_TRUE(has(balls.runs.failed_run->outcome, "killed by signal 6 (ABRT)"))
      << balls.runs.failed_run->outcome;
  EXPECT_TRUE(fs::exists(balls.runs.failed_run->log));
  EXPECT_TRUE(balls.runs.rounds.empty());  // it crashed in its warm-up
  EXPECT_TRUE(has(r.out, "ABRT")) << r.out;
  EXPECT_TRUE(has(r.out, balls.runs.failed_run->log.string())) << r.out;
}

TEST_F(RunCli, TracerThatWritesNoImageFailsEveryScene) {
  commit(sources_.imageless, "forget the image");
  const CliRun r = run("HEAD", dir_.path() / "r.json");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  ASSERT_EQ(d.scenes.size(), 2u);
  for (const SceneResult& s : d.scenes) {
    EXPECT_EQ(s.status, SceneStatus::failed) << s.entry.id;
    ASSERT_TRUE(s.runs.failed()) << s.entry.id;
    EXPECT_EQ(s.runs.failed_run->outcome, "exited with status 0");
    EXPECT_TRUE(has(s.runs.failed_run->failure, "wrote no image")) << s.runs.failed_run->failure;
    EXPECT_TRUE(s.images.empty());
  }
  EXPECT_TRUE(has(r.out, "wrote no image")) << r.out;
}

// The tracer exited 0 but wrote no image: its failure (exit 1), not raygate's (3).
TEST_F(RunCli, UnreadableImageFailsEvenWithoutGoldens) {
  commit(sources_.garbling, "write text, not an image");
  const CliRun r = run("HEAD", dir_.path() / "r.json", quick());
  EXPECT_EQ(r.exit_code, 1) << r.out;
  // Named: a reference through .at() into read_results(...)'s temporary would dangle (ASan).
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  const ImageCheck& check = d.scenes.at(0).images.at(0);
  EXPECT_EQ(check.verdict, ImageVerdict::fail);
  EXPECT_TRUE(has(check.error, "cannot read image")) << check.error;
  EXPECT_TRUE(has(r.out, "cannot read image")) << r.out;
}

TEST_F(RunCli, HangIsStoppedAtTheAdaptersRunTimeout) {
  commit(sources_.hanging, "sleep before rendering");
  Options options;
  options.adapter = short_timeout_adapter().string();
  options.scenes = {"balls"};
  const CliRun r = run("HEAD", dir_.path() / "r.json", options);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  ASSERT_EQ(d.scenes.size(), 1u);
  const SceneRuns& runs = d.scenes[0].runs;
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  EXPECT_TRUE(has(runs.failed_run->outcome, "timed out after 1")) << runs.failed_run->outcome;
  EXPECT_LT(runs.failed_run->wall_seconds, 5.0);  // SIGTERM at 1 s ended the sleep
  EXPECT_TRUE(has(r.out, "timed out")) << r.out;
}

// The adapter allows a run 600 s; the user's --max-seconds 2 bounds the tracer's run too, as it
// does the baseline's (issue 25, class 10).
TEST_F(RunCli, HangIsStoppedAtTheUsersBudget) {
  commit(sources_.hanging, "sleep before rendering");
  Options options;
  options.scenes = {"balls"};
  options.extra = {"--max-seconds", "2"};
  const auto started = std::chrono::steady_clock::now();
  const CliRun r = run("HEAD", dir_.path() / "r.json", options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_LT(seconds, 30.0) << r.out;  // the build of the fixture tracer included
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  ASSERT_EQ(d.scenes.size(), 1u);
  ASSERT_TRUE(d.scenes[0].runs.failed());
  EXPECT_EQ(d.scenes[0].runs.failed_role, Role::tracer);
  EXPECT_TRUE(has(d.scenes[0].runs.failed_run->outcome, "timed out after 2"))
      << d.scenes[0].runs.failed_run->outcome;
  EXPECT_TRUE(has(r.out, "timed out")) << r.out;
}

// --- usage errors ------------------------------------------------------------------------------

TEST_F(RunCli, UnknownRevisionIsAUsageError) {
  commit(sources_.fast, "tracer");
  const CliRun r = run("no-such-branch", dir_.path() / "r.json");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_TRUE(has(r.out, "no-such-branch")) << r.out;
  EXPECT_FALSE(fs::exists(dir_.path() / "r.json"));
}

TEST_F(RunCli, BrokenAdapterIsAUsageErrorNamingTheField) {
  commit(sources_.fast, "tracer");
  json adapter = json::parse(read_file(kSource / "adapters" / "make-nff.json"));
  adapter["run"][1] = "{scen}";
  write_file_atomically(dir_.path() / "typo.json", adapter.dump(2));
  Options options;
  options.adapter = (dir_.path() / "typo.json").string();
  const CliRun typo = run("HEAD", dir_.path() / "r.json", options);
  EXPECT_EQ(typo.exit_code, 2) << typo.out;
  EXPECT_TRUE(has(typo.out, "$.run[1]")) << typo.out;
  EXPECT_TRUE(has(typo.out, "did you mean '{scene}'")) << typo.out;

  write_file_atomically(dir_.path() / "cut.json", "{\"name\": \"make-nff\",");
  options.adapter = (dir_.path() / "cut.json").string();
  const CliRun cut = run("HEAD", dir_.path() / "r.json", options);
  EXPECT_EQ(cut.exit_code, 2) << cut.out;
  EXPECT_TRUE(has(cut.out, "cut.json")) << cut.out;
  EXPECT_FALSE(fs::exists(cache_ / "builds")) << "nothing is built with a broken adapter";
}

// --- goldens -----------------------------------------------------------------------------------

// The shipped goldens are the ci suite's: balls at size 4, tetra at size 6. This suite renders
// the same ids at other sizes, so those goldens are not pictures of these scenes.
TEST_F(RunCli, GoldensOfOtherSceneSettingsAreNotCompared) {
  commit(sources_.fast, "tracer");
  Options options;
  options.golden_dir = (kSource / "golden" / "raygate-baseline").string();
  options.max_rounds = "1";
  options.warmup = "0";
  const CliRun r = run("HEAD", dir_.path() / "r.json", options);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  for (const SceneResult& s : d.scenes) {
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].verdict, ImageVerdict::missing) << s.entry.id;
    EXPECT_TRUE(has(s.images[0].error, "size")) << s.images[0].error;
  }
}

// Goldens blessed for this very suite are compared with the tracer's PPMs: the fixture tracer
// renders tetra (diffuse only) exactly as the baseline does, but has no reflections, so balls
// fails, with evidence, and the run exits 1.
TEST_F(RunCli, ImageUnlikeTheGoldenOfTheSameSettingsFailsTheRun) {
  commit(sources_.fast, "tracer");
  const CliRun bless = run_raygate({"golden", "bless", "--suite", suite_.string(), "--golden-dir",
                                    "tiny-goldens", "--work-dir", "bless-work"},
                                   dir_);
  ASSERT_EQ(bless.exit_code, 0) << bless.out;
  Options options = quick();
  options.scenes = {"tetra", "balls"};
  options.golden_dir = (dir_.path() / "tiny-goldens").string();
  const CliRun r = run("HEAD", dir_.path() / "r.json", options);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const ResultsDocument d = read_results(dir_.path() / "r.json");
  const ImageCheck& tetra = scene(d, "tetra").images.at(0);
  EXPECT_EQ(tetra.verdict, ImageVerdict::pass) << tetra.error;
  ASSERT_TRUE(tetra.metrics);
  EXPECT_TRUE(tetra.metrics->identical());
  const ImageCheck& balls = scene(d, "balls").images.at(0);
  EXPECT_EQ(balls.verdict, ImageVerdict::fail) << balls.error;
  ASSERT_TRUE(balls.metrics);
  EXPECT_EQ(balls.metrics->width, 128);
  EXPECT_FALSE(balls.metrics->size_mismatch);
  ASSERT_EQ(balls.evidence.size(), 3u);
  EXPECT_TRUE(fs::exists(balls.evidence[2])) << balls.evidence[2];
}

}  // namespace
}  // namespace raygate::test
