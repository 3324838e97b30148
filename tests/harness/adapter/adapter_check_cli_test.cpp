// `raygate adapter check` end to end: the real binary, exit 0 for valid files, 2 for invalid
// ones (every bad file reported, not only the first), and the summary shows placeholders.
#include <gtest/gtest.h>

#include <string>

#include "core/fs.h"
#include "core/process.h"

namespace raygate {
namespace {

struct CheckRun {
  ProcessResult result;
  std::string out;
  std::string err;
};

CheckRun check(const std::vector<std::string>& files) {
  TempDir logs;
  ProcessSpec spec;
  spec.argv = {std::string(RAYGATE_BINARY_DIR) + "/bin/raygate", "adapter", "check"};
  spec.argv.insert(spec.argv.end(), files.begin(), files.end());
  spec.stdout_path = logs.path() / "out.txt";
  spec.stderr_path = logs.path() / "err.txt";
  spec.timeout = std::chrono::seconds(60);
  CheckRun run{run_process(spec), "", ""};
  run.out = read_file(spec.stdout_path);
  run.err = read_file(spec.stderr_path);
  return run;
}

std::string shipped(const std::string& name) {
  return std::string(RAYGATE_SOURCE_DIR) + "/adapters/" + name;
}

TEST(AdapterCheckCli, ShippedAdaptersPass) {
  const CheckRun run = check(
      {shipped("raygate-baseline-bbox.json"), shipped("cmake-nff.json"), shipped("make-nff.json")});
  ASSERT_EQ(run.result.outcome, ProcessOutcome::exited) << run.result.describe();
  EXPECT_EQ(run.result.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("{build}/bin/raygate-baseline {scene} -o {image} --accel bbox"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("cmake-nff.json: ok"), std::string::npos) << run.out;
}

TEST(AdapterCheckCli, InvalidFilesExitTwoAndAreAllReported) {
  TempDir dir;
  const auto typo = dir.path() / "typo.json";
  const auto broken = dir.path() / "broken.json";
  write_file_atomically(typo, R"({"name": "t", "scene_format": "nff", "run": ["t", "{scen}"],
                                  "image": "{workdir}/a.ppm"})");
  write_file_atomically(broken, "{\"name\": ");
  const CheckRun run = check({typo.string(), shipped("cmake-nff.json"), broken.string()});
  ASSERT_EQ(run.result.outcome, ProcessOutcome::exited) << run.result.describe();
  EXPECT_EQ(run.result.exit_code, 2);
  EXPECT_NE(run.err.find(typo.string() + ": $.run[1]: unknown placeholder '{scen}' (did you "
                                         "mean '{scene}'?)"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find(broken.string() + ":1:10: not JSON"), std::string::npos) << run.err;
  EXPECT_NE(run.out.find("cmake-nff.json: ok"), std::string::npos) << run.out;
}

TEST(AdapterCheckCli, MissingPackagesAreAWarningWithTheAptGetLine) {
  TempDir dir;
  const auto file = dir.path() / "needs.json";
  write_file_atomically(file, R"({"name": "t", "scene_format": "nff", "run": ["t", "{scene}"],
      "image": "{workdir}/a.ppm", "requires": ["coreutils", "raygate-no-such-package-xyz"]})");
  const CheckRun run = check({file.string()});
  EXPECT_EQ(run.result.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("apt-get install -y raygate-no-such-package-xyz\n"), std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("coreutils"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace raygate
