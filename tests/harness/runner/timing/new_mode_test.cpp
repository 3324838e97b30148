// Adding a timing mode is one file and one registration line (DESIGN.md §12), even for a mode
// that records something no run records today. instruction_mode.h is that file for a mode
// raygate does not ship (a perf-stat instruction counter); its registration is the one line
// marked below (in raygate: a line in modes.def, which a test cannot add). What this shows: its
// document is checked, read, reported in its unit, and refused by a registry without it, with
// no edit outside the mode.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "core/fs.h"
#include "instruction_mode.h"
#include "report/report_model.h"
#include "results/results.h"
#include "results/results_check.h"
#include "results_fixture.h"
#include "runner/timing/timing_check.h"
#include "runner/timing/timing_modes.h"

namespace raygate {
namespace {

const test::InstructionMode instructions;

// The registry with the new mode: the one registration line is the push_back.
TimingModeList registered() {
  TimingModeList modes = timing_modes();
  modes.push_back(&instructions);
  return modes;
}

TEST(NewTimingMode, WrapsTheProcessAndReadsItsCounter) {
  const TempDir dir("raygate-new-mode");
  ProcessSpec spec;
  spec.argv = {"tracer", "scene.nff"};
  const ProcessSpec wrapped = instructions.wrap(spec, dir.path(), std::nullopt);
  EXPECT_EQ(wrapped.argv.front(), "perf");
  EXPECT_EQ(wrapped.argv.back(), "scene.nff");
  write_file_atomically(dir.path() / "perf.txt",
                        "# started on Sat Nov 28\n\n2500000000,,instructions:u,1000,100.00,,\n");
  RunRecord run;
  run.ok = true;
  instructions.collect(run, dir.path());
  ASSERT_TRUE(run.ok) << run.failure;
  EXPECT_DOUBLE_EQ(*instructions.seconds(run), 2.5e9);
  write_file_atomically(dir.path() / "perf.txt", "<not counted>,,instructions:u,0,0.00,,\n");
  RunRecord refused;
  refused.ok = true;
  instructions.collect(refused, dir.path());
  EXPECT_FALSE(refused.ok);
}

// A document as the pipeline writes it under the new mode: settings and baseline from the
// mode, every run through its collect.
nlohmann::json document_json() {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(1);
  spec.scenes = {{.id = "balls"}, {.id = "gears"}};
  ResultsDocument document = test::make_document(spec);
  document.baseline.timing = std::string(instructions.baseline_clock());
  document.settings.tracer_clock = std::string(instructions.tracer_clock());
  document.settings.baseline_clock = std::string(instructions.baseline_clock());
  document.settings.unit = std::string(instructions.unit());
  for (SceneResult& scene : document.scenes) {
    for (Round& round : scene.runs.rounds) {
      for (auto& [role, run] : round.runs) {
        run.counters["instructions"] = {role == "baseline" ? 2.0e9 : 3.0e9, "instructions"};
        run.seconds = *instructions.seconds(run);
      }
    }
  }
  return to_json(document);
}

TEST(NewTimingMode, ItsDocumentIsCheckedByItsRegistrationAlone) {
  const nlohmann::json json = document_json();
  EXPECT_NO_THROW(check_results_json(json, registered()));
  // Without the registration line, the same document is refused, naming the path and the word.
  try {
    check_results_json(json);
    FAIL() << "accepted without the mode";
  } catch (const FieldError& e) {
    EXPECT_EQ(e.path(), "$.baseline.timing");
    EXPECT_NE(std::string(e.what()).find("unknown value \"instructions\""), std::string::npos)
        << e.what();
  }
  // The counters are checked from the registration too: a counter no mode declares, and one
  // in another unit, are refused at their path.
  nlohmann::json wrong_unit = json;
  auto& counters = wrong_unit["scenes"][0]["rounds"][0]["runs"]["baseline"]["counters"];
  counters["instructions"]["unit"] = "seconds";
  try {
    check_results_json(wrong_unit, registered());
    FAIL() << "accepted a counter in the wrong unit";
  } catch (const FieldError& e) {
    EXPECT_EQ(e.path(), "$.scenes[0].rounds[0].runs.baseline.counters.instructions.unit");
  }
  nlohmann::json unknown = json;
  unknown["scenes"][1]["rounds"][0]["runs"]["tracer"]["counters"]["cycles"] = {{"value", 1.0},
                                                                               {"unit", "cycles"}};
  try {
    check_results_json(unknown, registered());
    FAIL() << "accepted an unknown counter";
  } catch (const FieldError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown counter \"cycles\""), std::string::npos);
  }
}

TEST(NewTimingMode, ItsRunsRoundTripAndReportInItsUnit) {
  const nlohmann::json json = document_json();
  const nlohmann::json& written =
      json.at("scenes").at(0).at("rounds").at(0).at("runs").at("tracer");
  const RunRecord run = written;
  EXPECT_EQ(run.counters.at("instructions"), (Counter{3.0e9, "instructions"}));
  EXPECT_EQ(nlohmann::json(run), written);
  ResultsDocument document;
  document.settings.unit = "instructions";
  EXPECT_EQ(report::cost_text(document, 3.0e9), "3e+09 instructions");
}

}  // namespace
}  // namespace raygate
