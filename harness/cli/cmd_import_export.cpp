// `raygate import FILE...`: store results documents (each once, however often imported);
// `raygate export`: write stored documents back as JSON, byte for byte as `raygate run` wrote
// them. Exit 0, 2 for input that is not a results document or a query that matches nothing.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/store_options.h"
#include "cli/subcommand.h"
#include "pipeline/store_commands.h"

namespace raygate::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> files;
  std::string store = kDefaultStorePath;
  std::string branch;
};

int import_command(const ImportArgs& args) {
  fmt::print("{}", import_documents(args.files, args.store, args.branch));
  return 0;
}

int export_command(const ExportRequest& request) {
  fmt::print("{}", export_stored_documents(request));
  return 0;
}

}  // namespace

void add_import_command(CLI::App& command, int& exit_code) {
  ImportArgs& args = bind_command<ImportArgs>(command, import_command, exit_code);
  command.add_option("files", args.files, "results documents (results.json)")->required();
  add_store_option(command, args.store, kDefaultStorePath, StoreUse::written);
  command.add_option("--branch", args.branch,
                     "branch to record a document under when its revision names none");
}

void add_export_command(CLI::App& command, int& exit_code) {
  ExportRequest& args = bind_command<ExportRequest>(command, export_command, exit_code);
  args.store = kDefaultStorePath;
  add_store_option(command, args.store, kDefaultStorePath);
  CLI::Option* sha =
      command.add_option("--sha", args.sha, "documents that measured a commit (sha or prefix)");
  // Bounded: CLI11 reads "-5" into a std::size_t as 2^64 - 5, which would mean "all".
  add_bounded_option(command, "--last", args.last, std::size_t{0}, std::size_t{1000000},
                     "the N most recently stored documents (0: all)")
      ->excludes(sha);
  command.add_option("--branch", args.branch, "only documents recorded under this branch");
  add_deprecated_alias(command, "--out",
                       command.add_option("-o,--output", args.out,
                                          "a directory (one file per document) or FILE.json "
                                          "(required)"),
                       args.out);
}

}  // namespace raygate::cli
