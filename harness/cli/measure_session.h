// The measuring part shared by `raygate run` and `raygate compare`: for every selected scene,
// prepare its files, run the contenders through the scheduler, summarize the ratios, check the
// tracers' images against the goldens, and rewrite the results document (atomically) before
// moving to the next scene, so a killed job keeps every scene it finished.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cli/measure_options.h"
#include "cli/progress.h"
#include "compare/golden.h"
#include "compare/image_compare.h"
#include "gate/policy.h"
#include "runner/baseline_tool.h"
#include "runner/contender.h"
#include "runner/executor.h"
#include "runner/scheduler.h"
#include "runner/suite.h"
#include "store/results.h"

namespace raygate::cli {

struct SuiteMeasurement {
  std::vector<SuiteScene> scenes;
  std::vector<const Contender*> contenders;  // the baseline first
  std::vector<std::string> tracer_roles;     // normalized against the baseline, image-checked
  std::vector<SceneFormat> formats{SceneFormat::nff};  // scene files the contenders read
  ScheduleOptions schedule;
  std::function<StopRule(const SuiteScene&)> stop;  // the stopping rule of each scene
  GatePolicy policy;  // image thresholds per scene
  std::filesystem::path golden_dir;
  std::filesystem::path scene_cache;  // generated scene files
  std::filesystem::path work_dir;     // run directories and evidence images
  std::filesystem::path out;          // the results document
  // Extra per-scene summaries after the ratios and golden checks (compare adds its change).
  std::function<void(SceneResult&)> finish_scene;
};

// A new, empty directory <parent>/<stem>, or <stem>-2, -3, ... if that exists: two runs started
// in the same second (shards of a CI matrix on one machine) never share run files or documents.
std::filesystem::path fresh_run_dir(const std::filesystem::path& parent, const std::string& stem);

// The parts of a measurement every measuring command shares: the context's scenes, schedule,
// policy, goldens and scene cache, a fresh run directory named `run_name` under
// <cache>/runs/, and the document at `out` (or results.json in the run directory).
SuiteMeasurement suite_measurement(const MeasureContext& context, const std::string& run_name,
                                   const std::filesystem::path& out);

// A document's header: kind, versions, start time, machine, baseline, suite, settings.
ResultsDocument new_document(const std::string& kind, const MeasureContext& context,
                             const BaselineTool& baseline);

// Measures every scene into `document` (whose header the caller filled in), writing it to
// m.out after each scene and once more, complete, at the end. On SIGINT or SIGTERM it stops the
// running child, writes the scenes finished so far (complete: false) and throws Interrupted
// saying what was kept and where.
void measure_suite(ResultsDocument& document, const SuiteMeasurement& m, Executor& executor,
                   Clock& clock, Progress& progress);

// One line per scene for logs and the end-of-run table.
std::string scene_line(const SceneResult& scene, const std::vector<std::string>& tracer_roles);


}  // namespace raygate::cli
