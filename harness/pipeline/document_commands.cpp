#include "pipeline/document_commands.h"

#include <fmt/core.h>

#include <algorithm>

#include "consistency/consistency_report.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"
#include "core/paths.h"
#include "core/sha256.h"
#include "gate/growth_gate.h"
#include "runner/baseline_tool.h"
#include "scaling/scaling_stage.h"
#include "spd.h"

namespace raygate {

JudgedDocument judge_document(const std::string& results, const std::string& policy_file,
                              bool fail_on_inconclusive, std::string& note) {
  JudgedDocument j;
  j.path = std::filesystem::absolute(results);
  j.document = read_results(j.path);
  if (!policy_file.empty()) {
    j.policy = load_policy(policy_file);
    // An image's verdict needs its pixels, which a document does not hold: a stricter or looser
    // image_tolerance given here changed nothing, silently (the tenth sweep).
    const auto has_images = [](const SceneResult& scene) { return !scene.images.empty(); };
    if (std::any_of(j.document.scenes.begin(), j.document.scenes.end(), has_images)) {
      note = fmt::format(
          "{} for speed and memory; images keep the verdicts they were measured with (its "
          "image thresholds and image_tolerance apply when measuring: compare --policy)",
          policy_file);
    }
  } else {
    j.policy = recorded_policy(j.document.settings, note);
  }
  j.policy.fail_on_inconclusive = j.policy.fail_on_inconclusive || fail_on_inconclusive;
  j.gate = evaluate_gate(j.document, j.policy);
  return j;
}

namespace {

// The fits count each scene's primitives by generating it again at its size: a document whose
// scene names no SPD generator, or a size that one does not make, cannot be placed on the size
// axis. The document is the user's argument (edited, or of a newer raygate): exit 2, its path.
void check_scaling_scenes(const ResultsDocument& document, const std::string& results) {
  for (std::size_t i = 0; i < document.scenes.size(); ++i) {
    const SuiteScene& entry = document.scenes[i].entry;
    const std::string where = fmt::format("{}: $.scenes[{}].scene", results, i);
    const scenes::SceneGenerator* generator = scenes::find_generator(entry.scene);
    if (generator == nullptr) {
      throw UsageError(
          fmt::format("{}.scene: \"{}\" is not an SPD scene (raygate scenes list); "
                      "scaling fits the SPD generators' families",
                      where, entry.scene.substr(0, 80)));
    }
    if (entry.size < 0 || entry.size > scenes::max_size(*generator)) {
      throw UsageError(
          fmt::format("{}.size: {} is out of range for {} (0, its default, or 1 to "
                      "{})",
                      where, entry.size, entry.scene, scenes::max_size(*generator)));
    }
  }
}

}  // namespace

ScalingJudgement judge_scaling(const std::string& results, const std::string& policy_file,
                               bool no_write, OutputFailures& failures) {
  ScalingJudgement j;
  j.document = read_results(results);
  check_scaling_scenes(j.document, results);
  std::string note;
  j.policy =
      policy_file.empty() ? recorded_policy(j.document.settings, note) : load_policy(policy_file);
  j.analysis = attach_scaling(j.document, scaling_limits(j.policy));
  if (j.analysis.families.empty()) {
    throw UsageError(
        fmt::format("{}: no scene family was measured at 3 sizes or more (suite {}); "
                    "measure the scaling suite: --suite scaling",
                    results, j.document.suite));
  }
  // The fits not written back still judge, and the reports still go out. Only the "scaling" key
  // of the file as it was read changes: a newer raygate's keys elsewhere were dropped when the
  // whole document was written again (the eleventh sweep).
  if (!no_write) {
    failures.attempt("the fits in " + results, [&] {
      nlohmann::json as_read = read_json_file(results);
      as_read["scaling"] = to_json(j.document).at("scaling");
      write_file_atomically(results, as_read.dump(1) + "\n");
    });
  }
  j.gate.families = judge_growth(j.document, j.policy);
  const bool failed =
      std::any_of(j.gate.families.begin(), j.gate.families.end(),
                  [](const SceneGate& g) { return g.outcome == GateOutcome::fail; });
  j.gate.exit_code = failed ? 1 : 0;
  return j;
}

namespace {

ResultsDocument read_document(const std::string& path) {
  try {
    return read_results(path);
  } catch (const UsageError& e) {  // the user's argument: still exit 2, with what is wanted
    throw UsageError(std::string(e.what()) +
                     " (consistency needs results documents written by "
                     "raygate run or compare --out)");
  }
}

}  // namespace

ConsistencyResult check_consistency(const std::vector<std::string>& paths,
                                    const ConsistencyOptions& options) {
  if (paths.size() < 2) {
    throw UsageError(
        fmt::format("consistency needs at least 2 results documents (one per "
                    "machine), got {}",
                    paths.size()));
  }
  std::vector<DocumentRatios> documents;
  std::vector<std::string> hashes;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    documents.push_back(document_ratios(read_document(paths[i]), paths[i], document_label(i)));
    // One measurement given twice agrees with itself perfectly: no evidence of two machines.
    hashes.push_back(sha256_file_hex(paths[i]));
    for (std::size_t j = 0; j < i; ++j) {
      if (hashes[j] == hashes[i]) {
        throw UsageError(
            fmt::format("{} and {} are the same measurement (identical files); "
                        "consistency compares documents measured apart",
                        paths[j], paths[i]));
      }
    }
  }
  return analyse_consistency(std::move(documents), options);
}

DoctorReport examine_machine(int rounds, const std::string& baseline,
                             const std::function<void(const std::string&)>& status) {
  if (rounds < 2) {
    throw UsageError(fmt::format("--rounds {}: a noise score needs at least 2 rounds", rounds));
  }
  // A --baseline that is not there is the user's to fix (exit 2), before anything is probed;
  // one that is there but cannot run is what the noise line reports.
  if (!baseline.empty()) locate_tools(baseline);
  DoctorReport report;
  report.facts = probe_system_facts();  // before measuring: the load must not be our own
  report.findings = diagnose(report.facts);
  try {
    const ToolPaths tools = locate_tools(baseline);
    report.baseline_version = BaselineTool(tools.baseline).version_line();
    TempDir work("raygate-doctor");
    NoiseOptions options;
    options.baseline = tools.baseline;
    options.rounds = rounds;
    options.work_dir = work.path();
    status(fmt::format("measuring noise: {} rounds of two raygate-baseline runs...", rounds));
    report.noise = measure_noise(options);
  } catch (const InfraError& e) {
    report.noise_error = e.what();
  }
  return report;
}

}  // namespace raygate
