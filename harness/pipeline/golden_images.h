// The golden images as a stage (docs/gate.md): verify the baseline's goldens by rendering again
// and demanding identical pixels, bless the baseline's (only the scenes asked for, never as a side
// effect), and bless a foreign tracer's images from a run it already made and checked. Each says
// one line per scene through the ProgressSink; `raygate golden` prints them on standard output.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/domain.h"
#include "pipeline/pipeline_io.h"
#include "runner/baseline_tool.h"
#include "runner/suite.h"

namespace raygate {

// The baseline's goldens of a suite's scenes, and where renders and evidence go.
struct BaselineGoldens {
  Suite suite;
  std::vector<SuiteScene> selected;
  std::filesystem::path golden_dir;
  std::filesystem::path work_dir;
  BaselineTool baseline;
};

// `suite` by name or file; `scene_ids` empty: all; `golden_dir` empty: the baseline's
// golden/raygate-baseline/ under the data root; `baseline` empty: the one beside raygate.
BaselineGoldens open_baseline_goldens(const std::string& suite,
                                      const std::vector<std::string>& scene_ids,
                                      const std::filesystem::path& golden_dir,
                                      const std::filesystem::path& work_dir,
                                      const std::filesystem::path& baseline);

struct GoldenVerification {
  std::size_t identical = 0;  // identical pixels, or (Monte Carlo) the same within noise
  std::size_t different = 0;  // evidence written under work_dir/evidence
  std::size_t missing = 0;
  std::size_t inconclusive = 0;  // Monte Carlo: too noisy to tell
  // The golden cannot be trusted (its bytes are not its manifest's SHA-256, its statistics could
  // never fail) or read: nothing was verified, exit 3.
  std::size_t unverifiable = 0;
};

// Renders each selected scene that has a golden and compares pixels; a render that fails is an
// InfraError (the instrument itself broke).
GoldenVerification verify_baseline_goldens(const BaselineGoldens& goldens, ProgressSink& progress);

// Renders each selected scene and swaps in the golden set with it and the manifest (after each
// scene, so an interrupted bless keeps its work; the old set stays whole until a new one is
// complete, so a full disk never leaves a golden that its manifest's sha256 does not match). UsageError when golden_dir holds another suite's goldens or
// a tracer's.
void bless_baseline_goldens(const BaselineGoldens& goldens, ProgressSink& progress);

struct BlessFromRun {
  std::filesystem::path results;       // the run's document
  Role role = Role::tracer;            // whose images: tracer, head or base
  std::vector<std::string> scene_ids;  // empty: every scene of the document
  std::filesystem::path golden_dir;    // empty: golden/<adapter>/ under the data root
  std::filesystem::path baseline;      // only to find the data root
};

// Copies each chosen scene's image of `role` (its first successful run's, the image the run
// compared) into the golden dir with the run's provenance. Every scene is checked first (known
// id, image still there, a safe name, an image extension, the image decodes), so a bad one
// blesses nothing; then the whole new set is swapped in at once, so a failed write (a full disk)
// blesses nothing either and leaves the old set and its manifest as they were.
void bless_goldens_from_run(const BlessFromRun& request, ProgressSink& progress);

// `golden verify --from-run`: a run's images of `role` checked against its adapter's goldens
// (request.golden_dir, or the adapter's under the data root), as the run itself would check
// them: per pixel, or for a Monte Carlo adapter every run's image against the golden's
// statistics. Evidence goes to `evidence_dir`.
GoldenVerification verify_goldens_from_run(const BlessFromRun& request,
                                           const std::filesystem::path& evidence_dir,
                                           ProgressSink& progress);

}  // namespace raygate
