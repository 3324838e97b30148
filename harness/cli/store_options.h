// Options and steps shared by the commands that use the results store: --store for all of them,
// and for the measuring commands (run, compare) --no-store and --branch plus recording the
// finished document. A bad --store is rejected while parsing, before any measuring starts.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "cli/console.h"
#include "results/results.h"
#include "store/store.h"

namespace raygate::cli {

// --store PATH: `default_text` is shown in --help (where the store is when it is not given).
CLI::Option* add_store_option(CLI::App& command, std::string& store,
                              const std::string& default_text);

// The filters of the commands that read history (history, alert), bound straight into `query`:
// --branch, --scene, --repository, --adapter, --suite, --role.
void add_history_filters(CLI::App& command, HistoryQuery& query);

struct RecordArgs {
  std::string store;  // "" -> <cache-dir>/results.db
  bool no_store = false;
  std::string branch;  // recorded when the revision names no branch
};

// --store, --no-store, --branch for run and compare.
void add_record_options(CLI::App& command, RecordArgs& args);

// Where run and compare record: --store, else <cache_dir>/results.db; "" with --no-store.
std::filesystem::path record_store_path(const RecordArgs& args,
                                        const std::filesystem::path& cache_dir);

// Stores the finished document (complete or not: the store keeps the flag) and says where.
// A store that cannot be written is a warning on stderr, not a failure of the measurement: the
// document file stays, and the warning says how to import it later.
void record_results(const ResultsDocument& document, const RecordArgs& args,
                    const std::filesystem::path& cache_dir,
                    const std::filesystem::path& document_path, const Console& console);

}  // namespace raygate::cli
