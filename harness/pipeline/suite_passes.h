// The parts of measure_suite() (pipeline/suite_measurement.h) its passes share, and the passes
// after the first: the second, over the scenes a whole-measurement budget left undecided, and
// the third, ratio rounds for the scenes whose stored ratio is not yet precise
// (pipeline/stored_ratio.h). Internal to the pipeline; commands call measure_suite().
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/document_output.h"
#include "pipeline/measurement_plan.h"
#include "pipeline/pipeline_io.h"
#include "pipeline/suite_measurement.h"
#include "results/results.h"
#include "runner/executor.h"

namespace raygate::suite_pass {

// Each tracer role's normalized ratio over the rounds the baseline joined.
void summarize_ratios(SceneResult& scene, const SuiteMeasurement& m);

// The suite scores over the scenes so far (the same computation `raygate merge` makes).
void update_scores(ResultsDocument& document, const SuiteMeasurement& m);

// The results document at m.out, or in the run folder when m.out cannot be written: a full
// disk under -o must not end the measurement (pipeline/document_output.h).
KeptDocument keep(const ResultsDocument& document, const SuiteMeasurement& m);

// <work_dir>/scenes/<scene id>: the scene's run directories.
std::filesystem::path scene_dir(const SuiteMeasurement& m, const SuiteScene& entry);

// The second pass (MeasurementPlan::revisits): while time is left, the undecided scene cheapest
// to decide gets what it is estimated to need, is judged again over all its rounds, and goes
// back among the undecided if it is still one. One line per visit ("[second pass 1, 3 scenes
// undecided]").
void revisit_scenes(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                    Executor& executor, PipelineIo& io);

// The third pass: each scene the plan says wants ratio rounds gets them, in the suite's order,
// with what its stop rule allows; one line per scene ("[ratio 1/4] balls ...").
void add_ratio_rounds(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                      Executor& executor, PipelineIo& io);

}  // namespace raygate::suite_pass
