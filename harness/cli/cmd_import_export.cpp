// `raygate import FILE...`: store results documents (each once, however often imported);
// `raygate export`: write stored documents back as JSON, byte for byte as `raygate run` wrote
// them. Exit 0, 2 for input that is not a results document or a query that matches nothing.
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <memory>

#include "cli/console.h"
#include "cli/store_commands.h"
#include "cli/store_options.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/path_component.h"
#include "store/store.h"

namespace raygate::cli {
namespace {

struct ImportArgs {
  std::vector<std::string> files;
  std::string store = kDefaultStorePath;
  std::string branch;
};

// A clear refusal for JSON that is something else (an adapter, a suite, a build record).
ResultsDocument load_results_file(const std::string& file) {
  const std::string text = read_file(file);
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw UsageError(
        fmt::format("{}: not JSON ({}); import takes results documents", file, e.what()));
  }
  const bool looks_like_results = json.is_object() && json.contains("schema_version") &&
                                  json.contains("revisions") && json.contains("scenes");
  if (!looks_like_results) {
    throw UsageError(
        fmt::format("{}: not a raygate results document (no schema_version, "
                    "revisions and scenes); import takes the results.json that "
                    "`raygate run` writes",
                    file));
  }
  return results_from_json(json, file);
}

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

std::string checked_sha_prefix(std::string sha) {
  std::transform(sha.begin(), sha.end(), sha.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool hex =
      std::all_of(sha.begin(), sha.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
  if (!hex || sha.size() > 40) {
    throw UsageError(fmt::format("--sha {}: not a commit sha or a prefix of one", sha));
  }
  return sha;
}

std::string short_sha_of(const nlohmann::json& document) {
  for (const nlohmann::json& revision : document.value("revisions", nlohmann::json::array())) {
    const std::string sha = revision.at("worktree").value("short_sha", std::string());
    if (!sha.empty()) return sha;
  }
  return "unknown";
}

// The document's text exactly as write_results writes it.
std::string document_text(const StoredDocument& stored) { return stored.document.dump(1) + "\n"; }

void export_to(const std::vector<StoredDocument>& documents, const std::filesystem::path& out) {
  if (out.extension() == ".json") {
    if (documents.size() != 1) {
      throw UsageError(
          fmt::format("{} documents match but -o {} names one file; give a "
                      "directory, or narrow with --sha or --last 1",
                      documents.size(), out.string()));
    }
    write_file_atomically(out, document_text(documents.front()));
    fmt::print("wrote document {} to {}\n", documents.front().id, out.string());
    return;
  }
  // The sha is read back from the store, which holds whatever was imported: every name is
  // checked before anything is written, so a bad one leaves the directory untouched.
  std::vector<std::filesystem::path> paths;
  for (const StoredDocument& stored : documents) {
    const std::string sha = checked_component(
        short_sha_of(stored.document),
        fmt::format("stored document {}: revisions[].worktree.short_sha", stored.id));
    paths.push_back(join_component(out, fmt::format("{}-{}", stored.id, sha),
                                   "exported document name", ".json"));
  }
  for (std::size_t i = 0; i < documents.size(); ++i) {
    write_file_atomically(paths[i], document_text(documents[i]));
  }
  fmt::print("wrote {} documents to {}\n", documents.size(), out.string());
}

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
  export_to(documents, args.out);
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
