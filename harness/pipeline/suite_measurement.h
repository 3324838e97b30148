// The measuring part shared by `raygate run` and `raygate compare`: for every selected scene,
// prepare its files, run the contenders through the scheduler, summarize the ratios, check the
// tracers' images against the goldens, and rewrite the results document (atomically) before
// moving to the next scene, so a killed job keeps every scene it finished.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "compare/golden.h"
#include "compare/image_compare.h"
#include "gate/policy.h"
#include "runner/baseline_contender.h"
#include "runner/baseline_tool.h"
#include "runner/contender.h"
#include "runner/scheduler.h"
#include "pipeline/document_output.h"
#include "pipeline/measurement_plan.h"
#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "results/results.h"
#include "runner/suite.h"

namespace raygate {

struct SuiteMeasurement {
  std::vector<SuiteScene> scenes;
  std::vector<const Contender*> contenders;  // the baseline first
  std::vector<Role> tracer_roles;            // normalized against the baseline, image-checked
  std::vector<SceneFormat> formats{SceneFormat::nff};  // scene files the contenders read
  ScheduleOptions schedule;
  GatePolicy policy;                            // image thresholds per scene
  ImageKind images = ImageKind::deterministic;  // the adapter's: how its images are judged
  std::filesystem::path golden_dir;
  std::filesystem::path scene_cache;  // generated scene files
  std::filesystem::path work_dir;     // run directories and evidence images
  std::filesystem::path out;          // the results document
  // Idle CPUs are held polling while measuring, through this PM QoS file (runner/idle_poll.h);
  // empty: left to the kernel (--no-idle-poll, sim mode, tests).
  std::filesystem::path idle_poll_device;
  // The whole measurement's budget (--max-minutes), in seconds; 0: none. Every run started is
  // bounded by it (runner/deadline_executor.h), not only the stopping rule between rounds.
  double budget_seconds = 0.0;
};

// A scene's files as the contenders read them (generated into m.scene_cache if not there).
SceneInput prepare_scene_input(const SuiteScene& entry, const SuiteMeasurement& m);

// A new, empty directory <parent>/<stem>, or <stem>-2, -3, ... if that exists: two runs started
// in the same second (shards of a CI matrix on one machine) never share run files or documents.
std::filesystem::path fresh_run_dir(const std::filesystem::path& parent, const std::string& stem);

// The parts of a measurement every measuring command shares: the context's scenes, schedule,
// policy, goldens and scene cache, a fresh run directory named `run_name` under
// <cache>/runs/, and the document at `out` (or results.json in the run directory).
SuiteMeasurement suite_measurement(const MeasureContext& context, const std::string& run_name,
                                   const std::filesystem::path& out);

// A document's header: kind, versions, start time, machine, baseline, suite, settings.
ResultsDocument new_document(DocumentKind kind, const MeasureContext& context,
                             const BaselineTool& baseline);

// Measures every scene into `document` (whose header the caller filled in) as `plan` decides,
// in up to three passes (pipeline/measurement_plan.h), writing it to
// m.out after each scene and once more, complete, at the end (to the run folder instead while
// m.out cannot be written: pipeline/document_output.h). On SIGINT, SIGTERM, SIGHUP or SIGQUIT it stops
// the running child, writes the scenes finished so far (complete: false) and throws Interrupted
// saying what was kept and where.
void measure_suite(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                   PipelineIo& io);

// A finished measurement: its document and where it was written; `unwritten` lists the final
// writes that failed (-o on a full disk), for the command to report after storing the document.
struct MeasuredDocument {
  ResultsDocument document;
  std::filesystem::path path;
  std::vector<FailedWrite> unwritten;
};

// The end run and compare share: `opening` said, measure_suite(), the plan's judgement of the
// suite (MeasurementPlan::finish_suite), the finish time stamped, the
// growth of each scene family fitted and said when the suite measured one at 3 sizes or more
// (scaling/), the complete document written to m.out.
MeasuredDocument measure_document(ResultsDocument document, const SuiteMeasurement& m,
                                  MeasurementPlan& plan, const std::string& opening,
                                  PipelineIo& io);

// The baseline as the context times it (its sampling and the clock matched to the tracer's); in
// sim mode simulated under cachegrind, its costs cached in <cache-dir>/simulated-baseline under
// the baseline's source hash.
BaselineContender baseline_contender(const MeasureContext& context,
                                     const std::string& baseline_source_sha256);

// One line per scene for logs and the end-of-run table.
std::string scene_line(const SceneResult& scene, const std::vector<Role>& tracer_roles);

}  // namespace raygate
