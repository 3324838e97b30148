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
#include "pipeline/merge_stage.h"

namespace raygate::cli {
namespace {

struct MergeArgs {
  MergeRequest request;
  std::string cache_dir = ".raygate";  // where the default store is, as for run
  RecordArgs record;                 // --store, --no-store, --branch
  std::vector<std::string> reports;  // --report FORMAT:PATH
};

int merge_command(const MergeArgs& args, const Console& console) {
  if (args.request.out.empty()) {
    throw UsageError("merge: --output is required (the merged document)");
  }
  parse_report_targets(args.reports);
  check_output_path(args.request.out, "--output");  // a folder or a device: refused before reading
  MergeRequest request = args.request;
  request.out = std::filesystem::absolute(request.out).string();
  OutputFailures failures;
  const MergedShards merged = merge_shard_documents(request, console, failures);
  const std::filesystem::path cache_dir = std::filesystem::absolute(args.cache_dir);
  return publish(merged.document,
                 publish_request(request.out, args.record, cache_dir, merged.policy,
                                 args.reports, console),
                 console, failures);
}

}  // namespace

void add_merge_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* command = app.add_subcommand(
      "merge", "join the results documents of the shards of a CI matrix (--shard K/N) into one "
               "and gate it");
  command->add_option("documents", args->request.documents, "the shards' results documents")
      ->required();
  command->add_option("--cache-dir", args->cache_dir,
                      "the default store is <cache-dir>/results.db, as for run")
      ->capture_default_str();
  command->add_option("--policy", args->request.policy, "gate policy file (docs/gate.md)");
  command->add_flag("--fail-on-inconclusive", args->request.fail_on_inconclusive,
                    "an INCONCLUSIVE change fails the gate instead of warning");
  command->add_flag("--allow-partial", args->request.allow_partial,
                    "merge even if whole shards are missing (the result is incomplete: exit 3)");
  add_publish_options(*command, args->request.out, "the merged results document (required)",
                      args->record, args->reports);
  command->callback([args, command, &exit_code] {
    exit_code = merge_command(*args, console_of(*command));
  });
}

}  // namespace raygate::cli
