// `raygate consistency` and `raygate doctor` as a user runs them: hand-made results documents
// of two machines give exit 0 or 1, one document or mixed baselines exit 2, an unreadable file
// exits 3; doctor measures a real noise score with the built raygate-baseline.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "results_fixture.h"

namespace raygate::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

DocumentSpec machine(const std::string& host, double mount_ratio) {
  DocumentSpec spec;
  spec.sha = fake_sha(7);
  spec.hostname = host;
  spec.cpu_model = "CPU of " + host;
  spec.scenes = {{"balls", 0.50, 0.05},
                 {"gears", 0.80, 0.05},
                 {"mount", mount_ratio, 0.05},
                 {"rings", 1.50, 0.05},
                 {"teapot", 0.90, 0.05}};
  return spec;
}

class ConsistencyCli : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const DocumentSpec& spec) {
    write_results(make_document(spec), dir.path() / name);
    return name;
  }
  TempDir dir;
};

TEST_F(ConsistencyCli, SameRatiosOnTwoMachinesExitZero) {
  const CliRun r =
      run_raygate({"consistency", write("a.json", machine("straylight", 1.2)),
                   write("b.json", machine("neolith", 1.21)), "--markdown", "out/consistency.md"},
                  dir);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("straylight  CPU of straylight"));
  EXPECT_THAT(r.out, HasSubstr("neolith  CPU of neolith"));
  EXPECT_THAT(r.out, HasSubstr("machine-independent: every pair r²"));
  EXPECT_THAT(read_file(dir.path() / "out/consistency.md"), HasSubstr("| A vs B | 5 |"));
}

TEST_F(ConsistencyCli, AMovedSceneExitsOneAndNamesIt) {
  const CliRun r = run_raygate({"consistency", write("a.json", machine("straylight", 1.2)),
                                write("b.json", machine("neolith", 1.6)), "--format", "json"},
                               dir);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["unstable"], nlohmann::json::array({"mount"}));
  EXPECT_EQ(json["machine_independent"], false);
  EXPECT_EQ(json["exit_code"], 1);
}

TEST_F(ConsistencyCli, UsageErrorsExitTwo) {
  const std::string a = write("a.json", machine("straylight", 1.2));
  const CliRun one = run_raygate({"consistency", a}, dir);
  EXPECT_EQ(one.exit_code, 2) << one.out;
  EXPECT_THAT(one.out, HasSubstr("at least 2 results documents"));
  DocumentSpec other = machine("neolith", 1.2);
  other.baseline_sha256 = std::string(64, 'c');
  const std::string b = write("b.json", other);
  const CliRun mixed = run_raygate({"consistency", a, b}, dir);
  EXPECT_EQ(mixed.exit_code, 2) << mixed.out;
  EXPECT_THAT(mixed.out, HasSubstr("different raygate-baseline sources"));
  EXPECT_EQ(run_raygate({"consistency", a, b, "--allow-mixed"}, dir).exit_code, 0);
  // One measurement given twice agrees with itself: no evidence about two machines.
  std::filesystem::copy_file(dir.path() / a, dir.path() / "copy.json");
  for (const std::string& again : {a, (dir.path() / "copy.json").string()}) {
    const CliRun twice = run_raygate({"consistency", a, again}, dir);
    EXPECT_EQ(twice.exit_code, 2) << twice.out;
    EXPECT_THAT(twice.out, HasSubstr("are the same measurement"));
  }
}

// A document argument that is not there or not a results document is the user's to fix, as in
// gate and report: exit 2, naming it.
TEST_F(ConsistencyCli, UnreadableDocumentIsAUsageError) {
  const std::string a = write("a.json", machine("straylight", 1.2));
  const CliRun missing = run_raygate({"consistency", a, "nowhere.json"}, dir);
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_THAT(missing.out, HasSubstr("nowhere.json"));
  write_file_atomically(dir.path() / "text.json", "not json");
  const CliRun text = run_raygate({"consistency", a, "text.json"}, dir);
  EXPECT_EQ(text.exit_code, 2) << text.out;
  EXPECT_THAT(text.out, HasSubstr("consistency needs results documents"));
}

TEST(DoctorCli, JsonWithAMeasuredNoiseScore) {
  TempDir dir;
  const CliRun r = run_raygate({"doctor", "--rounds", "3", "--format", "json"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  ASSERT_TRUE(json["noise"].is_object()) << r.out;
  EXPECT_EQ(json["noise"]["rounds"], 3);
  EXPECT_GT(json["noise"]["seconds"]["median"].get<double>(), 0.0);
  EXPECT_GE(json["noise"]["ratio_cv"].get<double>(), 0.0);
  EXPECT_THAT(json["noise"]["grade"].get<std::string>(), ::testing::AnyOf("good", "fair", "noisy"));
  EXPECT_EQ(json["checks"].size(), 10u);  // governor ... virtualization, idle
  EXPECT_THAT(json["baseline"].get<std::string>(), HasSubstr("raygate-baseline"));
}

TEST(DoctorCli, BadRoundsAndMissingBaseline) {
  TempDir dir;
  EXPECT_EQ(run_raygate({"doctor", "--rounds", "1"}, dir).exit_code, 2);
  EXPECT_EQ(run_raygate({"doctor", "--rounds", "nan"}, dir).exit_code, 2);
  // A --baseline the user named that is not there is a usage error, said before any probing.
  const CliRun missing =
      run_raygate({"doctor", "--baseline", "/nonexistent/raygate-baseline"}, dir);
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  EXPECT_THAT(missing.out, HasSubstr("--baseline /nonexistent/raygate-baseline: not an "
                                     "executable file"));
  // One that is there but cannot run is what the noise line reports, the checks still given.
  write_file_atomically(dir.path() / "broken-baseline", "#!/bin/sh\nexit 7\n");
  std::filesystem::permissions(dir.path() / "broken-baseline", std::filesystem::perms::owner_all);
  const CliRun r = run_raygate({"doctor", "--baseline", "./broken-baseline"}, dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_THAT(r.out, HasSubstr("noise: not measured"));
  EXPECT_THAT(r.out, HasSubstr("governor"));  // the checks are still reported
}

// The seventh sweep: a baseline that answers --version but fails its run was reported with a log
// in the doctor's temporary folder, removed on exit; its end is shown instead. A relative
// --baseline runs too (it did not: each run starts in its own folder).
TEST(DoctorCli, ABaselineThatFailsItsRunIsShownByItsLog) {
  TempDir dir;
  write_file_atomically(dir.path() / "failing-baseline",
                        "#!/bin/sh\nif [ \"$1\" = --version ]; then echo raygate-baseline 0.0; "
                        "exit 0; fi\necho 'broken: no scene here'\nexit 7\n");
  std::filesystem::permissions(dir.path() / "failing-baseline", std::filesystem::perms::owner_all);
  const CliRun r =
      run_raygate({"doctor", "--rounds", "2", "--baseline", "./failing-baseline"}, dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_THAT(r.out, HasSubstr("its log ended:\nbroken: no scene here"));
  EXPECT_THAT(r.out, Not(HasSubstr("(log: ")));
}

}  // namespace
}  // namespace raygate::test
