// Every document raygate writes, it can read back (issue 40): for EVERY registered timing mode,
// a run and a compare document as the pipeline fills them (the mode's clock names and unit in
// the settings, every run's measure read by the mode, its counters recorded) are written, read
// back equal, and accepted by `raygate report`, `gate` and `import` as a user runs them. The
// modes are taken from the registry, so a mode added later is covered without a line here.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <string>

#include "../../cli/cli_support.h"
#include "results/results.h"
#include "results_fixture.h"
#include "runner/timing/timing_modes.h"

namespace raygate::test {
namespace {

// A run as the mode leaves it: the numbers every mode may read (process times, a reported
// time, cachegrind's counts under cachegrind), the mode's counters, and its measure.
void time_run(RunRecord& run, const TimingMode& mode) {
  if (mode.under_cachegrind()) {
    run.simulated = SimulatedCounters{};
    run.simulated->ir = static_cast<std::uint64_t>(1e9 * run.user_seconds) + 1;
    run.simulated->dr = run.simulated->ir / 3;
    run.simulated->processes = 1;
  }
  run.reported_seconds = run.user_seconds * 0.8;
  for (const CounterSpec& counter : mode.counters()) {
    run.counters[std::string(counter.name)] = {0.125, std::string(counter.unit)};
  }
  const std::optional<double> measure = mode.seconds(run);
  ASSERT_TRUE(measure) << mode.name() << " reads nothing from a filled run";
  run.seconds = *measure;
}

ResultsDocument document_of(const TimingMode& mode, DocumentKind kind, int seed) {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.kind = kind;
  spec.with_change = kind == DocumentKind::compare;
  if (kind == DocumentKind::compare) spec.roles = {Role::base, Role::head};
  spec.scenes = {{.id = "balls", .ratio = 0.5}, {.id = "gears", .ratio = 0.8}};
  ResultsDocument document = make_document(spec);
  document.baseline.timing = std::string(mode.baseline_clock());
  document.settings.metric = std::string(mode.name());
  document.settings.timing_source = mode.source();
  document.settings.tracer_clock = std::string(mode.tracer_clock());
  document.settings.baseline_clock = std::string(mode.baseline_clock());
  document.settings.unit = std::string(mode.unit());
  for (SceneResult& scene : document.scenes) {
    for (Round& round : scene.runs.rounds) {
      for (auto& [role, run] : round.runs) time_run(run, mode);
    }
  }
  return document;
}

TEST(EveryTimingMode, ItsDocumentsRoundTripThroughEveryReader) {
  const TempDir dir("raygate-every-mode");
  int seed = 0;
  for (const TimingMode* mode : timing_modes()) {
    for (const DocumentKind kind : {DocumentKind::run, DocumentKind::compare}) {
      const ResultsDocument written = document_of(*mode, kind, ++seed);
      const std::string file = fmt::format("{}-{}.json", mode->name(), to_string(kind));
      SCOPED_TRACE(file);
      write_results(written, dir.path() / file);
      const ResultsDocument read = read_results(dir.path() / file);
      EXPECT_EQ(to_json(read), to_json(written));
      EXPECT_EQ(read.settings.measure_unit(), mode->unit());

      const CliRun report = run_raygate({"report", file}, dir);
      EXPECT_EQ(report.exit_code, 0) << report.out;
      EXPECT_NE(report.out.find(fmt::format("(measures in {})", mode->unit())), std::string::npos)
          << report.out;
      for (const CounterSpec& counter : mode->counters()) {
        EXPECT_NE(report.out.find(std::string(counter.name) + " (median per run)"),
                  std::string::npos)
            << report.out;
      }
      const CliRun gate = run_raygate({"gate", file}, dir);
      EXPECT_TRUE(gate.exit_code == 0 || gate.exit_code == 1) << gate.out;
      const CliRun import = run_raygate({"import", "--store", "store.db", file}, dir);
      EXPECT_EQ(import.exit_code, 0) << import.out;
    }
  }
  EXPECT_GE(seed, 10);  // five modes at least, each as a run and a compare
}

}  // namespace
}  // namespace raygate::test
