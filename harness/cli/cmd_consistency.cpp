// `raygate consistency A.json B.json ...`: are this tracer's normalized ratios the same on
// different machines (the paper's claim, checked for your tracer)? Reads results documents of
// one tracer revision measured with one baseline on several machines and reports r² per pair of
// documents and the scenes whose ratio is not machine-stable (harness/consistency/).
// Exit 0 machine-independent, 1 not, 2 usage (fewer than 2 documents, mixed baselines or
// revisions without --allow-mixed), 3 a document could not be read.
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/subcommand.h"
#include "consistency/consistency.h"
#include "consistency/consistency_report.h"
#include "core/fs.h"
#include "pipeline/document_commands.h"

namespace raygate::cli {
namespace {

struct ConsistencyArgs {
  std::vector<std::string> documents;
  ConsistencyOptions options;
  std::string format;  // text, json
  std::string markdown;
};

int consistency_command(const ConsistencyArgs& args) {
  check_output_beside_inputs({"--markdown", args.markdown}, args.documents, "the document");
  const ConsistencyResult result = check_consistency(args.documents, args.options);
  if (!args.markdown.empty()) write_file_atomically(args.markdown, consistency_markdown(result));
  print_result(
      args.format, [&] { return consistency_json(result); },
      [&] { return consistency_table(result); });
  return result.exit_code();
}

}  // namespace

void add_consistency_command(CLI::App& command, int& exit_code) {
  ConsistencyArgs& args = bind_command<ConsistencyArgs>(command, consistency_command, exit_code);
  command.add_option("documents", args.documents,
                     "results documents (raygate run/compare --out), one per machine or run");
  add_bounded_option(command, "--min-r2", args.options.min_r2, 0.0, 1.0,
                     "every pair of documents needs at least this r² of per-scene ratios");
  add_bounded_option(command, "--max-deviation", args.options.max_deviation, 0.0001, 1.0,
                     "a scene whose ratio strays further than this fraction from its mean "
                     "over documents is not machine-stable");
  command.add_flag("--allow-mixed", args.options.allow_mixed,
                   "compare documents of different baselines or tracer revisions anyway");
  add_format_option(command, args.format, {"text", "json"}, true);
  command.add_option("--markdown", args.markdown, "also write the result as Markdown to PATH");
}

}  // namespace raygate::cli
