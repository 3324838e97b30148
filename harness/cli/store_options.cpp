#include "cli/store_options.h"

#include "pipeline/store_commands.h"

namespace raygate::cli {

CLI::Option* add_store_option(CLI::App& command, std::string& store,
                              const std::string& default_text, StoreUse use) {
  return command
      .add_option("--store", store,
                  "results store: an SQLite file (default " + default_text +
                      ") or postgresql://USER@HOST[:PORT]/DATABASE")
      ->check(
          CLI::Validator(use == StoreUse::written ? written_store_problem : store_location_problem,
                         "PATH", "store location"));
}

void add_history_filters(CLI::App& command, HistoryQuery& query) {
  command.add_option("--branch", query.branch, "only results recorded under this branch");
  command.add_option("--scene", query.scenes, "only these suite scene ids (repeatable)");
  command.add_option("--repository", query.repository,
                     "only the repository whose key contains this text (its root commit sha or "
                     "URL, as history's table headings show)");
  command.add_option("--adapter", query.adapter, "only results measured with this adapter");
  command.add_option("--suite", query.suite, "only results of this suite");
  command
      .add_option("--role", query.role,
                  "which revision of a document: tracer (run), head or base (compare), any")
      ->check(CLI::IsMember({"tracer", "head", "base", "any"}))
      ->capture_default_str();
}

void add_record_options(CLI::App& command, PublishOptions& options) {
  CLI::Option* store =
      add_store_option(command, options.store, "<cache-dir>/results.db", StoreUse::written);
  command.add_flag("--no-store", options.no_store, "do not record the results in the store")
      ->excludes(store);
  command.add_option("--branch", options.branch,
                     "branch to record the results under when the revision names none");
}

}  // namespace raygate::cli
