// pipeline/golden_commands: `raygate golden` as library calls. The closing line and exit code of
// each kind of verification (a different scene fails; a missing golden is a usage problem, which
// outranks a difference only for the baseline's own set) and the role a run's images are taken
// from, without rendering anything.
#include <gtest/gtest.h>

#include "core/error.h"
#include "pipeline/golden_commands.h"
#include "pipeline/pipeline_io.h"

namespace raygate {
namespace {

// Scenes identical (or the same within noise), different, missing, too noisy to tell.
GoldenVerification counted(std::size_t identical, std::size_t different, std::size_t missing,
                           std::size_t inconclusive = 0) {
  return {identical, different, missing, inconclusive};
}

TEST(GoldenCommands, TheBaselinesVerificationSaysEveryCount) {
  const GoldenOutcome all = baseline_verification_outcome(counted(13, 0, 0), 13);
  EXPECT_EQ(all.summary, "13 scenes: 13 identical, 0 different, 0 missing");
  EXPECT_EQ(all.exit_code, ExitCode::pass);
  EXPECT_EQ(baseline_verification_outcome(counted(12, 1, 0), 13).exit_code, ExitCode::regression);
  // Every golden of the baseline's set is expected: one missing is a usage problem first.
  EXPECT_EQ(baseline_verification_outcome(counted(11, 1, 1), 13).exit_code, ExitCode::usage);
}

TEST(GoldenCommands, ARunsVerificationCountsNoiseAndPutsADifferenceFirst) {
  const GoldenOutcome noisy = run_verification_outcome(counted(2, 0, 0, 1));
  EXPECT_EQ(noisy.summary, "3 scenes: 2 same, 0 different, 1 too noisy to tell, 0 missing");
  EXPECT_EQ(noisy.exit_code, ExitCode::pass);
  EXPECT_EQ(run_verification_outcome(counted(1, 0, 2)).exit_code, ExitCode::usage);
  EXPECT_EQ(run_verification_outcome(counted(1, 1, 2)).exit_code, ExitCode::regression);
}

TEST(GoldenCommands, ARunsImagesComeFromOneOfItsRevisions) {
  GoldenOptions options;
  options.from_run = "results.json";
  options.scenes = {"balls"};
  options.golden_dir = "golden/povray";
  const BlessFromRun tracer = from_run_request(options);
  EXPECT_EQ(tracer.role, Role::tracer);
  EXPECT_TRUE(tracer.results.is_absolute());
  EXPECT_EQ(tracer.results.filename().string(), "results.json");
  EXPECT_EQ(tracer.scene_ids, std::vector<std::string>{"balls"});
  EXPECT_EQ(tracer.golden_dir.string(), "golden/povray");
  options.role = "head";
  EXPECT_EQ(from_run_request(options).role, Role::head);
  for (const char* refused : {"baseline", "HEAD"}) {
    options.role = refused;
    EXPECT_THROW(from_run_request(options), UsageError) << refused;
  }
}

// The fourth sweep: --role without --from-run was read by nobody, and a --work-dir that is the
// --golden-dir put scenes/, renders/ and evidence/ among the goldens. Both are refused before
// anything is rendered or read.
TEST(GoldenCommands, OptionsNobodyWouldReadOrAWorkDirAmongTheGoldensAreRefused) {
  SilentProgress lines;
  GoldenOptions role_alone;
  role_alone.role = "head";
  try {
    verify_goldens(role_alone, lines);
    FAIL() << "--role without --from-run was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--role head: whose images to take from a results "
                                         "document, so it needs --from-run"),
              std::string::npos)
        << e.what();
  }
  GoldenOptions same;
  same.golden_dir = "golden/mine";
  same.work_dir = "golden/./mine/";
  try {
    bless_goldens(same, lines);
    FAIL() << "--work-dir equal to --golden-dir was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--work-dir and --golden-dir are the same folder"),
              std::string::npos)
        << e.what();
  }
}

// The seventh sweep: `golden verify --from-run run.json --suite nosuch` ignored --suite and
// checked the run's suite, exit 0. A run's images are of the suite it was measured on.
TEST(GoldenCommands, ASuiteBesideFromRunIsRefused) {
  SilentProgress lines;
  GoldenOptions options;
  options.from_run = "results.json";
  options.suite = "nosuch";
  for (const bool bless : {false, true}) {
    try {
      bless ? bless_goldens(options, lines) : static_cast<void>(verify_goldens(options, lines));
      FAIL() << "--suite beside --from-run was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--suite nosuch: --from-run takes the suite its "
                                           "results document was measured on"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace raygate
