// `raygate merge A.json B.json ... -o OUT.json`: the documents of the shards of one CI matrix
// (run or compare with --shard K/N) joined into the document one job measuring every scene
// would have written (results/merge.h): written atomically, stored and reported like run's, and
// gated like `raygate gate` does, whose exit code it returns (0 pass, 1 regression, 3 not
// everything measured). Shards that do not belong together are refused with exit 2.
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/report_options.h"
#include "cli/subcommand.h"
#include "pipeline/publish_options.h"

namespace raygate::cli {
namespace {

struct MergeArgs {
  MergeRequest request;
  std::string cache_dir = ".raygate";  // where the default store is, as for run
  PublishOptions publish;              // --store, --no-store, --branch, --report, --format
};

int merge_command(const MergeArgs& args, const Console& console) {
  return merge_and_publish(args.request, args.publish, args.cache_dir, console);
}

}  // namespace

void add_merge_command(CLI::App& command, int& exit_code) {
  MergeArgs& args = bind_command<MergeArgs>(command, merge_command, exit_code);
  command.add_option("documents", args.request.documents, "the shards' results documents")
      ->required();
  command
      .add_option("--cache-dir", args.cache_dir,
                  "the default store is <cache-dir>/results.db, as for run")
      ->capture_default_str()
      ->check(writable_folder());
  command.add_option("--policy", args.request.policy, "gate policy file (docs/gate.md)");
  command.add_flag("--fail-on-inconclusive", args.request.fail_on_inconclusive,
                   "an INCONCLUSIVE change fails the gate instead of warning");
  command.add_flag("--allow-partial", args.request.allow_partial,
                   "merge even if whole shards are missing (the result is incomplete: exit 3)");
  add_publish_options(command, args.request.out, "the merged results document (required)",
                      args.publish);
}

}  // namespace raygate::cli
