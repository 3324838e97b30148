// The commands over the results store as library calls: history's view of a store, documents
// imported into one and exported from it (`raygate history | import | export`). Each opens the
// store named by its location (an SQLite path or a postgresql:// URL, store/store.h) and returns
// what the command shows, so a front end only parses options and prints.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "alert/history_alert.h"
#include "history/history_view.h"
#include "store/store.h"

namespace raygate {

// What is wrong with a --store location, told without opening it: a URL of a kind that is not
// postgresql://. "" when none. written_store_problem also refuses, for a command that writes the
// store, an SQLite path where no file can be written (/dev/null, a read-only folder): said before
// the documents are read or measured, not after.
std::string store_location_problem(const std::string& location);
std::string written_store_problem(const std::string& location);

// `history --html DIR`'s page, DIR/history.html, checked as any output is before the store is
// read (a symbolic link there is refused, exit 2); "" for "".
std::filesystem::path history_page(const std::string& html_dir);

// The newest query.last_commits commits of each series matching `query`, with the machine's
// whole history beside them for the drift rule. UsageError when the store does not exist.
HistoryView store_history_view(const std::string& store, const HistoryQuery& query);

struct AlertRequest {
  std::string store;
  HistoryQuery query;  // the series and the newest query.last_commits commits judged
  std::string policy;  // a gate policy file (each scene's max_slowdown); "" = the defaults
  AlertAction action = AlertAction::fail;
  EDivisiveOptions detection;
};

// Each series' change points over the newest commits, judged against the policy. `say` hears
// the line naming what is judged. UsageError when no measured commit matches the filters.
AlertJudgement judge_store_history(const AlertRequest& request,
                                   const std::function<void(const std::string&)>& say);

// `files` stored in `store` (created if missing), each under its revision's branch or else
// `branch`. Every file is read and checked before any is stored. Returns one line per file
// ("FILE: stored as document N (branch B)") and a closing count.
std::string import_documents(const std::vector<std::string>& files, const std::string& store,
                             const std::string& branch);

struct ExportRequest {
  std::string store;
  std::string sha;       // documents that measured a commit (a sha or its prefix); "" = any
  std::size_t last = 0;  // the newest N stored; 0 = all
  std::string branch;
  std::string out;  // a directory (one file per document) or FILE.json
};

// Writes the documents the request matches; returns the line saying where. UsageError when
// --output is missing or nothing matches.
std::string export_stored_documents(const ExportRequest& request);

}  // namespace raygate
