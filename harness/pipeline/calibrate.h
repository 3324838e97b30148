// `raygate calibrate`: sizes a suite to a tracer. Each scene of a suite is rendered by the
// tracer at its own resolution and at half each side, the fastest of `runs` renders kept; a line
// through the two (pipeline/render_time.h) gives the resolution at which a render takes about
// the target seconds, and the suite with those resolutions is written (atomically) as a suite
// file (runner/suite.h) to commit beside the adapter and pass to run and compare with --suite.
// Slow tracers then fit a CI job: the budget of a compare is rounds x scenes x render time.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "checkout/worktree.h"
#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "pipeline/render_time.h"
#include "runner/baseline_tool.h"
#include "runner/suite.h"

namespace raygate {

// The render times calibrate can size a suite for (--target-seconds), in wall seconds.
inline constexpr double kMinTargetSeconds = 0.001;
inline constexpr double kMaxTargetSeconds = 3600.0;

struct CalibrateRequest {
  const MeasureContext& context;  // the adapter, the suite and its selected scenes, the cache
  const BaselineTool& baseline;   // its source hash keys the build cache, as in run
  std::string repository;         // as the user named it, for the suite's description
  Worktree worktree;              // the tracer's revision to time
  double target_seconds = 1.0;    // wall seconds a render should take
  std::size_t runs = 1;           // renders at each of the two sizes; the fastest is kept
  int min_side = 16;              // no calibrated picture side below this
  std::string suite_name;         // the written suite's name; "" = <suite>-<adapter>
  std::filesystem::path out;      // the suite file to write
};

// Checks what can be checked before anything is built: the target, runs, smallest side, the
// name and the output path. UsageError naming the option.
void check_calibrate_request(const CalibrateRequest& request);

struct SceneCalibration {
  SuiteScene entry;     // as the suite has it
  TimedRender smaller;  // half each side
  TimedRender larger;   // the suite's resolution
  RenderTimeModel model;
  ChosenResolution chosen;
};

struct Calibration {
  std::vector<SceneCalibration> scenes;
  Suite suite;  // as written, and read back with load_suite
  std::filesystem::path path;
};

// Builds the tracer (InfraError with the log tail if it fails), times every selected scene,
// writes the calibrated suite to request.out and reads it back. A render that fails is an
// InfraError naming the scene, the resolution and the run's log. A line per scene goes to
// io.progress as it is measured (calibration_line).
Calibration calibrate_suite(const CalibrateRequest& request, PipelineIo& io);

// "balls  128x128 2.31 s, 64x64 0.66 s -> 84x84, predicted 1.00 s (fixed 0.11 s)".
std::string calibration_line(const SceneCalibration& scene, double target_seconds);

// The closing line: where the suite went, how many scenes reached the target, how to use it.
std::string calibration_summary(const Calibration& calibration, double target_seconds);

// The suite file's text: `source`'s sampling, the calibrated scenes (ids, scenes and sizes as
// they were, the chosen resolutions), `name` and `description`.
std::string calibrated_suite_text(const Suite& source, const std::string& name,
                                  const std::string& description,
                                  const std::vector<SceneCalibration>& scenes);

}  // namespace raygate
