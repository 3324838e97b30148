// Options shared by the commands that use the results store: --store for all of them, and for
// the commands that publish a document (run, compare, merge) --no-store and --branch
// (pipeline/publish.h records it). A bad --store is rejected while parsing, before any
// measuring starts.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "pipeline/publish_options.h"
#include "store/store.h"

namespace raygate::cli {

enum class StoreUse { read, written };  // written (import, run...): a file must be writable there

// --store PATH: `default_text` is shown in --help (where the store is when it is not given).
CLI::Option* add_store_option(CLI::App& command, std::string& store,
                              const std::string& default_text, StoreUse use = StoreUse::read);

// The filters of the commands that read history (history, alert), bound straight into `query`:
// --branch, --scene, --repository, --adapter, --suite, --role.
void add_history_filters(CLI::App& command, HistoryQuery& query);

// --store, --no-store, --branch for run, compare and merge (pipeline/publish_options.h).
void add_record_options(CLI::App& command, PublishOptions& options);

}  // namespace raygate::cli
