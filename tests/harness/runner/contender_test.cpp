// Contenders without running anything: TracerContender fills the adapter's placeholders into a
// ProcessSpec and judges a hand-made ProcessResult (image, timing source and metric, exit);
// BaselineContender is timed by the clock it is given and reads its --stats file, and a missing
// or garbled one is a failed run.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>

#include "core/fs.h"
#include "runner/baseline_contender.h"
#include "runner/timing/timing_modes.h"
#include "runner/tracer_contender.h"
#include "timing/instruction_mode.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

ProcessResult exited_with(int code, double wall, double user = 0.0, double system = 0.0) {
  ProcessResult result;
  result.outcome = ProcessOutcome::exited;
  result.exit_code = code;
  result.wall_seconds = wall;
  result.user_seconds = user;
  result.system_seconds = system;
  result.max_rss_kib = 4096;
  return result;
}

// An adapter that uses every run placeholder somewhere: argv, stdin, cwd and env.
constexpr const char* kEveryPlaceholder = R"({
  "name": "fancy",
  "scene_format": "nff",
  "run": ["{build}/bin/rt", "{scene}", "--out={image}", "--threads", "{threads}",
          "--name", "{scene_stem}", "--assets", "{repo_root}/assets", "--src", "{src}",
          "--size", "{width}x{height}"],
  "stdin": "{scene}",
  "cwd": "{build}",
  "image": "{image}",
  "env": {"OMP_NUM_THREADS": "{threads}", "RT_TMP": "{workdir}/tmp"},
  "threads": 3,
  "timeout_s": {"run": 42}
})";

constexpr const char* kWorkdirImage = R"({
  "name": "fixed-name",
  "scene_format": "nff",
  "run": ["{build}/rt", "{scene}"],
  "image": "{workdir}/trace.ppm"
})";

constexpr const char* kCpuTimed = R"({
  "name": "cpu-timed",
  "scene_format": "nff",
  "run": ["{build}/rt", "{scene}", "{image}"],
  "image": "{image}",
  "timing": {"source": "process", "metric": "cpu"}
})";

constexpr const char* kReported = R"({
  "name": "talker",
  "scene_format": "nff",
  "run": ["{build}/rt", "{scene}", "{image}"],
  "image": "{image}",
  "timing": {"source": "reported", "regex": "render time: ([0-9.]+) ms", "unit": "ms"}
})";

class ContenderTest : public ::testing::Test {
 protected:
  ContenderTest() {
    scene_.entry = SuiteScene{"balls", "balls", 1, 32, 24};
    scene_.nff = dir_.path() / "scenes" / "balls-s1.nff";
    scene_.files[SceneFormat::nff] = scene_.nff;
    run_dir_ = dir_.path() / "run";
    fs::create_directories(run_dir_);
  }

  TracerContender tracer(const char* adapter_json, const char* timing = nullptr) const {
    TracerSetup setup;
    setup.adapter = parse_adapter(adapter_json, "test-adapter.json");
    setup.build.build_dir = dir_.path() / "build";
    setup.build.src_dir = dir_.path() / "tree" / "src";
    setup.repo_root = dir_.path() / "tree";
    if (timing != nullptr) setup.timing = &timing_mode(timing);
    return TracerContender(setup);
  }

  // command(), then the image (if any) and output the "process" left, then interpret().
  RunRecord run(const TracerContender& contender, const ProcessResult& result,
                const std::string& image_bytes, const std::string& output = "") const {
    const ProcessSpec spec = contender.command(scene_, run_dir_);
    write_file_atomically(spec.stdout_path, output);
    const fs::path image = contender.setup().adapter.image == "{image}"
                               ? run_dir_ / "work" / "image.png"
                               : run_dir_ / "work" / "trace.ppm";
    if (image_bytes != "<none>") write_file_atomically(image, image_bytes);
    return contender.interpret(scene_, result, spec, run_dir_);
  }

  TempDir dir_;
  SceneInput scene_;
  fs::path run_dir_;
};

std::string contains(const std::string& text, const std::string& part) {
  return text.find(part) == std::string::npos ? "'" + part + "' not in: " + text : "";
}

// --- command -----------------------------------------------------------------------------------

TEST_F(ContenderTest, TracerArgvGetsEveryPlaceholderFilledIn) {
  const ProcessSpec spec = tracer(kEveryPlaceholder).command(scene_, run_dir_);
  const std::string root = dir_.path().string();
  const std::vector<std::string> expected{root + "/build/bin/rt",
                                          scene_.nff.string(),
                                          "--out=" + root + "/run/work/image.png",
                                          "--threads",
                                          "3",
                                          "--name",
                                          "balls-s1",
                                          "--assets",
                                          root + "/tree/assets",
                                          "--src",
                                          root + "/tree/src",
                                          "--size",
                                          "32x24"};
  EXPECT_EQ(spec.argv, expected);
}

TEST_F(ContenderTest, TracerStdinCwdEnvAndTimeoutComeFromTheAdapter) {
  const ProcessSpec spec = tracer(kEveryPlaceholder).command(scene_, run_dir_);
  EXPECT_EQ(spec.stdin_path, scene_.nff);
  EXPECT_EQ(spec.working_directory, dir_.path() / "build");
  EXPECT_EQ(spec.environment.at("OMP_NUM_THREADS"), "3");
  EXPECT_EQ(spec.environment.at("RT_TMP"), (run_dir_ / "work" / "tmp").string());
  EXPECT_EQ(spec.timeout, std::chrono::milliseconds(42000));
  EXPECT_EQ(spec.stdout_path, run_dir_ / "log.txt");
  EXPECT_EQ(spec.stderr_path, spec.stdout_path);
  EXPECT_TRUE(spec.cpu_affinity.empty());
}

TEST_F(ContenderTest, TracerRunsInAFreshWorkdirByDefault) {
  const ProcessSpec spec = tracer(kWorkdirImage).command(scene_, run_dir_);
  EXPECT_EQ(spec.working_directory, run_dir_ / "work");
  EXPECT_TRUE(fs::is_directory(run_dir_ / "work"));
  EXPECT_TRUE(spec.stdin_path.empty());
}

TEST_F(ContenderTest, TracerIsPinnedToTheCpusOfItsSetup) {
  TracerSetup setup = tracer(kWorkdirImage).setup();
  setup.cpus = {1, 2};
  EXPECT_EQ(TracerContender(setup).command(scene_, run_dir_).cpu_affinity,
            (std::vector<int>{1, 2}));
}

// --- interpret: images and exits ---------------------------------------------------------------

TEST_F(ContenderTest, OneThreadTracerIsTimedByCpuSecondsAndWallIsKept) {
  // No "metric" in the adapter: "auto", CPU time for one thread.
  const RunRecord r = run(tracer(kWorkdirImage), exited_with(0, 2.5, 1.5, 0.5), "P6 ...");
  EXPECT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 2.0);
  EXPECT_DOUBLE_EQ(r.wall_seconds, 2.5);
  EXPECT_DOUBLE_EQ(r.cpu_seconds(), 2.0);
  EXPECT_EQ(r.max_rss_kib, 4096);
  EXPECT_EQ(r.image, run_dir_ / "work" / "trace.ppm");
  EXPECT_EQ(r.log, run_dir_ / "log.txt");
  EXPECT_FALSE(r.reported_seconds);
  EXPECT_EQ(r.outcome, "exited with status 0");
}

TEST_F(ContenderTest, MissingImageIsAFailure) {
  const RunRecord r = run(tracer(kWorkdirImage), exited_with(0, 1.0), "<none>");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(contains(r.failure,
                     "fixed-name wrote no image at " + (run_dir_ / "work" / "trace.ppm").string()),
            "");
}

TEST_F(ContenderTest, EmptyImageIsAFailure) {
  const RunRecord r = run(tracer(kEveryPlaceholder), exited_with(0, 1.0), "");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(contains(r.failure, "wrote an empty image"), "");
}

TEST_F(ContenderTest, AnImageLinkedOutOfTheRunFolderIsAFailureOneInsideIsRead) {
  const fs::path image = run_dir_ / "work" / "trace.ppm";
  const fs::path earlier = dir_.path() / "earlier.ppm";
  write_file_atomically(earlier, "P6 ...");
  const TracerContender fixed = tracer(kWorkdirImage);
  const ProcessSpec spec = fixed.command(scene_, run_dir_);
  write_file_atomically(spec.stdout_path, "");
  fs::create_symlink(earlier, image);
  const RunRecord out = fixed.interpret(scene_, exited_with(0, 1.0), spec, run_dir_);
  EXPECT_FALSE(out.ok);
  EXPECT_EQ(contains(out.failure, "left its image as a symbolic link to " + earlier.string()), "");
  fs::remove(image);
  write_file_atomically(run_dir_ / "work" / "real.ppm", "P6 ...");
  fs::create_symlink("real.ppm", image);
  EXPECT_TRUE(fixed.interpret(scene_, exited_with(0, 1.0), spec, run_dir_).ok);
}

TEST_F(ContenderTest, NonZeroExitIsAFailureEvenWithAnImage) {
  const RunRecord r = run(tracer(kWorkdirImage), exited_with(3, 1.0), "P6 ...");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.outcome, "exited with status 3");
  EXPECT_EQ(contains(r.failure, "exited with status 3"), "");
  EXPECT_EQ(r.image, run_dir_ / "work" / "trace.ppm");  // recorded, for the log reader
}

TEST_F(ContenderTest, CrashIsAFailureNamingTheSignal) {
  ProcessResult crash;
  crash.outcome = ProcessOutcome::signaled;
  crash.signal = SIGABRT;
  const RunRecord r = run(tracer(kWorkdirImage), crash, "P6 ...");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(contains(r.failure, "killed by signal 6 (ABRT)"), "");
}

// --- interpret: timing -------------------------------------------------------------------------

TEST_F(ContenderTest, CpuMetricTimesByUserPlusSystemSeconds) {
  const RunRecord r = run(tracer(kCpuTimed), exited_with(0, 3.0, 1.25, 0.5), "png");
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 1.75);
  EXPECT_DOUBLE_EQ(r.wall_seconds, 3.0);
}

TEST_F(ContenderTest, MetricOverrideBeatsTheAdaptersMetric) {
  const ProcessResult result = exited_with(0, 3.0, 1.25, 0.5);
  EXPECT_DOUBLE_EQ(run(tracer(kCpuTimed, "wall"), result, "png").seconds, 3.0);
  EXPECT_DOUBLE_EQ(run(tracer(kWorkdirImage, "cpu"), result, "ppm").seconds, 1.75);
}

// --timing user (runner/timing/process_user.cpp): user CPU seconds, system time left out.
TEST_F(ContenderTest, UserModeTimesByUserSecondsOnly) {
  const RunRecord r = run(tracer(kCpuTimed, "user"), exited_with(0, 3.0, 1.25, 0.5), "png");
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 1.25);
  EXPECT_DOUBLE_EQ(r.cpu_seconds(), 1.75);
}

TEST_F(ContenderTest, ReportedTimeIsTheLastMatchOfTheRegex) {
  const std::string output = "loading\nrender time: 900 ms\nrender time: 1250 ms\ndone\n";
  const RunRecord r = run(tracer(kReported), exited_with(0, 2.0, 1.9, 0.1), "png", output);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 1.25);
  ASSERT_TRUE(r.reported_seconds);
  EXPECT_DOUBLE_EQ(*r.reported_seconds, 1.25);
  EXPECT_DOUBLE_EQ(r.wall_seconds, 2.0);
}

TEST_F(ContenderTest, ReportedTimingWithoutAMatchIsAFailure) {
  const RunRecord r = run(tracer(kReported), exited_with(0, 2.0), "png", "finished in 3 s\n");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(contains(r.failure, "printed no positive time matching timing.regex"), "");
  EXPECT_EQ(contains(r.failure, "render time: ([0-9.]+) ms"), "");
}

TEST_F(ContenderTest, ReportedZeroIsAFailure) {
  const RunRecord r = run(tracer(kReported), exited_with(0, 2.0), "png", "render time: 0 ms\n");
  EXPECT_FALSE(r.ok);
}

// Sweep 12: `RTIME: 1e308` from a 0.03 s process was taken, and written into documents raygate's
// readers refuse. A time longer than the process ran is a failed run, saying why.
TEST_F(ContenderTest, AReportedTimeLongerThanTheProcessRanIsAFailure) {
  const RunRecord huge =
      run(tracer(kReported), exited_with(0, 2.0), "png", "render time: 100000000 ms\n");
  EXPECT_FALSE(huge.ok);
  EXPECT_EQ(contains(huge.failure,
                     "printed a time of 100000 s, longer than its process ran "
                     "(2.000 s of wall time)"),
            "");
  // Within the clocks' slack it stands: a tracer's clock and wait4's are read apart.
  EXPECT_TRUE(run(tracer(kReported), exited_with(0, 2.0), "png", "render time: 2050 ms\n").ok);
  EXPECT_FALSE(run(tracer(kReported), exited_with(0, 2.0), "png", "render time: 2200 ms\n").ok);
}

TEST_F(ContenderTest, AReportedTimeBelowAMicrosecondIsAFailureNotAZeroScore) {
  const RunRecord tiny =
      run(tracer(kReported), exited_with(0, 2.0), "png", "render time: 0.0000001 ms\n");
  EXPECT_FALSE(tiny.ok);
  EXPECT_EQ(contains(tiny.failure, "printed a time of 1e-10 s, less than a microsecond"), "");
  EXPECT_TRUE(run(tracer(kReported), exited_with(0, 2.0), "png", "render time: 0.002 ms\n").ok);
}

TEST_F(ContenderTest, ThreadsBeyondTheMachinesCpusAddNoTimeToTheBound) {
  std::string many_threads = kReported;
  many_threads.insert(many_threads.find("\"timing\""), "\"threads\": 4096,\n  ");
  // 4096 threads would allow 8,600 s from a 2 s process; no runner here has 2,000 CPUs.
  EXPECT_FALSE(
      run(tracer(many_threads.c_str()), exited_with(0, 2.0), "png", "render time: 4000000 ms\n")
          .ok);
}

// --- the baseline ------------------------------------------------------------------------------

class BaselineContenderTest : public ContenderTest {
 protected:
  RunRecord interpret(const ProcessResult& result, const std::string* stats) const {
    const ProcessSpec spec = baseline_.command(scene_, run_dir_);
    if (stats != nullptr) write_file_atomically(run_dir_ / "stats.json", *stats);
    return baseline_.interpret(scene_, result, spec, run_dir_);
  }

  BaselineContender baseline_{"/opt/raygate-baseline", "corners", std::chrono::seconds(9), "bbox"};
};

TEST_F(BaselineContenderTest, CommandRendersPpmIntoTheRunDirectory) {
  const ProcessSpec spec = baseline_.command(scene_, run_dir_);
  const std::vector<std::string> expected{"/opt/raygate-baseline",
                                          scene_.nff.string(),
                                          "-o",
                                          (run_dir_ / "image.ppm").string(),
                                          "--accel",
                                          "bbox",
                                          "--sampling",
                                          "corners",
                                          "--stats",
                                          (run_dir_ / "stats.json").string()};
  EXPECT_EQ(spec.argv, expected);
  EXPECT_EQ(spec.working_directory, run_dir_);
  EXPECT_EQ(spec.timeout, std::chrono::milliseconds(9000));
  EXPECT_EQ(baseline_.role(), Role::baseline);
}

// By default the baseline is timed like a process-timed tracer: by its process wall seconds.
// Its in-process seconds stay in the record.
TEST_F(BaselineContenderTest, TimedByProcessWallByDefaultKeepingInProcessSeconds) {
  const std::string stats =
      R"({"parse_seconds": 0.25, "prepare_seconds": 0.125, "render_seconds": 1.5, "rays": 7})";
  EXPECT_EQ(baseline_.clock().name(), "wall");
  const RunRecord r = interpret(exited_with(0, 2.0, 1.9, 0.05), &stats);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 2.0);
  ASSERT_TRUE(r.reported_seconds);
  EXPECT_DOUBLE_EQ(*r.reported_seconds, 1.875);
  EXPECT_DOUBLE_EQ(r.wall_seconds, 2.0);
  EXPECT_EQ(r.image, run_dir_ / "image.ppm");
}

TEST_F(BaselineContenderTest, ARunTheBudgetCutSaysSoAndStatisticsWithoutTimesArePlainWords) {
  ProcessResult cut = exited_with(0, 1.0);
  cut.outcome = ProcessOutcome::timed_out;
  const RunRecord r = interpret(cut, nullptr);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.stopped_by_budget);
  EXPECT_EQ(contains(r.failure, "the time budget's cut, not raygate-baseline's 30-minute limit"),
            "");
  const std::string no_times = R"({"rays": 7})";
  const RunRecord unusable = interpret(exited_with(0, 2.0), &no_times);
  EXPECT_FALSE(unusable.ok);
  EXPECT_EQ(contains(unusable.failure, "key 'parse_seconds' not found"), "");
  EXPECT_EQ(unusable.failure.find("json.exception"), std::string::npos) << unusable.failure;
}

TEST_F(BaselineContenderTest, ProcessCpuClockTimesByUserPlusSystemSeconds) {
  const std::string stats = R"({"parse_seconds": 0.25, "prepare_seconds": 0.125,
                                "render_seconds": 1.5, "cpu_seconds": 1.25})";
  baseline_ = BaselineContender{"/opt/raygate-baseline", "center", std::chrono::seconds(9), "none",
                                &timing_mode("cpu")};
  const RunRecord r = interpret(exited_with(0, 2.0, 1.5, 0.25), &stats);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 1.75);
  EXPECT_DOUBLE_EQ(*r.reported_seconds, 1.875);
}

TEST_F(BaselineContenderTest, InProcessClockTimesByParsePreparePlusRenderSeconds) {
  const std::string stats =
      R"({"parse_seconds": 0.25, "prepare_seconds": 0.125, "render_seconds": 1.5})";
  baseline_ = BaselineContender{"/opt/raygate-baseline", "center", std::chrono::seconds(9), "none",
                                &timing_mode("reported")};
  const RunRecord r = interpret(exited_with(0, 2.0, 1.9, 0.05), &stats);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 1.875);
  // The process's seconds are kept too: its start-up, what the in-process time leaves out.
  ASSERT_EQ(r.counters.count("startup_seconds"), 1u);
  EXPECT_DOUBLE_EQ(r.counters.at("startup_seconds").value, 0.125);
}

// A mode raygate does not ship (a perf-stat instruction counter: it wraps the process and reads
// what perf left, exact): the baseline asks it as the tracer does, knowing nothing of it.
TEST_F(BaselineContenderTest, AnyModeWrapsAndCollectsTheBaselineAsItDoesTheTracer) {
  const test::InstructionMode mode;
  baseline_ =
      BaselineContender{"/opt/raygate-baseline", "center", std::chrono::seconds(9), "none", &mode};
  const ProcessSpec spec = baseline_.command(scene_, run_dir_);
  EXPECT_EQ(spec.argv.front(), "perf");
  EXPECT_EQ(spec.argv[8], "/opt/raygate-baseline");
  // Exact: no --stats, whose formatting would make the count unrepeatable.
  EXPECT_EQ(std::find(spec.argv.begin(), spec.argv.end(), "--stats"), spec.argv.end());
  write_file_atomically(run_dir_ / "perf.txt", "12345,,instructions:u,1000,100.00,,\n");
  const RunRecord r = interpret(exited_with(0, 2.0, 1.9, 0.05), nullptr);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 12345.0);
  EXPECT_FALSE(r.reported_seconds);
}

// The denominator of every ratio: a zero CPU time (a clock too coarse) is a failed run.
TEST_F(BaselineContenderTest, ZeroProcessTimeIsAFailedRun) {
  const std::string stats =
      R"({"parse_seconds": 0.25, "prepare_seconds": 0.125, "render_seconds": 1.5})";
  baseline_ = BaselineContender{"/opt/raygate-baseline", "center", std::chrono::seconds(9), "none",
                                &timing_mode("cpu")};
  const RunRecord r = interpret(exited_with(0, 2.0, 0.0, 0.0), &stats);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(contains(r.failure, "no measurable process-cpu time"), "");
}

// Each side of the ratio on the same clock as the other (DESIGN.md §11), and the names the
// results document records.
TEST(BaselineClock, MatchesTheTracersClock) {
  const auto process = [](TimingMetric metric) {
    Timing timing;
    timing.metric = metric;
    return &adapter_timing_mode(timing);
  };
  Timing reported;
  reported.source = TimingSource::reported;
  EXPECT_EQ(process(TimingMetric::wall)->baseline_clock(), "process-wall");
  EXPECT_EQ(process(TimingMetric::cpu)->baseline_clock(), "process-cpu");
  EXPECT_EQ(adapter_timing_mode(reported).baseline_clock(), "in-process");
  EXPECT_EQ(process(TimingMetric::wall)->tracer_clock(), "process-wall");
  EXPECT_EQ(process(TimingMetric::cpu)->tracer_clock(), "process-cpu");
  EXPECT_EQ(adapter_timing_mode(reported).tracer_clock(), "reported");
}

// The baseline on the user clock: its user seconds, not user + system.
TEST_F(BaselineContenderTest, UserClockTimesByUserSecondsOnly) {
  const std::string stats =
      R"({"parse_seconds": 0.25, "prepare_seconds": 0.125, "render_seconds": 1.5})";
  baseline_ = BaselineContender{"/opt/raygate-baseline", "center", std::chrono::seconds(9), "none",
                                &timing_mode("user")};
  const RunRecord r = interpret(exited_with(0, 2.0, 1.5, 0.25), &stats);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_DOUBLE_EQ(r.seconds, 1.5);
}

TEST_F(BaselineContenderTest, MissingStatsIsAFailedRunNotAnException) {
  RunRecord r;
  EXPECT_NO_THROW(r = interpret(exited_with(0, 2.0), nullptr));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(contains(r.failure, "unusable statistics " + (run_dir_ / "stats.json").string()), "");
}

TEST_F(BaselineContenderTest, GarbledStatsIsAFailedRun) {
  for (const std::string& stats : {std::string("{\"parse_seconds\": 0.1,"),
                                   std::string(R"({"parse_seconds": 0.1, "render_seconds": 1})"),
                                   std::string(R"({"parse_seconds": "x", "prepare_seconds": 0,
                                                  "render_seconds": 1})"),
                                   std::string(R"({"parse_seconds": 0, "prepare_seconds": 0,
                                                  "render_seconds": 0})")}) {
    RunRecord r;
    EXPECT_NO_THROW(r = interpret(exited_with(0, 2.0), &stats)) << stats;
    EXPECT_FALSE(r.ok) << stats;
    EXPECT_EQ(contains(r.failure, "raygate-baseline wrote unusable statistics"), "") << stats;
  }
}

TEST_F(BaselineContenderTest, FailedProcessKeepsItsOwnReason) {
  const RunRecord r = interpret(exited_with(1, 0.3), nullptr);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.failure, "/opt/raygate-baseline exited with status 1");
}

}  // namespace
}  // namespace raygate
