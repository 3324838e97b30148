// `raygate golden verify | bless` as library calls, from the options as a front end gives them:
// the baseline's goldens (pipeline/golden_images.h renders and compares them), or with
// `from_run` a tracer's images from a run it already made. Each scene's line goes through the
// ProgressSink; verify returns its closing line and exit code instead of printing them.
#pragma once

#include <string>
#include <vector>

#include "core/exit_codes.h"
#include "pipeline/golden_images.h"
#include "pipeline/pipeline_io.h"

namespace raygate {

struct GoldenOptions {
  std::string suite;                // "": ci; with from_run, the suite the document was measured on
  std::vector<std::string> scenes;  // suite scene ids; empty: all
  std::string golden_dir;  // default: <data root>/golden/raygate-baseline (from_run: /<adapter>)
  std::string work_dir = ".raygate/golden";  // scenes, renders and evidence
  std::string baseline;                      // "": the raygate-baseline beside raygate
  std::string from_run;  // a results document whose images are verified or blessed
  std::string role;      // with from_run: whose images (tracer, head, base; "" is tracer)
};

struct GoldenOutcome {
  std::string summary;  // "13 scenes: 13 identical, 0 different, 0 missing"
  ExitCode exit_code = ExitCode::pass;
};

// What blessing or verifying from a run asks for; UsageError for a role that is not a revision
// of a run (tracer, base or head).
BlessFromRun from_run_request(const GoldenOptions& options);

// The closing line and exit code of a verification: 1 when a scene differs, 2 when one has no
// golden (a differing scene outranks it for a run's images; a missing one for the baseline's,
// whose goldens are all expected to exist).
GoldenOutcome baseline_verification_outcome(const GoldenVerification& v, std::size_t scenes);
GoldenOutcome run_verification_outcome(const GoldenVerification& v);

// verify: the baseline's goldens rendered again, or with from_run the run's images against its
// adapter's goldens (evidence under work_dir/evidence).
GoldenOutcome verify_goldens(const GoldenOptions& options, ProgressSink& lines);

// bless: the baseline's goldens rendered and swapped in, or with from_run the run's images.
void bless_goldens(const GoldenOptions& options, ProgressSink& lines);

}  // namespace raygate
