// `raygate merge A.json B.json ... -o OUT.json`: the documents of the shards of one CI matrix
// (run or compare with --shard K/N) joined into the document one job measuring every scene
// would have written (results/merge.h): written atomically, stored and reported like run's, and
// gated like `raygate gate` does, whose exit code it returns (0 pass, 1 regression, 3 not
// everything measured). Shards that do not belong together are refused with exit 2.
#include <fmt/core.h>

#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/report_options.h"
#include "cli/store_options.h"
#include "core/error.h"
#include "gate/policy.h"
#include "gate/verdict.h"
#include "results/merge.h"

namespace raygate::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> documents;
  std::string out;
  std::string cache_dir = ".raygate";  // where the default store is, as for run
  std::string policy;
  bool fail_on_inconclusive = false;
  bool allow_partial = false;
  RecordArgs record;                 // --store, --no-store, --branch
  std::vector<std::string> reports;  // --report FORMAT:PATH
};

void print_scores(const ResultsDocument& document, const Console& console) {
  for (const auto& [role, score] : document.scores) {
    console.info(fmt::format("suite score {} (geometric mean of normalized ratios): {:.3f} "
                             "[{:.3f}, {:.3f}] over {} scenes",
                             role, score.score, score.interval.lower, score.interval.upper,
                             score.scenes));
  }
}

int merge_command(const MergeArgs& args, const Console& console) {
  if (args.out.empty()) throw UsageError("merge: --output is required (the merged document)");
  check_report_specs(args.reports);
  check_output_path(args.out, "--output");  // a folder or a device: refused before reading
  std::vector<MergeInput> inputs;
  for (const std::string& path : args.documents) inputs.push_back({path, read_results(path)});
  // Without --policy the shards' own limits judge the merge (merge checked that they agree).
  std::string note;
  GatePolicy policy = args.policy.empty() || inputs.empty()
                          ? recorded_policy(inputs.empty() ? nlohmann::json::object()
                                                           : inputs.front().document.settings,
                                            note)
                          : load_policy(args.policy);
  if (!note.empty()) console.info(fmt::format("gate policy: {}", note));
  policy.fail_on_inconclusive = policy.fail_on_inconclusive || args.fail_on_inconclusive;

  MergeOptions options;
  options.allow_partial = args.allow_partial;
  const MergeResult merged = merge_shards(inputs, options);
  for (const std::string& warning : merged.warnings) {
    fmt::print(stderr, "raygate: warning: {}\n", warning);
  }
  const ResultsDocument& document = merged.document;
  const std::filesystem::path out = std::filesystem::absolute(args.out);
  // A full disk under -o must not lose the merge: the store still gets it, and the reports.
  OutputFailures failures;
  failures.attempt("the merged document (--output)", [&] { write_results(document, out); });
  console.info(fmt::format("merged {} shard documents of suite {}: {} scenes{}", inputs.size(),
                           document.suite, document.scenes.size(),
                           document.complete ? "" : " (incomplete)"));
  print_scores(document, console);

  return record_gate_and_report(document, out, args.record,
                                std::filesystem::absolute(args.cache_dir), policy, args.reports,
                                console, failures);
}

}  // namespace

void add_merge_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* command = app.add_subcommand(
      "merge", "join the results documents of the shards of a CI matrix (--shard K/N) into one "
               "and gate it");
  command->add_option("documents", args->documents, "the shards' results documents")
      ->required();
  add_deprecated_alias(*command, "--out",
                       command->add_option("-o,--output", args->out,
                                           "the merged results document (required)"),
                       args->out);
  command->add_option("--cache-dir", args->cache_dir,
                      "the default store is <cache-dir>/results.db, as for run")
      ->capture_default_str();
  command->add_option("--policy", args->policy, "gate policy file (docs/gate.md)");
  command->add_flag("--fail-on-inconclusive", args->fail_on_inconclusive,
                    "an INCONCLUSIVE change fails the gate instead of warning");
  command->add_flag("--allow-partial", args->allow_partial,
                    "merge even if whole shards are missing (the result is incomplete: exit 3)");
  add_record_options(*command, args->record);
  add_report_options(*command, args->reports);
  command->callback([args, command, &exit_code] {
    exit_code = merge_command(*args, console_of(*command));
  });
}

}  // namespace raygate::cli
