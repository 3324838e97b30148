// `raygate import FILE...`: store results documents (each once, however often imported);
// `raygate export`: write stored documents back as JSON, byte for byte as `raygate run` wrote
// them. Exit 0, 2 for input that is not a results document or a query that matches nothing.
#include <fmt/core.h>

#include <memory>

#include "cli/console.h"
#include "cli/store_commands.h"
#include "cli/store_options.h"
#include "core/error.h"
#include "store/document_files.h"
#include "store/store.h"

namespace raygate::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> files;
  std::string store = kDefaultStorePath;
  std::string branch;
};

int import_command(const ImportArgs& args) {
  std::vector<ResultsDocument> documents;  // all checked before any is stored
  for (const std::string& file : args.files) documents.push_back(load_results_file(file));
  const auto store = open_store(args.store, StoreOpen::create_if_missing);
  std::size_t fresh = 0;
  for (std::size_t i = 0; i < documents.size(); ++i) {
    const std::string branch = branch_of(documents[i], args.branch);
    const AddOutcome outcome = store->add(documents[i], branch);
    fresh += outcome.duplicate ? 0 : 1;
    fmt::print("{}: {} document {}{}\n", args.files[i],
               outcome.duplicate ? "already stored as" : "stored as", outcome.document_id,
               branch.empty() ? "" : " (branch " + branch + ")");
  }
  fmt::print("imported {} of {} documents into {}\n", fresh, documents.size(), store->location());
  return 0;
}

struct ExportArgs {
  std::string store = kDefaultStorePath;
  std::string sha;
  std::size_t last = 0;
  std::string branch;
  std::string out;
};

int export_command(const ExportArgs& args) {
  if (args.out.empty()) throw UsageError("export: --output is required (a directory or FILE.json)");
  const auto store = open_store(args.store, StoreOpen::must_exist);
  DocumentQuery query;
  query.sha_prefix = checked_sha_prefix(args.sha);
  query.last = args.last;
  query.branch = args.branch;
  const std::vector<StoredDocument> documents = store->documents(query);
  if (documents.empty()) {
    throw UsageError(fmt::format("no document in {} matches{}{}", store->location(),
                                 args.sha.empty() ? "" : " --sha " + args.sha,
                                 args.branch.empty() ? "" : " --branch " + args.branch));
  }
  const ExportedFiles exported = export_documents(documents, args.out);
  if (exported.single_file) {
    fmt::print("wrote document {} to {}\n", documents.front().id, args.out);
  } else {
    fmt::print("wrote {} documents to {}\n", documents.size(), args.out);
  }
  return 0;
}

}  // namespace

void add_import_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* command = app.add_subcommand(
      "import", "store results documents (a document already stored is kept once)");
  command->add_option("files", args->files, "results documents (results.json)")->required();
  add_store_option(*command, args->store, kDefaultStorePath);
  command->add_option("--branch", args->branch,
                      "branch to record a document under when its revision names none");
  command->callback([args, &exit_code] { exit_code = import_command(*args); });
}

void add_export_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* command = app.add_subcommand(
      "export", "write stored results documents as JSON (newest first), as they were stored");
  add_store_option(*command, args->store, kDefaultStorePath);
  CLI::Option* sha =
      command->add_option("--sha", args->sha, "documents that measured a commit (sha or prefix)");
  command->add_option("--last", args->last, "the N most recently stored documents")->excludes(sha);
  command->add_option("--branch", args->branch, "only documents recorded under this branch");
  add_deprecated_alias(*command, "--out",
                       command->add_option("-o,--output", args->out,
                                           "a directory (one file per document) or FILE.json "
                                           "(required)"),
                       args->out);
  command->callback([args, &exit_code] { exit_code = export_command(*args); });
}

}  // namespace raygate::cli
