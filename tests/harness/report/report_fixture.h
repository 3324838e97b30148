// Hand-made results documents for the reporter tests: a run of two scenes, and a compare with
// one of each kind of scene (a speed regression, an image failure, a scene that could not be
// measured, a pass), with real PNG images and evidence written into a temporary folder.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/fs.h"
#include "gate/policy.h"
#include "gate/verdict.h"
#include "report/reporter.h"
#include "results/results.h"

namespace raygate::test {

// The head commit's subject: characters every format must escape.
inline const std::string kNastySubject = R"(Use <fast> BVH & "SAH" split)";

ResultsDocument make_run_document(const std::filesystem::path& dir);
// Scenes in document order: balls (pass), mount (+7.9% regression), gears (head's image
// differs from golden and base), tetra (the baseline crashed: not measured).
ResultsDocument make_compare_document(const std::filesystem::path& dir);

// A document, its gate verdict under the default policy, and the ReportInput over them.
struct Fixture {
  TempDir dir{"raygate-report-test"};
  ResultsDocument document;
  GatePolicy policy;
  GateResult gate;
  std::unique_ptr<ReportInput> input;

  explicit Fixture(bool compare);
  std::string render(std::string_view format, const ReportOptions& options = {}) const;
};

// A trend of `n` commits for `scene`, ratio drifting up at the end.
TrendSeries make_trend(const std::string& scene, int n);

}  // namespace raygate::test
