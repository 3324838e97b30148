// Nothing lost when an output cannot be written (issue 25, items 4 and 5), end to end: the
// results document under -o on a full disk, a --report file on a full disk, standard output on a
// full disk. Each time the document is stored, every other output is written, the failed one is
// named with its path and the system's reason, and the exit code is 3. And the baseline's
// goldens blessed again on a full disk stay the old set, matching their manifest. A full disk
// is a small tmpfs, filled, in a private mount namespace (root only: skipped elsewhere);
// standard output is /dev/full, which needs nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_support.h"
#include "compare/golden.h"
#include "core/sha256.h"
#include "results/results.h"
#include "results_fixture.h"
#include "tracer_fixture.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

// Inside the namespace: `full` becomes a filled 4 KiB tmpfs, then raygate runs (exit 77 when
// the mount is not permitted).
constexpr const char* kFullDiskScript =
    "mount -t tmpfs -o size=4k raygate-full full || exit 77; "
    "head -c 8192 /dev/zero > full/fill 2>/dev/null; exec \"$@\"";

class OutputsCli : public TracerRepoTest {
 protected:
  OutputsCli() { fs::create_directories(dir_.path() / "full"); }

  // raygate through /bin/sh: `script` sets the scene up and ends with exec "$@".
  CliStreams shell(const std::vector<std::string>& prefix, const std::string& script,
                   const std::vector<std::string>& args) const {
    ProcessSpec spec;
    spec.argv = prefix;
    spec.argv.insert(spec.argv.end(), {"sh", "-c", script, "sh", RAYGATE_EXE});
    spec.argv.insert(spec.argv.end(), args.begin(), args.end());
    spec.stdout_path = dir_.path() / "cli.out";
    spec.stderr_path = dir_.path() / "cli.err";
    spec.working_directory = dir_.path();
    spec.timeout = std::chrono::minutes(5);
    const ProcessResult r = run_process(spec);
    return {r.outcome == ProcessOutcome::exited ? r.exit_code : -1, read_file(spec.stdout_path),
            read_file(spec.stderr_path)};
  }

  // raygate with `full` a full disk; skips the test where a private mount is not permitted.
  CliStreams with_full_disk(const std::vector<std::string>& args) {
    CliStreams result = shell({"unshare", "--mount"}, kFullDiskScript, args);
    if (result.exit_code == 77 || result.exit_code == -1) {
      skipped_ = true;
      return result;
    }
    return result;
  }

  // A one-shard document of two scenes that `merge` takes.
  std::string shard_file() const {
    DocumentSpec spec;
    spec.sha = fake_sha(4);
    spec.shard = "1/1";
    spec.scenes = {{.id = "balls", .ratio = 1.1}, {.id = "gears", .ratio = 0.9}};
    const fs::path path = dir_.path() / "shard.json";
    write_results(make_document(spec), path);
    return path.string();
  }

  // How many documents the store holds, through `raygate export`.
  std::size_t stored_documents(const std::string& store) const {
    const CliRun exported =
        run_raygate({"export", "--store", store, "--last", "10", "-o", "exported"}, dir_);
    if (exported.exit_code != 0) return 0;
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& file : fs::directory_iterator(dir_.path() / "exported")) {
      ++count;
    }
    return count;
  }

  bool skipped_ = false;
};

#define SKIP_WITHOUT_PRIVATE_MOUNTS() \
  if (skipped_) GTEST_SKIP() << "a private tmpfs mount is not permitted here (needs root)"

TEST_F(OutputsCli, AMergeOnAFullStandardOutputIsStoredAndItsOtherOutputsWritten) {
  const CliStreams merged = shell({}, "exec \"$@\" > /dev/full",
                                  {"merge", shard_file(), "-o", "merged.json", "--store",
                                   "store.db", "--format", "json", "--report", "html:report.html"});
  EXPECT_EQ(merged.exit_code, 3) << merged.err;
  EXPECT_TRUE(has(merged.err,
                  "--report json:- not written: cannot write -: No space left on "
                  "device"))
      << merged.err;
  EXPECT_TRUE(has(merged.err, "1 output could not be written (--report json:-)")) << merged.err;
  EXPECT_TRUE(fs::exists(dir_.path() / "merged.json"));
  EXPECT_TRUE(fs::exists(dir_.path() / "report.html"));  // the report after the failed one
  EXPECT_EQ(stored_documents("store.db"), 1u);
}

TEST_F(OutputsCli, AMergeWhoseOutputIsOnAFullDiskIsStoredAndReported) {
  const CliStreams merged =
      with_full_disk({"merge", shard_file(), "-o", "full/merged.json", "--store", "store.db",
                      "--report", "markdown:full/report.md", "--report", "junit:junit.xml"});
  SKIP_WITHOUT_PRIVATE_MOUNTS();
  EXPECT_EQ(merged.exit_code, 3) << merged.err;
  EXPECT_TRUE(has(merged.err, "the merged document (--output) not written: cannot write " +
                                  (dir_.path() / "full" / "merged.json").string() +
                                  ": No space left on device"))
      << merged.err;
  EXPECT_TRUE(has(merged.err,
                  "--report markdown:full/report.md not written: cannot write "
                  "full/report.md: No space left on device"))
      << merged.err;
  EXPECT_TRUE(has(merged.err, "2 outputs could not be written")) << merged.err;
  EXPECT_TRUE(fs::exists(dir_.path() / "junit.xml"));
  EXPECT_EQ(stored_documents("store.db"), 1u);
}

TEST_F(OutputsCli, AMergeIntoADeviceIsRefusedBeforeAnythingIsRead) {
  // Known before any work: a usage error (2), and the device is still a device.
  const CliRun merged = run_raygate({"merge", shard_file(), "-o", "/dev/full", "--no-store"}, dir_);
  EXPECT_EQ(merged.exit_code, 2) << merged.out;
  EXPECT_TRUE(has(merged.out, "--output: /dev/full is not a regular file")) << merged.out;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST_F(OutputsCli, ARegressionOutranksAFailedOutput) {
  // A merged shard with an image that fails its check: the gate says 1, and a report that
  // cannot be written does not turn that into "could not finish".
  DocumentSpec spec;
  spec.sha = fake_sha(5);
  spec.shard = "1/1";
  spec.scenes = {{.id = "balls", .max_error = 0.5, .verdict = ImageVerdict::fail}};
  write_results(make_document(spec), dir_.path() / "failing.json");
  const CliStreams merged =
      shell({}, "exec \"$@\" > /dev/full",
            {"merge", "failing.json", "-o", "merged.json", "--no-store", "--format", "markdown"});
  EXPECT_EQ(merged.exit_code, 1) << merged.err;
  EXPECT_TRUE(has(merged.err, "1 output could not be written")) << merged.err;
}

TEST_F(OutputsCli, ARunWhoseOutputIsOnAFullDiskKeepsTheDocumentInItsRunFolderAndTheStore) {
  const std::string sha = commit(sources_.fast, "tracer");
  const CliStreams run = with_full_disk({"run",
                                         "--repo",
                                         repo_.path().string(),
                                         "--rev",
                                         sha,
                                         "--adapter",
                                         "make-nff",
                                         "--suite",
                                         suite_.string(),
                                         "--scene",
                                         "tetra",
                                         "--max-rounds",
                                         "1",
                                         "--warmup",
                                         "0",
                                         "--golden-dir",
                                         "no-goldens",
                                         "--cache-dir",
                                         "cache",
                                         "-o",
                                         "full/results.json",
                                         "--store",
                                         "store.db",
                                         "--report",
                                         "html:report.html"});
  SKIP_WITHOUT_PRIVATE_MOUNTS();
  EXPECT_EQ(run.exit_code, 3) << run.err;
  const fs::path requested = dir_.path() / "full" / "results.json";
  EXPECT_TRUE(has(run.err, "the results document not written: cannot write " + requested.string() +
                               ": No space left on device"))
      << run.err;
  // The document in the run folder, complete, and said where.
  std::vector<fs::path> kept;
  for (const auto& run_dir : fs::directory_iterator(dir_.path() / "cache" / "runs")) {
    const fs::path copy = run_dir.path() / "results.json";
    if (fs::exists(copy)) kept.push_back(copy);
  }
  ASSERT_EQ(kept.size(), 1u) << run.err;
  EXPECT_TRUE(has(run.err, "results: " + kept.front().string())) << run.err;
  const ResultsDocument document = read_results(kept.front());
  EXPECT_TRUE(document.complete);
  EXPECT_EQ(document.scenes.size(), 1u);
  EXPECT_TRUE(fs::exists(dir_.path() / "report.html"));
  EXPECT_EQ(stored_documents("store.db"), 1u);
}

// Issue 25, item 5, end to end: the baseline's goldens blessed again on a disk that has filled
// up. The folder holds a golden of an older baseline (other bytes than a render gives now), so
// the new one must really be written: in place, that left a truncated tetra.png under a
// manifest naming the old sha256 (and an internal error). Now the second bless fails (exit 3)
// saying the goldens are unchanged, and they are: the old file, its manifest's sha256 matching,
// no temporary beside the folder. The tmpfs lives only while the shell runs, so the shell
// copies it out to after/ for the test to look at.
TEST_F(OutputsCli, ABaselineBlessOnAFullDiskLeavesTheOldGoldensAndTheirManifestInAgreement) {
  const std::string script =
      "mount -t tmpfs -o size=512k raygate-full full || exit 77\n"
      "\"$0\" golden bless tetra --golden-dir full/g --work-dir work > first.log 2>&1 || exit 78\n"
      "rendered=$(sha256sum full/g/tetra.png | cut -c1-64)\n"
      "printf 'a golden of an older baseline' > full/g/tetra.png\n"
      "older=$(sha256sum full/g/tetra.png | cut -c1-64)\n"
      "sed -i \"s/$rendered/$older/\" full/g/manifest.json\n"
      "cp -r full/g first\n"
      "head -c 600000 /dev/zero > full/fill 2>/dev/null\n"
      "\"$0\" golden bless tetra gears --golden-dir full/g --work-dir work; echo $? > second.code\n"
      "rm full/fill; cp -r full after\n";
  ProcessSpec spec;
  spec.argv = {"unshare", "--mount", "sh", "-c", script, RAYGATE_EXE};
  spec.stdout_path = dir_.path() / "cli.out";
  spec.stderr_path = dir_.path() / "cli.err";
  spec.working_directory = dir_.path();
  spec.timeout = std::chrono::minutes(5);
  const ProcessResult r = run_process(spec);
  if (r.outcome != ProcessOutcome::exited || r.exit_code == 77) {
    GTEST_SKIP() << "a private tmpfs mount is not permitted here (needs root)";
  }
  ASSERT_EQ(r.exit_code, 0) << read_file(dir_.path() / "cli.err")
                            << read_file(dir_.path() / "first.log");
  EXPECT_EQ(read_file(dir_.path() / "second.code"), "3\n");
  const std::string said = read_file(dir_.path() / "cli.err");
  EXPECT_TRUE(has(said, "No space left on device")) << said;
  EXPECT_TRUE(has(said, "the goldens there are unchanged")) << said;
  const fs::path after = dir_.path() / "after" / "g";
  EXPECT_EQ(read_file(after / "tetra.png"), read_file(dir_.path() / "first" / "tetra.png"));
  EXPECT_EQ(read_file(after / "manifest.json"), read_file(dir_.path() / "first" / "manifest.json"));
  EXPECT_FALSE(fs::exists(after / "gears.png"));
  const GoldenManifest manifest = load_golden_manifest(after);
  ASSERT_EQ(manifest.entries.size(), 1u);
  EXPECT_EQ(manifest.entries[0].sha256, sha256_file_hex(after / "tetra.png"));
  for (const auto& entry : fs::directory_iterator(dir_.path() / "after")) {
    EXPECT_EQ(entry.path().filename(), "g") << "left behind: " << entry.path();
  }
}

}  // namespace
}  // namespace raygate::test
